//! Plausible ranges of the physical inputs, in the units users type them in (µm, mN, GPa, µs,
//! N/m, m/s, g/cm³). A value outside its range is almost always a unit slip (E typed in Pa,
//! P_crit in MPa, a diameter in metres): it is refused before any work, naming the field or
//! flag, the unit, the range and its reason, and the value the likely slip would give.
//! Every range lets every meaningful value through; each one's reason is on `docs/inputs.md`,
//! which a test checks against this table ([`ALL`]).

use crate::error::SceneError;
use crate::units::significant;

/// `v` (user units) checked against the plausible range `p`, as the scene checks do (`material.rs`, `validate.rs`); the error names `field`.
pub(crate) fn plausible_field(field: &str, p: &Plausible, v: f64) -> Result<(), SceneError> {
    p.check(v)
        .map_err(|why| SceneError::invalid(field, significant(v, 9), &why))
}

/// One plausible range in user units, with the physical reason for its ends and the unit
/// slips it recognises. Cost of a check: O(number of slips).
#[derive(Debug, Clone, Copy)]
pub struct Plausible {
    /// What the value is, for messages: `Young's modulus E`.
    pub quantity: &'static str,
    /// The unit the user types it in: `GPa`.
    pub unit: &'static str,
    /// Smallest plausible value (inclusive), in `unit`.
    pub min: f64,
    /// Largest plausible value (inclusive), in `unit`.
    pub max: f64,
    /// Why the range ends where it does (one sentence, for messages and `docs/inputs.md`).
    pub reason: &'static str,
    /// Likely slips: (power of ten that turns the typed value into `unit`, the unit it was
    /// typed in). The first whose correction lands in the range is suggested.
    pub slips: &'static [(i32, &'static str)],
}

impl Plausible {
    /// Whether `v` (in [`Plausible::unit`]) lies in the range (a NaN does not).
    pub fn contains(&self, v: f64) -> bool {
        v >= self.min && v <= self.max
    }

    /// The likely slip of an out-of-range `v`: the corrected value (in `unit`, 6 significant
    /// digits) and the unit it was probably typed in.
    pub fn slip(&self, v: f64) -> Option<(f64, &'static str)> {
        self.slips.iter().find_map(|&(p, typed)| {
            let c = crate::units::significant(v * 10f64.powi(p), 6);
            self.contains(c).then_some((c, typed))
        })
    }

    /// `Ok` when `v` (in `unit`) is plausible, else the reason for a message after the field
    /// or flag name: "P_crit is in GPa; 4000 GPa is above the plausible 0.001–100 GPa (…);
    /// did you mean 4 GPa (typed in MPa)?".
    pub fn check(&self, v: f64) -> Result<(), String> {
        if self.contains(v) {
            return Ok(());
        }
        let side = if v > self.max { "above" } else { "below" };
        let mut why = format!(
            "{} is in {unit}; {} {unit} is {side} the plausible {} ({})",
            self.quantity,
            number(v),
            self.range_text(),
            self.reason,
            unit = self.unit
        );
        if let Some((c, typed)) = self.slip(v) {
            why.push_str(&format!(
                "; did you mean {} {} (the value typed in {typed})?",
                number(c),
                self.unit
            ));
        }
        Err(why)
    }

    /// The range as `docs/inputs.md` and the messages write it: `0.001 to 100 GPa`.
    pub fn range_text(&self) -> String {
        format!("{} to {} {}", number(self.min), number(self.max), self.unit)
    }
}

/// `v` as message text: plain decimals between 1e-3 and 1e5, `1e-9` / `1e10` style outside.
pub fn number(v: f64) -> String {
    if v != 0.0 && v.is_finite() && !(1e-3..1e5).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// Young's modulus E of the spheres, GPa.
pub const YOUNGS_GPA: Plausible = Plausible {
    quantity: "Young's modulus E",
    unit: "GPa",
    min: 1e-4,
    max: 1300.0,
    reason: "from the softest elastomer spheres, about 0.1 MPa, to diamond, about 1200 GPa",
    slips: &[(-3, "MPa"), (-9, "Pa"), (-6, "kPa")],
};

/// Density of the spheres, g/cm³.
pub const DENSITY_G_CM3: Plausible = Plausible {
    quantity: "the density",
    unit: "g/cm³",
    min: 0.01,
    max: 25.0,
    reason: "from aerogel, 0.01 g/cm³, to osmium, 22.6 g/cm³",
    slips: &[(-3, "kg/m³")],
};

/// Coating strength P_crit, GPa.
pub const P_CRIT_GPA: Plausible = Plausible {
    quantity: "P_crit",
    unit: "GPa",
    min: 1e-3,
    max: 100.0,
    reason: "a coating failing below 1 MPa carries nothing; none is stronger than diamond's \
             hardness, about 100 GPa",
    slips: &[(-3, "MPa"), (-9, "Pa"), (-6, "kPa")],
};

/// Sphere diameters, µm.
pub const DIAMETER_UM: Plausible = Plausible {
    quantity: "a sphere diameter",
    unit: "µm",
    min: 0.01,
    max: 1000.0,
    reason: "patterned spheres from 10 nm (below it a sphere is a cluster, not a Hertz \
             contact) to 1 mm",
    slips: &[(3, "mm"), (6, "m"), (-3, "nm")],
};

/// Nearest-site spacing of a lattice, µm (its lower end is the sphere diameter, checked apart).
pub const SPACING_UM: Plausible = Plausible {
    quantity: "a lattice spacing",
    unit: "µm",
    min: 0.01,
    max: 1000.0,
    reason: "at least the smallest sphere's 10 nm; a site per mm² leaves no patterned contact",
    slips: &[(3, "mm"), (6, "m"), (-3, "nm")],
};

/// Substrate side lengths and the slider radius, µm.
pub const SIZE_UM: Plausible = Plausible {
    quantity: "a slider or substrate size",
    unit: "µm",
    min: 0.0,
    max: 1e5,
    reason: "up to a 100 mm wafer",
    slips: &[(-3, "nm")],
};

/// Substrate roughness σ_h, µm (its upper end is the sphere radius, checked apart).
pub const SIGMA_H_UM: Plausible = Plausible {
    quantity: "σ_h",
    unit: "µm",
    min: 0.0,
    max: 100.0,
    reason: "non-negative and below the sphere radius; the study uses 0.002 and 0.01 µm",
    slips: &[(-3, "nm")],
};

/// The mount's tilt springs K1, N/m.
pub const TILT_K1_N_M: Plausible = Plausible {
    quantity: "the tilt spring K1",
    unit: "N/m",
    min: 0.0,
    max: 1e10,
    reason: "the study's is 1e6 N/m; past 1e10 N/m a spring is stiffer than the spheres' own \
             contacts by orders of magnitude",
    slips: &[],
};

/// Normal loads, mN.
pub const LOAD_MN: Plausible = Plausible {
    quantity: "the load",
    unit: "mN",
    min: 0.0,
    max: 1e4,
    reason: "the study uses 0.35 to 3.86 mN; 10 N on one patterned slider is beyond any \
             microtribometer and crushes micrometre spheres",
    slips: &[(-3, "µN"), (-6, "nN")],
};

/// Pulling speeds, m/s.
pub const SPEED_M_S: Plausible = Plausible {
    quantity: "the pulling speed",
    unit: "m/s",
    min: 0.0,
    max: 10.0,
    reason: "the study pulls at 0.1 m/s; past 10 m/s contacts flash-heat and the coating's \
             quasi-static law no longer holds",
    slips: &[(-6, "µm/s"), (-3, "mm/s")],
};

/// Durations of a DEM protocol (equilibrate, relax, slide, sampling), µs.
pub const DURATION_US: Plausible = Plausible {
    quantity: "a duration",
    unit: "µs",
    min: 1e-5,
    max: 1e6,
    reason: "at least one study time step (1e-5 µs); a second of DEM is 1e11 of those steps",
    slips: &[(-3, "ns")],
};

/// The DEM time step, µs.
pub const DT_US: Plausible = Plausible {
    quantity: "the time step",
    unit: "µs",
    min: 1e-9,
    max: 1.0,
    reason: "the study's step is 1e-5 µs; one as long as the 1 µs damping time integrates \
             nothing",
    slips: &[(6, "s"), (-3, "ns")],
};

/// Spring constants of the pulling spring (K0), N/m.
pub const SPRING_N_M: Plausible = Plausible {
    quantity: "the pulling spring",
    unit: "N/m",
    min: 0.0,
    max: 1e8,
    reason: "the study's K0 is 50 N/m; past 1e8 N/m the spring is stiffer than the contacts \
             it measures",
    slips: &[],
};

/// Every range, with the names it is checked under (scene fields, then flags), in the order
/// of `docs/inputs.md`.
pub const ALL: [(&str, Plausible); 13] = [
    ("material.youngs_GPa, --youngs-gpa", YOUNGS_GPA),
    ("material.density_g_cm3", DENSITY_G_CM3),
    ("coating.p_crit_GPa, --p-crit-gpa", P_CRIT_GPA),
    (
        "sphere_diameter_um, --slider/substrate-sphere-diameter-um",
        DIAMETER_UM,
    ),
    (
        "slider/substrate.lattice spacing, --slider-lattice",
        SPACING_UM,
    ),
    (
        "substrate.size_um, slider.radius_um, --substrate-um, --slider-radius-um",
        SIZE_UM,
    ),
    ("substrate.sigma_h_um, --sigma-h-um", SIGMA_H_UM),
    ("slider.tilt_k1_N_m, --tilt-k1-n-m", TILT_K1_N_M),
    ("--load-mn and every load list", LOAD_MN),
    ("--speed-m-s, --dem-speed-m-s", SPEED_M_S),
    (
        "--equilibrate/relax/slide/sample-us, --dem-…-us",
        DURATION_US,
    ),
    ("--dt-us, --dem-dt-us", DT_US),
    ("--k0-n-m", SPRING_N_M),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slips_are_named_with_the_value_they_would_give() {
        let e = P_CRIT_GPA.check(4000.0).unwrap_err();
        assert!(
            e.contains("P_crit is in GPa") && e.contains("did you mean 4 GPa") && e.contains("MPa"),
            "{e}"
        );
        let e = YOUNGS_GPA.check(1e11).unwrap_err();
        assert!(
            e.contains("did you mean 100 GPa") && e.contains("Pa)"),
            "{e}"
        );
        let e = DIAMETER_UM.check(3e-6).unwrap_err();
        assert!(
            e.contains("did you mean 3 µm") && e.contains("in m)"),
            "{e}"
        );
        assert!(DENSITY_G_CM3
            .check(2200.0)
            .unwrap_err()
            .contains("2.2 g/cm³"));
        assert!(LOAD_MN.check(f64::NAN).is_err());
    }

    /// `docs/inputs.md` states every range as the code has it, with its reason.
    #[test]
    fn the_inputs_page_states_every_range() {
        let page = include_str!("../../../docs/inputs.md");
        for (names, p) in ALL {
            let first = names.split(',').next().unwrap();
            let range = format!("| {} |", p.range_text());
            assert!(
                page.lines()
                    .any(|l| l.contains(&range) && l.contains(first) && l.contains(p.reason)),
                "docs/inputs.md: no row with `{first}`, `{range}` and the reason"
            );
        }
    }

    #[test]
    fn the_study_values_are_plausible() {
        // SPEC.md: E 100 and 50 GPa, ρ 2.2 g/cm³, P_crit 4 GPa, d 3 µm, spacing 3 µm,
        // substrate 364 × 270 µm, σ_h 0.002 / 0.01 µm, K1 1e6 N/m, loads 0.35–3.86 mN,
        // 0.1 m/s, 10 / 300 µs, dt 1e-5 µs, K0 50 N/m
        for (p, v) in [
            (YOUNGS_GPA, 100.0),
            (YOUNGS_GPA, 50.0),
            (DENSITY_G_CM3, 2.2),
            (P_CRIT_GPA, 4.0),
            (DIAMETER_UM, 3.0),
            (SPACING_UM, 3.0),
            (SIZE_UM, 364.0),
            (SIGMA_H_UM, 0.002),
            (TILT_K1_N_M, 1e6),
            (LOAD_MN, 0.35),
            (LOAD_MN, 3.86),
            (SPEED_M_S, 0.1),
            (DURATION_US, 300.0),
            (DT_US, 1e-5),
            (SPRING_N_M, 50.0),
        ] {
            assert!(p.check(v).is_ok(), "{} {v}", p.quantity);
        }
    }
}
