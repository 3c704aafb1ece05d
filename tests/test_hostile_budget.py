"""Every command as safe as ``gacli check``: one time budget, memory, terminal and size limits.

Files that ``check`` accepts (a hostile title) or that only time out in a
command are made here in ``tmp_path``: ``tests/hostile/`` holds files that
``check`` itself must reject.
"""

from __future__ import annotations

import re
import sys
import unicodedata
from pathlib import Path

import pytest
from typer.testing import CliRunner

from gacli.cli import app

ROOT = Path(__file__).resolve().parent.parent
HOSTILE = ROOT / "tests" / "hostile"
SLOW = HOSTILE / "exp_tower_in_constraint.yaml"  # the rank check never returns
BUDGET = "1"

SIMULATE = ["--input", "F=0,T=0", "--t-end", "0.1", "--points", "3"]
COMMANDS = {
    "derive_text": ["derive"],
    "derive_c": ["derive", "--format", "c"],
    "derive_latex": ["derive", "--format", "latex"],
    "gibbs": ["gibbs"],
    "verify": ["verify", "--samples", "1"],
    "linearize": ["linearize"],
    "simulate": ["simulate", *SIMULATE],
}


def run(*args: str):
    return CliRunner().invoke(app, [str(a) for a in args])


def assert_located_error(result, path: Path, expect: str) -> None:
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output, result.output
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    assert re.search(rf"^{re.escape(str(path))}:\d+:\d+: error: ", result.output, re.MULTILINE), result.output
    assert expect in result.output, result.output


# -- the time budget -------------------------------------------------------------------

@pytest.mark.parametrize("command", ["derive_text", "derive_c", "gibbs", "verify", "linearize", "simulate"])
def test_every_command_stops_at_its_budget_naming_the_step(command: str):
    result = run(*COMMANDS[command], "--timeout", BUDGET, SLOW)
    assert_located_error(result, SLOW, "ran out of time in the step 'rates in terms of the independent rates")
    assert "raise it with --timeout" in result.output


@pytest.mark.parametrize("command", ["derive", "gibbs", "verify", "linearize", "simulate"])
def test_every_command_documents_its_timeout(command: str):
    result = run(command, "--help")
    assert result.exit_code == 0
    assert "--timeout" in result.output and "ran out of time" in result.output


def test_the_cli_literals_agree_with_the_budget_module():
    from gacli import budget, cli

    assert cli.DEFAULT_TIMEOUT == budget.DEFAULT_TIMEOUT


def test_a_zero_timeout_means_no_limit():
    result = run("derive", "--timeout", "0", ROOT / "systems" / "particle_in_plane.yaml")
    assert result.exit_code == 0, result.output


def test_usage_errors_come_before_any_work():
    result = run("derive", "--steps", "--format", "c", "--timeout", BUDGET, SLOW)
    assert result.exit_code == 2
    assert "ran out of time" not in result.output


# -- memory ------------------------------------------------------------------------------

def test_out_of_memory_in_a_step_is_one_located_message(monkeypatch):
    def exhausted(*args, **kwargs):
        raise MemoryError

    monkeypatch.setattr("gacli.pipeline.derive", exhausted)
    monkeypatch.setattr("gacli.pipeline.read_off", exhausted)  # the printout's route
    path = ROOT / "systems" / "particle_in_plane.yaml"
    assert_located_error(run("derive", path), path, "ran out of memory in the step 'building the program")


def test_out_of_memory_anywhere_is_one_message(monkeypatch):
    def exhausted(*args, **kwargs):
        raise MemoryError

    monkeypatch.setattr("gacli.display.console.sections", exhausted)
    result = run("gibbs", ROOT / "systems" / "particle_in_plane.yaml")
    assert result.exit_code == 1
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    assert "error: ran out of memory" in result.output


# -- loading is bounded by what aliases expand to --------------------------------------

def test_aliases_are_counted_by_the_text_they_repeat():
    from gacli.errors import SystemFileError
    from gacli.read.source import MAX_EXPANDED_CHARS, parse_source

    long = "x" * 10_000
    uses = MAX_EXPANDED_CHARS // len(long) + 1
    text = f"a: &e {long}\nb: [" + ", ".join(["*e"] * uses) + "]\n"
    assert len(text) < MAX_EXPANDED_CHARS / 10  # few nodes and a small file: only the expansion is large
    with pytest.raises(SystemFileError, match="expands to more than") as caught:
        parse_source(text.encode(), "aliases.yaml")
    assert caught.value.diagnostics[0].location.line == 2  # the list that repeats the alias


def test_a_file_too_large_without_aliases_does_not_blame_aliases():
    from gacli.errors import SystemFileError
    from gacli.read.source import MAX_NODES, parse_source

    text = "gacli: 1\nname: big\nlist: [" + ", ".join(["0"] * (MAX_NODES + 1)) + "]\n"
    with pytest.raises(SystemFileError, match="expands to more than") as caught:
        parse_source(text.encode(), "big.yaml")
    assert "aliases" not in str(caught.value)


def test_anchors_used_as_intended_still_load():
    from gacli.read.source import parse_source

    source = parse_source(b"a: &e m*g\nb: [*e, *e, *e]\n", "fine.yaml")
    assert [item.text for item in source.root.items[1][1].items] == ["m*g"] * 3


def test_derive_refuses_an_alias_expansion_before_deriving():
    path = HOSTILE / "budget_alias_expansion.yaml"
    assert_located_error(run("derive", "--timeout", "30", path), path, "expands to more than")


# -- the terminal --------------------------------------------------------------------------

# ESC (clear screen), BEL, a bidi override, a zero-width space and a lone surrogate.
TITLE = r'"evil \e[2J \a \u202e zw\u200b lone \ud800"'
SYSTEM = f"""gacli: 1
name: target
title: {TITLE}
parameters:
  m: {{value: 1}}
  I: {{value: 1}}
inputs: [F, T]
coordinates: [x, y]
quasi_coordinates: [w]
bodies:
  disc:
    mass: m
    position: [x, y]
    inertia: I
    rotation: dw
loads:
  - force: [F, 0]
    at: disc
  - torque: T
    body: disc
"""


def _unsafe(text: str) -> list[str]:
    """Characters that would drive or confuse a terminal (tab and newline are layout)."""
    return [c for c in text if c not in "\n\t" and not (c.isprintable() or c == " ")
            or unicodedata.category(c) == "Cs"]


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_file_text_never_reaches_the_terminal_raw(command: str, tmp_path: Path):
    path = tmp_path / "title.yaml"
    path.write_text(SYSTEM, encoding="utf-8")
    result = run(*COMMANDS[command], path)
    assert result.exit_code == 0, (result.output, result.exception)
    assert _unsafe(result.output) == [], result.output


def test_text_derive_shows_the_title_escaped(tmp_path: Path):
    path = tmp_path / "title.yaml"
    path.write_text(SYSTEM, encoding="utf-8")
    result = run("derive", path)
    assert result.output.splitlines()[0] == r"evil \x1b[2J \x07 \u202e zw\u200b lone \ud800"


def test_an_error_quoting_a_control_character_escapes_it(tmp_path: Path):
    path = tmp_path / "name.yaml"
    path.write_text(SYSTEM.replace("name: target", r'name: "\e[2Jx"'), encoding="utf-8")
    result = run("derive", path)
    assert_located_error(result, path, r"\x1b[2J")
    assert "\x1b" not in result.output


def test_a_huge_scalar_is_quoted_shortened(tmp_path: Path):
    path = tmp_path / "scalar.yaml"
    path.write_text("x" * 900_000 + "\n", encoding="utf-8")
    result = run("derive", path)
    assert_located_error(result, path, "characters not shown")
    assert len(result.output) < 1000


def test_a_link_to_another_file_is_not_quoted_whole(tmp_path: Path):
    other = tmp_path / "notes.txt"
    other.write_text(" ".join(f"secret{i}" for i in range(2000)), encoding="utf-8")
    link = tmp_path / "link.yaml"
    link.symlink_to(other)
    result = run("gibbs", link)
    assert_located_error(result, link, "characters not shown")
    assert len(result.output) < 1000


# -- wide systems ----------------------------------------------------------------------------

@pytest.mark.parametrize("name", ["rolling_disk", "spinning_top", "particle_in_plane"])
def test_gibbs_entries_are_the_derivatives_of_g(name: str):
    """Term-by-term differentiation (gacli.mechanics.gibbs.gibbs_entries) equals differentiating the whole of G."""
    import sympy as sp

    from gacli.mechanics.gibbs import gibbs_entries
    from tests.conftest import derived

    d = derived(name)
    acc, zero = d.speed_rates, {a: 0 for a in d.speed_rates}
    sparse_H, sparse_g = gibbs_entries(d.gibbs, acc)
    for i in range(d.k):
        assert sp.expand(sp.diff(d.gibbs, acc[i]).xreplace(zero) - sparse_g.get(i, 0)) == 0
        for j in range(i, d.k):
            assert sp.expand(sp.diff(d.gibbs, acc[i], acc[j]) - sparse_H.get((i, j), 0)) == 0
    assert all(value != 0 for value in [*sparse_H.values(), *sparse_g.values()])


class _Late(Exception):
    pass


def test_an_alarm_inside_a_finalizer_prints_no_traceback(monkeypatch):
    # The budget's alarm repeats until the block gives up; one that lands in a __del__ while
    # the frames unwind cannot be raised there, and Python printed it with a traceback (a tiny
    # --timeout on a loaded machine). It is dropped, and raised again where it can be.
    import time

    from gacli.numeric.zero import time_limit

    class Slow:
        def __del__(self):
            end = time.monotonic() + 0.2
            while time.monotonic() < end:
                pass

    unraisable = []  # what Python would print as "Exception ignored in ...", with a traceback
    monkeypatch.setattr(sys, "unraisablehook", unraisable.append)
    with pytest.raises(_Late):
        with time_limit(0.01, _Late):
            slow = Slow()
            del slow  # the alarm fires inside its finalizer
            time.sleep(2)  # and again here
    assert unraisable == []


def _slow_program(n: int = 7) -> str:
    """A chain of n links with its positions written out by the addition formulas (a CAS's output):
    the builder reads them back as frames, seconds of work. ((sin x + cos y)**20 served here until
    reductions were bounded by their input.)"""
    import sympy as sp

    q, lengths = sp.symbols(f"q1:{n + 1}"), sp.symbols(f"l1:{n + 1}")
    lines = ["gacli: 1", "name: slow_program", "parameters:", "  g: {value: 9.81}"]
    lines += [f"  m{i + 1}: {{value: 1}}\n  l{i + 1}: {{value: 1}}" for i in range(n)]
    lines += [f"coordinates: [{', '.join(map(str, q))}]", "bodies:"]
    x = y = sp.S.Zero
    for i in range(n):
        angle = sum(q[:i + 1])
        cx = sp.expand(sp.expand_trig(x + lengths[i] * sp.cos(angle) / 2))
        cy = sp.expand(sp.expand_trig(y + lengths[i] * sp.sin(angle) / 2))
        lines += [f"  link{i + 1}: {{mass: m{i + 1}, position: [{cx}, {cy}], inertia: m{i + 1}*l{i + 1}**2/12, "
                  f"rotation: {' + '.join('d' + str(v) for v in q[:i + 1])}}}"]
        x, y = x + lengths[i] * sp.cos(angle), y + lengths[i] * sp.sin(angle)
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("command", [["check"], ["derive", "-f", "python"]])
def test_a_budget_spent_in_the_program_builder_is_not_taken_for_its_failure(command, tmp_path):
    # The builder's 'except Exception' caught the alarm: check said 'ok' at exactly its budget, and
    # derive -f python went on to the closed forms and wrote code after the budget ran out.
    path = tmp_path / "slow.yaml"
    path.write_text(_slow_program())
    result = run(*command, path, "--timeout", "2")
    assert_located_error(result, path, "ran out of time in the step 'building the program")
