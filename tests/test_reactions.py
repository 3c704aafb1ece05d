"""Generated reactions(t, x, p, r): the constraint forces in Python and C agree with SymPy's."""

from __future__ import annotations

import ctypes
import importlib.util
import subprocess

import numpy as np
import pytest

from conftest import derived, require_tool
from gacli.emit.c import emit_c
from gacli.emit.naming import layout
from gacli.emit.python import emit_python
from gacli.verify import constraint_forces

CASES = ["sphere_on_turntable", "chaplygin_sleigh", "cylinder_in_cylinder"]


def sample(d, rng):
    lay = layout(d)
    x, p, r = (rng.uniform(0.3, 1.2, len(v)) for v in (lay.state, lay.parameters, lay.r))
    values = dict(zip(lay.state_symbols + lay.parameter_symbols + lay.r_symbols, [*x, *p, *r]))
    expected = np.array(constraint_forces(d, simplify=False).xreplace(values).evalf(30).tolist(), dtype=float).ravel()
    return x, p, r, expected


@pytest.mark.parametrize("name", CASES)
def test_python_reactions(name, tmp_path, rng):
    d = derived(name)
    ((file, text),) = emit_python(d, reactions=True).items()
    (tmp_path / file).write_text(text)
    spec = importlib.util.spec_from_file_location(f"reactions_{name}", tmp_path / file)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for _ in range(10):
        x, p, r, expected = sample(d, rng)
        np.testing.assert_allclose(module.reactions(0.0, x, p, r), expected, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("name", CASES)
def test_c_reactions(name, tmp_path, rng):
    gcc = require_tool("gcc")
    d = derived(name)
    for file, text in emit_c(d, reactions=True).items():
        (tmp_path / file).write_text(text)
    library = tmp_path / "libr.so"
    subprocess.run([gcc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-shared", "-fPIC",
                    str(tmp_path / f"{name}.c"), "-o", str(library), "-lm"], check=True)
    function = getattr(ctypes.CDLL(str(library)), f"{name}_reactions")
    pointer = ctypes.POINTER(ctypes.c_double)
    function.argtypes = [ctypes.c_double, pointer, pointer, pointer, pointer]
    count = len(d.system.constraints)
    for _ in range(10):
        x, p, r, expected = sample(d, rng)
        out = np.zeros(count)
        args = [np.ascontiguousarray(v, dtype=float) for v in (x, p, r)]
        function(0.0, *(a.ctypes.data_as(pointer) if a.size else None for a in args), out.ctypes.data_as(pointer))
        np.testing.assert_allclose(out, expected, rtol=1e-12, atol=1e-12)
