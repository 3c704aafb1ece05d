"""Issue 18, numbers, comments, geometry and samples: hostile files that must be refused
(tests/hostile/num_*, geom_*, checked by test_hostile.py) and the ones that must be
accepted (tests/accepted_hostile/), whose generated code must compile and run."""

from __future__ import annotations

import importlib.util
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from typer.testing import CliRunner

from gacli.cli import app
from gacli.emit.c import comment_text, emit_c
from gacli.emit.printers import GacliCPrinter, GacliPythonPrinter
from gacli.emit.python import emit_python
from gacli.mechanics.equations import derive
from gacli.loader.loading import load, loads
from gacli.numeric import sample_parameters, unphysical
from gacli.errors import SystemFileError

HERE = Path(__file__).resolve().parent
ACCEPTED = HERE / "accepted_hostile"
HOSTILE = HERE / "hostile"
WIDE = ACCEPTED / "num_wide_rationals.yaml"
PRODUCTS = ACCEPTED / "num_symbolic_products_of_inertia.yaml"
X = sp.Symbol("x", real=True)


# -- numbers in generated code ----------------------------------------------------------

@pytest.mark.parametrize("printer", [GacliCPrinter, GacliPythonPrinter])
def test_wide_rationals_print_as_the_nearest_double(printer):
    wide = sp.Rational(10 ** 300 + 1, 3 * 10 ** 299)
    code = printer({X: "x"}).doprint(wide * X)
    assert not re.search(r"\d{20}", code), code
    assert float(re.search(r"[\d.e+-]+", code).group()) == float(wide)


def test_small_numbers_print_as_before():
    assert GacliCPrinter({X: "x"}).doprint(sp.Rational(3, 7) * X + 2) == "(3.0/7.0)*x + 2"
    assert GacliPythonPrinter({X: "x"}).doprint(sp.Rational(3, 7) * X + 2) == "(3/7)*x + 2"


def test_numbers_beyond_the_double_range_are_infinite():
    assert GacliCPrinter({X: "x"}).doprint(-sp.Integer(10) ** 400 * X) == "-HUGE_VAL*x"
    assert GacliPythonPrinter({X: "x"}).doprint(sp.Integer(10) ** 400 + X) == "x + math.inf"


# -- free text in comments --------------------------------------------------------------

@pytest.mark.parametrize("text", ["/* x */", "/*/", "a ??/", "???=", "??( ??) ??< ??> ??! ??' ??-", "tail \\"])
def test_comment_text_is_inert(text):
    safe = comment_text(text)
    assert "/*" not in safe and "*/" not in safe and not safe.endswith("\\")
    assert not re.search(r"\?\?[=(/)'<!>-]", safe)


def test_wide_rationals_file_is_accepted_by_check():
    result = CliRunner().invoke(app, ["check", "--timeout", "20", str(WIDE)])
    assert result.exit_code == 0, result.output


@pytest.fixture(scope="module")
def wide_derivation():
    derivation = derive(load(WIDE))
    longest = max(len(str(max(abs(r.p), r.q))) for r in sp.Matrix([*derivation.mass_matrix]).atoms(sp.Rational))
    assert longest > 267  # the file still makes the numbers the issue is about
    return derivation


@pytest.mark.parametrize("compiler", ["gcc", "clang"])
@pytest.mark.parametrize("flags", [["-std=c99", "-pedantic"], ["-std=gnu11", "-D_GNU_SOURCE"]])
def test_generated_c_compiles(wide_derivation, compiler, flags, tmp_path):
    from conftest import require_tool

    files = emit_c(wide_derivation)
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    assert "/* not a comment" not in files["wide_rationals.h"]
    done = subprocess.run([require_tool(compiler), *flags, "-Wall", "-Wextra", "-Werror", "-Wtrigraphs",
                           "-c", "wide_rationals.c", "-o", "wide.o"], cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def test_generated_python_imports_and_its_numbers_are_right(wide_derivation, tmp_path):
    (name, text), = emit_python(wide_derivation).items()
    assert not re.search(r"\d{20}", text)
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    x = [0.7, -0.2, 0.3, 0.1]
    M = module.mass_matrix(0.0, x, [1.0], [0.5])
    exact = np.array(sp.Matrix(wide_derivation.mass_matrix).subs(sp.Symbol("m", real=True), 1), dtype=float)
    np.testing.assert_allclose(M, exact, rtol=1e-15)
    assert np.all(np.isfinite(module.rhs(0.0, x, [1.0], [0.5])))


# -- imaginary quantities: refused by derive as by check ----------------------------------

@pytest.mark.parametrize("stem", ["num_asin_of_two", "num_sqrt_minus_one", "num_complex_at_every_state"])
def test_derive_refuses_imaginary_quantities_with_a_location(stem):
    path = HOSTILE / f"{stem}.yaml"
    result = CliRunner().invoke(app, ["derive", str(path)])
    assert result.exit_code == 1
    assert "Traceback" not in result.output
    assert re.search(rf"{re.escape(str(path))}:13:22: error: ", result.output), result.output


SPHERE = """
gacli: 1
name: s
parameters:
  m: {value: 1}
coordinates: [x, y, theta]
quasi_coordinates: [q_1, q_2, q_3]
bodies:
  b: {mass: m, position: [x, y, POSITION], inertia: [1, 1, 1], rotation: [dq_1, dq_2, dq_3]}
rolling:
  - {body: b, radius: RADIUS}
"""


@pytest.mark.parametrize("position", ["sqrt(1 - theta**2)", "sqrt(0.0001 - theta**2)", "sqrt(theta - 50)"])
def test_a_position_real_only_on_part_of_the_states_is_accepted(position):
    loads(SPHERE.replace("POSITION", position).replace("RADIUS", "1"))


def test_a_sphere_of_radius_zero_is_refused():
    with pytest.raises(SystemFileError, match="radius must be positive"):
        loads(SPHERE.replace("POSITION", "1").replace("RADIUS", "0"))


# -- physical samples --------------------------------------------------------------------

def test_sampled_inertias_are_physical():
    system = load(PRODUCTS)
    rng = np.random.default_rng(5)
    for _ in range(40):
        sample = sample_parameters(system, rng)
        assert sample.problem == ""
        symbols = {s.name: v for s, v in sample.values.items()}
        A, B, C, D, E, G = (symbols[n] for n in "ABCDEG")
        moments = np.linalg.eigvalsh([[A, -G, -E], [-G, B, -D], [-E, -D, C]])
        assert moments.min() > 0 and moments.max() <= moments.sum() - moments.max() + 1e-12
        assert symbols["m"] > 0


def test_unphysical_names_the_body():
    system = loads(SPHERE.replace("POSITION", "1").replace("RADIUS", "1").replace("inertia: [1, 1, 1]",
                                                                                  "inertia: [1, 1, 3]"))
    assert "triangle inequality" in unphysical(system, {})


def test_verify_passes_with_symbolic_products_of_inertia():
    result = CliRunner().invoke(app, ["verify", str(PRODUCTS)])
    assert result.exit_code == 0, result.output
    assert "verify: passed" in result.output


def test_verify_blames_a_sample_that_cannot_be_physical():
    from gacli.verify import verify

    text = PRODUCTS.read_text(encoding="utf-8").replace("m: {description: mass}", "m: {description: mass, value: -1}")
    system = loads(text)
    report = verify(system, derive(system), samples=3)
    assert report.passed, report.failures
    assert any("the sample, not the derivation, is at fault" in n and "mass of body" in n for n in report.notes)


def test_verify_report_says_m_was_not_judged_on_unphysical_samples():
    from gacli.verify import format_report, verify

    system = loads(PRODUCTS.read_text(encoding="utf-8").replace("m: {description: mass}", "m: {value: -1}"))
    lines = format_report(verify(system, derive(system), samples=2))
    assert "  M positive definite: not judged (no sample had physical parameters)" in lines
    assert lines[-1] == "verify: passed"
