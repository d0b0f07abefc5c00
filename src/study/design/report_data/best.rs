//! The best patterns of a multi-pattern design and their contacts: the equilibrium of each
//! one's rank-1 design at the load it stays superlubric to, for the report's contact maps.

use crate::study::design::model::{rank, DesignOutcome, PatternResult};
use anyhow::Result;
use surrogate::solver::{Equilibrium, Model, SearchKind};
use surrogate::units::{deg_to_rad, mn_to_n};
use surrogate::Scene;

/// How many of the best patterns a multi-pattern design shows in full (contact maps and
/// tolerance maps) and searches over the tolerance box for certain (the robust floor of
/// [`crate::study::design::design`]).
pub const BEST_PATTERNS: usize = 3;

/// One of the best patterns: its rank-1 design's scene and equilibrium.
#[derive(Debug, Clone)]
pub struct BestPattern {
    /// The pattern's scene with θ set to the design's, named as in the design.
    pub scene: Scene,
    /// The load of the map (mN): the robust superlubric limit, or the nominal one when the
    /// design holds only at its nominal orientation.
    pub load_mn: f64,
    /// The equilibrium at the default placement.
    pub eq: Equilibrium,
}

/// The rank-1 design of `pr` and the load it stays superlubric to (robust, else nominal; mN),
/// or `None` when no design of the pattern is superlubric at any load.
pub fn best_design(pr: &PatternResult) -> Option<(f64, f64)> {
    let c = pr.ranking.first()?;
    let w = if c.score.superlubric_to_mn > 0.0 {
        c.score.superlubric_to_mn
    } else {
        c.score.nominal_to_mn
    };
    (w > 0.0).then_some((c.theta_deg, w))
}

/// Every pattern of `o`, best first (indices into `o.patterns`): ordered by its rank-1 design
/// with the ranking's own order ([`rank::compare`]: the robust limit, the tolerance
/// windows, μ_est, contacts, then θ and α), then in the order given; patterns without a
/// candidate last. Cost: O(n log n) over the patterns.
pub fn pattern_order(o: &DesignOutcome) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..o.patterns.len()).collect();
    // a stable sort: exact ties keep the order given
    idx.sort_by(
        |&a, &b| match (o.patterns[a].ranking.first(), o.patterns[b].ranking.first()) {
            (Some(x), Some(y)) => rank::compare(x, y),
            (Some(_), None) => std::cmp::Ordering::Less,
            (None, Some(_)) => std::cmp::Ordering::Greater,
            (None, None) => std::cmp::Ordering::Equal,
        },
    );
    idx
}

/// The first `n` patterns of [`pattern_order`] whose rank-1 design is superlubric at some load
/// ([`best_design`]), as indices into `o.patterns`. Cost: as [`pattern_order`].
pub fn best_order(o: &DesignOutcome, n: usize) -> Vec<usize> {
    pattern_order(o)
        .into_iter()
        .filter(|&i| best_design(&o.patterns[i]).is_some())
        .take(n)
        .collect()
}

/// Pattern `i` of `o` with its rank-1 design's equilibrium at the load of [`best_design`]
/// ([`crate::study::contacts::contacts`], the screen's load-sharing model), `None` when it has
/// no superlubric design. Cost: one solver build and one solve (milliseconds for 3 500 spheres).
pub fn best_contacts(o: &DesignOutcome, i: usize) -> Result<Option<BestPattern>> {
    let pr = &o.patterns[i];
    let Some((theta_deg, load_mn)) = best_design(pr) else {
        return Ok(None);
    };
    let mut scene = pr.scene.scene.clone();
    scene.slider.theta = deg_to_rad(theta_deg);
    scene.pattern = pr.scene.name.clone();
    let cp = crate::study::contacts::ContactsParams {
        theta: scene.slider.theta,
        load: mn_to_n(load_mn),
        model: Model::Auto,
        search: SearchKind::Grid,
    };
    let eq = crate::study::contacts::contacts(&scene, &cp)?;
    Ok(Some(BestPattern { scene, load_mn, eq }))
}
