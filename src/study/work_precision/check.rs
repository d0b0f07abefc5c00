//! The convergence checks of the diagrams (the rule for defaults): each knob's error
//! falls as the knob is refined, within the stated noise; the DEM's error at its default step
//! is below the friction window's standard error; no default has a coarser neighbour with the
//! same error within noise, nor an error that changes the reference's verdict. Each check
//! returns its findings in words (empty: the check holds).

use super::{Knob, Tier, WorkPrecisionRow};

/// Relative difference below which two errors of a deterministic tier are equal: the solver's
/// tolerances (force 1e-12, moment 1e-10 relative) leave ~1e-9 in P_max and μ; 1e-6 is well
/// above that and well below any error a user reads.
pub const DETERMINISTIC_NOISE: f64 = 1e-6;

/// The noise of comparing two rows' errors: their stated noises in quadrature, at least
/// [`DETERMINISTIC_NOISE`].
fn noise(a: &WorkPrecisionRow, b: &WorkPrecisionRow) -> f64 {
    a.noise_rel.hypot(b.noise_rel).max(DETERMINISTIC_NOISE)
}

/// The numeric knobs of `rows` as (scene, knob, rows ordered coarse → fine, the reference
/// left out).
pub fn ladders(rows: &[WorkPrecisionRow]) -> Vec<(String, Knob, Vec<&WorkPrecisionRow>)> {
    let mut keys: Vec<(String, Knob)> = Vec::new();
    for r in rows {
        let k = (r.scene.clone(), r.knob);
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    keys.into_iter()
        .filter_map(|(scene, knob)| {
            let up = knob.larger_is_finer()?;
            let mut v: Vec<&WorkPrecisionRow> = rows
                .iter()
                .filter(|r| r.scene == scene && r.knob == knob && !r.is_reference)
                .filter(|r| r.setting_value.is_some() && r.note.find("failed").is_none())
                .collect();
            v.sort_by(|a, b| {
                let (x, y) = (a.setting_value.unwrap(), b.setting_value.unwrap());
                if up {
                    x.total_cmp(&y)
                } else {
                    y.total_cmp(&x)
                }
            });
            Some((scene, knob, v))
        })
        .collect()
}

/// Whether a knob is exercised on a scene: some setting's error is above the noise (a path
/// length on a periodic path, or inertial starts in steady sliding, are not).
fn exercised(v: &[&WorkPrecisionRow]) -> bool {
    v.iter()
        .any(|r| r.error_rel > r.noise_rel.max(DETERMINISTIC_NOISE))
}

/// Each knob's error falls (within noise) as it is refined: every finer setting's error is at
/// most the coarser one's plus the noise of the two.
pub fn monotone(rows: &[WorkPrecisionRow]) -> Vec<String> {
    let mut out = Vec::new();
    for (scene, knob, v) in ladders(rows) {
        for w in v.windows(2) {
            let (c, f) = (w[0], w[1]);
            if f.error_rel > c.error_rel + noise(c, f) {
                out.push(format!(
                    "{scene}, {knob}: error rises from {:.3e} at {} to {:.3e} at {} (noise {:.1e})",
                    c.error_rel,
                    c.setting,
                    f.error_rel,
                    f.setting,
                    noise(c, f)
                ));
            }
        }
    }
    out
}

/// The relative errors of a row that its tier is judged by, quantity by quantity (`None` where
/// not measured; the friction estimate's mean contacts are not judged).
fn components(r: &WorkPrecisionRow) -> [Option<f64>; 8] {
    [
        r.err_mu_rel,
        r.err_p_max_rel,
        r.err_contacts_rel.filter(|_| r.tier != Tier::Friction),
        r.err_corrugation_rel,
        r.err_max_pull_rel,
        r.err_landscape_range_rel,
        r.err_limit_rel,
        r.err_window_rel,
    ]
}

/// Whether two settings have the same error within `noise` in every quantity both measured.
fn same_error(a: &WorkPrecisionRow, b: &WorkPrecisionRow, noise: f64) -> bool {
    components(a)
        .iter()
        .zip(components(b))
        .all(|(x, y)| match (x, y) {
            (Some(x), Some(y)) => (x - y).abs() <= noise,
            _ => true,
        })
}

/// What the rule for defaults finds ([`default_front`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Front {
    /// Defaults the rule would move: a coarser neighbour with the same error (every quantity)
    /// within noise, or a verdict the reference does not give.
    pub moves: Vec<String>,
    /// Knobs where the noise exceeds the errors of the default and its coarser neighbour: the
    /// rule cannot decide (lengthen the window rather than read noise as agreement).
    pub unresolved: Vec<String>,
    /// Knobs that no setting exercises on a scene (every error within the noise), left out.
    pub not_exercised: Vec<String>,
}

/// The rule for defaults: a default is moved when a coarser setting has the same error within
/// its noise (in every quantity measured), or when the default's error changes the verdict a
/// finer setting gives.
pub fn default_front(rows: &[WorkPrecisionRow]) -> Front {
    let mut out = Front::default();
    for (scene, knob, v) in ladders(rows) {
        if !exercised(&v) {
            out.not_exercised.push(format!("{scene}, {knob}"));
            continue;
        }
        let Some(i) = v.iter().position(|r| r.is_default) else {
            continue;
        };
        let d = v[i];
        if d.verdict_changed {
            out.moves.push(format!(
                "{scene}, {knob}: the default {} gives the verdict `{}`, the reference another",
                d.setting, d.verdict
            ));
        }
        if i > 0 {
            let c = v[i - 1];
            let n = noise(c, d);
            if n >= c.error_rel.max(d.error_rel) && n > DETERMINISTIC_NOISE {
                out.unresolved.push(format!(
                    "{scene}, {knob}: the errors of the default {} ({:.3e}) and the coarser {} \
                     ({:.3e}) are below the noise {:.1e}",
                    d.setting, d.error_rel, c.setting, c.error_rel, n
                ));
            } else if same_error(c, d, n) && !c.verdict_changed {
                out.moves.push(format!(
                    "{scene}, {knob}: the coarser {} has the default {}'s error within noise \
                     ({:.3e} vs {:.3e}, noise {:.1e}) at {:.2}× less CPU",
                    c.setting,
                    d.setting,
                    c.error_rel,
                    d.error_rel,
                    n,
                    d.cost_cpu_s / c.cost_cpu_s.max(1e-12)
                ));
            }
        }
    }
    out
}

/// The DEM's μ error at the default step is below the friction window's standard error (its
/// stated noise), on every scene.
pub fn dem_default_step(rows: &[WorkPrecisionRow]) -> Vec<String> {
    rows.iter()
        .filter(|r| r.tier == Tier::Dem && r.knob == Knob::DtFraction && r.is_default)
        .filter_map(|r| {
            let e = r.err_mu_rel?;
            (e > r.noise_rel).then(|| {
                format!(
                    "{}: μ error {:.3e} at the default step exceeds the window's standard error {:.3e}",
                    r.scene, e, r.noise_rel
                )
            })
        })
        .collect()
}

/// The tolerance of [`speed_only_identical`] for a row: [`DETERMINISTIC_NOISE`], or for the
/// DEM the larger of it and the window's standard error (`noise_rel`). The active set is exact
/// to round-off, not bit-identical (it sums forces in another order); a chaotic slide
/// (stick-slip) grows any round-off difference into another slip sequence — a load changed by
/// 10⁻¹⁵ does the same, measured in docs/validation/work-precision.md — so there the two runs
/// are two samples of the same slide and can only agree within the window's noise.
pub fn speed_only_tolerance(r: &WorkPrecisionRow) -> f64 {
    if r.tier == Tier::Dem {
        r.noise_rel.max(DETERMINISTIC_NOISE)
    } else {
        DETERMINISTIC_NOISE
    }
}

/// The speed-only knobs change nothing: every setting's error is within its
/// [`speed_only_tolerance`] (stated in each finding).
pub fn speed_only_identical(rows: &[WorkPrecisionRow]) -> Vec<String> {
    rows.iter()
        .filter(|r| r.knob.speed_only() && r.error_rel > speed_only_tolerance(r))
        .map(|r| {
            format!(
                "{}, {} = {}: the output moved by {:.3e} (tolerance {:.1e})",
                r.scene,
                r.knob,
                r.setting,
                r.error_rel,
                speed_only_tolerance(r)
            )
        })
        .collect()
}

/// The tiers diagram is ordered as the README's tier table says: on every scene the screen
/// costs less CPU than the estimate, the estimate less than the full DEM at its default step,
/// and in every quantity a cheaper tier gives (the screen: P_max; the estimate: μ and P_max)
/// the full DEM's error against the best reference is below the cheaper tier's.
pub fn tiers_ordered(rows: &[WorkPrecisionRow]) -> Vec<String> {
    use super::tiers::Method;
    let mut out = Vec::new();
    let mut scenes: Vec<&str> = Vec::new();
    for r in rows.iter().filter(|r| r.tier == Tier::Tiers) {
        if !scenes.contains(&r.scene.as_str()) {
            scenes.push(&r.scene);
        }
    }
    for scene in scenes {
        let find = |m: Method| {
            rows.iter().find(|r| {
                r.tier == Tier::Tiers && r.scene == scene && Method::parse(&r.setting) == Some(m)
            })
        };
        let (Some(sc), Some(es), Some(de)) = (
            find(Method::Screen),
            find(Method::Estimate),
            find(Method::DemFull),
        ) else {
            out.push(format!(
                "{scene}: the screen, estimate or DEM row is missing"
            ));
            continue;
        };
        for (a, b) in [(sc, es), (es, de)] {
            if a.cost_cpu_s >= b.cost_cpu_s {
                out.push(format!(
                    "{scene}: {} costs {:.3e} s CPU, not less than {}'s {:.3e} s",
                    a.setting, a.cost_cpu_s, b.setting, b.cost_cpu_s
                ));
            }
        }
        for cheaper in [sc, es] {
            let pairs = [
                ("μ", cheaper.err_mu_rel, de.err_mu_rel),
                ("P_max", cheaper.err_p_max_rel, de.err_p_max_rel),
            ];
            for (q, c, d) in pairs {
                let Some(c) = c else { continue };
                match d {
                    Some(d) if d < c => {}
                    _ => out.push(format!(
                        "{scene}: the DEM's {q} error {d:?} is not below the {}'s {c:.3e}",
                        cheaper.setting
                    )),
                }
            }
        }
    }
    out
}
