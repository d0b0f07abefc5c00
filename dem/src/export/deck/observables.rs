//! The deck's observables: contacts, P_max, height, support position, spring force and tilts,
//! the thermo line, the time series and the contact dump.

use super::inputs::DeckInputs;
use super::number::N;
use super::{DUMP_COLUMNS, TIMESERIES_HEADER};
use std::fmt::Write;

/// The computes and variables, `thermo`, the time-series `fix print` and the dump.
pub(super) fn observables(s: &mut String, d: &DeckInputs) {
    w!(s, "# ---- observables ----");
    w!(s, "# contacts = slider-substrate pairs closer than 2R; P_max = (2E*/pi) sqrt(delta_max/R_eff)");
    w!(s, "compute         cpl all pair/local dist cutoff radius");
    w!(
        s,
        "compute         cpa all property/local patom1 patom2 cutoff radius"
    );
    w!(s, "compute         dmin all reduce min c_cpl");
    w!(s, "compute         dsum all reduce sum c_cpl");
    w!(s, "compute         dave all reduce ave c_cpl");
    w!(
        s,
        "variable        contacts equal round(c_dsum/(c_dave+(c_dave==0)))"
    );
    match &d.sizes {
        None => {
            w!(
                s,
                "variable        pmax_GPa equal (c_dsum>0)*{}*sqrt((c_dmin<{c})*({c}-c_dmin)/{})",
                N(d.contact.p0_prefactor_gpa),
                N(d.contact.r_eff),
                c = N(d.contact.contact_distance)
            );
        }
        Some(z) => crate::export::deck_sizes::p_max(s, z, d.contact.p0_prefactor_gpa),
    }
    w!(s, "variable        t_us equal time");
    match &d.sizes {
        None => w!(s, "variable        z_um equal xcm(slider,z)"),
        Some(z) => {
            w!(s, "# per-site sizes: the slider's reference plane = its centre of mass less the mass-weighted R - r_i");
            w!(
                s,
                "variable        z_um equal xcm(slider,z)-({})",
                N(z.z_offset)
            );
        }
    }
    w!(
        s,
        "variable        sup_x_um equal (x[{id}]-{})*{ca}+(y[{id}]-{})*{sa}",
        N(d.drive.support0[0]),
        N(d.drive.support0[1]),
        id = d.drive.support_id,
        ca = N(d.drive.alpha_cs[0]),
        sa = N(d.drive.alpha_cs[1])
    );
    w!(s, "variable        fspring_mN equal 0.0");
    w!(s, "# tilts (rad) in the slider frame from the half-layer heights, then rotated by theta to the lab");
    w!(
        s,
        "# frame (convention: sphere at offset (x, y) sits at z + tilt_x y - tilt_y x)"
    );
    w!(
        s,
        "variable        tsx equal (xcm(half_yp,z)-xcm(half_yn,z)-v_dzy0)/{}",
        N(d.control.half_distance[1])
    );
    w!(
        s,
        "variable        tsy equal -(xcm(half_xp,z)-xcm(half_xn,z)-v_dzx0)/{}",
        N(d.control.half_distance[0])
    );
    let [c, sn] = d.control.theta_cs.map(N);
    w!(
        s,
        "variable        tilt_x_urad equal 1e6*({c}*v_tsx-({sn})*v_tsy)"
    );
    w!(
        s,
        "variable        tilt_y_urad equal 1e6*({sn}*v_tsx+({c})*v_tsy)"
    );
    w!(s, "thermo_style    custom step time v_contacts v_pmax_GPa v_z_um v_fspring_mN v_tilt_x_urad v_tilt_y_urad");
    w!(s, "thermo_modify   norm no");
    w!(s, "thermo          ${{thermo_every}}");
    w!(s, "fix             ts all print ${{every}} \"${{t_us}},${{sup_x_um}},${{fspring_mN}},${{z_um}},${{contacts}},${{pmax_GPa}},${{tilt_x_urad}},${{tilt_y_urad}}\" file ${{csv}} screen no title \"{TIMESERIES_HEADER}\"");
    w!(s, "if \"${{dump_every}} > 0\" then \"dump cd all local ${{dump_every}} ${{dump}} {}\" \"dump_modify cd format float %.17g\"", DUMP_COLUMNS.join(" "));
}
