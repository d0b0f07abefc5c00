//! [`ModelArgs`]: which DEM model runs (`--model`, `--rigid-z`, `--prune`, `--no-active-set`),
//! the CLI's side of the mount and active-set parts of [`dem::SimParams`] (the engine decides
//! them per run from this request, [`dem::choose_model`]).

use crate::study::dem_run::ModelSpec;

/// Which DEM model (`--model`).
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModelArg {
    /// The cheapest model within its measured error for this scene (reason printed).
    Auto,
    /// Slider spheres on their k_z springs; the linear mount network (k_z springs, control
    /// layer Z and tilts, mount springs) integrated implicitly, the contacts explicitly: the
    /// step is set by the contacts (docs/validation/dem-integrator.md).
    Full,
    /// The full model with velocity-Verlet on everything (step set by the k_z springs): the
    /// reference for `full`.
    FullExplicit,
    /// Rigid-z: slider spheres rigid in z on the control layer.
    Reduced,
}

impl ModelArg {
    /// The engine's request.
    pub fn request(self) -> dem::ModelRequest {
        match self {
            ModelArg::Auto => dem::ModelRequest::Auto,
            ModelArg::Full => dem::ModelRequest::Full,
            ModelArg::FullExplicit => dem::ModelRequest::FullExplicit,
            ModelArg::Reduced => dem::ModelRequest::Reduced,
        }
    }
}

/// The DEM model flags of `equilibrate` and `slide`.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct ModelArgs {
    /// Model: `auto` picks rigid-z where its measured error is small for this scene and keeps
    /// the full model near coating failure, where stick-slip is expected and beyond the measured
    /// stiffness ratio (the choice and its reason are printed and in the JSON); `full` integrates
    /// the stiff mount springs implicitly (step set by the contacts), `full-explicit` is the same
    /// model by velocity-Verlet throughout (many more steps), for reference; pruning and the
    /// active set are exact and on in every model.
    #[arg(long, value_enum, default_value_t = ModelArg::Auto)]
    pub model: ModelArg,
    /// Reduction: slider spheres move rigidly with the control layer in z (replaces the stiff
    /// 10⁶ N/m z-springs; allows a larger time step). Same as `--model reduced`.
    #[arg(long = "rigid-z")]
    pub rigid_z: bool,
    /// Leave out substrate spheres that the slider can never touch along its path (exact; on in
    /// every `--model`, kept for compatibility).
    #[arg(long)]
    pub prune: bool,
    /// Integrate every particle every step instead of only the active set (the active set is
    /// exact to round-off; this is for comparisons and timing).
    #[arg(long = "no-active-set")]
    pub no_active_set: bool,
}

impl ModelArgs {
    /// The model asked for (`--prune` is on in every model and changes nothing).
    pub fn spec(&self) -> ModelSpec {
        ModelSpec {
            request: self.model.request(),
            force_rigid_z: self.rigid_z,
            active_set: !self.no_active_set,
        }
    }
}
