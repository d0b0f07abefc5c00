"""Shared fixtures: the `superlube` binary (to compare against) and small scenes."""

import os
import pathlib
import shutil

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli_bin():
    """The `superlube` binary: $SUPERLUBE_BIN, else the workspace's target/{debug,release}.
    Missing: skipped, unless SUPERLUBE_REQUIRE_BIN=1 (CI) makes it a failure."""
    cands = [os.environ.get("SUPERLUBE_BIN")]
    cands += [str(ROOT / "target" / p / "superlube") for p in ("debug", "release")]
    cands.append(shutil.which("superlube"))
    for c in cands:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    if os.environ.get("SUPERLUBE_REQUIRE_BIN") == "1":
        pytest.fail("no superlube binary (set SUPERLUBE_BIN)")
    pytest.skip("no superlube binary to compare with (set SUPERLUBE_BIN)")


@pytest.fixture
def private_tmp(tmp_path, monkeypatch):
    """Points tempfile at an empty directory, so a test can check that nothing is left."""
    import tempfile

    d = tmp_path / "tmp"
    d.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(d))
    return d
