//! Every check of `superlube design`'s flags, before any work: the patterns, the design's
//! parameters (SI) and the tolerance against each pattern's θ domain.

use super::super::design_dem_args::design_run_params;
use super::super::point_args::{self, STUDY_THETAS};
use super::super::{checks, parse_list_or_range};
use super::args::Args;
use super::scenes::scenes;
use crate::runs::output::check_outputs;
use crate::study::dem_run::DemParams;
use crate::study::design::{
    cut, AlphaScanParams, ConfirmParams, DesignParams, DesignScene, ScreenStageParams,
    ShortlistParams, ToleranceParams,
};
use anyhow::{bail, Result};
use dem::SimParams;
use surrogate::units::{mn_to_n, um_to_m, us_to_s};

/// Every check of `superlube design`, before any work.
pub fn prepare(a: &Args) -> Result<(Vec<DesignScene>, DesignParams)> {
    let thetas_deg = match a.theta.degrees()? {
        Some(t) => t,
        None => point_args::thetas_deg(STUDY_THETAS)?,
    };
    let loads = loads(a)?;
    let mu_superlubric = a.verdict.mu_superlubric()?;
    let shortlist = shortlist(a)?;
    let alpha_scan = alpha_scan(a)?;
    let friction = a.friction.params()?;
    let confirm = confirm(a, &loads, alpha_scan.line)?;
    let tolerance = tolerance(a)?;
    let params = DesignParams {
        loads: crate::study::load::Loads::new(loads),
        mu_superlubric,
        screen: ScreenStageParams {
            thetas_deg,
            theta_default: a.theta.text.is_none(),
            symmetry_cut: !a.no_symmetry_cut,
        },
        shortlist,
        alpha_scan,
        friction,
        tolerance,
        confirm,
        fab_yield: a.fab_yield.params()?,
    };
    let scenes = scenes(a)?;
    check_domains(&scenes, &params)?;
    check_outputs(&[("--out-dir", Some(&a.out.join("report.md")))])?;
    Ok((scenes, params))
}

/// `--load-mn` (N), strictly increasing.
fn loads(a: &Args) -> Result<Vec<f64>> {
    let loads = a.load.newtons()?;
    if let Some(k) = loads.windows(2).position(|w| w[1] <= w[0]) {
        bail!(
            "`--load-mn`: the loads must be strictly increasing ({} mN then {} mN): a design's superlubric load is the highest of an increasing list",
            a.load.text.split(',').nth(k).unwrap_or("?").trim(),
            a.load.text.split(',').nth(k + 1).unwrap_or("?").trim()
        );
    }
    Ok(loads)
}

/// The shortlist's flags.
fn shortlist(a: &Args) -> Result<ShortlistParams> {
    if a.per_level == 0 {
        bail!("`--per-level`: 0 would keep no orientation below the top level; give ≥ 1");
    }
    if a.max_top == 0 {
        bail!("`--max-top`: 0 would keep no orientation of the top level; give ≥ 1");
    }
    Ok(ShortlistParams {
        per_level: a.per_level,
        max_top: a.max_top,
    })
}

/// The α scan's flags, the contact line included (SI).
fn alpha_scan(a: &Args) -> Result<AlphaScanParams> {
    if a.alphas_per_theta == 0 {
        bail!("`--best-alphas`: give ≥ 1");
    }
    let step = checks::positive(a.alpha_step_deg, "--alpha-step-deg")?;
    if step > 90.0 {
        bail!("`--alpha-step-deg`: {step} must be at most 90");
    }
    let refine: Vec<f64> = if a.alpha_refine_deg.trim() == "none" {
        vec![]
    } else {
        parse_list_or_range(&a.alpha_refine_deg, "--alpha-refine-deg")?
    };
    let mut prev = step;
    for &r in &refine {
        if !(r > 0.0 && r < prev) {
            bail!("`--alpha-refine-deg`: each step must be positive and below the previous one ({r} after {prev})");
        }
        prev = r;
    }
    let line = checks::line_deg(a.line_deg)?;
    let scan_length = checks::positive(a.scan_um, "--scan-distance-um").map(um_to_m)?;
    let scan_step = checks::positive(a.scan_step_um, "--scan-step-um").map(um_to_m)?;
    if scan_step > scan_length {
        bail!(
            "`--scan-step-um`: {} must not exceed --scan-distance-um {}",
            a.scan_step_um,
            a.scan_um
        );
    }
    Ok(AlphaScanParams {
        alpha_step_deg: step,
        alpha_refine_deg: refine,
        line,
        scan_length,
        scan_step,
        alphas_per_theta: a.alphas_per_theta,
    })
}

/// The DEM confirmation's flags: how many designs, at which of `loads` (N), how many runs side
/// by side, the protocol and model (with the contact line `line`), the shard.
fn confirm(a: &Args, loads: &[f64], line: Option<f64>) -> Result<ConfirmParams> {
    if !a.no_dem && a.confirm == 0 {
        bail!("`--confirm`: 0 designs to confirm with the DEM on; give --confirm ≥ 1, or --no-dem to stop before the DEM");
    }
    let confirm_loads = match &a.confirm_loads {
        Some(t) => {
            let v = point_args::loads(t).map_err(|e| {
                anyhow::anyhow!(
                    "{}",
                    e.to_string().replace("`--load-mn`", "`--confirm-loads-mn`")
                )
            })?;
            for &w in &v {
                if !loads.iter().any(|&l| (l - w).abs() <= 1e-12 * l) {
                    bail!(
                        "`--confirm-loads-mn`: {} mN is not one of --load-mn (the DEM is compared with the estimate at the same load)",
                        surrogate::units::n_to_mn(w)
                    );
                }
            }
            v
        }
        None => {
            let mut v = vec![loads[0], loads[loads.len() / 2], loads[loads.len() - 1]];
            v.dedup();
            v
        }
    };
    let jobs = match a.jobs {
        Some(0) => bail!("`--jobs`: give ≥ 1 DEM runs side by side"),
        Some(j) => j,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let (dem, dem_is_study_protocol) = dem_protocol(a, line)?;
    let dem_shard = match &a.shard {
        Some(t) => {
            if a.no_dem {
                bail!("`--shard`: shards the DEM confirmation runs, but --no-dem skips them");
            }
            crate::runs::shard::Shard::parse(t, "--shard")?
        }
        None => crate::runs::shard::Shard::ALL,
    };
    Ok(ConfirmParams {
        designs: a.confirm,
        loads: confirm_loads,
        no_dem: a.no_dem,
        jobs,
        dem_shard,
        dem,
        dem_is_study_protocol,
        protocol_check: !a.no_protocol_check,
    })
}

/// The DEM protocol and model of every confirmation run (with the contact line `line`), and
/// whether the protocol is the study's.
fn dem_protocol(a: &Args, line: Option<f64>) -> Result<(DemParams, bool)> {
    let times = [
        (a.dem_equilibrate_us, "--dem-equilibrate-us"),
        (a.dem_slide_us, "--dem-slide-us"),
        (a.dem_speed_m_s, "--dem-speed-m-s"),
    ];
    for (v, f) in times {
        checks::positive(v, f)?;
    }
    checks::non_negative(a.dem_relax_us, "--dem-relax-us")?;
    let dt = a
        .dem_dt_us
        .map(|d| checks::time_us(d, "--dem-dt-us"))
        .transpose()?;
    let study = SimParams::default();
    let sim = SimParams {
        protocol: dem::ProtocolParams {
            load: mn_to_n(1.0),
            equilibrate_time: us_to_s(a.dem_equilibrate_us),
            relax_time: us_to_s(a.dem_relax_us),
            slide_time: us_to_s(a.dem_slide_us),
            support_speed: a.dem_speed_m_s,
            ..Default::default()
        },
        numerics: dem::NumericsParams {
            dt,
            ..Default::default()
        },
        ..SimParams::default()
    };
    let dem_is_study_protocol = sim.protocol.equilibrate_time == study.protocol.equilibrate_time
        && sim.protocol.relax_time == study.protocol.relax_time
        && sim.protocol.slide_time == study.protocol.slide_time
        && sim.protocol.support_speed == study.protocol.support_speed;
    let dem = design_run_params(sim, line, a.dem_model.request());
    Ok((dem, dem_is_study_protocol))
}

/// The fabrication tolerance's flags.
fn tolerance(a: &Args) -> Result<ToleranceParams> {
    let (theta_tol_deg, direction_tol_deg) = a.tol.checked()?;
    let theta_tol_step_deg = checks::positive(a.theta_tol_step, "--theta-tol-step-deg")?;
    let direction_tol_step_deg =
        checks::positive(a.direction_tol_step, "--direction-tol-step-deg")?;
    let seeds = a
        .seeds
        .as_deref()
        .map_or(Ok(Vec::new()), |t| checks::seed_list(t, "--extra-seeds"))?;
    Ok(ToleranceParams {
        theta_tol_deg,
        direction_tol_deg,
        theta_tol_step_deg,
        direction_tol_step_deg,
        seeds,
    })
}

/// The tolerance and the extra seeds against each pattern's θ domain and substrate.
fn check_domains(scenes: &[DesignScene], params: &DesignParams) -> Result<()> {
    for s in scenes {
        let (_, sym) = cut(s, &params.screen)?;
        let (lo, hi) = (sym.domain().lo_deg, sym.domain().hi_deg);
        if 2.0 * params.tolerance.theta_tol_deg >= hi - lo {
            bail!(
                "`--theta-tol-deg`: ±{}° spans the whole θ domain of {} ([{lo}°, {hi}°]); give a tolerance below {}°",
                params.tolerance.theta_tol_deg,
                s.name,
                0.5 * (hi - lo)
            );
        }
        if !params.tolerance.seeds.is_empty() && s.scene.substrate.sigma_h == 0.0 {
            bail!(
                "`--extra-seeds`: {} has a flat substrate (σ_h = 0), so every seed gives the same one; give --sigma-h-um > 0 or leave --extra-seeds out",
                s.name
            );
        }
    }
    Ok(())
}
