#!/usr/bin/env python3
"""Toy check for docs/validation/dem-integrator.md (issue 24): the fastest linear mode of the full
DEM model (one slider sphere's z against the light control layer, reduced mass, k_z = 1e6 N/m,
anchor-relative damping tau = 1 us) under a contact-like force; explicit velocity-Verlet at
0.25 dt_crit against the trapezoidal (implicit-midpoint) map at the contact-limited step.
Plain Python, no dependencies. SI units."""
import bisect
import math

ms = 3.110e-14  # slider sphere mass (kg): 3 um diameter, 2.2 g/cm3
mc = 1.152e-15  # control-layer sphere mass (kg): 0.5 um radius
kz, tau = 1e6, 1e-6
mu = 1 / (1 / mc + 1 / ms)
w0 = math.sqrt(kz / mu)


def force(t, tr):
    return 1e-6 * min(t / tr, 1.0) * (1 + 0.2 * math.sin(2 * math.pi * t / tr))


def inv2(m):
    a, b, c, d = m[0][0], m[0][1], m[1][0], m[1][1]
    det = a * d - b * c
    return [[d / det, -b / det], [-c / det, a / det]]


def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(2)) for j in range(2)] for i in range(2)]


def mv(a, v):
    return [a[0][0] * v[0] + a[0][1] * v[1], a[1][0] * v[0] + a[1][1] * v[1]]


def run(scheme, dt, T, tr):
    x = v = 0.0
    out = []
    A = [[0, 1], [-kz / mu, -1 / tau]]
    Im = [[1 - dt / 2 * A[0][0], -dt / 2 * A[0][1]], [-dt / 2 * A[1][0], 1 - dt / 2 * A[1][1]]]
    Ip = [[1 + dt / 2 * A[0][0], dt / 2 * A[0][1]], [dt / 2 * A[1][0], 1 + dt / 2 * A[1][1]]]
    Mi = inv2(Im)
    M = mul(Mi, Ip)
    for k in range(int(T / dt)):
        t = k * dt
        if scheme == "verlet":
            a = (force(t, tr) - kz * x) / mu - v / tau
            vh = v + dt / 2 * a
            x = x + dt * vh
            a2 = (force(t + dt, tr) - kz * x) / mu
            v = (vh + dt / 2 * a2) / (1 + dt / (2 * tau))
        else:
            f = 0.5 * (force(t, tr) + force(t + dt, tr)) / mu
            s = mv(M, [x, v])
            b = mv(Mi, [0, dt * f])
            x, v = s[0] + b[0], s[1] + b[1]
        out.append((t + dt, x))
    return out


def interp(ts, xs, t):
    j = min(max(bisect.bisect_left(ts, t), 1), len(ts) - 1)
    return xs[j - 1] + (xs[j] - xs[j - 1]) * (t - ts[j - 1]) / (ts[j] - ts[j - 1])


for tr in [2e-9, 5e-9, 20e-9]:
    T = 40e-9
    e = run("verlet", 0.25 * 2 / w0, T, tr)
    i = run("trap", 4.76e-10, T, tr)
    et = [p[0] for p in e]
    ex = [p[1] for p in e]
    me, mi = max(ex), max(p[1] for p in i)
    d = max(abs(p[1] - interp(et, ex, p[0])) for p in i)
    print(f"rise {tr * 1e9:4.0f} ns: max deflection trapezoidal vs explicit {mi / me - 1:+.2e}; "
          f"largest pointwise difference / max {d / me:.2e}")
