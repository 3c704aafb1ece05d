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
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

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


# Shipped systems whose equations are too large to print for reading
# (gacli.algebra.readable.DISPLAY_NODES); tests/test_readable.py checks this list.
LARGE = frozenset({"whipple_bicycle", "toroidal_bicycle", "rattleback"})


def evaluate(exprs, values):
    """Float values of the expressions at ``values``: SymPy's evalf at 30 digits, or for
    the large systems a double-precision walk of their distinct subexpressions (evalf
    on the printed trees of the bicycle would take hours)."""
    import numpy as np
    import sympy as sp

    from gacli.algebra.graph import is_large
    from gacli.numeric import Program

    exprs = list(exprs)
    if not any(is_large(e) for e in exprs):
        return np.array([complex(v) for v in sp.Matrix(exprs).xreplace(values).evalf(30)], dtype=complex).real
    return np.array(Program(exprs)({s: complex(v) for s, v in values.items()})).real
