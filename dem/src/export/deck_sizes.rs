//! The parts of the LAMMPS deck ([`super::deck`]) that differ with per-site sphere sizes:
//! per-atom viscous drag `−m_i v/τ` (LAMMPS `fix viscous` takes one γ per type, and each atom's
//! mass now differs) and P_max from each (slider size, substrate size) class of pairs (each with
//! its own contact distance and R_eff). One size per body never reaches this file: its deck is
//! unchanged. Cost: O(S·B) deck lines for S slider and B substrate sizes.

use std::fmt::Write;

/// Per-site sizes in deck terms (LAMMPS micro units).
#[derive(Debug, Clone, PartialEq)]
pub struct DeckSizes {
    /// The distinct slider sphere diameters (µm), ascending.
    pub slider_diameters: Vec<f64>,
    /// The distinct substrate sphere diameters (µm), ascending.
    pub substrate_diameters: Vec<f64>,
    /// Mass-weighted mean anchor offset `Σ m_i (R − r_i)/Σ m_i` (µm) of the slider spheres: the
    /// deck's `z_um` is the slider's centre of mass less this (its reference plane).
    pub z_offset: f64,
    /// Viscous damping time τ (µs); `None` = off.
    pub tau: Option<f64>,
    /// Density (pg/µm³) of the slider's material: a class is picked out by its atoms' mass
    /// `ρ π d³/6` (the per-atom diameter is not an atom-style variable keyword).
    pub slider_density: f64,
    /// Density (pg/µm³) of the substrate's material (as `slider_density`).
    pub substrate_density: f64,
}

/// The distinct values of `v` (µm), ascending (equal to 10⁻⁹ relative are one).
pub fn distinct(v: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut d: Vec<f64> = v.collect();
    d.sort_by(f64::total_cmp);
    d.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * b.abs());
    d
}

/// A number as LAMMPS reads it (as [`super::deck`]).
fn n(x: f64) -> String {
    let t = format!("{x:?}");
    t.strip_suffix(".0").unwrap_or(&t).to_string()
}

/// The viscous drag lines: control spheres by `fix viscous` with `gamma_control` (pg/µs), the
/// substrate (x, y; absolute) and slider spheres (relative to the control layer's mean
/// velocity when `relative`) by `fix addforce` of atom-style `−mass·v/τ`.
pub fn viscous(s: &mut String, z: &DeckSizes, gamma_control: f64, relative: bool) {
    let Some(tau) = z.tau else {
        let _ = writeln!(s, "# no viscous damping (tau = infinity)");
        return;
    };
    let t = n(tau);
    let mut w = |l: String| {
        let _ = writeln!(s, "{l}");
    };
    w(
        "# 0 K Langevin-equivalent damping F = -m v / tau, each sphere with its own mass (per-site"
            .into(),
    );
    w("# sizes: fix viscous takes one gamma per type): control spheres by fix viscous, the others".into());
    w("# by atom-style variables".into());
    w(format!(
        "fix             visc ctrl viscous {}",
        n(gamma_control)
    ));
    w(format!("variable        dsbx atom -mass*vx/{t}"));
    w(format!("variable        dsby atom -mass*vy/{t}"));
    w("fix             dsub sub addforce v_dsbx v_dsby 0.0".into());
    if relative {
        w("# relative frame (the Rust default): slider spheres damped relative to the control layer's velocity".into());
        w("compute         vctrl ctrl reduce ave vx vy vz   # = vcm (equal masses), once per step".into());
        for (c, k) in ["x", "y", "z"].iter().zip(1..) {
            w(format!(
                "variable        dsl{c} atom -mass*(v{c}-c_vctrl[{k}])/{t}"
            ));
        }
    } else {
        for c in ["x", "y", "z"] {
            w(format!("variable        dsl{c} atom -mass*v{c}/{t}"));
        }
    }
    w("fix             dsl slider addforce v_dslx v_dsly v_dslz".into());
}

/// The P_max lines: one group per (slider diameter, substrate diameter) class, its pairs'
/// smallest distance, its largest p0 `(2E*/π)√((c − d_min)/R_eff)` with the class's own
/// contact distance c and R_eff, and `pmax_GPa` the largest over the classes. `pref` = 2E*/π
/// (GPa).
pub fn p_max(s: &mut String, z: &DeckSizes, pref: f64) {
    let mut w = |l: String| {
        let _ = writeln!(s, "{l}");
    };
    w("# per-site sizes: P_max per (slider size, substrate size) class of pairs, each with its own".into());
    w("# contact distance c = (d_sl + d_sb)/2 and R_eff".into());
    let group = |w: &mut dyn FnMut(String), name: &str, ty: u32, d: f64| {
        let rho = if ty == 1 {
            z.substrate_density
        } else {
            z.slider_density
        };
        let m = rho * std::f64::consts::PI / 6.0 * d * d * d;
        w(format!(
            "variable        is_{name} atom (type=={ty})&&(abs(mass-{})<{})   # diameter {} um",
            n(m),
            n(1e-6 * m),
            n(d)
        ));
        w(format!("group           {name} variable is_{name}"));
    };
    for (a, &da) in z.slider_diameters.iter().enumerate() {
        group(&mut w, &format!("sl{a}"), 2, da);
    }
    for (b, &db) in z.substrate_diameters.iter().enumerate() {
        group(&mut w, &format!("sb{b}"), 1, db);
    }
    let mut terms = Vec::new();
    for (a, &da) in z.slider_diameters.iter().enumerate() {
        for (b, &db) in z.substrate_diameters.iter().enumerate() {
            let (ra, rb) = (0.5 * da, 0.5 * db);
            let (c, r_eff) = (ra + rb, ra * rb / (ra + rb));
            let k = format!("{a}_{b}");
            w(format!("group           pc{k} union sl{a} sb{b}"));
            w(format!(
                "compute         cpl{k} pc{k} pair/local dist cutoff radius"
            ));
            w(format!("compute         dmin{k} pc{k} reduce min c_cpl{k}"));
            w(format!("compute         dsum{k} pc{k} reduce sum c_cpl{k}"));
            w(format!(
                "variable        p{k} equal (c_dsum{k}>0)*{}*sqrt((c_dmin{k}<{c})*({c}-c_dmin{k})/{})",
                n(pref),
                n(r_eff),
                c = n(c)
            ));
            terms.push(format!("v_p{k}"));
        }
    }
    // the largest class, accumulated in variables (no two-argument max in every LAMMPS)
    let mut prev = terms[0].clone();
    for (k, t) in terms.iter().enumerate().skip(1) {
        w(format!(
            "variable        pm{k} equal ({prev}>{t})*{prev}+({prev}<={t})*{t}"
        ));
        prev = format!("v_pm{k}");
    }
    w(format!("variable        pmax_GPa equal {prev}"));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distinct_diameters_and_the_class_lines() {
        assert_eq!(
            distinct([3.0, 2.0, 3.0, 2.0 + 1e-12].into_iter()),
            [2.0, 3.0]
        );
        let z = DeckSizes {
            slider_diameters: vec![2.0, 4.0],
            substrate_diameters: vec![3.0],
            z_offset: 0.1,
            tau: Some(1.0),
            slider_density: 1.0,
            substrate_density: 1.0,
        };
        let mut s = String::new();
        p_max(&mut s, &z, 1.0);
        assert!(
            s.contains("variable        pm1 equal (v_p0_0>v_p1_0)*v_p0_0+(v_p0_0<=v_p1_0)*v_p1_0"),
            "{s}"
        );
        assert!(s.contains("variable        pmax_GPa equal v_pm1"), "{s}");
        assert!(s.contains("c_dmin1_0<3.5"), "{s}");
        let mut s = String::new();
        viscous(&mut s, &z, 0.5, true);
        assert!(
            s.contains("variable        dslz atom -mass*(vz-c_vctrl[3])/1"),
            "{s}"
        );
    }
}
