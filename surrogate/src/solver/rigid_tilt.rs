//! Rigid slider with height and two tilts: damped Newton on the three balance equations
//! (ΣF_z = W, ΣF_z·y = 0, ΣF_z·x = 0 about the disc centre), solved with faer.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::assemble::{assemble, Ctx};
use super::law::{body_pairs, pair_response, BodyPair};
use super::z_root::ZRoot;
use super::{Equilibrium, Model, PairSet};
use crate::error::SceneError;
use faer::linalg::solvers::Solve;
use faer::{Col, Mat, Side};

/// Potential `Π(q) = Σ Φ_j + W (z − z_ref)`, its gradient `[W − ΣF_z, −ΣF_z gx, −ΣF_z gy]` (N)
/// and Hessian `Σ s_j g_j g_jᵀ` (N/m). Π is convex wherever every s_j ≥ 0.
fn eval(ctx: &Ctx, tp: &[BodyPair], load: f64, q: [f64; 3]) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let k = ctx.hertz.k();
    let mut pi = load * q[0];
    let mut g = [load, 0.0, 0.0];
    let mut h = [[0.0; 3]; 3];
    for p in tp {
        let dz = q[0] + q[1] * p.g[0] + q[2] * p.g[1] - p.c;
        let r = pair_response(k, ctx.two_r, p.r2, p.ut, dz);
        if r.fz == 0.0 && r.s == 0.0 {
            continue;
        }
        pi += r.phi;
        let v = [1.0, p.g[0], p.g[1]];
        let s = r.s.max(0.0);
        for a in 0..3 {
            g[a] -= r.fz * v[a];
            for b in 0..=a {
                h[a][b] += s * v[a] * v[b];
            }
        }
    }
    for a in 0..3 {
        for b in 0..a {
            h[b][a] = h[a][b];
        }
    }
    (pi, g, h)
}

/// Damped (Levenberg–Marquardt regularised, trust-capped, Armijo line-searched) Newton on the
/// convex potential Π from `q0`. Returns the converged `q` and the iteration count.
///
/// With fewer than three non-collinear contacts the Hessian is singular in a tilt direction:
/// the regularisation μ = 1e-10·max diag(H) makes the step the minimum-norm one, capped by a
/// trust radius, so an unbalanced moment tips the slider (deterministically) until new contacts
/// stop it, and a balanced but undetermined tilt stays at its start value. If the tilt grows
/// until the rim drops by more than a sphere diameter the load point lies outside the support
/// (e.g. slider hanging over the substrate edge) and the solve fails with `NoEquilibrium`.
pub(crate) fn tilt_newton(
    ctx: &Ctx,
    tp: &[BodyPair],
    load: f64,
    q0: [f64; 3],
) -> Result<([f64; 3], usize), SceneError> {
    let params = ctx.params;
    let mut q = q0;
    let tol_f = params.force_rtol * load;
    let tol_m = params.moment_rtol * load;
    let mut rho = ctx.two_r; // trust radius (m) on the step
    let (mut pi, mut g, mut h) = eval(ctx, tp, load, q);
    for it in 1..=params.max_iter {
        if g[0].abs() <= tol_f && g[1].abs() <= tol_m && g[2].abs() <= tol_m {
            return Ok((q, it));
        }
        let dmax = h[0][0].max(h[1][1]).max(h[2][2]).max(f64::MIN_POSITIVE);
        let mut mu = 1e-10 * dmax;
        let step = loop {
            let m = Mat::from_fn(3, 3, |a, b| h[a][b] + if a == b { mu } else { 0.0 });
            match m.llt(Side::Lower) {
                Ok(llt) => {
                    let mut x = Col::from_fn(3, |a| -g[a]);
                    llt.solve_in_place(&mut x);
                    break [x[0], x[1], x[2]];
                }
                Err(_) => {
                    mu = (mu * 100.0).max(1e-30);
                }
            }
        };
        let norm = (step[0] * step[0] + step[1] * step[1] + step[2] * step[2]).sqrt();
        if !norm.is_finite() {
            return Err(SceneError::NoEquilibrium(
                "rigid-tilt Newton step is not finite".into(),
            ));
        }
        let cap = if norm > rho { rho / norm } else { 1.0 };
        let d = step.map(|v| v * cap);
        let slope = g[0] * d[0] + g[1] * d[1] + g[2] * d[2];
        let mut alpha = 1.0;
        let mut accepted = false;
        for _ in 0..60 {
            let qn = [
                q[0] + alpha * d[0],
                q[1] + alpha * d[1],
                q[2] + alpha * d[2],
            ];
            let (pn, gn, hn) = eval(ctx, tp, load, qn);
            let slack = 1e-13 * (pi.abs() + load * ctx.two_r * 1e-6);
            // Energy (Armijo) test; near convergence Π is flat to round-off, so a step that
            // halves the gradient is accepted too.
            let gnorm = |v: &[f64; 3]| v[0].abs().max(v[1].abs()).max(v[2].abs());
            if pn <= pi + 1e-4 * alpha * slope + slack || gnorm(&gn) < 0.5 * gnorm(&g) {
                q = qn;
                pi = pn;
                g = gn;
                h = hn;
                accepted = true;
                break;
            }
            alpha *= 0.5;
        }
        if !accepted {
            break;
        }
        rho = if alpha == 1.0 && cap < 1.0 {
            2.0 * rho
        } else {
            (alpha * norm * cap).max(1e-6 * ctx.two_r).max(rho * 0.25)
        };
        if q[1].abs() > ctx.two_r || q[2].abs() > ctx.two_r {
            return Err(SceneError::NoEquilibrium(format!(
                "the slider tips over (rim drop {:.3e} m exceeds a sphere diameter): the load \
                 point lies outside the support of its contacts (slider over the substrate edge?)",
                q[1].hypot(q[2])
            )));
        }
    }
    if g[0].abs() <= 1e3 * tol_f && g[1].abs() <= 1e3 * tol_m && g[2].abs() <= 1e3 * tol_m {
        // Stalled at round-off: the z polish restores ΣF_z = W exactly.
        return Ok((q, params.max_iter));
    }
    Err(SceneError::NoEquilibrium(format!(
        "rigid-tilt Newton did not converge: force residual {:e} N, moment residuals {:e}, {:e} N",
        g[0], g[1], g[2]
    )))
}

/// Rigid-tilt equilibrium: rigid-z start, tilt Newton, then a 1-D z polish at the final tilt
/// so ΣF_z = W holds to `force_rtol`. Cost: two rigid-z solves plus ~5–30 Newton iterations
/// of O(P) each (P candidate pairs).
pub(crate) fn solve_rigid_tilt(
    ctx: &Ctx,
    ps: &PairSet,
    load: f64,
) -> Result<Equilibrium, SceneError> {
    let (bp, zref) = body_pairs(ctx, ps);
    let (q, iters) = rigid_tilt_state(ctx, &bp, load)?;
    Ok(assemble(
        ctx,
        ps,
        &bp,
        zref,
        Model::RigidTilt,
        load,
        q,
        &|_| 0.0,
        iters,
    ))
}

/// Converged `[ζ, L·t_x, L·t_y]` (after the ζ polish) and iterations.
pub(crate) fn rigid_tilt_state(
    ctx: &Ctx,
    bp: &[BodyPair],
    load: f64,
) -> Result<([f64; 3], usize), SceneError> {
    let zr = ZRoot::new(bp, [0.0, 0.0], ctx.two_r, ctx.hertz);
    let (z0, it0) = zr.solve(load, ctx.hertz, ctx.params)?;
    let (q, it1) = tilt_newton(ctx, bp, load, [z0, 0.0, 0.0])?;
    let zr = ZRoot::new(bp, [q[1], q[2]], ctx.two_r, ctx.hertz);
    let (z, it2) = zr.solve(load, ctx.hertz, ctx.params)?;
    Ok(([z, q[1], q[2]], it0 + it1 + it2))
}
