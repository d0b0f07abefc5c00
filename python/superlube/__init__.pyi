"""Type stubs of superlube (units are in the names: _um µm, _nm nm, _mN mN, _GPa GPa, _us µs,
_deg degrees)."""

from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

__version__: str

#: A progress callback: called on the calling thread ≤ every 0.1 s with a dict of stage (str),
#: done (int), total (int), unit (str), status (str), notes (list of new log lines).
ProgressArg = Union[None, bool, Callable[[Dict[str, Any]], Any]]
#: A pandas.DataFrame, or a dict column name → numpy array where pandas is not installed.
Table = Any
#: A number, a sequence of numbers, or the CLI's text form ("0:30:0.1", "0.35,1.4").
Values = Union[float, int, str, Sequence[float], "np.ndarray[Any, Any]"]

class Scene:
    name: str
    warnings: Tuple[str, ...]
    def __init__(
        self,
        source: Optional[str] = None,
        *,
        pattern: Optional[str] = None,
        sphere_diameter_um: Optional[float] = None,
        radius_um: Optional[float] = None,
        theta_deg: Optional[float] = None,
        offset_um: Optional[Sequence[float]] = None,
        tilt: Optional[str] = None,
        tilt_k1_N_m: Optional[float] = None,
        size_um: Optional[Union[str, Sequence[float]]] = None,
        sigma_h_um: Optional[float] = None,
        seed: Optional[int] = None,
        youngs_GPa: Optional[float] = None,
        poisson: Optional[float] = None,
        density_g_cm3: Optional[float] = None,
        p_crit_GPa: Optional[float] = None,
        mu1: Optional[float] = None,
        mu2: Optional[float] = None,
        slider: Optional[Dict[str, Any]] = None,
        substrate: Optional[Dict[str, Any]] = None,
        material: Optional[Dict[str, Any]] = None,
        coating: Optional[Dict[str, Any]] = None,
        **fields: Any,
    ) -> None: ...
    def replace(self, **fields: Any) -> "Scene": ...
    def to_toml(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def write(self, path: str) -> None: ...

SceneLike = Union[Scene, str, None]

def screen(
    scene: SceneLike = None,
    *,
    theta_deg: Optional[Values] = None,
    load_mN: Optional[Values] = None,
    solver: Optional[str] = None,
    search: Optional[str] = None,
    contacts_out: Optional[str] = None,
    force: bool = False,
    shard: Optional[str] = None,
    resume: bool = False,
    out: Optional[str] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
) -> Table: ...
def landscape(
    scene: SceneLike = None,
    *,
    theta_deg: Optional[float] = None,
    load_mN: Optional[float] = None,
    grid: Optional[int] = None,
    plot: Optional[str] = None,
    contact_map: Optional[str] = None,
    contacts_out: Optional[str] = None,
    force: bool = False,
    shard: Optional[str] = None,
    resume: bool = False,
    out: Optional[str] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
) -> Table: ...
def corrugation(
    scene: SceneLike = None,
    *,
    theta_deg: Optional[float] = None,
    load_mN: Optional[float] = None,
    alpha_deg: Optional[Values] = None,
    line_deg: Optional[float] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
    **options: Any,
) -> Table: ...
def friction(
    scene: SceneLike = None,
    *,
    theta_deg: Optional[Values] = None,
    alpha_deg: Optional[Values] = None,
    load_mN: Optional[Values] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
    **options: Any,
) -> Table: ...
def tolerance(
    scene: SceneLike = None,
    *,
    theta_deg: Optional[float] = None,
    alpha_deg: Optional[float] = None,
    direction_deg: Optional[float] = None,
    load_mN: Optional[Values] = None,
    out_dir: Optional[str] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
    **options: Any,
) -> Table: ...
def yield_(
    scene: SceneLike = None,
    *,
    theta_deg: Optional[float] = None,
    direction_deg: Optional[float] = None,
    samples: Optional[int] = None,
    quantile: Optional[float] = None,
    load_mN: Optional[Values] = None,
    out_dir: Optional[str] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
    **options: Any,
) -> Tuple[Table, Dict[str, Any]]: ...
def equilibrate(
    scene: SceneLike = None,
    *,
    load_mN: Optional[float] = None,
    theta_deg: Optional[float] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
    **options: Any,
) -> Table: ...
def slide(
    scene: SceneLike = None,
    *,
    load_mN: Optional[float] = None,
    theta_deg: Optional[float] = None,
    alpha_deg: Optional[float] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
    **options: Any,
) -> Tuple[Table, Dict[str, Any]]: ...
def design(
    scenes: Union[SceneLike, Sequence[SceneLike]] = None,
    *,
    pattern: Optional[str] = None,
    load_mN: Optional[Values] = None,
    no_dem: bool = False,
    out_dir: Optional[str] = None,
    progress: ProgressArg = None,
    threads: Optional[int] = None,
    **options: Any,
) -> Tuple[Table, Dict[str, Any]]: ...
def run_command(
    argv: Sequence[str], *, progress: ProgressArg = None, threads: Optional[int] = None
) -> None: ...
