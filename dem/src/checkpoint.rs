//! Atomic checkpoints of a run: the full [`crate::system::State`], the last pair results and
//! the samples so far, in a small little-endian binary format (bit-exact f64), written to a
//! temporary sibling and renamed into place. [`load`] refuses a checkpoint whose header (layout
//! sizes, knobs, dt) differs from the run being resumed.

use crate::integrator::Sim;
use crate::model::PairOut;
use crate::protocol::Sample;
use crate::system::PairHist;
use crate::DemError;
use std::path::Path;

const MAGIC: &[u8; 8] = b"SLDEMCK1";

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
impl Bin for PairHist {
    fn put(&self, w: &mut Vec<u8>) {
        self.xi.put(w);
        self.ever_failed.put(w);
    }
    fn get(r: &mut &[u8]) -> Option<Self> {
        Some(PairHist {
            xi: Bin::get(r)?,
            ever_failed: Bin::get(r)?,
        })
    }
}
impl Bin for PairOut {
    fn put(&self, w: &mut Vec<u8>) {
        self.force.put(w);
        self.delta.put(w);
        self.p0.put(w);
        self.failed.put(w);
    }
    fn get(r: &mut &[u8]) -> Option<Self> {
        Some(PairOut {
            force: Bin::get(r)?,
            delta: Bin::get(r)?,
            p0: Bin::get(r)?,
            failed: Bin::get(r)?,
        })
    }
}
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
        ]
        .put(w);
    }
    fn get(r: &mut &[u8]) -> Option<Self> {
        let a = <[f64; 9]>::get(r)?;
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
        })
    }
}

/// Header string identifying the run a checkpoint belongs to (sizes, knobs, dt).
fn header(sim: &Sim) -> String {
    format!(
        "sub={} sl={} dt={:e} params={}",
        sim.n_substrate(),
        sim.n_slider(),
        sim.dt,
        serde_json::to_string(&sim.params).unwrap_or_default()
    )
}

/// Writes the state of `sim` and `samples` to `path` atomically (temp file + fsync + rename).
pub fn save(path: &Path, sim: &Sim, samples: &[Sample]) -> Result<(), DemError> {
    let err = |why: String| DemError::Checkpoint {
        path: path.display().to_string(),
        why,
    };
    let s = &sim.state;
    let mut w = Vec::with_capacity(64 * (s.sub_x.len() + s.sl_x.len()) + 128 * s.pairs.i.len());
    w.extend_from_slice(MAGIC);
    let h = header(sim);
    (h.len() as u64).put(&mut w);
    w.extend_from_slice(h.as_bytes());
    s.step.put(&mut w);
    s.t.put(&mut w);
    s.builds.put(&mut w);
    s.sub_x.put(&mut w);
    s.sub_v.put(&mut w);
    s.sub_f.put(&mut w);
    s.sl_x.put(&mut w);
    s.sl_v.put(&mut w);
    s.sl_f.put(&mut w);
    s.cl_x.put(&mut w);
    s.cl_v.put(&mut w);
    s.cl_f.put(&mut w);
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
    sim.out.put(&mut w);
    samples.to_vec().put(&mut w);
    surrogate::atomic_file::write_atomic(path, &w).map_err(|e| err(e.to_string()))?;
    Ok(())
}

/// Restores the state saved by [`save`] into `sim` (built with the same scene, knobs and dt)
/// and returns the samples so far.
pub fn load(path: &Path, sim: &mut Sim) -> Result<Vec<Sample>, DemError> {
    let err = |why: &str| DemError::Checkpoint {
        path: path.display().to_string(),
        why: why.into(),
    };
    let bytes = std::fs::read(path).map_err(|e| err(&e.to_string()))?;
    let mut r: &[u8] = &bytes;
    if r.len() < 8 || &r[..8] != MAGIC {
        return Err(err("not a superlube DEM checkpoint"));
    }
    r = &r[8..];
    let bad = || err("truncated or corrupt");
    let hl = u64::get(&mut r).ok_or_else(bad)? as usize;
    if hl > r.len() {
        return Err(bad());
    }
    let h = std::str::from_utf8(&r[..hl]).map_err(|_| bad())?;
    if h != header(sim) {
        return Err(err(
            "written by a different run (scene size, parameters or dt differ); rerun with the same flags",
        ));
    }
    r = &r[hl..];
    let s = &mut sim.state;
    let mut g = || -> Option<(Vec<PairOut>, Vec<Sample>)> {
        s.step = Bin::get(&mut r)?;
        s.t = Bin::get(&mut r)?;
        s.builds = Bin::get(&mut r)?;
        s.sub_x = Bin::get(&mut r)?;
        s.sub_v = Bin::get(&mut r)?;
        s.sub_f = Bin::get(&mut r)?;
        s.sl_x = Bin::get(&mut r)?;
        s.sl_v = Bin::get(&mut r)?;
        s.sl_f = Bin::get(&mut r)?;
        s.cl_x = Bin::get(&mut r)?;
        s.cl_v = Bin::get(&mut r)?;
        s.cl_f = Bin::get(&mut r)?;
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
        let out: Vec<PairOut> = Bin::get(&mut r)?;
        let samples: Vec<Sample> = Bin::get(&mut r)?;
        Some((out, samples))
    };
    let (out, samples) = g().ok_or_else(bad)?;
    sim.index_pairs();
    sim.out = out;
    if sim.out.len() != sim.state.pairs.i.len() {
        return Err(bad());
    }
    Ok(samples)
}
