//! Surrogate friction estimate: the friction coefficient the DEM protocol measures, estimated
//! from the quasi-static path of the rigid slider and a one-dimensional dynamics along it.
//!
//! For a scene (with its slider mount), a rotation θ, a pulling direction e (unit vector in the
//! substrate plane, angle φ from the x axis) and a load W, [`estimate_friction`] solves the
//! equilibrium ([`crate::solver::Model::Auto`]) at samples `s_k = k·h` of a straight path
//! `shift = y₀·e⊥ + s·e` parallel to the pull, from the scene's placement (y₀ = 0) or, where the
//! slider drifts off a crest of the landscape across the pull, from the lowest groove beside it
//! (see "The start across the pull"). From the samples it builds the quasi-static
//! (overdamped) estimate
//!
//! ```text
//! μ_qs = μ_coat + μ_PT
//! ```
//!
//! and the estimate itself, `μ_est`, the mean spring force of the same slider with its mass
//! (see "Inertial model" below): `μ_est = μ_qs` where the path cannot stick-slip (η ≤ 1: steady
//! sliding, where μ_qs is the exact dissipation per unit length), else the inertial model's
//! value, lower than μ_qs because the underdamped slips run past the next well.
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
//! ## Inertial model (the estimate where η > 1)
//! The slider's centre of mass along e, mass M = N·(m_sphere + m_control) (the DEM's slider and
//! control-layer spheres), pulled by the spring K from a support moving at the DEM's speed v:
//!
//! ```text
//! M ü = K (X₀ + v t − x) − V'(x) − γ (u − v) − C(x) sgn(u)
//! ```
//!
//! with V' = F_pull and `C(x) = Σ μ(p0_i) F_n,i |e_t,i|` (the coating term's integrand) linear
//! between samples, γ = N·m_control/τ the DEM's damping of the control layer relative to the
//! support (τ = 1 µs; the slider spheres are damped relative to the control layer, so this is
//! all that damps the centre of mass: damping ratio ≈ 0.03 on the study's slider), and Coulomb
//! sticking (u = 0 while the drive stays within ±C). Each run starts in steady sliding and
//! returns the mean spring force over the DEM's window (100–300 µs of a 300 µs slide at
//! 0.1 m/s); the stick-slip is chaotic, so `starts` runs (8) begin evenly spread along the
//! path and `μ_est` is their mean / W, `mu_est_spread` their standard deviation / W (what one
//! DEM run of the same length scatters by). On a flat profile a run is exactly steady sliding
//! (μ_est = C/W). Integration: symplectic Euler, step ≤ 0.05/ω_max and ≤ half a sample per
//! step, stuck phases skipped in closed form (`inertial.rs`); ≈ 1.5 ms per run.
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
//! varies on the 1.5–3 µm scale of the lattices (measured convergence:
//! `docs/validation/friction.md`, "Measured", "Error of the defaults").
//!
//! ## The start across the pull
//! The DEM's pulling spring holds the slider across the pull with only K0 = 50 N/m. Where the
//! placement is a crest of the landscape across the pull (square-tri near θ = 0: grooves 1.5 µm
//! apart and 60–85 nm deep along the substrate rows) and the path is not a mirror line of the
//! scene, the slider drifts into the groove while it slides (`dy/ds = F_⊥/C`, C the coating's
//! Coulomb force) and the DEM slides, or fails and locks in, there. `transverse.rs` integrates
//! that drift over the DEM's sliding distance, linearised about the crest, and starts the path at
//! the lowest `V + ½K0y²` on the side it leaves to (`transverse_offset`; ±1.5 µm
//! searched, `FrictionParams::transverse`). The placement's P_max still counts in `p_max_max`
//! (the DEM's slide starts there).
//!
//! ## Reported alongside
//! η, the barrier `U0 = max V − min V`, the largest lateral force, the mean and largest P_max
//! along the path, `failed_fraction = ⟨Σ_{p0 > P_crit} F_z⟩/W` (the path-averaged fraction of
//! the load carried by failed contacts), the mean contact number, K, and the path used.
//!
//! ## What it leaves out
//! The slider's vertical and tilt dynamics: the path is solved at static equilibrium, so the
//! coating force C(x) of a fast slip is that of the static path. Where the coating fails on a flat
//! substrate (tri-tri 30° above 2.1 mN) and the spring mount's tilt mode is tuned to the lateral
//! mode of the stuck contact pairs ([`TiltResonance`]: ω_t/ω_p in [`RESONANCE_BAND`]; the study's
//! mount is at 0.89), the DEM's tilt rocks the failed contacts during slips (their count changes 16
//! → 4 within a slip, the slider 0.5 nm higher) and its mean friction is 0.36–0.47 of μ_est
//! (reduced model; 0.43 with the full model at 2.45 mN). Off the resonance (K1 ≤ 4·10⁵ or ≥ 2·10⁶
//! N/m, or a locked or free mount) μ_est is within 0.96–1.46 of the DEM on the same runs (measured,
//! `docs/validation/friction.md`, "The mount's resonance"). Substrate roughness detunes it (σ_h ≥ 5 nm:
//! 0.85–0.92 of the off-resonance friction, [`roughness_detunes`]). `FrictionEstimate::mount_resonance`
//! flags the rows where μ_est may be such an upper bound. Also
//! thermal activation, the slider's wandering across the pull along the path (only the drift off
//! the placement's crest is modelled: the path is then straight again, and the DEM's slider
//! wanders ±0.3–0.7 µm across it on tri-tri 21.8° and 26°), the coupling of Coulomb friction and corrugation in the
//! jumps (the two terms are added), lock-in of commensurate interfaces under high load (the
//! model always slides, with a large μ_PT), and the lateral compliance of the spheres in the
//! contact geometry (contacts of the rigid slider only: the DEM closes some near-contacts at
//! incommensurate angles).

mod estimate;
mod inertial;
mod params;
mod path;
mod resonance;
mod tomlinson;
mod transverse;

pub use estimate::{estimate_friction, estimate_friction_loads, FrictionEstimate};
pub use params::FrictionParams;
pub use path::lattice_period;
pub use resonance::{
    critical_overlap, roughness_detunes, TiltResonance, DETUNING_OVERLAP_FRACTION,
    DETUNING_SIGMA_H, RESONANCE_BAND, RESONANCE_DROP_MAX,
};
