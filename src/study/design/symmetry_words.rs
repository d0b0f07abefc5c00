//! The symmetry cut in words: the log's and report's sentences about a pair's symmetry
//! ([`SymmetryWords`]). The geometry (rotation orders, mirrors, the fundamental domain, the
//! α period) is the scene model's: [`surrogate::scene::symmetry`].
//!
//! The design's cut keeps the θ values of `--theta` that lie in the domain; nothing left is an
//! error naming `--theta` with the domain. It is exact for a flat substrate with the slider
//! centred on a site; with σ_h > 0 or an offset the design says so in its log, and
//! `--no-symmetry-cut` screens the range as given.

pub use surrogate::scene::symmetry::{
    gcd, rotation_order, Domain, LatticeSymmetry, NotDerived, PairSymmetry,
};

/// The sentences about a [`PairSymmetry`] that the log and the report print.
pub trait SymmetryWords {
    /// The gaps of [`PairSymmetry::unscreened`] in words: `30°–60°`, `350°–360° and 0°–10°`.
    fn gaps_text(&self, gaps: &[(f64, f64)]) -> String;
    /// One line describing the symmetry, e.g. `period 30°, mirror θ → −θ: domain [0°, 15°];
    /// α period 180°`.
    fn describe(&self) -> String;
}

impl SymmetryWords for PairSymmetry {
    fn gaps_text(&self, gaps: &[(f64, f64)]) -> String {
        let Domain {
            lo_deg: lo,
            hi_deg: hi,
            ..
        } = self.domain();
        gaps.iter()
            .map(|&(a, b)| {
                if b > hi + 1e-9 {
                    format!(
                        "{}°–{}° and {}°–{}°",
                        fmt(a),
                        fmt(hi),
                        fmt(lo),
                        fmt(b - (hi - lo))
                    )
                } else {
                    format!("{}°–{}°", fmt(a), fmt(b))
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn describe(&self) -> String {
        if let Some(why) = &self.not_derived {
            let why = not_derived_text(why);
            return format!(
                "symmetry not derived ({why}): no symmetry cut, the domain is the full θ range [0°, 360°); α period 360°"
            );
        }
        let Domain {
            lo_deg: lo,
            hi_deg: hi,
            closed,
        } = self.domain();
        format!(
            "rotation orders {} (slider) and {} (substrate): θ period {}°, {}: domain [{}°, {}°{}; α period {}°",
            self.slider_order,
            self.substrate_order,
            fmt(self.period_deg),
            match self.mirror_deg {
                Some(0.0) => "mirror θ → −θ".to_string(),
                Some(c) => format!("mirror θ → {}° − θ", fmt(2.0 * c)),
                None => "no mirror".to_string(),
            },
            fmt(lo),
            fmt(hi),
            if closed { "]" } else { ")" },
            fmt(self.alpha_period_deg)
        )
    }
}

/// Why the symmetry was not derived, in words (`the substrate comes from the site file …`).
pub fn not_derived_text(why: &NotDerived) -> String {
    match why {
        NotDerived::SubstrateSites(path) => {
            format!("the substrate comes from the site file `{path}`")
        }
        NotDerived::SliderSizes(path) => {
            format!("the slider's spheres differ in size (per-site diameters of `{path}`)")
        }
    }
}

/// A degree value without binary noise (`15`, `22.5`).
pub fn fmt(v: f64) -> String {
    let r = (v * 1e9).round() / 1e9;
    format!("{r}")
}

#[cfg(test)]
mod geometry_tests {
    use super::*;
    use surrogate::{Lattice, Scene};

    fn scene(toml: &str) -> Scene {
        surrogate::SceneFile::from_toml(toml, "t.toml")
            .unwrap()
            .into_scene()
            .unwrap()
    }

    #[test]
    fn basis_outline_and_site_files_set_the_cut() {
        // plain presets: unchanged
        let p = Scene::preset("square-tri").unwrap();
        assert!(PairSymmetry::of(&p.slider.lattice, &p.substrate.lattice)
            .describe()
            .contains("[0°, 15°]"));
        assert_eq!(
            PairSymmetry::of_scene(&p),
            PairSymmetry::of(&p.slider.lattice, &p.substrate.lattice)
        );
        // a honeycomb site has rotation order 3 (its 6-fold axis is at the hexagon centre)
        let h = scene("pattern = 'tri-tri'\n[slider]\nradius_um = 30\nsphere_diameter_um = 1.5\nlattice = { kind = 'honeycomb', spacing_um = 3.0 }\n");
        let s = PairSymmetry::of_scene(&h);
        assert_eq!((s.slider_order, s.substrate_order), (3, 6));
        assert_eq!(s.period_deg, 60.0);
        assert!(s.not_derived.is_none());
        // a 30x21 µm pad of a square lattice: order 2 with mirrors along x and y; with the
        // square substrate's 4-fold rotation the period is 90°, the domain [0°, 45°]
        let r = scene("pattern = 'square-square'\n[slider]\noutline = { kind = 'rectangle', size_um = [30, 21] }\n");
        let s = PairSymmetry::of_scene(&r);
        assert_eq!(s.slider_order, 2);
        assert_eq!((s.period_deg, s.mirror_deg), (90.0, Some(0.0)));
        let d = s.domain();
        assert_eq!((d.lo_deg, d.hi_deg, d.closed), (0.0, 45.0, true));
        // a substrate from a site file: no cut, said so
        let dir = std::env::temp_dir().join(format!("sym-sites-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let f = dir.join("sub.csv");
        std::fs::write(&f, "x_um,y_um\n0,0\n3,0\n0,3\n3,3\n7,1\n").unwrap();
        let t = scene(&format!(
            "[slider]\nradius_um = 3\n[substrate]\nsize_um = [20, 20]\nsites = '{}'\n",
            f.display()
        ));
        let s = PairSymmetry::of_scene(&t);
        assert!(s.not_derived.is_some() && s.contains(-75.0) && s.contains(300.0));
        assert!(s.describe().contains("full θ range"), "{}", s.describe());
        assert!(!s.describe().contains("screened"), "{}", s.describe());
        // a slider site file of a plus-shaped pattern: order 4 with equal diameters; with one
        // larger arm sphere (per-site sizes) the symmetry is not derived (no cut)
        let sl = |name: &str, d: [&str; 2]| {
            let f = dir.join(name);
            let mut text = String::from("x_um,y_um,diameter_um\n");
            for (k, (x, y)) in [(0, 0), (6, 0), (0, 6), (-6, 0), (0, -6)]
                .iter()
                .enumerate()
            {
                text += &format!("{x},{y},{}\n", d[usize::from(k == 1)]);
            }
            std::fs::write(&f, text).unwrap();
            scene(&format!(
                "pattern = 'square-square'\n[substrate]\nsize_um = [40, 40]\n[slider]\nsites = '{}'\n",
                f.display()
            ))
        };
        let s = PairSymmetry::of_scene(&sl("equal.csv", ["3", "3"]));
        assert_eq!((s.slider_order, s.not_derived.is_none()), (4, true));
        let s = PairSymmetry::of_scene(&sl("sizes.csv", ["3", "4"]));
        assert!(
            matches!(s.not_derived, Some(NotDerived::SliderSizes(_))),
            "{s:?}"
        );
        assert!(s.describe().contains("differ in size"), "{}", s.describe());
    }

    /// The θ lists that leave part of the domain out are found, with the part named.
    #[test]
    fn unscreened_parts_of_the_domain() {
        let r = |t: &str| crate::study::range::parse_list_or_range(t, "--theta").unwrap();
        let t = Lattice::triangular(3e-6);
        let st = PairSymmetry::of(&Lattice::square(3e-6), &t);
        // square-tri [0°, 15°]: the study's list (cut) and a coarse list span it
        let cut: Vec<f64> = r("0:30:0.1")
            .into_iter()
            .filter(|&x| st.contains(x))
            .collect();
        assert!(st.unscreened(&cut).is_empty());
        assert!(st.unscreened(&r("0:30:0.1")).is_empty(), "folded, uncut");
        assert!(st.unscreened(&r("0,5,15")).is_empty());
        // a list stopping short of 15°, one starting late, a single θ
        assert_eq!(st.unscreened(&r("0:14:0.5")), vec![(14.0, 15.0)]);
        assert_eq!(st.unscreened(&r("3:15:1")), vec![(0.0, 3.0)]);
        assert_eq!(st.unscreened(&[7.0]), vec![(0.0, 7.0), (7.0, 15.0)]);
        // an oblique slider on a triangle: [0°, 60°) without a mirror; 0:30 covers half
        let o = PairSymmetry::of(&Lattice::oblique([3e-6, 0.0], [1.0e-6, 2.8e-6]), &t);
        let g = o.unscreened(&r("0:30:0.1"));
        assert_eq!(g.len(), 1);
        assert!(
            (g[0].0 - 30.0).abs() < 1e-9 && (g[0].1 - 60.0).abs() < 1e-9,
            "{g:?}"
        );
        let whole: Vec<f64> = r("0:60:0.1")
            .into_iter()
            .filter(|&x| o.contains(x))
            .collect();
        assert!(o.unscreened(&whole).is_empty());
        // around the period: −10°..10° leaves 10°–50° out
        let g = o.unscreened(&r("-10:10:1"));
        assert_eq!(g.len(), 1);
        assert!(
            (g[0].0 - 10.0).abs() < 1e-9 && (g[0].1 - 50.0).abs() < 1e-9,
            "{g:?}"
        );
        // not derived: the domain is [0°, 360°); 0:30 leaves 30°–360° out
        let mut nd = o.clone();
        nd.not_derived = Some(NotDerived::SubstrateSites("test".into()));
        nd.period_deg = 360.0;
        nd.mirror_deg = None;
        let g = nd.unscreened(&r("0:30:0.1"));
        assert_eq!(nd.gaps_text(&g), "30°–360°");
        // a gap through the period's end is named in two parts
        assert_eq!(
            nd.gaps_text(&nd.unscreened(&r("10:300:1"))),
            "300°–360° and 0°–10°"
        );
        assert!(nd.unscreened(&r("0:359.75:0.25")).is_empty());
    }
}
