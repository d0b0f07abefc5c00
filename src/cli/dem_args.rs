//! Flags shared by `superlube equilibrate` and `superlube slide` (the DEM tier), turned into a
//! scene and [`DemParams`], and the writing of their outputs.

pub use super::contact_args::ContactArgs;
pub use super::model_args::{ModelArg, ModelArgs};
use super::point_args::{self, default, help, Alphas, Loads, Thetas, ALPHA, LOAD, THETA};
use super::protocol_args::ProtocolArgs;
pub use super::start_args::StartArgs;
use super::{checks, SceneArgs};
use crate::runs::sink::csv_bytes;
use crate::runs::{meta::scene_file, meta::Inputs, output::check_outputs, output::Outputs};
use crate::study::dem_run::{DemOutcome, DemParams};
use crate::study::record;
use anyhow::{bail, Result};
use dem::protocol::RunIo;
use dem::SimParams;
use serde::Serialize;
use std::path::PathBuf;

use super::scene_args::Resolved;

/// `--theta-deg` (`None`: the scene's), `--alpha-deg` (degrees) and `--load-mn` (mN) values.
pub type Lists = (Vec<Option<f64>>, Vec<f64>, Vec<f64>);

/// DEM options shared by `equilibrate` and `slide`.
#[derive(clap::Args, Debug)]
#[command(
    mut_args(help(
        THETA,
        "Slider orientation θ in degrees [default: the scene file's theta_deg, else 0]. \
         `slide` also takes a list `0,21.8,30` or a range `0:30:10` (a batch, see `--out-dir`)"
    )),
    mut_args(help(
        LOAD,
        "Normal load W in mN (> 0). `slide` also takes a list `0.35,1.4` or a range \
         `0.35:3.5:0.35` (a batch, see `--out-dir`)"
    )),
    mut_args(default(LOAD, "1.4")),
    mut_args(help(
        ALPHA,
        "Pulling angle α in degrees from the slider's contact line (as in `superlube \
         corrugation`), |α| ≤ 180: α = 90 pulls perpendicular to the contact lines. The \
         pulling direction from the substrate x axis is line + α; both are printed and \
         reported in the JSON summary. `slide` also takes a list `0,90` or a range (a batch, \
         see `--out-dir`)"
    ))
)]
pub struct DemArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// `--theta-deg`: θ, a list or range (degrees).
    #[command(flatten)]
    pub theta: Thetas,
    /// `--load-mn`: loads, a list or range (mN).
    #[command(flatten)]
    pub load: Loads,
    /// `--alpha-deg`: α, a list or range (degrees).
    #[command(flatten)]
    pub alpha: Alphas,
    /// Contact-line angle in degrees from the substrate x axis. Default: the moiré estimate of
    /// `superlube corrugation` (square-tri at θ = 0: along x, 0°; the substrate row a1 when the
    /// lattices are commensurate).
    #[arg(long = "line-deg", value_name = "DEG", allow_hyphen_values = true)]
    pub line_deg: Option<f64>,
    /// Equilibration time under load in µs (control layer held laterally; > 0).
    #[arg(
        long = "equilibrate-us",
        value_name = "US",
        default_value_t = 10.0,
        allow_hyphen_values = true
    )]
    pub equilibrate_us: f64,
    /// Time step in µs (> 0) [default: 0.25 × the estimated stable step, printed at start].
    #[arg(long = "dt-us", value_name = "US", allow_hyphen_values = true)]
    pub dt_us: Option<f64>,
    #[command(flatten)]
    pub start: StartArgs,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub contact: ContactArgs,
    /// Sampling interval of the time series in µs (> 0). Each row's `p_max_peak_GPa` and the
    /// `slide` summary's `max_p_max_GPa` cover every step between rows, so a finer interval is not
    /// needed to catch pressure peaks.
    #[arg(
        long = "sample-us",
        value_name = "US",
        default_value_t = 0.1,
        allow_hyphen_values = true
    )]
    pub sample_us: f64,
    /// Time-series CSV `t_us,support_x_um,spring_force_mN,z_um,contacts,p_max_GPa,
    /// failed_contacts,p_max_peak_GPa` (the last: the largest p0 at any step since the previous
    /// row) (written atomically, with a sidecar FILE.csv.meta.json); stdout if
    /// absent.
    #[arg(long, value_name = "FILE.csv")]
    pub out: Option<PathBuf>,
    /// JSON summary file (written atomically, with a sidecar); printed to stdout if absent and
    /// `--out` is given, to stderr if both are absent.
    #[arg(long, value_name = "FILE.json")]
    pub json: Option<PathBuf>,
    /// Checkpoint file, written atomically every `--checkpoint-every` steps.
    #[arg(long, value_name = "FILE")]
    pub checkpoint: Option<PathBuf>,
    /// Steps between checkpoints (≥ 1).
    #[arg(
        long = "checkpoint-every",
        value_name = "STEPS",
        default_value_t = 100_000,
        allow_negative_numbers = true
    )]
    pub checkpoint_every: u64,
    /// Continue from `--checkpoint` if it exists (same inputs required; bit-identical result).
    #[arg(long, requires = "checkpoint")]
    pub resume: bool,
    /// Extended-XYZ snapshot file (OVITO reads it); one frame every `--xyz-every` steps.
    #[arg(long, value_name = "FILE.xyz")]
    pub xyz: Option<PathBuf>,
    /// Steps between snapshots (≥ 1).
    #[arg(
        long = "xyz-every",
        value_name = "STEPS",
        default_value_t = 10_000,
        allow_negative_numbers = true
    )]
    pub xyz_every: u64,
}

impl DemArgs {
    /// The values of `--theta-deg` (`None`: the scene's), `--alpha-deg` (degrees) and `--load-mn`
    /// (mN) as lists (one value each for a single run); errors name the flag.
    pub fn lists(&self) -> Result<Lists> {
        let thetas = match self.theta.degrees()? {
            None => vec![None],
            Some(t) => t.into_iter().map(Some).collect(),
        };
        let alphas = self.alpha.degrees()?;
        let loads = self.load.mn()?;
        Ok((thetas, alphas, loads))
    }

    /// The validated scene (θ applied) and the run parameters of a single run with the sliding
    /// `protocol` ([`ProtocolArgs::AT_REST`] for equilibrate). Every flag is checked here, and
    /// every output path, before any work. A list in `--theta-deg`, `--alpha-deg` or `--load-mn` is
    /// refused (naming the flag): only `slide --out-dir` runs batches.
    pub fn setup(&self, protocol: &ProtocolArgs) -> Result<(Resolved, DemParams)> {
        let (thetas, alphas, loads) = self.lists()?;
        for (n, flag) in [
            (thetas.len(), "--theta-deg"),
            (alphas.len(), "--alpha-deg"),
            (loads.len(), "--load-mn"),
        ] {
            if n != 1 {
                bail!("`{flag}`: {n} values given; this command runs one configuration (`superlube slide --out-dir DIR` runs lists as a batch)");
            }
        }
        let sc = self.scene.resolve(thetas[0])?;
        let p = self.params(alphas[0], loads[0], protocol)?;
        if protocol.slide_us > 0.0 {
            self.check_line(&sc.scene)?;
        }
        check_outputs(&[
            ("--out", self.out.as_deref()),
            ("--json", self.json.as_deref()),
            ("--checkpoint", self.checkpoint.as_deref()),
            ("--xyz", self.xyz.as_deref()),
        ])?;
        Ok((sc, p))
    }

    /// Refuses a site-file scene without `--line-deg` ([`checks::line_for`]): α is measured
    /// from the contact line.
    pub fn check_line(&self, scene: &surrogate::Scene) -> Result<()> {
        checks::line_for(scene, checks::line_deg(self.line_deg)?)
    }

    /// The run parameters at pulling angle `alpha_deg` (degrees) and load `load_mn` (mN) with
    /// the sliding `protocol`, from every other flag (checked, naming the flag); output paths
    /// are not checked here.
    pub fn params(
        &self,
        alpha_deg: f64,
        load_mn: f64,
        protocol: &ProtocolArgs,
    ) -> Result<DemParams> {
        let load = point_args::load(load_mn)?;
        let alpha = point_args::alpha(alpha_deg)?;
        let line = checks::line_deg(self.line_deg)?;
        let equilibrate = checks::time_us(self.equilibrate_us, "--equilibrate-us")?;
        let sample = checks::time_us(self.sample_us, "--sample-us")?;
        let dt = self
            .dt_us
            .map(|dt| checks::time_us(dt, "--dt-us"))
            .transpose()?;
        let friction = self.contact.friction()?;
        let start = self.start.start()?;
        checks::every(self.checkpoint_every, "--checkpoint-every", "checkpoint")?;
        checks::every(self.xyz_every, "--xyz-every", "snapshot")?;
        let mut sim = SimParams {
            protocol: dem::ProtocolParams {
                load,
                equilibrate_time: equilibrate,
                sample_interval: sample,
                ..Default::default()
            },
            contact: self.contact.params(),
            numerics: dem::NumericsParams {
                dt,
                ..Default::default()
            },
            ..SimParams::default()
        };
        protocol.apply(&mut sim.protocol);
        let params = DemParams {
            sim,
            alpha,
            line,
            start,
            friction,
            io: RunIo {
                checkpoint: self.checkpoint.clone(),
                checkpoint_every: self.checkpoint_every,
                xyz: self.xyz.clone(),
                xyz_every: self.xyz_every,
            },
            resume: if self.resume {
                self.checkpoint.clone()
            } else {
                None
            },
            model: self.model.spec(),
        };
        Ok(params)
    }

    /// The outputs of a run of `workflow`.
    pub fn outputs(&self, workflow: &str, sc: &Resolved, p: &DemParams) -> Outputs {
        Outputs::new(
            Inputs {
                workflow: workflow.into(),
                scene: Some(scene_file(&sc.scene)),
                params: record::dem(&sc.scene, p),
            },
            sc.warnings.clone(),
        )
    }

    /// Writes the time series (whatever happened: everything sampled is kept), the summary
    /// (`--json`, else stdout when the series went to `--out`, else stderr) and the snapshot
    /// file's sidecar; then reports every failed output, or the run's own error.
    pub fn write<T: Serialize>(
        &self,
        mut outs: Outputs,
        out: DemOutcome,
        summary: Option<&T>,
    ) -> Result<()> {
        outs.write(
            "--out",
            self.out.as_deref(),
            csv_bytes(&out.samples),
            Some(out.samples.len() as u64),
        );
        if let Some(s) = summary {
            let text = serde_json::to_string_pretty(s).map(|t| t + "\n");
            match (&self.json, &self.out) {
                (Some(p), _) => outs.write(
                    "--json",
                    Some(p),
                    text.map(String::into_bytes).map_err(Into::into),
                    None,
                ),
                (None, Some(_)) => outs.write(
                    "--json",
                    None,
                    text.map(String::into_bytes).map_err(Into::into),
                    None,
                ),
                (None, None) => eprint!("{}", text.unwrap_or_default()),
            }
        }
        if let Some(x) = &self.xyz {
            if x.exists() {
                outs.sidecar("--xyz", x, None);
            }
        }
        let written = outs.finish();
        if let Some(e) = out.error {
            return Err(anyhow::Error::new(e).context(match written {
                Ok(()) => "the run stopped early (the time series up to the failure was written)"
                    .to_string(),
                Err(w) => format!("the run stopped early; also: {w:#}"),
            }));
        }
        written
    }
}
