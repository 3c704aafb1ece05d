"""Issue 33, third round: what the second round left (docs/check.md, docs/generated-code.md, docs/verify.md).

Each test names the class of the issue it belongs to.
"""

from __future__ import annotations

import re

from gacli.check import capped
from gacli.errors import Diagnostic, Location

_LOCATED = re.compile(r"^[^:]+:\d+:\d+: (error|warning|note): ")


def _problems(severities: str) -> list[Diagnostic]:
    kinds = {"e": "error", "w": "warning", "n": "note"}
    return [Diagnostic(Location("m.yaml", i + 1, 3), f"problem {i}", severity=kinds[s])
            for i, s in enumerate(severities)]


# -- class 3: a flood of problems, every line located --------------------------------------------

def test_a_capped_report_ends_in_one_located_line_that_counts_the_rest():
    shown = capped(_problems("e" * 250), limit=100)
    assert len(shown) == 101
    assert all(_LOCATED.match(str(d)) for d in shown)
    assert str(shown[-1]) == "m.yaml:101:3: error: 150 more problems not shown (150 errors)"


def test_errors_past_the_limit_keep_the_file_failing():
    shown = capped(_problems("w" * 100 + "n" + "e" + "w" * 3), limit=100)
    assert all(d.severity == "warning" for d in shown[:100])
    assert shown[-1].severity == "error"
    assert shown[-1].message == "5 more problems not shown (1 error, 3 warnings, 1 note)"
    assert shown[-1].location == Location("m.yaml", 101, 3)


def test_a_report_within_the_limit_is_left_as_it_is():
    problems = _problems("ewn")
    assert capped(problems, limit=3) == tuple(problems)
