//! The design's yield outputs, when its yield stage ran
//! ([`crate::study::design::yield_stage`]): per answer `yield_<p>.csv` (one row per device,
//! the `yield` schema), `yield_<p>.json` (the summary) and `yield_<p>.png` (yield against
//! load with its band, the quoted load marked), each with its sidecar; with `--rank-by yield`,
//! `yield_rank.csv` ([`YieldRankRow`]); and the report's
//! "load at q yield" column ([`cell`]) and plots ([`YieldHead`]).

use super::words::fmt_g;
use crate::plot::yield_curve::yield_png;
use crate::present::yield_words;
use crate::runs::output::Outputs;
use crate::runs::sink::csv_bytes;
use crate::study::design::answer::Answer;
use crate::study::design::store::Store;
use crate::study::design::yield_stage::AnswerYield;
use crate::study::design::yield_stage::RankBy;
use crate::study::design::PatternResult;
use crate::study::design::{DesignOutcome, DesignParams};
use crate::study::rows::label;
use serde::Serialize;

/// What the report says of the yield stage (absent when it did not run).
#[derive(Debug, Clone, Serialize)]
pub struct YieldHead {
    /// q in percent (`95`).
    pub quantile_pct: String,
    /// γ in percent (`95`).
    pub confidence_pct: String,
    /// Devices per answer.
    pub samples: usize,
    /// The patterns with a yield plot `yield_<p>.png`.
    pub plots: Vec<String>,
    /// `--rank-by yield`: the designs are ranked by the load at yield q (`yield_rank.csv`).
    pub rank_by_yield: bool,
}

/// The report's yield head of `o` (`None` when the stage did not run).
pub fn head(o: &DesignOutcome, p: &DesignParams) -> Option<YieldHead> {
    let y = p.fab_yield.as_ref()?;
    Some(YieldHead {
        quantile_pct: format!("{}", label(100.0 * y.quantile)),
        confidence_pct: format!("{}", label(100.0 * y.confidence)),
        samples: y.samples,
        plots: o
            .patterns
            .iter()
            .zip(&o.yields)
            .filter(|(_, y)| y.is_some())
            .map(|(pr, _)| pr.scene.name.clone())
            .collect(),
        rank_by_yield: y.rank_by == RankBy::Yield,
    })
}

/// The answer's fabrication sentence: what its yield means for a fabricator
/// ([`yield_words::fabricator`]), its DEM check, and, where the bound lies below the answer's
/// robust limit, why: the device the DEM failed lowest, or the devices the runs allowed left
/// undecided and how far more runs could lift the bound (`None` without a yield).
pub fn sentence(pr: &PatternResult, a: &Answer, y: Option<&AnswerYield>) -> Option<String> {
    let s = &y?.outcome.summary;
    let mut t = format!("**Fabrication**: {}", yield_words::fabricator(s));
    if let Some(c) = yield_words::check(s) {
        t.push_str(&format!("; {c}"));
    }
    let robust = a
        .index
        .and_then(|i| pr.ranking.get(i))
        .map_or(0.0, |c| c.score.superlubric_to_mn);
    let below = s.load_at_quantile_bound_mN.is_some_and(|b| b < robust);
    match s.lowest_dem_failure.as_ref().filter(|f| f.load_mN < robust) {
        Some(f) if below => t.push_str(&format!(
            "; below the robust limit {} mN because the DEM fails device {}{} (θ offset {}°, pull offset {}°, substrate seed {}) at {} mN",
            yield_words::load(robust),
            f.sample,
            if f.check { " of the check" } else { "" },
            fmt_g(f.theta_offset_deg, 3),
            fmt_g(f.direction_offset_deg, 3),
            f.seed,
            yield_words::load(f.load_mN)
        )),
        None if below && s.undecided > 0 => t.push_str(&format!(
            "; below the robust limit {} mN because {} device(s) were still undecided when the {} DEM runs allowed were spent (no DEM run failed a device below it): {}",
            yield_words::load(robust),
            s.undecided,
            s.dem_runs_allowed,
            yield_words::ceiling(s)
                .unwrap_or_else(|| "they count at the lower end of what is known".into())
        )),
        _ => {}
    }
    t.push('.');
    Some(t)
}

/// The answer table's cell of one answer's yield: the load at yield q (mN, 3 significant
/// digits; the exact figure in `yield_<p>.json`) with its one-sided bound (`1.21 (≥ 1.05)`),
/// and with the DEM its check (`DEM 9/10 held at 1.21 mN`, `CONTRADICTS` where it does).
pub fn cell(y: Option<&AnswerYield>) -> String {
    let Some(y) = y else {
        return "–".into();
    };
    let s = &y.outcome.summary;
    let mn = |w: f64| yield_words::load(w);
    let mut t = match (s.load_at_quantile_mN, s.load_at_quantile_bound_mN) {
        (Some(w), Some(b)) => format!("{} (≥ {})", mn(w), mn(b)),
        (Some(w), None) => format!(
            "{} (no bound: {} devices, needs ≥ {})",
            mn(w),
            s.samples,
            s.min_samples_for_bound
        ),
        _ => "none holds any load".into(),
    };
    if s.dem_check_total > 0 {
        t.push_str(&format!(
            "; DEM {}/{} held at {} mN{}",
            s.dem_check_passed,
            s.dem_check_total,
            mn(s.dem_check_load_mN.unwrap_or(0.0)),
            match s.dem_check_consistent {
                Some(false) => " (CONTRADICTS the quote)",
                _ if s.quote_lowered_by_check => " (quote lowered to agree)",
                _ => "",
            }
        ));
    }
    t
}

/// One row of `yield_rank.csv` (`--rank-by yield`): a design ranked by its yield.
#[derive(Debug, Clone, Serialize)]
#[allow(non_snake_case)]
pub struct YieldRankRow {
    /// Pattern (design scene name).
    pub pattern: String,
    /// Rank within the pattern (1 = best; as in `ranking.csv`).
    pub rank: usize,
    /// θ (degrees).
    pub theta_deg: f64,
    /// α from the contact line (degrees).
    pub alpha_deg: f64,
    /// Pulling direction from x (degrees).
    pub direction_deg: f64,
    /// The load (mN) at least a fraction q of fabricated devices hold with confidence γ, by
    /// the estimate (the quoted load where the devices are too few for a bound): what ranks.
    pub load_at_yield_mN: f64,
    /// The robust limit (mN): the worst case over the tolerance box, the default order.
    pub superlubric_to_mN: f64,
}

/// The rows of `yield_rank.csv`: every design of `o` ranked by its yield, pattern by pattern
/// (empty without `--rank-by yield`).
pub fn rank_rows(o: &DesignOutcome) -> Vec<YieldRankRow> {
    o.patterns
        .iter()
        .flat_map(|pr| pr.ranking.iter().enumerate())
        .filter_map(|(k, c)| {
            Some(YieldRankRow {
                pattern: c.pattern.clone(),
                rank: k + 1,
                theta_deg: c.theta_deg,
                alpha_deg: c.alpha_deg,
                direction_deg: c.direction_deg,
                load_at_yield_mN: c.score.yield_to_mn?,
                superlubric_to_mN: c.score.superlubric_to_mn,
            })
        })
        .collect()
}

/// Writes each answer's yield files (see the module docs) and, with `--rank-by yield`,
/// `yield_rank.csv` ([`YieldRankRow`]) through `outs`, each only when its bytes change (the
/// plot when its data did or it is missing); appends each file written to `wrote`.
pub fn write(store: &Store, outs: &mut Outputs, wrote: &mut Vec<String>, o: &DesignOutcome) {
    let ranked = rank_rows(o);
    if !ranked.is_empty()
        && store.write_if_changed(
            outs,
            "yield_rank.csv",
            csv_bytes(&ranked),
            Some(ranked.len() as u64),
        )
    {
        wrote.push("yield_rank.csv".into());
    }
    for (pr, y) in o.patterns.iter().zip(&o.yields) {
        let Some(y) = y else { continue };
        let name = &pr.scene.name;
        let rows = &y.outcome.rows;
        let rel = format!("yield_{name}.csv");
        let csv = store.write_if_changed(outs, &rel, csv_bytes(rows), Some(rows.len() as u64));
        if csv {
            wrote.push(rel);
        }
        let rel = format!("yield_{name}.json");
        let json = store.write_if_changed(
            outs,
            &rel,
            serde_json::to_vec_pretty(&y.outcome.summary)
                .map(|mut v| {
                    v.push(b'\n');
                    v
                })
                .map_err(Into::into),
            None,
        );
        if json {
            wrote.push(rel);
        }
        super::redraw::redraw(
            store,
            outs,
            wrote,
            &format!("yield_{name}.png"),
            csv || json,
            |path| yield_png(path, &y.outcome.summary),
        );
    }
}
