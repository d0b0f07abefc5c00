//! The checks of a [`Scene`]: every field in user units ([`Scene::validate`]), the spacing of
//! a user scene's Bravais lattices, and the warning of a slider that hangs over the substrate
//! edge.

use super::pattern;
use super::plausible::{self, plausible_field};
use super::Scene;
use crate::error::SceneError;
use crate::units::{m_to_um, nm_text, significant, um_pair_text, um_text};

/// Fewer slider spheres than this draw a warning ([`Scene::slider_size_check`]): a centre
/// sphere and its ring of six in a triangular lattice.
pub const FEW_SLIDER_SPHERES: usize = 7;

impl Scene {
    /// Checks every field; the error names the first bad field in user units.
    pub fn validate(&self) -> Result<(), SceneError> {
        self.validate_plausible()?;
        self.validate_sphere_sizes()?;
        self.slider.lattice.validate("slider.lattice")?;
        self.substrate.lattice.validate("substrate.lattice")?;
        self.validate_geometry()?;
        self.validate_slider()?;
        self.validate_substrate()?;
        self.slider.mount.validate("slider.tilt")?;
        self.validate_placement()?;
        self.material.validate()?;
        if let Some(m) = &self.body_materials.slider {
            m.validate_in("slider.material")?;
        }
        if let Some(m) = &self.body_materials.substrate {
            m.validate_in("substrate.material")?;
        }
        self.coating.validate()?;
        Ok(())
    }

    /// The sphere diameters: positive.
    fn validate_sphere_sizes(&self) -> Result<(), SceneError> {
        let um = um_text;
        if !(self.sphere_radius.is_finite() && self.sphere_radius > 0.0) {
            return Err(SceneError::invalid(
                "sphere_diameter_um",
                um(2.0 * self.sphere_radius),
                "must be a positive number",
            ));
        }
        if let Some(r) = self.geometry.slider_sphere_radius {
            if !(r.is_finite() && r > 0.0) {
                return Err(SceneError::invalid(
                    "slider.sphere_diameter_um",
                    um(2.0 * r),
                    "must be a positive number",
                ));
            }
        }
        Ok(())
    }

    /// The slider's radius (non-negative), θ and offset (finite).
    fn validate_slider(&self) -> Result<(), SceneError> {
        let um = um_text;
        if !(self.slider.radius.is_finite() && self.slider.radius >= 0.0) {
            return Err(SceneError::invalid(
                "slider.radius_um",
                um(self.slider.radius),
                "must be a non-negative number",
            ));
        }
        if !self.slider.theta.is_finite() {
            return Err(SceneError::invalid(
                "slider.theta_deg",
                self.slider.theta.to_degrees(),
                "must be finite",
            ));
        }
        if !self.slider.offset.iter().all(|v| v.is_finite()) {
            return Err(SceneError::invalid(
                "slider.offset_um",
                um_pair_text(self.slider.offset),
                "must be finite",
            ));
        }
        Ok(())
    }

    /// The substrate's sides (positive) and σ_h (non-negative, below the sphere radius).
    fn validate_substrate(&self) -> Result<(), SceneError> {
        let um = um_text;
        let [lx, ly] = self.substrate.size;
        if !(lx.is_finite() && ly.is_finite() && lx > 0.0 && ly > 0.0) {
            return Err(SceneError::invalid(
                "substrate.size_um",
                format!("{}x{}", um(lx), um(ly)),
                "both sides must be positive",
            ));
        }
        let sh = self.substrate.sigma_h;
        if !(sh.is_finite() && sh >= 0.0) {
            return Err(SceneError::invalid(
                "substrate.sigma_h_um",
                um(sh),
                "must be a non-negative number",
            ));
        }
        let r_min = self.min_sphere_radius();
        if sh >= r_min {
            let nm = m_to_um(sh) * 10f64.powi(-3);
            let slip = if nm < m_to_um(r_min) {
                format!(
                    "; did you mean {} µm (the value typed in nm)?",
                    significant(nm, 6)
                )
            } else {
                String::new()
            };
            return Err(SceneError::invalid(
                "substrate.sigma_h_um",
                um(sh),
                &format!(
                    "σ_h is in µm and must be smaller than the sphere radius {} µm{slip}",
                    um(r_min)
                ),
            ));
        }
        Ok(())
    }

    /// The slider on the substrate: its disc fits, its centre is over it.
    fn validate_placement(&self) -> Result<(), SceneError> {
        let um = um_text;
        let [lx, ly] = self.substrate.size;
        if self.slider.radius > 0.5 * lx.min(ly) {
            return Err(SceneError::invalid(
                "slider.radius_um",
                um(self.slider.radius),
                &format!(
                    "the slider disc (diameter {} µm) does not fit on the {}x{} µm substrate; \
                     use a smaller slider or a larger substrate (substrate.size_um)",
                    um(2.0 * self.slider.radius),
                    um(lx),
                    um(ly)
                ),
            ));
        }
        let [ox, oy] = self.slider.offset;
        if ox.abs() > 0.5 * lx || oy.abs() > 0.5 * ly {
            return Err(SceneError::invalid(
                "slider.offset_um",
                um_pair_text([ox, oy]),
                &format!(
                    "slider centre is not over the {}x{} µm substrate",
                    um(lx),
                    um(ly)
                ),
            ));
        }
        Ok(())
    }

    /// The plausible ranges ([`super::plausible`]) of the scene's lengths and spring: sphere
    /// diameters, lattice spacings, substrate sides, slider radius, σ_h, K1 (materials and the
    /// coating check theirs). Refuses the first implausible one in user units, with the slip
    /// it most likely is. O(1).
    fn validate_plausible(&self) -> Result<(), SceneError> {
        let mut d = vec![("sphere_diameter_um", 2.0 * self.sphere_radius)];
        if let Some(r) = self.geometry.slider_sphere_radius {
            d.push(("slider.sphere_diameter_um", 2.0 * r));
        }
        for (field, v) in d {
            plausible_field(field, &plausible::DIAMETER_UM, m_to_um(v))?;
        }
        let g = &self.geometry;
        for (l, sites, field) in [
            (&self.slider.lattice, &g.slider_sites, "slider.lattice"),
            (
                &self.substrate.lattice,
                &g.substrate_sites,
                "substrate.lattice",
            ),
        ] {
            let s = m_to_um(l.min_spacing());
            if sites.is_none() && s.is_finite() && !plausible::SPACING_UM.contains(s) {
                let why = plausible::SPACING_UM.check(s).unwrap_err();
                return Err(SceneError::invalid(
                    field,
                    format!("{} µm nearest-site spacing", significant(s, 9)),
                    &why,
                ));
            }
        }
        let [lx, ly] = self.substrate.size;
        for v in [lx, ly] {
            if v.is_finite() && v > 0.0 {
                plausible_field("substrate.size_um", &plausible::SIZE_UM, m_to_um(v))?;
            }
        }
        let r = self.slider.radius;
        if r.is_finite() && r >= 0.0 {
            plausible_field("slider.radius_um", &plausible::SIZE_UM, m_to_um(r))?;
        }
        let sh = self.substrate.sigma_h;
        if sh.is_finite() && sh >= 0.0 {
            plausible_field("substrate.sigma_h_um", &plausible::SIGMA_H_UM, m_to_um(sh))?;
        }
        if let super::Mount::Springs { k1 } = self.slider.mount {
            if k1.is_finite() && k1 >= 0.0 {
                plausible_field("slider.tilt_k1_N_m", &plausible::TILT_K1_N_M, k1)?;
            }
        }
        Ok(())
    }

    /// A warning when the slider disc at its offset hangs over the substrate edge (some slider
    /// spheres have no substrate under them: edge effects, no longer the periodic interface),
    /// `None` when it lies wholly over the substrate. Valid scenes may overhang; commands report
    /// this warning in their log and outputs.
    pub fn edge_warning(&self) -> Option<String> {
        let r = self.slider.radius;
        let [lx, ly] = self.substrate.size;
        let [ox, oy] = self.slider.offset;
        let over_x = (ox.abs() + r - 0.5 * lx).max(0.0);
        let over_y = (oy.abs() + r - 0.5 * ly).max(0.0);
        if over_x > 0.0 || over_y > 0.0 {
            Some(format!(
                "the slider (radius {} µm at offset {} µm) hangs {:.3} µm over the edge of \
                 the {}x{} µm substrate: edge effects, not the periodic interface",
                um_text(r),
                um_pair_text([ox, oy]),
                m_to_um(over_x.max(over_y)),
                um_text(lx),
                um_text(ly)
            ))
        } else {
            None
        }
    }

    /// The size check of a user's slider (the commands run it on every scene they resolve;
    /// [`Scene::validate`] does not, so that a test may build a one-sphere slider on purpose):
    /// an error when a disc slider is narrower than one of its spheres (radius below the
    /// sphere radius, e.g. metres typed into the µm field `slider.radius_um`), a warning when
    /// the slider holds fewer than [`FEW_SLIDER_SPHERES`] spheres (too few to rest flat on
    /// the substrate the way a patterned slider does). Both name the field and the sphere
    /// count. O(N_slider) (one site enumeration).
    pub fn slider_size_check(&self) -> Result<Option<String>, SceneError> {
        let n = self.slider_sites_local().len();
        let (field, value) = match (&self.geometry.slider_sites, &self.geometry.outline) {
            (Some(l), _) => ("slider.sites", l.path.clone()),
            (None, pattern::Outline::Disc) => ("slider.radius_um", um_text(self.slider.radius)),
            (None, o) => ("slider.outline", o.describe(self.slider.radius)),
        };
        let spheres = if n == 1 { "sphere" } else { "spheres" };
        let r = self.slider_sphere_radius();
        if self.geometry.slider_sites.is_none()
            && self.geometry.outline == pattern::Outline::Disc
            && self.slider.radius < r
        {
            return Err(SceneError::invalid(
                field,
                format!("{value} µm"),
                &format!(
                    "the slider disc is narrower than one of its spheres (radius {} µm) and holds {n} {spheres}; lengths are in µm",
                    um_text(r)
                ),
            ));
        }
        Ok((n < FEW_SLIDER_SPHERES).then(|| {
            format!(
                "the slider holds only {n} {spheres} (`{field}` = {value}); a patterned slider rests on many: check the field's unit (µm)"
            )
        }))
    }

    /// Checks that a Bravais lattice (no basis, no site file replacing it) keeps its spheres
    /// apart: nearest sites at least one sphere diameter apart (within the relative
    /// [`super::touch::TOUCH_TOL`], 1e-6), for user scenes
    /// ([`crate::SceneFile::into_scene`]; a test may build denser rails on purpose). Errors
    /// name `slider.lattice` / `substrate.lattice`. O(1).
    pub fn check_lattice_spacing(&self) -> Result<(), SceneError> {
        let g = &self.geometry;
        let d_sl = 2.0 * self.slider_sphere_radius();
        let d_sb = 2.0 * self.sphere_radius;
        for (l, basis, sites, d, field) in [
            (
                &self.slider.lattice,
                &g.slider_basis,
                &g.slider_sites,
                d_sl,
                "slider.lattice",
            ),
            (
                &self.substrate.lattice,
                &g.substrate_basis,
                &g.substrate_sites,
                d_sb,
                "substrate.lattice",
            ),
        ] {
            let s = l.min_spacing();
            if basis.len() <= 1 && sites.is_none() && super::touch::overlaps(s, d) {
                return Err(SceneError::invalid(
                    field,
                    format!("{} µm nearest-site spacing", um_text(s)),
                    &format!(
                        "spheres of diameter {} µm on it overlap by {} nm: give a spacing of at least the sphere diameter",
                        um_text(d),
                        nm_text(d - s)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Checks the added geometry: outline, bases (no overlapping spheres), site files (no
    /// overlapping spheres, sizes consistent), a slider with at least one sphere. O(N_slider).
    fn validate_geometry(&self) -> Result<(), SceneError> {
        let g = &self.geometry;
        g.outline.validate("slider.outline")?;
        let d_sl = 2.0 * self.slider_sphere_radius();
        let d_sb = 2.0 * self.sphere_radius;
        if g.slider_basis.len() > 1 {
            pattern::check_basis(
                &self.slider.lattice,
                &g.slider_basis,
                d_sl,
                "slider.lattice.basis_um",
            )?;
        }
        if g.substrate_basis.len() > 1 {
            pattern::check_basis(
                &self.substrate.lattice,
                &g.substrate_basis,
                d_sb,
                "substrate.lattice.basis_um",
            )?;
        }
        for (l, d, field) in [
            (&g.slider_sites, d_sl, "slider.sites"),
            (&g.substrate_sites, d_sb, "substrate.sites"),
        ] {
            match l {
                Some(l) if l.radii.is_some() => {
                    if l.radii.as_ref().map(Vec::len) != Some(l.sites.len()) {
                        return Err(SceneError::invalid(
                            field,
                            &l.path,
                            "needs one radius per site",
                        ));
                    }
                    if let Some(r) = l
                        .radii
                        .iter()
                        .flatten()
                        .find(|r| !(r.is_finite() && **r > 0.0))
                    {
                        return Err(SceneError::invalid(
                            field,
                            &l.path,
                            &format!(
                                "diameter_um = {} must be a positive number",
                                um_text(2.0 * r)
                            ),
                        ));
                    }
                    l.check_overlap_sized(field)?
                }
                Some(l) => l.check_overlap(d, field)?,
                None => {}
            }
        }
        if !g.is_plain() && self.slider_sites_local().is_empty() {
            return Err(SceneError::invalid(
                "slider.outline",
                g.outline.describe(self.slider.radius),
                "holds no slider site: make the outline larger than the lattice spacing",
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Mount;

    #[test]
    fn bad_fields_are_named() {
        let mut s = Scene::preset("tri-tri").unwrap();
        s.slider.radius = -1.0;
        assert!(s
            .validate()
            .unwrap_err()
            .to_string()
            .contains("slider.radius_um"));
        let mut s = Scene::preset("tri-tri").unwrap();
        s.substrate.sigma_h = 2e-6;
        assert!(s.validate().unwrap_err().to_string().contains("sigma_h_um"));
        let mut s = Scene::preset("tri-tri").unwrap();
        s.slider.offset = [500e-6, 0.0];
        assert!(s
            .validate()
            .unwrap_err()
            .to_string()
            .contains("slider.offset_um"));
        let mut s = Scene::preset("tri-tri").unwrap();
        s.substrate.size = [2e-6, 2e-6];
        s.slider.radius = 15e-6;
        let e = s.validate().unwrap_err().to_string();
        assert!(
            e.contains("slider.radius_um") && e.contains("does not fit"),
            "{e}"
        );
        let mut s = Scene::preset("tri-tri").unwrap();
        s.slider.mount = Mount::Springs { k1: f64::NAN };
        assert!(s
            .validate()
            .unwrap_err()
            .to_string()
            .contains("slider.tilt_k1_N_m"));
        assert!(Scene::preset("hex-tri")
            .unwrap_err()
            .to_string()
            .contains("pattern"));
    }

    #[test]
    fn a_slider_too_small_is_refused_or_warned_with_its_sphere_count() {
        let mut s = Scene::preset("tri-tri").unwrap();
        assert_eq!(s.slider_size_check().unwrap(), None);
        // metres typed into the µm field: 1e-4 µm
        s.slider.radius = 1e-10;
        let e = s.slider_size_check().unwrap_err().to_string();
        assert!(
            e.contains("slider.radius_um") && e.contains("holds 1 sphere"),
            "{e}"
        );
        // a disc wider than a sphere holding a few (a square slider lattice: the centre and
        // its four neighbours): a warning naming the count
        let mut s = Scene::preset("square-tri").unwrap();
        s.slider.radius = 3.1e-6;
        let n = s.slider_sites_local().len();
        assert!((2..FEW_SLIDER_SPHERES).contains(&n), "{n}");
        let w = s.slider_size_check().unwrap().unwrap();
        assert!(
            w.contains(&format!("only {n} spheres")) && w.contains("slider.radius_um"),
            "{w}"
        );
    }

    #[test]
    fn edge_warning_only_when_overhanging() {
        let mut s = Scene::preset("tri-tri").unwrap();
        assert!(s.edge_warning().is_none());
        s.substrate.size = [60e-6, 60e-6];
        s.slider.radius = 15e-6;
        s.slider.offset = [25e-6, 0.0];
        s.validate().unwrap();
        assert!(s.edge_warning().unwrap().contains("hangs 10.000 µm over"));
    }
}
