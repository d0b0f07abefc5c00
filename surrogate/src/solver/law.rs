//! The vertical Hertz law of one pair as a function of the vertical centre gap, shared by the
//! load-sharing models.

/// Vertical response of one sphere pair at lateral distance² `r2` (m²) and vertical centre gap
/// `u` (m, slider centre minus substrate centre): `D = √(r² + u²)`, `δ = 2R − D`,
/// `F_n = k δ^{3/2}` (k = (4/3)E*√R_eff), `F_z = F_n u / D`,
/// stiffness `s = −dF_z/du = 1.5 k √δ u²/D² − F_n r²/D³`, potential `Φ = 0.4 k δ^{5/2}`
/// (so `dΦ/du = −F_z`). All zero when the spheres do not overlap or `u ≤ 0`.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct PairResponse {
    /// Vertical force on the slider sphere (N).
    pub fz: f64,
    /// −dF_z/du (N/m).
    pub s: f64,
    /// Elastic energy Φ (J).
    pub phi: f64,
}

/// Evaluates [`PairResponse`]. O(1).
#[inline]
pub(crate) fn pair_response(k: f64, two_r: f64, r2: f64, u: f64) -> PairResponse {
    if u <= 0.0 {
        return PairResponse::default();
    }
    let dd = (r2 + u * u).sqrt();
    let delta = two_r - dd;
    if delta <= 0.0 {
        return PairResponse::default();
    }
    let sd = delta.sqrt();
    let fnorm = k * delta * sd;
    let inv = 1.0 / dd;
    PairResponse {
        fz: fnorm * u * inv,
        s: 1.5 * k * sd * u * u * inv * inv - fnorm * r2 * inv * inv * inv,
        phi: 0.4 * fnorm * delta,
    }
}
