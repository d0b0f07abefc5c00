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
pub mod damping;
pub mod data_file;
pub mod deck;
pub mod deck_sizes;
pub mod dump;
pub mod layout;
pub mod meta;
pub mod micro;
pub mod options;

pub use check::{check_dump, CheckSummary, FailedContact, FrameReport};
pub use deck::files;
pub use layout::{layout, Layout};
pub use meta::ExportMeta;
pub use options::ExportOptions;

use crate::protocol::{step_counts, RunKind};
use crate::{DemError, SimParams, Start};
use deck::{DeckInputs, DeckMount, DeckPair, DeckViscous};
use std::path::{Path, PathBuf};
use surrogate::{Mount, Scene};

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

fn check_nonneg(v: f64, field: &str, unit_scale: f64) -> Result<(), DemError> {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        Err(DemError::invalid(
            field,
            v * unit_scale,
            "must be a non-negative number",
        ))
    }
}

/// Exports `scene` (at its own θ and offset) with the knobs `params` (load, α = pulling
/// direction from x, protocol times, dt or its safety factor, damping, stiffnesses) and the
/// constant μ and dump interval of `opts`. Errors name the bad field (user units) before any
/// work; `rigid_z` cannot be exported (LAMMPS has no per-axis rigid coupling of free spheres).
/// Cost: one surrogate solve and O(N) text.
pub fn export_lammps(
    scene: &Scene,
    params: &SimParams,
    opts: &ExportOptions,
) -> Result<LammpsExport, DemError> {
    scene.validate()?;
    if params.mount.rigid_z {
        return Err(DemError::invalid(
            "rigid_z",
            true,
            "the rigid-z reduction has no LAMMPS equivalent; export the full model",
        ));
    }
    if !(opts.mu.is_finite() && opts.mu >= 0.0) {
        return Err(DemError::invalid(
            "mu",
            opts.mu,
            "must be a non-negative number",
        ));
    }
    check_nonneg(opts.dump_interval, "dump_us", 1e6)?;
    if !(opts.tie_length.is_finite() && opts.tie_length > 0.0) {
        return Err(DemError::invalid(
            "tie_length_um",
            opts.tie_length * 1e6,
            "must be positive",
        ));
    }
    for (v, f) in [
        (params.protocol.equilibrate_time, "equilibrate_us"),
        (params.protocol.relax_time, "relax_us"),
        (params.protocol.slide_time, "slide_us"),
        (params.protocol.support_speed, "speed_m_s"),
    ] {
        let scale = if f == "speed_m_s" { 1.0 } else { 1e6 };
        check_nonneg(v, f, scale)?;
    }
    if !(params.protocol.sample_interval.is_finite() && params.protocol.sample_interval > 0.0) {
        return Err(DemError::invalid(
            "sample_us",
            params.protocol.sample_interval * 1e6,
            "must be positive",
        ));
    }
    if !(params.mount.k_slider_z >= params.mount.k_slider_xy && params.mount.k_slider_xy >= 0.0) {
        return Err(DemError::invalid(
            "k_slider_z",
            params.mount.k_slider_z,
            "the bond split needs k_slider_z ≥ k_slider_xy ≥ 0 (N/m)",
        ));
    }
    let (m_sl, m_sb) = (scene.slider_material(), scene.substrate_material());
    let damping = if m_sl == m_sb {
        damping::lammps_damping(params.contact.gamma_n, params.contact.gamma_t, m_sl.poisson)?
    } else {
        let ratio = 6.0 * m_sl.g_star_with(&m_sb) / m_sl.e_star_with(&m_sb);
        damping::lammps_damping_ratio(params.contact.gamma_n, params.contact.gamma_t, ratio)?
    };
    let friction = crate::model::Friction::Constant(crate::model::Constant { mu: opts.mu });
    let prep = crate::prepare(scene, params.clone(), Start::Surrogate, Some(friction))?;
    let sim = &prep.sim;
    let p = &sim.params;
    let (ne, nr, ns, every) = step_counts(sim, RunKind::Slide);
    let dump_every = if opts.dump_interval > 0.0 {
        ((opts.dump_interval / sim.dt).round() as u64).max(1)
    } else {
        0
    };
    let steps = meta::Steps {
        equilibrate: ne,
        relax: nr,
        slide: ns,
        sample_every: every,
        dump_every,
    };
    let lay = layout::layout(&sim.spec, &scene.slider_sites_local(), p, opts.tie_length);
    let hertz = scene.hertz();
    let m_s = sim.spec.slider_sphere_mass();
    let m_b = sim.spec.substrate_sphere_mass();
    let m_c = 0.5 * m_sl.sphere_mass(p.mount.control_sphere_radius);
    let viscous =
        (p.numerics.damping_time.is_finite() && p.numerics.damping_time > 0.0).then(|| {
            DeckViscous {
                gamma_sphere: micro::drag(m_s / p.numerics.damping_time),
                control_ratio: m_c / m_s,
                substrate_ratio: (m_b != m_s).then(|| m_b / m_s),
                relative: p.numerics.damping_frame == crate::DampingFrame::Relative,
            }
        });
    let mount = match scene.slider.mount {
        Mount::Locked => DeckMount::Locked,
        Mount::Free => DeckMount::Free,
        Mount::Springs { k1 } => DeckMount::Springs {
            k1: micro::stiffness(k1),
        },
    };
    let n = sim.spec.slider_sites.len();
    let (sa, ca) = p.protocol.alpha.sin_cos();
    let (st, ct) = scene.slider.theta.sin_cos();
    let um = 1e6;
    let mount_text = match scene.slider.mount {
        Mount::Springs { k1 } => format!("springs, K1 = {k1} N/m"),
        m => m.name().to_string(),
    };
    let direction = match opts.alpha_and_line {
        Some((a, l)) => format!(
            "{}° from x = contact line {}° + alpha {}°",
            p.protocol.alpha.to_degrees(),
            l.to_degrees(),
            a.to_degrees()
        ),
        None => format!("{}° from x", p.protocol.alpha.to_degrees()),
    };
    let mut header = vec![
        "superlube Tier 3 (DEM) model for stock LAMMPS (packages GRANULAR, MOLECULE, RIGID)".to_string(),
        format!("generated by: {}", if opts.command.is_empty() { "superlube export-lammps" } else { &opts.command }),
        format!(
            "scene: {}, theta = {}°, offset = [{}, {}] um, sigma_h = {} um (seed {}), mount {}",
            scene.pattern,
            scene.slider.theta.to_degrees(),
            scene.slider.offset[0] * um,
            scene.slider.offset[1] * um,
            scene.substrate.sigma_h * um,
            scene.substrate.seed,
            mount_text
        ),
        format!(
            "particles: {} substrate, {n} slider, {n} control, 1 support ({} LAMMPS atoms: the control layer has two sub-layers)",
            sim.spec.substrate.len(),
            lay.atoms.len()
        ),
        format!(
            "load W = {} mN; pulling direction {direction}; support {} m/s, K0 = {} N/m, lead {} um",
            p.protocol.load * 1e3,
            p.protocol.support_speed,
            p.protocol.k0,
            p.protocol.support_lead * um
        ),
        format!(
            "protocol: equilibrate {} us, relax {} us, slide {} us at dt = {} us (stable-step estimate {} us)",
            p.protocol.equilibrate_time * um,
            p.protocol.relax_time * um,
            p.protocol.slide_time * um,
            micro::time(sim.dt),
            micro::time(sim.dt_crit)
        ),
        format!(
            "start: the surrogate's equilibrium ({} contacts, P_max {} GPa, z {} um), as the Rust engine",
            prep.start.contacts,
            prep.start.p_max * 1e-9,
            prep.start.z * um
        ),
    ];
    let (r_sl, r_sb) = (
        sim.spec.slider_sphere_radius,
        sim.spec.substrate_sphere_radius,
    );
    if r_sl != r_sb {
        header.push(format!(
            "spheres: slider diameter {} um, substrate diameter {} um (per-atom diameters; R_eff = {} um, contact distance {} um)",
            2.0 * r_sl * um,
            2.0 * r_sb * um,
            hertz.r_eff * um,
            (r_sl + r_sb) * um
        ));
    }
    if let Some(w) = scene.edge_warning() {
        header.push(format!("warning: {w}"));
    }
    let spec = &sim.spec;
    let sizes = spec.has_sizes().then(|| {
        let n_sl = spec.slider_sites.len();
        let masses: Vec<f64> = (0..n_sl)
            .map(|i| spec.slider_material.sphere_mass(spec.slider_radius(i)))
            .collect();
        let z_offset = (0..n_sl)
            .map(|i| masses[i] * (spec.slider_sphere_radius - spec.slider_radius(i)))
            .sum::<f64>()
            / masses.iter().sum::<f64>();
        header.push(format!(
            "spheres: per-site sizes (each atom its own diameter and mass; {} slider, {} substrate diameters)",
            n_sl, spec.substrate.len()
        ));
        deck_sizes::DeckSizes {
            slider_diameters: deck_sizes::distinct(
                (0..n_sl).map(|i| micro::len(2.0 * spec.slider_radius(i))),
            ),
            substrate_diameters: deck_sizes::distinct(
                (0..spec.substrate.len()).map(|j| micro::len(2.0 * spec.substrate_radius(j))),
            ),
            z_offset: micro::len(z_offset),
            tau: (p.numerics.damping_time.is_finite() && p.numerics.damping_time > 0.0)
                .then(|| micro::time(p.numerics.damping_time)),
            slider_density: micro::density(spec.slider_material.density),
            substrate_density: micro::density(spec.substrate_material.density),
        }
    });
    let window_start = (p.protocol.measure_from * ns as f64).round() as u64;
    let inputs = DeckInputs {
        header,
        steps,
        window_start,
        dt: micro::time(sim.dt),
        youngs: micro::pressure(m_sl.youngs),
        poisson: m_sl.poisson,
        pair: (m_sl != m_sb).then(|| {
            // the one material whose E/(2(1 − ν²)) is the pair's E* (at the slider's ν), and the
            // pair's Mindlin stiffness 8G* given explicitly
            let nu = m_sl.poisson;
            DeckPair {
                youngs: micro::pressure(2.0 * (1.0 - nu * nu) * hertz.e_star),
                k_t: micro::pressure(8.0 * m_sl.g_star_with(&m_sb)),
                substrate: [micro::pressure(m_sb.youngs), m_sb.poisson],
            }
        }),
        damping,
        mu: opts.mu,
        contact_distance: micro::len(sim.spec.max_contact_distance()),
        r_eff: micro::len(hertz.r_eff),
        p0_prefactor_gpa: 2.0 * hertz.e_star / std::f64::consts::PI * 1e-9,
        skin: micro::len(p.numerics.skin),
        k_xy: micro::stiffness(p.mount.k_slider_xy),
        k_z: micro::stiffness(p.mount.k_slider_z),
        tie_length: micro::len(opts.tie_length),
        k_substrate: micro::stiffness(p.mount.k_substrate_xy),
        viscous,
        load_per_control: micro::force(p.protocol.load) / (2 * n) as f64,
        mount,
        half_distance: lay.half_distance.map(micro::len),
        theta_cs: [ct, st],
        k0: micro::stiffness(p.protocol.k0),
        lead: micro::len(p.protocol.support_lead),
        alpha_cs: [ca, sa],
        speed: micro::velocity(p.protocol.support_speed),
        support0: [micro::len(lay.support[0]), micro::len(lay.support[1])],
        support_id: lay.ids.support.first,
        sizes,
    };
    let deck = deck::render(&inputs);
    let title = format!(
        "superlube {} theta_deg={} load_mN={} mount={} (units micro, atom_style hybrid sphere bond)",
        scene.pattern,
        scene.slider.theta.to_degrees(),
        p.protocol.load * 1e3,
        scene.slider.mount.name()
    );
    let data = data_file::render(&lay, &title);
    let meta = ExportMeta {
        format: meta::FORMAT.to_string(),
        command: opts.command.clone(),
        pattern: scene.pattern.clone(),
        theta_deg: scene.slider.theta.to_degrees(),
        offset_um: scene.slider.offset.map(|v| v * um),
        sigma_h_um: scene.substrate.sigma_h * um,
        seed: scene.substrate.seed,
        mount: scene.slider.mount.name().to_string(),
        tilt_k1_n_m: match scene.slider.mount {
            Mount::Springs { k1 } => Some(k1),
            _ => None,
        },
        load_mn: p.protocol.load * 1e3,
        direction_deg: p.protocol.alpha.to_degrees(),
        alpha_deg: opts.alpha_and_line.map(|(a, _)| a.to_degrees()),
        line_deg: opts.alpha_and_line.map(|(_, l)| l.to_degrees()),
        mu: opts.mu,
        mu1: scene.coating.mu1,
        mu2: scene.coating.mu2,
        p_crit_gpa: scene.coating.p_crit * 1e-9,
        sphere_radius_um: r_sb * um,
        slider_sphere_radius_um: (r_sl != r_sb).then_some(r_sl * um),
        slider_radii_um: spec
            .slider_radii
            .as_ref()
            .map(|r| r.iter().map(|v| v * um).collect()),
        substrate_radii_um: spec
            .substrate_radii
            .as_ref()
            .map(|r| r.iter().map(|v| v * um).collect()),
        e_star_gpa: hertz.e_star * 1e-9,
        r_eff_um: hertz.r_eff * um,
        dt_us: sim.dt * um,
        steps,
        ids: lay.ids,
        surrogate: meta::SurrogateStart {
            contacts: prep.start.contacts,
            p_max_gpa: prep.start.p_max * 1e-9,
            z_um: prep.start.z * um,
        },
        atoms: lay.atoms.len() as u64,
    };
    let readme = readme(&meta, &inputs);
    Ok(LammpsExport {
        data,
        deck,
        readme,
        meta,
    })
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
        win = st.slide - d.window_start.min(st.slide),
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
