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

use anyhow::{bail, Result};
use std::f64::consts::PI;
use surrogate::map::{contact_line_direction, MapParams};
use surrogate::scene::{lattice_name, min_site_distance, rebased};
use surrogate::units::{deg_to_rad, um_to_m};
use surrogate::{Lattice, Scene};

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

/// How a candidate meets the substrate (Panizon et al. 2023).
#[derive(Debug, Clone, PartialEq)]
pub enum ContactType {
    /// No coincident reciprocal vector: lubric in every direction.
    Lubric,
    /// Coincident reciprocal vectors along one direction only: lubric perpendicular to it
    /// (`lubric_deg`, the free sliding direction, in [0°, 180°)).
    Directional { lubric_deg: f64 },
    /// Two non-parallel coincident reciprocal vectors: interlocked.
    Interlocked,
}

impl ContactType {
    /// `lubric`, `directional` or `interlocked`.
    pub fn name(&self) -> &'static str {
        match self {
            ContactType::Lubric => "lubric",
            ContactType::Directional { .. } => "directional",
            ContactType::Interlocked => "interlocked",
        }
    }
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

/// How the candidates of a family are made comparable (`--normalize`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Normalize {
    /// Every candidate keeps the base scene's slider outline: the same slider area.
    #[default]
    Area,
    /// Every candidate's outline is scaled so that it holds the base slider's sphere count
    /// (the closest count its lattice allows).
    Spheres,
}

impl Normalize {
    /// `area` or `spheres`.
    pub fn name(self) -> &'static str {
        match self {
            Normalize::Area => "area",
            Normalize::Spheres => "spheres",
        }
    }
}

/// Parses a family: `directional`, `presets[:s=3:6:0.5]`, `rectangular:a=3,b=2.6:6:0.05`,
/// `oblique:a=3,b=3.2,gamma_deg=60:90:5`; every value a number or `start:stop:step` (µm,
/// degrees). Errors name `--family`.
/// `values` parses one value or range (the command line's list/range parser).
pub fn parse_family(spec: &str, values: impl Fn(&str, &str) -> Result<Vec<f64>>) -> Result<Family> {
    let (kind, rest) = spec.split_once(':').unwrap_or((spec, ""));
    let mut vals: Vec<(String, Vec<f64>)> = Vec::new();
    for part in rest.split(',').filter(|s| !s.is_empty()) {
        let Some((k, v)) = part.split_once('=') else {
            bail!("`--family {spec}`: `{part}` is not `name=value` or `name=start:stop:step`");
        };
        let list = values(v, &format!("--family {spec}: {k}"))?;
        vals.push((k.trim().to_string(), list));
    }
    let take = |name: &str, default: Option<f64>, um: bool| -> Result<Vec<f64>> {
        let f = |x: f64| if um { um_to_m(x) } else { deg_to_rad(x) };
        match vals.iter().find(|(k, _)| k == name) {
            Some((_, v)) => Ok(v.iter().map(|&x| f(x)).collect()),
            None => match default {
                Some(d) => Ok(vec![f(d)]),
                None => bail!("`--family {spec}`: `{kind}` needs `{name}=…`"),
            },
        }
    };
    let known = |names: &[&str]| -> Result<()> {
        if let Some((k, _)) = vals.iter().find(|(k, _)| !names.contains(&k.as_str())) {
            bail!(
                "`--family {spec}`: unknown parameter `{k}` of `{kind}` (expected {})",
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
            "`--family`: unknown family `{other}` (expected directional, presets, rectangular:a=…,b=…, oblique:a=…,b=…,gamma_deg=…)"
        ),
    })
}

fn gcd(a: u32, b: u32) -> u32 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// Reciprocal vectors `m b1 + n b2` (1/m) of `l` with |G| ≤ `gmax`, the origin excluded.
fn reciprocal(l: &Lattice, gmax: f64) -> Vec<[f64; 2]> {
    let det = l.cell_area();
    let b1 = [2.0 * PI * l.a2[1] / det, -2.0 * PI * l.a2[0] / det];
    let b2 = [-2.0 * PI * l.a1[1] / det, 2.0 * PI * l.a1[0] / det];
    // |m| ≤ gmax·|a1|/2π bounds the coefficients
    let mmax = (gmax * l.a1[0].hypot(l.a1[1]) / (2.0 * PI)).ceil() as i64 + 1;
    let nmax = (gmax * l.a2[0].hypot(l.a2[1]) / (2.0 * PI)).ceil() as i64 + 1;
    let mut out = Vec::new();
    for m in -mmax..=mmax {
        for n in -nmax..=nmax {
            if m == 0 && n == 0 {
                continue;
            }
            let g = [
                m as f64 * b1[0] + n as f64 * b2[0],
                m as f64 * b1[1] + n as f64 * b2[1],
            ];
            if g[0].hypot(g[1]) <= gmax * (1.0 + 1e-9) {
                out.push(g);
            }
        }
    }
    out
}

/// Shortest reciprocal vector length (1/m) of `l`: 2π / (the largest row spacing).
fn g_min(l: &Lattice) -> f64 {
    let det = l.cell_area();
    let b1 = [2.0 * PI * l.a2[1] / det, -2.0 * PI * l.a2[0] / det];
    let b2 = [-2.0 * PI * l.a1[1] / det, 2.0 * PI * l.a1[0] / det];
    let mut best = f64::INFINITY;
    for m in -3i32..=3 {
        for n in -3i32..=3 {
            if m != 0 || n != 0 {
                let g = [
                    m as f64 * b1[0] + n as f64 * b2[0],
                    m as f64 * b1[1] + n as f64 * b2[1],
                ];
                best = best.min(g[0].hypot(g[1]));
            }
        }
    }
    best
}

/// Whether the basis' structure factor at G is non-zero (relative 1e-6).
fn structure_factor_nonzero(basis: &[[f64; 2]], g: [f64; 2]) -> bool {
    let (mut re, mut im) = (0.0, 0.0);
    for b in basis {
        let ph = g[0] * b[0] + g[1] * b[1];
        re += ph.cos();
        im += ph.sin();
    }
    re.hypot(im) > 1e-6 * basis.len() as f64
}

/// The contact type of a slider (lattice + basis, rotated by `theta` rad) on a substrate
/// (lattice + basis); see the module docs.
pub fn classify(
    slider: &Lattice,
    slider_basis: &[[f64; 2]],
    theta: f64,
    substrate: &Lattice,
    substrate_basis: &[[f64; 2]],
    max_order: f64,
) -> ContactType {
    let gmax = max_order * g_min(substrate);
    let (s, c) = theta.sin_cos();
    let (bs, bb) = (rebased(slider_basis), rebased(substrate_basis));
    let gb: Vec<[f64; 2]> = reciprocal(substrate, gmax)
        .into_iter()
        .filter(|g| structure_factor_nonzero(&bb, *g))
        .collect();
    let mut common: Vec<[f64; 2]> = Vec::new();
    for g in reciprocal(slider, gmax) {
        if !structure_factor_nonzero(&bs, g) {
            continue;
        }
        let gr = [c * g[0] - s * g[1], s * g[0] + c * g[1]];
        let l = gr[0].hypot(gr[1]);
        if gb
            .iter()
            .any(|h| (h[0] - gr[0]).hypot(h[1] - gr[1]) <= 1e-6 * l)
        {
            common.push(gr);
        }
    }
    let Some(n) = common.first().copied() else {
        return ContactType::Lubric;
    };
    let ln = n[0].hypot(n[1]);
    if common
        .iter()
        .all(|g| (n[0] * g[1] - n[1] * g[0]).abs() <= 1e-6 * ln * g[0].hypot(g[1]))
    {
        let lubric = (n[1].atan2(n[0]) + 0.5 * PI).to_degrees().rem_euclid(180.0);
        ContactType::Directional {
            lubric_deg: tidy(if (lubric - 180.0).abs() < 1e-9 {
                0.0
            } else {
                lubric
            }),
        }
    } else {
        ContactType::Interlocked
    }
}

/// A degree or µm value without binary noise.
pub fn tidy(v: f64) -> f64 {
    (v * 1e9).round() / 1e9 + 0.0
}

/// Rotation order of a Bravais lattice (6, 4 or 2).
fn rotation_order(l: &Lattice) -> u32 {
    [6u32, 4, 3]
        .into_iter()
        .find(|&n| {
            let (s, c) = (2.0 * PI / n as f64).sin_cos();
            [l.a1, l.a2].iter().all(|v| {
                let w = [c * v[0] - s * v[1], s * v[0] + c * v[1]];
                let k = l.to_lattice_coords(w);
                k.iter().all(|x| (x - x.round()).abs() < 1e-6)
            })
        })
        .unwrap_or(2)
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
    let sub = &scene.substrate.lattice;
    let sub_basis = &scene.geometry.substrate_basis;
    if scene.geometry.substrate_sites.is_some() {
        bail!("`--family`: the substrate comes from a site file; candidates are classified against a substrate lattice");
    }
    let d = 2.0 * scene.slider_sphere_radius();
    let mut raw: Vec<Raw> = Vec::new();
    match &p.family {
        Family::Directional => {
            for (u, du) in row_directions(sub) {
                let h = sub.cell_area().abs() / du;
                let (e, n) = ([u.cos(), u.sin()], [-u.sin(), u.cos()]);
                for q in 1..=p.max_pq {
                    for pp in 1..=p.max_pq {
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
        }
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
    let total = raw.len();
    let mut out = Vec::new();
    for (l, basis, kind, comm) in raw {
        if l.validate("--family").is_err() || min_site_distance(&l, &basis) < d * (1.0 - 1e-9) {
            continue;
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
                continue;
            }
        }
        out.push(Candidate {
            lattice: l,
            basis,
            kind,
            commensurate: comm,
            contact,
        });
    }
    if out.is_empty() {
        bail!(
            "`--family {}`: none of its {total} lattices is valid over this substrate: the spheres (diameter {} µm) overlap{}",
            p.family_text,
            tidy(d * 1e6),
            if p.family == Family::Directional {
                ", or no directionally commensurate lattice has contact lines along its row (raise --max-pq)"
            } else {
                " (use spacings of at least the sphere diameter)"
            }
        );
    }
    Ok(out)
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
/// kept (`Normalize::Area`: the base's slider area) or scaled to hold the base's sphere count
/// (`Normalize::Spheres`, [`scale_to_count`]). Also its index row (`spheres` counted from the
/// built scene). Errors name the candidate.
pub fn candidate_scene(
    base: &Scene,
    c: &Candidate,
    id: &str,
    normalize: Normalize,
) -> Result<(surrogate::SceneFile, IndexRow)> {
    let um2 = |v: [f64; 2]| {
        [
            tidy(surrogate::units::m_to_um(v[0])),
            tidy(surrogate::units::m_to_um(v[1])),
        ]
    };
    let mut f = super::meta::scene_file(base);
    f.slider.sites = None;
    f.slider.lattice = Some(surrogate::scene::LatticeFile {
        kind: "oblique".into(),
        a1_um: Some(um2(c.lattice.a1)),
        a2_um: Some(um2(c.lattice.a2)),
        basis_um: (!c.basis.is_empty()).then(|| c.basis.iter().map(|b| um2(*b)).collect()),
        ..Default::default()
    });
    if normalize == Normalize::Spheres {
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
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct CandidateFacts {
    /// `lubric`, `directional` or `interlocked`.
    pub contact_type: String,
    /// Period ratio `p/q` along the commensurate direction (empty when none).
    pub p_q: String,
    /// Commensurate direction (degrees from the substrate x axis), when there is one.
    pub commensurate_direction_deg: Option<f64>,
    /// What the candidates share (`area` or `spheres`: `superlube patterns --normalize`), from
    /// the index's sidecar; empty when it does not say.
    #[serde(default)]
    pub normalize: String,
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
    let mut r = csv::Reader::from_path(index)
        .map_err(|e| anyhow::anyhow!("`--patterns`: cannot read {}: {e}", index.display()))?;
    // the fairness rule the candidates were made with (a hand-written index has no sidecar)
    let normalize = super::meta::Sidecar::of(index)
        .ok()
        .and_then(|s| s.params.get("normalize")?.as_str().map(str::to_string))
        .unwrap_or_default();
    let mut out = Vec::new();
    for (k, row) in r.deserialize::<Row>().enumerate() {
        let row = row.map_err(|e| {
            anyhow::anyhow!("`--patterns`: {} line {}: {e}", index.display(), k + 2)
        })?;
        out.push((
            row.pattern_id,
            CandidateFacts {
                contact_type: row.contact_type,
                p_q: row.p_q,
                commensurate_direction_deg: row.commensurate_direction_deg,
                normalize: normalize.clone(),
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
    let text = std::fs::read_to_string(index)
        .map_err(|e| anyhow::anyhow!("`--patterns`: cannot read {}: {e}", index.display()))?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let Some(col) = header.iter().position(|c| *c == "scene_file") else {
        bail!(
            "`--patterns`: {} line 1: no `scene_file` column (an index.csv of `superlube patterns`)",
            index.display()
        );
    };
    let dir = index.parent().unwrap_or(std::path::Path::new(""));
    let mut out = Vec::new();
    for (k, l) in lines.enumerate().filter(|(_, l)| !l.trim().is_empty()) {
        match l.split(',').nth(col).filter(|f| !f.is_empty()) {
            Some(f) => out.push(dir.join(f)),
            None => bail!(
                "`--patterns`: {} line {}: no scene_file",
                index.display(),
                k + 2
            ),
        }
    }
    if out.is_empty() {
        bail!("`--patterns`: {} lists no pattern", index.display());
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params(family: &str) -> PatternParams {
        PatternParams {
            family: parse_family(family, |v, _| {
                Ok(
                    match v
                        .split(':')
                        .map(|x| x.parse::<f64>().unwrap())
                        .collect::<Vec<_>>()[..]
                    {
                        [a] => vec![a],
                        [a, b, s] => (0..=((b - a) / s + 1e-9) as usize)
                            .map(|k| a + k as f64 * s)
                            .collect(),
                        _ => panic!(),
                    },
                )
            })
            .unwrap(),
            family_text: family.into(),
            max_pq: 3,
            max_order: 4.0,
        }
    }

    #[test]
    fn contact_types_of_known_pairs() {
        let s = 3e-6;
        let (sq, tri) = (Lattice::square(s), Lattice::triangular(s));
        assert_eq!(
            classify(&sq, &[], 0.0, &sq, &[], 4.0),
            ContactType::Interlocked
        );
        assert_eq!(
            classify(&tri, &[], 0.0, &tri, &[], 4.0),
            ContactType::Interlocked
        );
        // square on triangle at θ = 0: the rows along x coincide (every second substrate G
        // along x), nothing across: lubric across the rows (90°), as the study's contact lines
        assert_eq!(
            classify(&sq, &[], 0.0, &tri, &[], 4.0),
            ContactType::Directional { lubric_deg: 90.0 }
        );
        // twisted by an irrational-looking angle: lubric
        assert_eq!(
            classify(&tri, &[], 0.3, &tri, &[], 4.0),
            ContactType::Lubric
        );
    }

    #[test]
    fn directional_candidates_have_contact_lines_along_their_row() {
        let scene = Scene::preset("square-tri").unwrap();
        let cands = candidates(&scene, &params("directional")).unwrap();
        assert!(cands.len() >= 3, "{}", cands.len());
        for c in &cands {
            let m = c.commensurate.as_ref().unwrap();
            let mut s = scene.clone();
            s.slider.lattice = c.lattice;
            let cl = contact_line_direction(&s, 0.0, &MapParams::default());
            let diff = (cl.angle.to_degrees() - m.direction_deg).rem_euclid(180.0);
            assert!(!(1e-6..=180.0 - 1e-6).contains(&diff), "{c:?} {cl:?}");
            assert!(cl.spacing.is_finite() && cl.spacing > 0.0);
            // period along the row is p/q substrate row periods (3 µm at 0°, 3√3 µm at 30°)
            let d_u = if m.direction_deg == 0.0 {
                3e-6
            } else {
                3e-6 * 3f64.sqrt()
            };
            let a = c.lattice.a1[0].hypot(c.lattice.a1[1]);
            assert!((a / d_u - m.p as f64 / m.q as f64).abs() < 1e-9, "{c:?}");
            assert!(matches!(c.contact, ContactType::Directional { .. }));
        }
    }

    /// The pre-screen order: lubric, then directional, then interlocked, then unclassified;
    /// index order within a class.
    #[test]
    fn prescreen_order_puts_lubric_first_and_keeps_index_order_within_a_class() {
        let facts: Vec<(String, CandidateFacts)> = [
            ("p1", "interlocked"),
            ("p2", "directional"),
            ("p3", "lubric"),
            ("p4", "directional"),
            ("p5", ""),
            ("p6", "lubric"),
        ]
        .iter()
        .map(|(id, t)| {
            (
                id.to_string(),
                CandidateFacts {
                    contact_type: t.to_string(),
                    ..Default::default()
                },
            )
        })
        .collect();
        let files: Vec<std::path::PathBuf> = (1..=6)
            .map(|k| std::path::PathBuf::from(format!("c/p{k}.toml")))
            .collect();
        let got: Vec<String> = prescreen_order(files, &facts)
            .iter()
            .map(|f| f.file_stem().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(got, ["p3", "p6", "p2", "p4", "p1", "p5"]);
    }

    #[test]
    fn families_parse_and_bad_ones_are_named() {
        let scene = Scene::preset("square-tri").unwrap();
        let r = candidates(&scene, &params("rectangular:a=3,b=2.6:6:0.05")).unwrap();
        // b < 3 µm overlaps the 3 µm spheres: 2.6..2.95 left out
        assert_eq!(r.len(), 61);
        let p = candidates(&scene, &params("presets:s=3")).unwrap();
        assert_eq!(
            p.iter().map(|c| c.kind.as_str()).collect::<Vec<_>>(),
            ["triangular", "square"]
        );
        let e = candidates(&scene, &params("rectangular:a=1,b=2"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("--family") && e.contains("overlap"), "{e}");
        let e = parse_family("hexagonal", |_, _| Ok(vec![]))
            .unwrap_err()
            .to_string();
        assert!(e.contains("--family"), "{e}");
        let e = parse_family("rectangular:a=3", |_, _| Ok(vec![3.0]))
            .unwrap_err()
            .to_string();
        assert!(e.contains("b=…"), "{e}");
    }
}
