"""Steady motions against the textbook: the rolling disk's circular motions and the top's precession.

The disk's steady turning relation is written here from the balance of
moments about its centre (Routh, Advanced Rigid Dynamics, art. 244;
Neimark and Fufaev, Dynamics of Nonholonomic Systems, III.5): with lean θ,
turning rate Ω, spin ω about the axle, I_a = mr²/2 and I_d = mr²/4,

    (I_a + m r²) Ω (Ω sin θ + ω) cos θ − I_d Ω² sin θ cos θ + m g r sin θ = 0.

The top's steady precession (Goldstein 5.7): m g l = φ̇ (C ω₃ − A_O φ̇ cos θ).
"""

from __future__ import annotations

import json

import sympy as sp
from typer.testing import CliRunner

from conftest import SYSTEMS, derived
from gacli.cli import app
from gacli.steady.motions import steady_motions


def _s(name: str) -> sp.Symbol:
    return sp.Symbol(name, real=True)


def test_disk_circular_motions_satisfy_the_textbook_relation():
    m, r, g, lean, turn, spin = (_s(n) for n in ("m", "r", "g", "lean", "dot(yaw)", "dot(spin)"))
    result = steady_motions(derived("rolling_disk"))
    assert result.ignorable == ("x", "y", "yaw", "spin")
    turning = [f for f in result.families if set(f.free) == {turn, lean}]
    assert len(turning) == 1
    values = dict(turning[0].values)
    assert values[_s("dot(lean)")] == 0
    I_a, I_d = m * r**2 / 2, m * r**2 / 4
    relation = ((I_a + m * r**2) * turn * (turn * sp.sin(lean) + spin) * sp.cos(lean)
                - I_d * turn**2 * sp.sin(lean) * sp.cos(lean) + m * g * r * sp.sin(lean))
    assert sp.simplify(relation.xreplace({spin: values[spin]})) == 0
    # Dividing by Ω cos θ is the condition the family states.
    assert any(c.has(turn) and c.has(sp.cos(lean)) for c in turning[0].conditions)


def test_disk_upright_rolling_is_a_family_of_its_own():
    families = steady_motions(derived("rolling_disk")).families
    upright = [dict(f.values) for f in families if f.free == (_s("dot(spin)"),)]
    assert {_s("dot(yaw)"): 0, _s("dot(lean)"): 0, _s("lean"): 0} in upright


def test_top_steady_precession():
    m, g, l, A, C, theta, phi_rate, q = (_s(n) for n in ("m", "g", "l", "A", "C", "theta", "dot(phi)", "dot(q)"))
    result = steady_motions(derived("spinning_top"))
    precessing = [dict(f.values) for f in result.families if set(f.free) == {phi_rate, theta}]
    assert len(precessing) == 1
    A_O = A + m * l**2
    assert sp.simplify(m * g * l - phi_rate * (C * precessing[0][q] - A_O * phi_rate * sp.cos(theta))) == 0


def test_sleigh_runs_straight_at_any_speed():
    families = steady_motions(derived("chaplygin_sleigh")).families
    assert [(dict(f.values), f.free) for f in families] == [({_s("dot(theta)"): 0}, (_s("dot(s)"),))]


def test_steady_command_formats():
    text = CliRunner().invoke(app, ["steady", str(SYSTEMS / "chaplygin_sleigh.yaml")])
    assert text.exit_code == 0, text.output
    assert "dot(theta) = 0" in text.output and "x, y, theta" in text.output
    data = CliRunner().invoke(app, ["steady", str(SYSTEMS / "chaplygin_sleigh.yaml"), "--format", "json"])
    assert json.loads(data.output)["families"] == [
        {"values": {"dot(theta)": "0"}, "free": ["dot(s)"], "relations": [], "conditions_nonzero": [],
         "real_at_file_values": True, "not_at_constant_rates": []}]
    bad = CliRunner().invoke(app, ["steady", str(SYSTEMS / "chaplygin_sleigh.yaml"), "--format", "html"])
    assert bad.exit_code == 2


def test_a_system_too_large_for_symbolic_work_is_refused_plainly():
    result = CliRunner().invoke(app, ["steady", str(SYSTEMS / "whipple_bicycle.yaml")])
    assert result.exit_code == 1 and "too large for symbolic work" in result.output
    assert "Traceback" not in result.output


def test_latex_format_is_amsmath():
    result = CliRunner().invoke(app, ["steady", str(SYSTEMS / "rolling_disk.yaml"), "--format", "latex"])
    assert result.exit_code == 0, result.output
    assert result.output.count("\\begin{align*}") == result.output.count("\\end{align*}") == 3
    assert "\\dot{\\varphi} &= " in result.output    # the file's latex: for spin


def test_steady_reads_standard_input_and_locates_its_refusal():
    # As every command that reads one system file: '-' is standard input, and a refusal names the file.
    disk = (SYSTEMS / "rolling_disk.yaml").read_text()
    result = CliRunner().invoke(app, ["steady", "-"], input=disk)
    assert result.exit_code == 0 and "family 1" in result.output, result.output
    bicycle = CliRunner().invoke(app, ["integrals", str(SYSTEMS / "whipple_bicycle.yaml")])
    assert bicycle.exit_code == 1
    assert f"{SYSTEMS / 'whipple_bicycle.yaml'}:1:1: error: integrals: " in bicycle.output, bicycle.output


def test_a_four_bar_s_equilibria_are_a_relation_not_a_solve_without_end():
    # SymPy's solve of the 49-operation equilibrium in th1, th2, th3 (sin and cos of th1 beside the
    # others) simplified for minutes: steady ran to its budget on a shipped system.
    found = steady_motions(derived("four_bar_linkage"))
    assert found.families


def test_a_family_is_not_listed_again_as_its_own_special_case_and_unreal_ones_are_said_so():
    """Chaplygin's ball (A < B < C): at rest with θ and ψ free was listed again with ψ = asin(...)
    fixed, and ψ = asin(√((C − B)/(A − B))) = asin(√−2) was printed as a steady motion without a word."""
    from gacli.steady.motions import steady_motions

    import gacli

    d = gacli.derive(str(SYSTEMS / "chaplygin_ball.yaml"))
    families = steady_motions(d).families
    for f in families:
        for g in families:
            assert f is g or not (set(g.values) <= set(f.values) and set(g.relations) <= set(f.relations)
                                  and not g.conditions), (f, g)
    from gacli.algebra import symbols as S

    A, B, C = (S.value(n) for n in "ABC")
    at = {A: 0.002, B: 0.003, C: 0.005}  # the file's values
    for f in families:
        imaginary = any(abs(complex(v.subs(at).subs({u: 0.4 for u in f.free}).evalf()).imag) > 1e-9 for _, v in f.values)
        assert f.real is (not imaginary), f
    assert any(f.real is False for f in families)
    text = CliRunner().invoke(app, ["steady", str(SYSTEMS / "chaplygin_ball.yaml")]).output
    assert text.count("not real at the file's parameter values") == sum(f.real is False for f in families)


def test_coordinates_whose_rates_turn_are_not_said_to_move_at_constant_rates():
    """The disk's x, y go round a circle along its circular motion (ẋ = ... cos(yaw)), not along
    upright rolling; a satellite's e0..e3 turn as ė = ½ E(e) ω: all were 'moving at constant rates
    along every family'. The sleigh's x, y do, since θ̇ = 0 along its one family."""
    from gacli.steady.motions import steady_motions

    import gacli

    disk = steady_motions(gacli.derive(str(SYSTEMS / "rolling_disk.yaml")))
    assert disk.steady_rates == ("yaw", "spin")
    from gacli.algebra import symbols as S

    for family in disk.families:
        turning = dict(family.values).get(S.rate("yaw")) != 0
        assert (family.drifting == ("x", "y")) == turning, family
    sleigh = steady_motions(gacli.derive(str(SYSTEMS / "chaplygin_sleigh.yaml")))
    assert sleigh.steady_rates == ("x", "y", "theta") and not sleigh.drifting
    data = json.loads(CliRunner().invoke(app, ["steady", str(SYSTEMS / "satellite_reaction_wheels.yaml"),
                                               "--format", "json"]).output)
    assert all(f["not_at_constant_rates"] in ([], ["e0", "e1", "e2", "e3"]) for f in data["families"])
    assert any(f["not_at_constant_rates"] for f in data["families"])


def test_a_coordinate_inside_a_sign_is_not_ignorable(tmp_path):
    """k|x| in a potential: the force −k sign(x) has a zero Jacobian on either side of the kink, and
    x was 'moving at constant rates along every family', its family wrong (a reviewer's file)."""
    path = tmp_path / "well.yaml"
    path.write_text("gacli: 1\nname: well\nparameters: {m: 1, k: 2}\ncoordinates: [x, y]\n"
                    "bodies:\n  p: {mass: m, position: [x, y, 0]}\npotential: k*abs(x) + k*y**2\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["steady", str(path)])
    assert result.exit_code == 0, result.output
    assert "constant rates along every family: x" not in result.output and "sign(x)" in result.output
