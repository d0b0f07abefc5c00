//! The protocol's three phases in the deck as capped `run`s, from the [`super::DeckDrive`] (the
//! [`crate::ProtocolParams`] part), the mount and the step counts.

use super::control::{rigid, DeckMount};
use super::inputs::DeckInputs;
use super::number::N;
use std::fmt::Write;

/// 1. equilibrate, 2. attach K0 and relax, 3. slide, each followed by its `RESULT` line.
pub(super) fn phases(s: &mut String, d: &DeckInputs) {
    let st = &d.steps;
    let tilts = !matches!(d.control.mount, DeckMount::Locked);
    let result = "print           \"RESULT phase=PHASE step=$(step) t_us=$(time:%.10g) contacts=${contacts} p_max_GPa=${pmax_GPa} z_um=${z_um} spring_force_mN=${fspring_mN} tilt_x_urad=${tilt_x_urad} tilt_y_urad=${tilt_y_urad}\"";
    w!(s, "");
    w!(
        s,
        "# ---- 1. equilibrate under load ({} steps) ----",
        st.equilibrate
    );
    w!(
        s,
        "# steps left in the budget nsteps; each phase runs min(its length, what is left)"
    );
    w!(
        s,
        "variable        left equal (v_nsteps>step)*(v_nsteps-step)"
    );
    w!(s, "{}", run(st.equilibrate));
    w!(s, "{}", result.replace("PHASE", "equilibrate"));
    let nr = st.relax;
    if st.relax + st.slide > 0 {
        w!(s, "");
        w!(s, "# ---- 2. attach the pulling spring K0 (rest vector = the support's lead along alpha) and relax ({} steps) ----", st.relax);
        w!(s, "unfix           rig");
        w!(
            s,
            "fix             pull ctrl spring couple support {} {} {} NULL 0.0",
            N(d.drive.k0),
            N(d.drive.lead * d.drive.alpha_cs[0]),
            N(d.drive.lead * d.drive.alpha_cs[1])
        );
        w!(s, "variable        fspring_mN equal {}*((x[{id}]-xcm(ctrl,x))*{ca}+(y[{id}]-xcm(ctrl,y))*{sa}-{})*1e-6", N(d.drive.k0), N(d.drive.lead), id = d.drive.support_id, ca = N(d.drive.alpha_cs[0]), sa = N(d.drive.alpha_cs[1]));
        rigid(s, false, tilts);
        w!(s, "{}", run(nr));
        w!(s, "{}", result.replace("PHASE", "relax"));
    }
    if st.slide > 0 {
        let (vx, vy) = (
            d.drive.speed * d.drive.alpha_cs[0],
            d.drive.speed * d.drive.alpha_cs[1],
        );
        let n1 = d.drive.window_start.min(st.slide);
        let n2 = st.slide - n1;
        w!(s, "");
        w!(s, "# ---- 3. slide: the support moves at {} m/s along alpha ({} steps); friction = mean spring", N(d.drive.speed), st.slide);
        w!(s, "# force over the last {} steps ----", n2);
        w!(s, "unfix           rig");
        w!(
            s,
            "fix             mv support move linear {} {} 0.0",
            N(vx),
            N(vy)
        );
        if let Some(v) = d.numerics.viscous {
            if v.relative {
                let g = v.gamma_sphere * v.control_ratio;
                w!(s, "# relative frame: the control layer is damped (x, y) relative to the support's velocity");
                w!(
                    s,
                    "fix             relc ctrl addforce {} {} 0.0",
                    N(g * vx),
                    N(g * vy)
                );
            }
        }
        rigid(s, false, tilts);
        w!(s, "{}", run(n1));
        w!(
            s,
            "fix             fav all ave/time ${{every}} 1 ${{every}} v_fspring_mN ave running"
        );
        w!(s, "{}", run(n2));
        w!(s, "{}", result.replace("PHASE", "slide"));
        w!(s, "if \"$(step) == {}\" then \"print 'RESULT friction_mN=$(f_fav:%.10g) window_steps={}'\"", st.total(), n2);
    }
}

/// `run` of at most `n` steps, fewer when the `nsteps` budget is used up.
fn run(n: u64) -> String {
    format!("run             $((v_left<{n})*v_left+(v_left>={n})*{n})")
}
