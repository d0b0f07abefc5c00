//! Turns a converged state (z, tilts, deflections) into an [`Equilibrium`] with its contact list.

use super::ctx::Ctx;
use super::law::{BodyPair, Law};
use super::{ContactInfo, Equilibrium, Model, PairSet};

/// Most contacts [`assemble`] reserves room for at once (an unwatched list may hold every
/// candidate pair above its floor; speed only).
const CONTACTS_RESERVE_MAX: usize = 4096;

/// Builds the [`Equilibrium`] from the body state `q = [ζ, L·t_x, L·t_y]` (z = z_ref + ζ):
/// every pair with δ > 0 becomes a [`ContactInfo`] whose point is the midpoint of the two sphere
/// centres; the residuals are recomputed from the contact forces: the force residual
/// `ΣF_z − W` and the moment residual `M_c − K_t·t` with the contact moment about the disc
/// centre `M_c = [Σ F_z·(y − y_c), −Σ F_z·(x − x_c)]` (about the x and y axes). `defl(i)` is the upward
/// deflection (m) of slider sphere i relative to the rigid body. `floor` (m, relative to z_ref):
/// no pair with its touch height at or below it touches at `q` (−∞: any may); those are
/// skipped before their response is computed — they contribute nothing either way, so the
/// sums and the contact list are the same, bit for bit.
#[allow(clippy::too_many_arguments)]
pub(crate) fn assemble<L: Law>(
    ctx: &Ctx,
    ps: &PairSet,
    bp: &[BodyPair<L>],
    zref: f64,
    model: Model,
    load: f64,
    q: [f64; 3],
    defl: impl Fn(u32) -> f64,
    iterations: usize,
    floor: f64,
) -> Equilibrium {
    let (k, two_r) = (ctx.hertz.k(), ctx.two_r);
    // room for every pair above the floor (a superset of the contacts on a watched list), so
    // the list is not regrown push by push
    let above = bp.iter().filter(|b| b.c > floor).count();
    let mut contacts = Vec::with_capacity(above.min(CONTACTS_RESERVE_MAX));
    let mut p_max: f64 = 0.0;
    let mut fsum = 0.0;
    let mut mom = [0.0; 2];
    for (p, b) in ps.pairs.iter().zip(bp) {
        if b.c <= floor {
            continue;
        }
        let w = defl(p.slider);
        let dz = q[0] + q[1] * b.g[0] + q[2] * b.g[1] + w - b.c;
        let r = b.response(k, two_r, dz);
        if r.fz <= 0.0 {
            continue;
        }
        let arm = ps.arm(p.slider);
        let zs = p.h + b.ut + dz;
        let hertz = ctx.pair_hertz(p.slider, p.substrate);
        let fnorm = hertz.force(r.delta);
        let p0 = hertz.p0(r.delta);
        p_max = p_max.max(p0);
        fsum += r.fz;
        mom[0] += r.fz * arm[1];
        mom[1] -= r.fz * arm[0];
        let s = ps.slider_xy[p.slider as usize];
        let sub = ctx.substrate[p.substrate as usize];
        contacts.push(ContactInfo {
            slider: p.slider,
            substrate: p.substrate,
            point: [
                0.5 * (s[0] + sub[0]),
                0.5 * (s[1] + sub[1]),
                0.5 * (zs + p.h),
            ],
            overlap: r.delta,
            force_n: fnorm,
            force_z: r.fz,
            p0,
            failed: ctx.coating.failed(p0),
            deflection: w,
        });
    }
    let tilt = [q[1] / ctx.scale, q[2] / ctx.scale];
    let km = ctx.mount_moment(tilt);
    Equilibrium {
        model,
        load,
        z: zref + q[0],
        tilt,
        contacts,
        p_max,
        residual: fsum - load,
        iterations,
        contact_moment: mom,
        moment_residual: [mom[0] - km[0], mom[1] - km[1]],
    }
}
