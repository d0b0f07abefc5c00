//! # Recipes: scene fields as design variables
//!
//! A fabrication recipe is a scene with some of its numeric fields chosen: the slider's sphere
//! diameter, each body's material, the lattice spacing, the pad (outline) size. [`variants`]
//! makes the grid of recipes of one base scene: each [`Vary`] is a dotted field of the scene
//! file in user units (`slider.sphere_diameter_um`, `slider.material.youngs_GPa`,
//! `slider.lattice.spacing_um`, `slider.outline.size_um.0`, …) with its values; several form a
//! grid. Each value is written into the base scene's file form ([`surrogate::scene::scene_file`], a
//! TOML value tree) at its path, and the tree is parsed and validated as a scene file: every
//! numeric field works, and an unknown or non-numeric field, or a value the scene refuses, is
//! named in the error. The variants are the candidates of the design's multi-pattern ranking
//! (`crate::study::design::DesignScene`), named by their varied values.
//!
//! **Fair comparison** ([`Fairness`]): every variant keeps the base slider's outline (equal slider
//! area, the default), or its outline is scaled so that it holds the base slider's sphere count
//! ([`Fairness::Count`], as `superlube patterns --fair count`).
//!
//! **Validated range** ([`validated_range`]): the surrogate's verdict band was measured at the
//! study's sphere size (3 µm) and modulus (100 GPa, docs/validation/verdict-band.md); a recipe
//! outside them, or whose design lies in the mount-resonance band, is flagged ([`Outside`]) so
//! that the DEM, not the surrogate, names it (`crate::study::design::confirm`).
//!
//! Cost: one scene build per variant (plus about 40 per variant with [`Fairness::Count`]).

use crate::study::fairness::Fairness;
use anyhow::{anyhow, bail, Result};
use surrogate::{Scene, SceneFile};

mod range;
#[cfg(test)]
mod tests;

pub use range::{
    outside_validated_range, validated_range, Body, Outside, RecipeFacts, VALIDATED_DIAMETER,
    VALIDATED_YOUNGS,
};

/// Most variants a grid may have (a design screens each one).
pub const MAX_VARIANTS: usize = 1000;

/// One varied field: its dotted path in the scene file (user units) and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Vary {
    /// Dotted path in the scene file: tables by name, array elements by index
    /// (`slider.outline.size_um.0`).
    pub field: String,
    /// The values (in the field's unit), in the order given.
    pub values: Vec<f64>,
}

/// One recipe: the base scene with the varied fields set.
#[derive(Debug, Clone)]
pub struct Variant {
    /// `<base>+<field>=<value>+…` (file-name safe: letters, digits, `.`, `_`, `-`, `+`, `=`).
    pub name: String,
    /// The varied fields and their values (user units), in the order of the [`Vary`]s.
    pub values: Vec<(String, f64)>,
    /// The scene file of the recipe (user units), complete: reloads to `scene`.
    pub file: SceneFile,
    /// The validated scene (SI).
    pub scene: Scene,
}

/// The variants of a grid, and those that cannot be made when they may be skipped.
#[derive(Debug, Clone, Default)]
pub struct Recipes {
    /// The variants that can be made, in grid order (the first [`Vary`] slowest).
    pub variants: Vec<Variant>,
    /// The variants skipped (`name`, why), when skipping was asked for.
    pub skipped: Vec<(String, String)>,
}

/// Parses `FIELD=LIST` (a comma list or `start:stop:step`, as the other range inputs); `flag`
/// names the input in errors. Checks only the form; [`variants`] checks the field.
pub fn parse_vary(text: &str, flag: &str) -> Result<Vary> {
    let (field, list) = text.split_once('=').ok_or_else(|| {
        anyhow!("`{flag}`: `{text}` must be FIELD=LIST, e.g. slider.sphere_diameter_um=2:3:0.25")
    })?;
    let field = field.trim();
    if field.is_empty()
        || !field
            .split('.')
            .all(|p| !p.is_empty() && p.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
    {
        bail!("`{flag}`: `{field}` is not a dotted scene field (e.g. slider.material.youngs_GPa)");
    }
    if list.trim().is_empty() {
        bail!("`{flag}`: `{field}` has an empty list: give values like 50,100,200 or a range like 2:3:0.25");
    }
    let values = super::range::parse_list_or_range(list, &format!("{flag} {field}"))?;
    Ok(Vary {
        field: field.to_string(),
        values,
    })
}

/// Writes `v` at the dotted `path` of a TOML tree: missing tables are created, an array element
/// is named by its index; a whole number is written as an integer when the field holds one
/// (`seed`, `sides`). Errors name the path part that is not a table or an array.
pub fn set_path(root: &mut toml::Value, path: &str, v: f64) -> Result<()> {
    let parts: Vec<&str> = path.split('.').collect();
    let mut cur = root;
    for (k, part) in parts.iter().enumerate() {
        let last = k + 1 == parts.len();
        let here = parts[..=k].join(".");
        cur = match cur {
            toml::Value::Table(t) => {
                if last {
                    let int = matches!(t.get(*part), Some(toml::Value::Integer(_)))
                        || (t.get(*part).is_none() && INTEGER_FIELDS.contains(part));
                    t.insert(part.to_string(), number(v, int, &here)?);
                    return Ok(());
                }
                t.entry(part.to_string())
                    .or_insert_with(|| toml::Value::Table(Default::default()))
            }
            toml::Value::Array(a) => {
                let i: usize = part.parse().map_err(|_| {
                    anyhow!("`{here}`: an array's element is named by its index (0, 1, …)")
                })?;
                let n = a.len();
                let e = a
                    .get_mut(i)
                    .ok_or_else(|| anyhow!("`{here}`: the array has {n} elements"))?;
                if last {
                    let int = matches!(e, toml::Value::Integer(_));
                    *e = number(v, int, &here)?;
                    return Ok(());
                }
                e
            }
            _ => bail!(
                "`{}` is a value, not a table: `{path}` does not name a scene field",
                parts[..k].join(".")
            ),
        };
    }
    Ok(())
}

/// Integer fields of the scene file (written as TOML integers).
const INTEGER_FIELDS: [&str; 2] = ["seed", "sides"];

fn number(v: f64, int: bool, path: &str) -> Result<toml::Value> {
    if int {
        if v.fract() != 0.0 || v < 0.0 || v > i64::MAX as f64 {
            bail!("`{path}` takes a whole number, not {v}");
        }
        Ok(toml::Value::Integer(v as i64))
    } else {
        Ok(toml::Value::Float(v))
    }
}

/// The base scene's file form in which the fields are set: [`surrogate::scene_file`], with the
/// lattices written out when a lattice field is varied.
fn base_file(base: &Scene, varies: &[Vary]) -> SceneFile {
    let lattice = varies
        .iter()
        .any(|v| v.field.starts_with("slider.lattice") || v.field.starts_with("substrate.lattice"));
    if lattice {
        surrogate::scene::scene_file_with_lattices(base)
    } else {
        surrogate::scene::scene_file(base)
    }
}

/// The scene file `file` with `values` set at their fields. An unknown field or a value of the
/// wrong kind is an error saying what the scene file accepts there (the parser's own words,
/// without the text of the file, which the user never wrote); the caller names the field.
pub fn apply(file: &SceneFile, values: &[(String, f64)]) -> Result<SceneFile> {
    let mut tree = toml::Value::try_from(file)?;
    for (field, v) in values {
        set_path(&mut tree, field, *v)?;
    }
    let text = toml::to_string(&tree)?;
    toml::from_str(&text).map_err(|e: toml::de::Error| {
        anyhow!(
            "{} (the scene file's fields: docs/scenes-patterns.md)",
            e.message().trim()
        )
    })
}

/// `v` as it prints in a variant's name (shortest round-trip decimal).
pub fn value_text(v: f64) -> String {
    format!("{}", super::rows::label(v))
}

/// Every variant of `base` (named `base_name`) over the grid of `varies` (the first slowest),
/// made fair by `fair`; `flag` names the input in errors. A variant that cannot be made
/// (overlapping spheres, a pad beyond the substrate, a value out of range) is an error naming
/// its field and value, or, with `skip_invalid`, is skipped and listed. Checked before any
/// work: an unknown or non-numeric field fails on the first variant; an empty grid is refused.
/// Cost: one scene build per variant (about 40 more with [`Fairness::Count`]).
pub fn variants(
    base: &Scene,
    base_name: &str,
    varies: &[Vary],
    fair: Fairness,
    skip_invalid: bool,
    flag: &str,
) -> Result<Recipes> {
    if varies.is_empty() {
        return Ok(Recipes::default());
    }
    for (k, v) in varies.iter().enumerate() {
        if varies[..k].iter().any(|u| u.field == v.field) {
            bail!("`{flag}`: `{}` is given twice", v.field);
        }
        if v.values.is_empty() {
            bail!("`{flag}`: `{}` has an empty list", v.field);
        }
    }
    let n: usize = varies.iter().map(|v| v.values.len()).product();
    if n > MAX_VARIANTS {
        bail!("`{flag}`: the grid has {n} variants, more than {MAX_VARIANTS}: use fewer values");
    }
    if fair == Fairness::Count {
        if let Some(v) = varies
            .iter()
            .find(|v| v.field.starts_with("slider.outline") || v.field == "slider.radius_um")
        {
            bail!(
                "`{flag}`: `{}` sets the slider's outline, which the equal-sphere-count comparison scales itself: compare at equal area instead",
                v.field
            );
        }
    }
    let file = base_file(base, varies);
    let target = base.slider_sites_local().len();
    // the field check: the first value of every field on the base (unknown and non-numeric
    // fields fail here, whatever the grid)
    for v in varies {
        apply(&file, &[(v.field.clone(), v.values[0])])
            .map_err(|e| anyhow!("`{flag}`: `{}`: {e:#}", v.field))?;
    }
    let mut out = Recipes::default();
    for k in 0..n {
        let mut rest = k;
        let mut values = vec![(String::new(), 0.0); varies.len()];
        for (i, v) in varies.iter().enumerate().rev() {
            let m = v.values.len();
            values[i] = (v.field.clone(), v.values[rest % m]);
            rest /= m;
        }
        let name = std::iter::once(base_name.to_string())
            .chain(
                values
                    .iter()
                    .map(|(f, v)| format!("{f}={}", value_text(*v))),
            )
            .collect::<Vec<_>>()
            .join("+");
        let made = (|| -> Result<(SceneFile, Scene)> {
            let mut f = apply(&file, &values)?;
            let mut s = f.into_scene().map_err(|e| anyhow!("{e}"))?;
            if fair == Fairness::Count && s.slider_sites_local().len() != target {
                f = crate::study::patterns::scale_to_count(&f, target)?;
                s = f.into_scene().map_err(|e| anyhow!("{e}"))?;
            }
            Ok((f, s))
        })();
        match made {
            Ok((file, mut scene)) => {
                scene.slider.theta = base.slider.theta;
                out.variants.push(Variant {
                    name,
                    values,
                    file,
                    scene,
                })
            }
            Err(e) if skip_invalid => out.skipped.push((name, format!("{e:#}"))),
            Err(e) => bail!(
                "`{flag}`: the recipe {} cannot be made: {e:#} (skip such recipes with the skip-invalid option)",
                values
                    .iter()
                    .map(|(f, v)| format!("{f} = {}", value_text(*v)))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        }
    }
    if out.variants.is_empty() {
        bail!(
            "`{flag}`: none of the {n} recipes can be made (first: {})",
            out.skipped.first().map_or("", |s| s.1.as_str())
        );
    }
    Ok(out)
}

/// The base name and the varied values of a recipe's name `<base>+FIELD=VALUE+…` (as
/// [`variants`] names it); `None` for a name without varied values. O(length).
pub fn parse_name(name: &str) -> Option<(String, Vec<(String, f64)>)> {
    let mut parts = name.split('+');
    let base = parts.next()?.to_string();
    let values: Vec<(String, f64)> = parts
        .map(|p| {
            let (f, v) = p.split_once('=')?;
            Some((f.to_string(), v.parse().ok()?))
        })
        .collect::<Option<_>>()?;
    (!values.is_empty()).then_some((base, values))
}
