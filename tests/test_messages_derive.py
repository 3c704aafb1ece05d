"""Messages that say what is true of the file, from derive (issue 33, item 7)."""

from __future__ import annotations

from pathlib import Path

from typer.testing import CliRunner

from gacli.cli import app
from test_check_messages import PENDULUM

# The spherical pendulum of test_check_messages, its parameters without values.
SPHERICAL = PENDULUM.replace(": {value: VALUE}", ": {}")


def test_an_equation_that_reads_0_eq_0_is_explained(tmp_path: Path):
    path = tmp_path / "spherical.yaml"
    path.write_text(SPHERICAL, encoding="utf-8")
    result = CliRunner().invoke(app, ["derive", str(path)])
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    at = next(i for i, line in enumerate(lines) if line.strip() == "dG/d(ddot(q3)): 0 = 0")
    assert "M is singular" in lines[at + 1] and "ddot(q3)" in lines[at + 1]
    assert sum("M is singular" in line for line in lines) == 1  # q1 and q2 have their equations


def test_a_tiny_axle_is_not_called_the_zero_vector(tmp_path: Path):
    root = Path(__file__).resolve().parent.parent
    text = (root / "systems" / "rolling_disk.yaml").read_text(encoding="utf-8")
    assert "axle: [0, 1, 0]" in text
    for axle, words in (("[0, 1e-7, 0]", "too short to give a direction"), ("[0, 0, 0]", "the zero vector")):
        path = tmp_path / "disk.yaml"
        path.write_text(text.replace("axle: [0, 1, 0]", f"axle: {axle}"), encoding="utf-8")
        result = CliRunner().invoke(app, ["check", str(path)])
        assert result.exit_code == 1
        assert words in result.stderr


def test_every_command_has_one_default_budget():
    from gacli import budget, cli, cli_sweep
    from gacli.check import DEFAULT_TIMEOUT as CHECK

    assert cli.DEFAULT_TIMEOUT == budget.DEFAULT_TIMEOUT == CHECK == cli_sweep.DEFAULT_TIMEOUT
    for command in ("check", "derive", "gibbs", "verify", "simulate", "linearize", "sweep"):
        result = CliRunner().invoke(app, [command, "--help"], terminal_width=200)
        assert result.exit_code == 0
        options = {p.name: p.default for p in next(c for c in _commands() if c.name == command).params}
        assert options["timeout"] == budget.DEFAULT_TIMEOUT, command


def _commands():
    import typer.main

    return typer.main.get_command(app).commands.values()
