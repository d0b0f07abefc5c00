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

/// The pair-law constants a [`BodyPair`] carries: none ([`Shared`]: the scene's one Hertz
/// prefactor k and contact distance d, one sphere size per body — the fast path) or its own
/// ([`Own`]: per-site sizes). Every model is generic over it, so the fast path keeps its
/// 40-byte pairs and its arithmetic.
pub(crate) trait Law: Copy + std::fmt::Debug {
    /// Whether pairs carry their own law (per-site sizes).
    const SIZED: bool;
    /// The law of slider sphere `i` on substrate sphere `j`: itself, its contact distance d (m)
    /// and the slider sphere's drop `r_i − R_sl` (m) below the reference plane.
    fn of(ctx: &Ctx, i: u32, j: u32) -> (Self, f64, f64);
    /// `(k, d)`: this pair's, or the shared `k`, `d` given.
    fn kd(&self, k: f64, d: f64) -> (f64, f64);
}

/// The scene's one law (one sphere size per body).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Shared;

impl Law for Shared {
    const SIZED: bool = false;
    #[inline]
    fn of(ctx: &Ctx, _: u32, _: u32) -> (Self, f64, f64) {
        (Shared, ctx.two_r, 0.0)
    }
    #[inline]
    fn kd(&self, k: f64, d: f64) -> (f64, f64) {
        (k, d)
    }
}

/// A pair's own Hertz prefactor k (N/m^{3/2}) and contact distance d = r_i + r_j (m).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Own {
    k: f64,
    d: f64,
}

impl Law for Own {
    const SIZED: bool = true;
    #[inline]
    fn of(ctx: &Ctx, i: u32, j: u32) -> (Self, f64, f64) {
        let s = ctx.sizes.expect("per-site sizes");
        let d = s.distance(i, j);
        let k = s.hertz(i, j).k();
        (Own { k, d }, d, s.slider[i as usize] - s.r_sl)
    }
    #[inline]
    fn kd(&self, _: f64, _: f64) -> (f64, f64) {
        (self.k, self.d)
    }
}

/// One pair in the body unknowns `q = [ζ, L·t_x, L·t_y]` (ζ = z − z_ref): its offset from first
/// touch is `dz = ζ + q₁ g₀ + q₂ g₁ (+ w_i) − c` with `g = [y_arm/L, −x_arm/L]` and
/// `c = h + u_t − z_ref` the pair's touch height relative to the highest one (with per-site
/// sizes `c = h + (r_i − R_sl) + u_t − z_ref`, h the substrate centre height). `law`: the pair's
/// Hertz prefactor and contact distance when it has its own ([`Law`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct BodyPair<L> {
    pub g: [f64; 2],
    pub r2: f64,
    pub ut: f64,
    pub c: f64,
    pub law: L,
}

impl<L: Law> BodyPair<L> {
    /// [`pair_response`] at offset `dz` (m) with the shared `k`, `d` unless the pair has its own.
    #[inline]
    pub fn response(&self, k: f64, d: f64, dz: f64) -> PairResponse {
        let (k, d) = self.law.kd(k, d);
        pair_response(k, d, self.r2, self.ut, dz)
    }
}

/// The pairs of `ps` in body unknowns, and the reference height z_ref (m): the highest touch
/// height `max(h + u_t)` (so ζ = 0 is first touch of a flat-lying slider). With per-site sizes
/// ([`Own`]) each pair has its own distance `d = r_i + r_j`, `u_t = √(d² − r²)`, `k` from
/// `R_eff = r_i r_j/(r_i + r_j)` and touch height `h + (r_i − R_sl) + u_t`. O(P).
pub(crate) fn body_pairs<L: Law>(ctx: &Ctx, ps: &PairSet) -> (Vec<BodyPair<L>>, f64) {
    let d2 = ctx.two_r * ctx.two_r;
    let mut zref = f64::NEG_INFINITY;
    let mut out: Vec<BodyPair<L>> = ps
        .pairs
        .iter()
        .map(|p| {
            let a = ps.arm(p.slider);
            let (law, d, drop) = L::of(ctx, p.slider, p.substrate);
            let (ut, c) = if L::SIZED {
                let ut = (d * d - p.r2).max(0.0).sqrt();
                (ut, p.h + drop + ut)
            } else {
                let ut = (d2 - p.r2).max(0.0).sqrt();
                (ut, p.h + ut)
            };
            zref = zref.max(c);
            BodyPair {
                g: [a[1] / ctx.scale, -a[0] / ctx.scale],
                r2: p.r2,
                ut,
                c,
                law,
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
