//! The shortlist: which orientations of the screen go on to the α scan and the friction
//! estimate.
//!
//! **The coating-intact load of an orientation.** From the screen of every θ × W:
//! `W_c(θ)` = the highest load of the list up to which the coating is intact at *every* load
//! (P_max ≤ P_crit, at the screened placement); 0 when it fails at the lowest load.
//!
//! **The rule.** Orientations are grouped by `W_c` into *levels* (the distinct `W_c` > 0,
//! highest first). From the top level — the orientations whose coating survives the highest
//! load asked, if any — every orientation is kept (up to `max_top`); from each lower level the
//! `per_level` orientations with the lowest P_max at that level's load (the most margin;
//! ties: more contacts, then smaller θ). The pipeline evaluates the levels from the top down
//! and stops at the first level whose load is below the best superlubric load B found so far
//! (once it has at least the candidates it confirms): a design is superlubric only where its
//! coating is intact on the whole sliding path, and the path starts at the screened placement,
//! so its superlubric load can never exceed `W_c(θ)` — no orientation of a level below B can
//! reach B.
//!
//! Why levels and not only the survivors of the highest load: a pattern may have no survivor,
//! or only commensurate ones (tri-tri at 0°, 21.8°, …: many contacts, low pressure, but
//! friction far above the superlubric limit); the low-friction, incommensurate orientations
//! (tri-tri near 30°) carry the load on few contacts and survive only lower loads. Descending
//! the levels finds them, and the bound says when to stop.

use super::params::ShortlistParams;
use crate::study::design::model::{DesignScene, Level, Orientation};
use crate::study::design::observer::Event;
use crate::study::design::screen::Screened;
use crate::study::design::stage_env::StageEnv;
use crate::study::rows::ScreenRow;
use anyhow::Result;
use surrogate::units::gpa_to_pa;

/// What the shortlist stage finds for one pattern.
#[derive(Debug, Clone)]
pub struct Shortlisted {
    /// The orientations of the screen, in θ order.
    pub orientations: Vec<Orientation>,
    /// The levels, highest first (empty: no orientation keeps its coating at the lowest load).
    pub levels: Vec<Level>,
}

/// Stage 2 of a design, the shortlist: the rule of the module docs on a pattern's
/// screen; its knobs are [`ShortlistParams`]; it reads the shared loads.
pub struct ShortlistStage<'a> {
    env: StageEnv<'a>,
    params: &'a ShortlistParams,
}

impl<'a> ShortlistStage<'a> {
    /// The stage in `env` with its knobs.
    pub fn new(env: StageEnv<'a>, params: &'a ShortlistParams) -> Self {
        ShortlistStage { env, params }
    }

    /// The orientations and levels of `ds`'s screen. Cost: one pass over the screen rows and
    /// a sort per level.
    pub fn run(&self, (ds, screened): (&DesignScene, &Screened)) -> Result<Shortlisted> {
        let (loads, obs) = (&self.env.limit.loads, self.env.obs);
        let orientations = orientations(&screened.rows, loads, ds.scene.coating.p_crit);
        let levels = levels(
            &orientations,
            loads,
            self.params.per_level,
            self.params.max_top,
        );
        if levels.is_empty() {
            obs.event(&Event::NoIntactOrientation { pattern: &ds.name });
        }
        Ok(Shortlisted {
            orientations,
            levels,
        })
    }
}

/// The orientations of a screen (rows θ outer, loads inner, `loads` in N ascending), in θ
/// order. A row without equilibrium counts as a failed coating.
pub fn orientations(rows: &[ScreenRow], loads: &[f64], p_crit: f64) -> Vec<Orientation> {
    let n = loads.len().max(1);
    rows.chunks(n)
        .map(|rs| {
            let mut o = Orientation {
                theta_deg: rs[0].theta_deg,
                w_intact: 0.0,
                p_max: rs[0].p_max_GPa.map_or(f64::INFINITY, gpa_to_pa),
                contacts: rs[0].contacts.unwrap_or(0),
            };
            for (r, &w) in rs.iter().zip(loads) {
                let intact = r.error.is_empty()
                    && r.p_max_GPa.is_some_and(|p| gpa_to_pa(p) <= p_crit)
                    && r.coating_failed == Some(false);
                if !intact {
                    break;
                }
                o.w_intact = w;
                o.p_max = r.p_max_GPa.map_or(f64::INFINITY, gpa_to_pa);
                o.contacts = r.contacts.unwrap_or(0);
            }
            o
        })
        .collect()
}

/// The levels of the rule (see the module docs), highest first.
pub fn levels(
    orients: &[Orientation],
    loads: &[f64],
    per_level: usize,
    max_top: usize,
) -> Vec<Level> {
    let top_load = loads.last().copied().unwrap_or(0.0);
    let mut out = Vec::new();
    for &w in loads.iter().rev() {
        let mut at: Vec<Orientation> = orients
            .iter()
            .filter(|o| o.w_intact == w && w > 0.0)
            .cloned()
            .collect();
        if at.is_empty() {
            continue;
        }
        at.sort_by(|a, b| {
            a.p_max
                .total_cmp(&b.p_max)
                .then(b.contacts.cmp(&a.contacts))
                .then(a.theta_deg.total_cmp(&b.theta_deg))
        });
        let top = w == top_load;
        let size = at.len();
        at.truncate(if top { max_top } else { per_level });
        out.push(Level {
            load: w,
            size,
            picks: at,
            top,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(theta: f64, w: f64, p: f64, c: usize) -> ScreenRow {
        ScreenRow {
            pattern: "x".into(),
            theta_deg: theta,
            load_mN: w,
            contacts: Some(c),
            p_max_GPa: Some(p),
            z_um: Some(3.0),
            coating_failed: Some(p > 4.0),
            failed_contacts: Some(0),
            tilt_x_urad: Some(0.0),
            tilt_y_urad: Some(0.0),
            model: "rigid-z".into(),
            residual_rel: Some(0.0),
            iterations: Some(1),
            error: String::new(),
        }
    }

    #[test]
    fn levels_keep_the_top_and_the_best_per_level() {
        let loads = [1e-3, 2e-3, 3e-3];
        // θ 0: survives all; θ 1: up to 2 mN; θ 2 and 3: up to 1 mN; θ 4: fails at once;
        // θ 5: fails at 2 but intact again at 3 (still W_c = 1 mN)
        let rows = vec![
            row(0.0, 1.0, 1.0, 100),
            row(0.0, 2.0, 1.5, 100),
            row(0.0, 3.0, 2.0, 100),
            row(1.0, 1.0, 2.0, 50),
            row(1.0, 2.0, 3.9, 50),
            row(1.0, 3.0, 4.1, 50),
            row(2.0, 1.0, 3.5, 30),
            row(2.0, 2.0, 4.5, 30),
            row(2.0, 3.0, 5.0, 30),
            row(3.0, 1.0, 3.0, 30),
            row(3.0, 2.0, 4.2, 30),
            row(3.0, 3.0, 5.0, 30),
            row(4.0, 1.0, 4.5, 10),
            row(4.0, 2.0, 5.0, 10),
            row(4.0, 3.0, 6.0, 10),
            row(5.0, 1.0, 3.8, 30),
            row(5.0, 2.0, 4.1, 30),
            row(5.0, 3.0, 3.9, 30),
        ];
        let o = orientations(&rows, &loads, 4e9);
        let wc: Vec<f64> = o.iter().map(|x| x.w_intact).collect();
        assert_eq!(wc, vec![3e-3, 2e-3, 1e-3, 1e-3, 0.0, 1e-3]);
        let l = levels(&o, &loads, 2, 10);
        assert_eq!(l.len(), 3);
        assert!(l[0].top && l[0].load == 3e-3 && l[0].picks.len() == 1);
        assert_eq!(l[1].picks[0].theta_deg, 1.0);
        // level 1 mN: three orientations, the two with the lowest P_max kept
        assert_eq!(l[2].size, 3);
        let t: Vec<f64> = l[2].picks.iter().map(|x| x.theta_deg).collect();
        assert_eq!(t, vec![3.0, 2.0]);
        // without survivors of the top load, no level is "top"
        let l = levels(&o[1..], &loads, 2, 10);
        assert!(!l[0].top && l[0].load == 2e-3);
    }
}
