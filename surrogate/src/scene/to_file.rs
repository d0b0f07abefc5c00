//! The reverse of [`SceneFile::into_scene`]: a [`Scene`] (SI) back to its file form in user
//! units, recorded in every output's sidecar and reloadable to the identical scene.

use super::{
    CoatingFile, LatticeFile, MaterialFile, Mount, Outline, OutlineFile, Scene, SceneFile,
    SliderFile, SubstrateFile,
};
use super::{Lattice, Material};
use crate::units::{
    gcm3_to_kgm3, gpa_to_pa, kgm3_to_gcm3, m_to_um, pa_to_gpa, rad_to_deg, um_to_m,
};

/// The shortest decimal user value `u` (trying 1 to 17 significant digits of `to_user(si)`) whose
/// conversion back, `to_si(u)`, is exactly `si`; `to_user(si)` if none is. Makes a recorded
/// scene reload to the identical SI scene.
fn exact_user(si: f64, to_user: impl Fn(f64) -> f64, to_si: impl Fn(f64) -> f64) -> f64 {
    let u = to_user(si);
    if !u.is_finite() {
        return u;
    }
    for digits in 0..17 {
        if let Ok(c) = format!("{u:.digits$e}").parse::<f64>() {
            if to_si(c) == si {
                return c;
            }
        }
    }
    // No decimal converts back exactly (e.g. a preset's 364e-6 m is not 364 × 1e-6): the nearest
    // neighbouring double that does.
    for k in 1..=8u64 {
        for c in [
            f64::from_bits(u.to_bits().wrapping_add(k)),
            f64::from_bits(u.to_bits().wrapping_sub(k)),
        ] {
            if c.is_finite() && to_si(c) == si {
                return c;
            }
        }
    }
    u
}

fn um(si: f64) -> f64 {
    exact_user(si, m_to_um, um_to_m)
}

fn um2(v: [f64; 2]) -> [f64; 2] {
    [um(v[0]), um(v[1])]
}

/// `l` with the basis `b` (m) recorded in µm (none when empty).
fn with_basis(mut l: LatticeFile, b: &[[f64; 2]]) -> LatticeFile {
    l.basis_um = (!b.is_empty()).then(|| b.iter().map(|p| um2(*p)).collect());
    l
}

/// The outline in user units (`None` for the disc: `radius_um` records it).
fn outline_file(o: &Outline) -> Option<OutlineFile> {
    let f = OutlineFile::default();
    match o {
        Outline::Disc => None,
        Outline::Rectangle { size } => Some(OutlineFile {
            kind: "rectangle".into(),
            size_um: Some(um2(*size)),
            ..f
        }),
        Outline::RegularPolygon { sides, radius } => Some(OutlineFile {
            kind: "polygon".into(),
            sides: Some(*sides),
            radius_um: Some(um(*radius)),
            ..f
        }),
        Outline::Polygon { vertices } => Some(OutlineFile {
            kind: "polygon".into(),
            vertices_um: Some(vertices.iter().map(|p| um2(*p)).collect()),
            ..f
        }),
    }
}

/// A material in user units, every field written.
fn material_file(m: &Material) -> MaterialFile {
    MaterialFile {
        youngs_gpa: Some(exact_user(m.youngs, pa_to_gpa, gpa_to_pa)),
        poisson: Some(m.poisson),
        density_g_cm3: Some(exact_user(m.density, kgm3_to_gcm3, gcm3_to_kgm3)),
    }
}

/// A lattice in user units: its named kind when it is exactly that kind's lattice, else oblique.
fn lattice_file(l: &Lattice) -> LatticeFile {
    let s = um(l.a1[0]);
    let named = [
        ("triangular", Lattice::triangular(um_to_m(s))),
        ("square", Lattice::square(um_to_m(s))),
    ];
    for (kind, cand) in named {
        if cand == *l {
            return LatticeFile {
                kind: kind.into(),
                spacing_um: Some(s),
                ..Default::default()
            };
        }
    }
    let sy = um(l.a2[1]);
    if Lattice::rectangular(um_to_m(s), um_to_m(sy)) == *l {
        return LatticeFile {
            kind: "rectangular".into(),
            spacing_um: Some(s),
            spacing_y_um: Some(sy),
            ..Default::default()
        };
    }
    LatticeFile {
        kind: "oblique".into(),
        a1_um: Some(um2(l.a1)),
        a2_um: Some(um2(l.a2)),
        ..Default::default()
    }
}

/// The full scene in user units, reloadable: `scene_file(s).into_scene() == s` (tested for the
/// presets and modified scenes). The lattices are written only when the scene's pattern says a
/// file changed them (`pattern*` or `custom`); otherwise the pattern's preset defines them.
pub fn scene_file(s: &Scene) -> SceneFile {
    let base = s.pattern.trim_end_matches('*');
    let custom_lattices = s.pattern.ends_with('*') || s.pattern == "custom";
    let g = &s.geometry;
    let (tilt, k1) = match s.slider.mount {
        Mount::Springs { k1 } => ("springs", Some(k1)),
        m => (m.name(), None),
    };
    SceneFile {
        pattern: (s.pattern != "custom").then(|| base.to_string()),
        sphere_diameter_um: Some(exact_user(
            s.sphere_radius,
            |r| m_to_um(2.0 * r),
            |d| um_to_m(d) / 2.0,
        )),
        slider: SliderFile {
            lattice: (custom_lattices && g.slider_sites.is_none())
                .then(|| with_basis(lattice_file(&s.slider.lattice), &g.slider_basis)),
            radius_um: Some(um(s.slider.radius)),
            outline: outline_file(&g.outline),
            sites: g.slider_sites.as_ref().map(|l| l.path.clone()),
            sphere_diameter_um: g
                .slider_sphere_radius
                .map(|r| exact_user(r, |r| m_to_um(2.0 * r), |d| um_to_m(d) / 2.0)),
            theta_deg: Some(exact_user(s.slider.theta, rad_to_deg, f64::to_radians)),
            offset_um: Some(um2(s.slider.offset)),
            tilt: Some(tilt.into()),
            tilt_k1_n_m: k1,
            material: s.body_materials.slider.as_ref().map(material_file),
        },
        substrate: SubstrateFile {
            lattice: (custom_lattices && g.substrate_sites.is_none())
                .then(|| with_basis(lattice_file(&s.substrate.lattice), &g.substrate_basis)),
            sites: g.substrate_sites.as_ref().map(|l| l.path.clone()),
            sphere_diameter_um: None,
            size_um: Some(um2(s.substrate.size)),
            sigma_h_um: Some(um(s.substrate.sigma_h)),
            seed: Some(s.substrate.seed),
            material: s.body_materials.substrate.as_ref().map(material_file),
        },
        material: material_file(&s.material),
        coating: CoatingFile {
            p_crit_gpa: Some(exact_user(s.coating.p_crit, pa_to_gpa, gpa_to_pa)),
            mu1: Some(s.coating.mu1),
            mu2: Some(s.coating.mu2),
        },
    }
}

/// [`scene_file`] with both bodies' lattices written even where the preset defines them (not
/// for a body from a site file), so that a lattice field (`slider.lattice.spacing_um`) can be
/// changed in the file form. Reloads to the same scene, its pattern marked as changed
/// (`square-tri*`).
pub fn scene_file_with_lattices(s: &Scene) -> SceneFile {
    let mut f = scene_file(s);
    let g = &s.geometry;
    if f.slider.lattice.is_none() && g.slider_sites.is_none() {
        f.slider.lattice = Some(with_basis(lattice_file(&s.slider.lattice), &g.slider_basis));
    }
    if f.substrate.lattice.is_none() && g.substrate_sites.is_none() {
        f.substrate.lattice = Some(with_basis(
            lattice_file(&s.substrate.lattice),
            &g.substrate_basis,
        ));
    }
    f
}

impl From<&Scene> for SceneFile {
    /// [`scene_file`].
    fn from(s: &Scene) -> SceneFile {
        scene_file(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Same scene: equal, except lengths that no user-unit number converts to exactly (the
    /// presets' `364e-6` m is not `364 × 1e-6`), which must agree to 1 ulp.
    fn same(a: &Scene, b: &Scene) {
        let close = |x: f64, y: f64| (x - y).abs() <= 2.0 * f64::EPSILON * x.abs().max(y.abs());
        let mut b2 = b.clone();
        for k in 0..2 {
            assert!(
                close(a.substrate.size[k], b.substrate.size[k]),
                "{a:?} {b:?}"
            );
            b2.substrate.size[k] = a.substrate.size[k];
        }
        assert_eq!(a, &b2);
    }

    fn round_trips(s: &Scene) {
        let f = scene_file(s);
        same(&f.into_scene().unwrap(), s);
        let toml = toml::to_string(&f).unwrap();
        let g = SceneFile::from_toml(&toml, "sidecar").unwrap();
        let reloaded = g.into_scene().unwrap();
        same(&reloaded, s);
        // Recording the reloaded scene gives the same record (and hash).
        assert_eq!(scene_file(&reloaded), f, "{toml}");
    }

    #[test]
    fn recorded_scenes_reload_exactly() {
        for p in crate::scene::PATTERNS {
            round_trips(&Scene::preset(p).unwrap());
        }
        let f = SceneFile::from_toml(
            "pattern = 'tri-tri'\nsphere_diameter_um = 2.7\n[slider]\nradius_um = 31.3\ntheta_deg = 10.2\n\
             offset_um = [1.1, -0.4]\ntilt = 'free'\n[substrate]\nsigma_h_um = 0.002\nseed = 7\n\
             lattice = { kind = 'oblique', a1_um = [3.0, 0.0], a2_um = [1.0, 2.8] }\n\
             [material]\nyoungs_GPa = 50\ndensity_g_cm3 = 2.2\n[coating]\np_crit_GPa = 3.3\nmu1 = 0.02\n",
            "t",
        )
        .unwrap();
        round_trips(&f.into_scene().unwrap());
        let f = SceneFile::from_toml(
            "[slider]\nlattice = { kind = 'rectangular', spacing_um = 3.05, spacing_y_um = 3.3 }\n\
             tilt_k1_N_m = 2.5e5\n[substrate]\nlattice = { kind = 'square', spacing_um = 3.1 }\n",
            "t",
        )
        .unwrap();
        let s = f.into_scene().unwrap();
        assert_eq!(s.pattern, "custom");
        round_trips(&s);
    }
}
