"""`Scene`: a validated scene, from a preset, a TOML scene file and/or scene-file fields."""

from __future__ import annotations

import json
import math
import os
from typing import Any, Dict, Optional, Tuple

from . import _native

#: Scene-file fields accepted as keywords, and the table of the scene file each lives in
#: (None: top level). Keywords match case-insensitively (`youngs_GPa` or `youngs_gpa`).
FIELDS: Dict[str, Optional[str]] = {
    "pattern": None,
    "sphere_diameter_um": None,
    "radius_um": "slider",
    "slider_radius_um": "slider",
    "theta_deg": "slider",
    "offset_um": "slider",
    "tilt": "slider",
    "tilt_k1_N_m": "slider",
    "slider_lattice": "slider",
    "outline": "slider",
    "slider_sites": "slider",
    "slider_sphere_diameter_um": "slider",
    "size_um": "substrate",
    "substrate_um": "substrate",
    "sigma_h_um": "substrate",
    "seed": "substrate",
    "substrate_lattice": "substrate",
    "substrate_sites": "substrate",
    "substrate_sphere_diameter_um": "substrate",
    "youngs_GPa": "material",
    "poisson": "material",
    "density_g_cm3": "material",
    "p_crit_GPa": "coating",
    "mu1": "coating",
    "mu2": "coating",
}
#: Keyword aliases: the CLI's scene flag names → the scene file's field names.
_ALIASES = {
    "slider_radius_um": "radius_um",
    "substrate_um": "size_um",
    "slider_lattice": "lattice",
    "substrate_lattice": "lattice",
    "slider_sites": "sites",
    "substrate_sites": "sites",
    "slider_sphere_diameter_um": "sphere_diameter_um",
    "substrate_sphere_diameter_um": "sphere_diameter_um",
}
_BY_LOWER = {k.lower(): k for k in FIELDS}
_TABLES = ("slider", "substrate", "material", "coating")


def _toml_value(v: Any, field: str) -> str:
    """One TOML value (numbers round-trip exactly: Python's repr is the shortest exact form)."""
    if hasattr(v, "tolist"):  # numpy arrays and scalars
        v = v.tolist()
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{k} = {_toml_value(x, field)}" for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x, field) for x in v) + "]"
    raise ValueError(f"`{field}`: cannot use a {type(v).__name__} as a scene field value")


def _number(text: str, key: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"`{key}`: `{text}` is not a number (µm)") from None


def _spec(name: str, value: Any, key: str) -> Any:
    """The command line's text forms of the geometry flags as scene-file tables:
    ``slider_lattice="honeycomb:6"`` (``KIND:SPACING_UM``, ``rectangular:3x3.5``) and
    ``outline="disc:R"``, ``"rectangle:WxH"``, ``"polygon:N:R"`` (µm); a dict is kept as is."""
    if not isinstance(value, str) or name not in ("slider_lattice", "outline"):
        return value
    parts = value.split(":")
    kind = parts[0].strip()
    if name == "slider_lattice":
        if len(parts) != 2:
            raise ValueError(f"`{key}`: `{value}` must be KIND:SPACING_UM, e.g. honeycomb:6")
        if kind == "rectangular":
            xy = parts[1].lower().split("x")
            if len(xy) != 2:
                raise ValueError(f"`{key}`: a rectangular lattice is rectangular:3x3.5")
            return {"kind": kind, "spacing_um": _number(xy[0], key),
                    "spacing_y_um": _number(xy[1], key)}  # fmt: skip
        return {"kind": kind, "spacing_um": _number(parts[1], key)}
    if kind == "disc" and len(parts) == 2:
        return {"kind": kind, "radius_um": _number(parts[1], key)}
    if kind == "rectangle" and len(parts) == 2 and len(parts[1].lower().split("x")) == 2:
        w, h = parts[1].lower().split("x")
        return {"kind": kind, "size_um": [_number(w, key), _number(h, key)]}
    if kind == "polygon" and len(parts) == 3 and parts[1].strip().isdigit():
        return {"kind": kind, "sides": int(parts[1]), "radius_um": _number(parts[2], key)}
    raise ValueError(f"`{key}`: `{value}` must be disc:R, rectangle:WxH or polygon:N:R (µm)")


def _overlay(fields: Dict[str, Any]) -> str:
    """The scene-file TOML text of keyword fields (unknown keyword → ValueError naming it)."""
    top, tables = [], {t: [] for t in _TABLES}
    for key, value in fields.items():
        if value is None:
            continue
        if key in _TABLES and isinstance(value, dict):
            for k, v in value.items():
                tables[key].append(f"{k} = {_toml_value(v, f'{key}.{k}')}")
            continue
        name = _BY_LOWER.get(key.lower())
        if name is None:
            raise ValueError(
                f"`{key}`: not a scene field (expected one of {', '.join(FIELDS)}, "
                f"or a table {', '.join(_TABLES)} as a dict)"
            )
        table = FIELDS[name]
        file_name = _ALIASES.get(name, name)
        if name == "size_um" or name == "substrate_um":
            if isinstance(value, str):
                parts = value.lower().split("x")
                if len(parts) != 2:
                    raise ValueError(f"`{key}`: `{value}` must be LXxLY, e.g. 364x270")
                try:
                    value = [float(p) for p in parts]
                except ValueError:
                    raise ValueError(f"`{key}`: `{value}` is not two numbers LXxLY") from None
        value = _spec(name, value, key)
        if name in ("slider_sites", "substrate_sites"):
            # relative to the working directory, as the command line's flags (the scene file
            # a workflow runs from is written elsewhere)
            value = os.path.abspath(os.fspath(value))
        line = f"{file_name} = {_toml_value(value, key)}"
        (top if table is None else tables[table]).append(line)
    text = "\n".join(top) + "\n"
    for t in _TABLES:
        if tables[t]:
            text += f"[{t}]\n" + "\n".join(tables[t]) + "\n"
    return text


class Scene:
    """A validated scene: the slider and substrate patterns, material and coating.

    ``Scene(source=None, **fields)``

    ``source`` is a preset name (``"tri-tri"``, ``"square-tri"``, ``"square-square"``,
    ``"tri-square"``: the reference study's geometry), a path to a TOML scene file, or None
    (the default preset, square-tri). Keyword ``fields`` are the scene file's field names in
    user units and override the source, e.g.
    ``Scene("square-tri", youngs_GPa=50, sigma_h_um=0.01, theta_deg=10.2)``:

    ===================  =========================================================
    pattern              preset pair ``slider-substrate``
    sphere_diameter_um   sphere diameter (µm)
    radius_um            slider disc radius (µm)
    theta_deg            slider orientation θ (degrees)
    offset_um            in-plane slider offset ``[x, y]`` (µm)
    tilt, tilt_k1_N_m    slider mount (locked/free/springs) and spring K1 (N/m)
    slider_lattice       slider lattice, ``"honeycomb:6"`` as ``--slider-lattice`` or a dict
    outline              slider outline, ``"disc:R"``, ``"rectangle:WxH"``, ``"polygon:N:R"``
    slider_sites         slider site file (CSV ``x_um,y_um[,diameter_um]``)
    substrate_sites      substrate site file (same form)
    slider_sphere_…      ``slider_sphere_diameter_um``: slider sphere diameter (µm)
    substrate_sphere_…   ``substrate_sphere_diameter_um``: substrate sphere diameter (µm)
    size_um              substrate rectangle ``[lx, ly]`` (µm) (or ``"364x270"``)
    sigma_h_um, seed     substrate height roughness amplitude (µm) and its seed
    youngs_GPa, poisson  Young's modulus E (GPa), Poisson ratio
    density_g_cm3        sphere density (g/cm³)
    p_crit_GPa           critical coating pressure P_crit (GPa)
    mu1, mu2             coating friction coefficients
    ===================  =========================================================

    A whole table can also be given as a dict (``slider={"lattice": {"kind": "square"}}``).
    The scene is resolved and validated exactly as the ``superlube`` commands do (same
    messages); a bad field raises ``ValueError`` naming it. Cheap (no solve).
    """

    def __init__(self, source: Optional[str] = None, **fields: Any) -> None:
        path = None
        name = "scene"
        if source is not None:
            source = os.fspath(source)
            if source.endswith(".toml") or os.path.sep in source or os.path.exists(source):
                path = source
                name = os.path.splitext(os.path.basename(source))[0]
            else:
                if any(k.lower() == "pattern" for k in fields):
                    raise ValueError("`pattern`: given twice (as the source and as a keyword)")
                fields = {"pattern": source, **fields}
                name = source
        elif "pattern" in fields:
            name = str(fields["pattern"])
        self.name: str = name
        self._path = path
        self._fields = dict(fields)
        toml_text, resolved, warnings = _native.scene(path, _overlay(fields))
        self._toml: str = toml_text
        self._resolved: Dict[str, Any] = json.loads(resolved)
        self.warnings: Tuple[str, ...] = tuple(warnings)

    def replace(self, **fields: Any) -> "Scene":
        """A copy with more fields overridden (same keywords as the constructor)."""
        s = Scene.__new__(Scene)
        merged = {**self._fields, **fields}
        s.__init__(self._path, **merged) if self._path else s.__init__(None, **merged)
        s.name = self.name
        return s

    def to_toml(self) -> str:
        """The scene file (TOML, user units) of the given fields (defaults come from the preset)."""
        return self._toml

    def to_dict(self) -> Dict[str, Any]:
        """Every field of the resolved scene in user units (the sidecars' `scene` record)."""
        return json.loads(json.dumps(self._resolved))

    def write(self, path: str) -> None:
        """Writes the scene file (TOML) to `path`, for the ``superlube --scene`` command line."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self._toml)

    def __repr__(self) -> str:
        given = ", ".join(f"{k}={v!r}" for k, v in self._fields.items())
        src = repr(self._path) if self._path else ""
        return f"Scene({', '.join(x for x in (src, given) if x)})"
