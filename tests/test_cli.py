"""The command line: exit codes, streams, help, and what it must never do."""

from __future__ import annotations

import subprocess
import sys

import pytest
from typer.testing import CliRunner

from conftest import SYSTEMS
from gacli import __version__
from gacli.cli import FORMATS, app

SPHERE = str(SYSTEMS / "sphere_on_turntable.yaml")


def run(*args):
    return CliRunner().invoke(app, list(args))


def test_version():
    result = run("--version")
    assert result.exit_code == 0
    assert result.output.strip() == f"gacli {__version__}"


@pytest.mark.parametrize("command", ["derive", "gibbs", "simulate", "check", "schema", "linearize", "verify"])
def test_every_command_help_has_a_working_example(command):
    result = run(command, "--help")
    assert result.exit_code == 0
    assert "Example:\n  gacli " + command in result.output


def test_derive_prints_the_chapter_steps():
    result = run("derive", SPHERE)
    assert result.exit_code == 0, result.output
    for heading in ("Degrees of freedom", "eq. (14.7)", "Gibbs function", "eq. (14.13)", "eq. (14.19)", "eq. (14.20)"):
        assert heading in result.output
    assert "k = n + p - d - l = 2 + 3 - 0 - 2 = 3" in result.output
    assert "Q_x = F_x + M_y/a" in result.output


def test_gibbs_prints_g_alone():
    result = run("gibbs", str(SYSTEMS / "cylinder_in_cylinder.yaml"))
    assert result.exit_code == 0, result.output
    assert "G = 3*M*c**2*ddot(theta)**2/4 + ..." in result.output
    assert "eq. (14.19)" not in result.output


def test_invalid_file_exits_1_with_location_on_stderr(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("gacli: 1\nname: bad\ncoordinates: [x]\nbodies: {p: {mass: m, position: [x, 0]}}\n")
    result = CliRunner().invoke(app, ["derive", str(bad)])
    assert result.exit_code == 1
    assert f"{bad}:4:20: error: bodies.p.mass: 'm' is not declared" in result.stderr
    assert result.stdout == ""
    assert "Traceback" not in result.output


def test_missing_file_is_a_usage_error(tmp_path):
    result = run("derive", str(tmp_path / "nope.yaml"))
    assert result.exit_code == 2


def test_unknown_format_is_a_usage_error():
    result = run("derive", SPHERE, "--format", "fortran")
    assert result.exit_code == 2


def test_standalone_without_latex_is_a_usage_error_as_steps_and_reactions_are():
    result = run("derive", SPHERE, "--format", "python", "--standalone")
    assert result.exit_code == 2
    assert "--standalone goes with --format latex" in result.output


def test_existing_output_untouched_on_error(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("gacli: 1\nname: bad\n")
    target = tmp_path / "out.py"
    target.write_text("precious\n")
    result = run("derive", str(bad), "--format", "python", "--output", str(target))
    assert result.exit_code == 1
    assert target.read_text() == "precious\n"


def test_formats_match_the_emitter_registry():
    from gacli.emit import EMITTERS

    assert set(FORMATS) == {"text", *EMITTERS}


def test_module_entry_point_and_lazy_imports():
    """`python -m gacli --help` works and does not import SymPy."""
    code = (
        "import sys, runpy\n"
        "sys.argv = ['gacli', '--help']\n"
        "try:\n    runpy.run_module('gacli', run_name='__main__')\n"
        "except SystemExit as e:\n    assert e.code in (0, None), e.code\n"
        "print('SYMPY' if 'sympy' in sys.modules else 'LEAN')\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert "Usage" in out
    assert out.strip().endswith("LEAN")


def test_public_api_is_sorted_and_complete():
    import gacli

    assert gacli.__all__ == sorted(gacli.__all__)
    for name in gacli.__all__:
        assert getattr(gacli, name) is not None


def test_methods_match_the_simulator():
    from gacli.cli import METHODS
    from gacli.simulate import METHODS as SIMULATOR

    assert tuple(METHODS) == tuple(SIMULATOR)


def test_simulate_command(tmp_path):
    pytest.importorskip("scipy")
    csv = tmp_path / "run.csv"
    result = run("simulate", str(SYSTEMS / "cylinder_in_cylinder.yaml"), "--init", "theta=0.1",
                 "--t-end", "1", "--csv", str(csv))
    assert result.exit_code == 0, result.output
    assert csv.read_text().splitlines()[0] == "t,theta,phi,dot(theta)"
    missing = run("simulate", SPHERE, "--t-end", "1")
    assert missing.exit_code == 1
    assert "Traceback" not in missing.output


def test_output_files_get_ordinary_permissions(tmp_path):
    import os
    import stat

    target = tmp_path / "cyl.py"
    result = run("derive", str(SYSTEMS / "cylinder_in_cylinder.yaml"), "--format", "python", "--output", str(target))
    assert result.exit_code == 0, result.output
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(target.stat().st_mode) == 0o666 & ~umask


def test_verify_reactions_and_check_verify():
    result = run("verify", SPHERE, "--samples", "3")
    assert result.exit_code == 0, result.output
    assert "verify: passed" in result.output
    reactions = run("derive", SPHERE, "--reactions")
    assert reactions.exit_code == 0 and "lambda_0 = " in reactions.output
    checked = run("check", "--verify", str(SYSTEMS / "cylinder_in_cylinder.yaml"))
    assert checked.exit_code == 0, checked.output


@pytest.mark.skipif(not __import__("os").path.exists("/dev/full"), reason="needs /dev/full")
@pytest.mark.parametrize("args", [["derive", str(SYSTEMS / "particle_in_plane.yaml")], ["--version"], ["schema"]],
                         ids=lambda a: a[0])
def test_a_full_standard_output_is_one_line_not_a_traceback(args):
    # `gacli derive f.yaml > /dev/full` ended in a rich traceback (OSError: No space left on device).
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    with open("/dev/full", "w") as full:
        done = subprocess.run([sys.executable, "-m", "gacli", *args], stdout=full, stderr=subprocess.PIPE,
                              text=True, timeout=120, cwd=root)
    assert done.returncode == 1
    assert done.stderr.strip().splitlines()[-1] == "error: stdout: No space left on device", done.stderr
    assert "Traceback" not in done.stderr


def test_a_reader_that_stops_early_ends_the_command_quietly():
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    done = subprocess.run(f"{sys.executable} -m gacli derive {SYSTEMS / 'whipple_bicycle.yaml'} | head -1",
                          shell=True, capture_output=True, text=True, timeout=120, cwd=root)
    assert done.stdout.startswith("Whipple bicycle") and done.stderr == ""
