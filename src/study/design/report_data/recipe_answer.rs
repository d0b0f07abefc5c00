//! Which recipe of `design --vary` the design names, per pattern the recipes were made from:
//! the recipes best first ([`super::best::pattern_order`]), each with its answer
//! ([`crate::study::design::model::answer`]) and why it lies outside the validated range
//! ([`crate::study::design::model::answer::outside_range`]). Inside the range the surrogate's answer stands (checked
//! by the DEM as any pattern's); outside it the DEM decides: such a recipe is named only when
//! the DEM confirmed it at its centre and its tolerance-box corners, and without the DEM
//! (`--no-dem`) it is named as unconfirmed.

use crate::study::design::model::answer::{outside_range, Check};
use crate::study::design::model::DesignOutcome;
use crate::study::recipe::Outside;

/// How a recipe stands for naming.
#[derive(Debug, Clone, PartialEq)]
pub enum Naming {
    /// Inside the validated range: the surrogate's answer, as for any pattern.
    Surrogate,
    /// Outside it, and the DEM confirmed its answer at its centre and its box corners.
    DemConfirmed,
    /// Outside it, and the DEM contradicted its answer or did not check it (the answer's
    /// [`Check`] says which): not named.
    Refused,
    /// Outside it, and the DEM did not run (`--no-dem`): named only as unconfirmed.
    Unconfirmed,
}

impl Naming {
    /// Whether a recipe so standing can be named the best recipe.
    pub fn nameable(&self) -> bool {
        !matches!(self, Naming::Refused)
    }
}

/// One recipe with an answer design superlubric at some load.
#[derive(Debug, Clone, PartialEq)]
pub struct RecipeDecision {
    /// Index into the outcome's patterns.
    pub pattern: usize,
    /// The pattern the recipe was made from.
    pub base: String,
    /// Index into the recipe's ranking of its answer's design.
    pub design: usize,
    /// Why the answer's design lies outside the validated range (empty: inside).
    pub outside: Vec<Outside>,
    /// What the DEM says of it.
    pub check: Check,
    /// How it stands for naming.
    pub naming: Naming,
}

/// Every recipe of `o` whose answer is superlubric at some load (robust limit, else nominal),
/// best first, with how it stands ([`Naming`]). Empty without recipes. Cost: as
/// [`super::best::pattern_order`].
pub fn decisions(o: &DesignOutcome) -> Vec<RecipeDecision> {
    let mut out = Vec::new();
    for i in super::best::pattern_order(o) {
        let pr = &o.patterns[i];
        let Some(facts) = &pr.scene.recipe else {
            continue;
        };
        let a = &o.answers[i];
        let Some((k, c)) = a.index.and_then(|k| pr.ranking.get(k).map(|c| (k, c))) else {
            continue;
        };
        if c.score.superlubric_to_mn <= 0.0 && c.score.nominal_to_mn <= 0.0 {
            continue;
        }
        let outside = outside_range(pr, c);
        let naming = if outside.is_empty() {
            Naming::Surrogate
        } else {
            match a.check {
                Check::NoDem => Naming::Unconfirmed,
                Check::Confirmed(_) => Naming::DemConfirmed,
                Check::Unchecked | Check::Contradicted(_) => Naming::Refused,
            }
        };
        out.push(RecipeDecision {
            pattern: i,
            base: facts.base.clone(),
            design: k,
            outside,
            check: a.check.clone(),
            naming,
        });
    }
    out
}

/// The recipe named for the base pattern `base`: the first of `d` (best first) made from it
/// that can be named ([`Naming::nameable`]), with the better ones the DEM refused before it.
/// `None` when no recipe of `base` can be named.
pub fn named<'a>(
    d: &'a [RecipeDecision],
    base: &str,
) -> (Option<&'a RecipeDecision>, Vec<&'a RecipeDecision>) {
    let mut refused = Vec::new();
    for r in d.iter().filter(|r| r.base == base) {
        if r.naming.nameable() {
            return (Some(r), refused);
        }
        refused.push(r);
    }
    (None, refused)
}
