//! Extended-XYZ snapshots (OVITO reads them): one frame per call, appended.

use crate::integrator::Sim;
use std::io::Write;
use std::path::Path;

/// Appends one frame of every substrate sphere (species `B`), slider sphere (`S`), control
/// layer centre (`C`) and support (`P`) to `path`. Columns: species, x, y, z (µm), radius (µm),
/// failed (1 if any contact of the sphere has a failed coating now). Comment line holds
/// `Time=` (µs). O(N + P).
pub fn append_frame(path: &Path, sim: &Sim) -> std::io::Result<()> {
    let s = &sim.state;
    let um = 1e6;
    let r = sim.spec.sphere_radius * um;
    let mut failed_sl = vec![false; s.sl_x.len()];
    let mut failed_sub = vec![false; s.sub_x.len()];
    for (k, o) in sim.pair_results().iter().enumerate() {
        if o.delta > 0.0 && o.failed {
            failed_sl[s.pairs.i[k] as usize] = true;
            failed_sub[s.pairs.j[k] as usize] = true;
        }
    }
    let n = s.sl_x.len() + s.sub_x.len() + 2;
    let mut b = String::with_capacity(n * 64);
    b.push_str(&format!(
        "{n}\nProperties=species:S:1:pos:R:3:radius:R:1:failed:I:1 Time={:.6} pbc=\"F F F\"\n",
        s.t * 1e6
    ));
    for (j, x) in s.sub_x.iter().enumerate() {
        b.push_str(&format!(
            "B {:.6} {:.6} {:.6} {r} {}\n",
            x[0] * um,
            x[1] * um,
            sim.spec.substrate[j][2] * um,
            failed_sub[j] as u8
        ));
    }
    for (i, x) in s.sl_x.iter().enumerate() {
        b.push_str(&format!(
            "S {:.6} {:.6} {:.6} {r} {}\n",
            x[0] * um,
            x[1] * um,
            x[2] * um,
            failed_sl[i] as u8
        ));
    }
    let rc = sim.params.control_sphere_radius * um;
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
    f.write_all(b.as_bytes())
}
