//! # LAMMPS export of the Tier 3 (DEM) model (`superlube export-lammps`)
//!
//! Writes the study's dynamic model — the same [`Scene`] (sites, order, θ, offset, σ_h
//! heights, mount) and [`SimParams`] (stiffnesses, damping, load, K0, protocol) the Rust engine
//! runs — as a LAMMPS data file and input deck for stock LAMMPS (packages GRANULAR, MOLECULE,
//! RIGID), so one large run can go to a cluster's MPI LAMMPS. One source of truth: the particle
//! layout comes from [`crate::prepare`] (the Rust engine's own start state, including the
//! surrogate's start height and its time step), and every number in the deck is computed here.
//!
//! Pipeline ([`export_lammps`]): validate → prepare (Rust start state, dt) → [`layout()`] (atoms,
//! bonds, halves) → [`data_file`] + [`deck`] + README + [`meta`] → [`LammpsExport::write`].
//! The reverse direction, reading the deck's contact dump back ([`dump`]) and checking it
//! against the coating strength ([`check`]), is `superlube lammps-check`.
//!
//! What stock LAMMPS cannot express, and how the export deviates (details in
//! `dem/lammps/README.md`): one constant μ for every contact (no switch to μ2 at P_crit);
//! the anisotropic slider ties as two harmonic bonds (exact to first order); the control layer as
//! a LAMMPS rigid body of two sub-layers of spheres (the Rust engine's control layer is a point
//! body; the same translational dynamics, its own rotational inertia).

pub mod check;
mod context;
pub mod damping;
pub mod data_file;
pub mod deck;
pub mod deck_sizes;
pub mod dump;
pub mod layout;
pub mod meta;
pub mod micro;
pub mod options;
mod validate;

pub use check::{check_dump, CheckSummary, FailedContact, FrameReport};
pub use deck::files;
pub use layout::{layout, Layout};
pub use meta::ExportMeta;
pub use options::ExportOptions;

use crate::protocol::{step_counts, RunKind};
use crate::{DemError, SimParams, Start};
use context::Context;
use deck::DeckInputs;
use std::path::{Path, PathBuf};
use surrogate::Scene;

/// The rendered export: file contents and metadata.
#[derive(Debug, Clone)]
pub struct LammpsExport {
    /// The data file (`scene.data`).
    pub data: String,
    /// The input deck (`in.superlube.lmp`).
    pub deck: String,
    /// The directory's README (`README.md`).
    pub readme: String,
    /// The metadata (`export.json`).
    pub meta: ExportMeta,
}

/// Exports `scene` (at its own θ and offset) with the knobs `params` (load, α = pulling
/// direction from x, protocol times, dt or its safety factor, damping, stiffnesses) and the
/// constant μ and dump interval of `opts`. Errors name the bad field (user units) before any
/// work; `rigid_z` cannot be exported (LAMMPS has no per-axis rigid coupling of free spheres).
/// Pipeline: validate → [`crate::prepare`] → [`layout()`] → header, deck inputs (one part of the
/// deck per part of [`SimParams`]) → deck, data file, `export.json`, README.
/// Cost: one surrogate solve and O(N) text.
pub fn export_lammps(
    scene: &Scene,
    params: &SimParams,
    opts: &ExportOptions,
) -> Result<LammpsExport, DemError> {
    let damping = validate::validate(scene, params, opts)?;
    let friction = crate::model::Friction::Constant(crate::model::Constant { mu: opts.mu });
    let prep = crate::prepare(scene, params.clone(), Start::Surrogate, Some(friction))?;
    let sim = &prep.sim;
    let lay = layout::layout(
        &sim.spec,
        &scene.slider_sites_local(),
        &sim.params,
        opts.tie_length,
    );
    let cx = Context {
        scene,
        prep: &prep,
        lay: &lay,
        opts,
        steps: steps(sim, opts),
    };
    let mut header = cx.header();
    let sizes = cx.sizes(&mut header);
    let inputs = cx.deck_inputs(damping, header, sizes);
    let deck = deck::render(&inputs);
    let data = data_file::render(&lay, &cx.title());
    let meta = cx.meta();
    let readme = readme(&meta, &inputs);
    Ok(LammpsExport {
        data,
        deck,
        readme,
        meta,
    })
}

/// The protocol's step counts of `sim` and the dump interval of `opts` in steps.
fn steps(sim: &crate::Sim, opts: &ExportOptions) -> meta::Steps {
    let (ne, nr, ns, every) = step_counts(sim, RunKind::Slide);
    let dump_every = if opts.dump_interval > 0.0 {
        ((opts.dump_interval / sim.dt).round() as u64).max(1)
    } else {
        0
    };
    meta::Steps {
        equilibrate: ne,
        relax: nr,
        slide: ns,
        sample_every: every,
        dump_every,
    }
}

fn readme(m: &ExportMeta, d: &DeckInputs) -> String {
    let st = &m.steps;
    format!(
        "# LAMMPS export of a superlube Tier 3 (DEM) run\n\n\
Made by `{cmd}`. Scene {pattern}, θ = {theta}°, mount {mount}, W = {load} mN, pulling direction \
{dir}° from x; {atoms} LAMMPS atoms; dt = {dt} µs; {total} steps (equilibrate {ne}, relax {nr}, \
slide {ns}).\n\n\
| file | what |\n|---|---|\n\
| `{data}` | atoms (substrate, slider, two control sub-layers, support) and the slider ties as bonds |\n\
| `{deck}` | the model and protocol; every knob computed by superlube (header: deviations) |\n\
| `{meta}` | what `superlube lammps-check` needs (material, P_crit, IDs, steps) |\n\n\
Run it (stock LAMMPS with GRANULAR, MOLECULE and RIGID, e.g. Debian's `lammps`):\n\n\
```\n\
lmp -in {deck} -var nsteps 0        # check: set up and compute the forces, no steps\n\
lmp -in {deck}                      # serial\n\
mpirun -np 32 lmp -in {deck}        # MPI on a cluster (any rank count)\n\
```\n\n\
On a Slurm cluster: `srun lmp -in {deck}` inside a job with the ranks you want; shorten with \
`-var nsteps N`. Outputs (working directory): `{ts}` (`{head}`, every {every} steps), `{dump}` \
(slider–substrate pairs in contact, every {de} steps), `log.lammps` (`RESULT` lines after each \
phase and `RESULT friction_mN=…`, the mean spring force over the last {win} sliding steps).\n\n\
**Constant μ = {mu}.** Stock LAMMPS cannot switch the friction coefficient of a contact when its \
Hertz pressure passes P_crit = {pc} GPa (the coating: μ1 = {mu1} below, μ2 = {mu2} above). The run \
is the study's model only while no contact exceeds P_crit. Check:\n\n\
```\n\
superlube lammps-check {dump} --out contacts_check.csv\n\
```\n\n\
lists, per dump frame, the contacts, P_max and the contacts above P_crit, and says where the \
constant-μ run is not valid. Other deviations: see the deck's header and `dem/lammps/README.md`.\n",
        cmd = if m.command.is_empty() { "superlube export-lammps" } else { &m.command },
        pattern = m.pattern,
        theta = m.theta_deg,
        mount = m.mount,
        load = m.load_mn,
        dir = m.direction_deg,
        atoms = m.atoms,
        dt = m.dt_us,
        total = st.total(),
        ne = st.equilibrate,
        nr = st.relax,
        ns = st.slide,
        data = files::DATA,
        deck = files::DECK,
        meta = files::META,
        ts = files::TIMESERIES,
        head = deck::TIMESERIES_HEADER,
        every = st.sample_every,
        dump = files::DUMP,
        de = st.dump_every,
        win = st.slide - d.drive.window_start.min(st.slide),
        mu = m.mu,
        pc = m.p_crit_gpa,
        mu1 = m.mu1,
        mu2 = m.mu2,
    )
}

impl LammpsExport {
    /// Writes the four files into `dir` (created if missing), each atomically; returns their
    /// paths. Refuses a `dir` that exists and is not a directory.
    pub fn write(&self, dir: &Path) -> std::io::Result<Vec<PathBuf>> {
        if dir.exists() && !dir.is_dir() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::AlreadyExists,
                format!("{} exists and is not a directory", dir.display()),
            ));
        }
        std::fs::create_dir_all(dir)?;
        let meta = serde_json::to_string_pretty(&self.meta)
            .map_err(|e| std::io::Error::other(e.to_string()))?
            + "\n";
        let mut out = Vec::new();
        for (name, text) in [
            (files::DATA, self.data.as_str()),
            (files::DECK, self.deck.as_str()),
            (files::README, self.readme.as_str()),
            (files::META, meta.as_str()),
        ] {
            let p = dir.join(name);
            surrogate::atomic_file::write_atomic(&p, text.as_bytes())?;
            out.push(p);
        }
        Ok(out)
    }
}
