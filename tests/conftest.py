"""Shared fixtures: paths, cached derivations, a pinned console width."""

from __future__ import annotations

import functools
import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SYSTEMS = ROOT / "systems"

# Wrapped output must not depend on the terminal running the tests.
os.environ.setdefault("GACLI_WIDTH", "3000")


@functools.lru_cache(maxsize=None)
def derived(name: str):
    """The derivation of systems/<name>.yaml (cached: derivations are immutable)."""
    from gacli.equations import derive
    from gacli.loading import load

    return derive(load(SYSTEMS / f"{name}.yaml"))


@pytest.fixture
def rng():
    import numpy as np

    return np.random.default_rng(20261122)


def require_tool(name: str) -> str:
    """The path of an external tool; skip without it, except in CI where it must be there."""
    import shutil

    path = shutil.which(name)
    if path is None:
        if os.environ.get("CI"):
            pytest.fail(f"{name} is required in CI (.ci/run installs it)")
        pytest.skip(f"{name} is not installed")
    return path
