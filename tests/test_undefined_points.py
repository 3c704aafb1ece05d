"""Every code target reports the same points where the equations are undefined (issue #33, item 5).

One small system whose forcing takes sqrt(a), log(b) and sin(w x): at a
defined point every target gives the same finite numbers (checked against
the closed form here, not against another target); at each undefined point
(a square root of a negative number, a logarithm of zero, an angle multiple
that overflows, a mass of zero, NaN given) Python raises UndefinedPointError,
C's rhs returns a nonzero status with NaN in every entry, Octave raises
gacli:undefined, JAX returns NaN in every entry, and the FMU's derivatives
fail with a message. docs/generated-code.md ("Undefined points") is the
contract. A target whose tool is missing is skipped.
"""

from __future__ import annotations

import ctypes
import math
import subprocess

import numpy as np
import pytest
from conftest import require_tool

from gacli.emit import emit_c, emit_fmu, emit_jax, emit_octave, emit_python
from gacli.loader.loading import loads
from gacli.mechanics.equations import derive
from test_emit_c import STRICT
from test_emit_python import import_module

SYSTEM = """\
gacli: 1
name: undefined_point
parameters:
  m: {value: 2}
  a: {value: 4}
  b: {value: 1}
  w: {value: 3}
coordinates: [x]
bodies:
  bead: {mass: m, position: [x, 0, 0]}
loads:
  - {force: [-sqrt(a)*sin(w*x) + log(b)*x, 0, 0], at: bead}
"""

DEFINED = {"m": 2.0, "a": 4.0, "b": math.e, "w": 3.0, "x": 0.3, "dx": -0.5}
UNDEFINED = {
    "sqrt_of_negative": {"a": -1.0},
    "log_of_zero": {"b": 0.0},
    "angle_multiple_overflows": {"w": 1e308, "x": 10.0},
    "mass_zero": {"m": 0.0},
    "mass_negative": {"m": -1.0},
    "nan_given": {"x": float("nan")},
    "infinity_given": {"dx": float("inf")},
}


def point(case: str | None) -> tuple[list[float], list[float]]:
    values = {**DEFINED, **(UNDEFINED[case] if case else {})}
    return [values["x"], values["dx"]], [values["m"], values["a"], values["b"], values["w"]]


def expected_rhs() -> list[float]:
    """ẋ and ẍ = F/m of the closed form, at the defined point."""
    v = DEFINED
    force = -math.sqrt(v["a"]) * math.sin(v["w"] * v["x"]) + math.log(v["b"]) * v["x"]
    return [v["dx"], force / v["m"]]


CASES = [None, *UNDEFINED]


@pytest.fixture(scope="module")
def derivation():
    return derive(loads(SYSTEM, path="undefined_point.yaml"))


@pytest.fixture(scope="module")
def built(derivation, tmp_path_factory):
    return tmp_path_factory.mktemp("undefined")


def _write(files: dict, directory) -> None:
    for name, text in files.items():
        (directory / name).write_text(text, encoding="utf-8")


def _written(files: dict, built, folder: str):
    """``files`` written into a new folder of ``built``."""
    directory = built / folder
    directory.mkdir()
    _write(files, directory)
    return directory


# -- Python ------------------------------------------------------------------------

@pytest.mark.parametrize("case", CASES)
def test_python(case, derivation, built):
    _write(emit_python(derivation), built)
    module = import_module(built / "undefined_point.py")
    x, p = point(case)
    if case is None:
        np.testing.assert_allclose(module.rhs(0.0, x, p), expected_rhs(), rtol=1e-14)
        return
    with pytest.raises(module.UndefinedPointError, match="undefined|not positive definite|not finite") as caught:
        module.rhs(0.0, x, p)
    # NumPy's LinAlgError (what a caller caught before) is M not positive definite, and only that.
    assert isinstance(caught.value, np.linalg.LinAlgError) == case.startswith("mass"), caught.value


def test_python_errors_of_the_caller_are_not_undefined_points(derivation, built):
    """A wrong length or a value that is not a number is the caller's error, said as such."""
    _write(emit_python(derivation), built)
    module = import_module(built / "undefined_point.py")
    x, p = point(None)
    with pytest.raises(ValueError, match="expected 2 states") as caught:
        module.rhs(0.0, x[:1], p)
    assert not isinstance(caught.value, module.UndefinedPointError)
    with pytest.raises(ValueError) as caught:
        module.rhs(0.0, ["one", 2.0], p)
    assert not isinstance(caught.value, module.UndefinedPointError)


def test_python_mass_matrix_and_forcing_refuse_too(derivation, built):
    _write(emit_python(derivation), built)
    module = import_module(built / "undefined_point.py")
    x, p = point("sqrt_of_negative")
    with pytest.raises(module.UndefinedPointError):
        module.forcing(0.0, x, p)
    x, p = point("nan_given")
    with pytest.raises(module.UndefinedPointError):
        module.forcing(0.0, x, p)
    module.mass_matrix(0.0, x, p)  # M does not depend on x: defined


# -- C ------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def c_library(derivation, built):
    compiler = require_tool("gcc")
    directory = _written(emit_c(derivation), built, "c")
    library = directory / "libundefined.so"
    result = subprocess.run([compiler, *STRICT, "-O2", "-shared", "-fPIC", str(directory / "undefined_point.c"),
                             "-o", str(library), "-lm"], capture_output=True, text=True)
    assert result.returncode == 0 and not result.stderr, result.stderr
    function = ctypes.CDLL(str(library)).undefined_point_rhs
    pointer = ctypes.POINTER(ctypes.c_double)
    function.argtypes = [ctypes.c_double, pointer, pointer, pointer, pointer]
    function.restype = ctypes.c_int
    return function


@pytest.mark.parametrize("case", CASES)
def test_c(case, c_library):
    x, p = (np.ascontiguousarray(v, dtype=float) for v in point(case))
    xdot = np.zeros(2)
    as_pointer = lambda a: a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))  # noqa: E731
    status = c_library(0.0, as_pointer(x), as_pointer(p), None, as_pointer(xdot))
    if case is None:
        assert status == 0
        np.testing.assert_allclose(xdot, expected_rhs(), rtol=1e-14)
        return
    assert status == (1 if case.startswith("mass") else -1)
    assert np.isnan(xdot).all()


# -- Octave -------------------------------------------------------------------------

@pytest.fixture(scope="module")
def octave_results(derivation, built):
    """One Octave run for every case: 'ok v1 v2' or 'error IDENTIFIER'."""
    octave = require_tool("octave")
    directory = _written(emit_octave(derivation), built, "octave")
    lines = ["format long g"]
    for case in CASES:
        x, p = point(case)
        vector = lambda v: "[" + "; ".join(_octave_number(e) for e in v) + "]"  # noqa: E731
        lines += [f"try, v = undefined_point_rhs(0, {vector(x)}, {vector(p)}, []); "
                  f"printf('{case} ok %.17g %.17g\\n', v(1), v(2)); "
                  f"catch err, printf('{case} error %s\\n', err.identifier); end"]
    (directory / "run_cases.m").write_text("\n".join(lines) + "\n", encoding="utf-8")
    result = subprocess.run([octave, "--no-gui", "--norc", "--quiet", "--eval", f"cd('{directory}'); run_cases"],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    return {line.split()[0]: line.split()[1:] for line in result.stdout.splitlines() if line.strip()}


def _octave_number(value: float) -> str:
    return "NaN" if math.isnan(value) else ("Inf" if value == math.inf else repr(value))


@pytest.mark.parametrize("case", CASES)
def test_octave(case, octave_results):
    got = octave_results[str(case)]
    if case is None:
        assert got[0] == "ok", got
        np.testing.assert_allclose([float(v) for v in got[1:]], expected_rhs(), rtol=1e-14)
        return
    assert got == ["error", "gacli:undefined"]


# -- JAX ----------------------------------------------------------------------------

@pytest.fixture(scope="module")
def jax_module(derivation, built):
    jax = pytest.importorskip("jax")
    jax.config.update("jax_enable_x64", True)
    directory = _written(emit_jax(derivation), built, "jax")
    return import_module(directory / "undefined_point_jax.py"), jax


@pytest.mark.parametrize("case", CASES)
def test_jax(case, jax_module):
    module, jax = jax_module
    x, p = (jax.numpy.array(v) for v in point(case))
    got = np.asarray(jax.jit(module.rhs)(0.0, x, p))
    if case is None:
        np.testing.assert_allclose(got, expected_rhs(), rtol=1e-12)
        return
    assert np.isnan(got).all(), got


# -- FMU ----------------------------------------------------------------------------

@pytest.mark.parametrize("case", [None, "sqrt_of_negative", "mass_zero"])
def test_fmu(case, derivation, built, monkeypatch, capfd):
    from test_emit_fmu import Model, need_fmpy

    fmpy = need_fmpy()
    monkeypatch.setenv("CC", require_tool("gcc"))
    from fmpy.fmi1 import FMICallException

    directory = built / f"fmu_{case}"
    directory.mkdir()
    ((name, data),) = emit_fmu(derivation).items()
    (directory / name).write_bytes(data)
    model = Model(directory / name, fmpy.extract(str(directory / name), str(directory / "u")))
    from gacli.emit.naming import layout

    x, p = point(case)
    try:
        if case is None:
            dx, _ = model.derivatives(layout(derivation), 0.0, x, p, [])
            np.testing.assert_allclose(dx, expected_rhs(), rtol=1e-14)
            return
        with pytest.raises(FMICallException):
            model.derivatives(layout(derivation), 0.0, x, p, [])
        log = capfd.readouterr().out
        assert ("undefined at t = 0" if case == "sqrt_of_negative" else "not positive definite at t = 0") in log
    finally:
        model.close()
