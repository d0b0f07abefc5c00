//! [`MountParams`]: how the bodies are held — the slider spheres' springs to the control
//! layer, the substrate's tethers, the control layer's size, and which mount model integrates
//! them (rigid-z, implicit).

use serde::{Deserialize, Serialize};

/// The springs that hold the slider spheres on the control layer and the substrate spheres on
/// their sites (N/m, m), and the model of that network. Defaults = the reference study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MountParams {
    /// Lateral (x, y) stiffness of each slider-sphere–control-layer spring (N/m). Study: 1e3.
    pub k_slider_xy: f64,
    /// Vertical stiffness of each slider-sphere–control-layer spring (N/m). Study: 1e6.
    pub k_slider_z: f64,
    /// Lateral tether stiffness of each substrate sphere to its site (N/m). Study: 1e3.
    pub k_substrate_xy: f64,
    /// Radius (m) of each control-layer sphere (mass from its volume). Study: 0.5 µm.
    pub control_sphere_radius: f64,
    /// Reduction (b): slider spheres move rigidly with the control layer in z (no 1e6 N/m
    /// z-springs, no z-DOF per slider sphere).
    pub rigid_z: bool,
    /// Full model only (ignored with `rigid_z`): integrate the linear z network of the mount —
    /// the slider spheres' k_z springs and their damping, the control layer's Z and tilts with
    /// the mount springs, the load — with the trapezoidal (implicit-midpoint) rule, solved in
    /// O(N) through the star structure (`integrator::mount`), and the contact forces explicit
    /// (Strang split). The step is then limited by the contacts, not by the stiff k_z springs
    /// (×28 larger on the study scene). `false`: velocity-Verlet on everything
    /// (`--model full-explicit`).
    /// (Left out of the serialized form when `false`, so checkpoints and stored runs of the
    /// explicit engine made before it existed still match.)
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub implicit_mount: bool,
}

impl Default for MountParams {
    fn default() -> Self {
        MountParams {
            k_slider_xy: 1e3,
            k_slider_z: 1e6,
            k_substrate_xy: 1e3,
            control_sphere_radius: 0.5e-6,
            rigid_z: false,
            implicit_mount: false,
        }
    }
}
