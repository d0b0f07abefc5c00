//! The landscape workflow: the equilibrium height Δz(x, y) = z − min z of the slider translated
//! over one repeat cell of the substrate, on an N×N grid (both cell edges included).
//!
//! Two passes, memory flat in N: (1) solve the grid in row-major order (x fastest), parallel over
//! a bounded window of points, appending each height z as 8 bytes to a spill file (`OUT.z.partial`
//! next to the output, or a temporary file for stdout); (2) read the heights back, once for
//! min z and the periodicity check, once to push the [`LandscapeRow`]s. The rows are
//! bit-identical to `surrogate::map::compute_landscape` (same poses, same solver calls).

use super::budget::Estimate;
use super::progress::Progress;
use super::rows::LandscapeRow;
use super::sink::RowSink;
use anyhow::{Context, Result};
use rayon::prelude::*;
use std::io::{BufReader, BufWriter, Read, Seek, SeekFrom, Write};
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
        &format!("`--grid {}`", p.grid),
        n2,
        scene.slider_sites_local().len(),
        scene.substrate_spheres().len(),
        if plot { 8.0 * n2 as f64 } else { 0.0 },
        8.0 + 45.0,
    )
}

/// The spill file of an output `OUT`: `OUT.z.partial`.
pub fn spill_path(out: &Path) -> PathBuf {
    let mut s = out.as_os_str().to_owned();
    s.push(".z.partial");
    PathBuf::from(s)
}

/// Computes the landscape of `scene` at its θ, pushing N² [`LandscapeRow`]s (row-major, x
/// fastest) into `rows`. `spill` is where the heights are kept between the passes (`None`: a
/// temporary file in the system's temp directory); it is removed at the end.
///
/// Errors (before any solve): `grid` < 2, a non-finite θ, the slider leaving the substrate
/// somewhere over the cell (field `offset_um`); then a failed solve or sink.
pub fn landscape(
    scene: &Scene,
    p: &LandscapeParams,
    spill: Option<&Path>,
    rows: &mut dyn RowSink<LandscapeRow>,
    progress: &dyn Progress,
) -> Result<LandscapeStats> {
    let n = p.grid;
    let theta = scene.slider.theta;
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
    let solver = Solver::new(scene)?;
    let cell =
        RepeatCell::for_lattice(&scene.substrate.lattice, MapParams::default().max_cell_mult);
    check_slider_stays_on_substrate(scene, cell.bounding_box(), "offset_um")?;
    let shift = |k: usize| {
        let d = (n - 1) as f64;
        cell.point((k % n) as f64 / d, (k / n) as f64 / d)
    };
    let spill_path = match spill {
        Some(p) => p.to_path_buf(),
        None => std::env::temp_dir().join(format!(
            "superlube-landscape-{}.z.partial",
            std::process::id()
        )),
    };
    let result = (|| {
        let file = std::fs::File::options()
            .read(true)
            .write(true)
            .create(true)
            .truncate(true)
            .open(&spill_path)
            .with_context(|| format!("creating {}", spill_path.display()))?;
        // Pass 1: heights, streamed to the spill file in order.
        let total = n * n;
        progress.stage("landscape", total as u64, "grid points");
        let mut w = BufWriter::new(&file);
        let win = 64 * rayon::current_num_threads().max(1);
        let mut k0 = 0;
        while k0 < total {
            let k1 = (k0 + win).min(total);
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
            for z in z? {
                w.write_all(&z.to_le_bytes())?;
            }
            k0 = k1;
        }
        w.flush()?;
        drop(w);
        progress.finish();
        // Pass 2a: min, max and the edge mismatch (first row kept to compare with the last).
        let read = |f: &mut dyn FnMut(usize, f64) -> Result<()>| -> Result<()> {
            let mut r = BufReader::new(&file);
            r.seek(SeekFrom::Start(0))?;
            let mut b = [0u8; 8];
            for k in 0..total {
                r.read_exact(&mut b)?;
                f(k, f64::from_le_bytes(b))?;
            }
            Ok(())
        };
        let (mut zmin, mut zmax, mut mismatch) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64);
        let mut first_row = Vec::with_capacity(n);
        let mut row_start = 0.0;
        read(&mut |k, z| {
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
        // Pass 2b: the rows.
        read(&mut |k, z| rows.push(&LandscapeRow::new(shift(k), z - zmin)))?;
        Ok(LandscapeStats {
            cell,
            n,
            z_min: zmin,
            range: zmax - zmin,
            edge_mismatch: mismatch,
        })
    })();
    let _ = std::fs::remove_file(&spill_path);
    result
}
