//! The design's yield outputs, when its yield stage ran
//! ([`crate::study::design::yield_stage`]): per answer `yield_<p>.csv` (one row per device,
//! the `yield` schema), `yield_<p>.json` (the summary) and `yield_<p>.png` (yield against
//! load with its band, the quoted load marked), each with its sidecar; and the report's
//! "load at q yield" column ([`cell`]) and plots ([`YieldHead`]).

use super::words::fmt_g;
use crate::plot::yield_curve::yield_png;
use crate::runs::output::Outputs;
use crate::runs::sink::csv_bytes;
use crate::study::design::store::Store;
use crate::study::design::yield_stage::AnswerYield;
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
    })
}

/// The answer table's cell of one answer's yield: the load at yield q (mN, 3 significant
/// digits; the exact figure in `yield_<p>.json`) with its one-sided bound (`1.21 (≥ 1.05)`),
/// and with the DEM its check (`DEM 9/10 held at 1.21 mN`).
pub fn cell(y: Option<&AnswerYield>) -> String {
    let Some(y) = y else {
        return "–".into();
    };
    let s = &y.outcome.summary;
    let mn = |w: f64| fmt_g(w, 3);
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
            "; DEM {}/{} held at {} mN",
            s.dem_check_passed,
            s.dem_check_total,
            mn(s.dem_check_load_mN.unwrap_or(0.0))
        ));
    }
    t
}

/// Writes each answer's yield files (see the module docs) through `outs`, each only when its
/// bytes change (the plot when its data did or it is missing); appends each file written to
/// `wrote`.
pub fn write(store: &Store, outs: &mut Outputs, wrote: &mut Vec<String>, o: &DesignOutcome) {
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
        super::redraw(
            store,
            outs,
            wrote,
            &format!("yield_{name}.png"),
            csv || json,
            |path| yield_png(path, &y.outcome.summary),
        );
    }
}
