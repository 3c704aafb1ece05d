"""Vectors as 3-tuples of expressions along some frame's axes, and the passes that give velocities.

A *pass* is a vector ρ of coordinate rates: the velocities it gives are
linear in it (transport theorem), so one function computes the partial
velocities (ρ = the rates of u_r = 1, eq. 14.8), the actual velocities
(ρ = q̇, eq. 14.7) and the part the dependent accelerations add (ρ = γ,
eq. 14.14) alike.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import sympy as sp

ZERO = sp.S.Zero
ONE = sp.S.One
ZV = (ZERO, ZERO, ZERO)


@dataclass(frozen=True, eq=False)
class Pass:
    """Coordinate rates ρ (coordinate name → expression; absent: 0), named by ``key`` for the caches;
    ``timed``: with ṫ = 1, so that angles and positions that hold time add their ∂/∂t (the actual
    velocities, and the rows' a₀), where a partial velocity or γ has none."""

    key: str
    rho: Mapping[str, sp.Expr]
    timed: bool = False
    # The rates of a pair of coordinates turned back by the heading they were solved along
    # (gacli.mechanics.program.solve.turned_columns), by the pair's names; empty without a heading.
    along: Mapping[str, sp.Expr] = None

    def rate(self, name: str) -> sp.Expr:
        return self.rho.get(name, ZERO)

    def rate_along(self, name: str) -> sp.Expr:
        """The rate of ``name`` along the heading (see ``along``)."""
        return (self.along or {}).get(name, ZERO)


def add(*vs: Sequence) -> tuple:
    return tuple(sp.Add(*(v[i] for v in vs)) for i in range(3))


def neg(v: Sequence) -> tuple:
    return tuple(-c for c in v)


def scale(k, v: Sequence) -> tuple:
    return tuple(k * c for c in v)


def cross(a: Sequence, b: Sequence) -> tuple:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a: Sequence, b: Sequence) -> sp.Expr:
    return sp.Add(*(x * y for x, y in zip(a, b)))


def unit(i: int) -> tuple:
    return tuple(ONE if j == i else ZERO for j in range(3))


def matrix_times(rows: Sequence[Sequence], v: Sequence) -> tuple:
    """A 3 × 3 matrix (rows) times a vector."""
    return tuple(dot(row, v) for row in rows)


def turned(v: Sequence, axis: int, c, s) -> tuple:
    """v turned about a frame axis by the angle of cosine c and sine s (R v; with −s, turned back)."""
    j, k = (axis + 1) % 3, (axis + 2) % 3
    out = list(v)
    out[j], out[k] = c * v[j] - s * v[k], s * v[j] + c * v[k]
    return tuple(out)


def isotropic(inertia: Sequence[Sequence]) -> bool:
    """I = λ 1 (a uniform sphere or shell, a cube): its rotation terms read alike along any axes."""
    return all(inertia[i][j] == (inertia[0][0] if i == j else 0) for i in range(3) for j in range(3))
