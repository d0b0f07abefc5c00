//! LAMMPS's point of the tiers diagram: the scene exported by `dem::export` (the `superlube
//! export-lammps` deck) with the DEM's setting and protocol, run by stock LAMMPS in a temporary
//! folder. μ is the deck's own window mean of the spring force (`RESULT friction_mN=` of
//! `log.lammps`) over W, its standard error from ten block means of the time series in the same
//! window (the last 2/3 of the slide); P_max is the largest sample of the time series in the
//! window (the Rust engine takes the largest of every step, so LAMMPS's can only be lower).
//! Stock LAMMPS has one constant μ (the coating's μ1): where contacts exceed P_crit its μ is not
//! the coating law's. Cost: the export plus the LAMMPS process's CPU time; the deck integrates
//! every sphere explicitly, at the explicit model's step (about 1/28 of the full model's on the
//! study scenes), so it is the most expensive point.

use super::cost::measure;
use super::dem::{block_mean_se, sim_params, DemSetting, Protocol};
use super::row::{Measured, Setting, Values};
use super::StudyScene;
use crate::study::verdict::Verdict;
use dem::export::{export_lammps, files, ExportOptions};
use std::path::Path;
use std::process::Command;
use surrogate::units::{gpa_to_pa, n_to_mn, s_to_us};

/// μ below which a run is superlubric (the study's).
const MU_SL: f64 = 0.02;

/// The LAMMPS binary: `SUPERLUBE_LMP` or `lmp`, if it runs (`-h` succeeds); `None` otherwise.
pub fn find_lmp() -> Option<String> {
    let exe = std::env::var("SUPERLUBE_LMP").unwrap_or_else(|_| "lmp".into());
    let ok = Command::new(&exe)
        .arg("-h")
        .output()
        .is_ok_and(|o| o.status.success());
    ok.then_some(exe)
}

/// What one LAMMPS run gave (user units, as the deck writes them).
struct LammpsResult {
    /// Window mean of the spring force (mN).
    friction_mn: f64,
    /// Its standard error from ten block means (mN).
    friction_se_mn: f64,
    /// Largest P_max sample in the window (GPa).
    p_max_gpa: f64,
    /// Steps and step (µs) of the run.
    steps: u64,
    dt_us: f64,
}

/// Exports `s` with setting `d` under `pr` into a temporary folder, runs `exe` on it and
/// measures it (export and run together). A failure is a row with its reason in `note`.
pub fn run_one(
    s: &StudyScene,
    pr: &Protocol,
    d: &DemSetting,
    exe: &str,
    setting: Setting,
) -> Measured {
    let dir = std::env::temp_dir().join(format!(
        "superlube-wp-lammps-{}-{}",
        std::process::id(),
        s.name
    ));
    let (r, cost) = measure(|| export_and_run(s, pr, d, exe, &dir));
    let _ = std::fs::remove_dir_all(&dir);
    let w_mn = n_to_mn(s.load);
    let values = match r {
        Ok(r) => {
            let mu = r.friction_mn / w_mn;
            let p_max = gpa_to_pa(r.p_max_gpa);
            let superlubric = p_max <= s.scene.coating.p_crit && mu < MU_SL;
            Values {
                mu: Some(mu),
                mu_se: r.friction_se_mn / w_mn,
                p_max: Some(p_max),
                verdict: Some(if superlubric {
                    Verdict::Superlubric
                } else {
                    Verdict::Not
                }),
                note: format!(
                    "LAMMPS ({exe}): {} steps of {:.3e} µs, constant μ = μ1 = {}",
                    r.steps, r.dt_us, s.scene.coating.mu1
                ),
                ..Values::default()
            }
        }
        Err(e) => Values {
            note: format!("LAMMPS run failed: {e:#}"),
            ..Values::default()
        },
    };
    Measured {
        setting,
        cost,
        values,
    }
}

fn export_and_run(
    s: &StudyScene,
    pr: &Protocol,
    d: &DemSetting,
    exe: &str,
    dir: &Path,
) -> anyhow::Result<LammpsResult> {
    let params = {
        let mut params = sim_params(s, pr, d);
        params.protocol.alpha = s.direction;
        // only the substrate spheres the slider can reach along its path (exact: the others
        // never touch it)
        params.active.prune_substrate = true;
        params
    };
    let opts = ExportOptions {
        mu: s.scene.coating.mu1,
        dump_interval: 0.0,
        command: "superlube figures (work-precision: the tiers diagram)".into(),
        alpha_and_line: Some((s.direction, 0.0)),
        ..ExportOptions::default()
    };
    let ex = export_lammps(&s.scene, &params, &opts)?;
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir)?;
    ex.write(dir)?;
    let out = Command::new(exe)
        .current_dir(dir)
        .args(["-in", files::DECK, "-log", "log.lammps", "-screen", "none"])
        .output()?;
    let log = std::fs::read_to_string(dir.join("log.lammps")).unwrap_or_default();
    if !out.status.success() {
        let tail: Vec<&str> = log.lines().rev().take(5).collect();
        anyhow::bail!("{} exited with {}: {}", exe, out.status, tail.join(" | "));
    }
    let friction_mn = log
        .lines()
        .find_map(|l| l.strip_prefix("RESULT friction_mN="))
        .and_then(|v| v.split_whitespace().next()?.parse::<f64>().ok())
        .ok_or_else(|| anyhow::anyhow!("no `RESULT friction_mN=` line in log.lammps"))?;
    let t0 = s_to_us(pr.equilibrate + pr.relax + d.slide_time / 3.0);
    let t1 = s_to_us(pr.equilibrate + pr.relax + d.slide_time);
    let text = std::fs::read_to_string(dir.join(files::TIMESERIES))?;
    let mut lines = text.lines();
    let head: Vec<&str> = lines
        .next()
        .unwrap_or_default()
        .trim_start_matches("# ")
        .split(',')
        .collect();
    let col = |name: &str| {
        head.iter()
            .position(|c| *c == name)
            .ok_or_else(|| anyhow::anyhow!("no column `{name}` in {}", files::TIMESERIES))
    };
    let (ct, cf, cp) = (col("t_us")?, col("spring_force_mN")?, col("p_max_GPa")?);
    let mut force = Vec::new();
    let mut p_max_gpa = 0.0f64;
    for line in lines.filter(|l| !l.trim().is_empty()) {
        let v: Vec<f64> = line
            .split(',')
            .map(|x| x.trim().parse().unwrap_or(f64::NAN))
            .collect();
        let value = |c: usize| v.get(c).copied().unwrap_or(f64::NAN);
        let t = value(ct);
        if t >= t0 - 1e-9 && t <= t1 + 1e-9 {
            force.push(value(cf));
            p_max_gpa = p_max_gpa.max(value(cp));
        }
    }
    if force.len() < 10 {
        anyhow::bail!("{} samples in the friction window", force.len());
    }
    Ok(LammpsResult {
        friction_mn,
        friction_se_mn: block_mean_se(&force)[1],
        p_max_gpa,
        steps: ex.meta.steps.total(),
        dt_us: ex.meta.dt_us,
    })
}
