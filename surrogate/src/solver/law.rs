//! The vertical Hertz law of one pair, written in the offset from its touch height so that
//! tiny overlaps (grazing contacts, nN loads on thousands of contacts) keep full precision.

use super::ctx::Ctx;
use super::PairSet;

/// Vertical response of one sphere pair.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct PairResponse {
    /// Vertical force on the slider sphere (N).
    pub fz: f64,
    /// −dF_z/du (N/m).
    pub s: f64,
    /// Elastic energy Φ (J).
    pub phi: f64,
    /// Overlap δ (m).
    pub delta: f64,
}

/// Response of a pair at lateral distance² `r2` (m²) whose vertical centre gap is
/// `u = u_t + dz` (m), `u_t = √(4R² − r²)` being the gap at first touch:
/// `D = √(r² + u²)`, `δ = 2R − D = −dz (u_t + u) / (2R + D)` (no cancellation),
/// `F_n = k δ^{3/2}` (k = (4/3)E*√R_eff), `F_z = F_n u / D`,
/// `s = −dF_z/du = 1.5 k √δ u²/D² − F_n r²/D³`, `Φ = 0.4 k δ^{5/2}` (dΦ/du = −F_z).
/// All zero when `dz ≥ 0` (no overlap) or `u ≤ 0`. O(1).
#[inline]
pub(crate) fn pair_response(k: f64, two_r: f64, r2: f64, ut: f64, dz: f64) -> PairResponse {
    let u = ut + dz;
    if dz >= 0.0 || u <= 0.0 {
        return PairResponse::default();
    }
    let dd = (r2 + u * u).sqrt();
    let delta = -dz * (ut + u) / (two_r + dd);
    let sd = delta.sqrt();
    let fnorm = k * delta * sd;
    let inv = 1.0 / dd;
    PairResponse {
        fz: fnorm * u * inv,
        s: 1.5 * k * sd * u * u * inv * inv - fnorm * r2 * inv * inv * inv,
        phi: 0.4 * fnorm * delta,
        delta,
    }
}

/// One pair in the body unknowns `q = [ζ, L·t_x, L·t_y]` (ζ = z − z_ref): its offset from first
/// touch is `dz = ζ + q₁ g₀ + q₂ g₁ (+ w_i) − c` with `g = [y_arm/L, −x_arm/L]` and
/// `c = h + u_t − z_ref` the pair's touch height relative to the highest one (with per-site
/// sizes `c = h + (r_i − R_sl) + u_t − z_ref`, h the substrate centre height). `k` and `d` are
/// the pair's Hertz prefactor and contact distance (the scene's one law, or per pair).
#[derive(Clone, Copy, Debug)]
pub(crate) struct BodyPair {
    pub g: [f64; 2],
    pub r2: f64,
    pub ut: f64,
    pub c: f64,
    pub k: f64,
    pub d: f64,
}

/// The pairs of `ps` in body unknowns, and the reference height z_ref (m): the highest touch
/// height `max(h + u_t)` (so ζ = 0 is first touch of a flat-lying slider). With per-site sizes
/// each pair has its own distance `d = r_i + r_j`, `u_t = √(d² − r²)`, `k` from
/// `R_eff = r_i r_j/(r_i + r_j)` and touch height `h + (r_i − R_sl) + u_t`. O(P).
pub(crate) fn body_pairs(ctx: &Ctx, ps: &PairSet) -> (Vec<BodyPair>, f64) {
    let d2 = ctx.two_r * ctx.two_r;
    let k = ctx.hertz.k();
    let mut zref = f64::NEG_INFINITY;
    let mut out: Vec<BodyPair> = ps
        .pairs
        .iter()
        .map(|p| {
            let a = ps.arm(p.slider);
            let g = [a[1] / ctx.scale, -a[0] / ctx.scale];
            match ctx.sizes {
                None => {
                    let ut = (d2 - p.r2).max(0.0).sqrt();
                    zref = zref.max(p.h + ut);
                    BodyPair {
                        g,
                        r2: p.r2,
                        ut,
                        c: p.h + ut,
                        k,
                        d: ctx.two_r,
                    }
                }
                Some(s) => {
                    let d = s.distance(p.slider, p.substrate);
                    let ut = (d * d - p.r2).max(0.0).sqrt();
                    let c = p.h + (s.slider[p.slider as usize] - s.r_sl) + ut;
                    zref = zref.max(c);
                    BodyPair {
                        g,
                        r2: p.r2,
                        ut,
                        c,
                        k: s.hertz(p.slider, p.substrate).k(),
                        d,
                    }
                }
            }
        })
        .collect();
    if !zref.is_finite() {
        zref = 0.0;
    }
    for b in &mut out {
        b.c -= zref;
    }
    (out, zref)
}
