"""The emitter registry, the layout of x/p/r, the printers and the Python module.

Numerical agreement with SymPy and with the C code is in
test_generated_numeric.py; byte-for-byte output in test_golden.py.
"""

from __future__ import annotations

import ast
import dataclasses
import importlib.util
import os
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from conftest import SYSTEMS, derived
from gacli.algebra import symbols as S
from gacli.emit import EMITTERS
from gacli.emit.naming import header_lines, layout
from gacli.emit.printers import GacliCPrinter, GacliPythonPrinter
from gacli.emit.python import emit_python
from gacli.mechanics.equations import derive
from gacli.errors import EmitError
from gacli.loader.loading import loads

ALL = sorted(p.stem for p in SYSTEMS.glob("*.yaml"))

# Every awkward case at once: t in F (a prescribed function), a free function
# whose ddot occurs but not its dot, names that clash with the generated code
# (x, M, pow, map), with each other once spelt for C (dot_x, m/M), and '_q'.
AWKWARD = """
gacli: 1
name: shaken
title: "A bead on a shaken wire */ with a comment closer"
parameters:
  m: {value: 2}
  M: {value: 3*m}
  k: {}
  dot_x: {value: k + 1}
  _q: {value: pi}
  pow: {value: 1}
  map: {value: 0.5}
functions:
  h: height of the support
  w: {value: sin(t)}
inputs: [f]
coordinates: [x]
bodies:
  bead: {mass: m + M + pow + _q + map, position: [x, 0, h]}
work: (f + m*ddot(h) + w + k*dot_x*x)*dx
"""


# The least a system can be: no parameters, inputs or functions; M and F constant.
BARE = """
gacli: 1
name: bare
coordinates: [z]
bodies: {ball: {mass: 2, position: [0, 0, z]}}
"""

EXTRA = {"shaken": AWKWARD, "bare": BARE}
# And the hand-written twins kept in tests/cases/ (the rolling disk in format 1):
# every target is checked on them as on systems/.
EXTRA.update({p.stem: p.read_text(encoding="utf-8")
              for p in sorted((Path(__file__).resolve().parent / "cases").glob("*.yaml"))})


def extra(name):
    """A derivation of one of the test's own systems (EXTRA)."""
    return derive(loads(EXTRA[name], path=f"/somewhere/private/{name}.yaml"))


def awkward():
    return extra("shaken")


def import_module(path):
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_python(derivation, tmp_path):
    ((name, text),) = emit_python(derivation).items()
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return import_module(path)


# -- registry --------------------------------------------------------------------

def test_registry_names_every_format():
    assert sorted(EMITTERS) == ["c", "fmu", "jax", "latex", "octave", "python"]


@pytest.mark.parametrize(("fmt", "suffixes"), [("python", [".py"]), ("c", [".c", ".h"]), ("latex", [".tex"])])
def test_each_emitter_returns_files_as_data(fmt, suffixes, tmp_path):
    before = set(os.listdir(tmp_path))
    files = EMITTERS[fmt](derived("cylinder_in_cylinder"))
    assert sorted(files) == [f"cylinder_in_cylinder{s}" for s in suffixes]
    assert all(isinstance(text, str) and text.endswith("\n") for text in files.values())
    assert set(os.listdir(tmp_path)) == before


# -- layout ------------------------------------------------------------------------

def test_layout_follows_the_declaration_order():
    lay = layout(derived("sphere_on_turntable"))
    assert lay.state == ("x", "y", "dot(x)", "dot(y)", "dot(q_z)")
    assert lay.state_symbols == derived("sphere_on_turntable").state
    assert lay.parameters == ("M", "a", "I")
    assert lay.r == ("F_x", "F_y", "F_z", "M_x", "M_y", "M_z", "Omega", "dot(Omega)")
    assert lay.defaults == {"M": 1.0, "a": 0.1, "I": pytest.approx(0.004, rel=1e-15)}
    assert (lay.n, lay.k) == (2, 3)


def test_layout_r_holds_every_rate_up_to_the_highest_that_occurs():
    lay = layout(awkward())
    assert lay.r == ("f", "h", "dot(h)", "ddot(h)")
    assert lay.r_symbols == (S.value("f"), S.value("h"), S.rate("h"), S.rate("h", 2))


def test_layout_defaults_follow_earlier_parameters_and_skip_unknowns():
    lay = layout(awkward())
    assert lay.parameters == ("m", "M", "k", "dot_x", "_q", "pow", "map")
    assert lay.defaults == {"m": 2.0, "M": 6.0, "_q": pytest.approx(np.pi, rel=1e-15), "pow": 1.0, "map": 0.5}


def test_identifiers_are_unique_and_clear_of_generated_names():
    lay = layout(awkward())
    assert [e.identifier for e in lay.entries] == [
        "x_", "dot_x", "m", "M_", "k", "dot_x_2", "v_q", "pow_", "map_", "f", "h", "dot_h", "ddot_h",
    ]


def test_index_macros_are_upper_case_and_unique():
    lay = layout(awkward())
    assert [e.macro for e in lay.entries] == [
        "SHAKEN_X_X", "SHAKEN_X_DOT_X",
        "SHAKEN_P_M", "SHAKEN_P_M_2", "SHAKEN_P_K", "SHAKEN_P_DOT_X", "SHAKEN_P_V_Q", "SHAKEN_P_POW",
        "SHAKEN_P_MAP",
        "SHAKEN_R_F", "SHAKEN_R_H", "SHAKEN_R_DOT_H", "SHAKEN_R_DDOT_H",
    ]


def test_layout_rejects_a_symbol_with_no_slot():
    d = derived("cylinder_in_cylinder")
    # What generated code computes is Derivation.code (the program's F), where the stray symbol goes.
    stray = dataclasses.replace(d)
    stray.__dict__["code"] = dataclasses.replace(d.code, forcing=(d.code.forcing[0] + S.value("zeta"),))
    with pytest.raises(EmitError, match="not in x, p or r: zeta"):
        emit_python(stray)


def test_header_names_the_file_by_base_name_and_hash():
    d = awkward()
    lines = header_lines(d, "python")
    text = "\n".join(lines)
    assert "gacli 0.1.0" in lines[0] and "shaken.yaml" in lines[0] and "Do not edit" in lines[0]
    assert d.system.sha256 in text
    assert "/somewhere" not in text
    assert lines[-1] == "A bead on a shaken wire */ with a comment closer"


# -- printers --------------------------------------------------------------------

def test_c_printer_prints_pi_as_a_literal_and_no_macros():
    theta = S.value("theta")
    printer = GacliCPrinter({theta: "theta"})
    code = printer.doprint(sp.pi * sp.sqrt(2) * sp.E * theta / 2)
    assert "M_" not in code and "3.14159265358979" in code and "2.71828182845904" in code
    assert printer.includes() == ["math.h"]


@pytest.mark.parametrize("printer_class", [GacliCPrinter, GacliPythonPrinter])
def test_printers_map_symbols_and_refuse_unknown_ones(printer_class):
    a = S.rate("q_z")
    assert printer_class({a: "dot_q_z"}).doprint(2 * a) == "2*dot_q_z"
    with pytest.raises(EmitError, match="zeta has no slot"):
        printer_class({a: "dot_q_z"}).doprint(a + S.value("zeta"))


@pytest.mark.parametrize("fmt", ["python", "c"])
def test_unsupported_node_names_its_type_and_equation(fmt, monkeypatch):
    # The nodes are put into the closed forms, which code then must take: with them, the closed
    # forms cost more than the program built from the file, which knows nothing of them.
    monkeypatch.setattr("gacli.mechanics.derivation.program_for", lambda system: None)
    d = derived("cylinder_in_cylinder")
    theta = S.value("theta")
    odd = sp.Function("f")(theta)
    broken = dataclasses.replace(d, forcing=sp.ImmutableMatrix([d.forcing[0] + odd]))
    with pytest.raises(EmitError, match=r"F\[0\]: f cannot be printed as"):
        EMITTERS[fmt](broken)
    derivative = sp.Derivative(odd, theta)
    broken = dataclasses.replace(d, mass_matrix=sp.ImmutableMatrix([[d.mass_matrix[0] + derivative]]))
    with pytest.raises(EmitError, match=r"M\[0, 0\]: Derivative cannot be printed as"):
        EMITTERS[fmt](broken)


# -- the Python module -------------------------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_module_imports_only_the_standard_library_and_numpy(name):
    ((_, text),) = emit_python(derived(name)).items()
    tree = ast.parse(text)
    imported = {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import) for alias in node.names}
    assert imported == {"functools", "math", "numpy"}  # the standard library and NumPy only
    assert not any(isinstance(node, ast.ImportFrom) for node in ast.walk(tree))


@pytest.mark.parametrize("name", ALL)
def test_module_interface(name, tmp_path):
    d = derived(name)
    module = write_python(d, tmp_path)
    lay = layout(d)
    assert (module.STATE, module.PARAMETERS, module.INPUTS) == (lay.state, lay.parameters, lay.r)
    assert module.DEFAULTS == lay.defaults
    x = np.linspace(0.4, 1.3, len(module.STATE))
    p = [module.DEFAULTS[n] for n in module.PARAMETERS]
    r = np.linspace(0.2, 0.9, len(module.INPUTS))
    M, F, xdot = module.mass_matrix(0.1, x, p, r), module.forcing(0.1, x, p, r), module.rhs(0.1, x, p, r)
    assert M.shape == (d.k, d.k) and F.shape == (d.k,) and xdot.shape == (len(x),)
    assert M.dtype == F.dtype == xdot.dtype == np.float64
    np.testing.assert_array_equal(M, M.T)
    # Two solvers agree to rounding relative to the solution's size: a small component beside large
    # ones (the rattleback's 0.73 beside 32 and -50) carries their rounding, 1e-12 of itself.
    expected = np.linalg.solve(M, F)
    np.testing.assert_allclose(xdot[lay.n:], expected, rtol=1e-12, atol=1e-12 * np.linalg.norm(expected))


def test_r_may_be_a_callable_of_t_and_x(tmp_path):
    module = write_python(derived("sphere_on_turntable"), tmp_path)
    x, p = [0.3, -0.2, 0.1, 0.5, 2.0], [1.0, 0.1, 0.004]
    seen = []

    def r(t, state):
        seen.append((t, list(state)))
        return [0.1, 0.2, 0.0, 0.01, 0.02, 0.03, 2.0 + t, 1.0]

    expected = module.rhs(0.5, x, p, r(0.5, x))
    np.testing.assert_array_equal(module.rhs(0.5, x, p, r), expected)
    np.testing.assert_array_equal(module.forcing(0.5, x, p, r), module.forcing(0.5, x, p, r(0.5, x)))
    assert seen[-1] == (0.5, x)


def test_bare_system_gives_a_working_module(tmp_path):
    module = write_python(extra("bare"), tmp_path)
    assert (module.PARAMETERS, module.INPUTS, module.DEFAULTS) == ((), (), {})
    np.testing.assert_array_equal(module.rhs(0.0, [1.0, 3.0], ()), [3.0, 0.0])
    np.testing.assert_array_equal(module.mass_matrix(0.0, [1.0, 3.0], []), [[2.0]])


def test_r_may_be_omitted_without_inputs(tmp_path):
    module = write_python(derived("spinning_top"), tmp_path)
    x, p = [0.1, 0.5, 0.2, 0.3, 0.4, 50.0], list(module.DEFAULTS.values())
    np.testing.assert_array_equal(module.rhs(0.0, x, p), module.rhs(0.0, x, p, ()))
    np.testing.assert_array_equal(module.rhs(0.0, x, p), module.rhs(0.0, x, p, lambda t, x: ()))


def test_rhs_raises_when_the_mass_matrix_is_not_positive_definite(tmp_path):
    module = write_python(derived("sphere_on_turntable"), tmp_path)
    with pytest.raises(np.linalg.LinAlgError, match="not positive definite"):
        module.rhs(0.0, [0.0] * 5, [-1.0, 0.1, 0.004], [0.0] * 8)


def test_awkward_names_give_a_working_module(tmp_path):
    d = awkward()
    module = write_python(d, tmp_path)
    x, p, r = [0.3, 0.7], [2.0, 6.0, 0.5, 1.5, np.pi, 1.0, 0.5], [0.2, 0.4, 0.6, 0.8]
    mass = 2.0 + 6.0 + 1.0 + np.pi + 0.5
    force = 0.2 + 2.0 * 0.8 + np.sin(1.1) + 0.5 * 1.5 * 0.3
    np.testing.assert_allclose(module.rhs(1.1, x, p, r), [0.7, force / mass], rtol=1e-14)
