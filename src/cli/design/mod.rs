//! `superlube design`: flags → pattern scenes + [`DesignParams`] → [`crate::study::design::design`]
//! (which writes everything under `--out-dir`).

mod args;
mod prepare;
mod scenes;
mod yield_args;

pub use args::Args;
pub use prepare::prepare;

use crate::runs::progress::Reporter;
use crate::study::design::design;
use crate::study::design::store::Store;
use anyhow::Result;

/// Runs `superlube design`.
pub fn run(a: Args) -> Result<()> {
    let (scenes, params) = prepare(&a)?;
    let rep = Reporter::stderr();
    for s in &scenes {
        for w in &s.warnings {
            crate::runs::progress::Progress::note(&rep, &format!("warning: {}: {w}", s.name));
        }
    }
    if a.patterns.is_some() || a.family.is_some() {
        let mut n = [0usize; 4];
        for s in &scenes {
            let t = s.facts.as_ref().map_or("", |f| f.contact_type.as_str());
            n[crate::study::patterns::prescreen_class(t)] += 1;
        }
        crate::runs::progress::Progress::note(
            &rep,
            &format!(
                "design: {} candidates in the contact-type pre-screen's order: {} lubric (in every direction), {} directional, {} interlocked{}; index order within each",
                scenes.len(),
                n[0],
                n[1],
                n[2],
                if n[3] > 0 {
                    format!(", then {} unclassified", n[3])
                } else {
                    String::new()
                }
            ),
        );
    }
    let t0 = std::time::Instant::now();
    let store = Store::new(&a.out).labelled("--out-dir");
    let record = crate::study::design::inputs(&scenes, &params, true);
    let files = crate::present::design_report::Writer::new(&store, &record, &params);
    let log = crate::present::design_report::Log::new(&rep);
    let o = design(&scenes, &params, &store, &log, &|pr| files.pattern(pr))?;
    if !params.confirm.dem_shard.is_all() {
        crate::runs::progress::Progress::note(
            &rep,
            &format!(
                "design: shard {}/{} of the DEM runs done in {:.1} s (no report from a shard)",
                params.confirm.dem_shard.index,
                params.confirm.dem_shard.count,
                t0.elapsed().as_secs_f64()
            ),
        );
        return Ok(());
    }
    crate::present::design_report::publish(files, &o, &rep)?;
    let failed = o.dem.iter().filter(|d| d.outcome.error.is_some()).count();
    crate::runs::progress::Progress::note(
        &rep,
        &format!(
            "design: done in {:.1} s; the answer is in {}{}",
            t0.elapsed().as_secs_f64(),
            a.out.join("report.md").display(),
            if failed > 0 {
                format!(" ({failed} DEM run(s) failed: see the report)")
            } else {
                String::new()
            }
        ),
    );
    Ok(())
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod answer_tests;

#[cfg(test)]
mod test_args;
