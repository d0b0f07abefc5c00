//! The deck's head: the header lines, how to run it, its limitation and units, the variables a
//! user may override (`nsteps`, file names, intervals) and the LAMMPS setup (units, atom style,
//! data file, communication cutoff).

use super::files;
use super::inputs::DeckInputs;
use super::number::N;
use std::fmt::Write;

/// The header comments: provenance, how to run, the constant-μ limitation, the units.
pub(super) fn header(s: &mut String, d: &DeckInputs) {
    for l in &d.header {
        w!(s, "# {l}");
    }
    let st = &d.steps;
    w!(s, "#");
    w!(
        s,
        "# Run (in this directory; outputs go to the working directory):"
    );
    w!(
        s,
        "#   lmp -in {}                          # serial",
        files::DECK
    );
    w!(
        s,
        "#   mpirun -np 32 lmp -in {}            # MPI (any rank count; processors * * 1)",
        files::DECK
    );
    w!(
        s,
        "#   lmp -in {} -var nsteps 0            # check the deck: set up, compute forces, stop",
        files::DECK
    );
    w!(s, "# Outputs: {} (every {} steps), {} (contact pairs, every {} steps: `superlube lammps-check {}`),", files::TIMESERIES, st.sample_every, files::DUMP, st.dump_every, files::DUMP);
    w!(
        s,
        "#   log.lammps with lines `RESULT phase=... contacts=... p_max_GPa=...` after each phase."
    );
    w!(s, "#");
    w!(s, "# LIMITATION: one constant friction coefficient mu = {} for every contact. Stock LAMMPS cannot", N(d.contact.mu));
    w!(s, "# switch mu per contact when its Hertz pressure p0 passes P_crit (the study's coating: mu1 below,");
    w!(s, "# mu2 above). This run is the study's model only while no contact exceeds P_crit: check with");
    w!(
        s,
        "# `superlube lammps-check {}`, which lists the frames and contacts where it does.",
        files::DUMP
    );
    w!(s, "# Other deviations from the Rust DEM (dem/lammps/README.md): the anisotropic slider ties are two");
    w!(s, "# harmonic bonds (exact to first order; the axial bond's tension T adds a lateral stiffness");
    w!(
        s,
        "# T/{} um); the control layer is a LAMMPS rigid body of two sub-layers of control spheres.",
        N(d.ties.tie_length)
    );
    w!(s, "#");
    w!(
        s,
        "# Units: LAMMPS `units micro`: um, us, pg, nN; pressure 1e3 Pa (100 GPa = 1e8); stiffness"
    );
    w!(
        s,
        "# nN/um = 1e-3 N/m (1e3 N/m = 1e6); velocity um/us = m/s; density pg/um^3 = g/cm^3."
    );
    w!(s, "");
}

/// The overridable variables and the LAMMPS setup, through `read_data` and `comm_modify`.
pub(super) fn setup(s: &mut String, d: &DeckInputs) {
    let st = &d.steps;
    w!(s, "variable nsteps     index {}   # total steps: equilibrate {} + relax {} + slide {}; 0 = setup only", st.total(), st.equilibrate, st.relax, st.slide);
    w!(s, "variable data       index {}", files::DATA);
    w!(s, "variable csv        index {}", files::TIMESERIES);
    w!(s, "variable dump       index {}", files::DUMP);
    w!(
        s,
        "variable every      index {}   # time-series interval (steps)",
        st.sample_every
    );
    w!(
        s,
        "variable dump_every index {}   # contact-dump interval (steps); 0 = no dump",
        st.dump_every
    );
    w!(
        s,
        "variable thermo_every index {}",
        (st.sample_every * 10).max(1)
    );
    w!(s, "# optional: -var extra FILE includes a LAMMPS file before the runs (extra fixes, computes)");
    w!(s, "");
    w!(s, "units           micro");
    w!(s, "atom_style      hybrid sphere bond");
    w!(s, "atom_modify     map array");
    w!(s, "boundary        s s s");
    w!(s, "newton          on");
    w!(s, "processors      * * 1");
    w!(s, "read_data       ${{data}}");
    w!(
        s,
        "comm_modify     vel yes cutoff {}",
        N(d.ties.tie_length + d.contact.contact_distance + d.numerics.skin + 1.0)
    );
    w!(s, "");
}
