//! Rigid slider with height and two tilts held by the scene's mount: damped Newton on the three
//! balance equations (ΣF_z = W and the moment balance `M_c = K_t·t` about the disc centre, with
//! `K_t` = 0 for a free mount), solved by a 3 × 3 Cholesky factorisation.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::assemble::assemble;
use super::columns::Columns;
use super::ctx::Ctx;
#[allow(unused_imports)]
use super::ctx::Watch;
use super::law::{body_pairs, BodyPair, Law};
use super::z_root::ZRoot;
use super::{Equilibrium, Model, PairSet};
use crate::error::SceneError;

/// Potential `Π(q) = Σ Φ_j + W (z − z_ref) + ½ q₁₂ᵀ K_q q₁₂` (the last term the mount's
/// `½ tᵀ K_t t`, `K_q = K_t/L²`), its gradient
/// `[W − ΣF_z, −ΣF_z gx + (K_q q₁₂)₀, −ΣF_z gy + (K_q q₁₂)₁]` (N) and Hessian
/// `Σ s_j v_j v_jᵀ + diag(0, K_q)` (N/m), `v_j = [1, g_j]`. Π is convex wherever every s_j ≥ 0.
fn eval<L: Law>(ctx: &Ctx, tp: &[BodyPair<L>], load: f64, q: [f64; 3]) -> Potential {
    let k = ctx.hertz.k();
    let mut acc = Potential::mount(ctx, load, q);
    for p in tp {
        let dz = q[0] + q[1] * p.g[0] + q[2] * p.g[1] - p.c;
        let r = p.response(k, ctx.two_r, dz);
        acc.add(r.fz, r.s, r.phi, p.g);
    }
    acc.finish()
}

/// [`eval`] of the pairs held in `cols` (the scene's one law): every pair's response in one
/// vectorised pass ([`Columns::respond`]), then the same sums in the same order (same bits).
fn eval_columns(ctx: &Ctx, cols: &mut Columns, load: f64, q: [f64; 3]) -> Potential {
    cols.respond(ctx.hertz.k(), ctx.two_r, q);
    let mut acc = Potential::mount(ctx, load, q);
    for j in 0..cols.len() {
        acc.add(cols.fz[j], cols.s[j], cols.phi[j], cols.g(j));
    }
    acc.finish()
}

/// Π (J), its gradient (N) and Hessian (N/m) at one state, summed term by term as [`eval`]
/// describes.
struct Potential {
    pi: f64,
    grad: [f64; 3],
    hess: [[f64; 3]; 3],
}

impl Potential {
    /// The mount's terms at `q` and the load's: `Π = W ζ + ½ q₁₂ᵀ K_q q₁₂`, its gradient and
    /// Hessian (lower triangle).
    #[inline]
    fn mount(ctx: &Ctx, load: f64, q: [f64; 3]) -> Self {
        let kq = ctx.kq();
        let kq1 = [
            kq[0][0] * q[1] + kq[0][1] * q[2],
            kq[1][0] * q[1] + kq[1][1] * q[2],
        ];
        Potential {
            pi: load * q[0] + 0.5 * (q[1] * kq1[0] + q[2] * kq1[1]),
            grad: [load, kq1[0], kq1[1]],
            hess: [[0.0; 3], [0.0, kq[0][0], 0.0], [0.0, kq[1][0], kq[1][1]]],
        }
    }

    /// Adds one pair of lever `g` with force `fz` (N), stiffness `s` (N/m) and energy `phi` (J);
    /// a pair with neither force nor stiffness is skipped.
    #[inline(always)]
    fn add(&mut self, fz: f64, s: f64, phi: f64, g: [f64; 2]) {
        if fz == 0.0 && s == 0.0 {
            return;
        }
        self.pi += phi;
        let v = [1.0, g[0], g[1]];
        let s = s.max(0.0);
        for a in 0..3 {
            self.grad[a] -= fz * v[a];
            for b in 0..=a {
                self.hess[a][b] += s * v[a] * v[b];
            }
        }
    }

    /// Copies the lower triangle of the Hessian to the upper.
    #[inline]
    fn finish(mut self) -> Self {
        for a in 0..3 {
            for b in 0..a {
                self.hess[b][a] = self.hess[a][b];
            }
        }
        self
    }
}

/// The Newton step `x = −(H + μI)⁻¹ g` of the symmetric 3×3 `h` (lower triangle read) by
/// Cholesky factorisation `H + μI = L Lᵀ`, `None` where a pivot is not positive (H + μI not
/// positive definite, or not finite). O(1): 3 square roots, ≈ 30 flops, no allocation (a
/// general dense factorisation cost more than its evaluation of a few hundred pairs:
/// `docs/validation/path-solve.md`).
fn cholesky_solve3(h: &[[f64; 3]; 3], mu: f64, g: &[f64; 3]) -> Option<[f64; 3]> {
    let pivot = |a: f64| (a > 0.0 && a.is_finite()).then(|| a.sqrt());
    let l00 = pivot(h[0][0] + mu)?;
    let l10 = h[1][0] / l00;
    let l20 = h[2][0] / l00;
    let l11 = pivot(h[1][1] + mu - l10 * l10)?;
    let l21 = (h[2][1] - l20 * l10) / l11;
    let l22 = pivot(h[2][2] + mu - l20 * l20 - l21 * l21)?;
    // L y = −g, then Lᵀ x = y
    let y0 = -g[0] / l00;
    let y1 = (-g[1] - l10 * y0) / l11;
    let y2 = (-g[2] - l20 * y0 - l21 * y1) / l22;
    let x2 = y2 / l22;
    let x1 = (y1 - l21 * x2) / l11;
    let x0 = (y0 - l10 * x1 - l20 * x2) / l00;
    Some([x0, x1, x2])
}

/// Damped (Levenberg–Marquardt regularised, trust-capped, Armijo line-searched) Newton on the
/// convex potential Π from `q0`. Returns the converged `q`, the iteration count and whether the
/// force balance already holds to `force_rtol` (false only after a round-off stall).
///
/// With fewer than three non-collinear contacts the Hessian is singular in a tilt direction:
/// the regularisation μ = 1e-10·max diag(H) makes the step the minimum-norm one, capped by a
/// trust radius, so an unbalanced moment tips the slider (deterministically) until new contacts
/// stop it, and a balanced but undetermined tilt stays at its start value. If the tilt grows
/// until the rim drops by more than a sphere diameter the load point lies outside the support
/// (e.g. slider hanging over the substrate edge) and the solve fails with `NoEquilibrium`.
///
/// `whole`: `tp` is every pair of the list (not a working set): each state it evaluates is
/// recorded with [`Ctx::rely_tilted`].
///
/// With the scene's one law the pairs are evaluated as [`Columns`] (a vectorised pass, same
/// bits); with per-site sizes pair by pair.
pub(crate) fn tilt_newton<L: Law>(
    ctx: &Ctx,
    tp: &[BodyPair<L>],
    load: f64,
    q0: [f64; 3],
    whole: bool,
) -> Result<([f64; 3], usize, bool), SceneError> {
    let mut cols = (!L::SIZED).then(|| {
        let mut c = COLUMNS.with(|c| c.take());
        c.fill(tp);
        c
    });
    let out = newton(ctx, load, q0, |q| {
        if whole {
            ctx.rely_tilted(q);
        }
        match &mut cols {
            Some(cols) => eval_columns(ctx, cols, load, q),
            None => eval(ctx, tp, load, q),
        }
    });
    if let Some(cols) = cols {
        COLUMNS.with(|c| c.replace(cols));
    }
    out
}

thread_local! {
    /// The columns of [`tilt_newton`], kept per thread (no allocation per solve).
    static COLUMNS: std::cell::RefCell<Columns> = std::cell::RefCell::new(Columns::default());
}

/// The damped Newton of [`tilt_newton`] on the potential `eval` (Π, gradient, Hessian at a state).
fn newton(
    ctx: &Ctx,
    load: f64,
    q0: [f64; 3],
    mut eval: impl FnMut([f64; 3]) -> Potential,
) -> Result<([f64; 3], usize, bool), SceneError> {
    let params = ctx.params;
    let mut q = q0;
    let tol_f = params.force_rtol * load;
    let tol_m = params.moment_rtol * load;
    let mut rho = ctx.two_r; // trust radius (m) on the step
    let Potential {
        mut pi,
        grad: mut g,
        hess: mut h,
    } = eval(q);
    for it in 1..=params.max_iter {
        if g[0].abs() <= tol_f && g[1].abs() <= tol_m && g[2].abs() <= tol_m {
            return Ok((q, it, true));
        }
        let dmax = h[0][0].max(h[1][1]).max(h[2][2]).max(f64::MIN_POSITIVE);
        let mut mu = 1e-10 * dmax;
        let step = loop {
            match cholesky_solve3(&h, mu, &g) {
                Some(x) => break x,
                None => mu = (mu * 100.0).max(1e-30),
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
            let Potential {
                pi: pn,
                grad: gn,
                hess: hn,
            } = eval(qn);
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
        return Ok((q, params.max_iter, g[0].abs() <= tol_f));
    }
    Err(SceneError::NoEquilibrium(format!(
        "rigid-tilt Newton did not converge: force residual {:e} N, moment residuals {:e}, {:e} N",
        g[0], g[1], g[2]
    )))
}

/// Rigid-tilt equilibrium: rigid-z start, then [`tilt_from`]. Cost: one rigid-z solve plus
/// ~2–30 Newton iterations of O(P) each (P candidate pairs; 1–3 with the study's K1 springs).
pub(crate) fn solve_rigid_tilt<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    load: f64,
) -> Result<Equilibrium, SceneError> {
    let (bp, zref) = body_pairs::<L>(ctx, ps);
    let (q, iters) = rigid_tilt_state(ctx, ps, &bp, load)?;
    Ok(assemble_tilt(ctx, ps, &bp, zref, load, q, iters))
}

/// The [`Equilibrium`] of a converged rigid-tilt state. On a watched list, where the lever bound
/// gmax is known, only the pairs above `ζ − |q₁₂|·gmax` (the only ones that can touch at `q`)
/// are evaluated; else every pair. Same result.
pub(crate) fn assemble_tilt<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    bp: &[BodyPair<L>],
    zref: f64,
    load: f64,
    q: [f64; 3],
    iters: usize,
) -> Equilibrium {
    let floor = ctx
        .watch
        .map_or(f64::NEG_INFINITY, |w| q[0] - q[1].hypot(q[2]) * w.gmax);
    assemble(
        ctx,
        ps,
        bp,
        zref,
        Model::RigidTilt,
        load,
        q,
        |_| 0.0,
        iters,
        floor,
    )
}

/// Converged `[ζ, L·t_x, L·t_y]` and iterations, from the rigid-z start.
pub(crate) fn rigid_tilt_state<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    bp: &[BodyPair<L>],
    load: f64,
) -> Result<([f64; 3], usize), SceneError> {
    let zr = ZRoot::new(bp, [0.0, 0.0], ctx.two_r, ctx.hertz.k());
    let (z0, it0) = zr.solve(ctx, load)?;
    let near = NearSet::new(ctx, bp, z0, ctx.lever_bound(ps));
    let (q, it1) = tilt_from(ctx, bp, &near, load, z0, None)?;
    Ok((q, it0 + it1))
}

/// The tilt Newton's working set around the rigid-z state ζ₀: the pairs whose touch height c lies
/// above `floor = ζ₀ − band`, `band` = [`NEAR_BAND`]·(−ζ₀) (−ζ₀ is the deepest rigid-z overlap) —
/// typically a few hundred of the ≈ 10⁴ candidate pairs, and a superset of the pairs touching at
/// ζ₀. Built in one O(P) pass.
pub(crate) struct NearSet<L> {
    /// The pairs with c > `floor`, in pair order.
    pub pairs: Vec<BodyPair<L>>,
    /// ζ₀ − band (m).
    floor: f64,
    /// Bound on |g| = |arm|/L over every pair.
    gmax: f64,
    /// Whether no pair was left out.
    complete: bool,
}

impl<L: Law> NearSet<L> {
    /// The working set of `bp` around the rigid-z state `z0` (m); `gmax` bounds |g| over every
    /// pair ([`Ctx::max_lever`]). On a partial list ([`Ctx::watch`]) the set is never complete unless
    /// its band is empty, as on the whole list.
    pub fn new(ctx: &Ctx, bp: &[BodyPair<L>], z0: f64, gmax: f64) -> NearSet<L> {
        let band = NEAR_BAND * (-z0).max(0.0);
        let floor = z0 - band;
        ctx.rely(floor);
        // counted first: the set is not regrown push by push
        let n = bp.iter().filter(|p| p.c > floor).count();
        let mut pairs: Vec<BodyPair<L>> = Vec::with_capacity(n);
        pairs.extend(bp.iter().filter(|p| p.c > floor).copied());
        NearSet {
            complete: (pairs.len() == bp.len() && ctx.watch.is_none()) || band == 0.0,
            pairs,
            floor,
            gmax,
        }
    }

    /// Whether a pair of `bp` left out of the set touches at state `q`: O(1) when the bound
    /// `ζ − |q₁₂|·max|g| > floor` rules it out, else one O(P) pass.
    fn misses_a_contact(&self, ctx: &Ctx, bp: &[BodyPair<L>], q: [f64; 3]) -> bool {
        if self.complete || q[0] - (q[1] * q[1] + q[2] * q[2]).sqrt() * self.gmax > self.floor {
            return false;
        }
        ctx.rely_tilted(q);
        bp.iter()
            .any(|p| p.c <= self.floor && p.c > q[0] + q[1] * p.g[0] + q[2] * p.g[1])
    }
}

/// Tilt Newton from `warm` (a path's previous tilted state, extrapolated) or else the rigid-z
/// state ζ = `z0` (t = 0), then, only if Newton stalled before the force balance held, a 1-D z
/// polish at the final tilt so ΣF_z = W holds to `force_rtol`. Returns `[ζ, L·t_x, L·t_y]` and
/// the iterations. If the start already balances the moments to `moment_rtol`·W·L this returns
/// it unchanged after one evaluation.
///
/// Newton first runs on the working set `near` (see [`NearSet`]); the answer is then verified on
/// every pair: if a left-out pair touches at the final state, or if Newton on the set fails (a
/// free slider may tip further than the set reaches), Newton is rerun on all pairs from there.
/// So the result is the all-pairs equilibrium either way; the set only saves time (each
/// iteration costs O(set) instead of O(P)).
pub(crate) fn tilt_from<L: Law>(
    ctx: &Ctx,
    bp: &[BodyPair<L>],
    near: &NearSet<L>,
    load: f64,
    z0: f64,
    warm: Option<[f64; 3]>,
) -> Result<([f64; 3], usize), SceneError> {
    debug_assert!(ctx.tilts, "tilt model under a locked mount");
    let cold = [z0, 0.0, 0.0];
    let start = warm.unwrap_or(cold);
    let (q, it1, force_ok) = if near.complete {
        tilt_newton(ctx, bp, load, start, true)?
    } else {
        match tilt_newton(ctx, &near.pairs, load, start, false) {
            Ok((q, it, ok)) if !near.misses_a_contact(ctx, bp, q) => (q, it, ok),
            Ok((q, it, _)) => {
                let (q2, it2, ok2) = tilt_newton(ctx, bp, load, q, true)?;
                (q2, it + it2, ok2)
            }
            Err(_) => tilt_newton(ctx, bp, load, cold, true)?,
        }
    };
    if force_ok {
        return Ok((q, it1));
    }
    let zr = ZRoot::new(bp, [q[1], q[2]], ctx.two_r, ctx.hertz.k());
    let drop = ctx.watch.map_or(0.0, |w| q[1].hypot(q[2]) * w.gmax);
    let (z, it2) = zr.solve_dropped(ctx, load, drop)?;
    Ok(([z, q[1], q[2]], it1 + it2))
}

/// Width of the tilt Newton's working set in units of the deepest rigid-z overlap (see
/// [`NearSet`]). Only a speed knob: the result is verified on every pair.
const NEAR_BAND: f64 = 1.0;
