//! [`SiteList`]: sphere sites read from a site file (`slider.sites`, `substrate.sites`), with
//! per-site sphere diameters where the file's `diameter_um` column gives them.

use super::touch::{overlaps, snap_um};
use crate::error::SceneError;
use crate::units::{nm_text, um_pair_text, um_text, um_to_m};
use serde::{Deserialize, Serialize};

/// Sphere sites read from a site file (m): slider sites relative to the slider centre,
/// substrate sites relative to the substrate centre, in file order.
///
/// Per-site sizes: when the file's `diameter_um` column gives differing values (or leaves some
/// cells empty: an empty cell means the body's `sphere_diameter_um`), [`SiteList::radii`] holds
/// each sphere's radius r_i. Geometry convention: a slider sphere hangs from the slider plate
/// with its top on the plate, a substrate sphere sits with its bottom on the substrate plane,
/// so a larger sphere reaches further toward the other body. A sphere of radius r_i of a body
/// whose reference radius is R (its `sphere_diameter_um`/2) has its centre `R − r_i` above the
/// body's reference centre plane (slider) or `r_i − R` above it (substrate); with one size per
/// body every centre lies on that plane (the geometry without per-site sizes).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SiteList {
    /// The file the sites came from (as given, for records and messages).
    pub path: String,
    /// Sphere centres (m).
    pub sites: Vec<[f64; 2]>,
    /// The sphere diameter (m) the file's `diameter_um` column gives when every row gives the
    /// same one.
    pub diameter: Option<f64>,
    /// Radius (m) of each sphere, in site order, when the body's spheres differ in size (set by
    /// [`SiteList::resolve_sizes`]); `None`: every sphere has the body's radius.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radii: Option<Vec<f64>>,
    /// The `diameter_um` cell (m) of each row when they are not all equal and present (empty
    /// cells `None`); empty when the column is absent or uniform (not recorded).
    #[serde(skip)]
    pub cells: Vec<Option<f64>>,
    /// File line of each site (for messages; not recorded).
    #[serde(skip)]
    pub lines: Vec<usize>,
}

impl SiteList {
    /// Parses a site file: a header line naming the columns `x_um,y_um[,diameter_um]` (any
    /// order; `#` comments and blank lines skipped), then one sphere per line. Errors name the
    /// file, the line and the column (missing column, not a number, NaN/inf, non-positive
    /// diameter, overlapping spheres). `field` names the scene field (`slider.sites`).
    /// Coordinates are read onto the 1e-9 µm grid (`round(x·10⁹)/10⁹` µm), as the sites of a
    /// lattice with a basis: writing those sites to 9 or more decimals reproduces them exactly.
    /// Differing per-site diameters (or some empty cells) are kept in [`SiteList::cells`] for
    /// [`SiteList::resolve_sizes`]; the overlap check then waits for it. O(N log N).
    pub fn parse(text: &str, path: &str, field: &str) -> Result<SiteList, SceneError> {
        let err = |line: usize, why: String| {
            SceneError::invalid(field, format!("{path} line {line}"), &why)
        };
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        let (hl, header) = lines.next().ok_or_else(|| {
            err(
                1,
                "empty site file: needs a header `x_um,y_um[,diameter_um]` and one line per sphere"
                    .into(),
            )
        })?;
        let cols: Vec<&str> = header.split(',').map(str::trim).collect();
        let find = |name: &str| cols.iter().position(|c| *c == name);
        let (ix, iy) = match (find("x_um"), find("y_um")) {
            (Some(x), Some(y)) => (x, y),
            _ => {
                return Err(err(
                    hl,
                    format!(
                    "header `{header}` must name the columns x_um and y_um (optional diameter_um)"
                ),
                ))
            }
        };
        let id = find("diameter_um");
        if let Some(c) = cols
            .iter()
            .find(|c| !["x_um", "y_um", "diameter_um"].contains(c))
        {
            return Err(err(
                hl,
                format!("unknown column `{c}` (expected x_um, y_um, diameter_um)"),
            ));
        }
        let mut sites = Vec::new();
        let mut lines_of = Vec::new();
        let mut cells: Vec<Option<f64>> = Vec::new();
        for (ln, l) in lines {
            let f: Vec<&str> = l.split(',').map(str::trim).collect();
            let num = |i: usize, name: &str| -> Result<f64, SceneError> {
                let s = f
                    .get(i)
                    .filter(|s| !s.is_empty())
                    .ok_or_else(|| err(ln, format!("missing column {name}")))?;
                let v: f64 = s
                    .parse()
                    .map_err(|_| err(ln, format!("{name} = `{s}` is not a number")))?;
                if !v.is_finite() {
                    return Err(err(ln, format!("{name} = {s} is not a finite number")));
                }
                Ok(v)
            };
            let (x, y) = (num(ix, "x_um")?, num(iy, "y_um")?);
            if let Some(i) = id {
                // an empty cell: the body's sphere_diameter_um
                let d = match f.get(i).filter(|s| !s.is_empty()) {
                    Some(_) => Some(num(i, "diameter_um")?),
                    None => None,
                };
                if let Some(d) = d.filter(|d| *d <= 0.0) {
                    return Err(err(ln, format!("diameter_um = {d} must be positive")));
                }
                cells.push(d.map(um_to_m));
            }
            if f.len() > cols.len() {
                return Err(err(
                    ln,
                    format!("{} columns, the header names {}", f.len(), cols.len()),
                ));
            }
            sites.push([um_to_m(snap_um(x)), um_to_m(snap_um(y))]);
            lines_of.push(ln);
        }
        if sites.is_empty() {
            return Err(err(hl, "no sphere: the site file has only a header".into()));
        }
        let uniform = cells
            .first()
            .copied()
            .flatten()
            .filter(|d| cells.iter().all(|c| *c == Some(*d)));
        let list = SiteList {
            path: path.to_string(),
            sites,
            diameter: uniform,
            radii: None,
            cells: if uniform.is_some() { Vec::new() } else { cells },
            lines: lines_of,
        };
        if let Some(d) = list.diameter {
            list.check_overlap(d, field)?;
        }
        Ok(list)
    }

    /// Whether the file's `diameter_um` cells differ (or some are empty): the body's sizes then
    /// come from [`SiteList::resolve_sizes`].
    pub fn has_cells(&self) -> bool {
        self.cells.iter().any(Option::is_some)
    }

    /// Turns the per-row `diameter_um` cells into per-site radii with `body_radius` (m, the
    /// body's `sphere_diameter_um`/2) for empty cells, then checks that no two spheres overlap
    /// (each pair against its own r_i + r_j). When every resolved radius equals `body_radius`,
    /// `radii` stays `None` (one size: the geometry without per-site sizes). O(N log N).
    pub fn resolve_sizes(&mut self, body_radius: f64, field: &str) -> Result<(), SceneError> {
        if !self.has_cells() {
            return Ok(());
        }
        let radii: Vec<f64> = self
            .cells
            .iter()
            .map(|c| c.map_or(body_radius, |d| 0.5 * d))
            .collect();
        self.radii = radii.iter().any(|r| *r != body_radius).then_some(radii);
        match &self.radii {
            Some(_) => self.check_overlap_sized(field),
            None => self.check_overlap(2.0 * body_radius, field),
        }
    }

    /// Checks no two spheres of per-site radii `radii` overlap: centre distance < r_i + r_j
    /// (beyond the relative [`super::touch::TOUCH_TOL`], 1e-6); the error names both file lines and both diameters. Sweep over x with
    /// the largest diameter as the window (`first_overlap`): O(N log N + close
    /// pairs).
    pub fn check_overlap_sized(&self, field: &str) -> Result<(), SceneError> {
        let Some(radii) = &self.radii else {
            return Ok(());
        };
        let dmax = 2.0 * radii.iter().copied().fold(0.0, f64::max);
        match self.first_overlap(|i| radii[i], dmax) {
            None => Ok(()),
            Some((a, b, dist)) => Err(self.overlap_error(
                field,
                a,
                b,
                &format!(
                    "spheres at {} µm (diameter {} µm) and {} µm (diameter {} µm) overlap by {} nm: centre distance {} µm < radius sum {} µm",
                    um_pair_text(self.sites[a]),
                    um_text(2.0 * radii[a]),
                    um_pair_text(self.sites[b]),
                    um_text(2.0 * radii[b]),
                    nm_text(radii[a] + radii[b] - dist),
                    um_text(dist),
                    um_text(radii[a] + radii[b])
                ),
            )),
        }
    }

    /// The first overlapping pair (a < b, centre distance) of spheres of radius `radius(i)`
    /// (m): centre distance < r_a + r_b (beyond the relative 1e-6 of
    /// [`super::touch::TOUCH_TOL`]), by a sweep over x whose window
    /// `window` (m) is at least the largest radius sum. O(N log N + close pairs).
    fn first_overlap(
        &self,
        radius: impl Fn(usize) -> f64,
        window: f64,
    ) -> Option<(usize, usize, f64)> {
        let mut order: Vec<usize> = (0..self.sites.len()).collect();
        order.sort_by(|&a, &b| self.sites[a][0].total_cmp(&self.sites[b][0]));
        for (k, &i) in order.iter().enumerate() {
            let p = self.sites[i];
            for &j in &order[k + 1..] {
                let q = self.sites[j];
                if q[0] - p[0] >= window {
                    break;
                }
                let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
                let sum = radius(i) + radius(j);
                if overlaps(dx.hypot(dy), sum) {
                    return Some((i.min(j), i.max(j), dx.hypot(dy)));
                }
            }
        }
        None
    }

    /// The error of overlapping sites `a` and `b` (their file lines), `why` in words.
    fn overlap_error(&self, field: &str, a: usize, b: usize, why: &str) -> SceneError {
        let line = |i: usize| self.lines.get(i).copied().unwrap_or(i + 1);
        SceneError::invalid(
            field,
            format!("{} lines {} and {}", self.path, line(a), line(b)),
            why,
        )
    }

    /// Reads and parses a site file (see [`SiteList::parse`]); refuses files over 50 MB.
    pub fn read(path: &std::path::Path, field: &str) -> Result<SiteList, SceneError> {
        use std::io::Read;
        let shown = path.display().to_string();
        let io = |e: String| SceneError::invalid(field, &shown, &format!("cannot read: {e}"));
        let f = std::fs::File::open(path).map_err(|e| io(crate::io_error::plain(&e)))?;
        let mut bytes = Vec::new();
        f.take(50_000_001)
            .read_to_end(&mut bytes)
            .map_err(|e| io(crate::io_error::plain(&e)))?;
        if bytes.len() > 50_000_000 {
            return Err(io("larger than 50 MB: not a site file".into()));
        }
        let text = String::from_utf8(bytes).map_err(|_| io("not UTF-8 text".into()))?;
        Self::parse(&text, &shown, field)
    }

    /// Checks no two spheres of diameter `d` (m) overlap (centre distance < d beyond the relative
    /// [`super::touch::TOUCH_TOL`], 1e-6);
    /// the error names both file lines. Sweep over x (`first_overlap`):
    /// O(N log N + close pairs).
    pub fn check_overlap(&self, d: f64, field: &str) -> Result<(), SceneError> {
        match self.first_overlap(|_| 0.5 * d, d) {
            None => Ok(()),
            Some((a, b, dist)) => Err(self.overlap_error(
                field,
                a,
                b,
                &format!(
                    "spheres at {} and {} µm overlap by {} nm: centre distance {} µm < sphere diameter {} µm",
                    um_pair_text(self.sites[a]),
                    um_pair_text(self.sites[b]),
                    nm_text(d - dist),
                    um_text(dist),
                    um_text(d)
                ),
            )),
        }
    }
}
