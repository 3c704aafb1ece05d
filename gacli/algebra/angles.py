"""Two angles about one axis written through the angle between them: cos(θ − θ_T).

A robot towing a trailer, each with its own heading (θ and θ_T, both about
N's z), holds the trailer's motion along its own heading axes as
sin θ sin θ_T + cos θ cos θ_T, and the trailer's rate θ̇_T, solved from
rolling rows written in N, the same way. Such a sum depends on the two angles
only through θ − θ_T, which is what a hand derivation writes; but
sin² + cos² = 1, used one angle at a time (:mod:`gacli.algebra.trig`),
never forms it, and every product of two such sums doubles the terms. The
equations of a robot with a trailer printed 310,000 characters so.

:func:`relative` tries, for each pair of angles of an expression, writing
one of them as the other minus their difference (θ_T = θ − (θ − θ_T)),
distributing, and reducing: where the expression depends on the pair only
through their difference, both angles leave it, and only then is the new
form kept (when shorter). The difference is an angle of its own to the
reduction, as an angle a file writes as a sum is: an expression that held
it beside θ or θ_T alone would still be right, but no longer in one normal
form, and the products formed from it later would cancel less.
"""

from __future__ import annotations

import itertools
import random

import sympy as sp

from gacli.algebra import trig
from gacli.algebra.graph import expands_within, is_small, postorder

# Angles past which no pair is tried: each pair costs two reductions.
_MAX_ANGLES = 4
# Distinct subexpressions past which an expression is left as it is: the
# reductions it would take are the ones trig refuses anyway.
_MAX_NODES = 4_000


def relative(expr: sp.Expr, beside: sp.Expr = sp.S.One, sums: bool = False) -> sp.Expr:
    """``expr`` with pairs of its angles written through their difference, where that is shorter.

    ``beside`` is what the result will stand with (a quotient's denominator):
    a pair it holds is not rewritten either. With ``sums``, through their sum too
    (for display: in a derivation, θ + φ beside the other angles' products cancelled
    less, and a trailer's generated code grew by 7 %).
    """
    if not isinstance(expr, sp.Expr) or not is_small(expr, _MAX_NODES):
        return expr
    angles = _angles(expr)
    if not 2 <= len(angles) <= _MAX_ANGLES or not isinstance(beside, sp.Expr):
        return expr
    angles = [a for a in angles if a not in set(_angles(beside))]
    if len(angles) < 2:
        return expr
    best, best_size = expr, sp.count_ops(expr)
    for a, b in itertools.combinations(angles, 2):
        if not _together(best, a, b):
            continue
        trials = [(a, b, -1), (b, a, -1)] if _only_through(best, a, b, -1) else []
        trials += [(a, b, 1)] if sums and _only_through(best, a, b, 1) else []
        for trial in [_through(best, *t) for t in trials]:  # each from the same form, as tried before
            # Only where the pair leaves altogether: an expression still holding θ
            # or θ_T on its own beside θ − θ_T is no longer in one normal form, and
            # its products with others then cancel less (a snakeboard's grew by 40 %).
            size = sp.count_ops(trial)
            if size < best_size and not {a, b} & set(_angles(trial)):
                best, best_size = trial, size
    return best


def reduced(expr: sp.Expr) -> sp.Expr:
    """A small closed form distributed, with sin² + cos² = 1 and its pairs of angles written through
    their difference: a loop's row turned about the coupler, cos θ₂ (−l sin θ₁) + sin θ₂ (l cos θ₁),
    is −l sin(θ₁ − θ₂)."""
    if not expands_within(expr, trig.MAX_TERMS):
        return expr  # no reduction would take it, and SymPy's expand of (x + y + z)**60 never ends
    return relative(trig.reduce(sp.expand(expr), cancel=True))


def reduced_by(expr: sp.Expr, rates: list[sp.Symbol], each=None) -> sp.Expr:
    """:func:`reduced` (or ``each``) one product of ``rates`` at a time: each term of a loop's
    velocity-product term holds the angles of one link, which only apart are written through their
    differences."""
    each = each or reduced
    if not expands_within(expr, trig.MAX_TERMS):
        return expr
    groups: dict[sp.Expr, list[sp.Expr]] = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        rest, rate = term.as_independent(*rates, as_Add=False)
        groups.setdefault(rate, []).append(rest)
    return sp.Add(*(rate * each(sp.Add(*rest)) for rate, rest in groups.items()))


def _through(expr: sp.Expr, kept: sp.Symbol, gone: sp.Symbol, sense: int) -> sp.Expr:
    """``expr`` with ``gone`` written through ``kept`` and their difference (``sense`` −1:
    gone = kept − (kept − gone)) or their sum (+1: gone = (kept + gone) − kept), reduced.

    A bead at s on a hoop that spins by φ is at s + φ from the leaned frame, and an
    expression of the pair through their sum is written with sin(s + φ), as by hand.
    """
    combined = kept + sense * gone
    if sense < 0 and sp.sin(combined).could_extract_minus_sign():
        combined = -combined  # sin(θ_T − θ) is printed as −sin(θ − θ_T) anyway
    # gone = α·kept + β·d with d the combined angle, reduced as a plain angle and only
    # then written out: as θ − θ_T beside θ, the reduction would write it back into
    # θ and θ_T (gacli.algebra.angle_sums).
    alpha = -sense
    beta = 1 if sp.expand(alpha * kept + combined - gone) == 0 else -1
    d = sp.Dummy("d", real=True)
    replacement = {
        sp.sin(gone): alpha * sp.sin(kept) * sp.cos(d) + beta * sp.cos(kept) * sp.sin(d),
        sp.cos(gone): sp.cos(kept) * sp.cos(d) - alpha * beta * sp.sin(kept) * sp.sin(d),
    }
    reduced = trig.reduce(expr.xreplace(replacement), cancel=True)
    return reduced if d not in reduced.free_symbols else reduced.xreplace({d: combined})


def _only_through(expr: sp.Expr, a: sp.Symbol, b: sp.Symbol, sense: int) -> bool:
    """Whether ``expr`` keeps its value when a and b move with a + sense·b fixed, at a
    seeded point: only then can both angles leave it, and the reductions are tried."""
    rng = random.Random(_SEED)
    # 30 digits: an entry of F is a small difference of large terms, which 15 would blur.
    point = {s: sp.Float(rng.uniform(0.4, 1.6), 30) for s in sorted(expr.free_symbols, key=lambda s: s.name)}
    moved = {**point, a: point[a] + _STEP, b: point[b] - sense * _STEP}
    try:
        here, there = complex(expr.xreplace(point)), complex(expr.xreplace(moved))
    except (TypeError, ValueError, ArithmeticError):
        return True  # not a number there (a function with no value): let the reduction say
    return abs(here - there) <= 1e-9 * (1 + abs(here))


_SEED = 20261122
_STEP = sp.Float("0.37", 30)


def _angles(expr: sp.Expr) -> list[sp.Symbol]:
    found = {node.args[0] for node in postorder([expr])
             if isinstance(node, (sp.sin, sp.cos)) and node.args[0].is_Symbol}
    return sorted(found, key=sp.default_sort_key)


def _together(expr: sp.Expr, a: sp.Symbol, b: sp.Symbol) -> bool:
    """Whether some product holds a sine or cosine of both angles: only there can they combine."""
    trig_of = {sp.sin(a), sp.cos(a)}, {sp.sin(b), sp.cos(b)}
    for node in postorder([expr]):
        if node.is_Mul:
            factors = {f.base if f.is_Pow else f for f in node.args}
            if factors & trig_of[0] and factors & trig_of[1]:
                return True
    return False
