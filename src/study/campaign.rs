//! The reference study's friction campaign (`superlube figures --friction`): friction force and
//! μ versus load for the study's series, run through the batch runner ([`super::batch`]).
//!
//! | figure | series (α from the contact line; E = 100 GPa, σ_h = 0 unless said) |
//! |---|---|
//! | `2b` | tri-tri θ = 0°, 21.8°, 30° (α = 0) |
//! | `6` | square-tri θ = 0° and 10.2° at α = 0° and 90°, with the three tri-tri series |
//! | `7` | tri-tri 30° and square-tri 0°/α = 90° at σ_h = 0.002 and 0.01 µm (E = 100 GPa), square-tri 0°/α = 90° at σ_h = 0.01 µm with E = 50 GPa; the σ_h = 0 series of both for reference |
//!
//! Every series runs at every load (default the study's 11: 0.35, 0.70, …, 3.50, 3.86 mN); a
//! series with σ_h > 0 runs once per seed, the others once. The run list is the union of the
//! figures asked for, without duplicates (a series shared by two figures runs once), in figure,
//! series, load, seed order; `--shard i/n` cuts it into contiguous blocks.

use super::batch::{run_name, SlideJob};
use super::dem_run::{DemParams, ModelSpec};
use super::rows::{BatchRow, ConfigStatsRow};
use anyhow::Result;
use dem::protocol::RunIo;
use dem::{SimParams, Start};
use surrogate::units::{deg_to_rad, mn_to_n, us_to_s};
use surrogate::SceneFile;

/// The study's loads (mN): 0.35 to 3.50 in steps of 0.35, and 3.86.
pub const STUDY_LOADS_MN: [f64; 11] = [
    0.35, 0.70, 1.05, 1.40, 1.75, 2.10, 2.45, 2.80, 3.15, 3.50, 3.86,
];

/// One figure of the campaign.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fig {
    /// Fig 2b: tri-tri θ = 0°, 21.8°, 30°.
    F2b,
    /// Fig 6: square-tri θ = 0°, 10.2° at α = 0°, 90°, with the tri-tri series.
    F6,
    /// Fig 7: imperfect substrates (σ_h = 0.002, 0.01 µm; E = 100, 50 GPa).
    F7,
}

impl Fig {
    /// File name stem: `friction_fig2b`, `friction_fig6`, `friction_fig7`.
    pub fn stem(self) -> &'static str {
        match self {
            Fig::F2b => "friction_fig2b",
            Fig::F6 => "friction_fig6",
            Fig::F7 => "friction_fig7",
        }
    }

    /// Title of the figure.
    pub fn title(self) -> &'static str {
        match self {
            Fig::F2b => "Fig 2b: tri-tri friction vs load",
            Fig::F6 => "Fig 6: square-tri vs tri-tri friction",
            Fig::F7 => "Fig 7: imperfect substrates (σ_h, E)",
        }
    }

    /// The figure's series.
    pub fn series(self) -> Vec<Series> {
        let s = Series::new;
        let tri = vec![
            s("tri-tri", 0.0, 0.0, 0.0, 100.0),
            s("tri-tri", 21.8, 0.0, 0.0, 100.0),
            s("tri-tri", 30.0, 0.0, 0.0, 100.0),
        ];
        match self {
            Fig::F2b => tri,
            Fig::F6 => {
                let mut v = vec![
                    s("square-tri", 0.0, 0.0, 0.0, 100.0),
                    s("square-tri", 0.0, 90.0, 0.0, 100.0),
                    s("square-tri", 10.2, 0.0, 0.0, 100.0),
                    s("square-tri", 10.2, 90.0, 0.0, 100.0),
                ];
                v.extend(tri);
                v
            }
            Fig::F7 => vec![
                s("tri-tri", 30.0, 0.0, 0.0, 100.0),
                s("tri-tri", 30.0, 0.0, 0.002, 100.0),
                s("tri-tri", 30.0, 0.0, 0.01, 100.0),
                s("square-tri", 0.0, 90.0, 0.0, 100.0),
                s("square-tri", 0.0, 90.0, 0.002, 100.0),
                s("square-tri", 0.0, 90.0, 0.01, 100.0),
                s("square-tri", 0.0, 90.0, 0.01, 50.0),
            ],
        }
    }
}

/// One curve of a figure: a configuration run at every load (and every seed when σ_h > 0).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Pattern pair preset.
    pub pattern: &'static str,
    /// θ (degrees).
    pub theta_deg: f64,
    /// α from the contact line (degrees).
    pub alpha_deg: f64,
    /// σ_h (µm).
    pub sigma_h_um: f64,
    /// Young's modulus (GPa).
    pub youngs_gpa: f64,
}

impl Series {
    fn new(
        pattern: &'static str,
        theta_deg: f64,
        alpha_deg: f64,
        sigma_h_um: f64,
        youngs_gpa: f64,
    ) -> Series {
        Series {
            pattern,
            theta_deg,
            alpha_deg,
            sigma_h_um,
            youngs_gpa,
        }
    }

    /// Legend label, e.g. `square-tri θ=0° α=90° σ_h=0.01 µm E=50 GPa` (σ_h and E only when
    /// not the defaults 0 and 100 GPa).
    pub fn label(&self) -> String {
        let mut l = format!(
            "{} θ={}° α={}°",
            self.pattern, self.theta_deg, self.alpha_deg
        );
        if self.sigma_h_um > 0.0 {
            l.push_str(&format!(" σ_h={} µm", self.sigma_h_um));
        }
        if self.youngs_gpa != 100.0 {
            l.push_str(&format!(" E={} GPa", self.youngs_gpa));
        }
        l
    }
}

/// Parameters of the campaign (SI inside, except the series' own user-unit labels).
#[derive(Debug, Clone)]
pub struct CampaignParams {
    /// Figures to make.
    pub figs: Vec<Fig>,
    /// Loads (mN).
    pub loads_mn: Vec<f64>,
    /// Seeds of the σ_h > 0 series.
    pub seeds: Vec<u64>,
    /// Equilibration, relaxation and sliding times (s).
    pub times: [f64; 3],
    /// Support speed (m/s).
    pub speed: f64,
    /// Time step (s); `None`: the engine's default (0.25 × the stable estimate).
    pub dt: Option<f64>,
    /// Model request.
    pub model: ModelSpec,
    /// Steps between checkpoints of a run.
    pub checkpoint_every: u64,
    /// Scene override for tests: slider radius (µm) and substrate size (µm).
    pub small_scene: Option<(f64, [f64; 2])>,
}

/// A series and, per load, the indices of its runs (one per seed) in [`Plan::jobs`].
pub type SeriesRuns = (Series, Vec<Vec<usize>>);

/// The campaign's runs, and for each figure its series with the run indices per load (each a
/// list over seeds).
pub struct Plan {
    /// Every run, without duplicates, in order.
    pub jobs: Vec<SlideJob>,
    /// Per figure: per series: per load: the indices of its runs in `jobs`.
    pub figs: Vec<(Fig, Vec<SeriesRuns>)>,
}

impl CampaignParams {
    /// The scene and parameters of one run; errors name the field.
    fn job(&self, s: &Series, load_mn: f64, seed: u64) -> Result<SlideJob> {
        let mut f = SceneFile {
            pattern: Some(s.pattern.to_string()),
            ..Default::default()
        };
        f.slider.theta_deg = Some(s.theta_deg);
        f.substrate.sigma_h_um = Some(s.sigma_h_um);
        f.substrate.seed = Some(seed);
        f.material.youngs_gpa = Some(s.youngs_gpa);
        if let Some((r, size)) = self.small_scene {
            f.slider.radius_um = Some(r);
            f.substrate.size_um = Some(size);
        }
        let scene = f.into_scene()?;
        scene.validate()?;
        let params = DemParams {
            sim: SimParams {
                protocol: dem::ProtocolParams {
                    load: mn_to_n(load_mn),
                    equilibrate_time: self.times[0],
                    relax_time: self.times[1],
                    slide_time: self.times[2],
                    support_speed: self.speed,
                    ..Default::default()
                },
                numerics: dem::NumericsParams {
                    dt: self.dt,
                    ..Default::default()
                },
                ..SimParams::default()
            },
            alpha: deg_to_rad(s.alpha_deg),
            line: None,
            start: Start::Surrogate,
            friction: None,
            io: RunIo {
                checkpoint: None,
                checkpoint_every: self.checkpoint_every,
                xyz: None,
                xyz_every: 10_000,
            },
            resume: None,
            model: self.model,
        };
        Ok(SlideJob {
            name: run_name(&scene, &params),
            scene,
            params,
        })
    }

    /// The run list and the figures' series (see the module docs).
    pub fn plan(&self) -> Result<Plan> {
        let mut jobs: Vec<SlideJob> = Vec::new();
        let mut figs = Vec::new();
        for &fig in &self.figs {
            let mut series = Vec::new();
            for s in fig.series() {
                let seeds: &[u64] = if s.sigma_h_um > 0.0 {
                    &self.seeds
                } else {
                    &[1]
                };
                let mut per_load = Vec::new();
                for &w in &self.loads_mn {
                    let mut ix = Vec::new();
                    for &seed in seeds {
                        let j = self.job(&s, w, seed)?;
                        let k = match jobs.iter().position(|o| o.name == j.name) {
                            Some(k) => k,
                            None => {
                                jobs.push(j);
                                jobs.len() - 1
                            }
                        };
                        ix.push(k);
                    }
                    per_load.push(ix);
                }
                series.push((s, per_load));
            }
            figs.push((fig, series));
        }
        Ok(Plan { jobs, figs })
    }
}

/// The rows behind one figure: per series and load, the statistics over its runs (seeds).
pub fn figure_rows(series: &[SeriesRuns], rows: &[BatchRow]) -> Vec<ConfigStatsRow> {
    let mut out = Vec::new();
    for (s, per_load) in series {
        for ix in per_load {
            let rs: Vec<&BatchRow> = ix.iter().map(|&k| &rows[k]).collect();
            out.push(ConfigStatsRow::new(&s.label(), &rs));
        }
    }
    out
}

/// The study protocol's times (s): equilibrate 10 µs, relax 10 µs, slide 300 µs.
pub fn study_times() -> [f64; 3] {
    [us_to_s(10.0), us_to_s(10.0), us_to_s(300.0)]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(figs: Vec<Fig>, seeds: Vec<u64>) -> CampaignParams {
        CampaignParams {
            figs,
            loads_mn: STUDY_LOADS_MN.to_vec(),
            seeds,
            times: study_times(),
            speed: 0.1,
            dt: None,
            model: ModelSpec::default(),
            checkpoint_every: 100_000,
            small_scene: None,
        }
    }

    /// The study's campaign: 3 + 4 + 5 distinct series × 11 loads = 132 runs with one seed;
    /// the σ_h series (4 at E = 100 GPa, 1 at 50 GPa) × 3 seeds add 2 × 55 runs.
    #[test]
    fn run_list_is_the_union_without_duplicates() {
        let all = vec![Fig::F2b, Fig::F6, Fig::F7];
        let one = params(all.clone(), vec![1]).plan().unwrap();
        assert_eq!(one.jobs.len(), 132);
        let three = params(all, vec![1, 2, 3]).plan().unwrap();
        assert_eq!(three.jobs.len(), 132 + 2 * 55);
        let mut names: Vec<&str> = three.jobs.iter().map(|j| j.name.as_str()).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), three.jobs.len());
        // Fig 6 reuses the tri-tri runs of Fig 2b
        let f6 = &three.figs[1].1;
        assert_eq!(f6.len(), 7);
        assert_eq!(f6[4].1[0], three.figs[0].1[0].1[0]);
        // σ_h series run once per seed, the others once
        let f7 = &three.figs[2].1;
        assert_eq!(f7[0].1[0].len(), 1);
        assert_eq!(f7[1].1[0].len(), 3);
        assert_eq!(STUDY_LOADS_MN.len(), 11);
        assert!(f7[6].0.label().contains("E=50 GPa"));
    }
}
