"""Messages that say what is true of the file (issue 33, item 7).

A spherical pendulum written with frames, whose last angle spins the rod
about itself: the bob is a particle on the rod's axis, so nothing moves with
q3. It is in the frame's rotation sequence (the old message said it was in
no rotation), and M's row for its rate is zero at every state, so ``check``
fails it whether or not the parameters have values.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from gacli.cli import app

PENDULUM = """\
gacli: 1
name: spherical
parameters:
  m: {value: VALUE}
  l: {value: VALUE}
  g: {value: VALUE}
coordinates: [q1, q2, q3]
frames:
  rod: {rotations: [[z, q1], [x, q2], [z, q3]]}
points:
  bob: {rod: [0, 0, -l]}
bodies:
  ball: {mass: m, position: bob}
potential: -m*g*l*cos(q2)
"""


@pytest.mark.parametrize("values", [True, False], ids=["with-values", "without-values"])
def test_a_coordinate_that_turns_only_a_particle_is_named_truly_and_fails(tmp_path: Path, values: bool):
    text = PENDULUM.replace("VALUE", "1") if values else PENDULUM.replace(": {value: VALUE}", ": {}")
    path = tmp_path / "spherical.yaml"
    path.write_text(text, encoding="utf-8")
    line, column = 7, text.splitlines()[6].index("q3") + 1
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 1, result.output
    assert f"{path}:{line}:{column}: error: mass_matrix: M is singular at every state: its row for dot(q3) " \
           "is zero" in result.stderr
    assert "coordinate 'q3' turns frame 'rod', but no body's position or rotation depends on it" in result.stderr
    assert "it is in no position or rotation" not in result.stderr


_SLIDER_CRANK = """gacli: 1
name: slider
parameters: {m: {value: 1}, l1: {value: 0.3}, l2: {value: 1}}
coordinates: [th1, th2, s]
constraints:
  - l1*cos(th1) + l2*cos(th2) - s = 0
  - l1*sin(th1) + l2*sin(th2) = 0
independent: [th1]
bodies:
  crank: {mass: m, position: [l1*cos(th1)/2, l1*sin(th1)/2], inertia: m*l1**2/12, rotation: dth1}
  rod: {mass: m, position: [l1*cos(th1) + l2*cos(th2)/2, l1*sin(th1) + l2*sin(th2)/2], inertia: m*l2**2/12,
        rotation: dth2}
"""


def test_a_massless_slider_that_closes_a_loop_is_a_note_that_strict_passes(tmp_path: Path):
    """The slider's travel s moves no body, but the loop needs it: not a mistake to fail CI on."""
    path = tmp_path / "slider.yaml"
    path.write_text(_SLIDER_CRANK, encoding="utf-8")
    result = CliRunner().invoke(app, ["check", "--strict", str(path)])
    assert result.exit_code == 0, result.output
    assert "note: coordinates.s: no body depends on coordinate 's', but constraints[0] ties it to two or more " \
           "others" in result.stderr
    assert "warning" not in result.stderr


def test_a_coordinate_in_a_relation_only_through_an_identity_is_tied_to_nothing(tmp_path: Path):
    """sin(s)**2 + cos(s)**2 in a relation does not tie s: the warning stands (a reviewer's file)."""
    path = tmp_path / "fake.yaml"
    path.write_text(_SLIDER_CRANK.replace("- l1*cos(th1) + l2*cos(th2) - s = 0",
                                          "- l1*cos(th1) + l2*cos(th2) + sin(s)**2 + cos(s)**2 = 1.5"),
                    encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert "warning: coordinates.s: no body depends on coordinate 's'" in result.stderr


def test_a_coordinate_in_nothing_keeps_its_message(tmp_path: Path):
    path = tmp_path / "idle.yaml"
    path.write_text(PENDULUM.replace("VALUE", "1").replace("[q1, q2, q3]", "[q1, q2, q3, s]"), encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert "no body depends on coordinate 's' (it is in no position or rotation)" in result.stderr


def test_a_parameter_value_past_what_a_double_holds_fails_check_where_it_stands(tmp_path: Path):
    # 10**100 to the fourth passed check (M was 'not checked: no value for b'), and simulate refused it.
    path = tmp_path / "pv.yaml"
    path.write_text("gacli: 1\nname: pv\nparameters:\n  a: {value: \"10**100\"}\n  b: {value: \"a*a*a*a\"}\n"
                    "  m: {value: \"b*b\"}\ncoordinates: [x, y]\nbodies:\n  p: {mass: m, position: [x, y]}\n"
                    "potential: a*b*y\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 1, result.output
    assert f"{path}:5:3: error: parameters.b: the value of 'b' is not a finite real number" in result.output
    assert "'m' is not a finite" not in result.output


@pytest.mark.parametrize("name, why", [("lambda", "is a Python keyword"), ("x__2", "contains '__'")])
def test_a_symbol_no_expression_could_write_is_refused_where_it_is_declared(tmp_path: Path, name, why):
    # Accepted when declared, refused only at its first use in an expression (or never, if unused).
    path = tmp_path / "kw.yaml"
    path.write_text(f"gacli: 1\nname: kw\nparameters: {{{name}: {{value: 1}}, m: {{value: 1}}}}\ncoordinates: [x]\n"
                    "bodies: {b: {mass: m, position: [x, 0, 0]}}\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 1, result.output
    assert f"{path}:3:14: error: parameters: '{name}' {why}: no expression could use it" in result.output


def test_a_relation_without_a_coordinate_is_said_to_constrain_nothing(tmp_path: Path):
    """'1 = 0' was 'not independent of the others (it depends on nothing)'."""
    path = tmp_path / "one.yaml"
    path.write_text("gacli: 1\nname: h\nparameters: {m: {value: 1}}\ncoordinates: [x]\nconstraints:\n  - 1 = 0\n"
                    "bodies:\n  p: {mass: m, position: [x, 0, 0]}\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 1
    assert f"{path}:6:5: error: constraints[0]: this relation constrains no coordinate or rate" in result.stderr
    assert "depends on nothing" not in result.stderr


def _checked(tmp_path: Path, text: str):
    path = tmp_path / "f.yaml"
    path.write_text(text, encoding="utf-8")
    return path, CliRunner().invoke(app, ["check", str(path)])


def test_an_inertia_no_body_can_have_is_a_warning_at_the_body(tmp_path: Path):
    """Principal moments 1, 1, 3 break A + B ≥ C: verify's samples said so, check did not."""
    path, result = _checked(tmp_path, "gacli: 1\nname: b\nparameters: {m: {value: 1}}\ncoordinates: [th]\n"
                                      "frames: {body: {rotations: [[z, th]]}}\n"
                                      "bodies:\n  b: {mass: m, position: [0, 0, 0], frame: body, inertia: [1, 1, 3]}\n")
    assert f"{path}:7:3: warning: bodies.b: no real body has these values: the inertia of b breaks the " \
           "triangle inequality (principal moments 1, 1, 3)" in result.stderr


def test_m_is_sampled_where_the_positions_are_real(tmp_path: Path):
    """A pendulum of length 0.25 placed by sqrt(L**2 - x**2): no sample of [0.3, 1.7] is real, and check
    passed without testing M, whose rotor moment is negative."""
    _, result = _checked(tmp_path, "gacli: 1\nname: p\nparameters: {m: {value: 0.5}, L: {value: 0.25}, "
                                   "Jr: {value: -0.002}}\ncoordinates: [x, th]\n"
                                   "frames: {rotor: {rotations: [[z, th]]}}\nbodies:\n"
                                   "  bob: {mass: m, position: [x, -sqrt(L**2 - x**2), 0], frame: rotor, "
                                   "inertia: [0.001, 0.001, Jr]}\n")
    assert result.exit_code == 1
    assert "error: mass_matrix: M is not positive definite at the sample state" in result.stderr


def test_an_empty_bodies_mapping_is_said_to_be_empty(tmp_path: Path):
    """It said 'expected a mapping of named bodies, found a mapping'."""
    path, result = _checked(tmp_path, "gacli: 1\nname: h\nparameters: {m: {value: 1}}\ncoordinates: [x]\nbodies: {}\n")
    assert f"{path}:5:9: error: bodies: expected a mapping of named bodies, found an empty mapping" in result.stderr
