//! Test fixtures of the design's data: a pattern holding only a hand-made ranking.

use super::rank::{Candidate, Pick, Score};
use super::{DesignScene, PatternResult};
use crate::study::design::symmetry_words::PairSymmetry;

/// The preset pattern `name` with a ranking of `n` designs θ = 0°, 1°, … (α 90°), each exact
/// and superlubric to 3.86 mN, without friction rows.
pub fn pattern(name: &str, n: usize) -> PatternResult {
    let scene = surrogate::Scene::preset(name).unwrap();
    let sym = PairSymmetry::of(&scene.slider.lattice, &scene.substrate.lattice);
    let ranking = (0..n)
        .map(|k| Candidate {
            pattern: name.into(),
            theta_deg: k as f64,
            alpha_deg: 90.0,
            line_deg: 0.0,
            direction_deg: 90.0,
            corrugation_nm: 0.1,
            scan_load_mn: 3.86,
            screen_intact_to_mn: 3.86,
            reason: Pick::Top,
            friction: vec![],
            corners: vec![],
            score: Score {
                superlubric_to_mn: 3.86,
                nominal_to_mn: 3.86,
                theta_window_deg: None,
                direction_window_deg: None,
                verdict: crate::study::verdict::Verdict::Superlubric,
                exact: true,
                intact_to_mn: 3.86,
                mu_worst: 0.01,
                contacts: 100.0,
                seed_limits_mn: None,
                yield_to_mn: None,
                below_ladder_mn: None,
            },
        })
        .collect();
    PatternResult::of_ranking(
        DesignScene {
            name: name.into(),
            scene,
            flags: vec![],
            warnings: vec![],
            facts: None,
            recipe: None,
        },
        sym,
        ranking,
    )
}
