"""Linearization: A and B against closed forms and against KanesMethod, and the command."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from typer.testing import CliRunner

from conftest import SYSTEMS, derived
from gacli.cli import app
from gacli.linearize import linearize, linearize_symbolic


def test_cylinder_is_a_pendulum_of_frequency_sqrt_2g_3c():
    lin = linearize(derived("cylinder_in_cylinder"))
    g, c = 9.81, 0.5 - 0.1
    A = lin.block(["theta", "dot(theta)"])
    np.testing.assert_allclose(A, [[0, 1], [-2 * g / (3 * c), 0]], rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(sorted(lin.eigenvalues(["theta", "dot(theta)"]).imag),
                               [-np.sqrt(2 * g / (3 * c)), np.sqrt(2 * g / (3 * c))], rtol=1e-12)


def test_symbolic_and_numeric_agree_for_the_top():
    d = derived("spinning_top")
    at = {"theta": 0.4, "dot(phi)": 0.3, "dot(q)": 50.0}
    numeric = linearize(d, at).A
    A, _ = linearize_symbolic(d, at)
    values = {sp.Symbol(n, real=True): v for n, v in
              {"m": 1, "g": 9.81, "l": 0.05, "A": 0.0005, "C": 0.0008}.items()}
    np.testing.assert_allclose(np.array(A.xreplace(values).evalf().tolist(), dtype=float), numeric,
                               rtol=1e-10, atol=1e-10)


def test_rolling_disk_against_kane_finite_differences():
    """∂u̇/∂(lean, u) at upright rolling, gacli's complex step against central differences of Kane's u̇."""
    from test_frames import kane_accelerations, kane_rolling_disk

    kane, (yaw, lean, spin), u, (m, r, g) = kane_rolling_disk()
    values = {m: 2.0, r: 0.3, g: 9.81}
    spin_rate = -10.0
    base = {yaw: 0.0, lean: 0.0, spin: 0.0, u[0]: 0.0, u[1]: 0.0, u[2]: spin_rate}

    def kane_u_dot(changes):
        return kane_accelerations(kane, {**base, **values, **changes})

    lin = linearize(derived("rolling_disk"), {"dot(spin)": spin_rate})
    rows = [lin.state.index(n) for n in ("dot(yaw)", "dot(lean)", "dot(spin)")]
    h = 1e-6
    for name, symbol in (("lean", lean), ("dot(yaw)", u[0]), ("dot(lean)", u[1]), ("dot(spin)", u[2])):
        column = (kane_u_dot({symbol: base[symbol] + h}) - kane_u_dot({symbol: base[symbol] - h})) / (2 * h)
        np.testing.assert_allclose(lin.A[rows, lin.state.index(name)], column, rtol=1e-6, atol=1e-6)


def test_linearize_command():
    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "cylinder_in_cylinder.yaml"),
                                      "--states", "theta,dot(theta)"])
    assert result.exit_code == 0, result.output
    assert "-16.35" in result.output and "eigenvalues:" in result.output
    bad = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "cylinder_in_cylinder.yaml"), "--states", "lean"])
    assert bad.exit_code == 2 and "not in the state: lean" in bad.output



@pytest.mark.parametrize("sweep, said", [("theta=0:inf:3", "finite numbers"), ("theta=-1e308:1e308:3", "finite numbers"),
                                         ("theta=0:1:1000000000", "more than 1,000,000 values")])
def test_a_sweep_past_what_numbers_hold_is_a_usage_error(sweep, said):
    # inf ended in numpy's LinAlgError as a traceback; a billion values grew to 7.8 GB before the budget.
    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "cylinder_in_cylinder.yaml"), "--sweep", sweep])
    assert result.exit_code == 2, result.output
    assert said in result.output and "Traceback" not in result.output


def test_symbolic_linearization_differentiates_the_forms_read_off_the_program(monkeypatch):
    """--symbolic needs no closed route: the forms read off the program are what it differentiates,
    and A agrees with the chapter's rolling-disk result (the doc's example: 4g/(5r), 6w/5, −2w)."""
    from typer.testing import CliRunner

    import gacli.pipeline as pipeline
    from gacli.cli import app

    def refused(*args, **kwargs):
        raise AssertionError("the closed route ran")

    monkeypatch.setattr(pipeline, "derive", refused)
    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "rolling_disk.yaml"), "--symbolic", "--at",
                                      "dot(spin)=w", "--states", "lean,dot(yaw),dot(lean),dot(spin)"])
    assert result.exit_code == 0, result.output
    rows = {line.split()[0]: line.split()[1:] for line in result.output.splitlines()[2:6]}
    assert rows["dot(yaw)"] == ["0", "0", "-2*w", "0"]
    assert rows["dot(lean)"] == ["4*g/(5*r)", "6*w/5", "0", "0"]
