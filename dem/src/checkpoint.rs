//! Atomic checkpoints of a run: the full [`crate::system::State`] (active set included) and the
//! samples so far, in a small little-endian binary format (bit-exact f64), written to a temporary
//! sibling and renamed into place.
//!
//! Layout: magic `SLDEMCK2`, CRC-32 of everything after it, then a header of `key=value` lines
//! recording every input that changes the physics (the whole scene with its mount, coating,
//! material, σ_h and seed, θ; the contact model with the friction law, i.e. `--mu`; every
//! [`crate::SimParams`] field; dt; the layout sizes), then the state. [`load`] refuses a file
//! whose checksum does not match (corrupt or edited), whose header differs from the run being
//! resumed (naming the inputs that differ), or which holds a non-finite or inconsistent state.

use crate::integrator::Sim;
use crate::model::{Friction, PairOut};
use crate::protocol::Sample;
use crate::system::{ActiveStats, CommonMode, FrameMark, PairHist, Ringing};
use crate::DemError;
use std::path::Path;

const MAGIC: &[u8; 8] = b"SLDEMCK2";
/// Magic of the format before the checksum and the full header.
const MAGIC_V1: &[u8; 8] = b"SLDEMCK1";

trait Bin: Sized {
    fn put(&self, w: &mut Vec<u8>);
    fn get(r: &mut &[u8]) -> Option<Self>;
}
/// Little-endian fixed-size numbers.
macro_rules! bin_le {
    ($($t:ty),*) => {$(
        impl Bin for $t {
            fn put(&self, w: &mut Vec<u8>) {
                w.extend_from_slice(&self.to_le_bytes());
            }
            fn get(r: &mut &[u8]) -> Option<Self> {
                let (a, b) = r.split_at_checked(std::mem::size_of::<$t>())?;
                *r = b;
                Some(<$t>::from_le_bytes(a.try_into().ok()?))
            }
        }
    )*};
}
bin_le!(f64, u64, u32);
impl Bin for bool {
    fn put(&self, w: &mut Vec<u8>) {
        w.push(*self as u8);
    }
    fn get(r: &mut &[u8]) -> Option<Self> {
        let (a, b) = r.split_first()?;
        *r = b;
        Some(*a != 0)
    }
}
impl<const N: usize> Bin for [f64; N] {
    fn put(&self, w: &mut Vec<u8>) {
        for v in self {
            v.put(w);
        }
    }
    fn get(r: &mut &[u8]) -> Option<Self> {
        let mut a = [0.0; N];
        for v in a.iter_mut() {
            *v = f64::get(r)?;
        }
        Some(a)
    }
}
impl<T: Bin> Bin for Vec<T> {
    fn put(&self, w: &mut Vec<u8>) {
        (self.len() as u64).put(w);
        for v in self {
            v.put(w);
        }
    }
    fn get(r: &mut &[u8]) -> Option<Self> {
        let n = u64::get(r)? as usize;
        if n > r.len() {
            return None;
        }
        (0..n).map(|_| T::get(r)).collect()
    }
}
/// Structs as the sequence of their fields.
macro_rules! bin_struct {
    ($t:ident { $($f:ident),* }) => {
        impl Bin for $t {
            fn put(&self, w: &mut Vec<u8>) {
                $(self.$f.put(w);)*
            }
            fn get(r: &mut &[u8]) -> Option<Self> {
                Some($t { $($f: Bin::get(r)?,)* })
            }
        }
    };
}
bin_struct!(PairHist { xi, ever_failed });
bin_struct!(PairOut {
    force,
    delta,
    p0,
    failed
});
bin_struct!(CommonMode {
    u,
    v,
    fu,
    w,
    s,
    fw,
    d,
    dv,
    fd,
    dz,
    dzv,
    fdz
});
bin_struct!(FrameMark {
    cl,
    tilt,
    u,
    w,
    step,
    ring
});
bin_struct!(Ringing {
    sl,
    sl_dev,
    sub,
    sub_dev
});
bin_struct!(ActiveStats {
    evaluations,
    activations,
    deactivations,
    late_pairs,
    particle_steps
});
impl Bin for Sample {
    fn put(&self, w: &mut Vec<u8>) {
        [
            self.t_us,
            self.support_x_um,
            self.spring_force_mn,
            self.z_um,
            self.contacts as f64,
            self.p_max_gpa,
            self.failed_contacts as f64,
            self.slider_x_um,
            self.contact_fz_mn,
            self.p_max_peak_gpa,
        ]
        .put(w);
    }
    fn get(r: &mut &[u8]) -> Option<Self> {
        let a = <[f64; 10]>::get(r)?;
        Some(Sample {
            t_us: a[0],
            support_x_um: a[1],
            spring_force_mn: a[2],
            z_um: a[3],
            contacts: a[4] as usize,
            p_max_gpa: a[5],
            failed_contacts: a[6] as usize,
            slider_x_um: a[7],
            contact_fz_mn: a[8],
            p_max_peak_gpa: a[9],
        })
    }
}

/// Flattens a JSON value into `prefix.key=value` pairs (arrays as `prefix[i]`).
fn flatten(prefix: &str, v: &serde_json::Value, out: &mut Vec<(String, String)>) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                flatten(&format!("{prefix}.{k}"), x, out);
            }
        }
        serde_json::Value::Array(a) => {
            for (k, x) in a.iter().enumerate() {
                flatten(&format!("{prefix}[{k}]"), x, out);
            }
        }
        other => out.push((prefix.to_string(), other.to_string())),
    }
}

/// Every input of `sim` that changes the physics, as `(key, value)` pairs: layout sizes, dt,
/// every knob, the scene (mount, coating, material, σ_h, seed, θ, …) and the contact model
/// (the friction law: the coating's or a constant `--mu`). Floats in shortest round-trip form.
pub fn header_fields(sim: &Sim) -> Vec<(String, String)> {
    let mut h = vec![
        ("format".to_string(), "3".to_string()),
        (
            "layout.substrate_spheres".into(),
            sim.n_substrate().to_string(),
        ),
        ("layout.slider_spheres".into(), sim.n_slider().to_string()),
        ("dt_s".into(), format!("{:?}", sim.dt)),
        (
            "mount.tilt_stiffness_N_m".into(),
            format!("{:?}", sim.spec.tilt_stiffness),
        ),
    ];
    if let Ok(v) = serde_json::to_value(&sim.params) {
        flatten("params", &v, &mut h);
    }
    // serde_json writes ∞ as null: keep the knobs that may be infinite exact
    h.push((
        "params.damping_time_exact".into(),
        format!("{:?}", sim.params.numerics.damping_time),
    ));
    match &sim.spec.scene {
        Some(scene) => {
            if let Ok(v) = serde_json::to_value(scene) {
                flatten("scene", &v, &mut h);
            }
        }
        None => h.push(("scene".into(), "none (built by hand)".into())),
    }
    let m = &sim.model;
    h.push((
        "friction".into(),
        match m.friction {
            Friction::Constant(c) => format!("constant mu = {:?} (--mu)", c.mu),
            Friction::PressureSwitched(f) => format!(
                "coating law mu1 = {:?}, mu2 = {:?}, P_crit = {:?} Pa",
                f.mu1, f.mu2, f.p_crit
            ),
        },
    ));
    h.push((
        "contact".into(),
        format!(
            "E* = {:?} Pa, R_eff = {:?} m, gamma_n = {:?}, G* = {:?} Pa, gamma_t = {:?}, R1+R2 = {:?} m",
            m.normal.hertz.e_star,
            m.normal.hertz.r_eff,
            m.normal.gamma_n,
            m.tangential.g_star,
            m.tangential.gamma_t,
            m.radius_sum
        ),
    ));
    h
}

fn header_text(fields: &[(String, String)]) -> String {
    fields.iter().map(|(k, v)| format!("{k}={v}\n")).collect()
}

/// Writes the state of `sim` and `samples` to `path` atomically (temp file + fsync + rename).
pub fn save(path: &Path, sim: &Sim, samples: &[Sample]) -> Result<(), DemError> {
    let err = |why: String| DemError::Checkpoint {
        path: path.display().to_string(),
        why,
    };
    let s = &sim.state;
    let a = &s.act;
    let mut w = Vec::with_capacity(64 * (s.sub_x.len() + s.sl_x.len()) + 128 * s.pairs.i.len());
    let h = header_text(&header_fields(sim));
    (h.len() as u64).put(&mut w);
    w.extend_from_slice(h.as_bytes());
    s.step.put(&mut w);
    s.t.put(&mut w);
    s.builds.put(&mut w);
    s.sub_x.put(&mut w);
    s.sub_v.put(&mut w);
    s.sl_x.put(&mut w);
    s.sl_v.put(&mut w);
    a.sl.put(&mut w);
    a.sl_x.put(&mut w);
    a.sl_v.put(&mut w);
    a.sl_f.put(&mut w);
    a.sl_x0.put(&mut w);
    a.sub.put(&mut w);
    a.sub_x.put(&mut w);
    a.sub_v.put(&mut w);
    a.sub_f.put(&mut w);
    a.sub_x0.put(&mut w);
    a.pairs.put(&mut w);
    a.hist.put(&mut w);
    a.out.put(&mut w);
    s.common.put(&mut w);
    s.ringing.put(&mut w);
    s.cl_x.put(&mut w);
    s.cl_v.put(&mut w);
    s.cl_f.put(&mut w);
    s.tilt.put(&mut w);
    s.tilt_v.put(&mut w);
    s.tilt_f.put(&mut w);
    s.support.put(&mut w);
    s.support0.put(&mut w);
    s.support_v.put(&mut w);
    s.spring_on.put(&mut w);
    s.held_xy.put(&mut w);
    s.pairs.i.put(&mut w);
    s.pairs.j.put(&mut w);
    s.pairs.hist.put(&mut w);
    s.ref_sub.put(&mut w);
    s.ref_sl.put(&mut w);
    s.mark.put(&mut w);
    s.stats.put(&mut w);
    s.xyz_bytes.put(&mut w);
    s.xyz_frames.put(&mut w);
    s.p0_peak.put(&mut w);
    samples.to_vec().put(&mut w);
    let mut file = Vec::with_capacity(w.len() + 12);
    file.extend_from_slice(MAGIC);
    crc32fast::hash(&w).put(&mut file);
    file.extend_from_slice(&w);
    surrogate::atomic_file::write_atomic(path, &file).map_err(|e| err(e.to_string()))?;
    Ok(())
}

/// Parses `key=value` lines.
fn parse_header(text: &str) -> Vec<(String, String)> {
    text.lines()
        .filter_map(|l| l.split_once('='))
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

/// The inputs that differ between a checkpoint's header and this run's, as readable lines.
fn differences(file: &[(String, String)], run: &[(String, String)]) -> Vec<String> {
    let get = |h: &[(String, String)], k: &str| {
        h.iter()
            .find(|(a, _)| a == k)
            .map(|(_, v)| v.clone())
            .unwrap_or_else(|| "(absent)".into())
    };
    let mut keys: Vec<&String> = run.iter().map(|(k, _)| k).collect();
    for (k, _) in file {
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    keys.into_iter()
        .filter_map(|k| {
            let (a, b) = (get(file, k), get(run, k));
            (a != b).then(|| format!("`{k}`: checkpoint {a}, this run {b}"))
        })
        .collect()
}

/// Restores the state saved by [`save`] into `sim` (built with the same scene, knobs and dt)
/// and returns the samples so far. Refuses (with the reason) a file that is not a checkpoint,
/// fails its checksum, was written by a run with other inputs, or holds a non-finite or
/// inconsistent state.
pub fn load(path: &Path, sim: &mut Sim) -> Result<Vec<Sample>, DemError> {
    let err = |why: &str| DemError::Checkpoint {
        path: path.display().to_string(),
        why: why.into(),
    };
    let bytes = std::fs::read(path).map_err(|e| err(&e.to_string()))?;
    if bytes.len() >= 8 && &bytes[..8] == MAGIC_V1 {
        return Err(err(
            "written by an older superlube (no checksum, incomplete header); start the run afresh without --resume",
        ));
    }
    if bytes.len() < 12 || &bytes[..8] != MAGIC {
        return Err(err("not a superlube DEM checkpoint"));
    }
    let mut r: &[u8] = &bytes[8..];
    let crc = u32::get(&mut r).ok_or_else(|| err("truncated"))?;
    if crc32fast::hash(r) != crc {
        return Err(err(
            "corrupt checkpoint: the state checksum does not match (the file was truncated, damaged or edited); start afresh without --resume",
        ));
    }
    let bad = || err("corrupt checkpoint: truncated or malformed state");
    let hl = u64::get(&mut r).ok_or_else(bad)? as usize;
    if hl > r.len() {
        return Err(bad());
    }
    let h = std::str::from_utf8(&r[..hl]).map_err(|_| bad())?;
    let diff = differences(&parse_header(h), &header_fields(sim));
    if !diff.is_empty() {
        let shown: Vec<&str> = diff.iter().take(8).map(|s| s.as_str()).collect();
        return Err(err(&format!(
            "written by a run with different inputs ({} differ): {}{}; rerun with the same inputs, or start afresh without --resume",
            diff.len(),
            shown.join("; "),
            if diff.len() > 8 { "; …" } else { "" }
        )));
    }
    r = &r[hl..];
    let mut st = sim.state.clone();
    let mut g = || -> Option<Vec<Sample>> {
        let s = &mut st;
        s.step = Bin::get(&mut r)?;
        s.t = Bin::get(&mut r)?;
        s.builds = Bin::get(&mut r)?;
        s.sub_x = Bin::get(&mut r)?;
        s.sub_v = Bin::get(&mut r)?;
        s.sl_x = Bin::get(&mut r)?;
        s.sl_v = Bin::get(&mut r)?;
        let a = &mut s.act;
        a.sl = Bin::get(&mut r)?;
        a.sl_x = Bin::get(&mut r)?;
        a.sl_v = Bin::get(&mut r)?;
        a.sl_f = Bin::get(&mut r)?;
        a.sl_x0 = Bin::get(&mut r)?;
        a.sub = Bin::get(&mut r)?;
        a.sub_x = Bin::get(&mut r)?;
        a.sub_v = Bin::get(&mut r)?;
        a.sub_f = Bin::get(&mut r)?;
        a.sub_x0 = Bin::get(&mut r)?;
        a.pairs = Bin::get(&mut r)?;
        a.hist = Bin::get(&mut r)?;
        a.out = Bin::get(&mut r)?;
        s.common = Bin::get(&mut r)?;
        s.ringing = Bin::get(&mut r)?;
        s.cl_x = Bin::get(&mut r)?;
        s.cl_v = Bin::get(&mut r)?;
        s.cl_f = Bin::get(&mut r)?;
        s.tilt = Bin::get(&mut r)?;
        s.tilt_v = Bin::get(&mut r)?;
        s.tilt_f = Bin::get(&mut r)?;
        s.support = Bin::get(&mut r)?;
        s.support0 = Bin::get(&mut r)?;
        s.support_v = Bin::get(&mut r)?;
        s.spring_on = Bin::get(&mut r)?;
        s.held_xy = Bin::get(&mut r)?;
        s.pairs.i = Bin::get(&mut r)?;
        s.pairs.j = Bin::get(&mut r)?;
        s.pairs.hist = Bin::get(&mut r)?;
        s.ref_sub = Bin::get(&mut r)?;
        s.ref_sl = Bin::get(&mut r)?;
        s.mark = Bin::get(&mut r)?;
        s.stats = Bin::get(&mut r)?;
        s.xyz_bytes = Bin::get(&mut r)?;
        s.xyz_frames = Bin::get(&mut r)?;
        s.p0_peak = Bin::get(&mut r)?;
        Bin::get(&mut r)
    };
    let samples = g().ok_or_else(bad)?;
    if !r.is_empty() {
        return Err(bad());
    }
    if let Some(what) = inconsistent(&st, sim.n_slider(), sim.n_substrate()) {
        return Err(err(&format!("corrupt checkpoint: {what}")));
    }
    sim.state = st;
    sim.index();
    Ok(samples)
}

/// Why a loaded state cannot be resumed (a non-finite value, a size or index out of range),
/// or `None`.
fn inconsistent(s: &crate::system::State, n: usize, nb: usize) -> Option<String> {
    if let Some(f) = non_finite(s) {
        return Some(format!(
            "non-finite value in the {f} (the file holds a state that cannot be resumed)"
        ));
    }
    if !fits(s, n, nb) {
        return Some("array sizes or indices do not fit the scene".into());
    }
    None
}

/// The first part of the state `s` that holds a non-finite value, or `None`.
fn non_finite(s: &crate::system::State) -> Option<&'static str> {
    fn finite<const N: usize>(v: &[[f64; N]]) -> bool {
        v.iter().all(|x| x.iter().all(|c| c.is_finite()))
    }
    let a = &s.act;
    let fields: [(&str, bool); 14] = [
        ("substrate positions", finite(&s.sub_x) && finite(&a.sub_x)),
        ("substrate velocities", finite(&s.sub_v) && finite(&a.sub_v)),
        ("substrate forces", finite(&a.sub_f) && finite(&a.sub_x0)),
        ("slider positions", finite(&s.sl_x) && finite(&a.sl_x)),
        ("slider velocities", finite(&s.sl_v) && finite(&a.sl_v)),
        ("slider forces", finite(&a.sl_f) && finite(&a.sl_x0)),
        (
            "control layer",
            [s.cl_x, s.cl_v, s.cl_f]
                .iter()
                .chain([[s.tilt[0], s.tilt[1], s.tilt_v[0]]].iter())
                .all(|x| x.iter().all(|c| c.is_finite()))
                && s.tilt_v[1].is_finite()
                && s.tilt_f.iter().all(|c| c.is_finite()),
        ),
        (
            "common mode",
            [
                s.common.u,
                s.common.v,
                s.common.fu,
                s.common.d,
                s.common.dv,
                s.common.fd,
            ]
            .iter()
            .all(|x| x.iter().all(|c| c.is_finite()))
                && [
                    s.common.w,
                    s.common.s,
                    s.common.fw,
                    s.common.dz,
                    s.common.dzv,
                    s.common.fdz,
                ]
                .iter()
                .all(|x| x.iter().all(|c| c.is_finite()))
                && finite(&s.ringing.sl_dev)
                && finite(&s.ringing.sub_dev),
        ),
        (
            "support",
            [s.support, s.support0, s.support_v]
                .iter()
                .all(|x| x.iter().all(|c| c.is_finite())),
        ),
        (
            "contact histories",
            s.pairs
                .hist
                .iter()
                .all(|h| h.xi.iter().all(|c| c.is_finite()))
                && a.hist.iter().all(|h| h.xi.iter().all(|c| c.is_finite())),
        ),
        (
            "pair results",
            a.out
                .iter()
                .all(|o| o.force.iter().all(|c| c.is_finite()) && o.delta.is_finite()),
        ),
        (
            "neighbour-list references",
            finite(&s.ref_sl) && finite(&s.ref_sub),
        ),
        ("time", s.t.is_finite()),
        (
            "active-set references",
            [s.mark.cl, s.mark.w]
                .iter()
                .all(|x| x.iter().all(|c| c.is_finite()))
                && s.mark.u.iter().chain(&s.mark.tilt).all(|c| c.is_finite()),
        ),
    ];
    fields.iter().find(|(_, ok)| !ok).map(|(f, _)| *f)
}

/// Whether the array sizes and indices of `s` fit a scene of `n` slider and `nb` substrate
/// spheres (sorted active and ringing lists, pair indices in range, consistent lengths).
fn fits(s: &crate::system::State, n: usize, nb: usize) -> bool {
    let a = &s.act;
    let np = s.pairs.i.len();
    let sizes_ok = s.sub_x.len() == nb
        && s.sub_v.len() == nb
        && s.ref_sub.len() == nb
        && s.sl_x.len() == n
        && s.sl_v.len() == n
        && s.ref_sl.len() == n
        && s.pairs.j.len() == np
        && s.pairs.hist.len() == np
        && [a.sl_x.len(), a.sl_v.len(), a.sl_f.len(), a.sl_x0.len()] == [a.sl.len(); 4]
        && [a.sub_x.len(), a.sub_v.len(), a.sub_f.len(), a.sub_x0.len()] == [a.sub.len(); 4]
        && a.hist.len() == a.pairs.len()
        && a.out.len() == a.pairs.len();
    let ascending = |v: &[u32], lim: usize| {
        v.windows(2).all(|w| w[0] < w[1]) && v.last().is_none_or(|&x| (x as usize) < lim)
    };
    let r = &s.ringing;
    let ring_ok = r.sl.len() == r.sl_dev.len()
        && r.sub.len() == r.sub_dev.len()
        && ascending(&r.sl, n)
        && ascending(&r.sub, nb)
        && r.sl.iter().all(|i| a.sl.binary_search(i).is_err())
        && r.sub.iter().all(|j| a.sub.binary_search(j).is_err());
    let idx_ok = ring_ok
        && s.mark.step <= s.step
        && ascending(&a.sl, n)
        && ascending(&a.sub, nb)
        && ascending(&a.pairs, np)
        && s.pairs.i.iter().all(|&i| (i as usize) < n)
        && s.pairs.j.iter().all(|&j| (j as usize) < nb)
        && a.pairs.iter().all(|&k| {
            a.sl.binary_search(&s.pairs.i[k as usize]).is_ok()
                && a.sub.binary_search(&s.pairs.j[k as usize]).is_ok()
        });
    sizes_ok && idx_ok
}
