//! The landscape workflow: the equilibrium height Δz(x, y) = z − min z of the slider translated
//! over one repeat cell of the substrate, on an N×N grid (both cell edges included).
//!
//! Two passes, memory flat in N:
//! 1. [`heights`]: solve grid points `k` (row-major, x fastest) in order, parallel over a bounded
//!    window, pushing one [`LandscapeZRow`] (shift and exact z) per point. The whole grid goes to
//!    a spill file (`OUT.z.partial`, renamed `OUT.z` when complete, next to the output; a
//!    temporary file for stdout); a shard (`--shard i/n`) streams its block of points to its own
//!    `--out` instead.
//! 2. [`finish`]: read the z rows of the whole grid back (one spill file, or the shards in order
//!    — `superlube merge` calls the same function), once for min z and the periodicity check,
//!    once to push the [`LandscapeRow`]s.
//!
//! Sharding and resuming work on pass 1's z rows: Δz needs the global min z, which no shard
//! knows, so shards write z and the merge computes Δz. z is written as its exact decimal in µm
//! ([`super::rows::exact_um`]), so the Δz rows of a merge are byte-identical to an unsharded
//! run's, and both are bit-identical to `surrogate::map::compute_landscape` (same poses, same
//! solver calls).

use super::rows::{LandscapeRow, LandscapeZRow};
use crate::runs::budget::Estimate;
use crate::runs::progress::Progress;
use crate::runs::sink::RowSink;
use crate::runs::sweep::{Sweep, LANDSCAPE_Z};
use anyhow::{bail, Context, Result};
use rayon::prelude::*;
use std::ops::Range;
use std::path::{Path, PathBuf};
use surrogate::map::{check_slider_stays_on_substrate, MapParams, RepeatCell};
use surrogate::solver::{Model, Pose, Solver};
use surrogate::{Scene, SceneError};

/// Parameters of a landscape (SI). θ is the scene's `slider.theta`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LandscapeParams {
    /// Normal load W (N).
    pub load: f64,
    /// Grid points per side N (≥ 2).
    pub grid: usize,
}

/// Summary of a finished landscape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LandscapeStats {
    /// The repeat cell mapped.
    pub cell: RepeatCell,
    /// Points per side.
    pub n: usize,
    /// min z (m).
    pub z_min: f64,
    /// max z − min z (m).
    pub range: f64,
    /// Largest |z| difference between opposite cell edges (m): 0 for an exactly periodic map.
    pub edge_mismatch: f64,
}

/// Cost estimate; `plot` adds the in-memory heat-map buffer.
pub fn estimate(scene: &Scene, p: &LandscapeParams, plot: bool) -> Estimate {
    let n2 = (p.grid as u64).saturating_mul(p.grid as u64);
    Estimate::solves(
        &format!("{} {}", crate::study::input::Input::Grid, p.grid),
        n2,
        scene.slider_sites_local().len(),
        scene.substrate_spheres().len(),
        if plot { 8.0 * n2 as f64 } else { 0.0 },
        8.0 + 45.0,
    )
}

/// The sweep of pass 1: N² grid points, one z row each.
pub fn sweep(p: &LandscapeParams) -> Sweep {
    Sweep {
        items: p.grid.saturating_mul(p.grid),
        rows_per_item: 1,
        unit: "grid points",
        schema: LANDSCAPE_Z,
    }
}

/// The spill file of an output `OUT`: `OUT.z` (streamed through `OUT.z.partial`).
pub fn spill_path(out: &Path) -> PathBuf {
    let mut s = out.as_os_str().to_owned();
    s.push(".z");
    PathBuf::from(s)
}

/// The repeat cell of `scene`'s substrate and the grid shift (m) of point `k` of an N×N grid.
fn grid(scene: &Scene, n: usize) -> (RepeatCell, impl Fn(usize) -> [f64; 2]) {
    let cell =
        RepeatCell::for_lattice(&scene.substrate.lattice, MapParams::default().max_cell_mult);
    let shift = move |k: usize| {
        let d = (n - 1) as f64;
        cell.point((k % n) as f64 / d, (k / n) as f64 / d)
    };
    (cell, shift)
}

/// Pass 1: the heights of grid points `items` (row-major, x fastest; a part of `0..N²`), one
/// [`LandscapeZRow`] each, pushed in order. Returns the repeat cell.
///
/// Errors (before any solve): `grid` < 2, a non-finite θ, the slider leaving the substrate
/// somewhere over the cell (field `offset_um`); then a failed solve or sink.
pub fn heights(
    scene: &Scene,
    p: &LandscapeParams,
    items: Range<usize>,
    rows: &mut dyn RowSink<LandscapeZRow>,
    progress: &dyn Progress,
) -> Result<RepeatCell> {
    let n = p.grid;
    let theta = scene.slider.theta;
    if let Some(l) = &scene.geometry.substrate_sites {
        bail!(
            "`substrate.sites`: the substrate from the site file `{}` has no lattice repeat cell, which a landscape maps; use a substrate lattice (with a basis if needed)",
            l.path
        );
    }
    if n < 2 {
        return Err(SceneError::invalid(
            "grid",
            n,
            "needs at least 2 points per side (both cell edges are included)",
        )
        .into());
    }
    if !theta.is_finite() {
        return Err(SceneError::invalid("theta_deg", theta.to_degrees(), "must be finite").into());
    }
    if items.end > n * n {
        bail!("grid points {items:?} outside the {n}×{n} grid");
    }
    let solver = Solver::new(scene)?;
    let (cell, shift) = grid(scene, n);
    check_slider_stays_on_substrate(scene, cell.bounding_box(), "offset_um")?;
    progress.stage("landscape", items.len() as u64, "grid points");
    let win = 64 * rayon::current_num_threads().max(1);
    let mut k0 = items.start;
    while k0 < items.end {
        let k1 = (k0 + win).min(items.end);
        let z: Result<Vec<f64>, SceneError> = (k0..k1)
            .into_par_iter()
            .map(|k| {
                let eq = solver.solve(
                    Pose {
                        theta,
                        shift: shift(k),
                    },
                    p.load,
                    Model::Auto,
                )?;
                progress.advance(1);
                Ok(eq.z)
            })
            .collect();
        for (k, z) in (k0..k1).zip(z?) {
            rows.push(&LandscapeZRow::new(shift(k), z))?;
        }
        k0 = k1;
    }
    progress.finish();
    Ok(cell)
}

/// What pass 2 finds in the heights of the whole grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeightStats {
    /// Points per side.
    pub n: usize,
    /// min z (m).
    pub z_min: f64,
    /// max z − min z (m).
    pub range: f64,
    /// Largest |z| difference between opposite cell edges (m).
    pub edge_mismatch: f64,
}

/// Reads the z rows of `files` in order (together the whole N×N grid, `n` = N).
fn read_heights(
    n: usize,
    files: &[PathBuf],
    f: &mut dyn FnMut(usize, &LandscapeZRow) -> Result<()>,
) -> Result<()> {
    let total = n * n;
    let mut k = 0;
    for path in files {
        let mut r = csv::Reader::from_path(path)
            .with_context(|| format!("reading the heights in {}", path.display()))?;
        for row in r.deserialize::<LandscapeZRow>() {
            let row = row.with_context(|| format!("reading the heights in {}", path.display()))?;
            if k >= total {
                bail!(
                    "{}: more height rows than the {n}×{n} grid has ({total})",
                    path.display()
                );
            }
            f(k, &row)?;
            k += 1;
        }
    }
    if k != total {
        bail!("{k} height rows for a {n}×{n} grid (expected {total})");
    }
    Ok(())
}

/// Pass 2: turns the z rows of the whole N×N grid (`n` = N), held by `files` in order, into the
/// [`LandscapeRow`]s (Δz = z − min z), pushed in order. Used by [`landscape`] on its spill file
/// and by `superlube merge` on a landscape's shards.
pub fn finish(
    n: usize,
    files: &[PathBuf],
    rows: &mut dyn RowSink<LandscapeRow>,
) -> Result<HeightStats> {
    let (mut zmin, mut zmax, mut mismatch) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64);
    let mut first_row = Vec::with_capacity(n);
    let mut row_start = 0.0;
    read_heights(n, files, &mut |k, r| {
        let z = r.z;
        zmin = zmin.min(z);
        zmax = zmax.max(z);
        let (i, j) = (k % n, k / n);
        if j == 0 {
            first_row.push(z);
        }
        if j == n - 1 {
            mismatch = mismatch.max((first_row[i] - z).abs());
        }
        if i == 0 {
            row_start = z;
        }
        if i == n - 1 {
            mismatch = mismatch.max((row_start - z).abs());
        }
        Ok(())
    })?;
    read_heights(n, files, &mut |_, r| rows.push(&r.dz_row(zmin)))?;
    Ok(HeightStats {
        n,
        z_min: zmin,
        range: zmax - zmin,
        edge_mismatch: mismatch,
    })
}

/// Computes the landscape of `scene` at its θ in one process, pushing N² [`LandscapeRow`]s
/// (row-major, x fastest) into `rows`: [`heights`] of the whole grid into the spill file `spill`
/// (`None`: a temporary file in the system's temp directory; removed at the end), then
/// [`finish`].
pub fn landscape(
    scene: &Scene,
    p: &LandscapeParams,
    spill: Option<&Path>,
    rows: &mut dyn RowSink<LandscapeRow>,
    progress: &dyn Progress,
) -> Result<LandscapeStats> {
    let spill_path = match spill {
        Some(p) => p.to_path_buf(),
        None => {
            static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
            let k = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            std::env::temp_dir().join(format!("superlube-landscape-{}-{k}.z", std::process::id()))
        }
    };
    let result = (|| {
        let file = std::fs::File::create(&spill_path)
            .with_context(|| format!("creating {}", spill_path.display()))?;
        let mut z = csv::Writer::from_writer(std::io::BufWriter::new(file));
        struct Spill<'a, W: std::io::Write>(&'a mut csv::Writer<W>);
        impl<W: std::io::Write> RowSink<LandscapeZRow> for Spill<'_, W> {
            fn push(&mut self, r: &LandscapeZRow) -> Result<()> {
                self.0.serialize(r)?;
                Ok(())
            }
        }
        let cell = heights(scene, p, 0..p.grid * p.grid, &mut Spill(&mut z), progress)?;
        z.flush()?;
        drop(z);
        let h = finish(p.grid, std::slice::from_ref(&spill_path), rows)?;
        Ok(stats(cell, &h))
    })();
    let _ = std::fs::remove_file(&spill_path);
    result
}

/// The summary of a landscape over `cell` with heights `h`.
pub fn stats(cell: RepeatCell, h: &HeightStats) -> LandscapeStats {
    LandscapeStats {
        cell,
        n: h.n,
        z_min: h.z_min,
        range: h.range,
        edge_mismatch: h.edge_mismatch,
    }
}

/// The repeat cell a landscape of `scene` maps.
pub fn cell(scene: &Scene) -> RepeatCell {
    grid(scene, 2).0
}
