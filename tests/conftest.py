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
    return derived_file(SYSTEMS / f"{name}.yaml")


@functools.lru_cache(maxsize=None)
def derived_file(path: Path):
    """``derive(load(path))``, once per worker: the modules that check a file's equations, its
    code and its printout share one derivation and what it caches (``code``, the display's
    simplifications), instead of deriving the same file again in each."""
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    return derive(load(path))


@functools.lru_cache(maxsize=None)
def printout(path: Path):
    """``gacli.pipeline.run(path, needs=PRINTOUT)``, once per worker: what ``gacli derive FILE`` prints."""
    from gacli.pipeline import PRINTOUT, run

    return run(path, needs=PRINTOUT)


@functools.lru_cache(maxsize=None)
def printed(path: Path) -> tuple[int, str]:
    """Exit code and output of ``gacli derive PATH`` (text), run in-process once per worker.

    The command runs as a user runs it, but the derivation it prints is :func:`printout`'s,
    so the report's simplifications (most of the time of a printout) are done once for every
    module that reads this file's printout. Nothing else is shared: any other file, or any
    other ``needs``, goes through the real pipeline.
    """
    from unittest import mock

    from typer.testing import CliRunner

    import gacli.pipeline as pipeline
    from gacli.cli import app

    real, shared = pipeline.run, printout(path)

    def run(file, *, needs=pipeline.CLOSED, **options):
        if needs == pipeline.PRINTOUT and Path(file) == path:
            return shared
        return real(file, needs=needs, **options)

    with mock.patch.object(pipeline, "run", run):
        result = CliRunner().invoke(app, ["derive", str(path)])
    return result.exit_code, result.output


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


# Modules whose tests, one per system file, read the shared derivations and printouts above.
SHARING = frozenset({"test_code.py", "test_compact.py", "test_display_sizes.py", "test_display_values.py",
                     "test_program.py", "test_readable.py"})


def _group(item) -> str:
    """The xdist group of a test: its system file in a sharing module, else its module.

    Under ``--dist loadgroup`` (pyproject.toml) a group runs on one worker. By file: the tests
    of one file from every sharing module meet the per-worker caches above. By module for the
    rest: a module- or session-scoped fixture (a corpus run, a C build, a pdflatex pass) is
    set up once, not once per worker given a share of its module.
    """
    module = item.path.name
    params = getattr(getattr(item, "callspec", None), "params", {})
    if module in SHARING:
        for value in params.values():
            if isinstance(value, Path) and value.suffix == ".yaml":
                return f"file:{value}"
            if isinstance(value, str) and value.isidentifier() and (SYSTEMS / f"{value}.yaml").is_file():
                return f"file:{SYSTEMS / f'{value}.yaml'}"
    return module


@pytest.hookimpl(tryfirst=True)  # before xdist's own hook, which reads the group into the test's id
def pytest_collection_modifyitems(config, items):
    for item in items:
        item.add_marker(pytest.mark.xdist_group(_group(item)))
