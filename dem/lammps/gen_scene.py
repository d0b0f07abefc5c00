#!/usr/bin/env python3
"""Write a LAMMPS data file (units micro, atom_style sphere) of a superlube study scene.

The geometry reproduces surrogate/src/scene (lattice.rs, scene.rs) exactly, in the same order:

  IDs 1 .. Nsub                  type 1  substrate spheres, `Lattice::sites_in_rect` order,
                                         centres at z = 0 (sigma_h = 0 only, see below)
  IDs Nsub+1 .. Nsub+Nsl         type 2  slider spheres, `Lattice::sites_in_disc` order, rotated
                                         by theta about the disc centre, centre at the offset,
                                         sphere centres at height z0 (rigid-z equilibrium at W)
  IDs Nsub+Nsl+1 .. Nsub+2Nsl    type 3  control layer, 1 um spheres, one per slider sphere,
                                         same in-plane position, CONTROL_DZ_UM above it
  --ties bond only:
  IDs Nsub+2Nsl+1 .. Nsub+3Nsl   type 5  second control sub-layer, 1 um spheres co-located with
                                         the slider spheres (partners of the x,y bonds)
  last ID                        type 4  support particle (1 um), 120 um ahead of the slider
                                         centre along alpha, at the control-layer height

--ties var  (atom_style sphere): the slider-control springs are applied by in.ties_var.lmp with
            atom-style variables (exact anisotropic springs, slow: scripted).
--ties bond (atom_style hybrid sphere bond): bond type 1 = slider -> control sphere above it
            (harmonic, rest length CONTROL_DZ_UM: axial = z stiffness), bond type 2 = slider ->
            co-located control sphere (harmonic, rest length 0: isotropic x,y stiffness); the two
            control sub-layers have density/2 each so the control layer mass is the same.

Units (LAMMPS `units micro`): length um, time us, mass pg, density pg/um^3 (= g/cm^3),
force nN, pressure 1e3 Pa (so E = 100 GPa is 1e8), velocity um/us (= m/s), stiffness nN/um
(= 1e-3 N/m, so 1e3 N/m is 1e6).

z0 is found here by a rigid-z bisection (the surrogate's RigidZ model: every slider sphere at the
same height, vertical Hertz forces sum to W) so that the DEM run starts in contact, as the Rust
engine does. Random substrate heights (sigma_h > 0) are NOT reproduced (the surrogate uses a
ChaCha8 stream that has no stdlib Python equivalent): this generator only makes sigma_h = 0 scenes.

Standard library only. Prints a one-line JSON summary on stdout.
"""

import argparse
import json
import math
import sys

S = 3e-6  # lattice spacing (m)
R = 1.5e-6  # sphere radius (m)
CONTROL_DZ_UM = 3.0  # control-layer sphere height above its slider sphere (um)
SUPPORT_AHEAD_UM = 120.0  # support starts this far ahead along alpha (um)


def triangular(s):
    return ((s, 0.0), (0.5 * s, 0.5 * math.sqrt(3.0) * s))


def square(s):
    return ((s, 0.0), (0.0, s))


def cell_area(lat):
    a1, a2 = lat
    return a1[0] * a2[1] - a1[1] * a2[0]


def point(lat, u, v):
    a1, a2 = lat
    return (u * a1[0] + v * a2[0], u * a1[1] + v * a2[1])


def index_bounds(lat, rx, ry):
    det = abs(cell_area(lat))
    r = max(rx, ry)
    a1, a2 = lat
    l1 = math.hypot(a1[0], a1[1])
    l2 = math.hypot(a2[0], a2[1])
    return (math.ceil(r * l2 / det) + 1, math.ceil(r * l1 / det) + 1)


def sites_in_disc(lat, r):
    imax, jmax = index_bounds(lat, r, r)
    r2 = r * r * (1.0 + 1e-9)
    out = []
    for j in range(-jmax, jmax + 1):
        for i in range(-imax, imax + 1):
            p = point(lat, float(i), float(j))
            if p[0] * p[0] + p[1] * p[1] <= r2:
                out.append(p)
    return out


def sites_in_rect(lat, lx, ly):
    hx = 0.5 * lx * (1.0 + 1e-12)
    hy = 0.5 * ly * (1.0 + 1e-12)
    imax, jmax = index_bounds(lat, math.hypot(hx, hy), math.hypot(hx, hy))
    out = []
    for j in range(-jmax, jmax + 1):
        for i in range(-imax, imax + 1):
            p = point(lat, float(i), float(j))
            if abs(p[0]) <= hx and abs(p[1]) <= hy:
                out.append(p)
    return out


PRESETS = {
    # name: (slider lattice, slider radius (m), substrate lattice)
    "tri-tri": (triangular(S), 93.5e-6, triangular(S)),
    "square-tri": (square(S), 100e-6, triangular(S)),
    "square-square": (square(S), 100e-6, square(S)),
    "tri-square": (triangular(S), 93.5e-6, square(S)),
}


def hertz_k(youngs, poisson):
    """(4/3) E* sqrt(R_eff) for two equal spheres of radius R (SI)."""
    e_star = youngs / (2.0 * (1.0 - poisson * poisson))
    return 4.0 / 3.0 * e_star * math.sqrt(R / 2.0), e_star


def candidate_rho2(substrate, slider):
    """Squared in-plane distances (m^2) of every slider-substrate pair closer than 2R in-plane."""
    cell = 2.0 * R
    grid = {}
    for (x, y) in substrate:
        grid.setdefault((math.floor(x / cell), math.floor(y / cell)), []).append((x, y))
    out = []
    lim = (2.0 * R) ** 2
    for (x, y) in slider:
        cx, cy = math.floor(x / cell), math.floor(y / cell)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for (sx, sy) in grid.get((cx + dx, cy + dy), ()):
                    d2 = (x - sx) ** 2 + (y - sy) ** 2
                    if d2 < lim:
                        out.append(d2)
    return out


def rigid_z(rho2, load, k):
    """Height z (m) where sum of vertical Hertz forces equals load (N); bisection."""

    def force(z):
        f = 0.0
        for r2 in rho2:
            d = math.sqrt(r2 + z * z)
            delta = 2.0 * R - d
            if delta > 0.0:
                f += k * delta ** 1.5 * (z / d)
        return f

    lo, hi = 1e-3 * R, 2.0 * R
    if not rho2 or force(lo) < load:
        raise SystemExit("rigid-z: load cannot be carried by the slider")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if force(mid) > load:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-18:
            break
    z = 0.5 * (lo + hi)
    contacts = 0
    dmax = 0.0
    for r2 in rho2:
        delta = 2.0 * R - math.sqrt(r2 + z * z)
        if delta > 0.0:
            contacts += 1
            dmax = max(dmax, delta)
    return z, contacts, dmax


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pattern", default="square-tri", choices=sorted(PRESETS))
    ap.add_argument("--theta-deg", type=float, default=0.0, help="slider rotation (degrees)")
    ap.add_argument("--alpha-deg", type=float, default=0.0,
                    help="pulling direction from +x (degrees); places the support particle")
    ap.add_argument("--offset-um", type=float, nargs=2, default=[0.0, 0.0],
                    help="slider centre relative to the substrate sphere at the origin (um)")
    ap.add_argument("--load-mN", type=float, default=1.4, help="normal load W (mN) for the start height")
    ap.add_argument("--z-um", type=float, default=None,
                    help="slider sphere centre height (um); default: rigid-z equilibrium at --load-mN")
    ap.add_argument("--youngs-GPa", type=float, default=100.0)
    ap.add_argument("--poisson", type=float, default=0.3)
    ap.add_argument("--density-g-cm3", type=float, default=2.2)
    ap.add_argument("--ties", default="var", choices=["var", "bond"],
                    help="how in.scene.lmp ties slider spheres to the control layer (see above)")
    ap.add_argument("--out", default="scene.data", help="LAMMPS data file to write")
    a = ap.parse_args()

    sl_lat, sl_r, sb_lat = PRESETS[a.pattern]
    substrate = sites_in_rect(sb_lat, 364e-6, 270e-6)
    th = math.radians(a.theta_deg)
    s, c = math.sin(th), math.cos(th)
    cx, cy = a.offset_um[0] * 1e-6, a.offset_um[1] * 1e-6
    slider = [(cx + c * p[0] - s * p[1], cy + s * p[0] + c * p[1]) for p in sites_in_disc(sl_lat, sl_r)]

    k, e_star = hertz_k(a.youngs_GPa * 1e9, a.poisson)
    rho2 = candidate_rho2(substrate, slider)
    z_rigid, contacts, dmax = rigid_z(rho2, a.load_mN * 1e-3, k)
    z = z_rigid if a.z_um is None else a.z_um * 1e-6
    p_max = 2.0 * e_star / math.pi * math.sqrt(dmax / (R / 2.0)) if dmax > 0 else 0.0

    um = 1e6
    zc = z * um + CONTROL_DZ_UM
    al = math.radians(a.alpha_deg)
    sup = (cx * um + SUPPORT_AHEAD_UM * math.cos(al), cy * um + SUPPORT_AHEAD_UM * math.sin(al), zc)
    rho = a.density_g_cm3
    bond = a.ties == "bond"
    rho_c = 0.5 * rho if bond else rho

    def atom(aid, typ, dia, dens, x, y, zz):
        # sphere: id type diameter density x y z ; hybrid sphere bond: id type x y z diameter density mol
        if bond:
            return f"{aid} {typ} {x!r} {y!r} {zz!r} {dia} {dens} 0"
        return f"{aid} {typ} {dia} {dens} {x!r} {y!r} {zz!r}"

    lines = []
    bonds = []
    aid = 0
    for (x, y) in substrate:
        aid += 1
        lines.append(atom(aid, 1, 3.0, rho, x * um, y * um, 0.0))
    first_slider = aid + 1
    for (x, y) in slider:
        aid += 1
        lines.append(atom(aid, 2, 3.0, rho, x * um, y * um, z * um))
    n = len(slider)
    for i, (x, y) in enumerate(slider):
        aid += 1
        lines.append(atom(aid, 3, 1.0, rho_c, x * um, y * um, zc))
        bonds.append((1, first_slider + i, aid))
    if bond:
        for i, (x, y) in enumerate(slider):
            aid += 1
            lines.append(atom(aid, 5, 1.0, rho_c, x * um, y * um, z * um))
            bonds.append((2, first_slider + i, aid))
    aid += 1
    lines.append(atom(aid, 4, 1.0, rho, sup[0], sup[1], sup[2]))

    # Box: substrate plus margins (non-periodic, fixed boundaries); room for 150 um of travel.
    xlo, xhi = -182.0 - 10.0, 182.0 + 10.0
    ylo, yhi = -135.0 - 10.0, 135.0 + 10.0
    xlo = min(xlo, sup[0] - 160.0)
    xhi = max(xhi, sup[0] + 160.0)
    ylo = min(ylo, sup[1] - 160.0)
    yhi = max(yhi, sup[1] + 160.0)
    zlo, zhi = -5.0, zc + 10.0
    with open(a.out, "w") as f:
        f.write(f"superlube {a.pattern} theta_deg={a.theta_deg} alpha_deg={a.alpha_deg} "
                f"load_mN={a.load_mN} z_um={z * um!r} ties={a.ties} (units micro)\n\n")
        if bond:
            f.write(f"{aid} atoms\n5 atom types\n{len(bonds)} bonds\n2 bond types\n\n")
        else:
            f.write(f"{aid} atoms\n4 atom types\n\n")
        f.write(f"{xlo} {xhi} xlo xhi\n{ylo} {yhi} ylo yhi\n{zlo} {zhi} zlo zhi\n\n")
        f.write("Atoms # hybrid\n\n" if bond else "Atoms # sphere\n\n")
        f.write("\n".join(lines))
        f.write("\n")
        if bond:
            f.write("\nBonds\n\n")
            f.write("\n".join(f"{k + 1} {t} {i} {j}" for k, (t, i, j) in enumerate(bonds)))
            f.write("\n")
    summary = {
        "data": a.out,
        "pattern": a.pattern,
        "ties": a.ties,
        "theta_deg": a.theta_deg,
        "alpha_deg": a.alpha_deg,
        "load_mN": a.load_mN,
        "n_substrate": len(substrate),
        "n_slider": len(slider),
        "n_atoms": aid,
        "z_um": z * um,
        "rigid_z_um": z_rigid * um,
        "rigid_contacts": contacts,
        "rigid_p_max_GPa": p_max / 1e9,
        "support_um": list(sup),
        "control_z_um": zc,
    }
    json.dump(summary, sys.stdout)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
