//! Building a [`SystemSpec`] from a [`surrogate::Scene`], started from the surrogate's
//! quasi-static equilibrium or from a gap.

use super::SystemSpec;
use crate::{DemError, Nominal, SimParams};
use surrogate::solver::Equilibrium;
use surrogate::Scene;

/// How the slider starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Start {
    /// At the surrogate's rigid-slider equilibrium height for the load (contacts already loaded).
    Surrogate,
    /// Resting `gap` (m) above the highest first-touch height, falling under the load.
    Gap(f64),
}

/// The surrogate's answer for the same scene and load (SI), for comparison.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StartInfo {
    /// Surrogate equilibrium height z (m).
    pub z: f64,
    /// Surrogate contact number.
    pub contacts: usize,
    /// Surrogate P_max (Pa).
    pub p_max: f64,
    /// Substrate spheres left out by reduction (a).
    pub pruned: usize,
}

/// Lays out the particles of `scene` (at its own θ and offset) for `params` (load, α, travel,
/// reductions), with the slider's and the substrate's own sphere radii: one per body, or each
/// sphere's own where a site file gives per-site sizes (`SystemSpec::slider_radii`,
/// `substrate_radii`; slider sphere i starts `R − r_i` above the body's reference height, its
/// top on the slider plate). Cost: one surrogate solve, O(N log N); [`from_scene_at`] reuses a
/// run's nominal solve.
pub fn from_scene(
    scene: &Scene,
    params: &SimParams,
    start: Start,
) -> Result<(SystemSpec, StartInfo), DemError> {
    let nominal = Nominal::solve(scene, params.protocol.load)?;
    Ok(from_scene_at(scene, params, start, &nominal.eq))
}

/// [`from_scene`] from the surrogate's equilibrium `eq` of `scene` at `params.protocol.load`
/// (the run's [`Nominal`] solve). Cost: O(N log N).
pub fn from_scene_at(
    scene: &Scene,
    params: &SimParams,
    start: Start,
    eq: &Equilibrium,
) -> (SystemSpec, StartInfo) {
    let sites = scene.slider_sites();
    let n = sites.len();
    let mut sub = scene.substrate_spheres();
    let mut sub_radii = scene.substrate_radii().map(|r| r.to_vec());
    let all = sub.len();
    if params.active.prune_substrate {
        prune(scene, params, &mut sub, &mut sub_radii);
    }
    // slider sphere i's anchor offset R − r_i (none for one size)
    let r_ref = scene.slider_sphere_radius();
    let slider_radii = scene.slider_radii().map(|r| r.to_vec());
    let pruned = all - sub.len();
    let (slider_z, control_z) = match start {
        Start::Surrogate => {
            let mut z = vec![eq.z; n];
            let k = if params.mount.rigid_z {
                f64::INFINITY
            } else {
                params.mount.k_slider_z
            };
            let zc = eq.z - params.protocol.load / (eq.contacts.len().max(1) as f64) / k;
            let mut touching = vec![false; n];
            for c in &eq.contacts {
                touching[c.slider as usize] = true;
            }
            for (zi, t) in z.iter_mut().zip(&touching) {
                if !t {
                    *zi = zc;
                }
            }
            (z, zc)
        }
        Start::Gap(g) if scene.has_site_sizes() => {
            // the reference height whose lowest sphere bottom (R − 2 r_max below it) clears
            // the highest substrate top by g
            let top = sub
                .iter()
                .enumerate()
                .map(|(j, p)| p[2] + sub_radii.as_ref().map_or(scene.sphere_radius, |r| r[j]))
                .fold(f64::NEG_INFINITY, f64::max);
            let z0 = top + 2.0 * scene.max_slider_sphere_radius() - r_ref + g;
            (vec![z0; n], z0)
        }
        Start::Gap(g) => {
            let ztop = sub.iter().map(|p| p[2]).fold(f64::NEG_INFINITY, f64::max);
            let z0 = ztop + scene.contact_distance() + g;
            (vec![z0; n], z0)
        }
    };
    let slider_z = match &slider_radii {
        Some(r) => slider_z
            .iter()
            .zip(r)
            .map(|(z, ri)| z + (r_ref - ri))
            .collect(),
        None => slider_z,
    };
    (
        SystemSpec {
            substrate: sub,
            slider_sites: sites,
            slider_z,
            control_z,
            slider_sphere_radius: scene.slider_sphere_radius(),
            substrate_sphere_radius: scene.sphere_radius,
            slider_radii,
            substrate_radii: sub_radii,
            slider_material: scene.slider_material(),
            substrate_material: scene.substrate_material(),
            tilt_stiffness: scene
                .slider
                .mount
                .tilts()
                .then(|| scene.tilt_stiffness_at(scene.slider.theta)),
            disc: Some((scene.slider.offset, scene.slider.radius)),
            substrate_size: Some(scene.substrate.size),
            scene: Some(scene.clone()),
        },
        StartInfo {
            z: eq.z,
            contacts: eq.contact_count(),
            p_max: eq.p_max,
            pruned,
        },
    )
}

/// Reduction (a): leaves out the substrate spheres (and their radii) farther than the slider
/// radius + the largest contact distance + `prune_margin` from the slider centre's path.
/// O(N).
fn prune(
    scene: &Scene,
    params: &SimParams,
    sub: &mut Vec<[f64; 3]>,
    sub_radii: &mut Option<Vec<f64>>,
) {
    let c = scene.slider.offset;
    let travel =
        params.protocol.support_speed * params.protocol.slide_time + params.active.prune_margin;
    let e = [
        c[0] + travel * params.protocol.alpha.cos(),
        c[1] + travel * params.protocol.alpha.sin(),
    ];
    let reach = scene.slider.radius + scene.max_contact_distance() + params.active.prune_margin;
    let keep = |p: &[f64; 3]| seg_dist2([p[0], p[1]], c, e) <= reach * reach;
    if let Some(r) = sub_radii {
        let mut it = sub.iter();
        r.retain(|_| keep(it.next().unwrap()));
    }
    sub.retain(keep);
}

fn seg_dist2(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1]];
    let ap = [p[0] - a[0], p[1] - a[1]];
    let l2 = ab[0] * ab[0] + ab[1] * ab[1];
    let t = if l2 > 0.0 {
        ((ap[0] * ab[0] + ap[1] * ab[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let d = [ap[0] - t * ab[0], ap[1] - t * ab[1]];
    d[0] * d[0] + d[1] * d[1]
}
