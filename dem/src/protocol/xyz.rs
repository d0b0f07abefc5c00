//! Extended-XYZ snapshots (OVITO reads them): one frame per call, appended; the file is
//! replaced by a fresh run and cut back to the checkpoint's length on resume
//! ([`prepare_file`]).

use crate::integrator::Sim;
use std::io::Write;
use std::path::Path;

/// Makes `path` ready for a run of `sim`: a fresh run (step 0) replaces it with an empty file;
/// a resumed run cuts it back to the `sim.state.xyz_bytes` it had at the checkpoint, so the
/// frames continue exactly (no frame twice, none from an aborted later segment). Errors when
/// the file is shorter than recorded (it was changed since).
pub fn prepare_file(path: &Path, sim: &Sim) -> std::io::Result<()> {
    let want = sim.state.xyz_bytes;
    if sim.state.step == 0 || want == 0 {
        std::fs::File::create(path)?;
        return Ok(());
    }
    let f = std::fs::OpenOptions::new().write(true).open(path).map_err(|e| {
        std::io::Error::new(
            e.kind(),
            format!("cannot continue the snapshot file ({e}); it held {want} bytes at the checkpoint"),
        )
    })?;
    let have = f.metadata()?.len();
    if have < want {
        return Err(std::io::Error::other(format!(
            "the snapshot file has {have} bytes but held {want} at the checkpoint: it was changed since; \
             remove it or give another --xyz to start it afresh from here"
        )));
    }
    f.set_len(want)?;
    f.sync_all()
}

/// Appends one frame of every substrate sphere (species `B`), slider sphere (`S`), control
/// layer centre (`C`) and support (`P`) to `path` and returns the bytes written. Columns:
/// species, x, y, z (µm), radius (µm, each sphere's own), failed (1 if any contact of the sphere has a failed
/// coating now). Comment line holds `Time=` (µs). O(N + P).
pub fn append_frame(path: &Path, sim: &Sim) -> std::io::Result<u64> {
    let s = &sim.state;
    let um = 1e6;
    let r = sim.spec.slider_sphere_radius * um;
    let rb = sim.spec.substrate_sphere_radius * um;
    let snap = sim.snapshot();
    let n = snap.slider.len() + snap.substrate.len() + 2;
    let mut b = String::with_capacity(n * 64);
    b.push_str(&format!(
        "{n}\nProperties=species:S:1:pos:R:3:radius:R:1:failed:I:1 Time={:.6} pbc=\"F F F\"\n",
        s.t * 1e6
    ));
    let spec = &sim.spec;
    for (j, x) in snap.substrate.iter().enumerate() {
        // each sphere's own radius with per-site sizes
        let rb = match &spec.substrate_radii {
            None => rb,
            Some(r) => r[j] * um,
        };
        b.push_str(&format!(
            "B {:.6} {:.6} {:.6} {rb} {}\n",
            x[0] * um,
            x[1] * um,
            x[2] * um,
            snap.failed_substrate[j] as u8
        ));
    }
    for (i, x) in snap.slider.iter().enumerate() {
        let r = match &spec.slider_radii {
            None => r,
            Some(ri) => ri[i] * um,
        };
        b.push_str(&format!(
            "S {:.6} {:.6} {:.6} {r} {}\n",
            x[0] * um,
            x[1] * um,
            x[2] * um,
            snap.failed_slider[i] as u8
        ));
    }
    let rc = sim.params.mount.control_sphere_radius * um;
    b.push_str(&format!(
        "C {:.6} {:.6} {:.6} {rc} 0\n",
        s.cl_x[0] * um,
        s.cl_x[1] * um,
        s.cl_x[2] * um + 2.0 * r
    ));
    b.push_str(&format!(
        "P {:.6} {:.6} {:.6} {rc} 0\n",
        s.support[0] * um,
        s.support[1] * um,
        s.cl_x[2] * um + 2.0 * r
    ));
    let mut f = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)?;
    f.write_all(b.as_bytes())?;
    Ok(b.len() as u64)
}
