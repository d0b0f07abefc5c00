"""superlube from Python: screen, map and confirm patterned superlubric interfaces.

The same workflows as the ``superlube`` command line, run in process (no subprocess, the GIL
released, rayon on every core or ``threads``): each function takes a :class:`Scene` and the
command's options as keywords named like its flags in snake case with their unit
(``--load-mn`` → ``load_mN``, ``--theta-deg`` → ``theta_deg``), checks them exactly as
the command does (``ValueError`` naming the bad option or field, before any work), and returns
the command's CSV as a ``pandas.DataFrame`` with the CSV's column names (units in the names; a
dict of numpy arrays where pandas is not installed). ``df.attrs["meta"]`` holds the output's
sidecar: the resolved scene, the parameters and a hash of the inputs.

Values: numbers, lists/tuples/numpy arrays of numbers (``theta_deg=[0, 21.8, 30]``), or the
CLI's text forms (``theta_deg="0:30:0.1"``, an inclusive range). ``True`` turns a switch on.
Outputs a command can also write (``plot="map.png"``, ``contacts_out="c.csv"``, ``out="s.csv"``,
``out_dir="design"``) are written where the keyword says, with their sidecars; otherwise in a
temporary directory that is removed afterwards. A renamed flag keeps its old keyword for a
release, as the command line keeps the old flag name: ``screen(model="auto")`` works as
``screen(solver="auto")`` with a :class:`DeprecationWarning` naming the new keyword.

Every function also takes ``progress`` (None: a tqdm bar when tqdm is installed; False: none;
a callable ``f(p)``: called on the calling thread at most every 0.1 s with ``p`` a dict of
``stage``, ``done``, ``total``, ``unit``, ``status`` and ``notes``, the new log lines — raising
from it stops the run) and ``threads`` (size of the thread pool; results do not depend on it).
Ctrl-C stops a run within a progress step and raises ``KeyboardInterrupt``; the temporary
outputs are removed (a file named by ``out=`` is left as ``OUT.partial``, which the command's
``resume=True`` continues, like the command line). Log lines go to the ``superlube`` logger,
lines starting with ``warning:`` to :mod:`warnings`.

Adding a workflow (e.g. ``tolerance``): one function below calling ``_table`` (or ``_run.run``
and the readers for several outputs) with the command's name and its output flags.
"""

from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

from . import _native, _run
from ._scene import Scene

__all__ = [
    "Scene",
    "screen",
    "landscape",
    "corrugation",
    "friction",
    "tolerance",
    "yield_",
    "design",
    "equilibrate",
    "slide",
    "run_command",
]
__version__: str = _native.__version__

SceneLike = Union[Scene, str, None]


def _scene(s: SceneLike) -> Scene:
    return s if isinstance(s, Scene) else Scene(s)


def _scene_files(tmp: str, scenes: Sequence[Scene]) -> List[str]:
    """Writes each scene to ``tmp/<name>.toml`` (names made unique); returns the flags."""
    flags, seen = [], set()
    for sc in scenes:
        name, k = sc.name, 2
        while name in seen:
            name, k = f"{sc.name}_{k}", k + 1
        seen.add(name)
        d = os.path.join(tmp, "scenes")
        os.makedirs(d, exist_ok=True)
        path = os.path.join(d, f"{name}.toml")
        sc.write(path)
        flags.append(f"--scene={path}")
    return flags


def _go(command, scenes, options, outputs, progress, threads, allow_scene_flags=False):
    import tempfile

    tmp_scenes = tempfile.mkdtemp(prefix="superlube-scene-")
    try:
        flags = _scene_files(tmp_scenes, scenes)
        return _run.run(command, flags, options, outputs, progress, threads, allow_scene_flags)
    finally:
        _run.remove(tmp_scenes)


def _table(command: str, scene: SceneLike, options: Dict[str, Any], progress, threads) -> Any:
    tmp, paths = _go(command, [_scene(scene)], options, {"out": "out.csv"}, progress, threads)
    try:
        return _run._attach(_run.read_table(paths["out"]), paths["out"])
    finally:
        _run.remove(tmp)


def screen(scene: SceneLike = None, *, progress: Any = None, threads: Optional[int] = None,
           **options: Any) -> Any:  # fmt: skip
    """Orientation × load screen (quasi-static): for every θ (outer) and load W (inner), the
    contacts, P_max (GPa), height z (µm), coating failure, tilt (µrad) and the model used.

    Options (``superlube screen --help``): ``theta_deg`` (degrees; default the scene's θ, else
    0:30:0.1), ``load_mN`` (mN; default 0.35, 1.4, 2.1, 3.86), ``solver`` (auto, rigid-z,
    rigid-tilt, compliant; formerly ``model``), ``search`` (grid, bvh), ``contacts_out``
    (path), ``force``, ``shard`` ("i/n"), ``resume``, ``out`` (path). Cost: one equilibrium per
    (θ, W), about 1 ms each for the study's scenes on one core.

    Returns a DataFrame with the columns of the screen CSV: pattern, theta_deg, load_mN,
    contacts, p_max_GPa, z_um, coating_failed, failed_contacts, tilt_x_urad, tilt_y_urad, model,
    residual_rel, iterations, error.
    """
    return _table("screen", scene, options, progress, threads)


def landscape(scene: SceneLike = None, *, progress: Any = None, threads: Optional[int] = None,
              **options: Any) -> Any:  # fmt: skip
    """Height landscape Δz over the substrate's repeat cell at one θ and load (quasi-static).

    Options (``superlube landscape --help``): ``theta_deg`` (degrees), ``load_mN`` (mN),
    ``grid`` (N points per side, N×N solves; default 51), ``plot`` (heat-map PNG),
    ``contact_map`` (contact-map PNG), ``contacts_out`` (per-contact CSV), ``force``, ``shard``,
    ``resume``, ``out``.

    Returns a DataFrame ``x_um, y_um, dz_nm`` (shift of the slider centre in µm, Δz = z − min z
    in nm), row-major with x fastest.
    """
    return _table("landscape", scene, options, progress, threads)


def corrugation(scene: SceneLike = None, *, progress: Any = None,
                threads: Optional[int] = None, **options: Any) -> Any:  # fmt: skip
    """Corrugation (nm) and static-friction barrier (mN) along pulling directions α.

    Options (``superlube corrugation --help``): ``theta_deg``, ``load_mN``, ``alpha_deg``
    (degrees, list or range), ``line_deg``, ``distance_um`` and ``step_um`` (the path, µm),
    ``method`` (direct, landscape), ``grid``, ``plot`` (PNG), ``force``, ``shard``, ``resume``,
    ``out``.

    Returns a DataFrame ``theta_deg, load_mN, line_deg, alpha_deg, direction_deg,
    corrugation_nm, max_lateral_force_mN``, one row per α.
    """
    return _table("corrugation", scene, options, progress, threads)


def friction(scene: SceneLike = None, *, progress: Any = None, threads: Optional[int] = None,
             **options: Any) -> Any:  # fmt: skip
    """Surrogate friction estimate μ_est per θ × α × load (coating and Prandtl–Tomlinson
    terms on the quasi-static path).

    Options: those of ``superlube friction --help`` in snake case (``theta_deg``,
    ``alpha_deg``, ``load_mN``, ``mu_superlubric``, …). Returns the friction CSV as a
    DataFrame (one row per θ, α, load), with its ``verdict`` column (``superlubric``,
    ``borderline`` or ``not`` at the row's own θ, α and load, by ``design``'s rule).
    """
    return _table("friction", scene, options, progress, threads)


def tolerance(scene: SceneLike = None, *, progress: Any = None,
              threads: Optional[int] = None, **options: Any) -> Any:  # fmt: skip
    """Tolerance map of one design: the superlubric limit load (mN, friction estimate) over
    θ ± range × pulling direction ± range (degrees; the pull direction is fixed in the
    substrate frame when the slider is misaligned).

    Options (``superlube tolerance --help``): ``theta_deg`` (nominal θ), ``alpha_deg`` (degrees
    from the contact line; formerly ``alpha``) or ``direction_deg`` (from x), ``theta_range_deg``, ``theta_points``,
    ``direction_range_deg``, ``direction_points``, ``theta_tol_deg``, ``direction_tol_deg`` (degrees),
    ``load_mN``, ``mu_superlubric``, ``line_deg``, the path options of the estimate and
    ``out_dir`` (the command's folder: map.csv, map.png; kept).

    Returns a DataFrame with ``map.csv``'s columns (``theta_deg, direction_deg,
    theta_offset_deg, direction_offset_deg, …, superlubric_to_mN, confident_to_mN,
    limited_by``), one row per point, direction outer, θ inner.
    """
    tmp, paths = _go("tolerance", [_scene(scene)], options, {"out-dir": "tolerance"}, progress,
                     threads)  # fmt: skip
    try:
        p = os.path.join(paths["out-dir"], "map.csv")
        return _run._attach(_run.read_table(p), p)
    finally:
        _run.remove(tmp)


def yield_(scene: SceneLike = None, *, progress: Any = None, threads: Optional[int] = None,
           **options: Any) -> Tuple[Any, Dict[str, Any]]:  # fmt: skip
    """Yield of one design (``superlube yield``; ``yield`` is a Python keyword): the fraction
    of fabricated devices (θ and pull-direction offsets within the tolerance, a fresh substrate
    each) that stay superlubric at a load, the load a fraction q of them hold (mN) and its
    one-sided confidence bound; the DEM locates the critical loads of the devices that set them.

    Options (``superlube yield --help``): ``theta_deg``, ``direction_deg`` (degrees from x),
    ``theta_tol_deg``, ``direction_tol_deg``, ``theta_sigma_deg``, ``direction_sigma_deg``,
    ``sphere_diameter_cv``, ``p_crit_sigma_GPa``, ``samples`` (59), ``quantile`` (0.95),
    ``confidence`` (0.95), ``resolution`` (0.01), ``sample_seed``, ``searched_seeds``,
    ``load_mN``, ``no_dem``, ``dem_check``, the ``dem_…`` protocol options, ``jobs`` and
    ``out_dir`` (a directory, kept: yield.csv, summary.json, yield.png, dem/). Cost: about 0.6 s
    of estimates per device on the study's scenes, plus at most 40 DEM runs (the check's
    included).

    Returns ``(devices, summary)``: ``yield.csv`` as a DataFrame (one row per device:
    ``sample, theta_offset_deg, direction_offset_deg, seed, …, critical_load_mN,
    critical_load_low_mN, critical_load_high_mN, decided_by``, the check's devices pooled in)
    and ``summary.json`` as a dict (``load_at_quantile_mN``, ``load_at_quantile_bound_mN``,
    ``dem_check_passed``, ``dem_check_total``, ``dem_check_consistent``, ``band``, ``pairs``,
    ``fabrication``, ``curve`` …).
    """
    tmp, paths = _go("yield", [_scene(scene)], options, {"out-dir": "yield"}, progress, threads)
    try:
        out = paths["out-dir"]
        rows = os.path.join(out, "yield.csv")
        return (_run._attach(_run.read_table(rows), rows),
                _run.read_json(os.path.join(out, "summary.json")))  # fmt: skip
    finally:
        _run.remove(tmp)


def equilibrate(scene: SceneLike = None, *, progress: Any = None,
                threads: Optional[int] = None, **options: Any) -> Any:  # fmt: skip
    """Dynamic DEM equilibration under load, compared with the surrogate.

    Options: those of ``superlube equilibrate --help`` in snake case (``load_mN``,
    ``theta_deg``, ``equilibrate_us``, ``dt_us``, ``sample_us``, ``model``…). Cost: seconds to
    minutes (the DEM). Returns the time series ``t_us, support_x_um, spring_force_mN, z_um,
    contacts, p_max_GPa, failed_contacts, p_max_peak_GPa`` as a DataFrame; its JSON summary is
    in ``df.attrs["summary"]``.
    """
    return _dem("equilibrate", scene, options, progress, threads)[0]


def slide(scene: SceneLike = None, *, progress: Any = None, threads: Optional[int] = None,
          **options: Any) -> Tuple[Any, Dict[str, Any]]:  # fmt: skip
    """Dynamic DEM sliding simulation: friction force and coefficient of one configuration.

    Options: those of ``superlube slide --help`` in snake case (``load_mN``, ``theta_deg``,
    ``alpha_deg``, ``slide_us``, ``equilibrate_us``, ``relax_us``, ``dt_us``, ``model``…).
    Cost: seconds (small scenes, short protocols) to minutes (the study's).

    Returns ``(series, summary)``: the time series as a DataFrame (``t_us, support_x_um,
    spring_force_mN, z_um, contacts, p_max_GPa, failed_contacts, p_max_peak_GPa``) and the JSON
    summary as a dict (μ, mean friction force in mN, max_p_max_GPa, locked_in, …, the keys of
    ``slide --json``).
    """
    return _dem("slide", scene, options, progress, threads)


def _dem(command, scene, options, progress, threads):
    outs = {"out": "series.csv", "json": "summary.json"}
    tmp, paths = _go(command, [_scene(scene)], options, outs, progress, threads)
    try:
        table = _run._attach(_run.read_table(paths["out"]), paths["out"])
        summary = _run.read_json(paths["json"])
        if hasattr(table, "attrs"):
            table.attrs["summary"] = summary
        return table, summary
    finally:
        _run.remove(tmp)


def design(scenes: Union[SceneLike, Sequence[SceneLike]] = None, *, progress: Any = None,
           threads: Optional[int] = None, **options: Any) -> Tuple[Any, Dict[str, Any]]:  # fmt: skip
    """Design: screen → shortlist → α scan + friction estimate → ranking → DEM confirmation;
    the best θ and α per pattern and the load (mN) up to which it stays superlubric.

    ``scenes``: one Scene or several (each named after its preset or file stem), or None with
    ``pattern="tri-tri,square-tri"`` (the default patterns). Options: those of
    ``superlube design --help`` in snake case (``load_mN``, ``no_dem``, ``top``,
    ``confirm_loads_mn``, ``per_level``, ``out_dir`` (a directory, kept) …). Cost: a minute per
    pattern for the surrogate tiers (``no_dem=True``), plus the DEM runs.

    Returns ``(ranking, summary)``: ``ranking.csv`` as a DataFrame (every ranked design of every
    pattern, rank 1 first) and a dict: ``answer`` (pattern → the report's answer: θ, α, the load
    up to which superlubric and what the DEM said), ``report_md`` (report.md) and ``inputs``
    (design.json: the resolved scenes and parameters).
    """
    if scenes is None:
        scene_list: List[Scene] = []
    elif isinstance(scenes, (Scene, str)):
        scene_list = [_scene(scenes)]
    else:
        scene_list = [_scene(s) for s in scenes]
    tmp, paths = _go("design", scene_list, options, {"out-dir": "design"}, progress, threads,
                     allow_scene_flags=True)  # fmt: skip
    try:
        out = paths["out-dir"]
        ranking = os.path.join(out, "ranking.csv")
        table = _run._attach(_run.read_table(ranking), ranking) if os.path.exists(ranking) else None
        with open(os.path.join(out, "report.md"), encoding="utf-8") as f:
            report = f.read()
        summary = {
            "answer": _answers(report),
            "report_md": report,
            "inputs": _run.read_json(os.path.join(out, "design.json")),
        }
        return table, summary
    finally:
        _run.remove(tmp)


def _answers(report: str) -> Dict[str, str]:
    """The answer per pattern: the paragraphs of report.md's ``## Answer`` section, each
    ``**pattern**: text`` (the plain-words reading of the answer table's row)."""
    answers, inside = {}, False
    for line in report.splitlines():
        if line.startswith("## "):
            inside = line.strip() == "## Answer"
        elif inside and line.startswith("**") and "**: " in line:
            name, _, text = line[2:].partition("**: ")
            answers[name] = text
    return answers


def run_command(argv: Sequence[str], *, progress: Any = None,
                threads: Optional[int] = None) -> None:  # fmt: skip
    """Runs any ``superlube`` command line in process, e.g.
    ``run_command(["figures", "--only", "sweep", "--out-dir", "figs"])`` (no ``superlube``
    prefix), with the same progress, interrupt and error behaviour as the workflows."""
    rep = _run._Reporter(progress)
    try:
        _native.run(["superlube", *argv], rep, threads)
    finally:
        rep.close()
