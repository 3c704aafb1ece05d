"""A coefficient of a reduced polynomial multiplied out only where that is shorter and cheap.

gacli.algebra.trig sums each monomial's coefficient once; a sum of rates
may cancel only multiplied out, but a sum of parameters (m₁ + m₂) reads
better whole, and SymPy's expand of a quotient by a sum is unbounded (a
Chaplygin ball's force: 14 terms, 1,877 nodes, minutes). Both bounds are
counted before SymPy runs.
"""

from __future__ import annotations

import functools

import sympy as sp

from gacli.algebra.graph import expands_within, postorder, trees_within

# A coefficient is multiplied out to see whether it cancels only below this many terms.
COEFFICIENT_TERMS = 400
COEFFICIENT_NODES = 1_000


@functools.lru_cache(maxsize=8192)  # the same coefficients are rebuilt again by every later reduction of a tidy
def multiplied_out(total: sp.Expr) -> sp.Expr:
    """A coefficient multiplied out where that is shorter (sums of rates that cancel only so; a sum
    of parameters, m₁ + m₂, stays whole where it would lengthen), and only where a term has a sum
    to open: a loop's monomials over its dead point stay as many terms."""
    if not total.is_Add or not any(map(_distributes, total.args)) or \
            not expands_within(total, COEFFICIENT_TERMS) or not small_or_whole(total):
        return total
    expanded = sp.expand(total, power_base=False, power_exp=False, log=False)  # products and powers of sums alone
    return expanded if len(sp.Add.make_args(expanded)) < len(total.args) else total


def small_or_whole(total: sp.Expr) -> bool:
    """Small, or no quotient by a sum: the term count sees one as a factor, and expand of a Chaplygin
    ball's force (14 terms, 1,877 nodes, 50 such quotients) ran for minutes."""
    return trees_within([total], COEFFICIENT_NODES) or not any(
        n.is_Pow and n.exp.is_negative and n.base.is_Add for n in postorder([total]))


def _distributes(term: sp.Expr) -> bool:
    """Whether a term has a sum, or a positive power of one, among its factors."""
    return any((f.base if f.is_Pow and f.exp.is_positive else f).is_Add for f in sp.Mul.make_args(term))
