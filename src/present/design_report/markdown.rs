//! `report.md`: [`TEMPLATE`] rendered over [`ReportData`].

use super::data::ReportData;
use crate::study::design::{DesignOutcome, DesignParams};
use anyhow::{Context, Result};
use minijinja::{AutoEscape, Environment, UndefinedBehavior};

/// The report's template: the prose and the layout; loops and ifs over [`ReportData`] only.
pub const TEMPLATE: &str = include_str!("report.md.j2");

/// `report.md` of the outcome `o`: [`TEMPLATE`] rendered over [`ReportData::new`].
/// Cost: one pass over the outcome, then the rendering (microseconds per line).
pub fn markdown(o: &DesignOutcome, p: &DesignParams) -> Result<String> {
    render(&ReportData::new(o, p))
}

/// [`TEMPLATE`] rendered over `data` (strict: a name the data lacks is an error).
pub fn render(data: &ReportData) -> Result<String> {
    let mut env = Environment::new();
    env.set_trim_blocks(true);
    env.set_lstrip_blocks(true);
    env.set_keep_trailing_newline(true);
    env.set_undefined_behavior(UndefinedBehavior::Strict);
    env.set_auto_escape_callback(|_| AutoEscape::None);
    env.add_template("report.md", TEMPLATE)
        .context("the report template does not parse")?;
    env.get_template("report.md")
        .and_then(|t| t.render(data))
        .context("rendering report.md")
}

#[cfg(test)]
mod tests {
    use super::super::data::*;
    use super::render;

    /// A one-pattern report's data: `dem` runs with the DEM section, `levels` shortlist levels.
    fn small(dem: bool, levels: usize) -> ReportData {
        let s = |v: &str| v.to_string();
        ReportData {
            made: super::super::stamp::Made {
                version: s("0.1.0"),
                date_utc: s("2026-11-28 12:55"),
                command: s("superlube design --pattern square-tri,tri-tri"),
            },
            limit_example: s("a limit of 0.09 mN means superlubric at 0.09 mN and at every load below it, and not at the next load tried, 0.1 mN"),
            patterns: s("square-tri, tri-tri"),
            loads_mn: s("0.01,0.09"),
            mu_superlubric: s("0.02"),
            top: vec![super::super::top::TopRow {
                pattern: s("square-tri"),
                theta: s("10 ± 0.1"),
                pull_x: s("146 ± 0.5"),
                alpha: s("146"),
                limit_mn: s("0.09"),
                verdict: s("superlubric"),
                dem_centre: s("held at 0.09 mN"),
                dem_corners: s("4 of 4 held at 0.09 mN"),
                nominal: s("the same design"),
                fab_yield: String::new(),
            }],
            answers: vec![
                s("**square-tri**: make the slider at θ = 10°"),
                s("**tri-tri**: no design"),
            ],
            runs: vec![super::super::top::AnswerRun {
                pattern: s("square-tri"),
                scene_file: s("answer_square-tri.toml"),
                slide: s("superlube slide --scene answer_square-tri.toml --alpha 146"),
                tolerance: s("superlube tolerance --scene answer_square-tri.toml"),
                export: s("superlube export-lammps --scene answer_square-tri.toml"),
            }],
            tolerance: s("θ ±0.1° × pull direction ±0.5°"),
            resonance_drop: s("2.8"),
            maps: vec![s("square-tri")],
            compared: vec![],
            fairness: String::new(),
            recipes: None,
            contact_maps: vec![],
            fab_yield: None,
            dem_ran: dem,
            dem: dem.then(|| DemSection {
                protocol: s("equilibrate 0.1 + relax 0.05 + slide 0.3 µs at 0.1 m/s"),
                study_protocol: false,
                model: s("reduced"),
                checks: vec![StudyCheck {
                    what: s("the recommended design"),
                    pattern: s("square-tri"),
                    theta_deg: s("10"),
                    alpha_deg: s("146"),
                    load_mn: s("0.09"),
                    measured: true,
                    mu_short: s("0.0105"),
                    mu_study: s("0.0100"),
                    difference_pct: s("+5.0"),
                    same: false,
                    short_verdict: s("not superlubric"),
                    study_verdict: s("superlubric"),
                    error: String::new(),
                }],
                unmeasured: false,
                rows: vec![DemLine {
                    pattern: s("square-tri"),
                    rank: 1,
                    theta_deg: s("10"),
                    alpha_deg: s("146"),
                    corner: s("–"),
                    load_mn: s("0.09"),
                    protocol: s("design"),
                    mu_est: s("0.0100"),
                    mu_dem: s("0.0105"),
                    ratio: s("0.949"),
                    verdict_est: s("superlubric"),
                    verdict_dem: s("not"),
                    max_p_max_gpa: s("3.19"),
                    contacts: s("3.00"),
                    status: s("locked-in"),
                    wall_s: s("1.00"),
                }],
                agree: 0,
                judged: 1,
                path_um: s("12"),
                slid_um: s("30"),
                resonance_drop: s("2.8"),
            }),
            ranking: vec![],
            sampling: if levels > 0 {
                s("θ ±0.1° sampled every 0.02° (11 offsets) × pull direction ±0.5° sampled every 0.25° (5 offsets)")
            } else {
                String::new()
            },
            band: s("borderline = μ_est in [0.0166, 0.0220)"),
            resonance: vec![],
            screens: vec![ScreenLine {
                pattern: s("square-tri"),
                symmetry: s("rotation orders 4 and 6"),
                thetas: 16,
                theta_first: s("0"),
                theta_last: s("15"),
                loads: 2,
                levels: (0..levels)
                    .map(|k| LevelLine {
                        load_mn: format!("0.0{}", 9 - k),
                        size: 9 - k,
                        kept: 5,
                        evaluated: k == 0,
                    })
                    .collect(),
                stop: s("every level evaluated"),
            }],
            walls: vec![],
            dem_wall: None,
            reproduce: vec![],
            slides: vec![s("superlube slide --pattern square-tri --theta 10")],
        }
    }

    /// trim_blocks eats the newline after a block tag: a line of text that ends with one
    /// (`… {% endif %}`) joins the next line of output (a bullet merged into the one before:
    /// "`yield_<p>.json`.- **DEM check**") unless an empty line follows it.
    #[test]
    fn no_line_of_text_ends_in_a_block_tag_that_eats_its_newline() {
        let lines: Vec<&str> = super::TEMPLATE.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            let t = l.trim();
            let inline_end = !t.starts_with("{%") && t.ends_with("%}");
            let next_empty = lines.get(i + 1).is_none_or(|n| n.trim().is_empty());
            assert!(
                !inline_end || next_empty,
                "report.md.j2 line {}: text ending in a block tag joins the next line of output: `{t}`",
                i + 1
            );
        }
    }

    #[test]
    fn the_template_renders_the_answer_first_and_each_branch() {
        let md = render(&small(false, 2)).unwrap();
        assert!(md.starts_with("# superlube design: square-tri, tri-tri\n\nMade by superlube 0.1.0 on 2026-11-28 12:55 UTC with `superlube design --pattern square-tri,tri-tri`\n\nLoads 0.01,0.09 mN."), "{md}");
        assert!(md.contains(
            "## Answer\n\n| pattern | θ (°) | pull from x (°) | pull from contact line α (°) | robust limit (mN) | verdict | DEM at the design | DEM at the box corners | nominal optimum |\n|---|---|---|---|---|---|---|---|---|\n| square-tri | 10 ± 0.1 | 146 ± 0.5 | 146 | 0.09 | superlubric | held at 0.09 mN | 4 of 4 held at 0.09 mN | the same design |\n\nThe DEM did not run (`--no-dem`): the answers are the surrogate's alone.\n\n**square-tri**: make the slider at θ = 10°\n\n**tri-tri**: no design\n\n"
        ), "{md}");
        assert!(md.contains("**square-tri** (`answer_square-tri.toml`):\n\n```sh\nsuperlube slide --scene answer_square-tri.toml --alpha 146\nsuperlube tolerance --scene answer_square-tri.toml\nsuperlube export-lammps --scene answer_square-tri.toml\n```\n\n![square-tri:"), "{md}");
        // the definitions once, in "How to read this", linked from the top
        assert!(md.contains("[How to read this](#how-to-read-this)"));
        assert_eq!(md.matches("## How to read this\n").count(), 1);
        assert_eq!(md.matches("borderline = μ_est").count(), 1, "{md}");
        assert_eq!(md.matches("verdict-band.md").count(), 1, "{md}");
        assert_eq!(md.matches("tilt mode is tuned").count(), 1, "{md}");
        assert!(
            md.contains("\n\nNot confirmed with the DEM (`--no-dem`)."),
            "{md}"
        );
        assert!(!md.contains("Confirmation protocol"));
        assert!(md.contains(
            "Screened 16 θ (0° … 15°) × 2 loads. Shortlist levels (coating intact up to W_c at the screened placement): 0.09 mN: 9 θ (5 kept, evaluated); 0.08 mN: 8 θ (5 kept). every level evaluated.\n\n## Wall time per tier"
        ), "{md}");
        assert!(md.contains("```sh\nsuperlube slide --pattern square-tri --theta 10\n```\n"));
        assert!(
            md.ends_with("(\"Files … and columns\") in the superlube sources.\n"),
            "{md}"
        );
        assert!(!md.contains("README"));
        assert!(!md.contains("{{") && !md.contains("{%"));
        assert!(
            !md.contains("Patterns compared") && !md.contains("\n\n\n"),
            "{md}"
        );
    }

    /// The ranking section states the order of the score, the box's sampling and the band's
    /// source, and its table carries the robust and nominal limits, the windows and the
    /// verdict, with an upper bound marked "≤".
    #[test]
    fn the_ranking_table_has_the_robust_score() {
        let s = |v: &str| v.to_string();
        let mut d = small(false, 2);
        let line = |rank: usize, to: &str, exact_window: &str| RankingLine {
            pattern: s("square-tri"),
            rank,
            theta_deg: s("10"),
            alpha_deg: s("90"),
            pull_deg: s("90.0"),
            superlubric_to_mn: s(to),
            nominal_mn: s("0.09"),
            theta_window_deg: s(exact_window),
            direction_window_deg: s(exact_window),
            verdict: s("borderline"),
            mu_worst: s("0.0150"),
            contacts: s("12.0"),
            intact_to_mn: s("0.09"),
            screen_intact_to_mn: s("0.09"),
            corrugation_nm: s("0.100"),
            reason: s("survives the highest load"),
        };
        d.ranking = vec![line(1, "0.06", "±0.1"), line(2, "≤ 0.03", "–")];
        let md = render(&d).unwrap();
        let sec = &md[md.find("## Ranking").unwrap()..md.find("## Screen and shortlist").unwrap()];
        let order = [
            "robust limit",
            "θ window",
            "direction window",
            "μ_est",
            "contact number",
        ];
        let at: Vec<usize> = order
            .iter()
            .map(|w| sec.find(w).unwrap_or_else(|| panic!("{w}: {sec}")))
            .collect();
        assert!(at.windows(2).all(|w| w[0] < w[1]), "{sec}");
        assert!(sec.contains("over the tolerance box"), "{sec}");
        assert!(
            sec.contains("[How to read this](#how-to-read-this)"),
            "{sec}"
        );
        let how = &md[md.find("## How to read this").unwrap()..md.find("## How sure").unwrap()];
        assert!(how.contains("θ ±0.1° sampled every 0.02°"), "{how}");
        assert!(how.contains("docs/validation/verdict-band.md"), "{how}");
        assert!(!sec.contains("(1) highest load"), "{sec}");
        assert!(sec.contains("| superlubric to, robust (mN) | nominal (mN) | θ window (°) | direction window (°) | verdict |"), "{sec}");
        assert!(
            sec.contains("| 90.0 | 0.06 | 0.09 | ±0.1 | ±0.1 | borderline | 0.0150 |"),
            "{sec}"
        );
        assert!(
            sec.contains("| 90.0 | ≤ 0.03 | 0.09 | – | – | borderline |"),
            "{sec}"
        );
        // the files: the tolerance maps are named where there are any
        assert!(
            md.contains("`tolerance_<p>.csv` and `tolerance_<p>.png`"),
            "{md}"
        );
        d.maps.clear();
        d.sampling.clear();
        d.tolerance.clear();
        let md = render(&d).unwrap();
        assert!(!md.contains("tolerance_<p>.csv"));
        assert!(md.contains("(no tolerance: 0)"), "{md}");
    }

    #[test]
    fn patterns_are_compared_in_one_table_when_there_are_several() {
        let s = |v: &str| v.to_string();
        let mut d = small(false, 0);
        d.fairness = s("Compared at equal slider area.");
        d.compared = vec![super::super::patterns::PatternLine {
            rank: 1,
            pattern: s("p001"),
            outline: s("disc r=100"),
            spheres: 3505,
            slider_area_um2: s("31416"),
            theta_deg: s("0"),
            alpha_deg: s("90"),
            superlubric_to_mn: s("3.86"),
            nominal_mn: s("3.86"),
            mean_pressure_kpa: s("123"),
            load_per_sphere_un: s("1.10"),
            contact_type: s("directional"),
        }];
        d.contact_maps = vec![s("p001")];
        let md = render(&d).unwrap();
        assert!(md.contains("](patterns.png)"), "{md}");
        assert!(md.contains("](contacts_p001.png)"), "{md}");
        assert!(
            md.contains("outline area at the robust limit. Compared at equal slider area.\n"),
            "{md}"
        );
        assert!(md.contains("|---|\n| 1 | p001 | disc r=100 | 3505 | 31416 | 0 | 90 | 3.86 | 3.86 | 123 | 1.10 | directional |\n\n!["), "{md}");
        assert!(!md.contains("\n\n\n"), "{md}");
    }

    /// "How to read this" defines the axes, θ = 0, the pull direction's sense and what a limit
    /// between two loads of the ladder means, in the report itself; the answer table says which
    /// DEM protocol and model its DEM columns ran, or that the DEM did not run.
    #[test]
    fn the_report_defines_its_angles_and_names_the_dem_protocol() {
        for dem in [false, true] {
            let md = render(&small(dem, 0)).unwrap();
            let how = &md[md.find("## How to read this").unwrap()..md.find("## How sure").unwrap()];
            for needle in [
                "x runs along the substrate's first side",
                "At **θ = 0** the slider's lattice vector a₁",
                "lies along the substrate's a₁ row, that is along x",
                "θ > 0 turns the slider counter-clockwise seen from above",
                "0° moves the slider towards +x, 90° towards +y",
                "pull = contact line + α",
                "ladder (0.01,0.09 mN)",
                "not at the next load tried, 0.1 mN: the true limit lies between the two",
            ] {
                assert!(how.contains(needle), "{needle}: {how}");
            }
            let top = &md[md.find("## Answer").unwrap()..md.find("## How to read this").unwrap()];
            if dem {
                assert!(top.contains("The DEM columns are Tier 3 DEM runs of equilibrate 0.1 + relax 0.05 + slide 0.3 µs at 0.1 m/s (shorter than the study's 10 + 10 + 300 µs; its measured difference: [How sure](#how-sure-surrogate-estimate-against-the-dem)); DEM model: reduced.\n"), "{top}");
            } else {
                assert!(top.contains("The DEM did not run (`--no-dem`)"), "{top}");
            }
            // the only repository paths are "more: …" pointers
            for l in md.lines().filter(|l| l.contains("docs/")) {
                assert!(l.contains("in the superlube sources"), "{l}");
            }
        }
    }

    #[test]
    fn the_dem_section_has_the_check_and_one_row_per_run() {
        let md = render(&small(true, 0)).unwrap();
        assert!(md.contains("— **shorter than the study's** (model and reductions: reduced)."));
        assert!(md.contains(": μ = 0.0105 (short) vs 0.0100 (study protocol): +5.0 %; **the DEM verdicts differ**: not superlubric (short) vs superlubric (study protocol).\n\n"), "{md}");
        assert!(md.contains("\n| square-tri | 1 | 10 | 146 | – | 0.09 | design | 0.0100 | 0.0105 | 0.949 | superlubric / not | 3.19 | 3.00 | locked-in | 1.00 |\n\nVerdicts agree on 0 of 1 runs"), "{md}");
        assert!(md.contains("covers 12 µm where the study's DEM slides 30 µm"));
        assert!(md.contains("up to 2.8× below μ_est"));
        assert!(md.contains("placement): none. every level"), "{md}");
        assert!(!md.contains("Not confirmed with the DEM"));
    }
}
