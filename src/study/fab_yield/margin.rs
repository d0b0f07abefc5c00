//! A DEM run's margin transferred through one device's estimate ([`Ratios`],
//! [`transferred_limit`]).
//!
//! A DEM run at load W on a device measures P_DEM (its largest P_max over every step) and μ_DEM;
//! the device's estimate at the same load gives P_est(W) and μ_est(W), interpolated between
//! its single-load probes ([`super::critical::Probe`]). Their ratios ρ = P_DEM/P_est and
//! m = μ_est/μ_DEM (the quantities of the verdict band, `P_RATIO` and `MU_RATIO`) vary slowly
//! with the load, so the load at which the DEM's verdict turns is where the estimate, scaled by
//! them, crosses a threshold:
//!
//!   W* = the first W above the highest superlubric probe (below the first coating failure)
//!        where ρ·P_est(W) > P_crit or μ_est(W)/m ≥ μ_sl,
//!
//! found by linear interpolation between the probes bracketing the crossing. A friction failure
//! below a superlubric probe (scaled μ above μ_sl at a low load only) is a floor of the
//! device's superlubric range, not its limit; the yield counts the limit, and its DEM check at
//! the quoted load sees a floor that reaches it. The coating's failure (P_max rises with the
//! load) ends the range. The same function
//! with the band's worst and best ratios gives the bounds of a device's DEM critical load.
//! Cost: O(probes) per call.

use super::critical::Probe;

/// Ratios that map the estimate onto the DEM at the same load: P_DEM = `p`·P_est and
/// μ_DEM = μ_est/`mu`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ratios {
    /// ρ = P_DEM/P_est.
    pub p: f64,
    /// m = μ_est/μ_DEM.
    pub mu: f64,
}

impl Ratios {
    /// The identity (the estimate as it is).
    pub const ONE: Ratios = Ratios { p: 1.0, mu: 1.0 };
}

/// Linear interpolation of `f` over the `probes` (ascending load) at `w` (N); flat beyond the
/// ends; `None` where a bracketing probe has no value.
fn interpolate(probes: &[Probe], w: f64, f: impl Fn(&Probe) -> Option<f64>) -> Option<f64> {
    let k = probes.partition_point(|p| p.load < w);
    match (k.checked_sub(1).map(|i| &probes[i]), probes.get(k)) {
        (Some(a), Some(b)) if b.load > a.load => {
            let (fa, fb) = (f(a)?, f(b)?);
            Some(fa + (fb - fa) * (w - a.load) / (b.load - a.load))
        }
        (_, Some(b)) => f(b),
        (Some(a), None) => f(a),
        (None, None) => None,
    }
}

/// The estimate's P_max (GPa) and μ_est at `w` (N), interpolated between `probes`.
pub fn estimate_at(probes: &[Probe], w: f64) -> (Option<f64>, Option<f64>) {
    (
        interpolate(probes, w, |p| p.p_max_GPa),
        interpolate(probes, w, |p| p.mu_est),
    )
}

/// How far probe `p` is past the thresholds under `r`: max(ρ·P/P_crit, μ/(m·μ_sl)) − 1
/// (> 0: not superlubric; +∞ without an estimate).
fn excess(p: &Probe, r: Ratios, p_crit_gpa: f64, mu_sl: f64) -> f64 {
    match (p.p_max_GPa, p.mu_est) {
        (Some(pm), Some(mu)) => (r.p * pm / p_crit_gpa).max(mu / (r.mu * mu_sl)) - 1.0,
        _ => f64::INFINITY,
    }
}

/// The load (N) up to which the device of `probes` (ascending) stays superlubric when the
/// DEM is the estimate scaled by `r` (module docs): the crossing above its highest superlubric
/// probe below its first probe where the coating fails or there is no estimate (a friction
/// failure below a superlubric probe, μ above μ_sl at a low load only, is a floor, not its
/// limit; the coating's P_max only rises with the load); 0 when no such probe is superlubric,
/// its highest probe's load when that one is. Cost: O(probes).
pub fn transferred_limit(probes: &[Probe], r: Ratios, p_crit_gpa: f64, mu_sl: f64) -> f64 {
    let g: Vec<f64> = probes
        .iter()
        .map(|p| excess(p, r, p_crit_gpa, mu_sl))
        .collect();
    let coating_fails = |p: &Probe| p.p_max_GPa.is_none_or(|pm| r.p * pm > p_crit_gpa);
    let end = probes
        .iter()
        .zip(&g)
        .position(|(p, x)| !x.is_finite() || coating_fails(p))
        .unwrap_or(g.len());
    let Some(h) = g[..end].iter().rposition(|&x| x < 0.0) else {
        return 0.0;
    };
    let k = h + 1;
    if k == probes.len() {
        return probes[h].load;
    }
    let (a, b) = (&probes[h], &probes[k]);
    if !g[k].is_finite() {
        return a.load;
    }
    a.load + (b.load - a.load) * (-g[h]) / (g[k] - g[h])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn probe(load: f64, p: f64, mu: f64) -> Probe {
        Probe {
            load,
            p_max_GPa: Some(p),
            mu_est: Some(mu),
        }
    }

    /// P_max linear in W (1 GPa per N from 3 GPa at 1 N): P_crit 4 GPa is crossed at 2 N, and
    /// at 1.5 N when the DEM's P_max is 4/3.5 of the estimate's; μ crosses first when m is low.
    #[test]
    fn the_crossing_moves_with_the_ratio() {
        let probes: Vec<Probe> = (0..=4)
            .map(|i| {
                let w = 1.0 + 0.5 * i as f64;
                probe(w, 2.0 + w, 0.01)
            })
            .collect();
        let w = transferred_limit(&probes, Ratios::ONE, 4.0, 0.02);
        assert!((w - 2.0).abs() < 1e-12, "{w}");
        let w = transferred_limit(
            &probes,
            Ratios {
                p: 4.0 / 3.5,
                mu: 1.0,
            },
            4.0,
            0.02,
        );
        assert!((w - 1.5).abs() < 1e-12, "{w}");
        // μ_DEM = 2 μ_est = 0.02 everywhere: the rule fails at the first probe
        let w = transferred_limit(&probes, Ratios { p: 1.0, mu: 0.5 }, 4.0, 0.02);
        assert_eq!(w, 0.0);
        // an error probe ends it at the last good one
        let mut e = probes.clone();
        e[2].p_max_GPa = None;
        let w = transferred_limit(&e, Ratios { p: 0.5, mu: 1.0 }, 4.0, 0.02);
        assert_eq!(w, 1.5);
        // friction fails at the lowest probe only: a floor; the limit is P_max's crossing
        let mut f = probes.clone();
        f[0].mu_est = Some(0.03);
        let w = transferred_limit(&f, Ratios::ONE, 4.0, 0.02);
        assert!((w - 2.0).abs() < 1e-12, "{w}");
        // the coating fails at 2.5 N: a superlubric probe above it does not extend the range
        let mut c = probes.clone();
        c[4].p_max_GPa = Some(3.9);
        let w = transferred_limit(&c, Ratios::ONE, 4.0, 0.02);
        assert!((w - 2.0).abs() < 1e-12, "{w}");
        let (p, mu) = estimate_at(&probes, 1.25);
        assert!((p.unwrap() - 3.25).abs() < 1e-12 && mu == Some(0.01));
    }
}
