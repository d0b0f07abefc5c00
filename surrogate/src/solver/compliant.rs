//! Compliant slider: a rigid body (height, and the two tilts its mount allows) carrying every
//! slider sphere on its own vertical spring k_z; substrate spheres fixed in z. Sparse Newton with
//! faer's sparse Cholesky.

// Small dense index loops read like the math they implement.
#![allow(clippy::needless_range_loop)]

use super::assemble::assemble;
use super::ctx::Ctx;
use super::law::{body_pairs, BodyPair, Law};
use super::rigid_tilt::rigid_tilt_state;
use super::z_root::ZRoot;
use super::{Equilibrium, Model, PairSet};
use crate::error::SceneError;
use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Col, Side};

/// Unknowns `x = [w_0 … w_{n−1}, z, L·t_x, L·t_y]`: the upward deflection w_i (m) of each slider
/// sphere with candidate pairs, then the body pose (`nq` = 3 body unknowns; under a locked mount
/// only z, `nq` = 1, the tilts stay 0). Potential
/// `Π = Σ_j Φ(u_j) + Σ_i ½ k_z w_i² + W (z − z_ref) + ½ q₁₂ᵀ K_q q₁₂` with
/// `u_j = q·g_i + w_i − h_j` and the mount's `K_q = K_t/L²`, convex; its Hessian is an arrowhead
/// (diagonal w-block, dense nq×nq corner, nq dense coupling rows), factored with faer's sparse
/// Cholesky (AMD ordering, no fill-in beyond the arrow).
struct System<L> {
    /// The shared Hertz prefactor and contact distance (pairs with their own law ignore them).
    k: f64,
    two_r: f64,
    tp: Vec<BodyPair<L>>,
    groups: Vec<(u32, std::ops::Range<usize>)>,
    load: f64,
    kz: f64,
    /// Body unknowns: 3 (z and two tilts) or 1 (z only, locked mount).
    nq: usize,
    /// Mount stiffness in scaled tilt unknowns (N/m).
    kq: [[f64; 2]; 2],
}

struct State {
    pi: f64,
    grad: Vec<f64>,
    /// Per group: (H_ww, S_i) with H_wq = S_i·[1, g].
    diag: Vec<(f64, f64)>,
    hqq: [[f64; 3]; 3],
}

impl<L: Law> System<L> {
    fn n(&self) -> usize {
        self.groups.len()
    }

    /// The body pose `[ζ, L·t_x, L·t_y]` of `x` (tilts 0 when locked).
    fn q(&self, x: &[f64]) -> [f64; 3] {
        let n = self.n();
        if self.nq == 3 {
            [x[n], x[n + 1], x[n + 2]]
        } else {
            [x[n], 0.0, 0.0]
        }
    }

    /// Backtracking along the Newton step `d` from `x` (state `st`), from `cap` halving up to
    /// 60 times: moves `x` and `st` to the first point that passes the energy (Armijo) test, or
    /// near convergence, where Π is flat to round-off, halves the gradient; false where none
    /// does. O(P) per trial.
    fn line_search(&self, x: &mut Vec<f64>, st: &mut State, d: &[f64], cap: f64) -> bool {
        let slope: f64 = d.iter().zip(&st.grad).map(|(a, b)| a * b).sum::<f64>() * cap;
        let mut alpha = cap;
        for _ in 0..60 {
            let xn: Vec<f64> = x.iter().zip(d).map(|(a, b)| a + alpha * b).collect();
            let sn = self.eval(&xn);
            let slack = 1e-13 * st.pi.abs();
            let gnorm = |v: &[f64]| v.iter().fold(0.0f64, |m, g| m.max(g.abs()));
            if sn.pi <= st.pi + 1e-4 * (alpha / cap) * slope + slack
                || gnorm(&sn.grad) < 0.5 * gnorm(&st.grad)
            {
                *x = xn;
                *st = sn;
                return true;
            }
            alpha *= 0.5;
        }
        false
    }

    fn eval(&self, x: &[f64]) -> State {
        let n = self.n();
        let nq = self.nq;
        let q = self.q(x);
        let kq = self.kq;
        let kq1 = [
            kq[0][0] * q[1] + kq[0][1] * q[2],
            kq[1][0] * q[1] + kq[1][1] * q[2],
        ];
        let mut pi = self.load * q[0] + 0.5 * (q[1] * kq1[0] + q[2] * kq1[1]);
        let mut grad = vec![0.0; n + nq];
        grad[n] = self.load;
        let mut diag = Vec::with_capacity(n);
        let mut hqq = [[0.0; 3]; 3];
        if nq == 3 {
            grad[n + 1] = kq1[0];
            grad[n + 2] = kq1[1];
            for a in 0..2 {
                for b in 0..2 {
                    hqq[a + 1][b + 1] = kq[a][b];
                }
            }
        }
        for (gi, (_, range)) in self.groups.iter().enumerate() {
            let w = x[gi];
            let g = self.tp[range.start].g;
            let v = [1.0, g[0], g[1]];
            let base = q[0] + q[1] * g[0] + q[2] * g[1] + w;
            let mut f = 0.0;
            let mut s = 0.0;
            for p in &self.tp[range.clone()] {
                let r = p.response(self.k, self.two_r, base - p.c);
                pi += r.phi;
                f += r.fz;
                s += r.s.max(0.0);
            }
            pi += 0.5 * self.kz * w * w;
            grad[gi] = self.kz * w - f;
            for a in 0..nq {
                grad[n + a] -= f * v[a];
                for b in 0..nq {
                    hqq[a][b] += s * v[a] * v[b];
                }
            }
            diag.push((self.kz + s, s));
        }
        State {
            pi,
            grad,
            diag,
            hqq,
        }
    }

    /// Newton step `−(H + μ I_q)⁻¹ ∇Π` through faer's sparse Cholesky.
    fn step(&self, st: &State, mu: f64) -> Result<Vec<f64>, SceneError> {
        let n = self.n();
        let nq = self.nq;
        let mut trip: Vec<Triplet<usize, usize, f64>> = Vec::with_capacity((nq + 1) * n + 6);
        for (gi, (_, range)) in self.groups.iter().enumerate() {
            let (hww, s) = st.diag[gi];
            trip.push(Triplet::new(gi, gi, hww));
            let g = self.tp[range.start].g;
            let v = [1.0, g[0], g[1]];
            for a in 0..nq {
                trip.push(Triplet::new(n + a, gi, s * v[a]));
            }
        }
        for a in 0..nq {
            for b in 0..=a {
                let reg = if a == b { mu } else { 0.0 };
                trip.push(Triplet::new(n + a, n + b, st.hqq[a][b] + reg));
            }
        }
        let m = SparseColMat::<usize, f64>::try_new_from_triplets(n + nq, n + nq, &trip)
            .map_err(|e| SceneError::NoEquilibrium(format!("compliant matrix: {e:?}")))?;
        let llt = m
            .sp_cholesky(Side::Lower)
            .map_err(|e| SceneError::NoEquilibrium(format!("compliant factorisation: {e:?}")))?;
        let mut rhs = Col::from_fn(n + nq, |i| -st.grad[i]);
        llt.solve_in_place(&mut rhs);
        Ok((0..n + nq).map(|i| rhs[i]).collect())
    }
}

/// Compliant equilibrium from the rigid-tilt state (rigid-z under a locked mount): sparse damped
/// Newton until the force balance holds to `force_rtol`·W, the moment balance `M_c = K_t·t` to
/// `moment_rtol`·W·L and every sphere's spring balance to `force_rtol`·W. Cost per iteration:
/// O(P) assembly plus a sparse Cholesky of n + 3 unknowns (n + 1 locked; n slider spheres with
/// candidate pairs), i.e. O(n).
pub(crate) fn solve_compliant<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    load: f64,
) -> Result<Equilibrium, SceneError> {
    let (bp, zref) = body_pairs::<L>(ctx, ps);
    let (q0, it0) = if ctx.tilts {
        rigid_tilt_state(ctx, ps, &bp, load)?
    } else {
        let (z, it) = ZRoot::new(&bp, [0.0, 0.0], ctx.two_r, ctx.hertz.k()).solve(ctx, load)?;
        ([z, 0.0, 0.0], it)
    };
    let nq = if ctx.tilts { 3 } else { 1 };
    let sys = System {
        k: ctx.hertz.k(),
        two_r: ctx.two_r,
        tp: bp,
        groups: ps.groups(),
        load,
        kz: ctx.params.k_slider_z,
        nq,
        kq: ctx.kq(),
    };
    let n = sys.n();
    // Start: the rigid pose, springs pre-loaded with the rigid sphere forces.
    let mut x = vec![0.0; n + nq];
    x[n..].copy_from_slice(&q0[..nq]);
    let st0 = sys.eval(&x);
    for gi in 0..n {
        x[gi] = -(st0.grad[gi]) / sys.kz; // grad = k·0 − f
    }
    let mut st = sys.eval(&x);
    let tol_f = ctx.params.force_rtol * load;
    let tol_m = ctx.params.moment_rtol * load;
    let mut iters = it0;
    let mut converged = false;
    for _ in 0..ctx.params.max_iter {
        iters += 1;
        let ok_w = st.grad[..n].iter().all(|g| g.abs() <= tol_f);
        if ok_w && st.grad[n].abs() <= tol_f && st.grad[n + 1..].iter().all(|g| g.abs() <= tol_m) {
            converged = true;
            break;
        }
        let dmax = st.hqq[0][0]
            .max(st.hqq[1][1])
            .max(st.hqq[2][2])
            .max(f64::MIN_POSITIVE);
        let d = sys.step(&st, 1e-10 * dmax)?;
        let norm = d.iter().map(|v| v * v).sum::<f64>().sqrt();
        if !norm.is_finite() {
            return Err(SceneError::NoEquilibrium(
                "compliant Newton step is not finite".into(),
            ));
        }
        let cap = if norm > ctx.two_r {
            ctx.two_r / norm
        } else {
            1.0
        };
        if !sys.line_search(&mut x, &mut st, &d, cap) {
            break;
        }
        if x[n + 1..].iter().any(|v| v.abs() > ctx.two_r) {
            return Err(SceneError::NoEquilibrium(
                "the compliant slider tips over: load point outside the support of its contacts"
                    .into(),
            ));
        }
    }
    if !converged {
        // Accept a round-off stall only if the force balance holds to 1e-9 (the guarantee).
        let worst = st.grad.iter().fold(0.0f64, |m, g| m.max(g.abs()));
        if st.grad[n].abs() > 1e-9 * load || worst > 1e-6 * load {
            return Err(SceneError::NoEquilibrium(format!(
                "compliant Newton did not converge: force residual {:e} N, worst residual {worst:e}",
                st.grad[n]
            )));
        }
    }
    let mut defl = vec![0.0; ps.slider_xy.len()];
    for (gi, (i, _)) in sys.groups.iter().enumerate() {
        defl[*i as usize] = x[gi];
    }
    Ok(assemble(
        ctx,
        ps,
        &sys.tp,
        zref,
        Model::Compliant,
        load,
        sys.q(&x),
        |i| defl[i as usize],
        iters,
        f64::NEG_INFINITY,
    ))
}
