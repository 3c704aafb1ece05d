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
from gacli.algebra import symbols as S
from gacli.reactions import constraint_forces, multipliers_numeric, reaction_system

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


# -- systems too large for the closed form: a numeric solve in the generated code --------------

@pytest.mark.parametrize("name", [*CASES, "rolling_disk"])
def test_the_reaction_system_gives_the_closed_form_multipliers(name, rng):
    # Two routes: K z = b of the fundamental equations in all the rates, solved numerically, and the
    # multipliers solved symbolically from the reduced equations with u' = M^-1 F.
    d = derived(name)
    system = reaction_system(d)
    lay = layout(d)
    for _ in range(5):
        x, p, r, expected = sample(d, rng)
        values = dict(zip(lay.state_symbols + lay.parameter_symbols + lay.r_symbols, [*x, *p, *r]))
        K = np.array(system.K.xreplace(values).evalf(30).tolist(), dtype=float)
        b = np.array(system.b.xreplace(values).evalf(30).tolist(), dtype=float).ravel()
        z = np.linalg.solve(K, b)
        np.testing.assert_allclose(z[system.rates:system.rates + system.constraint_count], expected,
                                   rtol=1e-10, atol=1e-10)


@pytest.fixture(scope="module")
def bicycle_module(tmp_path_factory):
    ((file, text),) = emit_python(derived("whipple_bicycle"), reactions=True).items()
    path = tmp_path_factory.mktemp("bicycle") / file
    path.write_text(text)
    spec = importlib.util.spec_from_file_location("reactions_bicycle", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_bicycle_riding_straight_carries_its_static_load(bicycle_module):
    # Upright and straight at a steady speed nothing accelerates: no horizontal contact force,
    # and the front wheel carries the weight's share its position gives (the benchmark's masses
    # and centres of mass: rear wheel 2 kg at 0, frame 85 kg at 0.3 m, fork 4 kg at 0.9 m,
    # front wheel 3 kg at the wheelbase 1.02 m, g = 9.81). The rear normal force has no
    # multiplier: the coordinates keep the rear contact on the ground.
    m = bicycle_module
    x = np.zeros(len(m.STATE))
    x[m.STATE.index("dot(wheel_R)")] = 5.0 / 0.3
    p = [m.DEFAULTS[name] for name in m.PARAMETERS]
    front = 9.81 * (85 * 0.3 + 4 * 0.9 + 3 * 1.02) / 1.02
    np.testing.assert_allclose(m.reactions(0.0, x, p), [0, 0, 0, 0, front], rtol=1e-12, atol=1e-9)


def _bicycle_states(module, rng, count):
    for _ in range(count):
        x = np.zeros(len(module.STATE))
        for name, spread in (("roll", 0.3), ("steer", 0.4), ("pitch", 0.05), ("yaw", 3.0),
                             ("dot(roll)", 1.0), ("dot(wheel_R)", 20.0), ("dot(steer)", 1.0)):
            x[module.STATE.index(name)] = rng.uniform(-spread, spread)
        yield x


def test_bicycle_reactions_agree_with_the_fundamental_equation_in_30_digits(bicycle_module, rng):
    d = derived("whipple_bicycle")
    m = bicycle_module
    p = [m.DEFAULTS[name] for name in m.PARAMETERS]
    coordinates = [c.name for c in d.system.coordinates]
    for x in _bicycle_states(m, rng, 3):
        qdot = m.rhs(0.0, x, p)[:len(coordinates)]
        values = {S.value(n): x[m.STATE.index(n)] for n in coordinates}
        values.update({S.rate(n): v for n, v in zip(coordinates, qdot)})
        values.update({S.value(n): v for n, v in zip(m.PARAMETERS, p)})
        _, expected = multipliers_numeric(d.system, values)
        np.testing.assert_allclose(m.reactions(0.0, x, p), expected[:len(d.system.constraints)],
                                   rtol=1e-9, atol=1e-9)


def test_bicycle_reactions_in_c_agree_with_python(bicycle_module, tmp_path, rng):
    gcc = require_tool("gcc")
    d = derived("whipple_bicycle")
    for file, text in emit_c(d, reactions=True).items():
        (tmp_path / file).write_text(text)
    library = tmp_path / "libr.so"
    subprocess.run([gcc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O1", "-shared", "-fPIC",
                    str(tmp_path / "whipple_bicycle.c"), "-o", str(library), "-lm"], check=True)
    function = ctypes.CDLL(str(library)).whipple_bicycle_reactions
    pointer = ctypes.POINTER(ctypes.c_double)
    function.argtypes = [ctypes.c_double, pointer, pointer, pointer, pointer]
    m = bicycle_module
    p = np.array([m.DEFAULTS[name] for name in m.PARAMETERS])
    for x in _bicycle_states(m, rng, 5):
        out = np.zeros(len(d.system.constraints))
        function(0.0, x.ctypes.data_as(pointer), p.ctypes.data_as(pointer), None, out.ctypes.data_as(pointer))
        np.testing.assert_allclose(out, m.reactions(0.0, x, p), rtol=1e-10, atol=1e-9)


def _flat(module):
    x = np.zeros(len(module.STATE))
    x[module.STATE.index("roll")] = np.pi / 2  # lying flat: the rolling constraints lose rank
    x[module.STATE.index("dot(wheel_R)")] = 1.0
    return x


def test_bicycle_reactions_lying_flat_are_an_error_not_numbers(bicycle_module, tmp_path):
    m = bicycle_module
    p = np.array([m.DEFAULTS[name] for name in m.PARAMETERS])
    with pytest.raises(np.linalg.LinAlgError, match="singular"):
        m.reactions(0.0, _flat(m), p)
    gcc = require_tool("gcc")
    for file, text in emit_c(derived("whipple_bicycle"), reactions=True).items():
        (tmp_path / file).write_text(text)
    library = tmp_path / "libflat.so"
    subprocess.run([gcc, "-std=c99", "-O1", "-shared", "-fPIC", str(tmp_path / "whipple_bicycle.c"),
                    "-o", str(library), "-lm"], check=True)
    function = ctypes.CDLL(str(library)).whipple_bicycle_reactions
    pointer = ctypes.POINTER(ctypes.c_double)
    function.argtypes = [ctypes.c_double, pointer, pointer, pointer, pointer]
    out = np.zeros(5)
    x = _flat(m)
    function(0.0, x.ctypes.data_as(pointer), p.ctypes.data_as(pointer), None, out.ctypes.data_as(pointer))
    assert np.isnan(out).all()


@pytest.mark.parametrize("name", [*CASES, "differential_drive"])
def test_the_numeric_route_in_generated_python_equals_the_closed_form(name, tmp_path, rng, monkeypatch):
    # The route large systems take, forced on small ones; differential_drive repeats a constraint
    # row (two wheels on one axle), where both give the minimum-norm multipliers.
    import gacli.algebra.readable

    d = derived(name)
    monkeypatch.setattr(gacli.algebra.readable, "displayable", lambda derivation: False)
    ((file, text),) = emit_python(d, reactions=True).items()
    assert "_K = numpy.zeros" in text
    (tmp_path / file).write_text(text)
    spec = importlib.util.spec_from_file_location(f"numeric_{name}", tmp_path / file)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    monkeypatch.undo()
    for _ in range(3):
        x, p, r, expected = sample(d, rng)
        np.testing.assert_allclose(module.reactions(0.0, x, p, r), expected, rtol=1e-9, atol=1e-9)


def test_c_refuses_the_numeric_route_with_repeated_rows(monkeypatch):
    import gacli.algebra.readable
    from gacli.errors import EmitError

    monkeypatch.setattr(gacli.algebra.readable, "displayable", lambda derivation: False)
    with pytest.raises(EmitError, match="repeated constraint rows"):
        emit_c(derived("differential_drive"), reactions=True)


@pytest.mark.parametrize("name", ["routh_sphere", "chaplygin_ball"])
def test_the_text_reactions_of_a_shipped_sphere_are_printed(name):
    # derive --reactions ran out of its 120 s tidying λ: sympy's cancel (Routh's sphere) and expand of
    # quotients by sums inside trig.reduce and the rates' collection (Chaplygin's ball), unbounded.
    from typer.testing import CliRunner

    from gacli.cli import app
    from conftest import SYSTEMS

    result = CliRunner().invoke(app, ["derive", str(SYSTEMS / f"{name}.yaml"), "--reactions"])
    assert result.exit_code == 0, result.output
    assert "lambda_0 =" in result.output and "lambda_1 =" in result.output
