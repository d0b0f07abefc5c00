"""Running one ``superlube`` command in process and reading its outputs back."""

from __future__ import annotations

import csv
import json
import logging
import math
import os
import sys
import tempfile
import warnings
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

from . import _native

log = logging.getLogger("superlube")

#: The CLI's scene override flags: given to a workflow as a keyword, they belong to the Scene.
SCENE_FLAGS = {
    "pattern", "scene", "slider-radius-um", "substrate-um", "sigma-h-um", "seed",
    "youngs-gpa", "p-crit-gpa", "offset-um", "tilt", "tilt-k1-n-m", "slider-lattice",
    "outline", "slider-sites", "substrate-sites", "slider-sphere-diameter-um",
    "substrate-sphere-diameter-um",
}  # fmt: skip
#: Unit suffixes a keyword may carry where its flag has none: a keyword written with its unit
#: still finds a unitless flag (every θ and α flag now carries ``-deg`` itself).
_UNITS = ("deg", "um", "nm", "mn", "us", "gpa")


def _flag_value(v: Any, key: str) -> str:
    """A flag value: lists comma-joined, floats in their shortest exact form."""
    if hasattr(v, "tolist"):
        v = v.tolist()
    if isinstance(v, range):
        v = list(v)
    if isinstance(v, (list, tuple)):
        return ",".join(_flag_value(x, key) for x in v)
    if isinstance(v, bool):
        raise ValueError(f"`{key}`: expects a value, not {v}")
    if isinstance(v, float):
        return repr(v)
    return os.fspath(v) if hasattr(v, "__fspath__") else str(v)


def _caller_stacklevel() -> int:
    """The ``stacklevel`` of :func:`warnings.warn`, called from the caller of this function,
    that points at the first frame outside this package (the user's call)."""
    here = os.path.dirname(os.path.abspath(__file__))
    f, level = sys._getframe(1), 1
    while f is not None and os.path.dirname(os.path.abspath(f.f_code.co_filename)) == here:
        f, level = f.f_back, level + 1
    return level


def renamed_keywords(command: str, kwargs: Dict[str, Any]) -> Dict[str, Any]:
    """``kwargs`` with the keywords of renamed options under their current names, as the
    command line accepts an old flag name (a hidden alias, e.g. ``screen --model`` → ``--solver``)
    with a note: here a :class:`DeprecationWarning` naming the new keyword. Giving both the old
    and the new name is a ValueError."""
    old_to_new = dict(_native.renamed(command))
    if not old_to_new:
        return dict(kwargs)
    out: Dict[str, Any] = {}
    for key, value in kwargs.items():
        name = key.lower().replace("_", "-")
        new = old_to_new.get(name)
        if new is None:
            stem, _, unit = name.rpartition("-")
            if unit in _UNITS and stem in old_to_new:
                new = old_to_new[stem]
        if new is None or new == name:
            # not renamed, or already the current name (an old name plus its unit)
            out[key] = value
            continue
        new_key = new.replace("-", "_")
        if new_key in kwargs or new_key in out:
            raise ValueError(f"{command}: `{key}` is the old name of `{new_key}`: give one of them")
        warnings.warn(
            f"superlube.{command.replace('-', '_')}(): `{key}` is now `{new_key}`; the old name "
            "still works for this release",
            DeprecationWarning,
            stacklevel=_caller_stacklevel(),
        )
        out[new_key] = value
    return out


def to_argv(command: str, kwargs: Dict[str, Any], allow_scene_flags: bool = False) -> List[str]:
    """``superlube COMMAND`` flags from snake-case keywords: ``load_mN=[1.4, 2.1]`` →
    ``--load-mn=1.4,2.1``, ``theta_deg=(0, 30, 0.1)``… (a str is passed as is, e.g. a range
    ``"0:30:0.1"``); True → a switch, False/None → left out; an option that may be repeated
    (``design``'s ``vary``) takes a dict ``{"FIELD": values}`` or a list of ``"FIELD=LIST"``
    strings, one flag per entry; an old option name → its current one, with a
    DeprecationWarning. Unknown keyword → ValueError."""
    kwargs = renamed_keywords(command, kwargs)
    known = dict(_native.flags(command))
    repeated = set(_native.repeated(command))
    argv: List[str] = []
    for key, value in kwargs.items():
        if value is None or value is False:
            continue
        name = key.lower().replace("_", "-")
        if name not in known:
            stem, _, unit = name.rpartition("-")
            if unit in _UNITS and stem in known:
                name = stem
        if name not in known or name in ("help", "version"):
            flags = sorted(k.replace("-", "_") for k in known if k not in ("help", "version"))
            raise ValueError(f"{command}: unknown keyword `{key}` (options: {', '.join(flags)})")
        if name in SCENE_FLAGS and not allow_scene_flags:
            raise ValueError(
                f"{command}: `{key}` is a scene field: give it to the Scene "
                f"(superlube.Scene(..., {key}=...)) or use scene.replace({key}=...)"
            )
        if name in repeated and isinstance(value, dict):
            # `vary={"slider.sphere_diameter_um": [2.5, 3], …}`: one flag per FIELD=LIST
            argv.extend(f"--{name}={k}={_flag_value(v, key)}" for k, v in value.items())
        elif name in repeated and isinstance(value, (list, tuple)):
            # `vary=["slider.sphere_diameter_um=2.5,3", …]`: one flag per item
            argv.extend(f"--{name}={_flag_value(v, key)}" for v in value)
        elif value is True and not known[name]:
            argv.append(f"--{name}")
        elif not known[name]:
            raise ValueError(f"`{key}`: a switch: give True or False")
        else:
            argv.append(f"--{name}={_flag_value(value, key)}")
    return argv


def _column(values: List[str]) -> Any:
    import numpy as np

    try:
        return np.array([int(x) for x in values], dtype=np.int64)
    except ValueError:
        pass
    try:
        return np.array([float(x) if x != "" else math.nan for x in values], dtype=np.float64)
    except ValueError:
        pass
    if all(x in ("true", "false") for x in values):
        return np.array([x == "true" for x in values], dtype=bool)
    return np.array(values, dtype=object)


def read_table(path: str) -> Any:
    """A CSV output as a pandas.DataFrame (exact floats), or a dict of numpy arrays (column name
    → array) where pandas is not installed."""
    try:
        import pandas as pd
    except ImportError:
        pd = None
    if pd is not None:
        if int(pd.__version__.split(".")[0]) >= 3:
            return pd.read_csv(path)  # exact by default since pandas 3
        return pd.read_csv(path, float_precision="round_trip")
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {h: _column([r[i] for r in body]) for i, h in enumerate(header)}


def read_json(path: str) -> Dict[str, Any]:
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def _attach(table: Any, path: str) -> Any:
    """Records the output's sidecar (the inputs that made it) in ``DataFrame.attrs["meta"]``."""
    meta = path + ".meta.json"
    if hasattr(table, "attrs") and os.path.exists(meta):
        table.attrs["meta"] = read_json(meta)
    return table


class _Reporter:
    """The callback the native runner calls (on this thread, ≤ every 0.1 s): log lines to
    ``logging``/``warnings``, a tqdm bar per stage if tqdm is installed, then the user's."""

    def __init__(self, progress: Any) -> None:
        self.user: Optional[Callable[[Dict[str, Any]], Any]] = (
            progress if callable(progress) else None
        )
        self.bar_wanted = progress is not False and self.user is None
        self.bar: Any = None
        self.stage: Optional[Tuple[str, int]] = None

    def __call__(self, p: Dict[str, Any]) -> None:
        for line in p["notes"]:
            if line.startswith("warning: "):
                warnings.warn(line[len("warning: "):], RuntimeWarning, stacklevel=2)
            else:
                log.info(line)
        if self.bar_wanted and p["total"]:
            self._bar(p)
        if self.user is not None:
            self.user(p)

    def _bar(self, p: Dict[str, Any]) -> None:
        try:
            from tqdm.auto import tqdm
        except ImportError:
            self.bar_wanted = False
            return
        key = (p["stage"], p["total"])
        if key != self.stage:
            self.close()
            self.stage = key
            self.bar = tqdm(total=p["total"], desc=p["stage"], unit=f" {p['unit']}", leave=False)
        step = min(p["done"], p["total"]) - self.bar.n
        if step >= 0:
            self.bar.update(step)  # keeps tqdm's rate and ETA right
        else:
            self.bar.n = p["done"]
        if p["status"]:
            self.bar.set_postfix_str(p["status"], refresh=False)
        self.bar.refresh()

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
            self.bar = None


def run(
    command: str,
    scene_flags: Sequence[str],
    kwargs: Dict[str, Any],
    outputs: Dict[str, str],
    progress: Any = None,
    threads: Optional[int] = None,
    allow_scene_flags: bool = False,
) -> Tuple[str, Dict[str, str]]:
    """Runs ``superlube COMMAND`` with the scene flags, the keywords as flags and the outputs
    (flag → file name in a temporary directory unless the keyword gives a path), then hands the
    paths of the outputs to the caller; returns (tmp dir, {flag: path}). The caller reads them
    and removes the directory. Old option names are accepted as in :func:`to_argv`."""
    kw = renamed_keywords(command, kwargs)
    tmp = tempfile.mkdtemp(prefix="superlube-")
    rep = _Reporter(progress)
    try:
        paths = {}
        for flag, file_name in outputs.items():
            key = flag.replace("-", "_")
            given = kw.pop(key, None)
            paths[flag] = os.fspath(given) if given is not None else os.path.join(tmp, file_name)
        argv = ["superlube", command, *scene_flags, *to_argv(command, kw, allow_scene_flags)]
        argv += [f"--{flag}={path}" for flag, path in paths.items()]
        _native.run(argv, rep, threads)
    except BaseException:
        remove(tmp)
        raise
    finally:
        rep.close()
    return tmp, paths


def remove(tmp: str) -> None:
    import shutil

    shutil.rmtree(tmp, ignore_errors=True)
