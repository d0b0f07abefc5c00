"""Map the Rust engine's dimensionless damping (dem::SimParams gamma_n, gamma_t) to LAMMPS
`pair_style granular ... damping tsuji` inputs.

Rust:   F_n,damp = -gamma_n sqrt(m_eff S_n) v_n,  S_n = 2 E* sqrt(R_eff delta) = 2 E* a
        F_t,damp = -gamma_t sqrt(m_eff k_t) v_t,  k_t = 8 G* a
LAMMPS: F_n,damp = -alpha(e) sqrt(m_eff k_n a) v_n with k_n = 4/3 E*  (tsuji; the pair_coeff
        damping value is a restitution e, turned into alpha by Tsuji's polynomial)
        F_t,damp = -xgt * alpha(e) sqrt(m_eff k_n a) v_t
So alpha = gamma_n sqrt(3/2) and xgt = (gamma_t/alpha) sqrt(8 G* / (4/3 E*)) =
(gamma_t/alpha) sqrt(3 (1 - nu) / (2 - nu)) for equal materials.
"""

import math


def tsuji_alpha(e):
    """LAMMPS pair_granular.cpp: damping coefficient alpha of restitution e (Tsuji et al. 1992 fit)."""
    return (1.2728 - 4.2783 * e + 11.087 * e ** 2 - 22.348 * e ** 3 + 27.467 * e ** 4
            - 18.022 * e ** 5 + 4.8218 * e ** 6)


def tsuji_e_for_alpha(alpha):
    """The restitution e in [0, 1] with tsuji_alpha(e) = alpha (bisection; alpha decreases with e)."""
    lo, hi = 0.0, 1.0
    if not tsuji_alpha(hi) <= alpha <= tsuji_alpha(lo):
        raise ValueError(f"alpha {alpha} outside the Tsuji fit range")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if tsuji_alpha(mid) > alpha:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def lammps_damping(gamma_n, gamma_t, nu=0.3):
    """(e for `damping tsuji`, xgt) reproducing the Rust engine's gamma_n, gamma_t."""
    alpha = gamma_n * math.sqrt(1.5)
    e = tsuji_e_for_alpha(alpha)
    xgt = gamma_t / alpha * math.sqrt(3.0 * (1.0 - nu) / (2.0 - nu))
    return e, xgt


if __name__ == "__main__":
    import sys
    gn = float(sys.argv[1]) if len(sys.argv) > 1 else 0.1
    gt = float(sys.argv[2]) if len(sys.argv) > 2 else gn
    e, xgt = lammps_damping(gn, gt)
    print(f"gamma_n={gn} gamma_t={gt} -> tsuji e={e!r} alpha={tsuji_alpha(e)!r} xgt={xgt!r}")
