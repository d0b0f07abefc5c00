//! The deck's fixes: integration, the substrate tethers, the viscous bath, the load, the
//! mount springs, the user's `extra` file and, last, the rigid control layer.

use super::control::{rigid, DeckMount};
use super::inputs::DeckInputs;
use super::number::N;
use std::fmt::Write;

/// The fixes in LAMMPS order (`fix rigid` after every fix that adds forces to its spheres).
pub(super) fn fixes(s: &mut String, d: &DeckInputs) {
    let tilts = !matches!(d.control.mount, DeckMount::Locked);
    w!(s, "# ---- integration: velocity Verlet, translations only (fix nve, not nve/sphere: the spheres");
    w!(
        s,
        "# are fixed to a non-rotating slider and substrate) ----"
    );
    w!(s, "fix             integ mobile nve");
    w!(
        s,
        "fix             tether sub spring/self {} xy",
        N(d.ties.k_substrate)
    );
    super::numerics::viscous(s, &d.numerics, d.sizes.as_ref());
    w!(s, "# normal load W on the control layer, shared equally by its spheres (acts at its centre of mass)");
    w!(
        s,
        "fix             load ctrl addforce 0.0 0.0 {}",
        N(-d.drive.load_per_control)
    );
    w!(
        s,
        "# substrate fixed in z (last force fix on the substrate)"
    );
    w!(s, "fix             zsub sub setforce NULL NULL 0.0");
    w!(
        s,
        "variable        dzx0 equal $(xcm(half_xp,z)-xcm(half_xn,z):%.17g)"
    );
    w!(
        s,
        "variable        dzy0 equal $(xcm(half_yp,z)-xcm(half_yn,z):%.17g)"
    );
    if let DeckMount::Springs { k1 } = d.control.mount {
        w!(s, "# mount: anti-tilt springs K1 in z between the centres of mass of opposing halves (equal and");
        w!(s, "# opposite forces inside the rigid control layer = a restoring torque K1 d^2 per axis)");
        w!(
            s,
            "fix             k1x half_xn spring couple half_xp {} NULL NULL ${{dzx0}} 0.0",
            N(k1)
        );
        w!(
            s,
            "fix             k1y half_yn spring couple half_yp {} NULL NULL ${{dzy0}} 0.0",
            N(k1)
        );
    }
    w!(
        s,
        "variable        has_extra equal is_defined(variable,extra)"
    );
    w!(s, "if \"${{has_extra}} == 1\" then \"include ${{extra}}\"");
    w!(s, "# control layer: one rigid body ({}), held laterally while equilibrating; defined after every", match d.control.mount { DeckMount::Locked => "mount locked: translation only", DeckMount::Free => "mount free: tilts about x and y, no restoring moment", DeckMount::Springs { .. } => "mount springs: tilts about x and y against K1" });
    w!(
        s,
        "# fix that adds forces to its spheres (fix rigid sums them at setup)"
    );
    rigid(s, true, tilts);
    w!(s, "");
}
