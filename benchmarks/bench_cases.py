"""The benchmark cases: a gacli system file and, where written, the same system for KanesMethod.

=========  =====================================================  ==================
case       system                                                 sizes
=========  =====================================================  ==================
pendulum   n-link planar pendulum, point masses, absolute angles  n links, k = n
chain      n rigid links joined by ball joints, 3 angles each     n links, k = 3n
disk       thin disk rolling without slipping (nonholonomic)      one size, k = 3
=========  =====================================================  ==================

Pendulum and chain files are generated at run time (``make_pendulum.py``,
``make_chain.py``) into a scratch directory; the disk is
``benchmarks/cases/rolling_disk.yaml``. The Whipple bicycle has a script
of its own, ``bench_bicycle.py``: its equations are compared and counted
as graphs of shared subexpressions, which this generic harness does not do.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import bench_kane
from make_chain import write_chain
from make_pendulum import write_pendulum

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

# A script in benchmarks/ has benchmarks/, not the checkout, first on sys.path:
# `import gacli` would find an installed gacli (an editable install of another
# checkout, say) and the benchmark would measure that code. This checkout first.
if sys.path[0] != str(ROOT):
    sys.path.insert(0, str(ROOT))

CASE_NAMES = ("pendulum", "chain", "disk")
DEFAULT_CASES = ("pendulum", "chain", "disk")


@dataclass(frozen=True)
class Case:
    name: str
    size: int | None                 # links, or None for a one-size case
    path: Path                       # the gacli system file
    kane: Callable[[], bench_kane.KaneModel] | None
    coordinate_range: float = 1.0    # coordinates are drawn from [-c, c]
    default_parameters: bool = False # the file's parameter values (else random in [0.5, 1.5])

    @property
    def label(self) -> str:
        return self.name if self.size is None else f"{self.name} n={self.size}"


def pendulum(n: int, scratch: Path) -> Case:
    return Case("pendulum", n, write_pendulum(n, scratch), lambda: bench_kane.pendulum(n))


def chain(n: int, scratch: Path) -> Case:
    return Case("chain", n, write_chain(n, scratch), lambda: bench_kane.chain(n))


def disk() -> Case:
    return Case("disk", None, HERE / "cases" / "rolling_disk.yaml", bench_kane.rolling_disk)


def cases(names: list[str], sizes: list[int], chain_sizes: list[int], scratch: Path) -> tuple[list[Case], list[str]]:
    """The cases to run, in order, and notes on the ones skipped."""
    out, skipped = [], []
    for name in names:
        if name == "pendulum":
            out += [pendulum(n, scratch) for n in sizes]
        elif name == "chain":
            out += [chain(n, scratch) for n in chain_sizes]
        elif name == "disk":
            out.append(disk())
        elif name == "bicycle":
            skipped.append("bicycle: run python benchmarks/bench_bicycle.py")
        else:
            raise ValueError(f"unknown case {name!r} (one of {', '.join(CASE_NAMES)})")
    return out, skipped
