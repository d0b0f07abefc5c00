"""Python call vs `superlube` command on the same work: the study's screen (tri-tri and
square-tri, θ = 0:30:0.1 × 4 loads = 2×1204 points) and a 51×51 landscape (square-tri, θ = 0,
1.4 mN). Runs them alternately REPEATS times and prints the median wall time of each and the
ratio. Usage: python compare_cli.py path/to/release/superlube [REPEATS]."""
import statistics, subprocess, sys, tempfile, time

import superlube

cli, repeats = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 5
cases = {
    "screen 2x1204": (
        lambda d: [subprocess.run([cli, "screen", "--pattern", p, "--out", f"{d}/{p}.csv"],
                                  check=True, capture_output=True) for p in ("tri-tri", "square-tri")],
        lambda: [superlube.screen(p, progress=False) for p in ("tri-tri", "square-tri")],
    ),
    "landscape 51x51": (
        lambda d: subprocess.run([cli, "landscape", "--pattern", "square-tri", "--theta-deg", "0",
                                  "--load-mn", "1.4", "--out", f"{d}/l.csv"], check=True, capture_output=True),
        lambda: superlube.landscape("square-tri", theta_deg=0, load_mN=1.4, progress=False),
    ),
}  # fmt: skip
for name, (run_cli, run_py) in cases.items():
    t_cli, t_py = [], []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as d:
            t0 = time.perf_counter(); run_cli(d); t_cli.append(time.perf_counter() - t0)  # noqa: E702
        t0 = time.perf_counter(); run_py(); t_py.append(time.perf_counter() - t0)  # noqa: E702
    c, p = statistics.median(t_cli), statistics.median(t_py)
    print(f"{name}: CLI {c:.3f} s, Python {p:.3f} s (medians of {repeats}), Python/CLI = {p / c:.3f}")
    print(f"  CLI runs {[round(x, 3) for x in t_cli]}, Python runs {[round(x, 3) for x in t_py]}")
