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

import sympy as sp

from gacli.algebra import trig
from gacli.algebra.graph import is_small, postorder

# Angles past which no pair is tried: each pair costs two reductions.
_MAX_ANGLES = 4
# Distinct subexpressions past which an expression is left as it is: the
# reductions it would take are the ones trig refuses anyway.
_MAX_NODES = 4_000


def relative(expr: sp.Expr, beside: sp.Expr = sp.S.One) -> sp.Expr:
    """``expr`` with pairs of its angles written through their difference, where that is shorter.

    ``beside`` is what the result will stand with (a quotient's denominator):
    a pair it holds is not rewritten either.
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
        for trial in (_through_difference(best, a, b), _through_difference(best, b, a)):
            # Only where the pair leaves altogether: an expression still holding θ
            # or θ_T on its own beside θ − θ_T is no longer in one normal form, and
            # its products with others then cancel less (a snakeboard's grew by 40 %).
            size = sp.count_ops(trial)
            if size < best_size and not {a, b} & set(_angles(trial)):
                best, best_size = trial, size
    return best


def _through_difference(expr: sp.Expr, kept: sp.Symbol, gone: sp.Symbol) -> sp.Expr:
    """``expr`` with ``gone`` written as ``kept`` − (kept − gone), distributed and reduced."""
    difference = kept - gone
    if sp.sin(difference).could_extract_minus_sign():
        difference = -difference  # sin(θ_T − θ) is printed as −sin(θ − θ_T) anyway
    sign = 1 if difference == kept - gone else -1
    # The difference is reduced as a plain angle d, and only then written out: as
    # θ − θ_T beside θ, the reduction would write it back into θ and θ_T
    # (gacli.algebra.angle_sums).
    d = sp.Dummy("d", real=True)
    replacement = {  # gone = kept − sign·d
        sp.sin(gone): sp.sin(kept) * sp.cos(d) - sign * sp.cos(kept) * sp.sin(d),
        sp.cos(gone): sp.cos(kept) * sp.cos(d) + sign * sp.sin(kept) * sp.sin(d),
    }
    reduced = trig.reduce(expr.xreplace(replacement), cancel=True)
    return reduced if d not in reduced.free_symbols else reduced.xreplace({d: difference})


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
