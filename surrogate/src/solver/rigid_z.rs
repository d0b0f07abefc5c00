//! Rigid slider, height only: a safeguarded 1-D Newton root find of ΣF_z(z) = W.

use super::{ContactInfo, Equilibrium, Model, SolverParams};
use crate::contact::{CandidatePair, Hertz};
use crate::error::SceneError;
use crate::scene::Coating;

/// Solves `Σ_pairs F_z(z) = W` for the slider height z (m), where for a pair at lateral
/// distance r and substrate height h, with `u = z − h`, `D = √(r² + u²)`, `δ = 2R − D`:
/// `F_z = (4/3)E*√R_eff δ^{3/2} · u/D`.
///
/// `slider_xy` are the slider sphere centres (m), `pairs` the candidates from a
/// [`crate::contact::CandidateSearch`] with reach 2R, `load` W (N).
///
/// ΣF_z is monotone in z, so Newton's method inside a shrinking bracket [z_lo, z_hi] converges
/// from any start; bisection takes over whenever a Newton step leaves the bracket (grazing
/// contacts where dF/dz → 0). Cost: O(P log P) to sort the P pairs by touch height, then
/// O(P_active) per iteration, typically < 15 iterations.
#[allow(clippy::too_many_arguments)]
pub fn solve_rigid_z(
    slider_xy: &[[f64; 2]],
    pairs: &[CandidatePair],
    radius_sum: f64,
    hertz: &Hertz,
    coating: &Coating,
    load: f64,
    params: &SolverParams,
) -> Result<Equilibrium, SceneError> {
    if pairs.is_empty() {
        return Err(SceneError::NoEquilibrium(
            "no substrate sphere lies under any slider sphere (slider off the substrate?)".into(),
        ));
    }
    let d2 = radius_sum * radius_sum;
    // (z_touch, r2, h, index) sorted by z_touch descending: pairs active at height z are a prefix.
    let mut act: Vec<(f64, f64, f64, u32)> = pairs
        .iter()
        .enumerate()
        .map(|(n, p)| (p.h + (d2 - p.r2).max(0.0).sqrt(), p.r2, p.h, n as u32))
        .collect();
    act.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.3.cmp(&b.3)));
    let k = hertz.k();
    let eval = |z: f64| -> (f64, f64) {
        let mut f = 0.0;
        let mut df = 0.0;
        for &(zt, r2, h, _) in &act {
            if zt <= z {
                break;
            }
            let u = z - h;
            let dd = (r2 + u * u).sqrt();
            let delta = radius_sum - dd;
            if delta <= 0.0 || u <= 0.0 {
                continue;
            }
            let sd = delta.sqrt();
            let fnorm = k * delta * sd;
            f += fnorm * u / dd;
            df += -1.5 * k * sd * u * u / (dd * dd) + fnorm * r2 / (dd * dd * dd);
        }
        (f, df)
    };
    let z_hi0 = act[0].0;
    let mut z_hi = z_hi0;
    // Lower bracket: step down by the overlap one on-top contact needs for W, doubling.
    let mut step = hertz.overlap_for_force(load).max(1e-15 * radius_sum);
    let mut z_lo = z_hi - step;
    let mut iters = 0;
    loop {
        let (f, _) = eval(z_lo);
        if f >= load {
            break;
        }
        z_hi = z_lo;
        step *= 2.0;
        z_lo = z_hi0 - step;
        iters += 1;
        if iters > params.max_iter || step > radius_sum {
            return Err(SceneError::NoEquilibrium(format!(
                "load {load:e} N cannot be carried with overlap below the sphere radius"
            )));
        }
    }
    let mut z = 0.5 * (z_lo + z_hi);
    let tol = params.force_rtol * load;
    let mut fz;
    loop {
        iters += 1;
        let (f, df) = eval(z);
        fz = f;
        let g = f - load;
        if g.abs() <= tol {
            break;
        }
        if g > 0.0 {
            z_lo = z;
        } else {
            z_hi = z;
        }
        let newton = if df < 0.0 { z - g / df } else { f64::NAN };
        z = if newton > z_lo && newton < z_hi {
            newton
        } else {
            0.5 * (z_lo + z_hi)
        };
        if z_hi - z_lo <= 4.0 * f64::EPSILON * z_hi.abs() || iters > params.max_iter {
            // Bracket exhausted at machine precision: accept the better end point.
            let (fl, _) = eval(z_lo);
            z = z_lo;
            fz = fl;
            if (fl - load).abs() > 1e-9 * load {
                return Err(SceneError::NoEquilibrium(format!(
                    "root find stalled at z = {z:e} m with residual {:e} N",
                    fl - load
                )));
            }
            break;
        }
    }
    let mut contacts = Vec::new();
    let mut p_max: f64 = 0.0;
    for &(zt, r2, h, n) in &act {
        if zt <= z {
            break;
        }
        let u = z - h;
        let dd = (r2 + u * u).sqrt();
        let delta = radius_sum - dd;
        if delta <= 0.0 || u <= 0.0 {
            continue;
        }
        let p = pairs[n as usize];
        let fnorm = hertz.force(delta);
        let p0 = hertz.p0(delta);
        p_max = p_max.max(p0);
        let s = slider_xy[p.slider as usize];
        contacts.push(ContactInfo {
            slider: p.slider,
            substrate: p.substrate,
            point: [s[0], s[1], 0.5 * (z + h)], // x, y of the slider sphere
            overlap: delta,
            force_n: fnorm,
            force_z: fnorm * u / dd,
            p0,
            failed: coating.failed(p0),
        });
    }
    contacts.sort_by_key(|c| (c.slider, c.substrate));
    Ok(Equilibrium {
        model: Model::RigidZ,
        load,
        z,
        tilt: [0.0, 0.0],
        contacts,
        p_max,
        residual: fz - load,
        iterations: iters,
    })
}
