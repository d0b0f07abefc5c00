"""The Python workflows against the `superlube` command line: same rows, same errors, same
summaries; interrupts; thread-count independence."""

import json
import subprocess
import time

import numpy as np
import pandas as pd
import pytest

import superlube

# A small square-tri scene (9 µm slider on a 60x40 µm substrate): milliseconds per solve.
TINY = dict(radius_um=9, size_um=[60, 40], sigma_h_um=0.002, seed=3)
# The DEM protocol of the command-line tests: fractions of a µs, about a second.
DEM = dict(equilibrate_us=0.1, relax_us=0.1, slide_us=0.3, speed_m_s=1, rigid_z=True, prune=True)


def test_screen_equals_cli_row_for_row(cli_bin, tmp_path):
    scene = superlube.Scene("square-tri", **TINY)
    scene.write(tmp_path / "s.toml")
    thetas, loads = [0, 0.5, 10.2, 29.9], [0.35, 1.4, 3.86]
    df = superlube.screen(scene, theta_deg=thetas, load_mN=loads, out=tmp_path / "py.csv")
    subprocess.run(
        [cli_bin, "screen", "--scene", tmp_path / "s.toml", "--theta-deg", "0,0.5,10.2,29.9",
         "--load-mn", "0.35,1.4,3.86", "--out", tmp_path / "cli.csv"],
        check=True, capture_output=True,
    )  # fmt: skip
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()
    cli = superlube._run.read_table(str(tmp_path / "cli.csv"))
    pd.testing.assert_frame_equal(df, cli, check_exact=True)
    assert len(df) == len(thetas) * len(loads)
    assert list(df["theta_deg"][:: len(loads)]) == thetas
    assert "p_max_GPa" in df.columns and df["p_max_GPa"].gt(0).all()
    assert df.attrs["meta"]["workflow"] == "screen"


def test_no_pandas_gives_numpy_columns(monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "pandas", None)
    d = superlube.screen(superlube.Scene("square-tri", **TINY), theta_deg=[0, 5], load_mN=[1.4])
    assert isinstance(d, dict)
    assert d["theta_deg"].dtype == np.float64 and list(d["theta_deg"]) == [0.0, 5.0]
    assert d["contacts"].dtype == np.int64 and (d["contacts"] > 0).all()


@pytest.mark.parametrize(
    "fields, name",
    [
        (dict(youngs_GPa=-50), "youngs_GPa"),
        (dict(sigma_h_um=-0.01), "sigma_h_um"),
        (dict(radius_um=float("nan")), "radius_um"),
        (dict(pattern="hex-tri"), "hex-tri"),
        (dict(youngs_gpa=100, color="red"), "color"),
    ],
)
def test_bad_scene_field_raises_value_error_naming_it(fields, name):
    with pytest.raises(ValueError, match=name):
        superlube.Scene(**{"pattern": "square-tri", **fields})


def test_scene_message_is_the_clis(cli_bin, tmp_path):
    with pytest.raises(ValueError) as e:
        superlube.Scene("square-tri", p_crit_GPa=-4)
    r = subprocess.run([cli_bin, "screen", "--p-crit-gpa", "-4", "--theta-deg", "0"],
                       capture_output=True, text=True)  # fmt: skip
    assert r.returncode != 0
    # the same reason, and the CLI names the flag and the field it sets
    reason = str(e.value).rsplit("(", 1)[-1].rstrip(")")
    assert reason in r.stderr and "coating.p_crit_GPa" in r.stderr, (str(e.value), r.stderr)


def test_bad_option_raises_before_any_file(private_tmp, tmp_path):
    out = tmp_path / "out" / "s.csv"
    out.parent.mkdir()
    scene = superlube.Scene("square-tri", **TINY)
    with pytest.raises(ValueError, match="load"):
        superlube.screen(scene, theta_deg=[0], load_mN=[-1.4], out=out)
    with pytest.raises(ValueError, match="theta_dgr"):
        superlube.screen(scene, theta_dgr=[0])
    with pytest.raises(ValueError, match="sigma_h_um"):
        superlube.screen(scene, sigma_h_um=0.01)
    assert list(out.parent.iterdir()) == []
    assert list(private_tmp.iterdir()) == []


def test_old_option_names_work_with_a_warning(tmp_path):
    scene = superlube.Scene("square-tri", **TINY)
    new = superlube.screen(scene, theta_deg=[0, 5], load_mN=[1.4], solver="rigid-z")
    with pytest.warns(DeprecationWarning, match="`model` is now `solver`") as w:
        old = superlube.screen(scene, theta_deg=[0, 5], load_mN=[1.4], model="rigid-z")
    ours = [x for x in w if "is now" in str(x.message)]
    assert [x.filename for x in ours] == [__file__]  # points at the caller, not the package
    pd.testing.assert_frame_equal(old, new, check_exact=True)
    assert set(new["model"]) == {"rigid-z"}
    with pytest.raises(ValueError, match="old name"):
        superlube.screen(scene, theta_deg=[0], solver="auto", model="auto")
    # an output keyword: tolerance's folder is `out_dir`, formerly `out`
    opts = dict(theta_deg=30, alpha_deg=0, load_mN="0.05", theta_range_deg=0.2, theta_points=2,
                direction_range_deg=0.5, direction_points=2)  # fmt: skip
    with pytest.warns(DeprecationWarning, match="`out` is now `out_dir`"):
        superlube.tolerance(superlube.Scene("tri-tri", radius_um=9, size_um=[60, 60]),
                            out=tmp_path / "tol", **opts)  # fmt: skip
    assert (tmp_path / "tol" / "map.csv").exists()
    # θ and α carry their unit: `alpha` (tolerance's old spelling) is `alpha_deg`
    with pytest.warns(DeprecationWarning, match="`alpha` is now `alpha_deg`"):
        old = superlube.tolerance(superlube.Scene("tri-tri", radius_um=9, size_um=[60, 60]),
                                  alpha=0, **{k: v for k, v in opts.items() if k != "alpha_deg"})  # fmt: skip
    assert len(old) == 4


def test_the_geometry_flags_are_scene_fields():
    scene = superlube.Scene("square-tri", radius_um=12, size_um=[60, 60],
                            slider_lattice="honeycomb:6", slider_sphere_diameter_um=3)  # fmt: skip
    assert "honeycomb" in scene.to_toml()
    disc = superlube.Scene("square-tri", size_um=[60, 60], outline="disc:9")
    assert "outline" in disc.to_toml()
    for key in ("slider_lattice", "outline", "slider_sites", "substrate_sites",
                "slider_sphere_diameter_um", "substrate_sphere_diameter_um"):  # fmt: skip
        with pytest.raises(ValueError, match="is a scene field"):
            superlube.screen(scene, theta_deg=0, load_mN=1, **{key: "x"})


def test_slide_returns_the_json_summary(cli_bin, tmp_path):
    scene = superlube.Scene("square-tri", radius_um=9, size_um=[60, 40])
    series, summary = superlube.slide(scene, load_mN=1.4, **DEM)
    scene.write(tmp_path / "s.toml")
    flags = ["--equilibrate-us", "0.1", "--relax-us", "0.1", "--slide-us", "0.3",
             "--speed-m-s", "1", "--rigid-z", "--prune"]  # fmt: skip
    subprocess.run(
        [cli_bin, "slide", "--scene", tmp_path / "s.toml", "--load-mn", "1.4", *flags,
         "--out", tmp_path / "cli.csv", "--json", tmp_path / "cli.json"],
        check=True, capture_output=True,
    )  # fmt: skip
    cli = json.loads((tmp_path / "cli.json").read_text())
    assert set(summary) == set(cli)
    timing = {k for k in cli if "wall" in k or k.endswith("_per_s")}  # machine-dependent
    assert {k: v for k, v in summary.items() if k not in timing} == {
        k: v for k, v in cli.items() if k not in timing
    }
    assert {"mu", "friction_mN", "max_p_max_GPa"} <= set(summary)
    assert list(series.columns) == list(pd.read_csv(tmp_path / "cli.csv").columns)
    assert series.attrs["summary"] == summary


def _long_screen(**kw):
    # 3001 θ × 4 loads on the study's square-tri: tens of seconds on two cores.
    return superlube.screen("square-tri", theta_deg="0:30:0.01", **kw)


def test_raising_callback_stops_promptly(private_tmp):
    calls = []

    def stop(p):
        calls.append(p)
        if p["done"] > 0:
            raise KeyboardInterrupt

    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        _long_screen(progress=stop)
    assert time.monotonic() - t0 < 10, "did not stop promptly"
    assert calls and calls[-1]["stage"] == "screen" and calls[-1]["done"] < calls[-1]["total"]
    assert list(private_tmp.iterdir()) == []  # no partial files left


def test_callback_exception_propagates():
    class Stop(Exception):
        pass

    def stop(p):
        raise Stop("from the callback")

    t0 = time.monotonic()
    with pytest.raises(Stop, match="from the callback"):
        _long_screen(progress=stop)
    assert time.monotonic() - t0 < 10


def test_progress_reaches_the_callback():
    seen = []
    superlube.screen(superlube.Scene("square-tri", **TINY), theta_deg="0:30:1", load_mN=[1.4],
                     progress=seen.append)  # fmt: skip
    assert seen and seen[-1]["total"] == 31 and seen[-1]["unit"] == "θ"


def test_thread_count_does_not_change_results():
    scene = superlube.Scene("square-tri", **TINY)
    kw = dict(theta_deg="0:30:1.5", load_mN=[0.35, 2.1])
    a = superlube.screen(scene, threads=1, **kw)
    b = superlube.screen(scene, threads=2, **kw)
    pd.testing.assert_frame_equal(a, b, check_exact=True)
    la = superlube.landscape(scene, load_mN=1.4, grid=6, threads=1)
    lb = superlube.landscape(scene, load_mN=1.4, grid=6, threads=3)
    pd.testing.assert_frame_equal(la, lb, check_exact=True)
    assert list(la.columns) == ["x_um", "y_um", "dz_nm"] and len(la) == 36


def test_scene_keywords_and_files(tmp_path):
    s = superlube.Scene("square-tri", youngs_GPa=50, sigma_h_um=0.01)
    d = s.to_dict()
    assert d["material"]["youngs_GPa"] == 50 and d["substrate"]["sigma_h_um"] == 0.01
    s.write(tmp_path / "a.toml")
    t = superlube.Scene(str(tmp_path / "a.toml"), seed=7)
    assert t.to_dict()["material"]["youngs_GPa"] == 50
    assert t.to_dict()["substrate"]["seed"] == 7 and t.name == "a"
    assert s.replace(youngs_GPa=100).to_dict()["material"]["youngs_GPa"] == 100


def test_sigint_raises_keyboard_interrupt(private_tmp):
    import os
    import signal
    import threading

    # SIGINT every 0.2 s until the call returns (a loaded machine may start the sender late);
    # Python's handler raises on the first one and ignores the rest.
    first = []

    def handler(signum, frame):
        if not first:
            first.append(time.monotonic())
            raise KeyboardInterrupt

    done = threading.Event()

    def sender():
        while not done.wait(0.2):
            os.kill(os.getpid(), signal.SIGINT)

    old = signal.signal(signal.SIGINT, handler)
    t = threading.Thread(target=sender)
    t.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            superlube.screen("square-tri", theta_deg="0:30:0.002", progress=False)
        stopped = time.monotonic()
    finally:
        done.set()
        t.join()
        signal.signal(signal.SIGINT, old)
    assert stopped - first[0] < 5, "did not stop promptly"
    assert list(private_tmp.iterdir()) == []


def test_corrugation_friction_equilibrate_columns(cli_bin, tmp_path):
    scene = superlube.Scene("square-tri", radius_um=9, size_um=[60, 40])
    cor = superlube.corrugation(scene, theta_deg=0, load_mN=1.4, alpha_deg=[0, 90],
                                distance_um=3, step_um=0.5)  # fmt: skip
    assert list(cor["alpha_deg"]) == [0.0, 90.0] and "corrugation_nm" in cor.columns
    fr = superlube.friction(scene, theta_deg=[0], alpha_deg=[0], load_mN=[1.4], length_um=6)
    assert len(fr) == 1 and "load_mN" in fr.columns
    eq = superlube.equilibrate(scene, load_mN=1.4, equilibrate_us=0.1, rigid_z=True)
    assert "t_us" in eq.columns and len(eq) > 0 and "summary" in eq.attrs
    scene.write(tmp_path / "s.toml")
    r = subprocess.run([cli_bin, "friction", "--scene", tmp_path / "s.toml", "--theta-deg", "0",
                        "--alpha-deg", "0", "--load-mn", "1.4", "--length-um", "6"],
                       check=True, capture_output=True, text=True)  # fmt: skip
    assert list(fr.columns) == r.stdout.splitlines()[0].split(",")


def test_design_on_scenes_returns_ranking_and_answer():
    k = dict(radius_um=9, size_um=[100, 100])
    scenes = [superlube.Scene("square-tri", **k), superlube.Scene("tri-tri", **k)]
    ranking, summary = superlube.design(scenes, load_mN="0.35,1.4", no_dem=True)
    assert set(summary["answer"]) == {"square-tri", "tri-tri"}
    assert set(ranking["pattern"]) == {"square-tri", "tri-tri"}
    assert ranking["rank"].min() == 1 and "superlubric_to_mN" in ranking.columns
    assert summary["report_md"].startswith("# superlube design")


def test_design_vary_is_repeatable_and_equals_cli(cli_bin, tmp_path):
    """`vary` as a dict (or a list of FIELD=LIST strings) gives one `--vary` per field: the
    recipes and their limits are those of the command line with the same flags."""
    k = dict(radius_um=9, size_um=[100, 100])
    opts = dict(load_mN="0.35,1.4", theta_deg="0:15:5", theta_tol_deg=0, direction_tol_deg=0,
                no_dem=True)  # fmt: skip
    vary = {"slider.sphere_diameter_um": [2.5, 3], "slider.material.youngs_GPa": "50,100"}
    ranking, _ = superlube.design(superlube.Scene("tri-tri", **k), vary=vary, **opts)
    assert len(set(ranking["pattern"])) == 4
    assert "tri-tri+slider.sphere_diameter_um=2.5+slider.material.youngs_GPa=50" in set(
        ranking["pattern"])  # fmt: skip
    as_list = ["slider.sphere_diameter_um=2.5,3", "slider.material.youngs_GPa=50,100"]
    ranking2, _ = superlube.design(superlube.Scene("tri-tri", **k), vary=as_list, **opts)
    assert list(ranking2["superlubric_to_mN"]) == list(ranking["superlubric_to_mN"])
    superlube.Scene("tri-tri", **k).write(tmp_path / "tri-tri.toml")
    subprocess.run([cli_bin, "design", "--scene", tmp_path / "tri-tri.toml", "--load-mn",
                    "0.35,1.4", "--theta-deg", "0:15:5", "--theta-tol-deg", "0", "--direction-tol-deg",
                    "0", "--no-dem", "--vary", "slider.sphere_diameter_um=2.5,3", "--vary",
                    "slider.material.youngs_GPa=50,100", "--out-dir", tmp_path / "cli"],
                   check=True, capture_output=True)  # fmt: skip
    import csv
    with open(tmp_path / "cli" / "ranking.csv") as f:
        cli = list(csv.DictReader(f))
    assert [float(r["superlubric_to_mN"]) for r in cli] == list(ranking["superlubric_to_mN"])
    assert [r["pattern"] for r in cli] == list(ranking["pattern"])


def test_tolerance_map_equals_cli(cli_bin, tmp_path):
    scene = superlube.Scene("tri-tri", radius_um=9, size_um=[60, 60])
    opts = dict(theta_deg=30, alpha_deg=0, load_mN="0.05,0.1", theta_range_deg=0.2, theta_points=3,
                direction_range_deg=0.5, direction_points=3, theta_tol_deg=0.1, direction_tol_deg=0.5)  # fmt: skip
    m = superlube.tolerance(scene, **opts)
    assert len(m) == 9 and "superlubric_to_mN" in m.columns
    scene.write(tmp_path / "s.toml")
    subprocess.run([cli_bin, "tolerance", "--scene", tmp_path / "s.toml", "--theta-deg", "30",
                    "--alpha-deg", "0", "--load-mn", "0.05,0.1", "--theta-range-deg", "0.2",
                    "--theta-points", "3", "--direction-range-deg", "0.5", "--direction-points",
                    "3", "--out-dir", tmp_path / "cli"], check=True, capture_output=True)  # fmt: skip
    import csv
    with open(tmp_path / "cli" / "map.csv") as f:
        cli = list(csv.DictReader(f))
    assert [float(r["superlubric_to_mN"]) for r in cli] == list(m["superlubric_to_mN"])


def test_yield_equals_cli(cli_bin, tmp_path):
    scene = superlube.Scene("tri-tri", radius_um=9, size_um=[60, 60], sigma_h_um=0.002)
    opts = dict(theta_deg=30, direction_deg=0, load_mN="0.02,0.05,0.1", samples=4, no_dem=True)
    devices, summary = superlube.yield_(scene, **opts)
    assert len(devices) == 4 and "critical_load_mN" in devices.columns
    assert summary["samples"] == 4 and summary["dem"] is False
    scene.write(tmp_path / "s.toml")
    subprocess.run([cli_bin, "yield", "--scene", tmp_path / "s.toml", "--theta-deg", "30",
                    "--direction-deg", "0", "--load-mn", "0.02,0.05,0.1", "--samples", "4",
                    "--no-dem", "--out-dir", tmp_path / "cli"],
                   check=True, capture_output=True)  # fmt: skip
    import csv
    with open(tmp_path / "cli" / "yield.csv") as f:
        cli = list(csv.DictReader(f))
    assert [float(r["critical_load_mN"]) for r in cli] == list(devices["critical_load_mN"])
