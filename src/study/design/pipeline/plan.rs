//! [`Plan`]: the design's cross-stage rules, computed once from its parameters: the knobs the
//! stages share, how many designs per pattern are kept exact, ranked and confirmed, each
//! stage's own params that the plan derives, and the robust floor across many patterns
//! ([`Floor`]).

use crate::study::design::limit::LimitKnobs;
use crate::study::design::model::PatternResult;
use crate::study::design::params::DesignParams;
use crate::study::design::ranking::RankParams;
use crate::study::design::report_data::best::BEST_PATTERNS;
use crate::study::design::report_data::ReportDataParams;
use crate::study::design::robust::RobustParams;
use crate::study::design::yield_stage::{RankBy, YieldDemParams, YieldRunParams};

/// The fewest designs per pattern the robust search makes exact, the walk holds before it
/// stops and the ranking by yield ranks (the DEM confirms `--confirm` of them).
pub const MIN_KEPT: usize = 3;

/// The cross-stage rules of one design (module docs).
#[derive(Debug, Clone)]
pub struct Plan {
    /// The knobs every stage shares.
    pub limit: LimitKnobs,
    /// Designs per pattern kept: made exact by the robust search, held by the level walk
    /// before it stops, ranked by yield (`max(confirm, 3)`).
    pub keep: usize,
    /// Designs per pattern the DEM confirms (`--confirm`; the rows [`PatternResult::trim`]
    /// keeps whole include them).
    pub confirmed: usize,
    /// Whether the DEM runs (not `--no-dem`).
    pub dem: bool,
    /// The ranking's knobs.
    pub rank: RankParams,
    /// The report data's knobs.
    pub report: ReportDataParams,
    /// The yield stage's knobs; `None`: it does not run.
    pub fab_yield: Option<YieldRunParams>,
}

impl Plan {
    /// The plan of `p`. Cost: a few small copies.
    pub fn new(p: &DesignParams) -> Plan {
        let keep = p.confirm.designs.max(MIN_KEPT);
        let dem = !p.confirm.no_dem;
        let limit = p.limit_knobs();
        Plan {
            keep,
            confirmed: p.confirm.designs,
            dem,
            rank: RankParams {
                keep,
                by_yield: p.fab_yield.clone().filter(|y| y.rank_by == RankBy::Yield),
            },
            report: ReportDataParams {
                answer: limit.answer_rule(p.confirm.designs),
                dem_ran: dem,
            },
            fab_yield: p.fab_yield.clone().map(|knobs| YieldRunParams {
                knobs,
                dem: dem.then(|| YieldDemParams {
                    dem: p.confirm.dem.clone(),
                    jobs: p.confirm.jobs,
                }),
            }),
            limit,
        }
    }

    /// The robust search's knobs of a pattern above the floor `floor_mn` (mN; 0: none): across
    /// many patterns (`cross`) without the DEM only each pattern's best counts, otherwise the
    /// plan's `keep` must be exact.
    pub fn robust(&self, floor_mn: f64, cross: bool) -> RobustParams {
        RobustParams {
            floor_mn,
            keep: if cross && !self.dem { 1 } else { self.keep },
        }
    }
}

/// The robust floor across many patterns: the [`BEST_PATTERNS`]-th best exact robust limit
/// found so far (mN; 0 until that many patterns have one, and always 0 unless `cross`).
#[derive(Debug, Clone, Default)]
pub struct Floor {
    cross: bool,
    best: Vec<f64>,
}

impl Floor {
    /// The floor of a design taking its patterns across many (`cross`) or not.
    pub fn new(cross: bool) -> Self {
        Floor {
            cross,
            best: Vec::new(),
        }
    }

    /// The floor now (mN; 0: none).
    pub fn mn(&self) -> f64 {
        if self.cross && self.best.len() >= BEST_PATTERNS {
            self.best[BEST_PATTERNS - 1]
        } else {
            0.0
        }
    }

    /// Records the robust limit of `pr`'s rank-1 design, where exact.
    pub fn record(&mut self, pr: &PatternResult) {
        if let Some(c) = pr.ranking.first().filter(|c| c.score.exact) {
            self.best.push(c.score.superlubric_to_mn);
            self.best.sort_by(|a, b| b.total_cmp(a));
        }
    }
}
