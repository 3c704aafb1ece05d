"""``gacli check``: exit codes, formats, warnings, the time budget, and mutated system files."""

from __future__ import annotations

import json
import re
import shutil
import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from gacli.check import (
    STEP_CLASSIFY, STEP_LOAD, STEP_MASS, STEP_READ, CheckReport, FileReport, PathsError,
    check_file, check_paths, expand_paths, to_github, to_json,
)
from gacli.read.textsafe import printable
from gacli.cli import app
from gacli.mechanics.equations import derive
from gacli.errors import Diagnostic, Location
from gacli.loader.loading import load

ROOT = Path(__file__).resolve().parent.parent
SYSTEMS = ROOT / "systems"

GOOD = """\
gacli: 1
name: pendulum
parameters:
  m: {value: 1}
  l: {value: 2}
  g: {value: 9.81}
coordinates: [theta]
bodies:
  bob: {mass: m, position: [l*sin(theta), -l*cos(theta)]}
potential: -m*g*l*cos(theta)
"""


def invoke(*args: str):
    return CliRunner().invoke(app, ["check", *args])


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


# -- exit codes ------------------------------------------------------------------------

def test_the_shipped_systems_pass():
    result = invoke(str(SYSTEMS))
    assert result.exit_code == 0, result.output
    shipped = sorted(SYSTEMS.glob("*.yaml"))
    for path in shipped:
        assert path.name in result.stdout
    assert f"all {len(shipped)} files passed" in result.stdout
    assert "Traceback" not in result.output


def test_a_good_file_passes(tmp_path):
    result = invoke(str(write(tmp_path, "good.yaml", GOOD)))
    assert result.exit_code == 0, result.output
    assert result.stderr == ""


@pytest.mark.parametrize("args", [["no/such/file.yaml"], ["nothing-*.yaml"], [], ["--bogus", "x.yaml"],
                                  ["--format", "xml", "x.yaml"], ["--timeout", "-1", "x.yaml"]])
def test_usage_errors_exit_2(args, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = invoke(*args)
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output


def test_a_missing_path_is_named(tmp_path):
    good = write(tmp_path, "good.yaml", GOOD)
    result = invoke(str(good), str(tmp_path / "missing.yaml"))
    assert result.exit_code == 2
    assert "missing.yaml" in result.output


def test_a_folder_without_system_files_is_a_usage_error(tmp_path):
    write(tmp_path, "notes.txt", "hello")
    result = invoke(str(tmp_path))
    assert result.exit_code == 2, result.output
    assert "no system files" in result.output


# -- many files, each format ---------------------------------------------------------------

@pytest.fixture
def mixed(tmp_path) -> tuple[Path, set[str]]:
    """A folder of two good files and three bad ones (one nested, one .yml)."""
    shutil.copy(SYSTEMS / "cylinder_in_cylinder.yaml", tmp_path / "a_good.yaml")
    write(tmp_path, "sub/b_good.yml", GOOD)
    bad = {
        write(tmp_path, "c_bad.yaml", GOOD.replace("mass: m", "mass: mass")),
        write(tmp_path, "sub/d_bad.yml", GOOD.replace("gacli: 1", "gacli: 7")),
        write(tmp_path, "sub/deeper/e_bad.yaml", GOOD + "extra: 1\n"),
    }
    write(tmp_path, "sub/workflow.yml", "name: ci\non: push\n")  # not a gacli file: skipped, counted
    write(tmp_path, ".hidden/f_bad.yaml", "- skipped: hidden folders are not searched\n")
    write(tmp_path, "notes.txt", "not YAML at all")
    return tmp_path, {str(p) for p in bad}


def test_json_reports_exactly_the_bad_files(mixed):
    folder, bad = mixed
    result = invoke("--format", "json", str(folder))
    assert result.exit_code == 1, result.output
    report = json.loads(result.stdout)
    assert report["exit_code"] == 1
    assert {f["path"] for f in report["files"] if f["failed"]} == bad
    assert len(report["files"]) == 5
    assert report["summary"] == {"files": 5, "failed": 3, "errors": 3, "warnings": 0, "notes": 0, "skipped": 1}
    assert report["skipped"] == [{"path": str(folder / "sub" / "workflow.yml"),
                                  "reason": "not a gacli file (no top-level 'gacli:' key)"}]
    for file in report["files"]:
        for d in file["diagnostics"]:
            assert d["line"] >= 1 and d["column"] >= 1 and d["path"] == file["path"]


def test_github_reports_exactly_the_bad_files(mixed):
    folder, bad = mixed
    result = invoke("--format", "github", str(folder))
    assert result.exit_code == 1, result.output
    *lines, skipped = result.stdout.splitlines()
    assert skipped == "::notice title=gacli check::skipped 1 file (not a gacli file: 1)"
    assert all(re.match(r"::(error|warning) file=[^,]+,line=\d+,col=\d+,title=gacli check::.+", line)
               for line in lines), lines
    assert {re.match(r"::error file=([^,]+),", line)[1] for line in lines} == bad


def test_text_reports_bad_files_on_stderr_and_a_table_on_stdout(mixed):
    folder, bad = mixed
    result = invoke(str(folder))
    assert result.exit_code == 1
    assert {line.split(":")[0] for line in result.stderr.splitlines()} == bad
    assert "3 of 5 files failed" in result.stdout
    assert "holonomic" in result.stdout  # the cylinder's constraint


def test_files_come_sorted_and_once(mixed):
    folder, _ = mixed
    paths = expand_paths([folder, folder / "c_bad.yaml", str(folder / "sub" / "*.yml")])
    names = [p.relative_to(folder).as_posix() for p in paths]
    assert names == ["a_good.yaml", "c_bad.yaml", "sub/b_good.yml", "sub/d_bad.yml", "sub/deeper/e_bad.yaml"]


def test_a_symlink_out_of_the_folder_is_not_followed(tmp_path):
    outside = write(tmp_path, "outside/secret.yaml", "password: hunter2\n")
    write(tmp_path, "repo/good.yaml", GOOD)
    (tmp_path / "repo" / "leak.yaml").symlink_to(outside)
    assert [p.name for p in expand_paths([tmp_path / "repo"])] == ["good.yaml"]


def test_paths_error_names_every_missing_pattern(tmp_path):
    with pytest.raises(PathsError, match=r"^no such file, directory or match: .*/one\.yaml, .*/two-\*\.yml$"):
        expand_paths([tmp_path / "one.yaml", str(tmp_path / "two-*.yml")])


# -- warnings and --strict -----------------------------------------------------------------

WARNED = GOOD.replace("  g: {value: 9.81}\n", "  g: {value: 9.81}\n  k: {value: 3}\ninputs: [F]\n").replace(
    "coordinates: [theta]", "coordinates: [theta, s]\nconstraints: [ds = l*dtheta]")


def test_warnings_are_shown_and_pass_without_strict(tmp_path):
    path = write(tmp_path, "warned.yaml", WARNED)
    result = invoke(str(path))
    assert result.exit_code == 0, result.output
    warnings = [line for line in result.stderr.splitlines() if ": warning: " in line]
    assert len(warnings) == 2, result.stderr
    assert "parameter 'k' is not used" in result.stderr
    assert "no body depends on coordinate 's'" in result.stderr
    # An unused input is the generated code's interface: a note, never a failure (docs/check.md).
    assert "note: inputs.F: input 'F' is declared but no load uses it" in result.stderr


def test_strict_turns_a_warning_into_a_failure(tmp_path):
    path = write(tmp_path, "warned.yaml", WARNED)
    result = invoke("--strict", "--format", "json", str(path))
    assert result.exit_code == 1, result.output
    assert json.loads(result.stdout)["files"][0]["status"] == "warning"
    assert invoke("--strict", str(write(tmp_path, "good.yaml", GOOD))).exit_code == 0


def test_github_warnings_are_warning_annotations(tmp_path):
    path = write(tmp_path, "warned.yaml", WARNED)
    result = invoke("--format", "github", str(path))
    assert result.exit_code == 0
    levels = sorted(line.split()[0] for line in result.stdout.splitlines())
    assert levels == ["::notice", "::warning", "::warning"], result.stdout


def test_an_unused_input_alone_passes_strict(tmp_path):
    unused_input = GOOD.replace("  g: {value: 9.81}\n", "  g: {value: 9.81}\ninputs: [F]\n")
    path = write(tmp_path, "input.yaml", unused_input)
    result = invoke("--strict", "--format", "json", str(path))
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["summary"]["notes"] == 1 and report["summary"]["warnings"] == 0
    assert report["files"][0]["diagnostics"][0]["severity"] == "note"


# -- sanity of M ----------------------------------------------------------------------------------

def test_a_massless_particle_fails_positive_definiteness(tmp_path):
    path = write(tmp_path, "massless.yaml", GOOD.replace("m: {value: 1}", "m: {value: 0}"))
    report = check_file(path)
    assert report.mass_matrix.positive_definite is False
    assert "M is not positive definite at every state (M is constant)" in report.errors[0].message


def test_positive_definiteness_needs_every_parameter_value(tmp_path):
    path = write(tmp_path, "symbolic.yaml", GOOD.replace("m: {value: 1}", "m: mass of the bob"))
    report = check_file(path)
    assert report.errors == ()
    assert report.mass_matrix.positive_definite is None
    assert report.mass_matrix.note == "not checked: no value for m"
    assert report.mass_matrix.symmetric is True


def test_masses_twelve_decades_apart_are_positive_definite(tmp_path):
    """A satellite's 5e6 beside a wheel's 2e-6: definite whatever the units (generated code's Cholesky
    solves it); a test relative to the largest entry called it not positive definite."""
    path = write(tmp_path, "stiff.yaml", "gacli: 1\nname: stiff\nparameters: {m1: {value: 5e6}, m2: {value: 2e-6}}\n"
                 "coordinates: [x, y]\nbodies:\n  a: {mass: m1, position: [x, 0]}\n  b: {mass: m2, position: [0, y]}\n")
    report = check_file(path)
    assert report.errors == () and report.mass_matrix.positive_definite is True


@pytest.mark.parametrize("written, value", [("1", 1), ("5e6", 5e6), ("-2.5", -2.5), (".5", 0.5), ("1/2", 0.5),
                                            ("2*pi", 6.283185307179586), ("exp(1)", 2.718281828459045)])
def test_a_number_written_for_a_parameter_is_its_value(tmp_path, written, value):
    path = write(tmp_path, "short.yaml", GOOD.replace("m: {value: 1}", f"m: {written}").replace(
        "l: {value: 2}", "l: length of the rod"))
    system = load(path)
    by_name = {p.name: p for p in system.parameters}
    assert float(by_name["m"].value) == pytest.approx(value, rel=1e-15) and by_name["m"].description == ""
    assert by_name["l"].value is None and by_name["l"].description == "length of the rod"


def test_the_shipped_systems_have_symmetric_positive_definite_M():
    for path in sorted(SYSTEMS.glob("*.yaml")):
        report = check_file(path)
        assert report.errors == (), report.errors
        assert report.mass_matrix.symmetric is True
        assert report.mass_matrix.positive_definite is True, path.name
        assert report.mass_matrix.samples == 3


def test_an_undefined_value_in_the_equations_is_an_error(tmp_path):
    path = write(tmp_path, "log0.yaml", GOOD.replace("potential: -m*g*l*cos(theta)", "potential: theta*log(0)"))
    report = check_file(path)
    assert any("undefined or infinite" in d.message for d in report.errors), report.diagnostics


# -- the time budget ------------------------------------------------------------------------

def test_a_tiny_timeout_names_the_step():
    result = invoke("--timeout", "0.001", str(SYSTEMS / "sphere_on_turntable.yaml"))
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output
    message = re.search(r"sphere_on_turntable\.yaml:1:1: error: ran out of time in the step '([^']+)'",
                        result.stderr)
    assert message, result.stderr
    steps = [STEP_READ, STEP_LOAD, STEP_CLASSIFY, STEP_MASS]
    derive(load(SYSTEMS / "sphere_on_turntable.yaml"), progress=steps.append)
    assert message[1] in steps, message[1]


def test_the_budget_restores_the_previous_handler_and_timer():
    fired = []
    previous = signal.signal(signal.SIGALRM, lambda *a: fired.append(1))
    try:
        signal.setitimer(signal.ITIMER_REAL, 100)
        check_file(SYSTEMS / "cylinder_in_cylinder.yaml", timeout=30)
        handler = signal.getsignal(signal.SIGALRM)
        remaining, _ = signal.getitimer(signal.ITIMER_REAL)
        assert handler is not None and handler.__name__ == "<lambda>"
        assert 0 < remaining <= 100
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    assert fired == []


def test_no_budget_outside_the_main_thread():
    reports = []
    thread = threading.Thread(target=lambda: reports.append(check_file(SYSTEMS / "rigid_body.yaml", timeout=0.001)))
    thread.start()
    thread.join()
    assert reports[0].errors == ()


@pytest.mark.parametrize("name", ["four_bar_linkage", "chaplygin_ball", "sphere_on_turntable"])
def test_check_reads_the_equations_generated_code_computes_not_the_closed_forms(name, monkeypatch):
    """Without --verify, check runs the one engine users integrate: the closed route never runs."""
    def refused(*args, **kwargs):
        raise AssertionError("the closed route ran")

    monkeypatch.setattr("gacli.pipeline.derive", refused)
    report = check_file(SYSTEMS / f"{name}.yaml")
    assert not report.errors, report.errors
    assert report.mass_matrix.symmetric and report.mass_matrix.positive_definite


def test_m_is_tested_where_the_euler_parameters_are_kept_on_their_sphere():
    """A chain of quaternion links: generated code's M is positive definite on e·e = 1, not off it,
    and check's sample states (each entry in [0.3, 1.7]) were off it."""
    report = check_file(ROOT / "benchmarks" / "kane_set" / "variants" / "free7" / "f7_chain3_quat.yaml")
    assert not report.errors, [d.message for d in report.errors]
    assert report.mass_matrix.positive_definite and report.mass_matrix.samples == 3


def test_a_crash_is_reported_as_an_internal_error(tmp_path, monkeypatch):
    def broken(*args, **kwargs):
        raise ZeroDivisionError("boom")

    monkeypatch.setattr("gacli.pipeline.derive", broken)
    monkeypatch.setattr("gacli.pipeline.read_off", broken)  # the printout's route
    monkeypatch.setattr("gacli.pipeline.derive_for_code", broken)  # check's, generated code's program
    result = invoke(str(write(tmp_path, "good.yaml", GOOD)))
    assert result.exit_code == 1
    assert "good.yaml:1:1: error: internal error in the step" in result.stderr
    assert "ZeroDivisionError: boom" in result.stderr
    assert "Traceback" not in result.output


# -- renderers ---------------------------------------------------------------------------------

def _report() -> CheckReport:
    where = Location("we,ird:name.yaml", 3, 7)
    diagnostic = Diagnostic(where, "100% wrong\nsecond line \x1b[2J", "bodies.b", "a hint")
    return CheckReport((FileReport("we,ird:name.yaml", (diagnostic,), elapsed=0.5),), strict=False)


def test_github_escapes_data_and_properties():
    assert to_github(_report()) == (
        "::error file=we%2Cird%3Aname.yaml,line=3,col=7,title=gacli check::"
        "bodies.b: 100%25 wrong%0Asecond line \\x1b[2J (a hint)\n")


def test_json_is_stable_and_sorted():
    text = to_json(_report())
    assert text == to_json(_report())
    data = json.loads(text)
    assert list(data) == sorted(data)
    assert data["files"][0]["diagnostics"][0]["message"] == "100% wrong\nsecond line \x1b[2J"


def test_printable_escapes_control_characters():
    assert printable("a\tb\x1bc\u202ed") == "a\\tb\\x1bc\\u202ed"
    assert printable("θ = ω·t") == "θ = ω·t"


def test_check_paths_reports_in_order(tmp_path):
    b = write(tmp_path, "b.yaml", GOOD)
    a = write(tmp_path, "a.yaml", "gacli: 1\n[")
    report = check_paths([tmp_path], timeout=30)
    assert [f.path for f in report.files] == [str(a), str(b)]
    assert report.exit_code == 1 and report.failed == (report.files[0],)


def test_help_does_not_import_sympy():
    code = ("import sys\nfrom typer.testing import CliRunner\nfrom gacli.cli import app\n"
            "r = CliRunner().invoke(app, ['check', '--help'])\nassert r.exit_code == 0, r.output\n"
            "assert 'Example:\\n  gacli check' in r.output, r.output\nprint('sympy' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.stdout.strip() == "False", done.stderr


def test_the_pre_commit_hook():
    hooks = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text(encoding="utf-8"))
    hook = next(h for h in hooks if h["id"] == "gacli-check")
    assert hook["entry"] == "gacli check --skip-other-yaml"  # it is handed every YAML file
    assert re.search(hook["files"], "systems/top.yaml") and re.search(hook["files"], "a.yml")
    assert not re.search(hook["files"], "notes.txt")


# -- mutated system files (Hypothesis) ----------------------------------------------------------

SOURCES = {p.name: p.read_text(encoding="utf-8") for p in sorted(SYSTEMS.glob("*.yaml"))}
TOKENS = ["x", "dx", "dt", "t", "0", "1e999", "2**2**99", "__import__", "!!python/name:os.system", "&a", "*a",
          "{", "}", "[", "]", ":", "- ", "'", '"', "|", ">", "#", "%", "=", "dot(x)", "ddot(q)", "null", "~",
          "on", "sin(", ")", "\t", "\n", "\\", "\x00", "\u2212", "\x1b"]


@st.composite
def mutated(draw) -> str:
    text = SOURCES[draw(st.sampled_from(sorted(SOURCES)))]
    for _ in range(draw(st.integers(1, 3))):
        lines = text.splitlines(keepends=True)
        if not lines:
            break
        i, j = draw(st.integers(0, len(lines) - 1)), draw(st.integers(0, len(lines) - 1))
        kind = draw(st.sampled_from(["delete", "duplicate", "swap", "insert", "token", "truncate"]))
        if kind == "delete":
            del lines[i]
        elif kind == "duplicate":
            lines.insert(j, lines[i])
        elif kind == "swap":
            lines[i], lines[j] = lines[j], lines[i]
        text = "".join(lines)
        position = draw(st.integers(0, len(text)))
        if kind == "insert":
            text = text[:position] + draw(st.text(min_size=1, max_size=4)) + text[position:]
        elif kind == "token":
            words = list(re.finditer(r"[A-Za-z_][A-Za-z0-9_]*|\d+|\S", text))
            if not words:
                continue
            word = words[draw(st.integers(0, len(words) - 1))]
            text = text[:word.start()] + draw(st.sampled_from(TOKENS)) + text[word.end():]
        elif kind == "truncate":
            text = text[:position]
    return text


@pytest.fixture(scope="module")
def scratch(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("mutated") / "system.yaml"


@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(text=mutated())
def test_a_mutated_system_file_never_crashes(text, scratch):
    scratch.write_text(text, encoding="utf-8", errors="surrogatepass")
    result = invoke("--timeout", "10", str(scratch))
    assert "Traceback" not in result.output
    assert "internal error" not in result.output, result.output
    assert result.exit_code in (0, 1), result.output
    if result.exit_code == 1:
        assert re.search(rf"^{re.escape(str(scratch))}:\d+:\d+: error: ", result.stderr, re.MULTILINE), result.output


def test_machine_formats_quote_file_text_shortly_and_escaped():
    """JSON and GitHub annotations carry a message that quotes a huge scalar only in part, with no raw ESC."""
    from gacli.check import to_github, to_json
    from gacli.errors import Diagnostic, Location

    message = "bad value '" + "\x1b]0;pwned\x07" + "x" * 900_000 + "'"
    diagnostic = Diagnostic(Location("f.yaml", 1, 1), message, "title")
    report = CheckReport((FileReport(path="f.yaml", diagnostics=(diagnostic,)),), strict=False)
    for text in (to_json(report), to_github(report)):
        assert len(text) < 5_000
        assert "\x1b" not in text and "\x07" not in text


# -- classification: primitive quasi-coordinates (#19) ---------------------------------------

SPHERE_ON_A_FIXED_PLANE = """\
gacli: 1
name: sphere
parameters: [M, a, I]
coordinates: [x, y]
quasi_coordinates: [q_x, q_y, q_z]
constraints: ['dx - a*dq_y = 0', 'dy + a*dq_x = 0']
bodies:
  sphere: {mass: M, position: [x, y, a], inertia: [I, I, I], rotation: [ROTATION]}
"""


def test_the_rolling_sphere_is_non_holonomic_in_the_json_report(tmp_path):
    path = write(tmp_path, "sphere.yaml", SPHERE_ON_A_FIXED_PLANE.replace("ROTATION", "dq_x, dq_y, dq_z"))
    result = invoke("--format", "json", str(path))
    rows = json.loads(result.stdout)["files"][0]["classifications"]
    assert [(r["verdict"], r["integrable"], r["test"]) for r in rows] == [("non-holonomic", False, "alone")] * 2


def test_an_unknown_structure_is_undecided_with_a_note_that_never_fails(tmp_path):
    # q_y in no rotation: the body turns by other means, so nothing says what d(dq_y) is. The body
    # turns by q_x, x and q_z, so that M has no zero row (check's error for a rate that moves nothing).
    text = (SPHERE_ON_A_FIXED_PLANE.replace("ROTATION", "dq_x, dx, dq_z").replace(", 'dy + a*dq_x = 0'", ""))
    path = write(tmp_path, "unknown.yaml", text)
    result = invoke("--strict", "--format", "json", str(path))
    report = json.loads(result.stdout)["files"][0]
    assert result.exit_code == 0
    assert [r["verdict"] for r in report["classifications"]] == ["undecided"]
    notes = [d for d in report["diagnostics"] if d["severity"] == "note"]
    assert [(d["where"], d["line"]) for d in notes] == [("constraints[0]", 6)]
    assert "dq_y: in no body's rotation" in notes[0]["message"]


def test_a_quaternion_frame_without_rates_is_warned_of_where_it_is_declared(tmp_path):
    # Its automatic speeds are three Euler parameters' rates, and the fourth divides by a parameter:
    # the generated rhs raised ZeroDivisionError at the identity attitude, and check said nothing.
    text = """gacli: 1
name: quaternion_without_rates
parameters: [m, g, A, B, C]
coordinates: [x, y, z, q0, q1, q2, q3]
frames:
  body: {quaternion: [q0, q1, q2, q3]}
bodies:
  body: {mass: m, position: [x, y, z], frame: body, inertia: [A, B, C]}
loads:
  - {force: [0, 0, -m*g], at: body}
"""
    path = str(write(tmp_path, "q.yaml", text))
    result = invoke(path)
    assert result.exit_code == 0
    assert re.search(r"q\.yaml:4:\d+: warning: frames\.body: frame 'body' is turned by the quaternion \(q0, q1, q2, q3\) "
                     r"without body rates", result.stderr), result.stderr
    assert invoke(path, "--strict").exit_code == 1
    with_rates = text.replace("[q0, q1, q2, q3]}", "[q0, q1, q2, q3], rates: [w1, w2, w3]}").replace(
        "coordinates: [x, y, z, q0, q1, q2, q3]", "coordinates: [x, y, z, q0, q1, q2, q3]\nquasi_coordinates: [w1, w2, w3]")
    assert "without body rates" not in invoke(str(write(tmp_path, "r.yaml", with_rates))).stderr


def test_a_norm_kept_by_its_differential_is_noted_where_it_is_stated(tmp_path):
    # e·de = 0 keeps e·e at its start, which the file does not state: the kinematics divide by e·e,
    # where the finite constraint lets generated code read on the unit sphere. Right as it stands: a note.
    text = """gacli: 1
name: norm_by_differential
parameters: [m, g, A, B, C]
coordinates: [x, y, z, q0, q1, q2, q3]
quasi_coordinates:
  w1: 2*(-q1*dq0 + q0*dq1 + q3*dq2 - q2*dq3)
  w2: 2*(-q2*dq0 - q3*dq1 + q0*dq2 + q1*dq3)
  w3: 2*(-q3*dq0 + q2*dq1 - q1*dq2 + q0*dq3)
constraints:
  - q0*dq0 + q1*dq1 + q2*dq2 + q3*dq3 = 0
independent: [x, y, z, w1, w2, w3]
bodies:
  body: {mass: m, position: [x, y, z], inertia: [A, B, C], rotation: [dw1, dw2, dw3]}
potential: m*g*z
"""
    path = str(write(tmp_path, "n.yaml", text))
    result = invoke(path, "--strict")
    assert result.exit_code == 0
    assert re.search(r"n\.yaml:10:\d+: note: constraints\[0\]: this row keeps q0\*\*2 \+ q1\*\*2 \+ q2\*\*2 \+ q3\*\*2 "
                     r"at its starting value", result.stderr), result.stderr
    stated = text.replace("q0*dq0 + q1*dq1 + q2*dq2 + q3*dq3 = 0", "q0**2 + q1**2 + q2**2 + q3**2 = 1")
    assert "starting value" not in invoke(str(write(tmp_path, "s.yaml", stated))).stderr
    other = text.replace("q0*dq0 + q1*dq1 + q2*dq2 + q3*dq3 = 0", "q0*dq0 + q1*dq1 + q2*dq2 + 2*q3*dq3 = 0")
    assert "starting value" not in invoke(str(write(tmp_path, "o.yaml", other))).stderr


def test_a_long_path_at_80_columns_widens_the_table_rather_than_cut_its_time(tmp_path, monkeypatch):
    """A CI log is piped at 80 columns: the path and the time must stay whole (they showed '0.…')."""
    monkeypatch.setenv("GACLI_WIDTH", "80")
    deep = tmp_path / "a_folder_with_a_long_name" / "and_another_one_below_it"
    paths = [str(write(deep, name, GOOD)) for name in ("first_pendulum.yaml", "second_pendulum.yaml")]
    result = invoke(*paths)
    assert result.exit_code == 0, result.output
    rows = [line for line in result.stdout.splitlines() if "pendulum.yaml" in line]
    assert len(rows) == 2 and all(re.search(r"\d+\.\ds$", row.rstrip()) for row in rows), result.stdout
