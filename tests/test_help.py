"""`--help` as a newcomer meets it: whole sentences, plain metavars, and an example that runs."""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from conftest import ROOT
from gacli.cli import app

COMMANDS = [c.name or c.callback.__name__ for c in app.registered_commands]


def help_text(*command: str) -> str:
    result = CliRunner().invoke(app, [*command, "--help"], env={"COLUMNS": "80"})
    assert result.exit_code == 0, result.output
    return result.output


def example(*command: str) -> str:
    """The command line a help page ends with."""
    lines = help_text(*command).rstrip().splitlines()
    assert lines[-2] == "Example:", lines[-3:]
    return lines[-1].strip()


def test_the_commands_are_all_there():
    assert COMMANDS == ["derive", "gibbs", "check", "schema", "simulate", "linearize", "verify", "sweep", "steady",
                        "integrals"]


def test_each_summary_is_a_whole_sentence():
    listing = help_text().split("Commands:")[1].split("Example:")[0]
    summaries = dict(line.split(None, 1) for line in listing.strip().splitlines())
    assert sorted(summaries) == sorted(COMMANDS)
    for name, summary in summaries.items():
        # Click cuts a summary at its first full stop or with "...": neither may happen.
        assert summary.endswith(".") and not summary.endswith("..."), (name, summary)
        assert summary.count(". ") == 0, (name, summary)


@pytest.mark.parametrize("command", [(), *[(c,) for c in COMMANDS]])
def test_no_python_type_names_leak_into_help(command):
    text = help_text(*command)
    leaks = re.findall(r"<[a-z][a-z_\[\] |,]*>|\{[a-z_]+\}", text)
    assert not leaks, leaks


@pytest.mark.parametrize("command", [(), *[(c,) for c in COMMANDS]])
def test_help_ends_with_its_example(command):
    assert example(*command).startswith("gacli " + (command[0] if command else ""))


@pytest.fixture
def workdir(tmp_path):
    """A scratch copy of the repository's systems/ and schema/, so examples may write freely."""
    for name in ("systems", "schema"):
        shutil.copytree(ROOT / name, tmp_path / name)
    return tmp_path


def run_as_written(line: str, cwd) -> subprocess.CompletedProcess:
    """``line`` through a shell, with ``gacli`` this checkout's ``python -m gacli``."""
    assert line.startswith("gacli ")
    command = f"{shlex.quote(sys.executable)} -m gacli {line[len('gacli '):]}"
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run(command, shell=True, cwd=cwd, env=env, capture_output=True, text=True, timeout=600)


@pytest.mark.parametrize("command", [(), *[(c,) for c in COMMANDS]])
def test_each_help_example_runs_as_written(command, workdir):
    if command == ("simulate",):
        pytest.importorskip("scipy")
    line = example(*command)
    done = run_as_written(line, workdir)
    assert done.returncode == 0, (line, done.stdout[-2000:], done.stderr[-2000:])
    assert "Traceback" not in done.stderr


def test_linearize_option_examples_fit_the_example_file(workdir):
    """The quoted values in linearize's option help are names of one file: the example's."""
    text = help_text("linearize")
    values = {option: re.search(rf"{option} .*?\"([^\"]+)\"", text, re.S).group(1)
              for option in ("--at", "--set", "--states")}
    line = example("linearize").split(" --")[0] + "".join(f' {o} "{v}"' for o, v in values.items())
    done = run_as_written(line, workdir)
    assert done.returncode == 0, (line, done.stderr)


def test_a_wrong_format_lists_the_choices():
    from gacli.emit import EMITTERS

    result = CliRunner().invoke(app, ["derive", str(ROOT / "systems" / "rolling_disk.yaml"), "--format", "pdf"])
    assert result.exit_code == 2
    choices = ", ".join(sorted(["text", *EMITTERS]))
    assert f"'pdf' is not a format; choose one of: {choices}" in result.output
    assert "Value error" not in result.output


def test_a_wrong_check_format_lists_the_choices():
    result = CliRunner().invoke(app, ["check", str(ROOT / "systems"), "--format", "xml"])
    assert result.exit_code == 2
    assert "'xml' is not a check format; choose one of: github, json, text" in result.output
