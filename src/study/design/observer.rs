//! What the design pipeline tells its caller as it runs: typed events ([`Event`]), through ONE
//! [`Observer`] that the command passes in. The pipeline
//! holds no wording: the command's observer words the events
//! (`crate::present::design_report::log`), a test's records them.

use super::model::{Candidate, Stop};
use super::screen::domain::ThetaNote;
use super::symmetry_words::PairSymmetry;
use crate::runs::progress::{Progress, Silent};
use std::path::Path;

/// Something the pipeline reports (no wording: the observer words it). Loads in N unless the
/// field says mN.
#[derive(Debug, Clone, Copy)]
pub enum Event<'a> {
    /// The output folder holds a design of the same inputs: finished stages are reused.
    Reusing {
        /// The folder.
        dir: &'a Path,
    },
    /// Many patterns with a tolerance: each is evaluated at its nominal orientation first.
    NominalFirst {
        /// Number of patterns.
        patterns: usize,
    },
    /// A pattern's symmetry and the θ list kept by the cut.
    Symmetry {
        /// Pattern name.
        pattern: &'a str,
        /// Its symmetry.
        sym: &'a PairSymmetry,
        /// θ screened after the cut.
        screened: usize,
        /// θ given.
        given: usize,
        /// Whether the cut applies.
        cut: bool,
        /// What the θ list leaves out of the domain, if anything.
        note: Option<&'a ThetaNote>,
    },
    /// A site file's pattern measures α from the x axis (the note, in words).
    LineNote {
        /// Pattern name.
        pattern: &'a str,
        /// The note.
        note: &'a str,
    },
    /// The symmetry cut is approximate (σ_h > 0, or an offset slider).
    ApproximateCut {
        /// Pattern name.
        pattern: &'a str,
        /// The slider is offset (else σ_h > 0).
        offset: bool,
    },
    /// The screen was reused from its stored file.
    ScreenReused {
        /// Pattern name.
        pattern: &'a str,
        /// The stored file (relative to the output folder).
        file: &'a str,
        /// Its rows.
        rows: usize,
    },
    /// The screen was computed.
    Screened {
        /// Pattern name.
        pattern: &'a str,
        /// θ screened.
        thetas: usize,
        /// Loads.
        loads: usize,
        /// Wall time (s).
        wall_s: f64,
    },
    /// No orientation keeps the coating intact even at the lowest load.
    NoIntactOrientation {
        /// Pattern name.
        pattern: &'a str,
    },
    /// A shortlist level's α scans and estimates begin (a bar of `paths` paths).
    Level {
        /// Pattern name.
        pattern: &'a str,
        /// The level's load W_c (N).
        load: f64,
        /// Orientations evaluated.
        picks: usize,
        /// Orientations at the level.
        size: usize,
        /// Paths to solve.
        paths: u64,
    },
    /// A robust search begins (a bar of `designs` designs).
    Robust {
        /// Pattern name.
        pattern: &'a str,
        /// θ tolerance (degrees, ±).
        theta_tol_deg: f64,
        /// Direction tolerance (degrees, ±).
        direction_tol_deg: f64,
        /// Substrate realisations.
        substrates: usize,
        /// Designs to make exact.
        designs: u64,
    },
    /// A robust search ended.
    RobustDone {
        /// Pattern name.
        pattern: &'a str,
        /// Designs whose limit is exact.
        exact: usize,
        /// Designs searched.
        searched: usize,
        /// Wall time (s).
        wall_s: f64,
        /// Friction paths solved.
        paths: usize,
    },
    /// Designs searched only down to the floor of the best patterns.
    Floored {
        /// Pattern name.
        pattern: &'a str,
        /// Such designs.
        designs: usize,
        /// The floor (mN).
        floor_mn: f64,
    },
    /// The estimate's best design of a pattern.
    Best {
        /// Pattern name.
        pattern: &'a str,
        /// The design.
        design: &'a Candidate,
        /// Orientations evaluated.
        evaluated: usize,
        /// Why the evaluation stopped.
        stop: &'a Stop,
        /// Levels skipped under the floor.
        skipped: usize,
        /// The floor (mN; 0: none).
        floor_mn: f64,
    },
    /// The tolerance map around a pattern's answer begins (a bar of `points` points).
    ToleranceMap {
        /// Pattern name.
        pattern: &'a str,
        /// Points of the map.
        points: u64,
    },
    /// The best recipe's limit is re-evaluated at the coating strengths of
    /// [`super::model::P_CRIT_SWEEP_GPA`].
    PCritSweep {
        /// Pattern (recipe) name.
        pattern: &'a str,
    },
    /// The yield of a pattern's answer over fabrication is known ([`super::yield_stage`]).
    Yield {
        /// Pattern name.
        pattern: &'a str,
        /// What the yield found.
        summary: &'a crate::study::fab_yield::YieldSummary,
    },
    /// `--rank-by yield`: the estimate's yield of a pattern's top designs begins
    /// ([`super::ranking::by_yield`]).
    YieldRank {
        /// Pattern name.
        pattern: &'a str,
        /// Designs ranked by yield.
        designs: usize,
    },
    /// `--rank-by yield`: the pattern's ranking by yield is known; its best design.
    YieldRanked {
        /// Pattern name.
        pattern: &'a str,
        /// The best design (its `score.yield_to_mn` set).
        best: &'a Candidate,
    },
    /// No ranked design: nothing for the DEM to confirm.
    DemNothing,
    /// The DEM batch begins.
    DemRuns {
        /// Runs.
        runs: usize,
        /// Runs side by side.
        side_by_side: usize,
        /// Their folder.
        dir: &'a Path,
    },
    /// The study's protocol once on the recommended design.
    ProtocolCheck {
        /// Pattern name.
        pattern: &'a str,
        /// θ (degrees).
        theta_deg: f64,
        /// α (degrees).
        alpha_deg: f64,
        /// Load (N).
        load: f64,
    },
    /// DEM runs reused (input hash matches).
    DemReused {
        /// Runs reused.
        reused: usize,
        /// Runs in all.
        runs: usize,
    },
    /// A shard of the DEM stage: its share of the runs.
    DemShard {
        /// Shard index (1-based).
        index: usize,
        /// Shards.
        count: usize,
        /// First run (index into all runs).
        start: usize,
        /// One past the last run.
        end: usize,
        /// Runs in all.
        runs: usize,
        /// Their folder.
        dir: &'a Path,
    },
    /// Runs of a DEM shard that failed.
    DemShardFailed {
        /// Failed runs.
        failed: usize,
    },
}

/// The one observer of a design run: told of each [`Event`], and the progress sink of the
/// stages' bars (and of the workflows they call: the screen, the DEM batch, the tolerance map).
pub trait Observer: Sync {
    /// Something happened (see [`Event`]).
    fn event(&self, event: &Event<'_>);
    /// Where the bars go: `advance`/`finish` of the stages, and the called workflows' own.
    fn progress(&self) -> &dyn Progress;
}

/// Tells nothing (library use, tests).
impl Observer for Silent {
    fn event(&self, _: &Event<'_>) {}
    fn progress(&self) -> &dyn Progress {
        self
    }
}
