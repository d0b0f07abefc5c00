//! The exact commands that reproduce every row of the design (the report's "Reproduce any row"):
//! `superlube screen`, `corrugation`, `friction` per evaluated θ and `slide` per DEM run.

use super::rows::{DemProtocol, DemRow};
use crate::study::design::{DesignParams, Evaluated, PatternResult};
use crate::study::rows::label;
use std::fmt::Write as _;
use surrogate::units::{m_to_um, n_to_mn, rad_to_deg, s_to_us};

/// `--pattern P …` or `--scene F …` of a pattern, as one string.
pub fn flags(pr: &PatternResult) -> String {
    pr.scene.flags.join(" ")
}

/// A θ list as the shortest exact `--theta-deg` text: a range `a:b:s` if it parses back to the
/// same values, else the list.
pub fn theta_text(v: &[f64]) -> String {
    let list = v
        .iter()
        .map(|t| format!("{t}"))
        .collect::<Vec<_>>()
        .join(",");
    if v.len() >= 3 {
        let step = label(v[1] - v[0]);
        let range = format!("{}:{}:{}", v[0], v[v.len() - 1], step);
        if crate::study::range::parse_list_or_range(&range, "--theta-deg").is_ok_and(|r| r == v) {
            return range;
        }
    }
    list
}

/// The design's loads (mN), comma separated (a `--load-mn` value).
pub fn loads_text(p: &DesignParams) -> String {
    p.loads
        .iter()
        .map(|&w| format!("{}", label(n_to_mn(w))))
        .collect::<Vec<_>>()
        .join(",")
}

/// The DEM protocol flags of the design's runs (or the study's), with the model `model` (the
/// design's, or `auto` for a recipe the DEM decides: `confirm::dem_model`).
pub fn protocol_flags(p: &DesignParams, study: bool, model: dem::ModelRequest) -> String {
    let s = &p.confirm.dem.sim;
    let mut f = String::new();
    if !study {
        let _ = write!(
            f,
            " --equilibrate-us {} --relax-us {} --slide-us {} --speed-m-s {}",
            label(s_to_us(s.protocol.equilibrate_time)),
            label(s_to_us(s.protocol.relax_time)),
            label(s_to_us(s.protocol.slide_time)),
            s.protocol.support_speed
        );
    }
    if let Some(dt) = s.numerics.dt {
        let _ = write!(f, " --dt-us {}", label(s_to_us(dt)));
    }
    let _ = write!(f, " --model {}", model.name());
    f
}

/// ` --line-deg L` when the design fixes the contact line, else nothing.
pub fn line_flag(p: &DesignParams) -> String {
    p.alpha_scan
        .line
        .map_or(String::new(), |l| format!(" --line-deg {}", rad_to_deg(l)))
}

/// `superlube screen …` reproducing `screen_<p>.csv` (same input hash).
pub fn screen_command(pr: &PatternResult, p: &DesignParams) -> String {
    format!(
        "superlube screen {} --theta-deg {} --load-mn {} --out screen_{}.csv",
        flags(pr),
        theta_text(&pr.thetas_deg),
        loads_text(p),
        pr.scene.name
    )
}

/// `superlube corrugation …` reproducing the α scan of the evaluated θ `e`.
pub fn corrugation_command(pr: &PatternResult, e: &Evaluated, p: &DesignParams) -> String {
    let alphas: Vec<String> = e.scan_alphas_deg.iter().map(|a| format!("{a}")).collect();
    format!(
        "superlube corrugation {} --theta-deg {} --load-mn {} --alpha-deg {} --distance-um {} --step-um {}{}",
        flags(pr),
        e.eval.theta_deg,
        e.eval.scan_load_mN,
        alphas.join(","),
        label(m_to_um(p.alpha_scan.scan_length)),
        label(m_to_um(p.alpha_scan.scan_step)),
        line_flag(p)
    )
}

/// `superlube friction …` reproducing the friction estimates of the best α's of `e`.
pub fn friction_command(pr: &PatternResult, e: &Evaluated, p: &DesignParams) -> String {
    format!(
        "superlube friction {} --theta-deg {} --alpha-deg {} --load-mn {}{} --length-um {} --max-period-um {} --step-um {} --transient-um {} --k0-n-m {} --transverse-um {} --mu-superlubric {}",
        flags(pr),
        e.eval.theta_deg,
        e.eval
            .alphas_deg
            .iter()
            .map(|a| format!("{a}"))
            .collect::<Vec<_>>()
            .join(","),
        loads_text(p),
        line_flag(p),
        label(m_to_um(p.friction.length)),
        label(m_to_um(p.friction.max_period)),
        label(m_to_um(p.friction.step)),
        label(m_to_um(p.friction.transient)),
        p.friction.k0,
        label(m_to_um(p.friction.transverse)),
        p.mu_superlubric
    )
}

/// `superlube slide …` reproducing the DEM run `d` (`study`: the study's protocol).
pub fn slide_command(
    pr: &PatternResult,
    d: &DemRow,
    protocol: DemProtocol,
    p: &DesignParams,
) -> String {
    format!(
        "superlube slide {} --theta-deg {} --alpha-deg {} --load-mn {}{}{} --json {}/slide.json --out {}/slide.csv",
        flags(pr),
        d.theta_deg,
        d.alpha_deg,
        d.load_mN,
        line_flag(p),
        protocol_flags(
            p,
            protocol == DemProtocol::Study,
            pr.ranking.get(d.rank.saturating_sub(1)).map_or(p.confirm.dem.model.request, |c| {
                crate::study::design::confirm::dem_model(pr, c, &p.confirm).request
            })
        ),
        d.run_dir,
        d.run_dir
    )
}
