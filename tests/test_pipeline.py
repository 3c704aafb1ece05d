"""One pipeline: a command reads the file once, loads it once and builds its equations once (issue #28)."""

from __future__ import annotations

import re

import pytest
from typer.testing import CliRunner

from conftest import ROOT

SYSTEMS = ROOT / "systems"


@pytest.fixture
def counts(monkeypatch):
    """How often a file is parsed, a System built and a straight-line program built."""
    import gacli.mechanics.code as code
    import gacli.read.source as source
    from gacli.loader.loading import _Builder

    seen = {"read": 0, "load": 0, "program": 0}

    def counting(name, original):
        def wrapper(*args, **kwargs):
            seen[name] += 1
            return original(*args, **kwargs)
        return wrapper

    monkeypatch.setattr(source, "parse_source", counting("read", source.parse_source))
    monkeypatch.setattr(_Builder, "_system", counting("load", _Builder._system))
    monkeypatch.setattr(code, "build_program", counting("program", code.build_program))
    code._PROGRAMS.clear()
    return seen


def _derive(*args: str):
    from gacli.cli import app

    result = CliRunner().invoke(app, ["derive", *args])
    assert result.exit_code == 0, result.output
    return result.output


@pytest.mark.parametrize("name", ["rolling_disk", "whipple_bicycle", "sphere_on_turntable"])
def test_code_reads_and_loads_the_file_once(counts, name, tmp_path):
    _derive(str(SYSTEMS / f"{name}.yaml"), "--format", "c", "--output", f"{tmp_path}/")
    assert counts["read"] == 1
    assert counts["load"] == 1
    assert counts["program"] <= 1


def test_check_and_text_read_and_load_once(counts):
    from gacli.cli import app

    _derive(str(SYSTEMS / "rolling_disk.yaml"))
    assert (counts["read"], counts["load"]) == (1, 1)
    result = CliRunner().invoke(app, ["check", str(SYSTEMS / "rolling_disk.yaml")])
    assert result.exit_code == 0, result.output
    assert (counts["read"], counts["load"]) == (2, 2)


def test_rows_added_later_are_the_rows_of_one_load():
    from gacli.loader.loading import load_in_stages, load_source
    from gacli.read.source import read_source

    source = read_source(SYSTEMS / "whipple_bicycle.yaml")
    first, complete = load_in_stages(source)
    assert not first.rolling_rows and len(first.constraints) == 0
    later, whole = complete(), load_source(source)
    assert later.rolling_rows and whole.rolling_rows
    assert [c.text for c in later.constraints] == [c.text for c in whole.constraints]
    assert [c.form for c in later.constraints] == [c.form for c in whole.constraints]
    assert complete() is later


def test_standard_input_is_a_system_file():
    from gacli.cli import app

    text = (SYSTEMS / "particle_in_plane.yaml").read_text()
    result = CliRunner().invoke(app, ["derive", "-"], input=text)
    assert result.exit_code == 0, result.output
    assert "Gibbs-Appell equations" in result.output
    bad = CliRunner().invoke(app, ["derive", "-"], input="gacli: 1\nname: x\ncoordinates: [q]\nbodies: {b: {mass: m}}\n")
    assert bad.exit_code == 1
    assert "<stdin>:" in bad.output


def test_a_file_of_thousands_of_problems_prints_a_hundred(tmp_path):
    from gacli.check import MAX_DIAGNOSTICS
    from gacli.cli import MAX_DIAGNOSTICS as CLI_MAX
    from gacli.cli import app

    assert CLI_MAX == MAX_DIAGNOSTICS
    bodies = "".join(f"  b{i}: {{mass: zz{i}, position: [q, 0, 0]}}\n" for i in range(3000))
    path = tmp_path / "many.yaml"
    path.write_text("gacli: 1\nname: many\ncoordinates: [q]\nbodies:\n" + bodies)
    result = CliRunner().invoke(app, ["derive", str(path)])
    assert result.exit_code == 1
    lines = result.output.splitlines()
    assert len(lines) == MAX_DIAGNOSTICS + 1
    rest = 3000 - MAX_DIAGNOSTICS
    assert re.fullmatch(rf"{re.escape(str(path))}:\d+:\d+: error: {rest} more problems not shown \({rest} errors\)",
                        lines[-1]), lines[-1]


def test_a_fifo_output_is_refused_before_the_derivation(tmp_path, monkeypatch):
    import os

    import gacli.pipeline

    fifo = tmp_path / "out.c"
    os.mkfifo(fifo)
    monkeypatch.setattr(gacli.pipeline, "derive", lambda *a, **k: pytest.fail("derived before refusing"))
    from gacli.cli import app

    result = CliRunner().invoke(app, ["derive", str(SYSTEMS / "particle_in_plane.yaml"), "--format", "c",
                                      "--output", str(fifo)])
    assert result.exit_code == 1
    assert "not a regular file" in result.output
    assert fifo.exists() and not fifo.is_file()


def test_a_large_system_prints_without_forming_its_closed_forms(monkeypatch):
    # The bicycle's printout names the program's quantities: the chapter's closed forms, which
    # cost most of a text derive and are never printed for it, must not be formed (issue #28).
    import gacli.mechanics.equations as equations

    def refuse(*args, **kwargs):
        raise AssertionError("the closed forms were formed")

    monkeypatch.setattr(equations, "_derive", refuse)
    out = _derive(str(SYSTEMS / "whipple_bicycle.yaml"))
    assert "Named quantities" in out and "k = n + p - d - l = " in out
    assert "independent: " in out and "(as given in the file)" in out


def test_a_chain_without_independent_rates_takes_the_program(monkeypatch):
    # No rows: every rate is independent, which both routes choose alike; a chain of 40 frames
    # turned about alternating axes is linear in the program and blew up in the closed forms.
    import gacli.mechanics.equations as equations

    monkeypatch.setattr(equations, "_derive", lambda *a, **k: (_ for _ in ()).throw(AssertionError("closed forms")))
    frames = "\n".join(f"  f{i}: {{{'' if i == 1 else f'parent: f{i - 1}, '}rotations: [[z, a], [x, b]]}}"
                       for i in range(1, 41))
    text = ("gacli: 1\nname: chain\nparameters: {m: {value: 1}, I: {value: 0.1}, g: {value: 9.81}}\n"
            f"coordinates: [a, b]\nframes:\n{frames}\nbodies:\n"
            "  body: {mass: m, position: {f40: [1, 0, 0]}, frame: f40, inertia: [I, I, I]}\n"
            "loads:\n  - {force: {N: [0, 0, -m*g]}, at: body}\n")
    from gacli.pipeline import PRINTOUT, run_source
    from gacli.read.source import parse_source

    d = run_source(parse_source(text.encode(), "chain.yaml"), needs=PRINTOUT).derivation
    assert not d.closed and d.independent == ("a", "b")


def test_check_without_verify_reads_a_large_system_s_program(monkeypatch):
    # check's M, F and q̇ checks read the program's outputs as any printout does; verify alone
    # needs the closed forms (gacli.pipeline.CLOSED).
    import gacli.mechanics.equations as equations
    from gacli.cli import app

    monkeypatch.setattr(equations, "_derive", lambda *a, **k: (_ for _ in ()).throw(AssertionError("closed forms")))
    result = CliRunner().invoke(app, ["check", str(SYSTEMS / "whipple_bicycle.yaml")])
    assert result.exit_code == 0, result.output


def test_numeric_linearization_and_refusals_read_the_program(monkeypatch):
    # linearize (and its --sweep) compiles q̇, M and F as generated code computes them; steady and
    # integrals refuse a system too large to print before forming what they would refuse.
    import gacli.mechanics.equations as equations
    from gacli.cli import app

    monkeypatch.setattr(equations, "_derive", lambda *a, **k: (_ for _ in ()).throw(AssertionError("closed forms")))
    bicycle = str(SYSTEMS / "whipple_bicycle.yaml")
    result = CliRunner().invoke(app, ["linearize", bicycle, "--at", "dot(wheel_R)=-20"])
    assert result.exit_code == 0, result.output
    for command in ("steady", "integrals"):
        result = CliRunner().invoke(app, [command, bicycle])
        assert result.exit_code == 1 and "too large for symbolic work" in result.output, result.output


@pytest.mark.parametrize("name, at", [("rolling_disk", "lean=0.3"), ("cylinder_in_cylinder", "theta=0.2"),
                                      ("appell_hamel", "dot(x)=1"), ("spinning_top", "theta=0.4")])
def test_code_and_numeric_linearization_never_form_the_closed_forms(monkeypatch, tmp_path, name, at):
    # One engine for code (issue #28): a small system's generated code and numeric linearization
    # are its program's, as a large one's are; the closed forms are for what prints them.
    import gacli.mechanics.equations as equations
    from gacli.cli import app

    monkeypatch.setattr(equations, "_derive", lambda *a, **k: (_ for _ in ()).throw(AssertionError("closed forms")))
    path = str(SYSTEMS / f"{name}.yaml")
    _derive(path, "--format", "c", "--output", f"{tmp_path}/")
    assert (tmp_path / f"{name}.c").exists()
    result = CliRunner().invoke(app, ["linearize", path, "--at", at])
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("name", ["rolling_disk", "cylinder_in_cylinder", "appell_hamel", "spinning_top"])
def test_the_printout_is_read_off_the_program(monkeypatch, name):
    # One engine (issue #28): derive's text and LaTeX and gibbs print q̇, M, F and Q read off the
    # program (gacli.mechanics.read_off); the chapter's closed route is not run for them.
    import gacli.mechanics.equations as equations
    from gacli.cli import app

    monkeypatch.setattr(equations, "_derive", lambda *a, **k: (_ for _ in ()).throw(AssertionError("closed forms")))
    path = str(SYSTEMS / f"{name}.yaml")
    assert "Gibbs-Appell equations" in _derive(path)
    assert "\\begin" in _derive(path, "--format", "latex")
    result = CliRunner().invoke(app, ["gibbs", path])
    assert result.exit_code == 0 and "G = " in result.output, result.output


def test_a_printout_forms_the_closed_forms_only_where_they_may_print_written_out():
    # Read off the program, a tricycle's Q − F is 18,637 characters against 869 closed: the closed
    # forms print. An Ackermann car's closed forms are larger than its read-off ones, which already
    # print past the bound: both would print named, and the closed ones are not tidied for nothing.
    from gacli.pipeline import PRINTOUT, run

    twins = ROOT / "tests" / "twins"
    assert run(twins / "tricycle_front_drive.yaml", needs=PRINTOUT).derivation.closed
    car = run(twins / "ackermann_car.yaml", needs=PRINTOUT).derivation
    assert not car.closed and car.printable


def test_forms_read_off_that_miss_the_bound_by_little_are_named_without_forming_the_closed_forms(monkeypatch):
    """A five-bar's forms read off its program print 6,486 characters untidied for a bound of 5,125: the
    closed forms could not print shorter enough to matter, and forming them cost 2 s of its derive."""
    from gacli import pipeline

    def closed(*args, **kwargs):
        raise AssertionError("the closed forms were formed")

    monkeypatch.setattr(pipeline, "derive", closed)
    run = pipeline.run(ROOT / "benchmarks" / "kane_set" / "variants" / "linkages" / "l3_five_bar.yaml",
                       needs=pipeline.PRINTOUT)
    assert not run.derivation.closed and run.derivation.printable
