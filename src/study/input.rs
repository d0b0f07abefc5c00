//! The workflows' inputs, as the messages of `src/study` name them. A workflow names no flag:
//! a message that points the user at an input writes its [`Input`], which prints as the input's
//! keyword in single guillemets (`‹theta›`, the Python package's keyword), a mark that no field
//! name or file text uses; the command line turns each into its flag when it prints an error
//! or a log line, and the design report in the notes it quotes
//! ([`crate::present::inputs`]).

use std::fmt;

/// An input a workflow's message may name (refusals, hints, log notes).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Input {
    /// The slider orientations θ (degrees).
    Theta,
    /// The pulling angles α (degrees from the contact line).
    Alpha,
    /// The normal loads W (mN).
    LoadMn,
    /// The contact-line angle (degrees from the substrate x axis).
    LineDeg,
    /// The landscape grid size.
    Grid,
    /// The corrugation path length (µm).
    DistanceUm,
    /// The corrugation path step (µm).
    StepUm,
    /// The θ step of the figures (degrees).
    ThetaStepDeg,
    /// The surrogate's load-sharing model.
    Solver,
    /// The output directory.
    OutDir,
    /// A shard `I/N` of a sweep or of the DEM runs.
    Shard,
    /// Resuming an interrupted sweep.
    Resume,
    /// A lattice family of `patterns` / `design`.
    Family,
    /// An index.csv of `patterns` given to `design`.
    Patterns,
    /// The largest p, q of a commensurate ratio.
    MaxPq,
    /// Screening θ without the symmetry cut.
    NoSymmetryCut,
    /// The slider mount (locked, free, springs).
    Tilt,
}

impl Input {
    /// Every input, for the command line's table of flags.
    pub const ALL: [Input; 17] = [
        Input::Theta,
        Input::Alpha,
        Input::LoadMn,
        Input::LineDeg,
        Input::Grid,
        Input::DistanceUm,
        Input::StepUm,
        Input::ThetaStepDeg,
        Input::Solver,
        Input::OutDir,
        Input::Shard,
        Input::Resume,
        Input::Family,
        Input::Patterns,
        Input::MaxPq,
        Input::NoSymmetryCut,
        Input::Tilt,
    ];

    /// The input's keyword (snake case, as the Python package spells it).
    pub fn keyword(self) -> &'static str {
        match self {
            Input::Theta => "theta_deg",
            Input::Alpha => "alpha_deg",
            Input::LoadMn => "load_mn",
            Input::LineDeg => "line_deg",
            Input::Grid => "grid",
            Input::DistanceUm => "distance_um",
            Input::StepUm => "step_um",
            Input::ThetaStepDeg => "theta_step_deg",
            Input::Solver => "solver",
            Input::OutDir => "out_dir",
            Input::Shard => "shard",
            Input::Resume => "resume",
            Input::Family => "family",
            Input::Patterns => "patterns",
            Input::MaxPq => "max_pq",
            Input::NoSymmetryCut => "no_symmetry_cut",
            Input::Tilt => "tilt",
        }
    }
}

impl fmt::Display for Input {
    /// `‹keyword›` (see the module doc).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "‹{}›", self.keyword())
    }
}
