"""The one printed form of a derivation's results: each entry of M, each Q, Q − F and G, tidied once.

Text (``gacli derive``, ``--steps``, ``gacli gibbs``) and LaTeX (``--format
latex``, ``--steps``, the notebook) all print these same expressions, each
through its own printer, so that G or an equation never reads one way in one
output and another way in the next (docs/latex.md).
"""

from __future__ import annotations

import functools
import sys
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.readable import Tidy, show
from gacli.mechanics.equations import Derivation


@functools.lru_cache(maxsize=4096)  # G and the equations read the same coefficients
def tidy(expr: sp.Expr) -> sp.Expr:
    """The display simplifier (:class:`gacli.algebra.readable.Tidy`) within its size bounds, memoised."""
    return Tidy(budget=sys.maxsize)(expr)


@dataclass(frozen=True)
class Coefficients:
    """The equations' coefficients as printed: M's nonzero entries and Q − F, each tidied once.

    ∂G/∂u̇_s = Σ_r M_sr u̇_r + (Q_s − F_s) (eq. 14.19), so these are also G's
    coefficients: G = ½ Σ M_rs u̇_r u̇_s + Σ (Q_s − F_s) u̇_s + (terms free of u̇).
    """

    mass: dict[tuple[int, int], sp.Expr]
    rest: tuple[sp.Expr, ...]
    forces: tuple[sp.Expr, ...]


# One derivation's coefficients kept while it is the one being printed (text and LaTeX of one command):
# [derivation, coefficients, the characters they print], or [derivation, None, a limit they printed past].
_LAST: list = []


def coefficients(d: Derivation, limit: int | None = None) -> Coefficients | None:
    """The printed coefficients of ``d`` (memoised for the last derivation asked); None as soon as
    they print in more than ``limit`` characters (M's off-diagonal entries counted twice, as the
    equations print them), so that a long system is not tidied in full only to be named instead."""
    if _LAST and _LAST[0] is d:
        _, known, chars = _LAST
        if known is not None:
            return known if limit is None or chars <= limit else None
        if limit is not None and limit <= chars:
            return None  # past this limit already: the pipeline asks, then the report asks again
    # The nonzero entries only, each once: tidying every entry of a row made this ~k² per row.
    # One budget for all of them (readable.STEP_BUDGET_OPS operations handed to simplify), in a
    # fixed order: a large system's coefficients past it are shown as derived, and what a
    # reader gets does not depend on the machine; text and LaTeX print these same ones.
    budgeted, tally = Tidy(), _Tally(limit)
    mass = {}
    for (i, j), e in sorted(d.mass_matrix.todok().items()):
        if j >= i and e != 0:
            mass[(i, j)] = tally(budgeted(e), 1 if i == j else 2)
            if tally.over:
                _LAST[:] = [d, None, limit]
                return None
    mass.update({(j, i): e for (i, j), e in list(mass.items())})
    # In this order, rest then forces, as ever: the budget decides which are tidied.
    rest, forces = [], []
    for out, exprs in ((rest, [q - f for q, f in zip(d.generalized_forces, d.forcing)]), (forces, d.generalized_forces)):
        for e in exprs:
            out.append(tally(budgeted(e)))
            if tally.over:
                _LAST[:] = [d, None, limit]
                return None
    c = Coefficients(mass, tuple(rest), tuple(forces))
    _LAST[:] = [d, c, tally.chars]
    return c


class _Tally:
    """Characters printed so far, against a limit (None: no limit)."""

    def __init__(self, limit: int | None) -> None:
        self.limit, self.chars = limit, 0

    @property
    def over(self) -> bool:
        return self.limit is not None and self.chars > self.limit

    def __call__(self, e: sp.Expr, times: int = 1) -> sp.Expr:
        if not self.over:
            self.chars += times * len(show(e))
        return e


# G's diagonal halves are read again ((5 sin² θ + 2)/10, not (sin² θ + 2/5)/2) while the
# coefficients print in at most this many characters.
HALVES_READ = 2_000


def gibbs(d: Derivation) -> sp.Expr:
    """G's acceleration terms, ½ Σ M_ii ü_i² + Σ_{i<j} M_ij ü_i ü_j + Σ (Q_i − F_i) ü_i (eqs. 14.17, 14.19)."""
    c, acc = coefficients(d), d.speed_rates
    short = sum(len(show(e)) for e in (*c.mass.values(), *c.rest)) <= HALVES_READ
    terms = [(tidy(e / 2) if short else e / 2) * acc[i] ** 2 if i == j else e * acc[i] * acc[j]
             for (i, j), e in sorted(c.mass.items()) if i <= j]
    return sp.Add(*terms, *(r * a for r, a in zip(c.rest, acc)))


def equation(d: Derivation, s: int) -> tuple[sp.Expr, sp.Expr]:
    """∂G/∂u̇_s = Q_s as (Σ_r M_sr u̇_r + (Q_s − F_s), Q_s) (eq. 14.19)."""
    c = coefficients(d)
    terms = [e * d.speed_rates[r] for (i, r), e in sorted(c.mass.items()) if i == s]
    return sp.Add(*terms) + c.rest[s], c.forces[s]


def kinematic(d: Derivation) -> list[tuple[str, sp.Expr]]:
    """(coordinate, its rate) of eq. (14.20) for each coordinate whose rate is not a speed itself."""
    return [(n, tidy(e)) for n, e in d.kinematic_equations if e != S.rate(n)]
