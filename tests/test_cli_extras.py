"""The edges of the command line (issue #32): -V, shell completion, derive's text report written with --output."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from conftest import ROOT, SYSTEMS
from gacli.cli import app

CYLINDER = str(SYSTEMS / "cylinder_in_cylinder.yaml")


def invoke(*args: str):
    return CliRunner().invoke(app, list(args))


@pytest.mark.parametrize("flag", ["--version", "-V"])
def test_version_flags_print_the_packages_version(flag):
    from importlib.metadata import PackageNotFoundError, version

    result = invoke(flag)
    assert result.exit_code == 0
    assert result.output == f"gacli {__import__('gacli.version').version.__version__}\n"
    try:  # the installed distribution, when there is one, says the same
        installed = version("gacli")
    except PackageNotFoundError:
        return
    assert result.output.split()[1] == installed


def test_shell_completion_is_offered_as_the_docs_say():
    help_text = invoke("--help").output
    assert "--install-completion" in help_text and "--show-completion" in help_text
    env = {**os.environ, "PYTHONPATH": str(ROOT), "_TYPER_COMPLETE_TEST_DISABLE_SHELL_DETECTION": "1"}
    done = subprocess.run([sys.executable, "-m", "gacli", "--show-completion", "bash"], capture_output=True,
                          text=True, env=env, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "complete" in done.stdout and "_COMPLETE" in done.stdout


@pytest.fixture(scope="module")
def printed():
    result = invoke("derive", CYLINDER)
    assert result.exit_code == 0
    return result.output


def test_text_report_goes_to_a_named_file_as_printed(tmp_path, printed):
    target = tmp_path / "report.txt"
    result = invoke("derive", CYLINDER, "--output", str(target))
    assert result.exit_code == 0, result.output
    assert target.read_text(encoding="utf-8") == printed
    assert printed.startswith("Cylinder rolling without slipping inside a fixed cylinder\n")


def test_text_report_goes_into_an_existing_directory_as_name_txt(tmp_path, printed):
    result = invoke("derive", CYLINDER, "--output", str(tmp_path))
    assert result.exit_code == 0, result.output
    assert (tmp_path / "cylinder_in_cylinder.txt").read_text(encoding="utf-8") == printed


def test_an_existing_report_is_untouched_when_the_derivation_fails(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("gacli: 1\nname: bad\n")
    target = tmp_path / "report.txt"
    target.write_text("precious\n")
    result = invoke("derive", str(bad), "--output", str(target))
    assert result.exit_code == 1
    assert target.read_text() == "precious\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.yaml", "report.txt"]  # no temporary left
