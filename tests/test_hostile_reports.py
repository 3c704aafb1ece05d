"""The hostile corpus through the reports CI reads (issue 33, class 3): ``check --format json|github``.

tests/test_hostile.py reads ``check``'s text report of every file of
tests/hostile/; here the same files go through the two formats a CI job
parses. The JSON must be strict UTF-8 JSON (no lone surrogate: jq refuses
one) with one located error or more and at most a hundred diagnostics per
file; each GitHub annotation must be one line whose properties escape
``%``, ``,`` and ``:`` as GitHub documents, and whose message names where
it is. Neither report may carry a traceback or a control character.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from gacli.cli import app
from test_hostile import BUDGET, FILES, planted

PER_FILE = 100  # problems a report shows of one file (then how many more there are)
_PROPERTY = re.compile(r"^::error file=([^,]*),line=(\d+),col=(\d+),title=([^:]*)::(.*)$")


def _check(path: Path, fmt: str):
    return CliRunner().invoke(app, ["check", "--timeout", BUDGET, "--format", fmt, str(path)])


@pytest.mark.parametrize("source", FILES, ids=lambda p: p.stem)
def test_json_report_is_strict_and_located(source: Path, tmp_path: Path):
    path, marker = planted(source, tmp_path)
    result = _check(path, "json")
    assert result.exit_code == 1, result.output
    data = result.stdout_bytes.decode("utf-8")  # strict: a lone surrogate cannot be encoded
    report = json.loads(data)
    (entry,) = report["files"]
    errors = [d for d in entry["diagnostics"] if d["severity"] == "error"]
    assert errors and all(d["line"] >= 1 and d["column"] >= 1 for d in errors), errors
    assert len(entry["diagnostics"]) <= PER_FILE + 1  # the hundred, and the one that says how many more
    assert "Traceback" not in data and not re.search(r"[\x00-\x08\x0b-\x1f\x7f]", data)
    assert not marker.exists()


@pytest.mark.parametrize("source", FILES, ids=lambda p: p.stem)
def test_github_annotations_are_one_escaped_line_each(source: Path, tmp_path: Path):
    path, marker = planted(source, tmp_path)
    result = _check(path, "github")
    assert result.exit_code == 1, result.output
    text = result.stdout_bytes.decode("utf-8")
    annotations = [line for line in text.splitlines() if line.startswith("::error")]
    assert 1 <= len(annotations) <= PER_FILE + 1, text[-2000:]
    for line in annotations:
        match = _PROPERTY.match(line)
        assert match, line
        name = match.group(1)
        assert "%" not in name.replace("%25", "").replace("%2C", "").replace("%3A", "").replace("%0A", "") \
            .replace("%0D", ""), line
        assert path.name.replace("%", "%25").replace(",", "%2C").replace(":", "%3A") in name, line
    assert "Traceback" not in text and "\r" not in text and not marker.exists()
