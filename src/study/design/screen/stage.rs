//! Stage 1 of a design, the screen: the symmetry cut of θ to the pattern's fundamental
//! domain ([`super::domain::cut`]), then the screen of every θ × W
//! ([`crate::study::screen`]: contacts, P_max, coating failure), stored as `screen_<name>.csv`
//! and reused when finished. Cost: one Tier 1 solve per θ × W.

use super::domain::{cut, line_note, theta_note};
use super::inputs::{screen_inputs, screen_params};
use super::params::ScreenStageParams;
use crate::runs::sink::csv_bytes;
use crate::study::design::model::DesignScene;
use crate::study::design::observer::Event;
use crate::study::design::stage_env::StageEnv;
use crate::study::design::store::Timing;
use crate::study::design::symmetry_words::PairSymmetry;
use crate::study::rows::ScreenRow;
use crate::study::screen::screen;
use anyhow::Result;
use std::time::Instant;

/// What the screen stage finds for one pattern.
#[derive(Debug, Clone)]
pub struct Screened {
    /// θ screened (degrees, after the cut).
    pub thetas_deg: Vec<f64>,
    /// The pair's symmetry.
    pub sym: PairSymmetry,
    /// The screen rows (θ outer, loads inner).
    pub rows: Vec<ScreenRow>,
    /// Wall time of the screen when computed (s; `None` if not recorded).
    pub wall_s: Option<f64>,
}

/// The screen stage: its knobs are [`ScreenStageParams`] (the θ list and whether to cut it);
/// it reads the shared loads and contact line.
pub struct ScreenStage<'a> {
    env: StageEnv<'a>,
    params: &'a ScreenStageParams,
}

impl<'a> ScreenStage<'a> {
    /// The stage in `env` with its knobs.
    pub fn new(env: StageEnv<'a>, params: &'a ScreenStageParams) -> Self {
        ScreenStage { env, params }
    }

    /// The cut and the screen of `ds` (see the module docs), telling the observer what the
    /// cut kept and whether the screen was reused.
    pub fn run(&self, ds: &DesignScene) -> Result<Screened> {
        let (obs, sp) = (self.env.obs, self.params);
        let name = ds.name.as_str();
        let (thetas_deg, sym) = cut(ds, sp)?;
        let note = theta_note(&sym, &thetas_deg, sp);
        obs.event(&Event::Symmetry {
            pattern: name,
            sym: &sym,
            screened: thetas_deg.len(),
            given: sp.thetas_deg.len(),
            cut: sp.symmetry_cut,
            note: note.as_ref(),
        });
        if let Some(n) = line_note(ds, self.env.limit.line) {
            obs.event(&Event::LineNote {
                pattern: name,
                note: &n,
            });
        }
        let offset = ds.scene.slider.offset != [0.0; 2];
        if sp.symmetry_cut && (ds.scene.substrate.sigma_h > 0.0 || offset) {
            obs.event(&Event::ApproximateCut {
                pattern: name,
                offset,
            });
        }
        let (rows, wall_s) = self.screen(ds, &thetas_deg)?;
        Ok(Screened {
            thetas_deg,
            sym,
            rows,
            wall_s,
        })
    }

    /// The screen of `ds` at `thetas_deg` (`screen_<name>.csv`), reused when finished.
    fn screen(
        &self,
        ds: &DesignScene,
        thetas_deg: &[f64],
    ) -> Result<(Vec<ScreenRow>, Option<f64>)> {
        let StageEnv { limit, store, obs } = self.env;
        let sp = screen_params(thetas_deg, &limit.loads);
        let inputs = screen_inputs(ds, &sp);
        let rel = format!("screen_{}.csv", ds.name);
        let timing = format!("stages/{}/screen.json", ds.name);
        if let Some(rows) = store.load_csv::<ScreenRow>(&rel, &inputs)? {
            let t = store.load_json::<Timing>(&timing, &inputs)?;
            obs.event(&Event::ScreenReused {
                pattern: &ds.name,
                file: &rel,
                rows: rows.len(),
            });
            return Ok((rows, t.map(|t| t.wall_s)));
        }
        let t0 = Instant::now();
        let mut rows: Vec<ScreenRow> = Vec::new();
        let mut scene = ds.scene.clone();
        scene.slider.theta = 0.0;
        screen(&scene, &sp, &mut rows, obs.progress())?;
        let wall_s = t0.elapsed().as_secs_f64();
        store.save(&rel, &inputs, csv_bytes(&rows)?, Some(rows.len() as u64))?;
        store.save_json(&timing, &inputs, &Timing { wall_s })?;
        obs.event(&Event::Screened {
            pattern: &ds.name,
            thetas: thetas_deg.len(),
            loads: limit.loads.len(),
            wall_s,
        });
        Ok((rows, Some(wall_s)))
    }
}
