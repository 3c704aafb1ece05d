"""Seeded generic points: where the numeric tests look at an expression.

A random point of positive values of order one avoids the special places
(zero, the integers) where an expression that is not zero can vanish; the
seed makes every answer the same on every run, whatever PYTHONHASHSEED.
"""

from __future__ import annotations

import random

import sympy as sp

SEED = 20261122
SAMPLE_INTERVAL = (0.3, 1.7)


def sample_points(symbols, count: int, seed: int = SEED, signed: bool = False,
                  interval: tuple[float, float] = SAMPLE_INTERVAL) -> list[dict[sp.Symbol, float]]:
    """``count`` deterministic generic points: values in ``interval`` (either sign when ``signed``)."""
    rng = random.Random(seed)
    ordered = sorted(symbols, key=lambda s: s.name)
    points = []
    for _ in range(count):
        point = {}
        for s in ordered:
            value = rng.uniform(*interval)
            point[s] = -value if signed and rng.random() < 0.5 else value
        points.append(point)
    return points


def random_point(symbols, seed: int) -> dict[sp.Symbol, sp.Float]:
    """One point of values in [0.4, 1.6] as SymPy Floats, the draw of ``kinematics.random_point``."""
    (point,) = sample_points(symbols, 1, seed, interval=(0.4, 1.6))
    return {s: sp.Float(v) for s, v in point.items()}
