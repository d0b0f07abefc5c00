//! The LAMMPS input deck (`in.superlube.lmp`) of the exported model.
//!
//! Every number is computed in Rust from the same [`crate::SimParams`] and scene the Rust tier
//! uses and written in LAMMPS `units micro` (see [`super::micro`]); the deck has no lattice or
//! model logic of its own. Structure: variables (`nsteps`, file names, `extra`) → data →
//! groups → contact law → bonds → fixes (integration, tethers, damping, load, mount, rigid
//! control layer last) → observables and outputs → the protocol's phases, each a `run` whose
//! length is capped by `nsteps` (so `-var nsteps 0` sets everything up and stops).

use super::damping::LammpsDamping;
use super::layout::{BOND_AXIAL, BOND_LATERAL};
use super::meta::Steps;
use std::fmt::Write;

/// Names of the dump's columns (`dump local`): pair distance, then the two atom IDs.
pub const DUMP_COLUMNS: [&str; 3] = ["c_cpl", "c_cpa[1]", "c_cpa[2]"];

/// Columns of the deck's time series CSV.
pub const TIMESERIES_HEADER: &str =
    "t_us,support_x_um,spring_force_mN,z_um,contacts,p_max_GPa,tilt_x_urad,tilt_y_urad";

/// File names the export writes and the deck reads/writes.
pub mod files {
    /// The data file.
    pub const DATA: &str = "scene.data";
    /// The input deck.
    pub const DECK: &str = "in.superlube.lmp";
    /// The README of the export directory.
    pub const README: &str = "README.md";
    /// The metadata `superlube lammps-check` reads.
    pub const META: &str = "export.json";
    /// The time series the deck writes.
    pub const TIMESERIES: &str = "timeseries.csv";
    /// The contact dump the deck writes.
    pub const DUMP: &str = "contacts.dump";
}

/// How the control layer may tilt, in deck terms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DeckMount {
    /// `fix rigid` with every torque component off: translation only.
    Locked,
    /// `fix rigid` with torque about x and y on.
    Free,
    /// As `Free`, plus `fix spring couple` of stiffness `k1` (nN/µm) in z between the opposing
    /// half-layers.
    Springs {
        /// K1 (nN/µm).
        k1: f64,
    },
}

/// Damping of the 0 K Langevin-equivalent viscous drag, in deck terms.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckViscous {
    /// γ = m/τ of a slider sphere (pg/µs).
    pub gamma_sphere: f64,
    /// γ of one control sphere / γ of a slider sphere (–).
    pub control_ratio: f64,
    /// γ of a substrate sphere / γ of a slider sphere (–) when the two bodies' sphere sizes
    /// differ; `None` for one size (the substrate takes `gamma_sphere`).
    pub substrate_ratio: Option<f64>,
    /// Relative frame: slider spheres damped relative to the control layer's velocity, the
    /// control layer (x, y) relative to the support's.
    pub relative: bool,
}

/// The slider–substrate pair's coefficients when the bodies' materials differ (LAMMPS micro
/// units): an explicit `pair_coeff 1 2` whose `hertz/material` gives the pair's Hertz
/// `E* = E/(2(1 − ν²))` at the slider's ν, and whose Mindlin stiffness is the pair's `8G*`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckPair {
    /// `2(1 − ν_sl²) E*` (10³ Pa): the modulus that LAMMPS turns into the pair's E*.
    pub youngs: f64,
    /// `8 G*` (10³ Pa) of the pair: `1/G* = (2 − ν1)/G1 + (2 − ν2)/G2`.
    pub k_t: f64,
    /// The substrate's own Young's modulus (10³ Pa) and Poisson ratio (recorded in a comment).
    pub substrate: [f64; 2],
}

/// Everything the deck needs, in LAMMPS micro units (µm, µs, pg, nN, 10³ Pa, nN/µm).
#[derive(Debug, Clone, PartialEq)]
pub struct DeckInputs {
    /// Header lines (without `#`), e.g. the scene and the command.
    pub header: Vec<String>,
    /// Step counts.
    pub steps: Steps,
    /// Friction window: slide steps before the window starts.
    pub window_start: u64,
    /// Time step (µs).
    pub dt: f64,
    /// Young's modulus (10³ Pa) of the slider's material (of both bodies' when `pair` is
    /// `None`).
    pub youngs: f64,
    /// Poisson ratio (–) of the slider's material.
    pub poisson: f64,
    /// The slider–substrate pair's own coefficients when the two bodies' materials differ;
    /// `None`: one material.
    pub pair: Option<DeckPair>,
    /// Contact damping.
    pub damping: LammpsDamping,
    /// Constant friction coefficient.
    pub mu: f64,
    /// Contact distance R_sl + R_sb (µm; 2R for one sphere size), R_eff (µm), 2E*/π (GPa) for
    /// P_max.
    pub contact_distance: f64,
    /// R_eff (µm).
    pub r_eff: f64,
    /// 2E*/π (GPa).
    pub p0_prefactor_gpa: f64,
    /// Neighbour skin (µm).
    pub skin: f64,
    /// Lateral tie stiffness k_xy and axial tie stiffness k_z (nN/µm).
    pub k_xy: f64,
    /// See `k_xy`.
    pub k_z: f64,
    /// Axial tie rest length (µm).
    pub tie_length: f64,
    /// Substrate tether stiffness (nN/µm).
    pub k_substrate: f64,
    /// Viscous damping; `None` = off (τ = ∞).
    pub viscous: Option<DeckViscous>,
    /// Load per control sphere (nN, positive = downward).
    pub load_per_control: f64,
    /// Mount.
    pub mount: DeckMount,
    /// Half-layer distances `[d_x, d_y]` (µm), slider frame.
    pub half_distance: [f64; 2],
    /// cos θ, sin θ of the slider rotation.
    pub theta_cs: [f64; 2],
    /// Pulling spring K0 (nN/µm).
    pub k0: f64,
    /// Spring rest vector = support lead along α (µm).
    pub lead: f64,
    /// cos α, sin α of the pulling direction.
    pub alpha_cs: [f64; 2],
    /// Support speed (µm/µs).
    pub speed: f64,
    /// Support start position (µm).
    pub support0: [f64; 2],
    /// Atom ID of the support.
    pub support_id: u64,
    /// Per-site sphere sizes (then `contact_distance` is the largest radius sum, for the
    /// communication cutoff); `None`: one size per body.
    pub sizes: Option<super::deck_sizes::DeckSizes>,
}

/// The comment over the slider–substrate pair's own `pair_coeff` (two materials).
fn pair_lines(s: &mut String, p: &DeckPair) {
    let _ = writeln!(
        s,
        "# per-body materials: the slider (types 2-5) as above, the substrate E = {} nu = {}; the\n\
         # slider-substrate pair (types 1 2) takes 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 as the modulus\n\
         # whose E/(2(1-nu^2)) is E* at the slider's nu, and k_t = 8 G*, 1/G* = (2-nu1)/G1 + (2-nu2)/G2",
        N(p.substrate[0]),
        N(p.substrate[1])
    );
}

/// A number as LAMMPS reads it: the shortest text that round-trips (`1e-5`, `0.1`, `1e8`).
struct N(f64);

impl std::fmt::Display for N {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let t = format!("{:?}", self.0);
        f.write_str(t.strip_suffix(".0").unwrap_or(&t))
    }
}

fn on(b: bool) -> &'static str {
    if b {
        "on"
    } else {
        "off"
    }
}

/// Renders the deck.
pub fn render(d: &DeckInputs) -> String {
    let mut s = String::new();
    macro_rules! w {
        ($($t:tt)*) => {{ let _ = writeln!(s, $($t)*); }};
    }
    for l in &d.header {
        w!("# {l}");
    }
    let st = &d.steps;
    let tilts = !matches!(d.mount, DeckMount::Locked);
    w!("#");
    w!("# Run (in this directory; outputs go to the working directory):");
    w!(
        "#   lmp -in {}                          # serial",
        files_deck()
    );
    w!(
        "#   mpirun -np 32 lmp -in {}            # MPI (any rank count; processors * * 1)",
        files_deck()
    );
    w!(
        "#   lmp -in {} -var nsteps 0            # check the deck: set up, compute forces, stop",
        files_deck()
    );
    w!("# Outputs: {} (every {} steps), {} (contact pairs, every {} steps: `superlube lammps-check {}`),", super::deck::files::TIMESERIES, st.sample_every, files::DUMP, st.dump_every, files::DUMP);
    w!("#   log.lammps with lines `RESULT phase=... contacts=... p_max_GPa=...` after each phase.");
    w!("#");
    w!("# LIMITATION: one constant friction coefficient mu = {} for every contact. Stock LAMMPS cannot", N(d.mu));
    w!("# switch mu per contact when its Hertz pressure p0 passes P_crit (the study's coating: mu1 below,");
    w!("# mu2 above). This run is the study's model only while no contact exceeds P_crit: check with");
    w!(
        "# `superlube lammps-check {}`, which lists the frames and contacts where it does.",
        files::DUMP
    );
    w!("# Other deviations from the Rust DEM (dem/lammps/README.md): the anisotropic slider ties are two");
    w!("# harmonic bonds (exact to first order; the axial bond's tension T adds a lateral stiffness");
    w!(
        "# T/{} um); the control layer is a LAMMPS rigid body of two sub-layers of control spheres.",
        N(d.tie_length)
    );
    w!("#");
    w!("# Units: LAMMPS `units micro`: um, us, pg, nN; pressure 1e3 Pa (100 GPa = 1e8); stiffness");
    w!("# nN/um = 1e-3 N/m (1e3 N/m = 1e6); velocity um/us = m/s; density pg/um^3 = g/cm^3.");
    w!("");
    w!("variable nsteps     index {}   # total steps: equilibrate {} + relax {} + slide {}; 0 = setup only", st.total(), st.equilibrate, st.relax, st.slide);
    w!("variable data       index {}", files::DATA);
    w!("variable csv        index {}", files::TIMESERIES);
    w!("variable dump       index {}", files::DUMP);
    w!(
        "variable every      index {}   # time-series interval (steps)",
        st.sample_every
    );
    w!(
        "variable dump_every index {}   # contact-dump interval (steps); 0 = no dump",
        st.dump_every
    );
    w!(
        "variable thermo_every index {}",
        (st.sample_every * 10).max(1)
    );
    w!("# optional: -var extra FILE includes a LAMMPS file before the runs (extra fixes, computes)");
    w!("");
    w!("units           micro");
    w!("atom_style      hybrid sphere bond");
    w!("atom_modify     map array");
    w!("boundary        s s s");
    w!("newton          on");
    w!("processors      * * 1");
    w!("read_data       ${{data}}");
    w!(
        "comm_modify     vel yes cutoff {}",
        N(d.tie_length + d.contact_distance + d.skin + 1.0)
    );
    w!("");
    w!("# ---- groups (types: 1 substrate, 2 slider, 3 axial control, 4 lateral control, 5 support) ----");
    w!("group           sub     type 1");
    w!("group           slider  type 2");
    w!("group           ctrl    type 3 4");
    w!("group           ctrla   type 3");
    w!("group           ctrlb   type 4");
    w!("group           support type 5");
    w!("group           mobile  union sub slider");
    w!("group           damped  union sub slider ctrl");
    w!("# halves of the control layer in the slider's own frame: molecule = 1 + (sx+1) + 3(sy+1),");
    w!("# sx, sy = signs of the site's offset from the disc centre; a site on a dividing line counts");
    w!("# half to each side (its axial sphere to the + half, its lateral sphere to the - half).");
    w!("group           qxp     molecule 3 6 9");
    w!("group           qxn     molecule 1 4 7");
    w!("group           qx0     molecule 2 5 8");
    w!("group           qyp     molecule 7 8 9");
    w!("group           qyn     molecule 1 2 3");
    w!("group           qy0     molecule 4 5 6");
    w!("group           qx0a    intersect qx0 ctrla");
    w!("group           qx0b    intersect qx0 ctrlb");
    w!("group           qy0a    intersect qy0 ctrla");
    w!("group           qy0b    intersect qy0 ctrlb");
    w!("group           half_xp union qxp qx0a");
    w!("group           half_xn union qxn qx0b");
    w!("group           half_yp union qyp qy0a");
    w!("group           half_yn union qyn qy0b");
    w!("");
    w!("# ---- contacts: Hertz (hertz/material: F = 4/3 E* sqrt(R_eff) delta^1.5), Mindlin k_t = 8 G* a,");
    w!("# capped at mu |F_n| (damped normal force, as in the Rust engine); only slider-substrate pairs ----");
    match d.damping {
        LammpsDamping::Tsuji { e, xgammat } => {
            w!("# damping tsuji: F = -alpha(e) sqrt(m_eff 4/3 E* a) v_n = the Rust -gamma_n sqrt(m_eff 2E* a) v_n;");
            w!("# tangential damping = xgammat x normal = the Rust -gamma_t sqrt(m_eff k_t) v_t");
            w!("pair_style      granular");
            w!("pair_coeff      * * hertz/material {} {} {} damping tsuji tangential mindlin NULL {} {}", N(d.youngs), N(e), N(d.poisson), N(xgammat), N(d.mu));
            if let Some(p) = d.pair {
                pair_lines(&mut s, &p);
                w!("pair_coeff      1 2 hertz/material {} {} {} damping tsuji tangential mindlin {} {} {}", N(p.youngs), N(e), N(d.poisson), N(p.k_t), N(xgammat), N(d.mu));
            }
        }
        LammpsDamping::None => {
            w!("pair_style      granular");
            w!("pair_coeff      * * hertz/material {} 0.0 {} damping viscoelastic tangential mindlin NULL 0.0 {}", N(d.youngs), N(d.poisson), N(d.mu));
            if let Some(p) = d.pair {
                pair_lines(&mut s, &p);
                w!("pair_coeff      1 2 hertz/material {} 0.0 {} damping viscoelastic tangential mindlin {} 0.0 {}", N(p.youngs), N(d.poisson), N(p.k_t), N(d.mu));
            }
        }
    }
    w!("neighbor        {} bin", N(d.skin));
    w!("neigh_modify    delay 0 every 1 check yes exclude type 1 1 exclude type 2 2 exclude group ctrl all exclude group support all");
    w!("");
    w!("# ---- slider ties: bond {BOND_AXIAL} to the axial control sphere {} um above (k_z - k_xy, axial to first", N(d.tie_length));
    w!("# order), bond {BOND_LATERAL} to the co-located lateral control sphere (k_xy, isotropic, rest length 0);");
    w!("# harmonic bonds are E = K (r - r0)^2, so K = k/2 ----");
    w!("bond_style      harmonic");
    w!(
        "bond_coeff      {BOND_AXIAL} {} {}",
        N(0.5 * (d.k_z - d.k_xy)),
        N(d.tie_length)
    );
    w!("bond_coeff      {BOND_LATERAL} {} 0.0", N(0.5 * d.k_xy));
    w!("special_bonds   lj/coul 0.0 0.0 0.0");
    w!("");
    w!("timestep        {}", N(d.dt));
    w!("# equal atom counts per MPI rank in the plane");
    w!("balance         1.0 shift xy 20 1.0");
    w!("");
    w!("# ---- integration: velocity Verlet, translations only (fix nve, not nve/sphere: the spheres");
    w!("# are fixed to a non-rotating slider and substrate) ----");
    w!("fix             integ mobile nve");
    w!(
        "fix             tether sub spring/self {} xy",
        N(d.k_substrate)
    );
    match d.viscous {
        Some(v) if d.sizes.is_some() => {
            let z = d.sizes.as_ref().unwrap();
            super::deck_sizes::viscous(&mut s, z, v.gamma_sphere * v.control_ratio, v.relative);
        }
        Some(v) => {
            w!("# 0 K Langevin-equivalent damping F = -m v / tau (gamma = m/tau per type)");
            let sub = match v.substrate_ratio {
                Some(r) => format!(" scale 1 {}", N(r)),
                None => String::new(),
            };
            w!(
                "fix             visc damped viscous {}{sub} scale 3 {} scale 4 {}",
                N(v.gamma_sphere),
                N(v.control_ratio),
                N(v.control_ratio)
            );
            if v.relative {
                w!("# relative frame (the Rust default): slider spheres are damped relative to the control layer's");
                w!("# velocity: add back gamma * v_control");
                w!("compute         vctrl ctrl reduce ave vx vy vz   # = vcm (equal masses), once per step");
                w!("variable        rvx equal {}*c_vctrl[1]", N(v.gamma_sphere));
                w!("variable        rvy equal {}*c_vctrl[2]", N(v.gamma_sphere));
                w!("variable        rvz equal {}*c_vctrl[3]", N(v.gamma_sphere));
                w!("fix             relsl slider addforce v_rvx v_rvy v_rvz");
            }
        }
        None => {
            w!("# no viscous damping (tau = infinity)");
        }
    }
    w!("# normal load W on the control layer, shared equally by its spheres (acts at its centre of mass)");
    w!(
        "fix             load ctrl addforce 0.0 0.0 {}",
        N(-d.load_per_control)
    );
    w!("# substrate fixed in z (last force fix on the substrate)");
    w!("fix             zsub sub setforce NULL NULL 0.0");
    w!("variable        dzx0 equal $(xcm(half_xp,z)-xcm(half_xn,z):%.17g)");
    w!("variable        dzy0 equal $(xcm(half_yp,z)-xcm(half_yn,z):%.17g)");
    if let DeckMount::Springs { k1 } = d.mount {
        w!("# mount: anti-tilt springs K1 in z between the centres of mass of opposing halves (equal and");
        w!("# opposite forces inside the rigid control layer = a restoring torque K1 d^2 per axis)");
        w!(
            "fix             k1x half_xn spring couple half_xp {} NULL NULL ${{dzx0}} 0.0",
            N(k1)
        );
        w!(
            "fix             k1y half_yn spring couple half_yp {} NULL NULL ${{dzy0}} 0.0",
            N(k1)
        );
    }
    w!("variable        has_extra equal is_defined(variable,extra)");
    w!("if \"${{has_extra}} == 1\" then \"include ${{extra}}\"");
    let rigid = |s: &mut String, hold: bool| {
        let _ = writeln!(
            s,
            "fix             rig ctrl rigid single force * {} {} on torque * {} {} off",
            on(!hold),
            on(!hold),
            on(tilts),
            on(tilts)
        );
    };
    w!("# control layer: one rigid body ({}), held laterally while equilibrating; defined after every", match d.mount { DeckMount::Locked => "mount locked: translation only", DeckMount::Free => "mount free: tilts about x and y, no restoring moment", DeckMount::Springs { .. } => "mount springs: tilts about x and y against K1" });
    w!("# fix that adds forces to its spheres (fix rigid sums them at setup)");
    rigid(&mut s, true);
    w!("");
    w!("# ---- observables ----");
    w!("# contacts = slider-substrate pairs closer than 2R; P_max = (2E*/pi) sqrt(delta_max/R_eff)");
    w!("compute         cpl all pair/local dist cutoff radius");
    w!("compute         cpa all property/local patom1 patom2 cutoff radius");
    w!("compute         dmin all reduce min c_cpl");
    w!("compute         dsum all reduce sum c_cpl");
    w!("compute         dave all reduce ave c_cpl");
    w!("variable        contacts equal round(c_dsum/(c_dave+(c_dave==0)))");
    match &d.sizes {
        None => {
            w!(
                "variable        pmax_GPa equal (c_dsum>0)*{}*sqrt((c_dmin<{c})*({c}-c_dmin)/{})",
                N(d.p0_prefactor_gpa),
                N(d.r_eff),
                c = N(d.contact_distance)
            );
        }
        Some(z) => super::deck_sizes::p_max(&mut s, z, d.p0_prefactor_gpa),
    }
    w!("variable        t_us equal time");
    match &d.sizes {
        None => w!("variable        z_um equal xcm(slider,z)"),
        Some(z) => {
            w!("# per-site sizes: the slider's reference plane = its centre of mass less the mass-weighted R - r_i");
            w!(
                "variable        z_um equal xcm(slider,z)-({})",
                N(z.z_offset)
            );
        }
    }
    w!(
        "variable        sup_x_um equal (x[{id}]-{})*{ca}+(y[{id}]-{})*{sa}",
        N(d.support0[0]),
        N(d.support0[1]),
        id = d.support_id,
        ca = N(d.alpha_cs[0]),
        sa = N(d.alpha_cs[1])
    );
    w!("variable        fspring_mN equal 0.0");
    w!("# tilts (rad) in the slider frame from the half-layer heights, then rotated by theta to the lab");
    w!("# frame (convention: sphere at offset (x, y) sits at z + tilt_x y - tilt_y x)");
    w!(
        "variable        tsx equal (xcm(half_yp,z)-xcm(half_yn,z)-v_dzy0)/{}",
        N(d.half_distance[1])
    );
    w!(
        "variable        tsy equal -(xcm(half_xp,z)-xcm(half_xn,z)-v_dzx0)/{}",
        N(d.half_distance[0])
    );
    let [c, sn] = d.theta_cs.map(N);
    w!("variable        tilt_x_urad equal 1e6*({c}*v_tsx-({sn})*v_tsy)");
    w!("variable        tilt_y_urad equal 1e6*({sn}*v_tsx+({c})*v_tsy)");
    w!("thermo_style    custom step time v_contacts v_pmax_GPa v_z_um v_fspring_mN v_tilt_x_urad v_tilt_y_urad");
    w!("thermo_modify   norm no");
    w!("thermo          ${{thermo_every}}");
    w!("fix             ts all print ${{every}} \"${{t_us}},${{sup_x_um}},${{fspring_mN}},${{z_um}},${{contacts}},${{pmax_GPa}},${{tilt_x_urad}},${{tilt_y_urad}}\" file ${{csv}} screen no title \"{TIMESERIES_HEADER}\"");
    w!("if \"${{dump_every}} > 0\" then \"dump cd all local ${{dump_every}} ${{dump}} {}\" \"dump_modify cd format float %.17g\"", DUMP_COLUMNS.join(" "));
    let result = "print           \"RESULT phase=PHASE step=$(step) t_us=$(time:%.10g) contacts=${contacts} p_max_GPa=${pmax_GPa} z_um=${z_um} spring_force_mN=${fspring_mN} tilt_x_urad=${tilt_x_urad} tilt_y_urad=${tilt_y_urad}\"";
    w!("");
    w!(
        "# ---- 1. equilibrate under load ({} steps) ----",
        st.equilibrate
    );
    w!("# steps left in the budget nsteps; each phase runs min(its length, what is left)");
    w!("variable        left equal (v_nsteps>step)*(v_nsteps-step)");
    w!("{}", run(st.equilibrate));
    w!("{}", result.replace("PHASE", "equilibrate"));
    let nr = st.relax;
    if st.relax + st.slide > 0 {
        w!("");
        w!("# ---- 2. attach the pulling spring K0 (rest vector = the support's lead along alpha) and relax ({} steps) ----", st.relax);
        w!("unfix           rig");
        w!(
            "fix             pull ctrl spring couple support {} {} {} NULL 0.0",
            N(d.k0),
            N(d.lead * d.alpha_cs[0]),
            N(d.lead * d.alpha_cs[1])
        );
        w!("variable        fspring_mN equal {}*((x[{id}]-xcm(ctrl,x))*{ca}+(y[{id}]-xcm(ctrl,y))*{sa}-{})*1e-6", N(d.k0), N(d.lead), id = d.support_id, ca = N(d.alpha_cs[0]), sa = N(d.alpha_cs[1]));
        rigid(&mut s, false);
        w!("{}", run(nr));
        w!("{}", result.replace("PHASE", "relax"));
    }
    if st.slide > 0 {
        let (vx, vy) = (d.speed * d.alpha_cs[0], d.speed * d.alpha_cs[1]);
        let n1 = d.window_start.min(st.slide);
        let n2 = st.slide - n1;
        w!("");
        w!("# ---- 3. slide: the support moves at {} m/s along alpha ({} steps); friction = mean spring", N(d.speed), st.slide);
        w!("# force over the last {} steps ----", n2);
        w!("unfix           rig");
        w!(
            "fix             mv support move linear {} {} 0.0",
            N(vx),
            N(vy)
        );
        if let Some(v) = d.viscous {
            if v.relative {
                let g = v.gamma_sphere * v.control_ratio;
                w!("# relative frame: the control layer is damped (x, y) relative to the support's velocity");
                w!(
                    "fix             relc ctrl addforce {} {} 0.0",
                    N(g * vx),
                    N(g * vy)
                );
            }
        }
        rigid(&mut s, false);
        w!("{}", run(n1));
        w!("fix             fav all ave/time ${{every}} 1 ${{every}} v_fspring_mN ave running");
        w!("{}", run(n2));
        w!("{}", result.replace("PHASE", "slide"));
        w!("if \"$(step) == {}\" then \"print 'RESULT friction_mN=$(f_fav:%.10g) window_steps={}'\"", st.total(), n2);
    }
    s
}

/// `run` of at most `n` steps, fewer when the `nsteps` budget is used up.
fn run(n: u64) -> String {
    format!("run             $((v_left<{n})*v_left+(v_left>={n})*{n})")
}

fn files_deck() -> &'static str {
    files::DECK
}
