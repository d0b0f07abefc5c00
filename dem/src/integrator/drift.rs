//! The first half kick and drift of one chunk of active spheres ([`slider_chunk`],
//! [`substrate_chunk`]): the loop bodies of `Sim::kick_drift`'s pass (`step.rs`), inlined
//! into it, each returning the chunk's largest squared displacement since the last active-set
//! evaluation (m²; NaN when one is not finite).

use super::body::{dot3, g_of, Sizes};
use super::kernel::kick_hm;

/// What the slider chunks' kick and drift read: the step (s), the half step `h` (s) and `h/m`
/// of the body's spheres (s/kg), the mount's mode, the control layer's `q`, `q̇` and each
/// sphere's offset from the tilt axes, and the per-site sizes when there are.
pub(super) struct SliderDrift<'a> {
    pub dt: f64,
    pub h: f64,
    pub hm: f64,
    /// z follows the control layer rigidly.
    pub rigid: bool,
    /// z already advanced by the implicit mount step.
    pub implicit: bool,
    /// The control layer tilts.
    pub tilting: bool,
    pub q: [f64; 3],
    pub qd: [f64; 3],
    pub off: &'a [[f64; 2]],
    pub sizes: Option<&'a Sizes>,
}

/// Kicks (half step) and drifts the slider spheres `x`, `v` (ids `ids`, forces `f`, positions
/// at the last evaluation `x0`) of one chunk; the largest squared displacement (m², NaN when
/// one is not finite). O(chunk).
#[inline(always)]
pub(super) fn slider_chunk(
    k: &SliderDrift<'_>,
    x: &mut [[f64; 3]],
    v: &mut [[f64; 3]],
    f: &[[f64; 3]],
    x0: &[[f64; 3]],
    ids: &[u32],
) -> f64 {
    let SliderDrift {
        dt,
        h,
        hm,
        rigid,
        implicit,
        tilting,
        q,
        qd,
        off,
        sizes,
    } = *k;
    // largest squared displacement, and a flag for a non-finite one (no NaN-aware max
    // and no running sum in the loop's dependency chains)
    let (mut d2, mut bad) = (0.0f64, false);
    let it = x.iter_mut().zip(v.iter_mut()).zip(f).zip(x0).zip(ids);
    // one loop body, expanded twice so that each loop stays monomorphic (one size: the
    // body's mass, no anchor offset; per-site sizes: each sphere's own mass and anchor
    // offset R − r_i); a shared closure cost 15 % (not inlined)
    macro_rules! advance {
        ($hm:expr $(, $dz:expr)?) => {
            for ((((x, v), f), x0), &i) in it {
                let hm = $hm(i as usize);
                kick_hm(&mut v[0], f[0], hm);
                kick_hm(&mut v[1], f[1], hm);
                x[0] += dt * v[0];
                x[1] += dt * v[1];
                if rigid {
                    let g = if tilting {
                        g_of(off[i as usize])
                    } else {
                        [1.0, 0.0, 0.0]
                    };
                    x[2] = dot3(g, q) $(+ $dz(i as usize))?;
                    v[2] = dot3(g, qd);
                } else if !implicit {
                    kick_hm(&mut v[2], f[2], hm);
                    x[2] += dt * v[2];
                }
                let d = [x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]];
                let m = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                bad |= !m.is_finite();
                if m > d2 {
                    d2 = m;
                }
            }
        };
    }
    match sizes {
        Some(z) => advance!(|i: usize| h / z.sl_m[i], |i: usize| z.sl_dz[i]),
        None => advance!(|_: usize| hm),
    }
    if bad {
        f64::NAN
    } else {
        d2
    }
}

/// Kicks (half step `h`, s) and drifts (step `dt`, s) the substrate spheres `x`, `v` (forces
/// `f`, positions at the last evaluation `x0`, ids `ids`) of one chunk, `hm_b` = h/m of the
/// body's spheres or each one's own mass from `sizes`; the largest squared displacement (m²,
/// NaN when one is not finite). O(chunk).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn substrate_chunk(
    dt: f64,
    h: f64,
    hm_b: f64,
    sizes: Option<&Sizes>,
    x: &mut [[f64; 2]],
    v: &mut [[f64; 2]],
    f: &[[f64; 2]],
    x0: &[[f64; 2]],
    ids: &[u32],
) -> f64 {
    let (mut d2, mut bad) = (0.0f64, false);
    let it = x.iter_mut().zip(v.iter_mut()).zip(f.iter()).zip(x0);
    if let Some(z) = sizes {
        // each sphere's own mass (the loop below, per sphere)
        for ((((x, v), f), x0), &j) in it.zip(ids) {
            let hm_b = h / z.sub_m[j as usize];
            kick_hm(&mut v[0], f[0], hm_b);
            kick_hm(&mut v[1], f[1], hm_b);
            x[0] += dt * v[0];
            x[1] += dt * v[1];
            let d = [x[0] - x0[0], x[1] - x0[1]];
            let m = d[0] * d[0] + d[1] * d[1];
            bad |= !m.is_finite();
            if m > d2 {
                d2 = m;
            }
        }
        return if bad { f64::NAN } else { d2 };
    }
    for (((x, v), f), x0) in it {
        kick_hm(&mut v[0], f[0], hm_b);
        kick_hm(&mut v[1], f[1], hm_b);
        x[0] += dt * v[0];
        x[1] += dt * v[1];
        let d = [x[0] - x0[0], x[1] - x0[1]];
        let m = d[0] * d[0] + d[1] * d[1];
        bad |= !m.is_finite();
        if m > d2 {
            d2 = m;
        }
    }
    if bad {
        f64::NAN
    } else {
        d2
    }
}
