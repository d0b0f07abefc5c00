#!/usr/bin/env python3
"""Run the two LAMMPS reference cases and write the CSVs in reference/ (committed).

    cd dem/lammps && python3 make_reference.py            # needs `lmp` (Debian package lammps)

Cases (parameters exactly as in in.collision.lmp / in.drag.lmp, units micro in LAMMPS,
converted to the CSV column units named in each header):
  collision: two free spheres R = 1.5 um, rho = 2.2 g/cm^3, E = 100 GPa, nu = 0.3, head-on,
             relative speed v_rel, undamped or with the Rust engine's damping gamma_n = 0.1
             (LAMMPS `damping tsuji` with the e of damping.py), dt 1e-5 us
             -> reference/collision_<case>.csv (every 10 steps) + reference/collision_summary.csv
  drag:      sphere pressed with F_n = 10 uN on a fixed sphere, pulled by a K_d = 1e3 N/m spring
             whose anchor moves at 0.01 m/s for 2 us, mu = 0.5 and 0.01, gamma_n = gamma_t = 0.1
             -> reference/drag_mu<mu>.csv (every 100 steps) + reference/drag_summary.csv
  equilibrate (only with --with-scene, a few minutes each on one core): the study scene exported
             by `superlube export-lammps` (mount locked, the rigid translating control layer of the
             earlier peer scripts), 10 us at dt = 5e-5 us, square-tri theta 0 at 1.4 mN and tri-tri
             theta 30 at 2.1 mN, mu = 0.01
             -> reference/equilibrate_<case>.csv (t_us,contacts,p_max_GPa,z_um every 0.1 us)
                + reference/equilibrate_summary.csv (with the surrogate's start for comparison)
             The superlube binary: $SUPERLUBE, else `superlube` on the PATH, else
             `cargo run --release` in the repository.
  reference/rigid_z_python.csv is frozen: it was written by the former Python re-implementation
  of the scene (gen_scene.py, replaced by the export) and tests/lammps_peer.rs keeps checking the
  Rust scene against it.
Standard library only.
"""

import json
import math
import os
import subprocess
import sys
import tempfile

from damping import lammps_damping

HERE = os.path.dirname(os.path.abspath(__file__))
REF = os.path.join(HERE, "reference")

R = 1.5  # um
RHO = 2.2  # pg/um^3
E = 1e8  # 1e3 Pa  (100 GPa)
NU = 0.3
M = RHO * 4.0 / 3.0 * math.pi * R ** 3  # pg
E_STAR = E / (2.0 * (1.0 - NU * NU))
R_EFF = R / 2.0
G_STAR = E / (4.0 * (2.0 - NU) * (1.0 + NU))  # LAMMPS mix_stiffnessG for equal materials


def lmp(inp, **var):
    args = ["lmp", "-in", inp, "-log", "none", "-screen", "none"]
    for k, v in var.items():
        args += ["-var", k, str(v)]
    subprocess.run(args, cwd=HERE, check=True)


def read_table(path):
    with open(path) as f:
        lines = [ln.split() for ln in f if ln.strip() and not ln.startswith("#")]
    head = lines[0]
    rows = [[float(x) for x in ln] for ln in lines[1:]]
    return head, rows


def write_csv(path, header, rows, fmt="{:.15g}"):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(x if isinstance(x, str) else fmt.format(x) for x in r) + "\n")
    os.replace(tmp, path)


def hertz_collision(v_rel):
    """Closed-form undamped Hertz collision of two equal spheres: (t_contact_us, max_overlap_um)."""
    m_eff = M / 2.0
    k = 4.0 / 3.0 * E_STAR * math.sqrt(R_EFF)
    d_max = (15.0 * m_eff * v_rel ** 2 / (16.0 * E_STAR * math.sqrt(R_EFF))) ** 0.4
    # t_c = 2 d_max / v * int_0^1 (1 - x^(5/2))^(-1/2) dx, the integral = B(2/5, 1/2) / (5/2)
    integral = math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9) / 2.5
    assert abs(0.5 * m_eff * v_rel ** 2 - 0.4 * k * d_max ** 2.5) < 1e-9 * m_eff * v_rel ** 2
    return 2.0 * d_max / v_rel * integral, d_max


def crossing(t0, y0, t1, y1):
    return t0 + (0.0 - y0) * (t1 - t0) / (y1 - y0)


def collision_case(name, v_rel, gamma_n, dt=1e-5, steps=4000):
    if gamma_n > 0.0:
        damp, dcoef = "tsuji", lammps_damping(gamma_n, gamma_n)[0]
    else:
        damp, dcoef = "viscoelastic", 0.0
    with tempfile.TemporaryDirectory() as td:
        out = os.path.join(td, "c.txt")
        lmp("in.collision.lmp", v_rel=v_rel, damp=damp, dcoef=repr(dcoef), dt=dt, steps=steps, out=out)
        _, rows = read_table(out)
    # rows: step t x1 x2 v1 v2 overlap fx1
    idx = [i for i, r in enumerate(rows) if r[6] > 0.0]
    a, b = idx[0], idx[-1]
    t_in = crossing(rows[a - 1][1], rows[a - 1][6], rows[a][1], rows[a][6])
    t_out = crossing(rows[b][1], rows[b][6], rows[b + 1][1], rows[b + 1][6])
    v_in = rows[0][4] - rows[0][5]
    v_out = rows[-1][5] - rows[-1][4]
    tc_h, dmax_h = hertz_collision(v_rel)
    summary = [
        name, v_rel, gamma_n, damp, dcoef, dt, t_out - t_in, tc_h, v_out / v_in,
        max(r[6] for r in rows), dmax_h, max(-r[7] for r in rows) * 1e-3,
    ]
    csv_rows = [[r[1], r[2], r[3], r[4], r[5], r[6], -r[7] * 1e-3] for r in rows if int(r[0]) % 10 == 0]
    write_csv(
        os.path.join(REF, f"collision_{name}.csv"),
        ["t_us", "x1_um", "x2_um", "v1_m_s", "v2_m_s", "overlap_um", "contact_force_uN"],
        csv_rows,
    )
    return summary


def drag_case(mu, gamma_n=0.1, gamma_t=0.1, Fn=1.0e4, Kd=1.0e6, vd=0.01, dt=1e-5, steps=200000, every=100):
    e, xgt = lammps_damping(gamma_n, gamma_t)
    with tempfile.TemporaryDirectory() as td:
        out = os.path.join(td, "d.txt")
        lmp("in.drag.lmp", mu=mu, damp="tsuji", dcoef=repr(e), xgt=repr(xgt), Fn=Fn, Kd=Kd, vd=vd, dt=dt,
            steps=steps, every=every, out=out)
        _, rows = read_table(out)
    # rows: step t anchor x z fn ft ftx fspring   (nN, um)
    name = f"mu{mu:g}"
    write_csv(
        os.path.join(REF, f"drag_{name}.csv"),
        ["t_us", "anchor_x_nm", "x_nm", "z_um", "normal_force_uN", "tangential_force_uN",
         "tangential_force_x_uN", "spring_force_uN"],
        [[r[1], r[2] * 1e3, r[3] * 1e3, r[4], r[5] * 1e-3, r[6] * 1e-3, r[7] * 1e-3, r[8] * 1e-3]
         for r in rows],
    )
    # slip onset: first sample where ft >= (1 - 1e-6) mu fn
    slip = next((r for r in rows if r[6] >= (1.0 - 1e-6) * mu * r[5]), None)
    sliding = [r for r in rows if r[6] >= (1.0 - 1e-6) * mu * r[5]]
    ratio = sum(r[6] / r[5] for r in sliding) / len(sliding) if sliding else float("nan")
    # stick stiffness from the first 10 % of the stick branch
    stick = [r for r in rows[1:] if r[6] < 0.5 * mu * r[5]]
    kt_meas = (stick[-1][6] - stick[0][6]) / (stick[-1][3] - stick[0][3]) if len(stick) > 2 else float("nan")
    d0 = (Fn / (4.0 / 3.0 * E_STAR * math.sqrt(R_EFF))) ** (2.0 / 3.0)
    kt_theory = 8.0 * G_STAR * math.sqrt(R_EFF * d0)
    return [
        name, mu, Fn * 1e-3, Kd * 1e-3, vd, gamma_n, gamma_t, e, xgt, dt,
        slip[2] * 1e3 if slip else float("nan"), slip[6] * 1e-3 if slip else float("nan"),
        ratio, kt_meas * 1e-3, kt_theory * 1e-3,
    ]


def superlube():
    """The command that runs the superlube binary."""
    if os.environ.get("SUPERLUBE"):
        return [os.environ["SUPERLUBE"]]
    for d in os.environ.get("PATH", "").split(os.pathsep):
        if os.access(os.path.join(d, "superlube"), os.X_OK):
            return ["superlube"]
    root = os.path.dirname(os.path.dirname(HERE))
    return ["cargo", "run", "--release", "--quiet", "--manifest-path", os.path.join(root, "Cargo.toml"), "--"]


def equilibrate_case(pattern, theta, load, dt=5e-5, us=10.0):
    name = f"{pattern}_{theta:g}deg_{load:g}mN"
    with tempfile.TemporaryDirectory() as td:
        subprocess.run(
            superlube() + ["export-lammps", "--pattern", pattern, "--theta", str(theta), "--load-mn", str(load),
                           "--tilt", "locked", "--dt-us", str(dt), "--equilibrate-us", str(us), "--relax-us", "0",
                           "--slide-us", "0", "--sample-us", "0.1", "--dump-us", "0", "--out", td],
            check=True)
        with open(os.path.join(td, "export.json")) as f:
            meta = json.load(f)
        subprocess.run(["lmp", "-in", "in.superlube.lmp", "-log", "none", "-screen", "none"], cwd=td, check=True)
        with open(os.path.join(td, "timeseries.csv")) as f:
            lines = [ln.strip() for ln in f if ln.strip()]
    head = lines[0].lstrip("# ").split(",")
    keep = [head.index(c) for c in ("t_us", "contacts", "p_max_GPa", "z_um")]
    rows = [[r[i] for i in keep] for r in (ln.split(",") for ln in lines[1:])]
    write_csv(os.path.join(REF, f"equilibrate_{name}.csv"), ["t_us", "contacts", "p_max_GPa", "z_um"], rows)
    last = rows[-1]
    sur = meta["surrogate"]
    return [name, pattern, theta, load, dt, us, int(float(last[1])), float(last[2]), float(last[3]),
            sur["contacts"], sur["p_max_GPa"], sur["z_um"]]


def main():
    os.makedirs(REF, exist_ok=True)
    if "--with-scene" in sys.argv:
        eq = [equilibrate_case("square-tri", 0.0, 1.4), equilibrate_case("tri-tri", 30.0, 2.1)]
        write_csv(
            os.path.join(REF, "equilibrate_summary.csv"),
            ["case", "pattern", "theta_deg", "load_mN", "dt_us", "time_us", "contacts", "p_max_GPa", "z_um",
             "surrogate_contacts", "surrogate_p_max_GPa", "surrogate_z_um"],
            eq,
        )
        for r in eq:
            print(*r, sep=",")
    col = [
        collision_case("v0.2_undamped", 0.2, 0.0),
        collision_case("v0.2_gn0.1", 0.2, 0.1),
        collision_case("v1_gn0.1", 1.0, 0.1),
    ]
    write_csv(
        os.path.join(REF, "collision_summary.csv"),
        ["case", "v_rel_m_s", "gamma_n", "lammps_damping", "lammps_damping_coeff", "dt_us", "t_contact_us", "t_contact_hertz_us",
         "restitution", "max_overlap_um", "max_overlap_hertz_um", "max_force_uN"],
        col,
    )
    dr = [drag_case(0.5), drag_case(0.01)]
    write_csv(
        os.path.join(REF, "drag_summary.csv"),
        ["case", "mu", "normal_load_uN", "drag_spring_N_m", "anchor_speed_m_s", "gamma_n", "gamma_t",
         "lammps_tsuji_e", "lammps_xgt", "dt_us", "slip_onset_anchor_nm", "slip_tangential_force_uN", "sliding_ft_over_fn",
         "stick_stiffness_N_m", "mindlin_8Ga_N_m"],
        dr,
    )
    for r in col + dr:
        print(*r, sep=",")


if __name__ == "__main__":
    sys.exit(main())
