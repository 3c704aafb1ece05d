"""Constraints not linear in the rates (Appell-Hamel, Chetaev), as relations g(q, ṙ, t) = 0.

A system file may state such a constraint in two ways a reader of Pars ch.
XIV or Neimark and Fufaev recognises:

* homogeneous of degree one in the differentials, ``dz = -c*sqrt(dx**2 + dy**2)``:
  dividing by dt gives g(q, ṙ, t) = 0 with each d(x) read as ẋ and dt as 1;
* an explicit rate relation, ``dot(z) = -c*sqrt(dot(x)**2 + dot(y)**2)``
  (terms in t and rheonomic terms allowed).

The chapter's procedure carries over once the relation is solved for one
dependent rate, ṙ_d = f(q, ṙ_others, t) (eq. 14.7 becomes nonlinear in u):
virtual displacements follow Chetaev's rule, δr_d = Σ ∂f/∂u_s δq_s, so the
rows of β are ∂f/∂u (functions of u as well as q), β₀ = f − β u, and the
dependent acceleration is d/dt of f, linear in u̇ (eq. 14.14's form). The
linearization used by the rest of gacli is the row A = ∂g/∂ṙ with
a₀ = g − A ṙ: A ṙ + a₀ = g identically, and differentiating it with ṙ held
fixed gives the acceleration-level constraint with r̈'s coefficient A,
exactly as for a Pfaffian row. See docs/nonlinear.md.
"""

from __future__ import annotations

import random
from collections.abc import Sequence
import sympy as sp

from gacli.algebra import symbols as S
from gacli.model import RateRelation

_SEED = 20261124
_POINTS = 4


def rate_form(expr: sp.Expr, rate_names: Sequence[str]) -> tuple[sp.Expr | None, str]:
    """(g, kind) for a constraint that is not a Pfaffian form, or (None, reason) when it is not a relation.

    The reason "homogeneous" means: differentials, but not homogeneous of
    degree one in them (the caller names the offending term).

    ``kind`` is "rates" (written with dot(x)) or "homogeneous" (differentials,
    homogeneous of degree one). ``expr`` is lhs − rhs of the file's text.
    """
    diffs = {S.differential(n): S.rate(n) for n in rate_names}
    rates = {S.rate(n) for n in rate_names}
    free = expr.free_symbols
    has_diffs, has_rates = bool(free & (set(diffs) | {S.DT})), bool(free & rates)
    if has_diffs and has_rates:
        return None, "a constraint is written either with differentials (dx) or with rates (dot(x)), not both"
    if has_rates:
        return expr, "rates"
    if not _homogeneous_of_degree_one(expr, [*diffs, S.DT]):
        return None, "homogeneous"
    return expr.xreplace({**diffs, S.DT: sp.S.One}), "homogeneous"


def _homogeneous_of_degree_one(expr: sp.Expr, differentials: Sequence[sp.Symbol]) -> bool:
    """g(2 d) = 2 g(d) at generic points (all differentials and dt scaled together)."""
    scaled = expr.xreplace({d: 2 * d for d in differentials})
    others = sorted(expr.free_symbols, key=lambda s: s.name)
    rng = random.Random(_SEED)
    for _ in range(_POINTS):
        point = {s: sp.Float(rng.uniform(0.3, 1.7), 30) for s in others}
        try:
            a, b = complex(scaled.xreplace(point).evalf(30)), complex(2 * expr.xreplace(point).evalf(30))
        except (TypeError, ValueError, ArithmeticError):
            return False
        if abs(a - b) > 1e-20 * max(1.0, abs(b)):
            return False
    return True


def solve_for_rate(g: sp.Expr, rate_names: Sequence[str], preferred: str | None,
                   independent: Sequence[str] | None) -> RateRelation | str:
    """g = 0 solved for the rate it determines, or a reason why it cannot be.

    The rate must enter g linearly (∂g/∂ṙ_d free of ṙ_d and not zero). The
    one written alone on the left (``dot(z) = ...``, ``dz = ...``) is taken
    when it qualifies; else the last declared candidate that is not named
    independent.
    """
    candidates = [n for n in rate_names if _enters_linearly(g, S.rate(n))]
    if preferred is not None and preferred in candidates:
        dependent = preferred
    else:
        free = [n for n in candidates if not independent or n not in independent]
        if not free:
            present = [f"dot({n})" for n in rate_names if S.rate(n) in g.free_symbols]
            return ("this relation cannot be solved for a dependent rate: it is not linear in any of "
                    f"{', '.join(present) or 'its rates'} that may depend on the others; write it solved "
                    "for the rate it determines, e.g. dot(y) = sqrt(v**2 - dot(x)**2)")
        dependent = free[-1]
    rate = S.rate(dependent)
    slope = sp.diff(g, rate)
    solution = rate - g / slope
    return RateRelation(g, dependent, _tidy(solution))


def _enters_linearly(g: sp.Expr, rate: sp.Symbol) -> bool:
    if rate not in g.free_symbols:
        return False
    slope = sp.diff(g, rate)
    return rate not in slope.free_symbols and slope != 0


def _tidy(expr: sp.Expr) -> sp.Expr:
    """Cancel what solving left (ż − (ż + c√…)/1 is −c√…), while it is cheap."""
    numerator, denominator = sp.fraction(sp.together(expr))
    return sp.expand(numerator) / denominator if sp.count_ops(numerator) < 400 else expr


def split(f: sp.Expr, speeds: Sequence[sp.Symbol]) -> tuple[list[sp.Expr], sp.Expr]:
    """(β row, β₀) of ṙ = f(q, u, t): β = ∂f/∂u (Chetaev's virtual displacements), β₀ = f − β u."""
    row = [sp.diff(f, u) for u in speeds]
    rest = f - sp.Add(*[b * u for b, u in zip(row, speeds)])
    return row, _tidy(rest)


def linearized_row(g: sp.Expr, rate_names: Sequence[str]) -> tuple[tuple[tuple[str, sp.Expr], ...], sp.Expr]:
    """(coefficients, dt) with A = ∂g/∂ṙ and a₀ = g − A ṙ, so that A ṙ + a₀ = g."""
    coefficients = tuple((n, c) for n in rate_names if (c := sp.diff(g, S.rate(n))) != 0)
    rest = g - sp.Add(*[c * S.rate(n) for n, c in coefficients])
    return coefficients, _tidy(rest)
