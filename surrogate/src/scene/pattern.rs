//! Pattern geometry beyond a Bravais lattice cut to a disc: lattices with a basis, slider
//! outlines (disc, rectangle, polygon), site lists read from files ([`SiteList`], in
//! `sites.rs`), and a slider sphere size other than the substrate's. [`Geometry`] holds what a [`super::Scene`] adds to its lattices;
//! its default is the plain disc-of-a-Bravais-lattice of the presets.

use super::sites::SiteList;
use super::touch::{overlaps, snap_um};
use super::Lattice;
use crate::error::SceneError;
use crate::units::{m_to_um, nm_text, um_pair_text, um_text, um_to_m};
use serde::{Deserialize, Serialize};

/// The slider's outline in its own frame (m), centred on the slider centre (which sits on the
/// first basis site). Rotates with the slider.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Outline {
    /// A disc of radius `SliderSpec::radius` (the presets).
    #[default]
    Disc,
    /// An axis-aligned rectangle `[w, h]` (m).
    Rectangle {
        /// Side lengths (m).
        size: [f64; 2],
    },
    /// A regular polygon with `sides` vertices on a circle of `radius` (m), the first on +x.
    RegularPolygon {
        /// Number of vertices (≥ 3).
        sides: u32,
        /// Circumradius (m).
        radius: f64,
    },
    /// A simple polygon given by its vertices (m), in order.
    Polygon {
        /// Vertices (m).
        vertices: Vec<[f64; 2]>,
    },
}

impl Outline {
    /// The polygon's vertices (m); `None` for a disc.
    pub fn vertices(&self) -> Option<Vec<[f64; 2]>> {
        match self {
            Outline::Disc => None,
            Outline::Rectangle { size } => {
                let (w, h) = (0.5 * size[0], 0.5 * size[1]);
                Some(vec![[-w, -h], [w, -h], [w, h], [-w, h]])
            }
            Outline::RegularPolygon { sides, radius } => Some(
                (0..*sides)
                    .map(|k| {
                        let a = std::f64::consts::TAU * k as f64 / *sides as f64;
                        [radius * a.cos(), radius * a.sin()]
                    })
                    .collect(),
            ),
            Outline::Polygon { vertices } => Some(vertices.clone()),
        }
    }

    /// Largest distance (m) of the outline from the slider centre (`disc_r` for a disc).
    pub fn circumradius(&self, disc_r: f64) -> f64 {
        match self.vertices() {
            None => disc_r,
            Some(v) => v.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max),
        }
    }

    /// Area (m²) enclosed by the outline (shoelace formula for polygons).
    pub fn area(&self, disc_r: f64) -> f64 {
        match self.vertices() {
            None => std::f64::consts::PI * disc_r * disc_r,
            Some(v) => polygon_area(&v).abs(),
        }
    }

    /// Whether the point `p` (m, slider frame) lies inside or on the outline (within a relative
    /// 1e-9 of its size). O(vertices).
    pub fn contains(&self, p: [f64; 2], disc_r: f64) -> bool {
        match self {
            Outline::Disc => p[0] * p[0] + p[1] * p[1] <= disc_r * disc_r * (1.0 + 1e-9),
            Outline::Rectangle { size } => {
                p[0].abs() <= 0.5 * size[0] * (1.0 + 1e-12)
                    && p[1].abs() <= 0.5 * size[1] * (1.0 + 1e-12)
            }
            _ => {
                let v = self.vertices().unwrap_or_default();
                let tol = 1e-9 * self.circumradius(disc_r);
                point_in_polygon(&v, p) || edge_distance(&v, p) <= tol
            }
        }
    }

    /// Short description in µm for tables and logs: `disc r=100`, `rectangle 120x80`,
    /// `polygon 6 r=90`, `polygon 5 vertices`.
    pub fn describe(&self, disc_r: f64) -> String {
        match self {
            Outline::Disc => format!("disc r={}", um_text(disc_r)),
            Outline::Rectangle { size } => {
                format!("rectangle {}x{}", um_text(size[0]), um_text(size[1]))
            }
            Outline::RegularPolygon { sides, radius } => {
                format!("polygon {sides} r={}", um_text(*radius))
            }
            Outline::Polygon { vertices } => format!("polygon {} vertices", vertices.len()),
        }
    }

    /// The outline's fields as written in the scene file's `outline = { … }` table, in µm, for
    /// messages: `kind = "rectangle", size_um = [120, 80]` (at most 8 vertices listed).
    pub fn toml_text(&self) -> String {
        match self {
            Outline::Disc => r#"kind = "disc""#.to_string(),
            Outline::Rectangle { size } => {
                format!(r#"kind = "rectangle", size_um = {}"#, um_pair_text(*size))
            }
            Outline::RegularPolygon { sides, radius } => format!(
                r#"kind = "polygon", sides = {sides}, radius_um = {}"#,
                um_text(*radius)
            ),
            Outline::Polygon { vertices } => {
                let mut v: Vec<String> =
                    vertices.iter().take(8).map(|p| um_pair_text(*p)).collect();
                if vertices.len() > 8 {
                    v.push(format!("… {} more", vertices.len() - 8));
                }
                format!(r#"kind = "polygon", vertices_um = [{}]"#, v.join(", "))
            }
        }
    }

    /// Checks the outline is finite with a positive area; `field` names it in errors, which
    /// print the outline as its scene-file table in µm ([`Outline::toml_text`]).
    pub fn validate(&self, field: &str) -> Result<(), SceneError> {
        let bad = |why: &str| SceneError::invalid(field, self.toml_text(), why);
        match self {
            Outline::Disc => Ok(()),
            Outline::Rectangle { size } => {
                if size.iter().all(|v| v.is_finite() && *v > 0.0) {
                    Ok(())
                } else {
                    Err(bad("size_um: both sides must be positive numbers"))
                }
            }
            Outline::RegularPolygon { sides, radius } => {
                if *sides < 3 {
                    Err(bad("sides must be at least 3"))
                } else if !(radius.is_finite() && *radius > 0.0) {
                    Err(bad("radius_um must be a positive number"))
                } else {
                    Ok(())
                }
            }
            Outline::Polygon { vertices } => {
                if vertices.len() < 3 {
                    Err(bad("vertices_um needs at least 3 vertices"))
                } else if vertices.iter().flatten().any(|v| !v.is_finite()) {
                    Err(bad("vertices_um must be finite"))
                } else if polygon_area(vertices).abs() <= 0.0 {
                    Err(bad("vertices_um enclose no area"))
                } else if let Some((i, j)) = self_intersection(vertices) {
                    let n = vertices.len();
                    Err(bad(&format!(
                        "vertices_um: the outline crosses itself (edge {}–{} meets edge {}–{}; vertices counted from 1); give the vertices in order around a simple polygon",
                        i + 1,
                        (i + 1) % n + 1,
                        j + 1,
                        (j + 1) % n + 1
                    )))
                } else {
                    Ok(())
                }
            }
        }
    }
}

/// Signed area (m²) of a polygon (shoelace).
fn polygon_area(v: &[[f64; 2]]) -> f64 {
    let n = v.len();
    (0..n)
        .map(|i| {
            let (a, b) = (v[i], v[(i + 1) % n]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum::<f64>()
        * 0.5
}

/// The first pair of edges (i, j), i < j, of the closed polygon `v` that touch or cross
/// although they are not neighbours (edge k joins vertices k and k + 1), or whose neighbours
/// fold back onto each other (overlap along a line); `None` for a simple polygon. Exact
/// orientation tests on the coordinates. O(n²) in the vertices.
fn self_intersection(v: &[[f64; 2]]) -> Option<(usize, usize)> {
    let n = v.len();
    let orient = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        let x = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if x > 0.0 {
            1
        } else if x < 0.0 {
            -1
        } else {
            0
        }
    };
    // c on the segment ab, given that a, b, c are collinear
    let on = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        c[0] >= a[0].min(b[0])
            && c[0] <= a[0].max(b[0])
            && c[1] >= a[1].min(b[1])
            && c[1] <= a[1].max(b[1])
    };
    let meet = |p1: [f64; 2], p2: [f64; 2], q1: [f64; 2], q2: [f64; 2]| {
        let (d1, d2) = (orient(q1, q2, p1), orient(q1, q2, p2));
        let (d3, d4) = (orient(p1, p2, q1), orient(p1, p2, q2));
        (d1 * d2 < 0 && d3 * d4 < 0)
            || (d1 == 0 && on(q1, q2, p1))
            || (d2 == 0 && on(q1, q2, p2))
            || (d3 == 0 && on(p1, p2, q1))
            || (d4 == 0 && on(p1, p2, q2))
    };
    for i in 0..n {
        let (a, b) = (v[i], v[(i + 1) % n]);
        for j in i + 1..n {
            let (c, d) = (v[j], v[(j + 1) % n]);
            if j == i + 1 || (i == 0 && j == n - 1) {
                // neighbours share a vertex: they fail only by folding back along each other
                let (shared, p, q) = if j == i + 1 { (b, a, d) } else { (a, b, c) };
                if orient(shared, p, q) == 0
                    && (p[0] - shared[0]) * (q[0] - shared[0])
                        + (p[1] - shared[1]) * (q[1] - shared[1])
                        > 0.0
                {
                    return Some((i, j));
                }
                continue;
            }
            if meet(a, b, c, d) {
                return Some((i, j));
            }
        }
    }
    None
}

/// Even–odd crossing test.
fn point_in_polygon(v: &[[f64; 2]], p: [f64; 2]) -> bool {
    let n = v.len();
    let mut inside = false;
    let mut j = n - 1;
    for i in 0..n {
        let (a, b) = (v[i], v[j]);
        if (a[1] > p[1]) != (b[1] > p[1])
            && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]
        {
            inside = !inside;
        }
        j = i;
    }
    inside
}

/// Smallest distance (m) from `p` to the polygon's edges.
fn edge_distance(v: &[[f64; 2]], p: [f64; 2]) -> f64 {
    let n = v.len();
    (0..n)
        .map(|i| {
            let (a, b) = (v[i], v[(i + 1) % n]);
            let d = [b[0] - a[0], b[1] - a[1]];
            let l2 = d[0] * d[0] + d[1] * d[1];
            let t = if l2 > 0.0 {
                (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (p[0] - a[0] - t * d[0]).hypot(p[1] - a[1] - t * d[1])
        })
        .fold(f64::INFINITY, f64::min)
}

/// What a scene adds to its two Bravais lattices. The default (empty bases, a disc outline, no
/// site files, one sphere size) is the presets' geometry.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Geometry {
    /// Slider basis (m): sites `T + b − b₀` for lattice vectors T (b₀ the first basis site, so
    /// it sits at the slider centre). Empty: one site per cell.
    #[serde(default)]
    pub slider_basis: Vec<[f64; 2]>,
    /// Substrate basis (m), as the slider's (b₀ at the substrate centre).
    #[serde(default)]
    pub substrate_basis: Vec<[f64; 2]>,
    /// Slider outline.
    #[serde(default)]
    pub outline: Outline,
    /// Slider sites from a file (replace the slider lattice, basis and outline).
    #[serde(default)]
    pub slider_sites: Option<SiteList>,
    /// Substrate sites from a file (replace the substrate lattice, basis and rectangle cut).
    #[serde(default)]
    pub substrate_sites: Option<SiteList>,
    /// Slider sphere radius (m) when it differs from the substrate's `Scene::sphere_radius`.
    #[serde(default)]
    pub slider_sphere_radius: Option<f64>,
}

impl Geometry {
    /// Whether this is the presets' geometry (nothing added).
    pub fn is_plain(&self) -> bool {
        *self == Geometry::default()
    }

    /// Whether the slider is a plain Bravais lattice (no basis, no site file).
    pub fn slider_is_bravais(&self) -> bool {
        self.slider_basis.len() <= 1 && self.slider_sites.is_none()
    }

    /// Whether the substrate is a plain Bravais lattice (no basis, no site file).
    pub fn substrate_is_bravais(&self) -> bool {
        self.substrate_basis.len() <= 1 && self.substrate_sites.is_none()
    }
}

/// A site coordinate (m) of a lattice with a basis, placed on the 1e-9 µm grid so that a site
/// file with the coordinates written to 9 or more decimals (µm) gives exactly the same sites
/// (site files are read onto the same grid).
fn snap_m(v: f64) -> f64 {
    um_to_m(snap_um(m_to_um(v)))
}

/// Lattice-with-basis sites inside `outline` (disc radius `disc_r`), deterministic order
/// (rows of lattice cells, basis order inside a cell). With no basis and a disc it is exactly
/// [`Lattice::sites_in_disc`]. O(cells in the bounding disc × basis).
pub fn sites_in_outline(
    l: &Lattice,
    basis: &[[f64; 2]],
    outline: &Outline,
    disc_r: f64,
) -> Vec<[f64; 2]> {
    if basis.len() <= 1 && *outline == Outline::Disc {
        return l.sites_in_disc(disc_r);
    }
    let b = rebased(basis);
    let reach =
        outline.circumradius(disc_r) + b.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max);
    let (imax, jmax) = l.index_bounds(reach, reach);
    let mut out = Vec::new();
    for j in -jmax..=jmax {
        for i in -imax..=imax {
            let t = l.point(i as f64, j as f64);
            for q in &b {
                let mut p = [t[0] + q[0], t[1] + q[1]];
                if b.len() > 1 {
                    p = [snap_m(p[0]), snap_m(p[1])];
                }
                if outline.contains(p, disc_r) {
                    out.push(p);
                }
            }
        }
    }
    out
}

/// Lattice-with-basis sites in the rectangle `|x| ≤ lx/2, |y| ≤ ly/2` (m), deterministic order.
/// With no basis it is exactly [`Lattice::sites_in_rect`].
pub fn sites_in_rect(l: &Lattice, basis: &[[f64; 2]], lx: f64, ly: f64) -> Vec<[f64; 2]> {
    if basis.len() <= 1 {
        return l.sites_in_rect(lx, ly);
    }
    let b = rebased(basis);
    let hx = 0.5 * lx * (1.0 + 1e-12);
    let hy = 0.5 * ly * (1.0 + 1e-12);
    let reach = hx.hypot(hy) + b.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max);
    let (imax, jmax) = l.index_bounds(reach, reach);
    let mut out = Vec::new();
    for j in -jmax..=jmax {
        for i in -imax..=imax {
            let t = l.point(i as f64, j as f64);
            for q in &b {
                let p = [snap_m(t[0] + q[0]), snap_m(t[1] + q[1])];
                if p[0].abs() <= hx && p[1].abs() <= hy {
                    out.push(p);
                }
            }
        }
    }
    out
}

/// The basis shifted so that its first site is the origin (`[[0, 0]]` when empty).
pub fn rebased(basis: &[[f64; 2]]) -> Vec<[f64; 2]> {
    match basis.first() {
        None => vec![[0.0, 0.0]],
        Some(b0) => basis.iter().map(|b| [b[0] - b0[0], b[1] - b0[1]]).collect(),
    }
}

/// The closest pair of distinct sites of the lattice with `basis`: site `a` of the basis (index
/// into `basis`, from 0) in the cell at the origin, site `b` in the cell `(i, j)` (lattice
/// translation i·a1 + j·a2), and their distance (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosestSites {
    /// Basis index of the first site (cell 0).
    pub a: usize,
    /// Basis index of the second site.
    pub b: usize,
    /// The second site's cell (i, j).
    pub cell: (i32, i32),
    /// Centre distance (m).
    pub distance: f64,
}

/// The closest pair of distinct sites of the lattice with `basis` (the nearest-neighbour
/// spacing of the pattern). O(basis² × 49).
pub fn closest_sites(l: &Lattice, basis: &[[f64; 2]]) -> ClosestSites {
    let b = rebased(basis);
    let mut best = ClosestSites {
        a: 0,
        b: 0,
        cell: (0, 0),
        distance: f64::INFINITY,
    };
    for (k, p) in b.iter().enumerate() {
        for (m, q) in b.iter().enumerate() {
            for i in -3i32..=3 {
                for j in -3i32..=3 {
                    if k == m && i == 0 && j == 0 {
                        continue;
                    }
                    let t = l.point(i as f64, j as f64);
                    let d = (q[0] + t[0] - p[0]).hypot(q[1] + t[1] - p[1]);
                    if d < best.distance {
                        best = ClosestSites {
                            a: k,
                            b: m,
                            cell: (i, j),
                            distance: d,
                        };
                    }
                }
            }
        }
    }
    best
}

/// Smallest distance (m) between two distinct sites of the lattice with `basis` (the nearest-
/// neighbour spacing of the pattern). O(basis² × 49).
pub fn min_site_distance(l: &Lattice, basis: &[[f64; 2]]) -> f64 {
    closest_sites(l, basis).distance
}

/// `i·a1 + j·a2` as text for messages (`a1`, `a2 − a1`, … ; empty for the origin cell).
fn cell_text(cell: (i32, i32)) -> String {
    let term = |n: i32, v: &str| match n {
        0 => String::new(),
        1 => v.to_string(),
        -1 => format!("−{v}"),
        n if n < 0 => format!("−{}·{v}", -n),
        n => format!("{n}·{v}"),
    };
    match (term(cell.0, "a1"), term(cell.1, "a2")) {
        (a, b) if a.is_empty() && b.is_empty() => String::new(),
        (a, b) if b.is_empty() => format!(" + {a}"),
        (a, b) if a.is_empty() => format!(" + {b}"),
        (a, b) => format!(
            " + {a} {} {}",
            if cell.1 < 0 { "−" } else { "+" },
            b.trim_start_matches('−')
        ),
    }
}

/// Checks a lattice with a basis: finite basis sites, none repeated, and spheres of diameter
/// `d` (m) on them do not overlap beyond [`super::touch::TOUCH_TOL`]. `field` names the basis
/// (`slider.lattice.basis_um`); a refusal prints the basis as typed (µm), names the two sites
/// (`basis_um[k]`, counted from 1, and the lattice translation) and the overlap in nm.
pub fn check_basis(l: &Lattice, basis: &[[f64; 2]], d: f64, field: &str) -> Result<(), SceneError> {
    let typed = || {
        let v: Vec<String> = basis.iter().map(|b| um_pair_text(*b)).collect();
        format!("[{}]", v.join(", "))
    };
    if basis.iter().flatten().any(|v| !v.is_finite()) {
        return Err(SceneError::invalid(
            field,
            typed(),
            "basis sites must be finite",
        ));
    }
    let c = closest_sites(l, basis);
    if overlaps(c.distance, d) {
        let site = |k: usize| format!("basis_um[{}] = {}", k + 1, um_pair_text(basis[k]));
        let why = if c.a == c.b {
            format!(
                "{} and its copy{} are {} µm apart",
                site(c.a),
                cell_text(c.cell),
                um_text(c.distance)
            )
        } else {
            format!(
                "{} and {}{} are {} µm apart",
                site(c.a),
                site(c.b),
                cell_text(c.cell),
                um_text(c.distance)
            )
        };
        return Err(SceneError::invalid(
            field,
            typed(),
            &format!(
                "{why}: spheres of diameter {} µm overlap by {} nm (spheres touching within a relative 10⁻⁶ count as touching)",
                um_text(d),
                nm_text(d - c.distance)
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn polygon(v: &[[f64; 2]]) -> Outline {
        Outline::Polygon {
            vertices: v.iter().map(|p| p.map(um_to_m)).collect(),
        }
    }

    /// A self-intersecting polygon (a bow tie, a pentagram, a spike folding back on an edge) is
    /// refused naming the field and the edges; simple ones (convex, concave) are accepted.
    #[test]
    fn self_intersecting_polygons_are_refused() {
        let ok = [
            polygon(&[[0.0, 0.0], [100.0, 0.0], [50.0, 80.0]]),
            // an L-shaped (concave) pad
            polygon(&[
                [0.0, 0.0],
                [60.0, 0.0],
                [60.0, 20.0],
                [20.0, 20.0],
                [20.0, 60.0],
                [0.0, 60.0],
            ]),
        ];
        for o in &ok {
            assert!(o.validate("slider.outline").is_ok(), "{o:?}");
        }
        // a bow tie: edge 1–2 crosses edge 3–4 (its area is not zero: the halves differ)
        let bow = polygon(&[[0.0, 0.0], [100.0, 60.0], [100.0, 0.0], [0.0, 40.0]]);
        assert!(polygon_area(bow.vertices().unwrap().as_slice()).abs() > 0.0);
        let e = bow.validate("slider.outline").unwrap_err().to_string();
        assert!(
            e.contains("slider.outline") && e.contains("crosses itself") && e.contains("1–2"),
            "{e}"
        );
        // a pentagram (the vertices of a regular pentagon in star order)
        let star: Vec<[f64; 2]> = (0..5)
            .map(|k| {
                let a = std::f64::consts::TAU * (2 * k) as f64 / 5.0;
                [50.0 * a.cos(), 50.0 * a.sin()]
            })
            .collect();
        assert!(polygon(&star).validate("slider.outline").is_err());
        // a vertex touching a non-adjacent edge, and an edge folding back onto its neighbour
        let touch = polygon(&[
            [0.0, 0.0],
            [100.0, 0.0],
            [100.0, 50.0],
            [50.0, 0.0],
            [0.0, 50.0],
        ]);
        assert!(touch.validate("slider.outline").is_err());
        let fold = polygon(&[[0.0, 0.0], [100.0, 0.0], [50.0, 0.0], [50.0, 50.0]]);
        assert!(fold.validate("slider.outline").is_err());
    }
}
