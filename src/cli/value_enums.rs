//! Command-line spellings of the study's enums. `src/study/` stays free of clap: the enums live
//! there as plain types and get their `clap::ValueEnum` here (names and help as `--help` shows
//! them).

use clap::builder::PossibleValue;
use clap::ValueEnum;

use crate::study::campaign::Fig;
use crate::study::corrugation::Method;
use crate::study::fairness::Fairness;
use crate::study::figures::Group;
use crate::study::work_precision::Tier;

impl ValueEnum for Method {
    fn value_variants<'a>() -> &'a [Self] {
        &[Method::Direct, Method::Landscape]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self {
            Method::Direct => PossibleValue::new("direct").help(
                "A solver call at every sample along the path (exact up to the sampling step)",
            ),
            Method::Landscape => PossibleValue::new("landscape").help(
                "Bicubic interpolation of one periodic landscape (fast; flat substrates only; the \
                 lateral force is the rigid-limit W·dz/ds)",
            ),
        })
    }
}

impl ValueEnum for Group {
    fn value_variants<'a>() -> &'a [Self] {
        &[
            Group::Sweep,
            Group::Contacts,
            Group::Landscapes,
            Group::Corrugation,
        ]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self {
            Group::Sweep => PossibleValue::new("sweep")
                .help("Contacts and P_max versus θ (tri-tri, square-tri)"),
            Group::Contacts => PossibleValue::new("contacts").help("Contact maps at 1.4 mN"),
            Group::Landscapes => {
                PossibleValue::new("landscapes").help("Δz landscapes of square-tri at 0° and 10.2°")
            }
            Group::Corrugation => {
                PossibleValue::new("corrugation").help("Corrugation versus α for square-tri")
            }
        })
    }
}

impl ValueEnum for Fig {
    fn value_variants<'a>() -> &'a [Self] {
        &[Fig::F2b, Fig::F6, Fig::F7]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self {
            Fig::F2b => PossibleValue::new("2b").help("Fig 2b: tri-tri θ = 0°, 21.8°, 30°"),
            Fig::F6 => PossibleValue::new("6")
                .help("Fig 6: square-tri θ = 0°, 10.2° at α = 0°, 90°, with the tri-tri series"),
            Fig::F7 => PossibleValue::new("7")
                .help("Fig 7: imperfect substrates (σ_h = 0.002, 0.01 µm; E = 100, 50 GPa)"),
        })
    }
}

impl ValueEnum for Fairness {
    fn value_variants<'a>() -> &'a [Self] {
        &[Fairness::Area, Fairness::Count]
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        let v = PossibleValue::new(self.name());
        Some(match self {
            Fairness::Area => {
                v.help("Every candidate keeps the base slider's outline: equal slider area (µm²)")
            }
            Fairness::Count => v.alias("spheres").help(
                "Each candidate's outline is scaled to hold the base slider's sphere count (the \
                 closest its lattice allows)",
            ),
        })
    }
}

impl ValueEnum for Tier {
    fn value_variants<'a>() -> &'a [Self] {
        &Tier::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        let v = PossibleValue::new(self.name());
        Some(match self {
            Tier::ScreenMap => v.help("Solver model, landscape grid, corrugation path step"),
            Tier::Friction => v.help(
                "Friction estimate: path step, length, transverse search, inertial starts, segment",
            ),
            Tier::Tolerance => v.help("Tolerance search: θ and direction sampling steps"),
            Tier::Dem => v.help("DEM: step, model, tangential history, window, active set"),
            Tier::Tiers => v.help(
                "The tiers on one diagram: screen, estimate, DEM, LAMMPS against the best reference",
            ),
        })
    }
}
