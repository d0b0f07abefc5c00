//! The deck's contact law from the [`crate::ContactParams`] part and the scene's materials:
//! `pair_style granular` (Hertz + Mindlin + damping + constant μ) and the neighbour list.

use super::number::N;
use crate::export::damping::LammpsDamping;
use std::fmt::Write;

/// The contact law in deck terms (LAMMPS micro units): the materials, the damping of
/// [`crate::ContactParams`] as LAMMPS expresses it, the constant μ and the sizes for P_max.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckContact {
    /// Young's modulus (10³ Pa) of the slider's material (of both bodies' when `pair` is
    /// `None`).
    pub youngs: f64,
    /// Poisson ratio (–) of the slider's material.
    pub poisson: f64,
    /// The slider–substrate pair's own coefficients when the two bodies' materials differ;
    /// `None`: one material.
    pub pair: Option<DeckPair>,
    /// Contact damping.
    pub damping: LammpsDamping,
    /// Constant friction coefficient.
    pub mu: f64,
    /// Contact distance R_sl + R_sb (µm; 2R for one sphere size), R_eff (µm), 2E*/π (GPa) for
    /// P_max.
    pub contact_distance: f64,
    /// R_eff (µm).
    pub r_eff: f64,
    /// 2E*/π (GPa).
    pub p0_prefactor_gpa: f64,
}

/// The slider–substrate pair's coefficients when the bodies' materials differ (LAMMPS micro
/// units): an explicit `pair_coeff 1 2` whose `hertz/material` gives the pair's Hertz
/// `E* = E/(2(1 − ν²))` at the slider's ν, and whose Mindlin stiffness is the pair's `8G*`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckPair {
    /// `2(1 − ν_sl²) E*` (10³ Pa): the modulus that LAMMPS turns into the pair's E*.
    pub youngs: f64,
    /// `8 G*` (10³ Pa) of the pair: `1/G* = (2 − ν1)/G1 + (2 − ν2)/G2`.
    pub k_t: f64,
    /// The substrate's own Young's modulus (10³ Pa) and Poisson ratio (recorded in a comment).
    pub substrate: [f64; 2],
}

/// The comment over the slider–substrate pair's own `pair_coeff` (two materials).
fn pair_lines(s: &mut String, p: &DeckPair) {
    let _ = writeln!(
        s,
        "# per-body materials: the slider (types 2-5) as above, the substrate E = {} nu = {}; the\n\
         # slider-substrate pair (types 1 2) takes 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 as the modulus\n\
         # whose E/(2(1-nu^2)) is E* at the slider's nu, and k_t = 8 G*, 1/G* = (2-nu1)/G1 + (2-nu2)/G2",
        N(p.substrate[0]),
        N(p.substrate[1])
    );
}

/// `pair_style`/`pair_coeff` (one material, or the pair's own coefficients) and `neighbor`.
pub(super) fn contacts(s: &mut String, contact: &DeckContact, skin: f64) {
    w!(s, "# ---- contacts: Hertz (hertz/material: F = 4/3 E* sqrt(R_eff) delta^1.5), Mindlin k_t = 8 G* a,");
    w!(s, "# capped at mu |F_n| (damped normal force, as in the Rust engine); only slider-substrate pairs ----");
    match contact.damping {
        LammpsDamping::Tsuji { e, xgammat } => {
            w!(s, "# damping tsuji: F = -alpha(e) sqrt(m_eff 4/3 E* a) v_n = the Rust -gamma_n sqrt(m_eff 2E* a) v_n;");
            w!(
                s,
                "# tangential damping = xgammat x normal = the Rust -gamma_t sqrt(m_eff k_t) v_t"
            );
            w!(s, "pair_style      granular");
            w!(s, "pair_coeff      * * hertz/material {} {} {} damping tsuji tangential mindlin NULL {} {}", N(contact.youngs), N(e), N(contact.poisson), N(xgammat), N(contact.mu));
            if let Some(p) = contact.pair {
                pair_lines(s, &p);
                w!(s, "pair_coeff      1 2 hertz/material {} {} {} damping tsuji tangential mindlin {} {} {}", N(p.youngs), N(e), N(contact.poisson), N(p.k_t), N(xgammat), N(contact.mu));
            }
        }
        LammpsDamping::None => {
            w!(s, "pair_style      granular");
            w!(s, "pair_coeff      * * hertz/material {} 0.0 {} damping viscoelastic tangential mindlin NULL 0.0 {}", N(contact.youngs), N(contact.poisson), N(contact.mu));
            if let Some(p) = contact.pair {
                pair_lines(s, &p);
                w!(s, "pair_coeff      1 2 hertz/material {} 0.0 {} damping viscoelastic tangential mindlin {} 0.0 {}", N(p.youngs), N(contact.poisson), N(p.k_t), N(contact.mu));
            }
        }
    }
    w!(s, "neighbor        {} bin", N(skin));
    w!(s, "neigh_modify    delay 0 every 1 check yes exclude type 1 1 exclude type 2 2 exclude group ctrl all exclude group support all");
    w!(s, "");
}
