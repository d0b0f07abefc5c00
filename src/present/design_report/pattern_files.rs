//! Each pattern's own outputs, written as soon as the design completes the pattern (the
//! design's hook, [`crate::study::design::PatternHook`]), before the pattern's bulky rows are
//! dropped: `shortlist_<p>.csv`, `corrugation_<p>.csv`, `friction_<p>.csv`, `pmax_<p>.png`,
//! `corrugation_<p>.png`. Each is rewritten only when its bytes change; `mu_<p>.png` carries the
//! DEM and is drawn with the global outputs ([`super::finish()`]).

use super::charts::{corrugation_chart, pmax_chart};
use super::rows::ShortlistRow;
use crate::plot::chart::chart_png;
use crate::runs::meta::Inputs;
use crate::runs::output::Outputs;
use crate::runs::sink::csv_bytes;
use crate::study::design::store::Store;
use crate::study::design::{DesignParams, PatternResult};
use crate::study::rows::{label, CorrugationRow, FrictionRow};
use anyhow::{bail, Result};
use std::cell::RefCell;
use surrogate::units::{n_to_mn, pa_to_gpa};

/// Writes the per-pattern outputs of a design as its patterns complete, and remembers what it
/// wrote and what failed for [`super::finish()`] (one log line, one error at the end: a failed
/// write does not stop the design).
pub struct Writer<'a> {
    pub(super) store: &'a Store,
    pub(super) p: &'a DesignParams,
    state: RefCell<(Outputs, Vec<String>)>,
}

impl<'a> Writer<'a> {
    /// A writer into `store`; every sidecar records `record` (the design's inputs).
    pub fn new(store: &'a Store, record: &Inputs, p: &'a DesignParams) -> Writer<'a> {
        Writer {
            store,
            p,
            state: RefCell::new((Outputs::new(record.clone(), vec![]), Vec::new())),
        }
    }

    /// Writes the own files of the complete, untrimmed pattern `pr` (see the module docs).
    /// Errors only for a trimmed pattern (its rows are gone); a failed write is recorded for
    /// [`super::finish()`]. Cost: the pattern's CSV bytes and two charts (those redrawn).
    pub fn pattern(&self, pr: &PatternResult) -> Result<()> {
        if pr.trimmed {
            bail!(
                "{}: the pattern's rows were dropped before its files were written",
                pr.scene.name
            );
        }
        let mut st = self.state.borrow_mut();
        let (outs, wrote) = &mut *st;
        write_pattern(self.store, self.p, pr, outs, wrote);
        Ok(())
    }

    /// The outputs so far and the files written (relative paths, in order).
    pub(super) fn into_parts(self) -> (Outputs, Vec<String>) {
        self.state.into_inner()
    }
}

/// The own files of `pr` through `outs`; appends each file written to `wrote`.
fn write_pattern(
    store: &Store,
    p: &DesignParams,
    pr: &PatternResult,
    outs: &mut Outputs,
    wrote: &mut Vec<String>,
) {
    let name = &pr.scene.name;
    // shortlist
    let evaluated: Vec<f64> = pr.evaluated.iter().map(|e| e.eval.theta_deg).collect();
    let kept: Vec<f64> = pr
        .levels
        .iter()
        .flat_map(|l| l.picks.iter().map(|o| o.theta_deg))
        .collect();
    let sl: Vec<ShortlistRow> = pr
        .orientations
        .iter()
        .map(|or| ShortlistRow {
            theta_deg: or.theta_deg,
            coating_intact_to_mN: label(n_to_mn(or.w_intact)),
            p_max_GPa: pa_to_gpa(or.p_max),
            contacts: or.contacts,
            shortlisted: kept.contains(&or.theta_deg),
            evaluated: evaluated.contains(&or.theta_deg),
        })
        .collect();
    let rel = format!("shortlist_{name}.csv");
    let shortlist_changed =
        store.write_if_changed(outs, &rel, csv_bytes(&sl), Some(sl.len() as u64));
    if shortlist_changed {
        wrote.push(rel);
    }
    // corrugation scans
    let scans: Vec<CorrugationRow> = pr
        .evaluated
        .iter()
        .flat_map(|e| e.eval.scan.iter().cloned())
        .collect();
    let rel = format!("corrugation_{name}.csv");
    let scans_changed =
        store.write_if_changed(outs, &rel, csv_bytes(&scans), Some(scans.len() as u64));
    if scans_changed {
        wrote.push(rel);
    }
    // friction, each row with its verdict at its own (θ, α, W) (the rule of every sample)
    let p_crit = pr.scene.scene.coating.p_crit;
    let fr: Vec<FrictionRow> = pr
        .ranking
        .iter()
        .flat_map(|c| c.friction.iter().cloned())
        .map(|r| r.judged(p.mu_superlubric, p_crit))
        .collect();
    let rel = format!("friction_{name}.csv");
    if store.write_if_changed(outs, &rel, csv_bytes(&fr), Some(fr.len() as u64)) {
        wrote.push(rel);
    }
    // PNGs (redrawn when missing or their data changed)
    let rel = format!("pmax_{name}.png");
    super::redraw::redraw(store, outs, wrote, &rel, shortlist_changed, |path| {
        chart_png(path, &pmax_chart(pr, p))
    });
    let rel = format!("corrugation_{name}.png");
    super::redraw::redraw(store, outs, wrote, &rel, scans_changed, |path| {
        chart_png(path, &corrugation_chart(pr))
    });
}
