"""Broken system files: one located message each, exit code 1, no traceback.

Each ``tests/invalid/*.yaml`` starts with ``# expect: LINE:COL MESSAGE``; the
message text is API, so it is compared as written (a substring of the line
that carries the location).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from gacli.cli import app

CASES = sorted((Path(__file__).parent / "invalid").glob("*.yaml"))
EXPECT = re.compile(r"# expect: (\d+):(\d+) (.+)")


def expectation(path: Path) -> tuple[str, str]:
    first = path.read_text(encoding="utf-8").splitlines()[0]
    match = EXPECT.fullmatch(first)
    assert match, f"{path.name}: first line must be '# expect: LINE:COL MESSAGE'"
    line, col, message = match.groups()
    return f"{path}:{line}:{col}: error:", message


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_invalid_file_is_reported_at_its_place(path):
    where, message = expectation(path)
    result = CliRunner().invoke(app, ["derive", str(path)])
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output
    located = [line for line in result.output.splitlines() if line.startswith(where)]
    assert located, f"no message at {where}:\n{result.output}"
    assert any(message in line for line in located), result.output


def test_corpus_is_large_enough():
    assert len(CASES) >= 25
