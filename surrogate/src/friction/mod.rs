//! Surrogate friction estimate: the friction coefficient of steady sliding in the DEM protocol,
//! estimated from the quasi-static path of the rigid slider (no dynamics).
//!
//! For a scene (with its slider mount), a rotation θ, a pulling direction e (unit vector in the
//! substrate plane, angle φ from the x axis) and a load W, [`estimate_friction`] solves the
//! equilibrium ([`crate::solver::Model::Auto`]) at samples `s_k = k·h` of a straight path
//! `shift = s·e` from the scene's placement, and returns ([`FrictionEstimate`])
//!
//! ```text
//! μ_est = μ_coat + μ_PT
//! ```
//!
//! ## Coating term
//! In steady sliding every contact slips, so contact i resists with `μ(p0_i)·F_n,i` along its
//! tangent plane, against the slip direction `e_t,i = e − (e·n_i) n_i` (n_i the unit contact
//! normal from the substrate sphere to the slider sphere). Its component along e is
//! `μ(p0_i) F_n,i (e_t,i·e)/|e_t,i| = μ(p0_i) F_n,i |e_t,i|`, which is also the energy it
//! dissipates per unit sliding distance. `μ(p0) = μ1` for p0 ≤ P_crit and μ2 above (the DEM's law,
//! `dem/src/model/pressure_switched.rs`, switched on the current p0). P_max and the load on
//! failed contacts change along the path, so the term is averaged over it:
//!
//! ```text
//! μ_coat = ⟨ Σ_i μ(p0_i) · F_n,i · √(1 − (e·n_i)²) ⟩_s / W
//! ```
//!
//! For contacts whose normal lies in the vertical plane through e, `F_n,i √(1 − (e·n_i)²) =
//! F_z,i`, so a constant μ gives exactly `μ·ΣF_z/W = μ`. A contact inclined sideways (normal
//! tilted across e) carries `F_n = F_z/n_z > F_z` and rubs with all of it: the geometric excess
//! of a sphere-on-sphere interface over μW (+6 % on the square-tri θ = 0 study scene across its
//! contact lines, where the DEM measures μ = 0.0107 with μ1 = 0.01).
//!
//! ## Corrugation term (Prandtl–Tomlinson)
//! The enthalpy of the slider along the path, `V(s) = Σ_i (2/5) k δ_i^{5/2} + W·z + ½ tᵀK_t t`
//! (Hertz energy, work against the load, energy of the mount's tilt springs), has the exact
//! slope `V'(s) = F_pull(s) = −Σ_i F_n,i (n_i·e)` at every sample (envelope theorem). The
//! athermal quasi-static Prandtl–Tomlinson model pulls the slider through a spring K over
//! `V` (F_pull interpolated linearly between samples, so a cusp where the contacts change
//! partners cannot overshoot): `E(x; X) = V(x) + ½K(x − X)²`. As the
//! support X advances the slider follows a local minimum of E; where that minimum vanishes
//! (`V''(x) < −K`) it jumps to the next one, dissipating the energy drop. The dissipation per
//! unit length in steady sliding is the mean spring force, so
//!
//! ```text
//! μ_PT = (Σ_jumps ΔE) / (window length · W)
//! ```
//!
//! It is zero unless `η = max_s(−V''(s))/K > 1` (for a sinusoid of barrier U0 and period a,
//! `max(−V'') = 2π²U0/a²`, the classical `η = 2π²U0/(K a²)`), and tends to the largest lateral
//! force of the path for η ≫ 1. `K = (1/K0 + 1/k_lat)⁻¹`: the pulling spring K0 = 50 N/m in
//! series with the lateral stiffness of the contacting chains,
//! `k_lat = Σ_{slider spheres in contact} (1/k_xy + 1/(n_i k_tether))⁻¹` (ties of 10³ N/m to the
//! control layer, n_i substrate tethers of 10³ N/m in parallel), path-averaged. (Each single
//! asperity is far too stiffly tied to stick-slip by itself: its own curvature F_z,i/2R is below
//! 20 N/m at the study's loads against ties of 500 N/m in series.) The solution is closed-form on
//! every interval (`tomlinson.rs`).
//!
//! ## The path
//! If e is a substrate lattice direction (the shortest lattice vector T along e, within
//! `direction_tol`, has `|T| ≤ max_period`), V is exactly periodic with period |T| and the path
//! is that one period: the coating average is over the period, and the Prandtl–Tomlinson model
//! runs on the periodic extension until the motion repeats and measures one steady period (exact
//! for the interpolated V). Otherwise the landscape is quasi-periodic and the path has the fixed
//! `length` (12 µm, four 3 µm lattice spacings); the model skips the first `transient` (3 µm,
//! the spring loading from rest) and measures between the first and last landing after it, so
//! the window spans whole stick-slip cycles. The step (≤ 0.05 µm) resolves the landscape, which
//! varies on the 1.5–3 µm scale of the lattices (measured convergence: see the crate README).
//!
//! ## Reported alongside
//! η, the barrier `U0 = max V − min V`, the largest lateral force, the mean and largest P_max
//! along the path, `failed_fraction = ⟨Σ_{p0 > P_crit} F_z⟩/W` (the path-averaged fraction of
//! the load carried by failed contacts), the mean contact number, K, and the path used.
//!
//! ## What it leaves out
//! The slider's inertia: the Prandtl–Tomlinson slips are overdamped (the slider stops in the next
//! well) and the coating term is steady kinetic sliding, whereas the DEM slider's slips are
//! underdamped (damped only through the control layer and the contacts) and run several µm past
//! the next well, so in stick-slip (η ≫ 1, or pinned failed contacts on a flat substrate) the DEM's
//! mean friction is 0.35–0.5 of μ_est (measured on 15 DEM runs, `surrogate/README.md`): μ_est is
//! then an upper bound, exact in steady sliding. Also velocity-dependent (viscous) forces,
//! thermal activation, the slider's freedom to drift sideways
//! off the path (a 1-D model along e), the coupling of Coulomb friction and corrugation in the
//! jumps (the two terms are added), lock-in of commensurate interfaces under high load (the
//! model always slides, with a large μ_PT), and the lateral compliance of the spheres in the
//! contact geometry (contacts of the rigid slider only: the DEM closes some near-contacts at
//! incommensurate angles).

mod estimate;
mod params;
mod path;
mod tomlinson;

pub use estimate::{estimate_friction, estimate_friction_loads, FrictionEstimate};
pub use params::FrictionParams;
pub use path::lattice_period;
