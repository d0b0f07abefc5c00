//! [`ZRoot`]: the safeguarded 1-D Newton root find of ΣF_z(ζ) = W at fixed tilt, shared by the
//! rigid-z model and the final force-balance polish of the rigid-tilt model.

use super::ctx::Ctx;
use super::law::{pair_response, BodyPair, Law};
use super::SolverParams;
use crate::contact::Hertz;
use crate::error::SceneError;
use std::cell::RefCell;

/// The pairs of one pair set at fixed tilt, prepared for the root find. Build once per pair set
/// (and tilt), solve for many loads.
pub(crate) struct ZRoot {
    /// The pairs, in pair order, and the sorted prefix of the high ones.
    rows: Rows,
    /// Highest touch height (m): the top of the first bracket.
    c_max: f64,
    /// The one Hertz prefactor and contact distance of every pair (one size per body).
    k: f64,
    two_r: f64,
}

/// The pairs of a [`ZRoot`]: `(c, r2, u_t)` — touch height relative to z_ref (m), lateral
/// distance² (m²), touch gap (m) — when every pair shares one law (the fast path), plus the
/// pair's own Hertz prefactor and contact distance `(k, d)` with per-site sizes.
enum Rows {
    Uniform(Vec<Row3>, RefCell<Sorted<Row3>>),
    Sized(Vec<Row5>, RefCell<Sorted<Row5>>),
}

/// A row `(c, r2, u_t)` with the shared law.
type Row3 = (f64, f64, f64);
/// A row `(c, r2, u_t, k, d)` with its own law.
type Row5 = (f64, f64, f64, f64, f64);

/// The rows whose touch height lies above `cut`, sorted by touch height (descending; ties in
/// pair order): the pairs active at any ζ ≥ `cut` are a prefix. Grown downwards on demand, so
/// the loads of one pair set share one sort of the pairs near the top instead of filtering and
/// sorting every pair per load and bracket.
struct Sorted<R> {
    rows: Vec<R>,
    cut: f64,
}

/// How far below a requested floor the sorted prefix grows, in units of the floor's depth below
/// the top: a warm-started bracket rarely steps down, so a small margin sorts fewer rows (the
/// order, and so every sum, is the same for any value; speed only).
const GROW: f64 = 0.25;

impl<R: Row> Sorted<R> {
    fn new() -> Self {
        Sorted {
            rows: Vec::new(),
            cut: f64::INFINITY,
        }
    }

    /// The number of sorted rows with c > `floor`, first growing the prefix down to `floor`
    /// (and [`GROW`] of its depth below the top `c_max` further, so a bracket stepping down by
    /// doubling grows it a few times only). O(P + new·log new) when it grows, O(log P) else.
    fn upto(&mut self, all: &[R], c_max: f64, floor: f64) -> usize {
        if floor < self.cut {
            let cut = if floor.is_finite() && c_max.is_finite() {
                floor - GROW * (c_max - floor).max(0.0)
            } else {
                f64::NEG_INFINITY
            };
            let (start, old) = (self.rows.len(), self.cut);
            self.rows
                .extend(all.iter().filter(|r| r.c() > cut && r.c() <= old));
            sort_descending(&mut self.rows[start..]);
            self.cut = cut;
        }
        self.rows.partition_point(|r| r.c() > floor)
    }
}

/// Sorts `rows` by touch height, descending, ties in their given order: the order of a stable
/// `sort_by(|a, b| b.c().total_cmp(&a.c()))`, obtained as an unstable sort of integer keys
/// (`total_cmp`'s order as bits, inverted, then the position), about twice as fast on the
/// few hundred rows of a path sample (`docs/validation/path-solve.md`). O(n log n).
fn sort_descending<R: Row>(rows: &mut [R]) {
    if rows.len() < 2 {
        return;
    }
    // total_cmp's order on the bits: negative values flipped whole, positive ones' sign set
    let key = |c: f64| {
        let b = c.to_bits();
        let asc = if b >> 63 == 1 { !b } else { b | (1 << 63) };
        !asc
    };
    let mut keys: Vec<u128> = rows
        .iter()
        .enumerate()
        .map(|(i, r)| (u128::from(key(r.c())) << 32) | i as u128)
        .collect();
    keys.sort_unstable();
    let copy: Vec<R> = keys.iter().map(|k| rows[(*k as u32) as usize]).collect();
    rows.copy_from_slice(&copy);
}

/// One pair row: its touch height and its vertical response at ζ (with the shared `k`, `d`
/// unless it carries its own).
trait Row: Copy {
    fn c(&self) -> f64;
    fn response(&self, k: f64, d: f64, zeta: f64) -> super::law::PairResponse;
}

impl Row for (f64, f64, f64) {
    #[inline]
    fn c(&self) -> f64 {
        self.0
    }
    #[inline]
    fn response(&self, k: f64, d: f64, zeta: f64) -> super::law::PairResponse {
        pair_response(k, d, self.1, self.2, zeta - self.0)
    }
}

impl Row for (f64, f64, f64, f64, f64) {
    #[inline]
    fn c(&self) -> f64 {
        self.0
    }
    #[inline]
    fn response(&self, _: f64, _: f64, zeta: f64) -> super::law::PairResponse {
        pair_response(self.3, self.4, self.1, self.2, zeta - self.0)
    }
}

impl ZRoot {
    /// Takes the pairs at fixed body tilt `q12 = [L·t_x, L·t_y]` (m); every pair has the Hertz
    /// prefactor `k` and the contact distance `two_r` (m) unless it carries its own. O(P).
    pub fn new<L: Law>(pairs: &[BodyPair<L>], q12: [f64; 2], two_r: f64, k: f64) -> ZRoot {
        let c = |p: &BodyPair<L>| p.c - q12[0] * p.g[0] - q12[1] * p.g[1];
        let (rows, c_max) = if L::SIZED {
            let all: Vec<_> = pairs
                .iter()
                .map(|p| {
                    let (k, d) = p.law.kd(k, two_r);
                    (c(p), p.r2, p.ut, k, d)
                })
                .collect();
            let c_max = all.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
            (Rows::Sized(all, RefCell::new(Sorted::new())), c_max)
        } else {
            let all: Vec<_> = pairs.iter().map(|p| (c(p), p.r2, p.ut)).collect();
            let c_max = all.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
            (Rows::Uniform(all, RefCell::new(Sorted::new())), c_max)
        };
        ZRoot {
            rows,
            c_max,
            k,
            two_r,
        }
    }

    /// ΣF_z (N) and d(ΣF_z)/dζ (N/m) at ζ (m) over `act` (sorted, descending, a prefix of
    /// [`Sorted`]). O(active pairs).
    fn eval<R: Row>(&self, act: &[R], zeta: f64) -> (f64, f64) {
        let mut f = 0.0;
        let mut df = 0.0;
        for p in act {
            if p.c() <= zeta {
                break;
            }
            let r = p.response(self.k, self.two_r, zeta);
            f += r.fz;
            df -= r.s;
        }
        (f, df)
    }

    /// ζ (m) with ΣF_z(ζ) = `load` (N) to `params.force_rtol`, and the iteration count.
    ///
    /// ΣF_z is non-increasing in ζ, so Newton's method inside a shrinking bracket converges from
    /// any start; bisection takes over whenever a Newton step leaves the bracket (grazing contacts
    /// where dF/dz → 0). Typically < 15 iterations of O(active pairs) each, over the prefix of
    /// the pairs sorted by touch height that lies above the lower bracket (the others cannot
    /// touch at the root, since ΣF_z is non-increasing); the prefix is sorted once per pair set
    /// and grown only when a bracket reaches below it, so the loads share it: no sort of all P
    /// candidate pairs.
    ///
    /// Records its lowest bracket end with [`Ctx::rely`] (lowered by `drop`, m, the most a
    /// tilted row's height can sit above its untilted one): no pair below it was looked at.
    pub fn solve_dropped(
        &self,
        ctx: &Ctx,
        load: f64,
        drop: f64,
    ) -> Result<(f64, usize), SceneError> {
        let (z, it, z_lo) = self.solve_guess(ctx, load, None)?;
        ctx.rely(z_lo - drop);
        Ok((z, it))
    }

    /// [`ZRoot::solve_dropped`] for untilted rows, warm-started from the watch's guess where a
    /// path sets one ([`super::ctx::Watch::guess`]; the root found goes to its `root`).
    pub fn solve(&self, ctx: &Ctx, load: f64) -> Result<(f64, usize), SceneError> {
        let guess = ctx.watch.map(|w| w.guess.get()).filter(|g| g.is_finite());
        let (z, it, z_lo) = self.solve_guess(ctx, load, guess)?;
        ctx.rely(z_lo);
        if let Some(w) = ctx.watch {
            w.root.set(z);
        }
        Ok((z, it))
    }

    fn solve_guess(
        &self,
        ctx: &Ctx,
        load: f64,
        guess: Option<f64>,
    ) -> Result<(f64, usize, f64), SceneError> {
        match &self.rows {
            Rows::Uniform(all, srt) => self.solve_rows(
                all,
                &mut srt.borrow_mut(),
                load,
                ctx.hertz,
                ctx.params,
                guess,
            ),
            Rows::Sized(all, srt) => self.solve_rows(
                all,
                &mut srt.borrow_mut(),
                load,
                ctx.hertz,
                ctx.params,
                guess,
            ),
        }
    }

    /// [`ZRoot::solve`] over one kind of rows; also returns the lowest bracket end ζ_lo (m).
    fn solve_rows<R: Row>(
        &self,
        all: &[R],
        srt: &mut Sorted<R>,
        load: f64,
        hertz: &Hertz,
        params: &SolverParams,
        guess: Option<f64>,
    ) -> Result<(f64, usize, f64), SceneError> {
        if all.is_empty() {
            return Err(SceneError::NoEquilibrium(
                "no substrate sphere lies under any slider sphere (slider off the substrate?)"
                    .into(),
            ));
        }
        let z_hi0 = self.c_max;
        // the active rows at the bracket's lower end: a prefix of the sorted rows
        let mut n_act = 0;
        // Lower bracket: from `anchor`, step down by `w`, doubling, until the pairs touching
        // above z_lo carry the load (only they can carry any anywhere in [z_lo, z_hi]).
        let mut down = |anchor: f64, mut w: f64, mut z_hi: f64, n_act: &mut usize| {
            let mut iters = 0;
            let mut z_lo = anchor - w;
            loop {
                *n_act = srt.upto(all, z_hi0, z_lo);
                let (f, _) = self.eval(&srt.rows[..*n_act], z_lo);
                if f >= load {
                    return Ok((z_lo, z_hi, w, iters));
                }
                z_hi = z_lo;
                w *= 2.0;
                z_lo = anchor - w;
                iters += 1;
                if iters > params.max_iter || z_hi0 - z_lo > self.two_r {
                    return Err(SceneError::NoEquilibrium(format!(
                        "the load {} mN cannot be carried with overlap below the sphere diameter (load_mN)",
                        crate::units::significant(crate::units::n_to_mn(load), 6)
                    )));
                }
            }
        };
        let (mut z_lo, mut z_hi, mut iters);
        match guess.filter(|g| g.is_finite() && *g < z_hi0) {
            None => {
                // from the top, by the overlap one on-top contact needs for W
                let step = hertz.overlap_for_force(load).max(1e-30 * self.two_r);
                (z_lo, z_hi, _, iters) = down(z_hi0, step, z_hi0, &mut n_act)?;
            }
            Some(g) => {
                // Warm start (a path's previous sample): a bracket a tenth of the depth below
                // the top around the guess, doubled until it holds the root.
                let w0 = 0.1 * (z_hi0 - g) + 1e-9 * self.two_r;
                let w;
                (z_lo, z_hi, w, iters) = down(g, w0, (g + w0).min(z_hi0), &mut n_act)?;
                let mut w = w;
                let act = &srt.rows[..n_act];
                while z_hi < z_hi0 && self.eval(act, z_hi).0 > load {
                    z_lo = z_hi;
                    w *= 2.0;
                    z_hi = (g + w).min(z_hi0);
                    iters += 1;
                }
            }
        }
        let z_floor = z_lo;
        let act = &srt.rows[..n_act];
        let mut z = 0.5 * (z_lo + z_hi);
        let tol = params.force_rtol * load;
        let w23 = load.powf(2.0 / 3.0);
        loop {
            iters += 1;
            let (f, df) = self.eval(act, z);
            let g = f - load;
            if g.abs() <= tol {
                return Ok((z, iters, z_floor));
            }
            if g > 0.0 {
                z_lo = z;
            } else {
                z_hi = z;
            }
            let newton = newton_23(z, f, df, w23);
            z = if newton > z_lo && newton < z_hi {
                newton
            } else {
                0.5 * (z_lo + z_hi)
            };
            let scale = z_hi.abs().max(z_lo.abs()).max(1e-300);
            if z_hi - z_lo <= 4.0 * f64::EPSILON * scale || iters > params.max_iter {
                let zb = self.stalled(act, z_lo, z_hi, load)?;
                return Ok((zb, iters, z_floor));
            }
        }
    }

    /// The bracket `[z_lo, z_hi]` (m) exhausted at machine precision: its end point that better
    /// balances `load` (N), if that holds to 1e-9 (the documented guarantee), else an error.
    /// Two evaluations over `act`.
    fn stalled<R: Row>(
        &self,
        act: &[R],
        z_lo: f64,
        z_hi: f64,
        load: f64,
    ) -> Result<f64, SceneError> {
        let (fl, _) = self.eval(act, z_lo);
        let (fh, _) = self.eval(act, z_hi);
        let (zb, fb) = if (fl - load).abs() <= (fh - load).abs() {
            (z_lo, fl)
        } else {
            (z_hi, fh)
        };
        if (fb - load).abs() > 1e-9 * load {
            return Err(SceneError::NoEquilibrium(format!(
                "root find stalled at ζ = {zb:e} m with residual {:e} N",
                fb - load
            )));
        }
        Ok(zb)
    }
}

/// The Newton step from ζ = `z` (m) on φ(ζ) = ΣF_z^{2/3} − W^{2/3} (ΣF_z = `f` N, its slope
/// `df` N/m, `w23` = W^{2/3}), which is exactly linear in ζ while the set of touching pairs is
/// fixed and they share one touch height (on-top contacts), and nearly linear otherwise:
/// typically 2–4 fewer iterations than Newton on ΣF_z. NaN where ΣF_z is not positive and
/// falling. O(1).
#[inline]
fn newton_23(z: f64, f: f64, df: f64, w23: f64) -> f64 {
    if df < 0.0 && f > 0.0 {
        let phi = f.powf(2.0 / 3.0) - w23;
        let dphi = (2.0 / 3.0) * df / f.cbrt();
        z - phi / dphi
    } else {
        f64::NAN
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The key sort gives the stable descending order: ties (exact, and ±0) keep their order.
    #[test]
    fn key_sort_is_the_stable_descending_sort() {
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 33
        };
        for n in [0usize, 1, 2, 7, 300, 1500] {
            let rows: Vec<Row3> = (0..n)
                .map(|i| {
                    let c = match next() % 5 {
                        0 => 0.0,
                        1 => -0.0,
                        2 => (next() % 7) as f64 * 1e-9,
                        3 => -((next() % 7) as f64) * 1e-9,
                        _ => (next() as f64 - 2e9) * 1e-18,
                    };
                    (c, i as f64, 0.0)
                })
                .collect();
            let mut want = rows.clone();
            want.sort_by(|a, b| b.0.total_cmp(&a.0));
            let mut got = rows;
            sort_descending(&mut got);
            let bits = |v: &[Row3]| v.iter().map(|r| (r.0.to_bits(), r.1)).collect::<Vec<_>>();
            assert_eq!(bits(&got), bits(&want), "n = {n}");
        }
    }
}
