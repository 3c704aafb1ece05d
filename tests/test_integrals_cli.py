"""``gacli integrals``, the API's gacli.integrals/stability/steady, and simulate's drift of the integrals."""

from __future__ import annotations

import json

import numpy as np
import pytest
from typer.testing import CliRunner

from conftest import SYSTEMS
from gacli.cli import app

TOP = str(SYSTEMS / "spinning_top.yaml")


def test_candidate_conserved_and_not():
    # C ω₃ is the top's momentum about its axis (Goldstein 5.7); θ̇ is no integral.
    good = CliRunner().invoke(app, ["integrals", TOP, "--candidate", "C*dot(q)"])
    assert good.exit_code == 0, good.output
    assert "candidate 1: C*dot(q): conserved (proved symbolically)" in good.output
    bad = CliRunner().invoke(app, ["integrals", TOP, "--candidate", "dot(theta)"])
    assert bad.exit_code == 1 and "not conserved" in bad.output


def test_candidate_is_read_by_the_grammar_not_eval():
    result = CliRunner().invoke(app, ["integrals", TOP, "--candidate", "__import__('os')"])
    assert result.exit_code == 2 and "Traceback" not in result.output


@pytest.mark.parametrize("candidate, message", [("sqrt(-1)", "is not a real expression"),
                                                ("log(-1)*theta", "is not a real expression"),
                                                ("C*g", "holds no coordinate or rate")])
def test_a_constant_or_complex_candidate_is_a_usage_error(candidate, message):
    # sqrt(-1) and 3 were 'conserved (proved symbolically)', true of every constant and saying nothing.
    result = CliRunner().invoke(app, ["integrals", TOP, "--candidate", candidate])
    assert result.exit_code == 2 and message in result.output and "Traceback" not in result.output


def test_a_candidate_may_hold_a_function_of_time(tmp_path):
    # A bead on a ring turned at Ω(t): p = m R² (Ω + φ̇) is conserved; 'Omega' was 'not declared'.
    from test_integrals import RING

    path = tmp_path / "ring.yaml"
    path.write_text(RING)
    result = CliRunner().invoke(app, ["integrals", str(path), "--candidate", "m*R**2*(Omega + dot(phi))"])
    assert result.exit_code == 0 and "conserved (proved symbolically)" in result.output, result.output
    alone = CliRunner().invoke(app, ["integrals", str(path), "--candidate", "Omega"])
    assert alone.exit_code == 1 and "not conserved" in alone.output


def test_json_lists_the_sleighs_broken_momentum():
    result = CliRunner().invoke(app, ["integrals", str(SYSTEMS / "chaplygin_sleigh.yaml"), "--format", "json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert data["integrals"] == []
    assert any(n["name"] == "momentum of theta" for n in data["not_integrals"])


def test_api_names():
    import sympy as sp

    import gacli

    w = sp.Symbol("w", real=True)
    conditions = gacli.stability(str(SYSTEMS / "rolling_disk.yaml"), {"dot(spin)": w}, symbolic=True).conditions
    g, r = sp.Symbol("g", real=True), sp.Symbol("r", real=True)
    assert len(conditions) == 1 and sp.simplify(conditions[0].subs(w, sp.sqrt(g / (3 * r)))) == 0
    assert [c.conserved for c in gacli.integrals(TOP, ["C*dot(q)"]).candidates] == [True]
    # One string is one candidate, not its characters ("--candidate *: expected an expression").
    assert [c.conserved for c in gacli.integrals(TOP, "C*dot(q)").candidates] == [True]
    assert gacli.steady(str(SYSTEMS / "chaplygin_sleigh.yaml")).ignorable == ("x", "y", "theta")


def test_simulate_reports_the_momenta_drift():
    pytest.importorskip("scipy")
    import gacli

    run = gacli.simulate(TOP, initial={"theta": 0.5, "dot(q)": 50, "dot(phi)": 1}, t_end=0.5, points=51)
    assert set(run.integrals) == {"momentum of phi", "momentum of psi"}
    # p_φ = A_O sin²θ φ̇ + C ω₃ cos θ at t = 0, with the file's values (A_O = A + m l²).
    A_O, C = 0.0005 + 1 * 0.05**2, 0.0008
    assert run.integrals["momentum of phi"][0] == pytest.approx(A_O * np.sin(0.5)**2 + C * 50 * np.cos(0.5))
    assert run.integral_drift("momentum of phi") < 1e-6


def test_an_acceleration_in_a_candidate_is_refused_as_such_not_as_undeclared():
    # "'q' in 'ddot(q)' is not declared", of a quasi-coordinate the file declares.
    from typer.testing import CliRunner

    from gacli.cli import app

    result = CliRunner().invoke(app, ["integrals", str(SYSTEMS / "spinning_top.yaml"), "--candidate", "ddot(q)"])
    assert result.exit_code != 0
    assert "'ddot(q)' is not allowed here" in result.output and "not declared" not in result.output
