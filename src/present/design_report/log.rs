//! The design's log in words: [`Log`] is the observer the command passes to the pipeline
//! (`crate::study::design::Observer`); it words each event ([`line()`]) as a note, opens the
//! stages' bars, and passes the rest to the command's progress reporter.

use crate::runs::progress::Progress;
use crate::study::design::best::BEST_PATTERNS;
use crate::study::design::symmetry_words::SymmetryWords;
use crate::study::design::{Event, Observer, PatternResult, Stop};
use crate::study::input::Input;
use crate::study::rows::label;
use surrogate::units::n_to_mn;

/// The observer of a design run that logs to `progress` (the command's reporter).
pub struct Log<'a> {
    progress: &'a dyn Progress,
}

impl<'a> Log<'a> {
    /// The log of a design run into `progress`.
    pub fn new(progress: &'a dyn Progress) -> Self {
        Log { progress }
    }
}

impl Observer for Log<'_> {
    fn event(&self, e: &Event<'_>) {
        match *e {
            Event::Level {
                pattern,
                load,
                picks,
                size,
                paths,
            } => self.progress.stage(
                &format!(
                    "{pattern}: α scan + friction, level {} ({picks} of {size} θ)",
                    super::words::mn(load)
                ),
                paths,
                "paths",
            ),
            Event::Robust {
                pattern,
                theta_tol_deg,
                direction_tol_deg,
                substrates,
                designs,
            } => self.progress.stage(
                &format!(
                    "{pattern}: robust limits over θ ±{theta_tol_deg}° × direction ±{direction_tol_deg}°{}",
                    if substrates > 1 {
                        format!(" × {substrates} substrates")
                    } else {
                        String::new()
                    }
                ),
                designs,
                "designs",
            ),
            Event::ToleranceMap { pattern, points } => self.progress.stage(
                &format!("{pattern}: tolerance map around the answer"),
                points,
                "points",
            ),
            _ => {
                if let Some(l) = line(e) {
                    self.progress.note(&l);
                }
            }
        }
    }

    fn progress(&self) -> &dyn Progress {
        self.progress
    }
}

/// Why a pattern's evaluation stopped, in words (the log's and the report's): the [`Stop`],
/// then the levels skipped under the floor `floor_mn` (mN), if any.
pub fn stop_text(stop: &Stop, skipped: usize, floor_mn: f64) -> String {
    let base = match (stop, skipped) {
        (Stop::EveryLevel, 0) => "every level evaluated".to_string(),
        (Stop::EveryLevel, _) => "every level taken".to_string(),
        (
            Stop::Before {
                level,
                reach_mn,
                best_mn,
            },
            _,
        ) => format!(
            "stopped before level {}: its orientations cannot be superlubric beyond {reach_mn} mN < the best found, {best_mn} mN",
            super::words::mn(*level)
        ),
    };
    if skipped == 0 {
        base
    } else {
        format!(
            "{base}; {skipped} levels skipped: their orientations cannot be superlubric beyond {floor_mn} mN over the tolerance box, the floor of the best {BEST_PATTERNS} patterns"
        )
    }
}

/// [`stop_text`] of a pattern's result.
pub fn pattern_stop(pr: &PatternResult) -> String {
    stop_text(&pr.stop, pr.levels_skipped.len(), pr.robust_floor_mn)
}

/// The log line of an event that is a note (`None` for those that open a bar).
pub fn line(e: &Event<'_>) -> Option<String> {
    screen_line(e)
        .or_else(|| ranking_line(e))
        .or_else(|| confirm_line(e))
}

/// The log line of a note of the screen stage (`None` for any other event).
fn screen_line(e: &Event<'_>) -> Option<String> {
    Some(match *e {
        Event::Reusing { dir } => format!(
            "{}: a design of the same inputs is there: finished stages are reused",
            dir.display()
        ),
        Event::NominalFirst { patterns } => format!(
            "design: {patterns} patterns: each at its nominal orientation first, to search the tolerance boxes best first across patterns"
        ),
        Event::Symmetry {
            pattern,
            sym,
            screened,
            given,
            cut,
            note,
        } => {
            let uncut = if cut { "" } else { " (no symmetry cut)" };
            match note {
                // the presets' line, unchanged
                None => format!(
                    "{pattern}: {}; {screened} of {given} θ screened{uncut}",
                    sym.describe()
                ),
                Some(n) => format!(
                    "{pattern}: {}; {screened} θ screened{uncut}; {}",
                    sym.describe(),
                    super::words::theta_note(n, sym)
                ),
            }
        }
        Event::LineNote { pattern, note } => format!("{pattern}: note: {note}"),
        Event::ApproximateCut { pattern, offset } => format!(
            "{pattern}: note: the symmetry cut is exact for a flat substrate with the slider centred on a site; {}",
            if offset {
                format!(
                    "this slider is offset, so the cut is approximate ({} screens the whole range)",
                    Input::NoSymmetryCut
                )
            } else {
                "with σ_h > 0 it holds statistically".to_string()
            }
        ),
        Event::ScreenReused {
            pattern,
            file,
            rows,
        } => format!("{pattern}: screen reused from {file} ({rows} rows, input hash matches)"),
        Event::Screened {
            pattern,
            thetas,
            loads,
            wall_s,
        } => format!("{pattern}: screened {thetas} θ × {loads} loads in {wall_s:.2} s"),
        Event::NoIntactOrientation { pattern } => format!(
            "{pattern}: no orientation keeps the coating intact even at the lowest load"
        ),
        _ => return None,
    })
}

/// The log line of a note of the robust search and the ranking (`None` for any other event).
fn ranking_line(e: &Event<'_>) -> Option<String> {
    Some(match *e {
        Event::RobustDone {
            pattern,
            exact,
            searched,
            wall_s,
            paths,
        } => format!(
            "{pattern}: robust limits: {exact} of {searched} designs exact, the others bounded, in {wall_s:.1} s ({paths} friction paths)"
        ),
        Event::Floored {
            pattern,
            designs,
            floor_mn,
        } => format!(
            "{pattern}: {designs} designs searched over the tolerance box only until their bound fell to {floor_mn} mN, the lowest of the best {BEST_PATTERNS} patterns' robust limits so far: they cannot enter the best {BEST_PATTERNS}"
        ),
        Event::Best {
            pattern,
            design: b,
            evaluated,
            stop,
            skipped,
            floor_mn,
        } => format!(
            "{pattern}: the estimate's best design: θ = {}°, α = {}°, superlubric up to {} mN (μ_est ≤ {:.4}); {evaluated} orientations evaluated ({})",
            b.theta_deg,
            b.alpha_deg,
            b.score.superlubric_to_mn,
            b.score.mu_worst,
            stop_text(stop, skipped, floor_mn)
        ),
        Event::YieldRank { pattern, designs } => format!(
            "{pattern}: ranking the top {designs} design(s) by their yield over fabrication (--rank-by yield; the estimate's part of each)"
        ),
        Event::YieldRanked { pattern, best: b } => format!(
            "{pattern}: best design by yield: θ = {}°, α = {}°, load at yield {} mN (robust limit {} mN)",
            b.theta_deg,
            b.alpha_deg,
            b.score.yield_to_mn.unwrap_or(0.0),
            b.score.superlubric_to_mn
        ),
        _ => return None,
    })
}

/// The log line of a note of the yield, the DEM confirmation and its shards (`None` for any
/// other event).
fn confirm_line(e: &Event<'_>) -> Option<String> {
    Some(match *e {
        Event::DemNothing => "DEM: nothing to confirm (no ranked design)".to_string(),
        Event::Yield { pattern, summary: s } => {
            let mut t = format!(
                "{pattern}: yield of the answer over fabrication: {}",
                crate::present::yield_words::fabricator(s)
            );
            if s.dem {
                t.push_str(&format!("; {}", crate::present::yield_words::dem_work(s)));
            }
            if let Some(c) = crate::present::yield_words::check(s) {
                t.push_str(&format!("; {c}"));
            }
            t
        }
        Event::PCritSweep { pattern } => format!(
            "{pattern}: the best recipe's robust limit at P_crit = {} GPa",
            crate::study::design::p_crit::P_CRIT_SWEEP_GPA
                .iter()
                .map(|v| v.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Event::DemRuns {
            runs,
            side_by_side,
            dir,
        } => format!(
            "DEM: {runs} runs, {side_by_side} side by side (one thread each), into {}",
            dir.display()
        ),
        Event::ProtocolCheck {
            pattern,
            theta_deg,
            alpha_deg,
            load,
        } => format!(
            "DEM: the study's protocol (10 + 10 + 300 µs) on the recommended design, {pattern} θ = {theta_deg}°, α = {alpha_deg}° at {} mN, to measure the shorter protocol's difference",
            label(n_to_mn(load))
        ),
        Event::DemReused { reused, runs } => {
            format!("DEM: {reused} of {runs} runs reused (input hash matches)")
        }
        Event::DemShard {
            index,
            count,
            start,
            end,
            runs,
            dir,
        } => format!(
            "DEM shard {index}/{count}: runs {start}..{end} of {runs} into {}; run the design without {} (same {}, every shard's dem/ runs in it) to write the report",
            dir.display(),
            Input::Shard,
            Input::OutDir
        ),
        Event::DemShardFailed { failed } => format!("DEM shard: {failed} run(s) failed"),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stop reasons read as before the pipeline carried them as text.
    #[test]
    fn stop_words() {
        assert_eq!(
            stop_text(&Stop::EveryLevel, 0, 0.0),
            "every level evaluated"
        );
        assert_eq!(
            stop_text(&Stop::EveryLevel, 2, 1.4),
            "every level taken; 2 levels skipped: their orientations cannot be superlubric beyond 1.4 mN over the tolerance box, the floor of the best 3 patterns"
        );
        let s = Stop::Before {
            level: surrogate::units::mn_to_n(0.7),
            reach_mn: 0.7,
            best_mn: 1.4,
        };
        assert_eq!(
            stop_text(&s, 0, 0.0),
            "stopped before level 0.7 mN: its orientations cannot be superlubric beyond 0.7 mN < the best found, 1.4 mN"
        );
    }
}
