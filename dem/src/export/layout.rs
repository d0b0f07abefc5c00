//! [`Layout`]: the LAMMPS atoms and bonds of the Tier 3 (DEM) model, laid out from the same
//! [`SystemSpec`] the Rust engine starts from (same sites, order, heights).

use crate::system::SystemSpec;
use crate::SimParams;
use surrogate::Mount;

/// Atom type of the substrate spheres.
pub const TYPE_SUBSTRATE: u32 = 1;
/// Atom type of the slider spheres.
pub const TYPE_SLIDER: u32 = 2;
/// Atom type of the control-layer spheres that carry the axial (z) tie, `tie_length` above the
/// reference height.
pub const TYPE_CONTROL_AXIAL: u32 = 3;
/// Atom type of the control-layer spheres that carry the isotropic (x, y) tie, at the
/// reference height, co-located with their slider sphere.
pub const TYPE_CONTROL_LATERAL: u32 = 4;
/// Atom type of the support particle.
pub const TYPE_SUPPORT: u32 = 5;
/// Bond type of the axial tie (slider → axial control sphere, rest length `tie_length`).
pub const BOND_AXIAL: u32 = 1;
/// Bond type of the lateral tie (slider → co-located control sphere, rest length 0).
pub const BOND_LATERAL: u32 = 2;

/// One LAMMPS atom (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Atom {
    /// LAMMPS atom ID (1-based).
    pub id: u64,
    /// Atom type (`TYPE_*`).
    pub kind: u32,
    /// Position (m).
    pub pos: [f64; 3],
    /// Diameter (m).
    pub diameter: f64,
    /// Density (kg/m³); LAMMPS derives the mass from it and the diameter.
    pub density: f64,
    /// Molecule ID: for control spheres the quadrant code `1 + (s_x+1) + 3(s_y+1)` of their
    /// site, `s_x, s_y ∈ {−1, 0, 1}` the signs of the site's offset from the disc centre in the
    /// slider's own (unrotated) frame; 0 for every other atom.
    pub molecule: u32,
}

/// One harmonic bond.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bond {
    /// Bond type (`BOND_*`).
    pub kind: u32,
    /// First atom ID (the slider sphere).
    pub a: u64,
    /// Second atom ID (its control sphere).
    pub b: u64,
}

/// Inclusive range of atom IDs, `first..=last`; `count` 0 means empty.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct IdRange {
    /// First ID.
    pub first: u64,
    /// Number of IDs.
    pub count: u64,
}

impl IdRange {
    /// Whether `id` lies in the range.
    pub fn contains(&self, id: u64) -> bool {
        id >= self.first && id < self.first + self.count
    }
    /// Last ID (inclusive), `first − 1` when empty.
    pub fn last(&self) -> u64 {
        self.first + self.count - 1
    }
}

/// Atom-ID ranges of each particle kind, in this order in the data file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Ids {
    /// Substrate spheres, in [`SystemSpec::substrate`] order.
    pub substrate: IdRange,
    /// Slider spheres, in [`SystemSpec::slider_sites`] order (= `Scene::slider_sites`).
    pub slider: IdRange,
    /// Axial control spheres, one per slider sphere, same order.
    pub control_axial: IdRange,
    /// Lateral control spheres, one per slider sphere, same order.
    pub control_lateral: IdRange,
    /// The support particle.
    pub support: IdRange,
}

/// The full LAMMPS layout.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// Every atom, by increasing ID.
    pub atoms: Vec<Atom>,
    /// Two bonds per slider sphere (axial, then lateral).
    pub bonds: Vec<Bond>,
    /// ID ranges.
    pub ids: Ids,
    /// Control-layer centre of mass in the plane at the start (m) = the mean slider site.
    pub centroid: [f64; 2],
    /// Control-layer reference height Z (m): the z-ties are relaxed at `z_i = Z`.
    pub control_z: f64,
    /// Height of the axial control spheres above Z (m) = the axial bond's rest length.
    pub tie_length: f64,
    /// Distances `[d_x, d_y]` (m) between the centres of mass of the opposing halves of the
    /// control layer (right − left, upper − lower, slider frame); the mount springs K1 act
    /// between them (`Mount::tilt_stiffness` = R(θ) diag(K1 d_y², K1 d_x²) R(θ)ᵀ).
    pub half_distance: [f64; 2],
    /// Start position of the support (m): `support_lead` ahead of the centroid along α, at the
    /// axial control spheres' height.
    pub support: [f64; 3],
}

fn sign(v: f64) -> i32 {
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

/// Lays out `spec` (sites and start heights from [`crate::from_scene`]) with `local` the slider
/// sites relative to the disc centre in the slider's own frame (`Scene::slider_sites_local`, same
/// order), `params` (control-sphere radius, support lead, α) and the axial tie length (m).
/// Each substrate and slider atom has its own sphere diameter: its body's, or its site's with
/// per-site sizes (LAMMPS `granular` takes per-atom radii: R_eff and the contact distance of a
/// pair come from its two atoms; the mass from the diameter and the density); slider sphere i's
/// two control spheres then sit its anchor offset `R − r_i` higher.
/// The two control sub-layers have half the material density each, so the control layer has
/// the Rust engine's mass `n·m_control`. O(N).
pub fn layout(
    spec: &SystemSpec,
    local: &[[f64; 2]],
    params: &SimParams,
    tie_length: f64,
) -> Layout {
    let n = spec.slider_sites.len();
    assert_eq!(local.len(), n, "local sites must match the slider sites");
    let rho = spec.slider_material.density;
    let dc = 2.0 * params.mount.control_sphere_radius;
    let mut atoms = Vec::with_capacity(spec.substrate.len() + 3 * n + 1);
    let sub_first = 1;
    body_atoms(spec, &mut atoms);
    let sl_first = sub_first + spec.substrate.len() as u64;
    let zc = spec.control_z;
    control_atoms(spec, local, dc, tie_length, &mut atoms);
    let ax_first = sl_first + n as u64;
    let lat_first = ax_first + n as u64;
    let c = centroid(&spec.slider_sites);
    let (sa, ca) = params.protocol.alpha.sin_cos();
    let support = [
        c[0] + params.protocol.support_lead * ca,
        c[1] + params.protocol.support_lead * sa,
        zc + tie_length,
    ];
    let sup_first = lat_first + n as u64;
    push(&mut atoms, TYPE_SUPPORT, support, dc, rho, 0);
    let mut bonds = Vec::with_capacity(2 * n);
    for i in 0..n as u64 {
        bonds.push(Bond {
            kind: BOND_AXIAL,
            a: sl_first + i,
            b: ax_first + i,
        });
        bonds.push(Bond {
            kind: BOND_LATERAL,
            a: sl_first + i,
            b: lat_first + i,
        });
    }
    // d_x, d_y from the mount's own half split (K_t at θ = 0 for K1 = 1 is diag(d_y², d_x²)).
    let k = Mount::Springs { k1: 1.0 }.tilt_stiffness(local, 0.0);
    let half_distance = [k[1][1].sqrt(), k[0][0].sqrt()];
    let r = |first: u64, count: usize| IdRange {
        first,
        count: count as u64,
    };
    Layout {
        atoms,
        bonds,
        ids: Ids {
            substrate: r(sub_first, spec.substrate.len()),
            slider: r(sl_first, n),
            control_axial: r(ax_first, n),
            control_lateral: r(lat_first, n),
            support: r(sup_first, 1),
        },
        centroid: c,
        control_z: zc,
        tie_length,
        half_distance,
        support,
    }
}

/// Appends an atom with the next ID (IDs count from 1 in push order); returns its ID.
fn push(
    atoms: &mut Vec<Atom>,
    kind: u32,
    pos: [f64; 3],
    diameter: f64,
    density: f64,
    molecule: u32,
) -> u64 {
    let id = atoms.len() as u64 + 1;
    atoms.push(Atom {
        id,
        kind,
        pos,
        diameter,
        density,
        molecule,
    });
    id
}

/// The substrate atoms, then the slider atoms, each with its own diameter (its body's, or its
/// site's with per-site sizes).
fn body_atoms(spec: &SystemSpec, atoms: &mut Vec<Atom>) {
    let rho = spec.slider_material.density;
    let rho_sb = spec.substrate_material.density;
    let d_sb = 2.0 * spec.substrate_sphere_radius;
    for (j, p) in spec.substrate.iter().enumerate() {
        let d = match &spec.substrate_radii {
            None => d_sb,
            Some(r) => 2.0 * r[j],
        };
        push(atoms, TYPE_SUBSTRATE, *p, d, rho_sb, 0);
    }
    for (i, (s, z)) in spec.slider_sites.iter().zip(&spec.slider_z).enumerate() {
        push(
            atoms,
            TYPE_SLIDER,
            [s[0], s[1], *z],
            2.0 * spec.slider_radius(i),
            rho,
            0,
        );
    }
}

/// The axial control spheres (`tie_length` above), then the lateral ones, one per slider
/// sphere (diameter `dc`, m; half the slider's density), each in the rigid body of its
/// quadrant of the slider's own frame (`local`).
fn control_atoms(
    spec: &SystemSpec,
    local: &[[f64; 2]],
    dc: f64,
    tie_length: f64,
    atoms: &mut Vec<Atom>,
) {
    let rho = spec.slider_material.density;
    let quadrant = |q: &[f64; 2]| (1 + (sign(q[0]) + 1) + 3 * (sign(q[1]) + 1)) as u32;
    let zc = spec.control_z;
    // with per-site sizes slider sphere i's ties (and so its two control spheres) sit its
    // anchor offset R − r_i higher: the ties keep their rest lengths
    let dz = |i: usize| match &spec.slider_radii {
        None => 0.0,
        Some(r) => spec.slider_sphere_radius - r[i],
    };
    for (i, (s, q)) in spec.slider_sites.iter().zip(local).enumerate() {
        push(
            atoms,
            TYPE_CONTROL_AXIAL,
            [s[0], s[1], zc + dz(i) + tie_length],
            dc,
            0.5 * rho,
            quadrant(q),
        );
    }
    for (i, (s, q)) in spec.slider_sites.iter().zip(local).enumerate() {
        push(
            atoms,
            TYPE_CONTROL_LATERAL,
            [s[0], s[1], zc + dz(i)],
            dc,
            0.5 * rho,
            quadrant(q),
        );
    }
}

/// The centroid of the slider `sites` (m; the origin without sites).
fn centroid(sites: &[[f64; 2]]) -> [f64; 2] {
    let n = sites.len();
    let mut c = [0.0; 2];
    for s in sites {
        c[0] += s[0];
        c[1] += s[1];
    }
    if n > 0 {
        c[0] /= n as f64;
        c[1] /= n as f64;
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use surrogate::Material;

    #[test]
    fn ids_types_and_halves() {
        let spec = SystemSpec {
            substrate: vec![[0.0, 0.0, 0.0], [3e-6, 0.0, 1e-9]],
            slider_sites: vec![[1e-6, 2e-6], [4e-6, 2e-6], [1e-6, 5e-6]],
            slider_z: vec![3e-6, 3e-6, 2.9e-6],
            control_z: 2.9e-6,
            slider_sphere_radius: 1e-6,
            substrate_sphere_radius: 1.5e-6,
            slider_radii: None,
            substrate_radii: None,
            slider_material: Material::default(),
            substrate_material: Material::default(),
            tilt_stiffness: None,
            disc: None,
            substrate_size: None,
            scene: None,
        };
        let local = [[-1.0, -1.0], [2.0, -1.0], [-1.0, 2.0]];
        let l = layout(&spec, &local, &SimParams::default(), 3e-6);
        assert_eq!(l.atoms.len(), 2 + 3 * 3 + 1);
        assert!(l
            .atoms
            .iter()
            .enumerate()
            .all(|(i, a)| a.id == i as u64 + 1));
        assert_eq!(l.ids.slider.first, 3);
        assert_eq!(l.ids.support.last(), 12);
        assert_eq!(l.atoms[1].pos[2], 1e-9, "σ_h height kept");
        // each body's own sphere diameter
        assert!(l.atoms[..2].iter().all(|a| a.diameter == 3e-6));
        assert!(l.atoms[2..5].iter().all(|a| a.diameter == 2e-6));
        // control sphere of site 1 (local (2, −1)): s_x = +1, s_y = −1 → 1 + 2 + 0 = 3
        assert_eq!(l.atoms[l.ids.control_axial.first as usize].molecule, 3);
        assert_eq!(l.atoms[l.ids.control_axial.first as usize].pos[2], 5.9e-6);
        assert_eq!(l.atoms[l.ids.control_lateral.first as usize].pos[2], 2.9e-6);
        assert_eq!(l.bonds.len(), 6);
        assert_eq!(
            l.bonds[0],
            Bond {
                kind: BOND_AXIAL,
                a: 3,
                b: 6
            }
        );
        // halves: x' > 0 {2}, x' < 0 {−1, −1} → d_x = 3; same for y
        assert!((l.half_distance[0] - 3.0).abs() < 1e-12);
        assert!((l.half_distance[1] - 3.0).abs() < 1e-12);
        assert!((l.centroid[0] - 2e-6).abs() < 1e-18);
        assert!((l.support[0] - (2e-6 + 120e-6)).abs() < 1e-18);
    }
}
