//! The symmetry of a slider pattern over a substrate pattern: the period and mirror of the
//! orientation θ (its fundamental domain) and the period of the pulling angle α. Angles in
//! degrees where the field says `_deg`; user wording (the log's and report's sentences) is the
//! app's (`superlube::study::design::symmetry`).
//!
//! A 2-D Bravais lattice is invariant under rotations by 2π/n about any of its sites
//! (n ∈ {2, 3, 4, 6}: its *rotation order*, the largest such n) and possibly under reflections
//! about mirror lines through a site (always along lattice vectors). The slider (a disc of
//! lattice sites centred on a site) at rotation θ sits over the substrate with its centre on a
//! substrate site, so:
//!
//! - **Period.** Rotating the slider by 2π/n_s maps it onto itself (θ ≡ θ + 2π/n_s); rotating
//!   the whole picture by 2π/n_b maps the substrate onto itself and the slider to θ + 2π/n_b.
//!   Together θ ≡ θ + P with **P = 360°/lcm(n_s, n_b)**: 30° for square-on-triangle
//!   (lcm(4, 6) = 12), 60° for triangle-on-triangle, 90° for square-on-square.
//! - **Mirror.** Reflecting the picture about a substrate mirror line at angle m_b maps the
//!   slider at θ to the slider at 2(m_b − m_s) − θ for any slider mirror line m_s (angles in
//!   each lattice's own frame): θ ≡ 2c − θ about every centre c = m_b − m_s. For the presets
//!   (both lattices have a mirror line along their first vector, the x axis) c = 0:
//!   θ ≡ −θ. Mirror centres repeat every P/2.
//! - **Fundamental domain.** With a mirror: [c₀, c₀ + P/2], c₀ the smallest centre ≥ 0 (0 for
//!   the presets): **0–15° for square-tri, 0–30° for tri-tri**, 0–45° for square-square.
//!   Without one: [0, P).
//! - **The cut** (the design's) keeps the θ values that lie in the domain (every other θ is the
//!   image of one inside it; a range is not shifted or folded, so `0:30:0.1` becomes `0:15:0.1`
//!   for square-tri).
//! - **Pulling angle.** The rotations common to both lattices, by 2π/gcd(n_s, n_b) about the
//!   shared site, map every path onto an equivalent one, and 180° always does (all Bravais
//!   lattices are centrosymmetric): α ≡ α + P_α with **P_α = 360°/gcd(n_s, n_b)** (180° for
//!   square-tri, 60° for tri-tri). The design scans α over (−P_α/2, P_α/2].
//!
//! The cut is exact for a flat substrate with the slider centred on a site (the default
//! placement; the finite substrate rectangle is far from the slider). A random height
//! perturbation (σ_h > 0) keeps the symmetry only statistically, and an in-plane offset breaks
//! it (the design says so in its log, and can screen the range as given).
//!
//! **Pattern geometry** ([`PairSymmetry::of_scene`]). A basis, an outline or a site file can
//! lower a lattice's symmetry (a honeycomb site has rotation order 3, a rectangular pad on a
//! square lattice 2): the slider's rotations and mirrors are then tested on its actual finite
//! set of sites, the substrate's on its lattice with its basis (every basis site must map onto
//! a basis site modulo the lattice). A substrate from a site file has no derivable symmetry:
//! the full θ range is screened (no cut) and [`PairSymmetry::not_derived`] says why.

use crate::{Lattice, Scene};

/// Relative tolerance of "maps onto the lattice" (lattice coordinates within this of integers).
const TOL: f64 = 1e-6;

/// Rotation order of the Bravais lattice `l` about a site: the largest n ∈ {6, 4, 3, 2} such
/// that the rotation by 2π/n maps both primitive vectors onto lattice vectors (lattice
/// coordinates within 1e-6 of integers); 2 for every lattice (centrosymmetric). Cost: a few
/// 2×2 solves.
pub fn rotation_order(l: &Lattice) -> u32 {
    [6u32, 4, 3, 2]
        .into_iter()
        .find(|&n| maps_onto(l, rotation(std::f64::consts::TAU / n as f64)))
        .unwrap_or(2)
}

/// Symmetry of one lattice about a site.
#[derive(Debug, Clone, PartialEq)]
pub struct LatticeSymmetry {
    /// Largest n ∈ {6, 4, 3, 2} such that the rotation by 2π/n maps the lattice onto itself.
    pub rotation_order: u32,
    /// Angles (rad, in [0, π)) of the mirror lines through a site, ascending.
    pub mirrors: Vec<f64>,
}

/// Whether the linear map `m` (row-major 2×2) maps `l` onto itself: both primitive vectors go
/// to lattice vectors (integer coordinates).
fn maps_onto(l: &Lattice, m: [[f64; 2]; 2]) -> bool {
    [l.a1, l.a2].iter().all(|v| {
        let w = [
            m[0][0] * v[0] + m[0][1] * v[1],
            m[1][0] * v[0] + m[1][1] * v[1],
        ];
        let c = l.to_lattice_coords(w);
        c.iter().all(|x| (x - x.round()).abs() < TOL)
    })
}

fn rotation(phi: f64) -> [[f64; 2]; 2] {
    let (s, c) = phi.sin_cos();
    [[c, -s], [s, c]]
}

fn reflection(phi: f64) -> [[f64; 2]; 2] {
    let (s, c) = (2.0 * phi).sin_cos();
    [[c, s], [s, -c]]
}

impl LatticeSymmetry {
    /// The symmetry of `l` (mirror candidates: the directions of lattice vectors with
    /// coefficients up to 4, which contain every mirror line of a 2-D lattice).
    pub fn of(l: &Lattice) -> LatticeSymmetry {
        let rotation_order = rotation_order(l);
        let mut mirrors: Vec<f64> = Vec::new();
        for i in -4i32..=4 {
            for j in -4i32..=4 {
                if i == 0 && j == 0 {
                    continue;
                }
                let v = l.point(i as f64, j as f64);
                let phi = v[1].atan2(v[0]).rem_euclid(std::f64::consts::PI);
                let phi = if std::f64::consts::PI - phi < 1e-12 {
                    0.0
                } else {
                    phi
                };
                if mirrors.iter().any(|&m| (m - phi).abs() < 1e-9) {
                    continue;
                }
                if maps_onto(l, reflection(phi)) {
                    mirrors.push(phi);
                }
            }
        }
        mirrors.sort_by(f64::total_cmp);
        LatticeSymmetry {
            rotation_order,
            mirrors,
        }
    }
}

/// Greatest common divisor of two rotation orders (Euclid; `gcd(n, 0) = n`).
pub fn gcd(a: u32, b: u32) -> u32 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// The symmetry of a slider lattice over a substrate lattice (see the module docs); angles in
/// degrees.
#[derive(Debug, Clone, PartialEq)]
pub struct PairSymmetry {
    /// Slider lattice's rotation order n_s.
    pub slider_order: u32,
    /// Substrate lattice's rotation order n_b.
    pub substrate_order: u32,
    /// Period P of θ (degrees): 360/lcm(n_s, n_b).
    pub period_deg: f64,
    /// Smallest mirror centre c₀ ≥ 0 (degrees; θ ≡ 2c₀ − θ), if the pair has a mirror.
    pub mirror_deg: Option<f64>,
    /// Period P_α of the pulling angle (degrees): 360/gcd(n_s, n_b).
    pub alpha_period_deg: f64,
    /// Why no symmetry could be derived (then no cut: every θ is kept); `None` when derived.
    pub not_derived: Option<NotDerived>,
}

/// Why a pair's symmetry could not be derived from its geometry (then every θ is kept).
#[derive(Debug, Clone, PartialEq)]
pub enum NotDerived {
    /// The substrate comes from a site file (its path as given).
    SubstrateSites(String),
    /// The slider's spheres differ in size (per-site diameters of the site file at this path).
    SliderSizes(String),
}

/// The fundamental domain of θ (degrees): `[lo_deg, hi_deg]` when `closed` (a mirror),
/// `[lo_deg, hi_deg)` otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Domain {
    /// Lower end (degrees), included.
    pub lo_deg: f64,
    /// Upper end (degrees), included when `closed`.
    pub hi_deg: f64,
    /// Whether `hi_deg` is included (the pair has a mirror).
    pub closed: bool,
}

impl PairSymmetry {
    /// The symmetry of `slider` over `substrate`.
    pub fn of(slider: &Lattice, substrate: &Lattice) -> PairSymmetry {
        combine(
            &LatticeSymmetry::of(slider),
            &LatticeSymmetry::of(substrate),
        )
    }
}

/// The pair symmetry of a slider and a substrate symmetry (see the module docs).
fn combine(s: &LatticeSymmetry, b: &LatticeSymmetry) -> PairSymmetry {
    {
        let (ns, nb) = (s.rotation_order, b.rotation_order);
        let lcm = ns / gcd(ns, nb) * nb;
        let period_deg = 360.0 / lcm as f64;
        let half = period_deg / 2.0;
        let mut mirror: Option<f64> = None;
        for mb in &b.mirrors {
            for ms in &s.mirrors {
                let c = (mb - ms).to_degrees().rem_euclid(half);
                // snap to the 1e-9° grid: the centres of the presets are exact multiples
                let c = (c * 1e9).round() / 1e9;
                let c = if (half - c).abs() < 1e-9 { 0.0 } else { c };
                if mirror.is_none_or(|m| c < m) {
                    mirror = Some(c);
                }
            }
        }
        PairSymmetry {
            slider_order: ns,
            substrate_order: nb,
            period_deg,
            mirror_deg: mirror,
            alpha_period_deg: 360.0 / gcd(ns, nb) as f64,
            not_derived: None,
        }
    }
}

impl PairSymmetry {
    /// The symmetry of `scene`'s actual geometry (see the module docs): [`PairSymmetry::of`]
    /// for plain Bravais lattices cut to a disc; else the slider's finite site set and the
    /// substrate's lattice with its basis. A substrate site file, or a slider site file with per-site
    /// sizes: not derived (full range).
    /// Cost O(N_slider × candidate mirrors).
    pub fn of_scene(scene: &Scene) -> PairSymmetry {
        let g = &scene.geometry;
        if g.is_plain()
            || (g.slider_is_bravais()
                && g.substrate_is_bravais()
                && g.outline == Default::default())
        {
            return Self::of(&scene.slider.lattice, &scene.substrate.lattice);
        }
        if let Some(l) = &g.substrate_sites {
            return PairSymmetry {
                slider_order: 1,
                substrate_order: 1,
                period_deg: 360.0,
                mirror_deg: None,
                alpha_period_deg: 360.0,
                not_derived: Some(NotDerived::SubstrateSites(l.path.clone())),
            };
        }
        if let Some(l) = g.slider_sites.as_ref().filter(|l| l.radii.is_some()) {
            // spheres of different sizes are not interchangeable: no cut rather than a wrong one
            return PairSymmetry {
                slider_order: 1,
                substrate_order: 1,
                period_deg: 360.0,
                mirror_deg: None,
                alpha_period_deg: 360.0,
                not_derived: Some(NotDerived::SliderSizes(l.path.clone())),
            };
        }
        let s = finite_symmetry(&scene.slider_sites_local());
        let b = pattern_symmetry(&scene.substrate.lattice, &g.substrate_basis);
        combine(&s, &b)
    }

    /// The fundamental domain of θ (degrees): `[c₀, c₀ + P/2]` with a mirror, `[0, P)` without.
    pub fn domain(&self) -> Domain {
        match self.mirror_deg {
            Some(c) => Domain {
                lo_deg: c,
                hi_deg: c + self.period_deg / 2.0,
                closed: true,
            },
            None => Domain {
                lo_deg: 0.0,
                hi_deg: self.period_deg,
                closed: false,
            },
        }
    }

    /// Whether θ (degrees) lies in the fundamental domain (within 1e-9°); always when the
    /// symmetry was not derived.
    pub fn contains(&self, theta_deg: f64) -> bool {
        if self.not_derived.is_some() {
            return true;
        }
        let Domain {
            lo_deg: lo,
            hi_deg: hi,
            closed,
        } = self.domain();
        theta_deg >= lo - 1e-9
            && if closed {
                theta_deg <= hi + 1e-9
            } else {
                theta_deg < hi - 1e-9
            }
    }

    /// The orientation in the fundamental domain equivalent to θ (degrees).
    pub fn fold(&self, theta_deg: f64) -> f64 {
        if self.not_derived.is_some() {
            return theta_deg;
        }
        let lo = self.domain().lo_deg;
        let p = self.period_deg;
        match self.mirror_deg {
            Some(c) => {
                let t = (theta_deg - c).rem_euclid(p);
                c + if t > p / 2.0 { p - t } else { t }
            }
            None => (theta_deg - lo).rem_euclid(p) + lo,
        }
    }

    /// The parts of the fundamental domain that the θ list `thetas_deg` (degrees, as screened)
    /// leaves out: the gaps between its values folded into the domain (the domain's ends
    /// included; around the period for a domain without a mirror; modulo 360° when the symmetry
    /// was not derived) that are wider than the list's own largest step. Each gap is
    /// `(from, to)` in degrees, `to` past the domain's end for a gap through it. Empty when the
    /// list spans the domain. O(n log n).
    pub fn unscreened(&self, thetas_deg: &[f64]) -> Vec<(f64, f64)> {
        let Domain {
            lo_deg: lo,
            hi_deg: hi,
            closed,
        } = self.domain();
        let step = thetas_deg
            .windows(2)
            .map(|w| (w[1] - w[0]).abs())
            .fold(0.0, f64::max);
        let wide = |g: f64| g > step + 1e-6;
        let mut v: Vec<f64> = thetas_deg
            .iter()
            .map(|&t| {
                if self.not_derived.is_some() {
                    (t - lo).rem_euclid(hi - lo) + lo
                } else {
                    self.fold(t)
                }
            })
            .collect();
        v.sort_by(f64::total_cmp);
        v.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
        let (Some(&first), Some(&last)) = (v.first(), v.last()) else {
            return vec![(lo, hi)];
        };
        let mut gaps: Vec<(f64, f64)> = v
            .windows(2)
            .filter(|w| wide(w[1] - w[0]))
            .map(|w| (w[0], w[1]))
            .collect();
        if closed {
            if wide(first - lo) {
                gaps.insert(0, (lo, first));
            }
            if wide(hi - last) {
                gaps.push((last, hi));
            }
        } else if wide(first - lo + hi - last) {
            gaps.push((last, first + hi - lo));
        }
        gaps
    }
}

/// The rotations (order n ∈ {6, 4, 3, 2}, else 1) and mirror lines through the origin of a
/// finite point set (m). Mirror candidates: the bisectors of the nearest site with every site
/// at the same distance (a mirror maps it onto one of them). O(N × candidates).
fn finite_symmetry(pts: &[[f64; 2]]) -> LatticeSymmetry {
    let scale = pts
        .iter()
        .map(|p| p[0].hypot(p[1]))
        .fold(0.0, f64::max)
        .max(1e-12);
    let q = 1e-7 * scale;
    let key = |p: [f64; 2]| ((p[0] / q).round() as i64, (p[1] / q).round() as i64);
    let set: std::collections::HashSet<(i64, i64)> = pts.iter().map(|&p| key(p)).collect();
    let has = |p: [f64; 2]| {
        let (x, y) = key(p);
        (-1..=1).any(|dx| (-1..=1).any(|dy| set.contains(&(x + dx, y + dy))))
    };
    let maps = |m: [[f64; 2]; 2]| {
        pts.iter().all(|v| {
            has([
                m[0][0] * v[0] + m[0][1] * v[1],
                m[1][0] * v[0] + m[1][1] * v[1],
            ])
        })
    };
    let rotation_order = [6u32, 4, 3, 2]
        .into_iter()
        .find(|&n| maps(rotation(std::f64::consts::TAU / n as f64)))
        .unwrap_or(1);
    let r0 = pts
        .iter()
        .map(|p| p[0].hypot(p[1]))
        .filter(|&r| r > q)
        .fold(f64::INFINITY, f64::min);
    let mut mirrors: Vec<f64> = Vec::new();
    if let Some(p0) = pts
        .iter()
        .find(|p| (p[0].hypot(p[1]) - r0).abs() <= 1e-6 * r0)
    {
        let a0 = p0[1].atan2(p0[0]);
        for p in pts
            .iter()
            .filter(|p| (p[0].hypot(p[1]) - r0).abs() <= 1e-6 * r0)
        {
            let phi = (0.5 * (a0 + p[1].atan2(p[0]))).rem_euclid(std::f64::consts::PI);
            let phi = if std::f64::consts::PI - phi < 1e-12 {
                0.0
            } else {
                phi
            };
            for c in [
                phi,
                (phi + 0.5 * std::f64::consts::PI).rem_euclid(std::f64::consts::PI),
            ] {
                if !mirrors.iter().any(|&m| (m - c).abs() < 1e-9) && maps(reflection(c)) {
                    mirrors.push(c);
                }
            }
        }
    } else if pts.len() == 1 {
        return LatticeSymmetry::of(&Lattice::square(1.0));
    }
    mirrors.sort_by(f64::total_cmp);
    LatticeSymmetry {
        rotation_order,
        mirrors,
    }
}

/// The symmetry about the origin of a lattice with a basis (rebased: first site at the origin):
/// a rotation or mirror of the lattice that also maps every basis site onto a basis site modulo
/// the lattice. The plain lattice's when the basis has at most one site.
fn pattern_symmetry(l: &Lattice, basis: &[[f64; 2]]) -> LatticeSymmetry {
    let ls = LatticeSymmetry::of(l);
    if basis.len() <= 1 {
        return ls;
    }
    let b = super::rebased(basis);
    let keeps = |m: [[f64; 2]; 2]| {
        maps_onto(l, m)
            && b.iter().all(|v| {
                let w = [
                    m[0][0] * v[0] + m[0][1] * v[1],
                    m[1][0] * v[0] + m[1][1] * v[1],
                ];
                b.iter().any(|u| {
                    let c = l.to_lattice_coords([w[0] - u[0], w[1] - u[1]]);
                    c.iter().all(|x| (x - x.round()).abs() < TOL)
                })
            })
    };
    LatticeSymmetry {
        rotation_order: [6u32, 4, 3, 2]
            .into_iter()
            .find(|&n| keeps(rotation(std::f64::consts::TAU / n as f64)))
            .unwrap_or(1),
        mirrors: ls
            .mirrors
            .into_iter()
            .filter(|&m| keeps(reflection(m)))
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(s: &PairSymmetry) -> (f64, f64, bool) {
        let d = s.domain();
        (d.lo_deg, d.hi_deg, d.closed)
    }

    #[test]
    fn gcd_and_rotation_orders() {
        assert_eq!((gcd(4, 6), gcd(6, 6), gcd(3, 0)), (2, 6, 3));
        assert_eq!(rotation_order(&Lattice::triangular(3e-6)), 6);
        assert_eq!(rotation_order(&Lattice::square(3e-6)), 4);
        assert_eq!(rotation_order(&Lattice::rectangular(3e-6, 4e-6)), 2);
    }

    #[test]
    fn presets() {
        let t = Lattice::triangular(3e-6);
        let s = Lattice::square(3e-6);
        let st = PairSymmetry::of(&s, &t);
        assert_eq!((st.slider_order, st.substrate_order), (4, 6));
        assert_eq!(st.period_deg, 30.0);
        assert_eq!(st.mirror_deg, Some(0.0));
        assert_eq!(d(&st), (0.0, 15.0, true));
        assert_eq!(st.alpha_period_deg, 180.0);
        let tt = PairSymmetry::of(&t, &t);
        assert_eq!(d(&tt), (0.0, 30.0, true));
        assert_eq!(tt.alpha_period_deg, 60.0);
        let ss = PairSymmetry::of(&s, &s);
        assert_eq!(d(&ss), (0.0, 45.0, true));
        assert_eq!(ss.alpha_period_deg, 90.0);
        assert_eq!(LatticeSymmetry::of(&t).mirrors.len(), 6);
        assert_eq!(LatticeSymmetry::of(&s).mirrors.len(), 4);
        for (th, f) in [
            (20.0, 10.0),
            (-3.0, 3.0),
            (31.0, 1.0),
            (15.0, 15.0),
            (45.0, 15.0),
        ] {
            assert!((st.fold(th) - f).abs() < 1e-9, "{th} → {}", st.fold(th));
        }
        assert!(st.contains(0.0) && st.contains(15.0) && !st.contains(15.1));
    }

    #[test]
    fn rectangular_and_oblique() {
        let r = Lattice::rectangular(3e-6, 4e-6);
        let sym = LatticeSymmetry::of(&r);
        assert_eq!(sym.rotation_order, 2);
        assert_eq!(sym.mirrors.len(), 2);
        let t = Lattice::triangular(3e-6);
        let p = PairSymmetry::of(&r, &t);
        assert_eq!(p.period_deg, 60.0);
        assert_eq!(d(&p), (0.0, 30.0, true));
        assert_eq!(p.alpha_period_deg, 180.0);
        // a generic oblique lattice: no mirror, 2-fold only
        let o = Lattice::oblique([3e-6, 0.0], [1.0e-6, 2.8e-6]);
        let so = LatticeSymmetry::of(&o);
        assert_eq!(so.rotation_order, 2);
        assert!(so.mirrors.is_empty());
        let p = PairSymmetry::of(&o, &t);
        assert_eq!(p.mirror_deg, None);
        assert_eq!(d(&p), (0.0, 60.0, false));
        assert!(p.contains(0.0) && !p.contains(60.0));
        // a triangular lattice rotated by 10°: mirrors at 10° + k·30°, centre 10° (mod 15°)
        let (s10, c10) = 10f64.to_radians().sin_cos();
        let rot = |v: [f64; 2]| [c10 * v[0] - s10 * v[1], s10 * v[0] + c10 * v[1]];
        let t10 = Lattice::oblique(rot(t.a1), rot(t.a2));
        assert_eq!(LatticeSymmetry::of(&t10).rotation_order, 6);
        let sq = Lattice::square(3e-6);
        let p = PairSymmetry::of(&sq, &t10);
        assert_eq!(p.period_deg, 30.0);
        assert!((p.mirror_deg.unwrap() - 10.0).abs() < 1e-9, "{p:?}");
    }
}
