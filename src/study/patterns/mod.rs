//! The pattern-candidate workflow of `superlube patterns`: slider lattices of a family whose
//! spheres do not overlap, each classified against the substrate from the two lattices'
//! reciprocal-space geometry (the contact types of Panizon et al., Nanoscale 15, 1299 (2023)),
//! written as one scene file per candidate plus an index.
//!
//! **Classification.** Reciprocal vectors G of the slider (with its basis' structure factor
//! S(G) = Σ_b e^{iG·b} ≠ 0) and of the substrate that coincide (|G_s − G_b| ≤ 1e-6 |G|), with
//! 0 < |G| ≤ `max_order` × the substrate's shortest G, lock the two patterns together:
//! none → **lubric** in every direction; all parallel to one direction n → **directional**:
//! the energy varies along n only, sliding perpendicular to n is free (the lubric direction);
//! two non-parallel ones → **interlocked**. Cost O(order² × basis).
//!
//! **Directionally commensurate candidates.** For each substrate row direction u (lattice
//! vectors of the first two shells, up to the substrate's rotations) with row period d_u and
//! row spacing h_u = cell area / d_u: a rectangular slider with period a = (p/q)·d_u along u
//! (coprime p, q ≤ `max_pq`) and b = (m + f)·h_u across it, f the fractional part of a badly
//! approximable number (golden ratio, √2, √5 − 1) and m the smallest integer that makes
//! b ≥ max(sphere diameter, a), so that the slider rows never settle onto the substrate rows. Kept when
//! the spheres do not overlap, the classification is directional with u as the commensurate
//! direction, and the moiré contact lines (as `corrugation` finds them) run along u.

use crate::study::input::Input;
use anyhow::{bail, Result};
use std::f64::consts::PI;
use surrogate::map::{contact_line_direction, MapParams};
use surrogate::scene::symmetry::{gcd, rotation_order};
use surrogate::scene::{lattice_name, min_site_distance, overlaps};
use surrogate::units::{deg_to_rad, m_to_um, um_to_m};
use surrogate::{Lattice, Scene};

mod classify;
mod contact_type;
mod index;
mod tidy;

pub use classify::classify;
pub use contact_type::ContactType;
pub use index::*;
pub use tidy::tidy;

/// A family of slider lattices.
#[derive(Debug, Clone, PartialEq)]
pub enum Family {
    /// Directionally commensurate rectangular lattices (see the module docs).
    Directional,
    /// Rectangular lattices `a × b` (m), every combination of the values.
    Rectangular { a: Vec<f64>, b: Vec<f64> },
    /// Oblique lattices `a1 = (a, 0)`, `a2 = b (cos γ, sin γ)` (m, rad).
    Oblique {
        a: Vec<f64>,
        b: Vec<f64>,
        gamma: Vec<f64>,
    },
    /// Triangular, square, honeycomb and kagome lattices of lattice constant `s` (m).
    Presets { s: Vec<f64> },
}

/// Parameters of the candidate search (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct PatternParams {
    /// The family.
    pub family: Family,
    /// The family as given (for records).
    pub family_text: String,
    /// Largest p and q of the commensurate ratios.
    pub max_pq: u32,
    /// Cut-off of the classification: coincident G up to this multiple of the substrate's
    /// shortest reciprocal vector.
    pub max_order: f64,
}

/// The commensurate direction of a candidate.
#[derive(Debug, Clone, PartialEq)]
pub struct Commensurate {
    /// Direction u of the shared row (degrees from the substrate x axis).
    pub direction_deg: f64,
    /// Slider period along u = p/q × the substrate's.
    pub p: u32,
    /// See `p`.
    pub q: u32,
}

/// One slider lattice.
#[derive(Debug, Clone, PartialEq)]
pub struct Candidate {
    /// Slider lattice (m).
    pub lattice: Lattice,
    /// Basis (m; empty: Bravais).
    pub basis: Vec<[f64; 2]>,
    /// Named kind of the lattice (`rectangular`, `honeycomb`, …).
    pub kind: String,
    /// Commensurate direction, if the slider shares a row period ratio with the substrate.
    pub commensurate: Option<Commensurate>,
    /// Contact type.
    pub contact: ContactType,
}

/// Parses a family: `directional`, `presets[:s=3:6:0.5]`, `rectangular:a=3,b=2.6:6:0.05`,
/// `oblique:a=3,b=3.2,gamma_deg=60:90:5`; every value a number or `start:stop:step` (µm,
/// degrees). Errors name the family input ([`Input::Family`]).
/// `values` parses one value or range (the command line's list/range parser), given the text
/// and a name for its errors (`SPEC: k`).
pub fn parse_family(spec: &str, values: impl Fn(&str, &str) -> Result<Vec<f64>>) -> Result<Family> {
    let (kind, rest) = spec.split_once(':').unwrap_or((spec, ""));
    let mut vals: Vec<(String, Vec<f64>)> = Vec::new();
    for part in rest.split(',').filter(|s| !s.is_empty()) {
        let Some((k, v)) = part.split_once('=') else {
            bail!(
                "{} `{spec}`: `{part}` is not `name=value` or `name=start:stop:step`",
                Input::Family
            );
        };
        let list = values(v, &format!("{spec}: {k}"))?;
        vals.push((k.trim().to_string(), list));
    }
    let take = |name: &str, default: Option<f64>, um: bool| -> Result<Vec<f64>> {
        let f = |x: f64| if um { um_to_m(x) } else { deg_to_rad(x) };
        match vals.iter().find(|(k, _)| k == name) {
            Some((_, v)) => Ok(v.iter().map(|&x| f(x)).collect()),
            None => match default {
                Some(d) => Ok(vec![f(d)]),
                None => bail!("{} `{spec}`: `{kind}` needs `{name}=…`", Input::Family),
            },
        }
    };
    let known = |names: &[&str]| -> Result<()> {
        if let Some((k, _)) = vals.iter().find(|(k, _)| !names.contains(&k.as_str())) {
            bail!(
                "{} `{spec}`: unknown parameter `{k}` of `{kind}` (expected {})",
                Input::Family,
                names.join(", ")
            );
        }
        Ok(())
    };
    Ok(match kind {
        "directional" => {
            known(&[])?;
            Family::Directional
        }
        "presets" => {
            known(&["s"])?;
            Family::Presets {
                s: take("s", Some(3.0), true)?,
            }
        }
        "rectangular" => {
            known(&["a", "b"])?;
            Family::Rectangular {
                a: take("a", None, true)?,
                b: take("b", None, true)?,
            }
        }
        "oblique" => {
            known(&["a", "b", "gamma_deg"])?;
            Family::Oblique {
                a: take("a", None, true)?,
                b: take("b", None, true)?,
                gamma: take("gamma_deg", None, false)?,
            }
        }
        other => bail!(
            "{}: unknown family `{other}` (expected directional, presets, rectangular:a=…,b=…, oblique:a=…,b=…,gamma_deg=…)",
            Input::Family
        ),
    })
}

/// Substrate row directions (rad) and periods (m): lattice vectors up to twice the shortest,
/// at angles in [0, 180°/n] (n the rotation order: the others are images under rotations).
fn row_directions(l: &Lattice) -> Vec<(f64, f64)> {
    let smin = l.min_spacing();
    let lim = PI / rotation_order(l) as f64 + 1e-9;
    let mut out: Vec<(f64, f64)> = Vec::new();
    for i in -4i32..=4 {
        for j in -4i32..=4 {
            let v = l.point(i as f64, j as f64);
            let len = v[0].hypot(v[1]);
            if len < 1e-3 * smin || len > 2.0 * smin * (1.0 + 1e-9) {
                continue;
            }
            let ang = v[1].atan2(v[0]);
            if !(-1e-9..=lim).contains(&ang) {
                continue;
            }
            let ang = ang.max(0.0);
            match out.iter_mut().find(|(a, _)| (a - ang).abs() < 1e-9) {
                Some(e) => e.1 = e.1.min(len),
                None => out.push((ang, len)),
            }
        }
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out
}

/// A slider lattice vector along a substrate row direction with a small period ratio p/q.
fn commensurate_of(l: &Lattice, substrate: &Lattice, max_pq: u32) -> Option<Commensurate> {
    for (u, d) in row_directions(substrate) {
        let e = [u.cos(), u.sin()];
        for i in -4i32..=4 {
            for j in -4i32..=4 {
                let v = l.point(i as f64, j as f64);
                let len = v[0].hypot(v[1]);
                if len == 0.0
                    || (v[0] * e[1] - v[1] * e[0]).abs() > 1e-9 * len
                    || v[0] * e[0] + v[1] * e[1] < 0.0
                {
                    continue;
                }
                for q in 1..=max_pq {
                    for p in 1..=max_pq {
                        if gcd(p, q) == 1 && (len / d - p as f64 / q as f64).abs() < 1e-9 {
                            return Some(Commensurate {
                                direction_deg: tidy(u.to_degrees()),
                                p,
                                q,
                            });
                        }
                    }
                }
            }
        }
    }
    None
}

/// A lattice, its basis, its kind and its commensurate direction, before the checks.
type Raw = (Lattice, Vec<[f64; 2]>, String, Option<Commensurate>);

/// Fractional parts of badly approximable ratios (golden ratio, √2, √5 − 1) of the across
/// spacing to the substrate row spacing.
const NOBLE: [f64; 3] = [
    0.618_033_988_749_895,
    0.414_213_562_373_095,
    0.236_067_977_499_79,
];

/// The candidates of `p.family` over `scene`'s substrate, with spheres of the scene's slider
/// diameter not overlapping, in a deterministic order. Errors (naming `--family`) when none is
/// valid. Cost O(candidates × classification).
pub fn candidates(scene: &Scene, p: &PatternParams) -> Result<Vec<Candidate>> {
    if scene.geometry.substrate_sites.is_some() {
        bail!(
            "{}: the substrate comes from a site file; candidates are classified against a substrate lattice",
            Input::Family
        );
    }
    let d = 2.0 * scene.slider_sphere_radius();
    let raw = family_lattices(&p.family, &scene.substrate.lattice, d, p.max_pq);
    let total = raw.len();
    let out: Vec<Candidate> = raw
        .into_iter()
        .filter_map(|r| candidate(scene, p, d, r))
        .collect();
    if out.is_empty() {
        bail!(
            "{} `{}`: none of its {total} lattices is valid over this substrate: the spheres (diameter {} µm) overlap{}",
            Input::Family,
            p.family_text,
            tidy(m_to_um(d)),
            if p.family == Family::Directional {
                format!(
                    ", or no directionally commensurate lattice has contact lines along its row (raise {})",
                    Input::MaxPq
                )
            } else {
                " (use spacings of at least the sphere diameter)".to_string()
            }
        );
    }
    Ok(out)
}

/// Every lattice of `family` over the substrate lattice `sub`, before any check; `d` (m) the
/// slider's sphere diameter, `max_pq` the largest p and q of the commensurate ratios.
fn family_lattices(family: &Family, sub: &Lattice, d: f64, max_pq: u32) -> Vec<Raw> {
    let mut raw: Vec<Raw> = Vec::new();
    match family {
        Family::Directional => raw = directional_lattices(sub, d, max_pq),
        Family::Rectangular { a, b } => {
            for &x in a {
                for &y in b {
                    raw.push((Lattice::rectangular(x, y), Vec::new(), String::new(), None));
                }
            }
        }
        Family::Oblique { a, b, gamma } => {
            for &x in a {
                for &y in b {
                    for &g in gamma {
                        let l = Lattice::oblique([x, 0.0], [y * g.cos(), y * g.sin()]);
                        raw.push((l, Vec::new(), String::new(), None));
                    }
                }
            }
        }
        Family::Presets { s } => {
            for &x in s {
                let hc = vec![[0.0, 0.0], [0.5 * x, 0.5 * x / 3f64.sqrt()]];
                let kg = vec![
                    [0.0, 0.0],
                    [0.5 * x, 0.0],
                    [0.25 * x, 0.25 * 3f64.sqrt() * x],
                ];
                raw.push((
                    Lattice::triangular(x),
                    Vec::new(),
                    "triangular".into(),
                    None,
                ));
                raw.push((Lattice::square(x), Vec::new(), "square".into(), None));
                raw.push((Lattice::triangular(x), hc, "honeycomb".into(), None));
                raw.push((Lattice::triangular(x), kg, "kagome".into(), None));
            }
        }
    }
    raw
}

/// The directionally commensurate rectangular lattices over `sub` (see the module docs).
fn directional_lattices(sub: &Lattice, d: f64, max_pq: u32) -> Vec<Raw> {
    let mut raw: Vec<Raw> = Vec::new();
    for (u, du) in row_directions(sub) {
        let h = sub.cell_area().abs() / du;
        let (e, n) = ([u.cos(), u.sin()], [-u.sin(), u.cos()]);
        for q in 1..=max_pq {
            for pp in 1..=max_pq {
                if gcd(pp, q) != 1 {
                    continue;
                }
                let a = du * pp as f64 / q as f64;
                for f in NOBLE {
                    // b = (m + f)·h, m the smallest integer with b ≥ max(diameter, a):
                    // rows across are farther apart than along (the slider's first
                    // reciprocal shell lies across u) and the spheres do not overlap
                    let m = ((d.max(a) / h) - f).ceil().max(1.0);
                    let b = (m + f) * h;
                    let l = Lattice::oblique([a * e[0], a * e[1]], [b * n[0], b * n[1]]);
                    raw.push((
                        l,
                        Vec::new(),
                        "rectangular".into(),
                        Some(Commensurate {
                            direction_deg: tidy(u.to_degrees()),
                            p: pp,
                            q,
                        }),
                    ));
                }
            }
        }
    }
    raw
}

/// The lattice `raw` as a classified candidate over `scene`'s substrate, `None` when its
/// spheres (diameter `d`, m) overlap, it is invalid, or (directional family) its contact lines
/// do not run along its commensurate row.
fn candidate(scene: &Scene, p: &PatternParams, d: f64, raw: Raw) -> Option<Candidate> {
    let (l, basis, kind, comm) = raw;
    let sub = &scene.substrate.lattice;
    let sub_basis = &scene.geometry.substrate_basis;
    if l.validate("family").is_err() || overlaps(min_site_distance(&l, &basis), d) {
        return None;
    }
    let contact = classify(&l, &basis, scene.slider.theta, sub, sub_basis, p.max_order);
    let kind = if kind.is_empty() {
        lattice_name(&l)
    } else {
        kind
    };
    let comm = comm.or_else(|| commensurate_of(&l, sub, p.max_pq));
    if p.family == Family::Directional {
        // keep the directional contacts whose moiré lines run along u
        let u = comm.as_ref().map_or(0.0, |c| c.direction_deg);
        let ok_type = matches!(contact, ContactType::Directional { lubric_deg }
            if ((lubric_deg - u).rem_euclid(180.0) - 90.0).abs() < 1e-6);
        if !ok_type || !lines_along(scene, &l, u) {
            return None;
        }
    }
    Some(Candidate {
        lattice: l,
        basis,
        kind,
        commensurate: comm,
        contact,
    })
}

/// Whether the moiré contact lines of the slider lattice `l` on `scene`'s substrate run along
/// `u_deg` (within 1e-6°).
fn lines_along(scene: &Scene, l: &Lattice, u_deg: f64) -> bool {
    let mut s = scene.clone();
    s.slider.lattice = *l;
    let cl = contact_line_direction(&s, s.slider.theta, &MapParams::default());
    !cl.degenerate
        && ((cl.angle.to_degrees() - u_deg).rem_euclid(180.0) + 1e-6).rem_euclid(180.0) < 2e-6
}

/// The contact-line spacing (m) of the slider lattice `l` on `scene`'s substrate (moiré of the
/// first shells, as `corrugation`); infinite when commensurate.
pub fn line_spacing(scene: &Scene, l: &Lattice) -> f64 {
    let mut s = scene.clone();
    s.slider.lattice = *l;
    contact_line_direction(&s, s.slider.theta, &MapParams::default()).spacing
}

#[cfg(test)]
mod tests;
