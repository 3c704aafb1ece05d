"""The command line as a newcomer meets it: the shipped files, the check table, the counts, the messages."""

from __future__ import annotations

import json
import os

import pytest
from rich.console import Console
from typer.testing import CliRunner

from conftest import SYSTEMS
from gacli.cli import app


def invoke(*args: str):
    return CliRunner().invoke(app, list(args))


SHIPPED = sorted(SYSTEMS.glob("*.yaml"))


@pytest.mark.parametrize("path", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_every_shipped_file_passes_the_strictest_gate(path):
    """What `gacli check --help` advertises must hold for the repository's own files."""
    result = invoke("check", str(path), "--strict", "--format", "github")
    assert result.exit_code == 0, result.output
    assert "::warning" not in result.stdout and "::error" not in result.stdout


# -- the check table at 80 columns ---------------------------------------------------------------

@pytest.fixture(scope="module")
def report():
    """Four shipped files, named as `gacli check systems/` names them: the longest name is 32 characters."""
    from gacli.check import check_paths

    names = ("chaplygin_sleigh", "differential_drive", "sphere_on_turntable", "cylinder_in_cylinder")
    here = os.getcwd()
    os.chdir(SYSTEMS.parent)
    try:
        return check_paths([f"systems/{n}.yaml" for n in names], timeout=120)
    finally:
        os.chdir(here)


def render(report, width: int) -> str:
    from gacli.check.console import _table

    console = Console(width=width, record=True, color_system=None)
    console.print(_table(report, console.width))
    return console.export_text()


def test_at_80_columns_file_names_stay_whole_and_headers_full(report):
    text = render(report, 80)
    lines = text.splitlines()
    assert max(map(len, lines)) <= 80, text
    assert lines[0].split() == ["file", "result", "independent", "constraints", "time"], text
    for file in report.files:
        assert any(line.startswith(file.path + " ") for line in lines), (file.path, text)
    assert "…" not in text


def test_the_table_uses_the_room_it_has(report):
    wide = render(report, 200)
    assert "4 non-holonomic (4 rows, rank 3: constraints[3] repeats the others)" in wide


# -- derive and check agree on the constraint count ------------------------------------------------

RANK_NOTE = "4 rows, rank 3: constraints[3] repeats the others"


def test_derive_says_why_l_is_less_than_the_rows():
    result = invoke("derive", str(SYSTEMS / "differential_drive.yaml"))
    assert result.exit_code == 0, result.output
    assert f"l = 3 constraints ({RANK_NOTE})" in result.stdout


def test_check_says_the_same(report):
    drive = next(f for f in report.files if f.path.endswith("differential_drive.yaml"))
    assert drive.dependent == ("constraints[3]",)
    assert len([c for c in drive.classifications if c.kind == "constraint"]) == 4
    assert RANK_NOTE in render(report, 200)
    from gacli.check import to_json

    assert json.loads(to_json(report))["files"][1]["dependent"] == ["constraints[3]"]


def test_no_explanation_when_every_row_counts():
    result = invoke("derive", str(SYSTEMS / "sphere_on_turntable.yaml"))
    assert "l = 2 constraints\n" in result.stdout


# -- messages --------------------------------------------------------------------------------------

SPHERE = str(SYSTEMS / "sphere_on_turntable.yaml")
AT_REST = "F_x=0,F_y=0,F_z=0,M_x=0,M_y=0,M_z=0"


def test_several_problems_are_several_lines_not_a_literal_backslash_n():
    pytest.importorskip("scipy")
    result = invoke("simulate", SPHERE, "--input", AT_REST, "--function", "Om=2", "--t-end", "0.1")
    assert result.exit_code == 2  # an unknown name is a usage error (issue 33)
    assert "\\n" not in result.stderr, result.stderr
    lines = result.stderr.splitlines()
    assert lines[0] == "error: 2 problems with the simulation:", result.stderr
    assert lines[1].startswith("  --function Om: ") and lines[2].startswith("  free function 'Omega' has no value")


@pytest.mark.parametrize(("written", "meant"), [
    ("xdot", "dot(x)"), ("x_dot", "dot(x)"), ("ydot", "dot(y)"), ("dx", "dot(x)"), ("q_zdot", "dot(q_z)"),
    ("X", "x"), ("dot(X)", "dot(x)"),
])
def test_a_wrong_state_name_suggests_the_one_meant(written, meant):
    pytest.importorskip("scipy")
    result = invoke("simulate", SPHERE, "--input", AT_REST, "--function", "Omega=2", "--init", f"{written}=0.1",
                    "--t-end", "0.1")
    assert result.exit_code == 2  # an unknown name is a usage error (issue 33)
    assert f"(did you mean '{meant}'?)" in result.stderr, result.stderr


def test_a_report_stopped_before_classifying_still_renders():
    from gacli.check import CheckReport, FileReport

    stopped = FileReport(path="systems/differential_drive.yaml", k=2, independent=("phi_L", "phi_R"),
                         dependent=("constraints[3]",))
    assert "systems/differential_drive.yaml" in render(CheckReport((stopped,)), 80)


def test_a_wrong_method_lists_the_choices():
    result = invoke("simulate", SPHERE, "--method", "euler")
    assert result.exit_code == 2
    assert "'euler' is not a method; choose one of: BDF, DOP853, LSODA, RK23, RK45, Radau" in result.output


def test_a_newline_inside_one_problem_stays_escaped(capsys):
    from gacli.display import console

    console.error("2 problems:", ["one\nerror: forged", "two"])
    err = capsys.readouterr().err
    assert err.splitlines() == ["error: 2 problems:", "  one\\nerror: forged", "  two"]
