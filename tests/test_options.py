"""Option strings of ``linearize`` and ``simulate``: one strict parser, usage errors, numeric corners.

Duplicates, unknown names and conflicts are usage errors (exit 2); a file
that divides by a rate is one located error; ``abs`` of a rate is
differentiated (compared with the derivative worked by hand); ``--points`` is
bounded; library warnings are gacli notes.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from gacli.cli import app
from gacli.simulate.spec import MAX_POINTS, MAX_VALUES, OptionError, parse_assignments, state_names

ROOT = Path(__file__).resolve().parent.parent
CYLINDER = ROOT / "systems" / "cylinder_in_cylinder.yaml"
TEXT = CYLINDER.read_text(encoding="utf-8")
M, G, C = 1.0, 9.81, 0.4   # the file's M, g and c = b - a


def run(*args: str):
    return CliRunner().invoke(app, [*args])


def usage_error(result, *parts: str) -> None:
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    for part in parts:
        assert part in result.output, result.output


def with_load(tmp_path: Path, force: str) -> Path:
    path = tmp_path / "loaded.yaml"
    path.write_text(TEXT.replace("potential: -M*g*c*cos(theta)",
                                 f"potential: -M*g*c*cos(theta)\nloads:\n  - {{force: [{force}, 0], at: cylinder}}"),
                    encoding="utf-8")
    return path


# -- the parser ---------------------------------------------------------------------------------

def test_the_parser_writes_names_as_gacli_does_and_refuses_them_twice():
    assert parse_assignments("x=1, dot( x )=2") == [("x", "1"), ("dot(x)", "2")]
    assert state_names("x, dot( y )") == ["x", "dot(y)"]
    for call in (lambda: parse_assignments("x=1,x=2", "--at"), lambda: parse_assignments("dot(x)=1,dot( x )=2"),
                 lambda: state_names("x,x", "--states"), lambda: parse_assignments("x", "--at")):
        with pytest.raises(OptionError):
            call()


# -- linearize ------------------------------------------------------------------------------

@pytest.mark.parametrize("options, message", [
    (["--at", "theta=1,theta=2"], "'theta' given twice"),
    (["--at", "x=1,x=2"], "'x' given twice"),
    (["--at", "lean=1"], "not a state or input: lean"),
    (["--states", "theta,theta"], "'theta' given twice"),
    (["--states", "theta,dot(lean)"], "not in the state: dot(lean)"),
    (["--set", "g=1,g=2"], "'g' given twice"),
    (["--symbolic", "--sweep", "theta=0:1"], "--sweep computes eigenvalues numerically"),
    (["--symbolic", "--at", "lean=0"], "not a state or input: lean"),
    (["--at", "theta"], "expected name=value"),
    # The swept value given too was dropped without a word.
    (["--sweep", "theta=0:1", "--at", "theta=0.5"], "theta takes the sweep's values; leave it out of --at"),
    (["--sweep", "g=1:2", "--set", "g=3"], "g takes the sweep's values; leave it out of --set"),
])
def test_linearize_usage_errors(options, message):
    usage_error(run("linearize", str(CYLINDER), *options), message)


def test_symbolic_takes_the_operating_point():
    """θ'' = −(2g/3c) sin θ for the cylinder (eq. 14.30's pendulum): ∂θ''/∂θ = −(2g/3c) cos θ₀."""
    result = run("linearize", str(CYLINDER), "--symbolic", "--at", "theta=pi/3", "--states", "theta,dot(theta)")
    assert result.exit_code == 0, result.output
    lines = result.output.strip().splitlines()
    assert lines[0] == "A =" and lines[1].split() == ["theta", "dot(theta)"]   # rows and columns named
    assert lines[2].split() == ["theta", "0", "1"] and lines[3].split() == ["dot(theta)", "-g/(3*c)", "0"]


def _entry(output: str, row: str, column: int) -> float:
    line = next(line for line in output.splitlines() if line.startswith(row + " "))
    return float(line.split()[column + 1])


@pytest.mark.parametrize("w0", [2.0, -0.5, 0.0])
def test_abs_of_a_rate_is_differentiated(tmp_path, w0):
    """F = −|θ'|θ' at the centre: Q_θ = F c cos θ, M_θθ = 3/2 M c², so ∂θ''/∂θ' = −2|θ'₀| / (3/2 M c) at θ = 0."""
    path = with_load(tmp_path, "-abs(dot(theta))*dot(theta)")
    result = run("linearize", str(path), "--at", f"dot(theta)={w0}", "--states", "theta,dot(theta)")
    assert result.exit_code == 0, result.output
    np.testing.assert_allclose(_entry(result.output, "dot(theta)", 1), -2 * abs(w0) / (1.5 * M * C),
                               rtol=1e-9, atol=1e-12)  # printed to 10 digits
    np.testing.assert_allclose(_entry(result.output, "dot(theta)", 0), -2 * G / (3 * C), rtol=1e-9)


@pytest.mark.parametrize("force", ["1/dot(theta)", "dot(theta)**(-1/2)", "log(dot(theta))"])
def test_a_load_undefined_at_the_point_is_one_located_error(tmp_path, force):
    path = with_load(tmp_path, force)
    line = next(i for i, text in enumerate(path.read_text().splitlines(), 1) if "force:" in text)
    for symbolic in ((), ("--symbolic",)):
        result = run("linearize", str(path), *symbolic)
        assert result.exit_code == 1, result.output
        assert "Traceback" not in result.output
        assert re.search(rf"^{re.escape(str(path))}:{line}:\d+: error: linearize: ", result.stderr, re.M), result.stderr
    assert run("linearize", str(path), "--at", "dot(theta)=1").exit_code == 0


# -- simulate -----------------------------------------------------------------------------------

@pytest.mark.parametrize("options, message", [
    (["--points", str(MAX_POINTS + 1)], "--points: at most 1,000,000"),
    (["--points", "100000000"], "--points: at most 1,000,000"),
    (["--set", "a=1", "--set", "a=2"], "'a' is given twice"),
    (["--set", "a=1,a=2"], "'a' given twice"),
    (["--init", "foo=1"], "'foo' is not in the state"),
    (["--show", "theta,theta"], "'theta' given twice"),
    (["--phase", "theta"], "--phase: expected two state names"),
    (["--function", "x=1"], "is not a free function"),
])
def test_simulate_usage_errors(options, message):
    pytest.importorskip("scipy")
    usage_error(run("simulate", str(CYLINDER), "--t-end", "0.01", *options), message)


def test_simulate_bounds_the_values_it_keeps(monkeypatch):
    """points x state entries is bounded too (a wide system); shown with a small bound and three entries."""
    pytest.importorskip("scipy")
    assert MAX_VALUES * 8 <= 100 * 2**20  # a copy of the path stays under 100 MiB
    monkeypatch.setattr("gacli.simulate.values.MAX_VALUES", 30)
    usage_error(run("simulate", str(CYLINDER), "--t-end", "0.01", "--points", "11"),
                "11 samples of 3 state entries exceed 30 values; at most 10 samples for this system")
    assert run("simulate", str(CYLINDER), "--t-end", "0.01", "--points", "10").exit_code == 0


def test_library_warnings_are_gacli_notes():
    pytest.importorskip("scipy")
    # In a process of its own, as a user runs it: in one shared with earlier tests (the wheelchair's
    # reactions under xdist) this run took past its 120 s budget; see the session note.
    import subprocess
    import sys

    result = subprocess.run([sys.executable, "-m", "gacli", "simulate", str(CYLINDER), "--init", "dot(theta)=1e200",
                             "--t-end", "0.1", "--points", "3"], capture_output=True, text=True, timeout=300)
    assert result.returncode == 1
    notes = [line for line in result.stderr.splitlines() if "Warning" in line]
    assert notes and all(line.startswith("note: ") for line in notes), result.stderr
    assert "site-packages" not in result.stderr and "warnings.warn" not in result.stderr
    assert len(notes) == len(set(notes)) <= 6
