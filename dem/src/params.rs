//! [`SimParams`]: every numerical knob of the DEM engine in one place (SI units).

use serde::{Deserialize, Serialize};

/// In which frame the 0 K Langevin-equivalent viscous damping `−m (v − v_ref)/τ` acts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum DampingFrame {
    /// Substrate spheres: absolute (lab frame, they are tethered to fixed sites). Slider spheres:
    /// relative to the control layer's velocity. Control layer: z absolute, x/y relative to the
    /// support's velocity. A steadily sliding slider feels no drag, so the pulling-spring force
    /// measures contact friction only (default).
    Relative,
    /// Every particle damped against its absolute velocity (a plain `fix viscous`/`fix langevin`
    /// at 0 K). A slider sliding at v then feels an extra drag `Σm·v/τ` that adds to the spring
    /// force: 0.011 mN for the study scene at 0.1 m/s.
    Absolute,
}

/// The tangential history of the Mindlin spring (LAMMPS `pair granular` `tangential` names).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Tangential {
    /// History = elastic displacement ξ, force `−k_t(a)·ξ` at the current contact radius: a
    /// stuck contact's force follows a when its load changes (LAMMPS `mindlin`; default).
    #[default]
    Mindlin,
    /// History = elastic force, incremented by `−k_t(a)·v_t·dt`: a stuck contact keeps its force
    /// when its load changes (LAMMPS `mindlin_force`, `crate::model::MindlinForce`).
    MindlinForce,
    /// History = elastic displacement, scaled by a/a_prev when the contact radius falls: a
    /// stuck contact sheds force ∝ a² on unloading (LAMMPS `mindlin_rescale`,
    /// `crate::model::MindlinRescale`).
    MindlinRescale,
}

impl Tangential {
    /// Whether this is the default ([`Tangential::Mindlin`]).
    pub fn is_default(&self) -> bool {
        *self == Tangential::Mindlin
    }

    /// The kebab-case name (`mindlin`, `mindlin-force`, `mindlin-rescale`).
    pub fn name(self) -> &'static str {
        match self {
            Tangential::Mindlin => "mindlin",
            Tangential::MindlinForce => "mindlin-force",
            Tangential::MindlinRescale => "mindlin-rescale",
        }
    }
}

/// Every numerical knob of a DEM run (SI: s, m, N/m, N, rad). Defaults = the reference study
/// (docs/physics.md, Tier 3) except `dt`, which defaults to a fraction of the stable step.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SimParams {
    /// Time step (s). `None`: `dt_safety ×` the stable-step estimate of [`crate::stability`].
    pub dt: Option<f64>,
    /// Fraction of the estimated critical step used when `dt` is `None` (–).
    pub dt_safety: f64,
    /// Neighbour-list skin (m): pairs within `2R + skin` are listed; the list is rebuilt when
    /// any particle has moved more than `skin/2` since the last build.
    pub skin: f64,
    /// Damping time τ (s) of the 0 K Langevin-equivalent viscous damping; `f64::INFINITY` = off.
    pub damping_time: f64,
    /// Frame of that damping.
    pub damping_frame: DampingFrame,
    /// Dimensionless normal damping γ_n: `F_d = −γ_n √(m_eff S_n) v_n`, `S_n = 2E*√(R_eff δ)`.
    /// Coefficient of restitution `e ≈ 1 − 1.7207 γ_n` for small γ_n (velocity independent).
    pub gamma_n: f64,
    /// Dimensionless tangential damping γ_t: `F_td = −γ_t √(m_eff k_t) v_t`.
    pub gamma_t: f64,
    /// Tangential history of the Mindlin spring. (Left out of the serialized form at its
    /// default, so checkpoints and stored runs made before it existed still match.)
    #[serde(default, skip_serializing_if = "Tangential::is_default")]
    pub tangential: Tangential,
    /// Lateral (x, y) stiffness of each slider-sphere–control-layer spring (N/m). Study: 1e3.
    pub k_slider_xy: f64,
    /// Vertical stiffness of each slider-sphere–control-layer spring (N/m). Study: 1e6.
    pub k_slider_z: f64,
    /// Lateral tether stiffness of each substrate sphere to its site (N/m). Study: 1e3.
    pub k_substrate_xy: f64,
    /// Pulling spring stiffness K0 between support and control-layer centre of mass (N/m).
    pub k0: f64,
    /// Distance the support starts ahead of the control layer along α (m) = spring rest length.
    pub support_lead: f64,
    /// Support speed (m/s) along α during sliding. Study: 0.1.
    pub support_speed: f64,
    /// Pulling angle α (rad) from the +x axis (the substrate row / contact-line direction).
    pub alpha: f64,
    /// Normal load W (N) applied downward on the control layer.
    pub load: f64,
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
    /// Reduction (a): leave out substrate spheres farther than `slider radius + 2R + prune_margin`
    /// from the slider centre's path (start → start + travel along α).
    pub prune_substrate: bool,
    /// Extra margin (m) of reduction (a).
    pub prune_margin: f64,
    /// Active set (exact to round-off): integrate step by step only the particles in or near
    /// contact; the rest follow their rest state (substrate: tether site; slider: its site on
    /// the control layer plus the common relative motion of all free slider spheres) plus, while
    /// they ring down after a contact, an exactly propagated deviation. See `docs/validation/dem-engine.md`.
    /// With per-site sphere sizes every sphere of a body whose sizes differ stays in the set (the
    /// common mode and the ringing maps take one mass).
    pub active_set: bool,
    /// Activation margin (m): a slider–substrate pair is integrated while its gap
    /// (centre distance − 2R) is below this; the set is re-evaluated as soon as some particle
    /// has moved `active_margin/2` since the last evaluation, so no pair can touch unnoticed.
    pub active_margin: f64,
    /// Equilibration time under load (s), control layer held laterally. Study: 10 µs.
    pub equilibrate_time: f64,
    /// Relaxation time with the pulling spring attached and the support at rest (s). Study: 10 µs.
    pub relax_time: f64,
    /// Sliding time (s). Study: 300 µs.
    pub slide_time: f64,
    /// Friction = mean spring force over sliding times in `[measure_from·slide_time, slide_time]`.
    /// Study: 1/3 (100–300 µs of 300 µs).
    pub measure_from: f64,
    /// Sampling interval of the time series (s).
    pub sample_interval: f64,
    /// Lock-in: over the measuring window, slider advance / support advance below this → locked.
    pub lock_in_ratio: f64,
    /// Smallest work chunk (particles) of the parallel passes. Chunk sizes depend only on the
    /// work and this knob, never on the thread count, so results are bit-identical for any
    /// number of threads.
    pub chunk_min: usize,
    /// Below this many active particles + pairs a step runs on one thread (handing a pass to
    /// the team of threads costs a few µs); above it `Sim::run_steps` times both modes now and
    /// then and keeps the faster (on a shared machine a second thread can be slower). 0 forces
    /// the parallel passes (tests). Does not change results.
    pub parallel_min_work: usize,
    /// Largest admissible overlap as a fraction of the sphere radius (the smaller of the
    /// slider's and the substrate's when they differ); beyond it the run stops
    /// with [`crate::DemError::Unstable`].
    pub overlap_bound: f64,
}

impl Default for SimParams {
    fn default() -> Self {
        SimParams {
            dt: None,
            dt_safety: 0.25,
            skin: 0.3e-6,
            damping_time: 1e-6,
            damping_frame: DampingFrame::Relative,
            gamma_n: 0.1,
            gamma_t: 0.1,
            tangential: Tangential::Mindlin,
            k_slider_xy: 1e3,
            k_slider_z: 1e6,
            k_substrate_xy: 1e3,
            k0: 50.0,
            support_lead: 120e-6,
            support_speed: 0.1,
            alpha: 0.0,
            load: 0.35e-3,
            control_sphere_radius: 0.5e-6,
            rigid_z: false,
            implicit_mount: false,
            prune_substrate: false,
            prune_margin: 3e-6,
            active_set: false,
            active_margin: 20e-9,
            equilibrate_time: 10e-6,
            relax_time: 10e-6,
            slide_time: 300e-6,
            measure_from: 1.0 / 3.0,
            sample_interval: 0.1e-6,
            lock_in_ratio: 0.5,
            chunk_min: 192,
            parallel_min_work: 2500,
            overlap_bound: 0.1,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::SimParams;
    use surrogate::friction::FrictionParams;

    /// The surrogate's friction estimate mirrors the DEM protocol with its own copies of these
    /// knobs (the `surrogate` crate cannot read `SimParams`): the defaults must stay equal, or
    /// μ_est would silently estimate another protocol than the DEM runs.
    #[test]
    fn friction_estimate_defaults_mirror_the_dem_protocol() {
        let d = SimParams::default();
        let f = FrictionParams::default();
        assert_eq!(f.k0, d.k0);
        assert_eq!(f.k_slider_xy, d.k_slider_xy);
        assert_eq!(f.k_substrate_xy, d.k_substrate_xy);
        assert_eq!(f.speed, d.support_speed);
        assert_eq!(f.slide_time, d.slide_time);
        assert!((f.window_start - d.measure_from * d.slide_time).abs() <= 1e-12 * d.slide_time);
        assert_eq!(f.tau, d.damping_time);
        assert_eq!(f.control_sphere_radius, d.control_sphere_radius);
    }
}
