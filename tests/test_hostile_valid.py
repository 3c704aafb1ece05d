"""Valid files that hurt (issue 33, class 6): chains and repetitions of rotations, made here.

* A chain of ten frames with origins, which ``derive`` handles: ``verify``'s
  independent route (eq. 14.10 with multipliers) must finish within the
  default budget and pass. It used to run out of its time building the
  Jacobian of Σ m a·∂v/∂r̈ of every body's chain of rotations.
* Chains of 40 frames and a frame turned 200 times: text ``derive`` either
  finishes, or stops at its budget with one located message; never a
  traceback, never past the hostile corpus's 20 s with a short budget. The
  ones whose turns merge about one axis (the loader's canonical chain) must
  finish.

The files are made in ``tmp_path`` from the generators below (the first is
a regression of the verify route; the others are the issue's cases and
variants of them).
"""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from gacli.cli import app

GENEROUS = 60  # seconds: the hostile tests' bound for a case that is hung, not slow
SHORT_BUDGET = "5"


def chain_with_origins(n: int) -> str:
    """n links, each a frame turned about the next axis (y, x, z, ...) at the end of the one before."""
    lines = ["gacli: 1", f"name: chain_with_origins_{n}", "parameters:", "  g: {value: 9.81}", "  L: {value: 1}",
             "  m: {value: 1}", "  I: {value: 0.1}",
             "coordinates: [" + ", ".join(f"q{i}" for i in range(1, n + 1)) + "]", "frames:"]
    for i in range(1, n + 1):
        parent = "" if i == 1 else f"parent: f{i - 1}, origin: p{i}, "
        lines.append(f"  f{i}: {{{parent}rotations: [[{'zyx'[i % 3]}, q{i}]]}}")
    lines.append("points:")
    for i in range(2, n + 1):
        start = "" if i == 2 else f"from: p{i - 1}, "
        lines.append(f"  p{i}: {{{start}f{i - 1}: [L, 0, 0]}}")
    lines.append("bodies:")
    for i in range(1, n + 1):
        start = "" if i == 1 else f"from: p{i}, "
        lines.append(f"  b{i}: {{mass: m, position: {{{start}f{i}: [L/2, 0, 0]}}, frame: f{i}, inertia: [I, I, I]}}")
    lines.append("loads:")
    lines += [f"  - {{force: {{N: [0, 0, -m*g]}}, at: b{i}}}" for i in range(1, n + 1)]
    return "\n".join(lines) + "\n"


def _one_body(name: str, frames: list[str], last: str) -> str:
    return "\n".join([
        "gacli: 1", f"name: {name}", "parameters:", "  m: {value: 1}", "  I: {value: 0.1}", "  g: {value: 9.81}",
        "coordinates: [a, b]", "frames:", *frames, "bodies:",
        f"  body: {{mass: m, position: {{{last}: [1, 0, 0]}}, frame: {last}, inertia: [I, I, I]}}",
        "loads:", "  - {force: {N: [0, 0, -m*g]}, at: body}",
    ]) + "\n"


def chain_turned(n: int, rotations: str) -> str:
    """n frames, each its parent turned by ``rotations``; one body in the last."""
    frames = [f"  f{i}: {{{'' if i == 1 else f'parent: f{i - 1}, '}rotations: {rotations}}}" for i in range(1, n + 1)]
    return _one_body(f"chain_{n}", frames, f"f{n}")


def one_frame_turned(n: int, turns: list[str]) -> str:
    """One frame turned n times, cycling through ``turns``."""
    return _one_body(f"turned_{n}", ["  f: {rotations: [" + ", ".join(turns[i % len(turns)] for i in range(n)) + "]}"], "f")


def _write(tmp_path: Path, text: str, name: str) -> Path:
    path = tmp_path / f"{name}.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_verify_passes_a_chain_of_ten_frames_with_origins_within_its_budget(tmp_path):
    path = _write(tmp_path, chain_with_origins(10), "chain")
    result = CliRunner().invoke(app, ["verify", "--samples", "1", str(path)])
    assert result.exit_code == 0, result.output
    assert "verify: passed" in result.output


# Turns that merge about one axis (canonical chains): derive must finish.
MERGING = {
    "chain_of_40_turned_twice_about_one_axis": chain_turned(40, "[[z, a], [z, a]]"),
    "one_frame_turned_200_times_about_one_axis": one_frame_turned(200, ["[z, a]"]),
    "one_frame_turned_there_and_back_100_times": one_frame_turned(200, ["[z, a]", "[z, -a]"]),
}
# Turns that do not merge: the equations grow with every turn; derive may stop at its budget.
GROWING = {
    "chain_of_40_turned_by_two_angles": chain_turned(40, "[[z, a], [x, b]]"),
    "chain_of_40_turned_twice_by_the_same_angle": chain_turned(40, "[[z, a], [x, a]]"),
    "one_frame_turned_80_times_by_two_angles": one_frame_turned(80, ["[z, a]", "[x, b]"]),
}


@pytest.mark.parametrize("name", sorted(MERGING))
def test_merging_turns_derive_within_the_budget(name, tmp_path):
    path = _write(tmp_path, MERGING[name], name)
    result = CliRunner().invoke(app, ["derive", str(path)])
    assert result.exit_code == 0, result.output
    assert "Traceback" not in result.output


@pytest.mark.parametrize("name", sorted(GROWING))
def test_growing_turns_finish_or_stop_at_the_budget_cleanly(name, tmp_path):
    path = _write(tmp_path, GROWING[name], name)
    start = time.perf_counter()
    result = CliRunner().invoke(app, ["derive", "--timeout", SHORT_BUDGET, str(path)])
    elapsed = time.perf_counter() - start
    assert "Traceback" not in result.output and "internal error" not in result.output, result.output
    if result.exit_code != 0:
        assert result.exit_code == 1, result.output
        assert re.search(rf"^{re.escape(str(path))}(:\d+:\d+)?: error: .*ran out of time", result.output,
                         re.MULTILINE), result.output
    assert elapsed < GENEROUS
