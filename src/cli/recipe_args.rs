//! `design --vary`, `--fair`, `--skip-invalid`: scene fields as design variables. The flags
//! and their one call, [`RecipeArgs::expand`], which turns each pattern of the design into its
//! recipes ([`crate::study::recipe`]) before any work.

use crate::study::design::DesignScene;
use crate::study::fairness::{Fairness, MadeFair};
use crate::study::recipe;
use anyhow::{Context, Result};
use std::path::Path;

/// The recipe flags of `superlube design`.
#[derive(clap::Args, Debug, Default)]
pub struct RecipeArgs {
    /// A scene field as a design variable, `FIELD=LIST`, repeatable (several form a grid):
    /// FIELD is the dotted scene-file field in its file unit (`slider.sphere_diameter_um` µm,
    /// `slider.lattice.spacing_um` µm, `slider.radius_um` µm (the disc pad), `slider.outline.size_um.0`
    /// µm (a rectangle's width), `slider.material.youngs_GPa` GPa, `slider.material.poisson`,
    /// `substrate.sigma_h_um` µm, `substrate.material.youngs_GPa` GPa, …: any numeric field,
    /// docs/scenes-patterns.md); LIST is a comma list or start:stop:step. Each recipe is a
    /// candidate of the design, named `<pattern>+FIELD=VALUE+…` in patterns.csv; its scene
    /// file is written to OUT/recipes/.
    #[arg(long = "vary", value_name = "FIELD=LIST", allow_hyphen_values = true)]
    pub vary: Vec<String>,
    /// With --vary or --family: what the recipes or candidates share (as `superlube patterns
    /// --fair`): `area` (the base slider's outline, equal slider area in µm², default) or
    /// `count` (each outline scaled to hold the base slider's sphere count). patterns.csv
    /// gives each one's mean pressure (kPa) and load per sphere (µN) at its limit either way;
    /// the report states the rule.
    #[arg(long, alias = "normalize", value_enum, value_name = "RULE")]
    pub fair: Option<Fairness>,
    /// With --vary: skip the recipes that cannot be made (overlapping spheres, a pad beyond
    /// the substrate, a value out of range) and name them in the log, instead of refusing the
    /// grid.
    #[arg(long = "skip-invalid", requires = "vary")]
    pub skip_invalid: bool,
}

impl RecipeArgs {
    /// Each pattern of `scenes` replaced by its recipes (none given: `scenes` as it is); their
    /// scene files written to `out/recipes/`. Errors name `--vary`. Cost: one scene build per
    /// recipe.
    pub fn expand(&self, scenes: Vec<DesignScene>, out: &Path) -> Result<Vec<DesignScene>> {
        if self.vary.is_empty() {
            return Ok(scenes);
        }
        let varies = self
            .vary
            .iter()
            .map(|t| recipe::parse_vary(t, "--vary"))
            .collect::<Result<Vec<_>>>()?;
        let fair = self.fair.unwrap_or_default();
        let dir = out.join("recipes");
        let mut all = Vec::new();
        for ds in scenes {
            let r = recipe::variants(
                &ds.scene,
                &ds.name,
                &varies,
                fair,
                self.skip_invalid,
                "--vary",
            )
            .map_err(|e| anyhow::anyhow!("{e:#} (base scene {})", ds.name))?;
            for (name, why) in &r.skipped {
                eprintln!("note: `--skip-invalid`: recipe {name} skipped: {why}");
            }
            if !r.skipped.is_empty() {
                eprintln!(
                    "note: {}: {} of {} recipes skipped (`--skip-invalid`)",
                    ds.name,
                    r.skipped.len(),
                    r.skipped.len() + r.variants.len()
                );
            }
            std::fs::create_dir_all(&dir)
                .with_context(|| format!("cannot create {}", dir.display()))?;
            for v in r.variants {
                let path = dir.join(format!("{}.toml", v.name));
                let text = toml::to_string(&v.file)?;
                surrogate::atomic_file::write_atomic(&path, text.as_bytes())
                    .with_context(|| format!("cannot write {}", path.display()))?;
                let mut warnings = ds.warnings.clone();
                warnings.extend(recipe::outside_validated_range(&v.scene));
                let outside = recipe::validated_range(&v.scene);
                all.push(DesignScene {
                    name: v.name,
                    scene: v.scene,
                    flags: vec!["--scene".into(), path.display().to_string()],
                    warnings,
                    facts: Some(crate::study::patterns::CandidateFacts {
                        made_fair: Some(MadeFair::Recipe(fair)),
                        ..ds.facts.clone().unwrap_or_default()
                    }),
                    recipe: Some(recipe::RecipeFacts {
                        base: ds.name.clone(),
                        outside,
                    }),
                });
            }
        }
        Ok(all)
    }
}
