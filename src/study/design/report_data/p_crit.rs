//! How the best recipe's robust limit moves with the coating's strength P_crit (the study calls
//! its 4 GPa "somewhat arbitrary"): its answer's design re-evaluated over its tolerance box at
//! P_crit = 3.6, 4.0 and 4.4 GPa ([`P_CRIT_SWEEP_GPA`]).
//!
//! A new search per value, not a re-reading of the design's rows: above P_crit a contact's
//! coating fails and its friction switches from μ1 to μ2, so μ_est itself depends on P_crit,
//! and the design's robust search stopped at its first failing sample, so the loads above its
//! limit (which a stronger coating may hold) were never estimated there. The value equal to the
//! scene's own P_crit reuses the design's score. Stored under `stages/<pattern>/p_crit.json`.
//! Cost: one robust search per other value (about as much as the design's own search of that
//! design: seconds to tens of seconds on the study scenes, docs/validation/tolerance-cost.md).

use crate::runs::meta::{scene_file, Inputs};
use crate::study::design::limit::{seed_solvers, LimitKnobs};
use crate::study::design::model::{Candidate, DesignScene};
pub use crate::study::design::model::{PCritLimit, PCritSweep, P_CRIT_SWEEP_GPA};
use crate::study::design::store::Store;
use crate::study::load::LoadKey;
use crate::study::tolerance::{placement_intact, rows_upto, superlubric_count, LimitParams};
use crate::study::tolerance::{RobustSearch, ToleranceBox};
use crate::study::verdict::Verdict;
use anyhow::Result;
use serde_json::json;
use surrogate::units::{deg_to_rad, gpa_to_pa, pa_to_gpa};

/// The robust limit (load count) and verdict of the design (θ, direction) on `ds`'s scene at
/// its own P_crit, over the box `bx` and every seed of `p`.
fn robust_limit(
    ds: &DesignScene,
    theta_deg: f64,
    direction_deg: f64,
    guess: usize,
    bx: &ToleranceBox,
    p: &LimitKnobs,
    limit: &LimitParams,
) -> Result<(usize, Verdict)> {
    let solvers = seed_solvers(ds, &p.tolerance.seeds, None)?;
    let cap = placement_intact(&solvers[0], deg_to_rad(theta_deg), &p.loads);
    let (rows, _) = rows_upto(&solvers[0], theta_deg, direction_deg, cap, guess, limit)?;
    let p_crit = ds.scene.coating.p_crit;
    if bx.is_point() {
        let n = superlubric_count(&rows, p_crit, p.mu_superlubric);
        let v = Verdict::worst(rows.iter().take(n), p.mu_superlubric, p_crit);
        return Ok((n, if n == 0 { Verdict::Not } else { v }));
    }
    let mut s = RobustSearch::new(&solvers, theta_deg, direction_deg, &rows, bx, limit);
    s.run_above(0)?;
    let r = s.result();
    Ok((r.superlubric_to, r.verdict))
}

/// The sweep of the design `c` of `ds` (see the module docs); stored in `store` and reused.
pub fn p_crit_sweep(
    ds: &DesignScene,
    c: &Candidate,
    p: &LimitKnobs,
    store: &Store,
) -> Result<PCritSweep> {
    let bx = p.tolerance_box();
    let inputs = Inputs {
        workflow: "design/p-crit".into(),
        scene: Some(scene_file(&ds.scene.with_theta(deg_to_rad(c.theta_deg)))),
        params: json!({
            "theta_deg": c.theta_deg,
            "direction_deg": c.direction_deg,
            "p_crit_GPa": P_CRIT_SWEEP_GPA,
            "theta_tol_deg": p.tolerance.theta_tol_deg,
            "direction_tol_deg": p.tolerance.direction_tol_deg,
            "theta_tol_step_deg": p.tolerance.theta_tol_step_deg,
            "direction_tol_step_deg": p.tolerance.direction_tol_step_deg,
            "seeds": p.tolerance.seeds,
            "limit": p.record(),
        }),
    };
    let rel = format!("stages/{}/p_crit.json", ds.name);
    if let Some(s) = store.load_json::<PCritSweep>(&rel, &inputs)? {
        return Ok(s);
    }
    let limit = p.limit();
    let guess = p
        .loads
        .position(LoadKey::of_mn(c.score.superlubric_to_mn))
        .map_or(0, |k| k + 1);
    let mut limits = Vec::new();
    for gpa in P_CRIT_SWEEP_GPA {
        let p_crit = gpa_to_pa(gpa);
        let own = (pa_to_gpa(ds.scene.coating.p_crit) - gpa).abs() < 1e-9;
        let (to_mn, verdict) = if own {
            (c.score.superlubric_to_mn, c.score.verdict)
        } else {
            let mut d = ds.clone();
            d.scene.coating.p_crit = p_crit;
            let (n, v) = robust_limit(&d, c.theta_deg, c.direction_deg, guess, &bx, p, &limit)?;
            (p.loads.limit_mn(n), v)
        };
        limits.push(PCritLimit {
            p_crit,
            superlubric_to_mn: to_mn,
            verdict,
            own,
        });
    }
    let s = PCritSweep {
        pattern: ds.name.clone(),
        theta_deg: c.theta_deg,
        direction_deg: c.direction_deg,
        limits,
    };
    store.save_json(&rel, &inputs, &s)?;
    Ok(s)
}
