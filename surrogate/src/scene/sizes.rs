//! Per-site sphere sizes of a [`Scene`]: each sphere's radius where a site file's
//! `diameter_um` column gives differing ones, and the bounds and totals the tiers need.

use super::Scene;

impl Scene {
    /// Per-site radii (m) of the slider spheres, in [`Scene::slider_sites_local`] order, when
    /// they differ (a site file with a varying `diameter_um` column); `None`: every slider
    /// sphere has [`Scene::slider_sphere_radius`]. See [`super::SiteList`] for the geometry.
    pub fn slider_radii(&self) -> Option<&[f64]> {
        self.geometry.slider_sites.as_ref()?.radii.as_deref()
    }

    /// Per-site radii (m) of the substrate spheres, in [`Scene::substrate_spheres`] order, when
    /// they differ; `None`: every substrate sphere has `sphere_radius`.
    pub fn substrate_radii(&self) -> Option<&[f64]> {
        self.geometry.substrate_sites.as_ref()?.radii.as_deref()
    }

    /// Whether either body has per-site sphere sizes.
    pub fn has_site_sizes(&self) -> bool {
        self.slider_radii().is_some() || self.substrate_radii().is_some()
    }

    /// Largest slider sphere radius (m) (the reference radius without per-site sizes). O(N).
    pub fn max_slider_sphere_radius(&self) -> f64 {
        match self.slider_radii() {
            Some(r) => r.iter().copied().fold(0.0, f64::max),
            None => self.slider_sphere_radius(),
        }
    }

    /// Largest centre distance (m) at which any slider–substrate pair touches:
    /// `max r_i + max r_j` ([`Scene::contact_distance`], bit for bit, without per-site sizes).
    /// The lateral reach of the candidate search. O(N).
    pub fn max_contact_distance(&self) -> f64 {
        if !self.has_site_sizes() {
            return self.contact_distance();
        }
        let sb = match self.substrate_radii() {
            Some(r) => r.iter().copied().fold(0.0, f64::max),
            None => self.sphere_radius,
        };
        self.max_slider_sphere_radius() + sb
    }

    /// Smallest sphere radius (m) of either body. O(N).
    pub fn min_sphere_radius(&self) -> f64 {
        let mut m = self.sphere_radius.min(self.slider_sphere_radius());
        for r in [self.slider_radii(), self.substrate_radii()]
            .into_iter()
            .flatten()
        {
            m = r.iter().copied().fold(m, f64::min);
        }
        m
    }

    /// Total mass (kg) of the slider spheres: `N m(R)` for one size, `Σ m(r_i)` with per-site
    /// sizes. O(N).
    pub fn slider_spheres_mass(&self) -> f64 {
        match self.slider_radii() {
            Some(r) => {
                let m = self.slider_material();
                r.iter().map(|&ri| m.sphere_mass(ri)).sum()
            }
            None => {
                self.slider_sites_local().len() as f64
                    * self
                        .slider_material()
                        .sphere_mass(self.slider_sphere_radius())
            }
        }
    }
}
