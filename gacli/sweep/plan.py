"""The points of a sweep: a grid (every combination) or a random sample, as plain numbers.

.. code:: text

    --grid   NAME=START:STOP:COUNT   COUNT evenly spaced values, both ends included
    --random NAME=LOW:HIGH           uniform in [LOW, HIGH), --samples draws, --seed

Several ``--grid`` options make the product of their values, the last one
varying fastest (as nested loops written in that order); several
``--random`` options draw each point's values together, in the order given.
A name is a parameter or a state (for ``linearize`` also an input): what it
is is found once the system is loaded (:func:`classify`). The values are
floats written in the options, never expressions: nothing here evaluates text.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from gacli.errors import GacliError

MAX_POINTS = 10_000_000     # past this a grid is a typing mistake, not a study


class SweepError(GacliError, ValueError):
    """Options of a sweep that cannot be run."""


@dataclass(frozen=True)
class Axis:
    """One swept name and the text it came from (for messages)."""

    name: str
    option: str        # "--grid" or "--random"
    text: str
    values: tuple[float, ...]   # the grid's values; for --random, (low, high)


@dataclass(frozen=True)
class Plan:
    """The swept names and every point, in the order of the table's rows."""

    names: tuple[str, ...]
    points: tuple[tuple[float, ...], ...]

    def __len__(self) -> int:
        return len(self.points)


def plan(grid: Sequence[str] = (), random: Sequence[str] = (), samples: int | None = None, seed: int = 0) -> Plan:
    """The points of ``--grid`` or ``--random`` options.

    >>> plan(grid=["a=0:1:3", "b=5:6:2"]).points
    ((0.0, 5.0), (0.0, 6.0), (0.5, 5.0), (0.5, 6.0), (1.0, 5.0), (1.0, 6.0))
    """
    if grid and random:
        raise SweepError("give --grid or --random, not both: a sweep is a grid or a random sample")
    if not grid and not random:
        raise SweepError("nothing to sweep: give --grid NAME=START:STOP:COUNT or --random NAME=LOW:HIGH")
    if random and not samples:
        raise SweepError("--random needs --samples N, the number of points to draw")
    if grid and samples:
        raise SweepError("--samples goes with --random; a grid has as many points as its values")
    if samples and samples > MAX_POINTS:  # refused before any draw: a billion points fill the memory first
        raise SweepError(f"--samples {samples}: more than {MAX_POINTS} points")
    if seed < 0:
        raise SweepError(f"--seed {seed}: a seed is a whole number of at least 0")
    axes = [_axis(text, "--grid" if grid else "--random") for text in (grid or random)]
    names = [a.name for a in axes]
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise SweepError(f"swept twice: {', '.join(repeated)}")
    if grid:
        total = math.prod(len(a.values) for a in axes)
        if total > MAX_POINTS:
            raise SweepError(f"the grid has {total} points, more than {MAX_POINTS}")
        return Plan(tuple(names), tuple(itertools.product(*(a.values for a in axes))))
    rng = np.random.default_rng(seed)
    draws = rng.uniform([a.values[0] for a in axes], [a.values[1] for a in axes], size=(samples, len(axes)))
    return Plan(tuple(names), tuple(tuple(float(v) for v in row) for row in draws))


def _axis(text: str, option: str) -> Axis:
    name, equals, spec = text.partition("=")
    name, parts = name.strip(), [p.strip() for p in spec.split(":")]
    expected = "START:STOP:COUNT" if option == "--grid" else "LOW:HIGH"
    if not equals or not name or len(parts) != expected.count(":") + 1:
        raise SweepError(f"{option} '{text}': expected NAME={expected}")
    numbers = [_number(option, text, p) for p in parts[:2]]
    if option == "--random":
        if not numbers[0] < numbers[1]:
            raise SweepError(f"{option} '{text}': LOW must be below HIGH")
        return Axis(name, option, text, tuple(numbers))
    count = _count(option, text, parts[2])
    values = np.linspace(numbers[0], numbers[1], count)
    return Axis(name, option, text, tuple(float(v) for v in values))


def _number(option: str, text: str, part: str) -> float:
    try:
        value = float(part)
    except ValueError:
        raise SweepError(f"{option} '{text}': '{part}' is not a number") from None
    if not math.isfinite(value):
        raise SweepError(f"{option} '{text}': '{part}' is not a finite number")
    return value


def _count(option: str, text: str, part: str) -> int:
    if not part.isdigit() or int(part) < 1:
        raise SweepError(f"{option} '{text}': COUNT '{part}' is not a whole number of at least 1")
    if int(part) > MAX_POINTS:  # before its values are made, not after
        raise SweepError(f"{option} '{text}': COUNT {part} is more than {MAX_POINTS} points")
    return int(part)


def classify(names: Sequence[str], parameters: Sequence[str], state: Sequence[str],
             others: Sequence[str] = ()) -> dict[str, str]:
    """Name → "parameter", "state" or "input"; every unknown name is one error."""
    kinds = {**{n: "input" for n in others}, **{n: "state" for n in state}, **{n: "parameter" for n in parameters}}
    unknown = [n for n in names if n not in kinds]
    if unknown:
        allowed = [*parameters, *state, *others]
        raise SweepError(f"not a parameter or state of the system: {', '.join(unknown)} "
                         f"(it has {', '.join(allowed) or 'none'})")
    return {n: kinds[n] for n in names}
