"""The Whipple bicycle's self-stable speeds by ``linearize --sweep`` (Meijaard et al. 2007).

The paper (Proc. R. Soc. A 463, 1955-1982, Table 2) gives the weave speed
4.292382534 m/s and the capsize speed 6.024262018 m/s for the benchmark;
between them the upright, straight-ahead motion is stable. Its eigenvalues
along the sweep are compared with those of the paper's own linear equations
M q̈ + v C₁ q̇ + (g K₀ + v² K₂) q = 0 (tests/test_bicycle.py holds them as
SymPy's bicycle test does), at every speed swept.
"""

from __future__ import annotations

import functools
import re

import numpy as np
from typer.testing import CliRunner

from conftest import SYSTEMS, derived
from test_bicycle import REAR_RADIUS, reference, sorted_eigenvalues

PAPER_WEAVE, PAPER_CAPSIZE = 4.292382534, 6.024262018


@functools.lru_cache(maxsize=1)
def swept():
    from gacli.steady.sweep import sweep

    return sweep(derived("whipple_bicycle"), "dot(wheel_R)", 0.0, 10.0 / REAR_RADIUS, points=41)


def test_stable_speed_interval_is_the_papers():
    result = swept()
    assert result.state == ("roll", "steer", "dot(roll)", "dot(wheel_R)", "dot(steer)")
    assert result.zero_roots == 1     # another forward speed: the family's neighbour
    assert len(result.intervals) == 1
    low, high = (REAR_RADIUS * v for v in result.intervals[0])
    assert abs(low - PAPER_WEAVE) < 1e-4 and abs(high - PAPER_CAPSIZE) < 1e-4


def test_eigenvalues_along_the_sweep_are_the_papers():
    result = swept()
    for rate, ours in zip(result.values, result.eigenvalues):
        paper = np.append(sorted_eigenvalues(reference(REAR_RADIUS * rate)), 0.0)
        np.testing.assert_allclose(sorted_eigenvalues(np.diag(ours)), sorted_eigenvalues(np.diag(paper)),
                                   rtol=1e-8, atol=1e-8)


def test_sweep_command_prints_the_interval():
    from gacli.cli import app

    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "whipple_bicycle.yaml"),
                                      "--sweep", "dot(wheel_R)=12:22:6"])
    assert result.exit_code == 0, result.output
    found = re.search(r"stable for dot\(wheel_R\) in \[([-0-9.e]+), ([-0-9.e]+)\]", result.output)
    assert found, result.output
    assert abs(REAR_RADIUS * float(found.group(1)) - PAPER_WEAVE) < 1e-4
    assert abs(REAR_RADIUS * float(found.group(2)) - PAPER_CAPSIZE) < 1e-4
