"""Native bridge (Rust, pyo3) of the superlube package: see superlube.run_command."""

from typing import Any, Callable, Dict, List, Optional, Tuple

__version__: str

def run(
    argv: List[str],
    callback: Optional[Callable[[Dict[str, Any]], Any]] = None,
    threads: Optional[int] = None,
) -> None:
    """Runs one `superlube` command line (argv[0] = program name) in process, GIL released.
    ValueError: bad flag or input (before any work); RuntimeError: failure during the run;
    KeyboardInterrupt: Ctrl-C; or the callback's exception (the run stops at its next step)."""

def flags(command: str) -> List[Tuple[str, bool]]:
    """Long options of `command` as (name, takes a value)."""

def repeated(command: str) -> List[str]:
    """Long options of `command` that may be given more than once (`design`'s `vary`)."""

def renamed(command: str) -> List[Tuple[str, str]]:
    """Renamed options of `command` as (old name, current name), e.g. ("model", "solver"):
    the old names the command still accepts for a release."""

def scene(path: Optional[str], overlay: str) -> Tuple[str, str, List[str]]:
    """Scene file `path` (or none) with the TOML `overlay` on top → (merged TOML, resolved
    scene as JSON, warnings). ValueError naming the bad field."""
