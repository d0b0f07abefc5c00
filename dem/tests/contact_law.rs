//! The pair contact model alone (no engine): Hertz collision against its closed form and against
//! the LAMMPS reference, Mindlin stick/slip, and the pressure switch of μ at P_crit.

use dem::model::{Constant, ContactModel, Friction, HertzNormal, Mindlin, PressureSwitched};
use surrogate::contact::Hertz;
use surrogate::{Coating, Material};

const R: f64 = 1.5e-6;

fn model(gamma_n: f64, gamma_t: f64, friction: Friction) -> ContactModel {
    let mat = Material::default();
    ContactModel {
        normal: HertzNormal {
            hertz: Hertz::equal_spheres(R, &mat),
            gamma_n,
        },
        tangential: Mindlin::equal_spheres(mat.youngs, mat.poisson, gamma_t),
        history: dem::Tangential::Mindlin,
        friction,
        radius_sum: 2.0 * R,
    }
}

/// Head-on collision of two free spheres (velocity-Verlet on the gap); returns
/// (contact duration s, restitution, max overlap m).
fn collide(m: &ContactModel, v_rel: f64, dt: f64) -> (f64, f64, f64) {
    let mass = Material::default().sphere_mass(R);
    let m_eff = 0.5 * mass;
    // relative coordinate x = x1 − x2 (sphere 1 on the right moving left)
    let mut x = 2.0 * R + 1e-12;
    let mut v = -v_rel;
    let mut xi = [0.0; 3];
    let force =
        |x: f64, v: f64, xi: &mut [f64; 3]| m.pair([x, 0.0, 0.0], [v, 0.0, 0.0], xi, m_eff, dt);
    let mut f = force(x, v, &mut xi).force[0];
    let (mut t, mut t_in, mut t_out) = (0.0, f64::NAN, f64::NAN);
    let mut dmax: f64 = 0.0;
    let mut prev_gap = x - 2.0 * R;
    for _ in 0..10_000_000 {
        v += 0.5 * dt * f / m_eff;
        x += dt * v;
        f = force(x, v, &mut xi).force[0];
        v += 0.5 * dt * f / m_eff;
        t += dt;
        let gap = x - 2.0 * R;
        dmax = dmax.max(-gap);
        if prev_gap > 0.0 && gap <= 0.0 {
            t_in = t - dt * gap / (gap - prev_gap);
        }
        if prev_gap <= 0.0 && gap > 0.0 {
            t_out = t - dt * gap / (gap - prev_gap);
            break;
        }
        prev_gap = gap;
    }
    (t_out - t_in, v / v_rel, dmax)
}

#[test]
fn hertz_collision_matches_closed_form_and_lammps() {
    let m = model(0.0, 0.0, Friction::Constant(Constant { mu: 0.0 }));
    let v = 0.2;
    let (tc, e, dmax) = collide(&m, v, 1e-12);
    // Closed form: δ_max = (15 m_eff v² / (16 E* √R_eff))^{2/5}, t_c = 2.9432 δ_max / v.
    let mat = Material::default();
    let h = Hertz::equal_spheres(R, &mat);
    let m_eff = 0.5 * mat.sphere_mass(R);
    let dmax_cf = (15.0 * m_eff * v * v / (16.0 * h.e_star * h.r_eff.sqrt())).powf(0.4);
    let tc_cf = 2.943_28 * dmax_cf / v;
    assert!((dmax / dmax_cf - 1.0).abs() < 1e-4, "{dmax} vs {dmax_cf}");
    assert!((tc / tc_cf - 1.0).abs() < 1e-3, "{tc} vs {tc_cf}");
    assert!((e - 1.0).abs() < 1e-6, "undamped restitution {e}");
    // LAMMPS (dem/lammps/reference/collision_summary.csv, case v0.2_undamped): 0.01007237 µs.
    assert!((tc * 1e6 / 0.010_072_37 - 1.0).abs() < 2e-3, "{}", tc * 1e6);
}

#[test]
fn damped_collision_restitution_is_velocity_independent_and_matches_lammps() {
    let m = model(0.1, 0.1, Friction::Constant(Constant { mu: 0.0 }));
    let (_, e1, _) = collide(&m, 0.2, 1e-12);
    let (_, e2, _) = collide(&m, 1.0, 1e-12);
    // Viscoelastic (Tsuji-type) damping: e does not depend on the impact speed.
    assert!((e1 - e2).abs() < 2e-3, "{e1} vs {e2}");
    // First-order estimate e ≈ 1 − 1.7207 γ_n = 0.828; LAMMPS with the matched damping: 0.8417.
    assert!(
        (e1 - 0.8417).abs() < 0.01,
        "restitution {e1} (LAMMPS 0.8417)"
    );
}

/// A sphere pressed with a fixed overlap and dragged tangentially: the tangential force follows
/// the Mindlin spring k_t = 8G*a while below μF_n (stick) and stays at μF_n once sliding.
#[test]
fn mindlin_sticks_below_mu_fn_and_slides_at_mu_fn() {
    let mu = 0.3;
    let m = model(0.0, 0.0, Friction::Constant(Constant { mu }));
    let mat = Material::default();
    let m_eff = 0.5 * mat.sphere_mass(R);
    let delta = 20e-9;
    let dz = 2.0 * R - delta;
    let h = Hertz::equal_spheres(R, &mat);
    let fn_ = h.force(delta);
    let a = (h.r_eff * delta).sqrt();
    let kt = 8.0 * m.tangential.g_star * a;
    let (dt, v) = (1e-11, 1e-2);
    let mut xi = [0.0; 3];
    let mut x = 0.0;
    let mut slid = false;
    for _ in 0..200_000 {
        x += v * dt;
        let o = m.pair([x, 0.0, dz], [v, 0.0, 0.0], &mut xi, m_eff, dt);
        // split the force on the dragged sphere into normal and tangential parts
        let nn = (x * x + dz * dz).sqrt();
        let n = [x / nn, 0.0, dz / nn];
        let f_n = o.force[0] * n[0] + o.force[2] * n[2];
        let f_tan = ((o.force[0] - f_n * n[0]).powi(2) + (o.force[2] - f_n * n[2]).powi(2)).sqrt();
        let stick = kt * x;
        if stick < 0.99 * mu * fn_ {
            // sticking: the elastic Mindlin spring
            assert!(
                (f_tan / stick - 1.0).abs() < 1e-3,
                "stick: {f_tan} vs {stick}"
            );
            assert!(!slid);
        } else if stick > 1.01 * mu * fn_ {
            slid = true;
            // sliding: Coulomb cap
            assert!(
                (f_tan / (mu * f_n) - 1.0).abs() < 1e-6,
                "slide: {f_tan} vs {}",
                mu * f_n
            );
        }
    }
    assert!(slid, "never reached sliding");
}

/// μ switches from μ1 to μ2 exactly when the contact's p0 crosses P_crit, and the contact is
/// flagged as failed from then on.
#[test]
fn mu_switches_exactly_at_p_crit() {
    let coating = Coating::default();
    let m = model(
        0.0,
        0.0,
        Friction::PressureSwitched(PressureSwitched::from(&coating)),
    );
    let mat = Material::default();
    let m_eff = 0.5 * mat.sphere_mass(R);
    let h = Hertz::equal_spheres(R, &mat);
    // p0 = (2E*/π)√(δ/R_eff) = P_crit at δ_c
    let dc = h.r_eff * (coating.p_crit * std::f64::consts::PI / (2.0 * h.e_star)).powi(2);
    for (delta, expect_mu, failed) in [
        (dc * (1.0 - 1e-9), coating.mu1, false),
        (dc * (1.0 + 1e-9), coating.mu2, true),
    ] {
        // one huge tangential step: the force is capped at μ F_n at once
        let mut xi = [0.0; 3];
        let o = m.pair(
            [0.0, 0.0, 2.0 * R - delta],
            [1.0, 0.0, 0.0],
            &mut xi,
            m_eff,
            1e-6,
        );
        assert_eq!(o.failed, failed);
        assert!((o.p0 / coating.p_crit - 1.0).abs() < 1e-8);
        let ratio = -o.force[0] / o.force[2];
        assert!(
            (ratio / expect_mu - 1.0).abs() < 1e-9,
            "{ratio} vs {expect_mu}"
        );
    }
}
