//! `index.csv` and the candidates' scene files: writing them, scaling a pad to a sphere
//! count, reading an index back and ordering it by the contact-type pre-screen.

use super::contact_type::ContactType;
use super::tidy::tidy;
use super::{line_spacing, Candidate};
use crate::study::fairness::{Fairness, MadeFair};
use crate::study::input::Input;
use anyhow::{bail, Result};
use surrogate::Scene;

/// One row of `index.csv`, in user units.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct IndexRow {
    /// `p001`, … in candidate order.
    pub pattern_id: String,
    /// The candidate's scene file, relative to the index.
    pub scene_file: String,
    /// Lattice kind (`rectangular`, `oblique`, `honeycomb`, …).
    pub lattice: String,
    /// Basis sites in µm, `x y;x y` (empty: Bravais).
    pub basis: String,
    /// Slider outline (`disc r=100`, …).
    pub outline: String,
    /// Slider spheres.
    pub spheres: usize,
    /// Commensurate direction (degrees from the substrate x axis), empty when none.
    pub commensurate_direction_deg: Option<f64>,
    /// Period ratio `p/q` along it, empty when none.
    pub p_q: String,
    /// Expected contact-line spacing (µm; moiré of the first shells, as `corrugation`).
    pub contact_line_spacing_um: f64,
    /// `lubric`, `directional` or `interlocked`.
    pub contact_type: String,
    /// Free sliding direction of a directional contact (degrees, in [0, 180)); empty otherwise.
    pub lubric_direction_deg: Option<f64>,
    /// First lattice vector (µm), `x y`.
    pub a1_um: String,
    /// Second lattice vector (µm), `x y`.
    pub a2_um: String,
}

fn pair_um(v: [f64; 2]) -> String {
    format!(
        "{} {}",
        tidy(surrogate::units::m_to_um(v[0])),
        tidy(surrogate::units::m_to_um(v[1]))
    )
}

/// The scene file of candidate `c` on the base scene `base` (user units): the base with the
/// slider lattice (and basis) replaced; θ, substrate, material and coating kept; the outline
/// kept (`Fairness::Area`: the base's slider area) or scaled to hold the base's sphere count
/// (`Fairness::Count`, [`scale_to_count`]). Also its index row (`spheres` counted from the
/// built scene). Errors name the candidate.
pub fn candidate_scene(
    base: &Scene,
    c: &Candidate,
    id: &str,
    fairness: Fairness,
) -> Result<(surrogate::SceneFile, IndexRow)> {
    let um2 = |v: [f64; 2]| {
        [
            tidy(surrogate::units::m_to_um(v[0])),
            tidy(surrogate::units::m_to_um(v[1])),
        ]
    };
    let mut f = crate::runs::meta::scene_file(base);
    f.slider.sites = None;
    f.slider.lattice = Some(surrogate::scene::LatticeFile {
        kind: "oblique".into(),
        a1_um: Some(um2(c.lattice.a1)),
        a2_um: Some(um2(c.lattice.a2)),
        basis_um: (!c.basis.is_empty()).then(|| c.basis.iter().map(|b| um2(*b)).collect()),
        ..Default::default()
    });
    if fairness == Fairness::Count {
        f = scale_to_count(&f, base.slider_sites_local().len())
            .map_err(|e| anyhow::anyhow!("candidate {id}: {e}"))?;
    }
    let scene = f
        .clone()
        .into_scene()
        .map_err(|e| anyhow::anyhow!("candidate {id}: {e}"))?;
    let row = IndexRow {
        pattern_id: id.to_string(),
        scene_file: format!("{id}.toml"),
        lattice: c.kind.clone(),
        basis: c
            .basis
            .iter()
            .map(|b| pair_um(*b))
            .collect::<Vec<_>>()
            .join(";"),
        outline: scene.geometry.outline.describe(scene.slider.radius),
        spheres: scene.slider_sites_local().len(),
        commensurate_direction_deg: c.commensurate.as_ref().map(|m| m.direction_deg),
        p_q: c
            .commensurate
            .as_ref()
            .map_or(String::new(), |m| format!("{}/{}", m.p, m.q)),
        contact_line_spacing_um: tidy(surrogate::units::m_to_um(line_spacing(base, &c.lattice))),
        contact_type: c.contact.name().into(),
        lubric_direction_deg: match c.contact {
            ContactType::Directional { lubric_deg } => Some(lubric_deg),
            _ => None,
        },
        a1_um: pair_um(c.lattice.a1),
        a2_um: pair_um(c.lattice.a2),
    };
    Ok((f, row))
}

/// The slider of `f` scaled about its centre by `k` (disc radius, outline radius, sides and
/// vertices; the lattice is kept).
fn scaled(f: &surrogate::SceneFile, k: f64) -> surrogate::SceneFile {
    let mut g = f.clone();
    g.slider.radius_um = g.slider.radius_um.map(|r| r * k);
    if let Some(o) = &mut g.slider.outline {
        o.radius_um = o.radius_um.map(|r| r * k);
        o.size_um = o.size_um.map(|[w, h]| [w * k, h * k]);
        if let Some(v) = &mut o.vertices_um {
            for p in v.iter_mut() {
                *p = [p[0] * k, p[1] * k];
            }
        }
    }
    g
}

/// `f` with its slider outline scaled so that it holds the sphere count closest to `target`
/// (ties: the smaller slider). Bisection on the scale: about 40 scene builds.
pub fn scale_to_count(f: &surrogate::SceneFile, target: usize) -> Result<surrogate::SceneFile> {
    let count =
        |k: f64| -> Result<usize> { Ok(scaled(f, k).into_scene()?.slider_sites_local().len()) };
    let n1 = count(1.0)?.max(1);
    let guess = (target as f64 / n1 as f64).sqrt();
    // the smallest scale with at least `target` spheres, between lo (fewer) and hi (enough)
    let (mut lo, mut hi) = (guess * 0.5, guess * 2.0);
    match count(hi) {
        Ok(n) if n >= target => {}
        Ok(_) => {
            anyhow::bail!("its outline cannot hold {target} spheres at twice the estimated scale")
        }
        // twice the estimate does not fit the substrate: grow from the estimate in 5 % steps
        // (an error once even the needed scale does not fit)
        Err(_) => {
            hi = guess;
            while count(hi)? < target {
                hi *= 1.05;
            }
            lo = if hi == guess { guess * 0.5 } else { hi / 1.05 };
        }
    }
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if count(mid)? >= target {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let (n_lo, n_hi) = (count(lo)?, count(hi)?);
    let k = if target - n_lo.min(target) <= n_hi - target {
        lo
    } else {
        hi
    };
    Ok(scaled(f, k))
}

/// What `superlube patterns` recorded of one candidate that the scene itself does not say (the
/// index's columns a design carries into its `patterns.csv`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CandidateFacts {
    /// `lubric`, `directional` or `interlocked`.
    pub contact_type: String,
    /// Period ratio `p/q` along the commensurate direction (empty when none).
    pub p_q: String,
    /// Commensurate direction (degrees from the substrate x axis), when there is one.
    pub commensurate_direction_deg: Option<f64>,
    /// What the candidates share and who made them so: the rule `superlube patterns --fair`
    /// recorded in the index's sidecar, or the recipe grid's; `None` when nothing says (a
    /// hand-written index).
    pub made_fair: Option<MadeFair>,
}

/// The facts of every candidate of an `index.csv`, by `pattern_id`. Errors name `--patterns`.
pub fn index_facts(index: &std::path::Path) -> Result<Vec<(String, CandidateFacts)>> {
    #[derive(serde::Deserialize)]
    struct Row {
        pattern_id: String,
        #[serde(default)]
        contact_type: String,
        #[serde(default)]
        p_q: String,
        #[serde(default)]
        commensurate_direction_deg: Option<f64>,
    }
    let mut r = csv::Reader::from_path(index).map_err(|e| {
        let why = match e.kind() {
            csv::ErrorKind::Io(io) => surrogate::io_error::plain(io),
            _ => e.to_string(),
        };
        anyhow::anyhow!(
            "{}: cannot read {}: {why}",
            Input::Patterns,
            index.display()
        )
    })?;
    // the fairness rule the candidates were made with (a hand-written index has no sidecar)
    let made_fair = crate::runs::meta::Sidecar::of(index)
        .ok()
        .and_then(|s| serde_json::from_value::<Fairness>(s.params.get("normalize")?.clone()).ok())
        .map(MadeFair::Patterns);
    let mut out = Vec::new();
    for (k, row) in r.deserialize::<Row>().enumerate() {
        let row = row.map_err(|e| {
            anyhow::anyhow!(
                "{}: {} line {}: {e}",
                Input::Patterns,
                index.display(),
                k + 2
            )
        })?;
        out.push((
            row.pattern_id,
            CandidateFacts {
                contact_type: row.contact_type,
                p_q: row.p_q,
                commensurate_direction_deg: row.commensurate_direction_deg,
                made_fair,
            },
        ));
    }
    Ok(out)
}

/// Rank of a contact type in the pre-screen order: `lubric` (in every direction) first, then
/// `directional`, then `interlocked`, then anything else (an index without the column).
pub fn prescreen_class(contact_type: &str) -> usize {
    match contact_type {
        "lubric" => 0,
        "directional" => 1,
        "interlocked" => 2,
        _ => 3,
    }
}

/// The scene files `files` of an index (row order) in the order the contact-type pre-screen
/// gives ([`prescreen_class`] of each file's `pattern_id` in `facts`, its stem), index order
/// within a class: the surrogate's work goes to the most promising candidates first.
/// Deterministic (a stable sort).
pub fn prescreen_order(
    files: Vec<std::path::PathBuf>,
    facts: &[(String, CandidateFacts)],
) -> Vec<std::path::PathBuf> {
    let class = |f: &std::path::Path| {
        let stem = f.file_stem().map(|s| s.to_string_lossy().into_owned());
        facts
            .iter()
            .find(|(id, _)| Some(id) == stem.as_ref())
            .map_or(3, |(_, c)| prescreen_class(&c.contact_type))
    };
    let mut v: Vec<(usize, std::path::PathBuf)> =
        files.into_iter().map(|f| (class(&f), f)).collect();
    v.sort_by_key(|(c, _)| *c);
    v.into_iter().map(|(_, f)| f).collect()
}

/// The scene files of an `index.csv` written by `superlube patterns` (its `scene_file` column,
/// relative to the index), in row order. Errors name `--patterns` and the line.
pub fn index_scenes(index: &std::path::Path) -> Result<Vec<std::path::PathBuf>> {
    let text = std::fs::read_to_string(index).map_err(|e| {
        anyhow::anyhow!(
            "{}: cannot read {}: {}",
            Input::Patterns,
            index.display(),
            surrogate::io_error::plain(&e)
        )
    })?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let Some(col) = header.iter().position(|c| *c == "scene_file") else {
        bail!(
            "{}: {} line 1: no `scene_file` column (an index.csv of `superlube patterns`)",
            Input::Patterns,
            index.display()
        );
    };
    let dir = index.parent().unwrap_or(std::path::Path::new(""));
    let mut out = Vec::new();
    for (k, l) in lines.enumerate().filter(|(_, l)| !l.trim().is_empty()) {
        match l.split(',').nth(col).filter(|f| !f.is_empty()) {
            Some(f) => out.push(dir.join(f)),
            None => bail!(
                "{}: {} line {}: no scene_file",
                Input::Patterns,
                index.display(),
                k + 2
            ),
        }
    }
    if out.is_empty() {
        bail!("{}: {} lists no pattern", Input::Patterns, index.display());
    }
    Ok(out)
}
