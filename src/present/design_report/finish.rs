//! [`finish`]: the design's global outputs, each written only when its bytes change, and the
//! log line of every file written.

use super::charts::mu_chart;
use super::pattern_files::Writer;
use super::redraw::redraw;
use super::rows::dem_rows;
use super::words::fmt_g;
use super::{markdown, patterns, recipes, stamp, top, words, yields};
use crate::plot::chart::chart_png;
use crate::runs::output::Outputs;
use crate::runs::progress::Progress;
use crate::runs::sink::csv_bytes;
use crate::study::design::rank::RankingRow;
use crate::study::design::store::Store;
use crate::study::design::{DesignOutcome, DesignParams};
use anyhow::Result;

/// Writes the design's global outputs — `ranking.csv`, `patterns.csv`, `dem.csv`, the
/// `mu_<p>.png` charts (they carry the DEM), the tolerance maps, `report.md` — each only when
/// its bytes change, and logs every file written, the per-pattern ones `files` wrote included
/// (or that every output was already up to date). `o` may be trimmed. Errors when an output
/// could not be written (the others are).
pub fn finish(files: Writer, o: &DesignOutcome, progress: &dyn Progress) -> Result<()> {
    let (store, p) = (files.store, files.p);
    let (mut outs, mut wrote) = files.into_parts();
    let mut global = tables(store, &mut outs, o, p)?;
    global.append(&mut wrote);
    let mut wrote = global;
    dem(store, &mut outs, &mut wrote, o, p);
    tolerance_maps(store, &mut outs, &mut wrote, o, p);
    // the yield of each answer over fabrication, when the stage ran
    yields::write(store, &mut outs, &mut wrote, o);
    answer_scenes(store, &mut outs, &mut wrote, o);
    let md = stamp::keep_stamp(
        std::fs::read_to_string(store.path("report.md")).ok(),
        markdown(o, p)?,
    );
    if store.write_if_changed(&mut outs, "report.md", Ok(md.into_bytes()), None) {
        wrote.push("report.md".into());
    }
    outs.finish()?;
    progress.note(&if wrote.is_empty() {
        format!(
            "{}: every output already up to date (nothing rewritten)",
            store.dir().display()
        )
    } else {
        format!("{}: wrote {}", store.dir().display(), wrote.join(", "))
    });
    Ok(())
}

/// The ranking of every pattern, best first within each pattern.
fn ranking_rows(o: &DesignOutcome, p: &DesignParams) -> Vec<RankingRow> {
    o.patterns
        .iter()
        .flat_map(|pr| {
            pr.ranking.iter().enumerate().map(|(k, c)| {
                RankingRow::new(
                    k + 1,
                    c,
                    (p.tolerance.theta_tol_deg, p.tolerance.direction_tol_deg),
                    words::pick_words(c.reason),
                )
            })
        })
        .collect()
}

/// `ranking.csv`, `patterns.csv` and, with several patterns, their figures: the files written.
fn tables(
    store: &Store,
    outs: &mut Outputs,
    o: &DesignOutcome,
    p: &DesignParams,
) -> Result<Vec<String>> {
    let mut global = Vec::new();
    let ranking = ranking_rows(o, p);
    if store.write_if_changed(
        outs,
        "ranking.csv",
        csv_bytes(&ranking),
        Some(ranking.len() as u64),
    ) {
        global.push("ranking.csv".to_string());
    }
    // the patterns side by side
    let pats = patterns::pattern_rows(o);
    if store.write_if_changed(
        outs,
        "patterns.csv",
        csv_bytes(&pats),
        Some(pats.len() as u64),
    ) {
        global.push("patterns.csv".to_string());
    }
    if o.patterns.len() > 1 {
        patterns::write_figures(store, outs, &mut global, o, &pats)?;
        recipes::write_figures(store, outs, &mut global, &pats)?;
    }
    Ok(global)
}

/// `dem.csv` (when the DEM ran) and each pattern's `mu_<p>.png`, redrawn when its friction or
/// the DEM changed.
fn dem(
    store: &Store,
    outs: &mut Outputs,
    wrote: &mut Vec<String>,
    o: &DesignOutcome,
    p: &DesignParams,
) {
    let dem = dem_rows(o, p);
    let dem_changed = o.dem_ran
        && store.write_if_changed(outs, "dem.csv", csv_bytes(&dem), Some(dem.len() as u64));
    if dem_changed {
        wrote.push("dem.csv".into());
    }
    for pr in &o.patterns {
        let rel = format!("mu_{}.png", pr.scene.name);
        let fr_changed = wrote
            .iter()
            .any(|w| w == &format!("friction_{}.csv", pr.scene.name));
        redraw(
            store,
            outs,
            wrote,
            &rel,
            fr_changed || dem_changed,
            |path| chart_png(path, &mu_chart(pr, &dem, p)),
        );
    }
}

/// The tolerance map around each answer: `tolerance_<p>.csv` and its `.png`.
fn tolerance_maps(
    store: &Store,
    outs: &mut Outputs,
    wrote: &mut Vec<String>,
    o: &DesignOutcome,
    p: &DesignParams,
) {
    for (pr, m) in o.patterns.iter().zip(&o.maps) {
        let Some(m) = m else { continue };
        let name = &pr.scene.name;
        let rel = format!("tolerance_{name}.csv");
        let changed =
            store.write_if_changed(outs, &rel, csv_bytes(&m.rows), Some(m.rows.len() as u64));
        if changed {
            wrote.push(rel);
        }
        let rel = format!("tolerance_{name}.png");
        redraw(store, outs, wrote, &rel, changed, |path| {
            let title = format!(
                "{name}: superlubric limit around the answer θ = {}°, direction {}° (box ±{}° × ±{}°)",
                m.nominal.0,
                fmt_g(m.nominal.1, 4),
                p.tolerance.theta_tol_deg,
                p.tolerance.direction_tol_deg
            );
            crate::plot::tolerance::tolerance_png(
                path,
                &title,
                &m.rows,
                m.theta_points,
                m.nominal,
                (p.tolerance.theta_tol_deg, p.tolerance.direction_tol_deg),
                (
                    surrogate::units::pa_to_gpa(pr.scene.scene.coating.p_crit),
                    p.mu_superlubric,
                ),
            )
        });
    }
}

/// Each answer's scene with its θ set, for the commands the report gives.
fn answer_scenes(store: &Store, outs: &mut Outputs, wrote: &mut Vec<String>, o: &DesignOutcome) {
    for (pr, a) in o.patterns.iter().zip(&o.answers) {
        let Some(c) = a.index.and_then(|i| pr.ranking.get(i)) else {
            continue;
        };
        let rel = top::scene_file_name(&pr.scene.name);
        let toml = top::answer_toml(pr, c);
        if store.write_if_changed(outs, &rel, Ok(toml.into_bytes()), None) {
            wrote.push(rel);
        }
    }
}
