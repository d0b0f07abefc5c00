//! The pattern scenes of `superlube design`'s command line (`--pattern`, `--scene`,
//! `--patterns`, `--family`).

use super::super::SceneArgs;
use super::args::Args;
use crate::study::design::DesignScene;
use anyhow::{bail, Result};
use std::path::PathBuf;

/// The scene flags shared by every pattern, as given (for the reproduction commands).
pub(super) fn scene_args(a: &Args, pattern: Option<String>, scene: Option<PathBuf>) -> SceneArgs {
    SceneArgs {
        pattern,
        scene,
        overrides: a.overrides.clone(),
    }
}

/// The pattern scenes of the command line (errors name `--pattern` / `--scene`).
pub(super) fn scenes(a: &Args) -> Result<Vec<DesignScene>> {
    let mut files = a.scene.clone();
    let mut facts = Vec::new();
    let mut pattern = a.pattern.clone();
    if a.recipe.fair.is_some() && a.recipe.vary.is_empty() && a.family.is_none() {
        bail!("`--fair`: says what the recipes of --vary or the candidates of --family share: give one of them");
    }
    let generated = family(a, &mut pattern, &mut files)?;
    if let Some(index) = a.patterns.as_ref().or(generated.as_ref()) {
        facts = crate::study::patterns::index_facts(index)?;
        // the contact-type pre-screen orders the surrogate's work
        files.extend(crate::study::patterns::prescreen_order(
            crate::study::patterns::index_scenes(index)?,
            &facts,
        ));
    }
    let patterns: Vec<String> = match (&pattern, files.is_empty()) {
        (Some(p), _) => p.split(',').map(|s| s.trim().to_string()).collect(),
        (None, true) => vec!["square-tri".into(), "tri-tri".into()],
        (None, false) => vec![],
    };
    let mut out = named(a, patterns)?;
    for f in &files {
        out.push(from_file(a, f, &facts)?);
    }
    for (k, s) in out.iter().enumerate() {
        if out[..k].iter().any(|t| t.name == s.name) {
            bail!(
                "`--pattern`/`--scene`: `{}` is given twice (patterns and scene-file stems name the outputs)",
                s.name
            );
        }
    }
    a.recipe.expand(out, &a.out)
}

/// The candidates' index `--family` generates from the one base pattern or scene (taken out of
/// `pattern` / `files`), `None` without `--family`.
fn family(
    a: &Args,
    pattern: &mut Option<String>,
    files: &mut Vec<PathBuf>,
) -> Result<Option<PathBuf>> {
    let Some(spec) = &a.family else {
        return Ok(None);
    };
    if a.scene.len() > 1 || pattern.as_deref().is_some_and(|p| p.contains(',')) {
        bail!("`--family`: give at most one --pattern or --scene (the base of the candidates)");
    }
    let base = scene_args(a, pattern.take(), files.pop()).resolve(None)?;
    let params = super::super::patterns::check(
        spec,
        super::super::patterns::DEFAULT_MAX_PQ,
        super::super::patterns::DEFAULT_MAX_ORDER,
    )?;
    Ok(Some(super::super::patterns::generate(
        &base,
        &params,
        a.recipe.fair.unwrap_or_default(),
        &a.out.join("patterns"),
        Some("--family"),
    )?))
}

/// The scenes of the study's named `patterns` (`--pattern`).
fn named(a: &Args, patterns: Vec<String>) -> Result<Vec<DesignScene>> {
    let extra = a.overrides.flags();
    let mut out = Vec::new();
    for p in patterns {
        if !surrogate::scene::PATTERNS.contains(&p.as_str()) {
            bail!(
                "`--pattern`: unknown pattern `{p}` (expected a comma list of {})",
                surrogate::scene::PATTERNS.join(", ")
            );
        }
        let r = scene_args(a, Some(p.clone()), None).resolve(Some(0.0))?;
        let mut flags = vec!["--pattern".to_string(), p.clone()];
        flags.extend(extra.iter().cloned());
        out.push(DesignScene {
            name: p,
            scene: r.scene,
            flags,
            warnings: r.warnings,
            facts: None,
            recipe: None,
        });
    }
    Ok(out)
}

/// The scene of the file `f` (`--scene`, or a candidate of an index), with its facts from
/// the index where it has some.
fn from_file(
    a: &Args,
    f: &std::path::Path,
    facts: &[(String, crate::study::patterns::CandidateFacts)],
) -> Result<DesignScene> {
    let name = f
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    if name.is_empty()
        || !name
            .chars()
            .all(|c| c.is_alphanumeric() || "-_.".contains(c))
    {
        bail!(
            "`--scene`: {}: the file stem names the outputs and must be letters, digits, `-`, `_`, `.`",
            f.display()
        );
    }
    let r = scene_args(a, None, Some(f.to_path_buf())).resolve(Some(0.0))?;
    let mut flags = vec!["--scene".to_string(), f.display().to_string()];
    flags.extend(a.overrides.flags());
    let facts = facts
        .iter()
        .find(|(id, _)| *id == name)
        .map(|(_, f)| f.clone());
    Ok(DesignScene {
        name,
        scene: r.scene,
        flags,
        warnings: r.warnings,
        facts,
        recipe: None,
    })
}
