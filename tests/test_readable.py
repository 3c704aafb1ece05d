"""What is printed for people: the display limit for very large equations."""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from conftest import LARGE, SYSTEMS, derived
from gacli.cli import app
from gacli.algebra.readable import TOO_LARGE, displayable

ALL = sorted(p.stem for p in SYSTEMS.glob("*.yaml"))


@pytest.mark.parametrize("name", ALL)
def test_only_the_listed_systems_are_too_large_to_display(name):
    assert displayable(derived(name)) == (name not in LARGE)


@pytest.mark.parametrize("args", [["derive"], ["derive", "--steps"], ["gibbs"], ["derive", "--format", "latex"]])
def test_a_large_system_says_so_instead_of_printing(args):
    name = "whipple_bicycle"
    result = CliRunner().invoke(app, [args[0], str(SYSTEMS / f"{name}.yaml"), *args[1:]])
    assert result.exit_code == 0, result.output
    text = " ".join(result.output.split()).replace("-{}-", "--")  # as LaTeX writes --
    assert "--format python or --format c" in text
    assert len(result.output) < 5_000
    if args == ["derive"]:
        assert "k = n + p - d - l = 8 + 0 - 0 - 5 = 3" in text


def test_the_note_names_the_limit():
    assert "20,000" in TOO_LARGE


def test_reactions_of_a_large_system_are_computed_by_the_generated_code(tmp_path):
    bicycle = str(SYSTEMS / "whipple_bicycle.yaml")
    text = CliRunner().invoke(app, ["derive", bicycle, "--reactions"])
    assert text.exit_code == 0 and "--format python or --format c with --reactions" in " ".join(text.output.split())
    target = tmp_path / "bicycle.py"
    code = CliRunner().invoke(app, ["derive", bicycle, "--format", "python", "--reactions", "--output", str(target)])
    assert code.exit_code == 0, code.output
    assert "numpy.linalg.solve(_K, _b)" in target.read_text()


def test_symbolic_linearization_of_a_large_system_is_refused_clearly():
    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "whipple_bicycle.yaml"), "--symbolic"])
    assert result.exit_code != 0 and "leave out --symbolic" in " ".join(result.output.split())
    assert "Traceback" not in result.output


def test_a_latex_fragment_of_a_large_system_shows_the_note_as_text():
    # Every other line of a fragment's note is a % comment; this one must reach the page of an \input.
    result = CliRunner().invoke(app, ["derive", str(SYSTEMS / "whipple_bicycle.yaml"), "--format", "latex"])
    shown = [line for line in result.output.splitlines() if line and not line.startswith("%")]
    assert any("too large to print" in line for line in shown), result.output


# -- compact equations (issue: equations a reader can read) ---------------------

CASES = SYSTEMS.parent / "tests" / "cases"
# Vocabulary files with a hand-written format-1 twin in tests/cases.
TWINS = {"rolling_disk": "rolling_disk_format1"}


def _printed(path) -> str:
    result = CliRunner().invoke(app, ["derive", str(path)])
    assert result.exit_code == 0, result.output
    return result.output


@pytest.mark.parametrize("name", [n for n in ALL if n not in LARGE])
def test_printed_equations_are_as_compact_as_by_hand(name):
    text = _printed(SYSTEMS / f"{name}.yaml")
    if name in TWINS:
        assert len(text) <= 1.5 * len(_printed(CASES / f"{TWINS[name]}.yaml"))
    else:
        assert len(text) < 5_000


def test_the_rolling_disk_forcing_has_few_operations():
    import sympy as sp

    d = derived("rolling_disk")
    assert all(sp.count_ops(f) <= 40 for f in d.forcing)
    # Yaw and spin drop out of a disk symmetric in both, as by hand.
    names = {str(s) for e in (*d.mass_matrix, *d.forcing) for s in e.free_symbols}
    assert not names & {"yaw", "spin"}


def test_abs_and_sign_print_as_written_never_as_piecewise(tmp_path):
    path = tmp_path / "friction.yaml"
    path.write_text("gacli: 1\nname: friction\nparameters: [m, k, c]\ncoordinates: [x]\n"
                    "bodies: {b: {mass: m, position: [x, 0, 0]}}\n"
                    "potential: k*x**2/2 + c*abs(x)\n", encoding="utf-8")
    text = _printed(path)
    assert "Piecewise" not in text and "Abs" not in text
    assert "sign(x)" in text


def test_loads_are_not_printed_on_the_left_of_an_equation():
    # Q − F is free of the loads; as formed, Q's terms and F's copy of them meet only multiplied out.
    result = CliRunner().invoke(app, ["derive", str(SYSTEMS.parent / "tests" / "frames" / "spherical_robot.yaml")])
    lines = [line for line in result.output.splitlines() if "dG/d(" in line]
    assert len(lines) == 5
    for line in lines:
        left = line.split(": ", 1)[1].split(" = ")[0]
        assert "M_1" not in left and "M_2" not in left, line
