//! `superlube patterns`: flags → [`crate::study::patterns`] → one scene file per candidate +
//! `index.csv` (with sidecar).

use super::{parse_list_or_range, SceneArgs};
use crate::runs::{
    meta::scene_file, meta::Inputs, output::Outputs, progress::Progress, progress::Reporter,
};
use crate::study::fairness::Fairness;
use crate::study::patterns::{candidate_scene, candidates, parse_family, PatternParams};
use anyhow::{bail, Context, Result};
use std::path::PathBuf;

/// Default `--max-pq` (also what `design --family` uses).
pub(super) const DEFAULT_MAX_PQ: u32 = 3;
/// Default `--max-order` (also what `design --family` uses).
pub(super) const DEFAULT_MAX_ORDER: f64 = 4.0;

/// Options of `superlube patterns`: enumerate slider lattices of a family over the scene's
/// substrate (spheres not overlapping), classify each (lubric / directional / interlocked, from
/// the two lattices' reciprocal vectors), and write one scene file per candidate plus an index.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scene: SceneArgs,
    /// Family of slider lattices: `directional` (rectangular lattices commensurate with p/q
    /// times a substrate row period along that row, incommensurate across it), `presets`
    /// (triangular, square, honeycomb, kagome; `presets:s=3:6:0.5` sets the lattice constant in
    /// µm), `rectangular:a=3,b=2.6:6:0.05` (a × b in µm, each a value or start:stop:step) or
    /// `oblique:a=3,b=3.2,gamma_deg=60:90:5`.
    #[arg(long, value_name = "SPEC")]
    family: String,
    /// Largest p and q (each ≥ 1) of the commensurate period ratios p/q (directional family and
    /// the `p_q` column).
    #[arg(long = "max-pq", value_name = "N", default_value_t = DEFAULT_MAX_PQ)]
    max_pq: u32,
    /// Classification cut-off: reciprocal vectors shared by slider and substrate count up to
    /// this multiple of the substrate's shortest one (higher orders lock more weakly).
    #[arg(long = "max-order", value_name = "X", default_value_t = DEFAULT_MAX_ORDER)]
    max_order: f64,
    /// What the candidates share, so that `design --patterns` compares them fairly (as
    /// `design --fair`): `area` (the base scene's slider outline, default) or `count` (each
    /// outline scaled to hold the base slider's sphere count; the index's `spheres` column
    /// gives each count).
    #[arg(long = "fair", alias = "normalize", value_name = "RULE", value_enum, default_value_t = Fairness::Area)]
    fair: Fairness,
    /// Output folder: DIR/<pattern_id>.toml per candidate (the base scene with the slider
    /// lattice replaced, so equal slider outline and area) and DIR/index.csv
    /// (`pattern_id,scene_file,lattice,basis,outline,spheres,commensurate_direction_deg,p_q,
    /// contact_line_spacing_um,contact_type,lubric_direction_deg,a1_um,a2_um`) with a sidecar.
    #[arg(long = "out-dir", alias = "out", value_name = "DIR")]
    out: PathBuf,
}

/// Runs `superlube patterns`.
pub fn run(a: Args) -> Result<()> {
    let sc = a.scene.resolve(None)?;
    let params = check(&a.family, a.max_pq, a.max_order)?;
    generate(&sc, &params, a.fair, &a.out, None).map(|_| ())
}

/// The checked parameters of a family (errors name `--family`, `--max-pq`, `--max-order`).
pub(super) fn check(family: &str, max_pq: u32, max_order: f64) -> Result<PatternParams> {
    if max_pq < 1 {
        bail!("`--max-pq`: {max_pq} must be at least 1");
    }
    if !(max_order.is_finite() && max_order >= 1.0) {
        bail!("`--max-order`: {max_order} must be a number ≥ 1");
    }
    Ok(PatternParams {
        family: parse_family(family, |v, n| {
            parse_list_or_range(v, &format!("--family {n}"))
        })?,
        family_text: family.to_string(),
        max_pq,
        max_order,
    })
}

/// Writes the candidates of `params` over the scene `sc` into the folder `out` (one scene file
/// each and `index.csv`, with sidecars) and returns the index's path. Cost: the enumeration and
/// one classification per lattice (milliseconds), one small file per candidate. With `flag`
/// (`design --family`), a folder whose `index.csv` lists other candidates is refused naming
/// `flag`, before anything is written.
pub(super) fn generate(
    sc: &crate::cli::scene_args::Resolved,
    params: &PatternParams,
    fair: Fairness,
    out: &std::path::Path,
    keep_other: Option<&str>,
) -> Result<PathBuf> {
    if out.exists() && !out.is_dir() {
        bail!("`--out-dir`: {} exists and is not a folder", out.display());
    }
    let cands = candidates(&sc.scene, params)?;
    let width = cands.len().to_string().len().max(3);
    let mut files = Vec::new();
    for (k, c) in cands.iter().enumerate() {
        let id = format!("p{:0width$}", k + 1);
        files.push(candidate_scene(&sc.scene, c, &id, fair)?);
    }
    let mut csv = csv::Writer::from_writer(Vec::new());
    for (_, row) in &files {
        csv.serialize(row)?;
    }
    let index = csv.into_inner().map_err(|e| anyhow::anyhow!("{e}"))?;
    if let Some(flag) = keep_other {
        let path = out.join("index.csv");
        if path.exists() && std::fs::read(&path).ok().as_deref() != Some(&index[..]) {
            bail!(
                "`{flag}`: {} lists other candidates (another family or scene); give another --out-dir (nothing was written)",
                path.display()
            );
        }
    }
    std::fs::create_dir_all(out)
        .with_context(|| format!("`--out-dir`: cannot create {}", out.display()))?;
    let rep = Reporter::stderr();
    let mut outs = Outputs::new(
        Inputs {
            workflow: "patterns".into(),
            scene: Some(scene_file(&sc.scene)),
            params: serde_json::json!({
                "family": params.family_text,
                "max_pq": params.max_pq,
                "max_order": params.max_order,
                "normalize": fair,
            }),
        },
        sc.warnings.clone(),
    );
    for (f, row) in &files {
        let path = out.join(&row.scene_file);
        let text = toml::to_string(f).map_err(anyhow::Error::from);
        outs.write("scene", Some(&path), text.map(String::into_bytes), None);
    }
    outs.write(
        "--out-dir index",
        Some(&out.join("index.csv")),
        Ok(index),
        Some(files.len() as u64),
    );
    let mut kinds = std::collections::BTreeMap::new();
    for (_, r) in &files {
        *kinds.entry(r.contact_type.clone()).or_insert(0) += 1;
    }
    rep.note(&format!(
        "patterns: {} candidates ({}) in {}",
        files.len(),
        kinds
            .iter()
            .map(|(k, n)| format!("{n} {k}"))
            .collect::<Vec<_>>()
            .join(", "),
        out.display()
    ));
    outs.finish()?;
    Ok(out.join("index.csv"))
}
