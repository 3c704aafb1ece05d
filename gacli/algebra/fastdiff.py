"""One-pass, memoised directional derivatives of SymPy expressions.

The total time derivative (eqs. 14.14, 14.17) and the Jacobians of positions
(eq. 14.6) and of the potential (eq. 14.13) were formed with one ``sp.diff``
per symbol, each of which walks the whole expression again and goes through
SymPy's general ``Derivative`` machinery. Here the expression is walked once,

    D e = Σ_s ∂e/∂s · seeds[s],

with the sum, product, power and function rules, and every subexpression's
derivative is kept in a memo: the positions of a chain of bodies share most
of their subexpressions, so each one is differentiated once.

The result is mathematically the derivative ``sp.diff`` gives; its form may
differ (e.g. ``2*sin(x)*cos(x)`` is reached as ``2*sin(x)**1*cos(x)``, which
SymPy writes the same way).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

import sympy as sp

from gacli.algebra.canonical import mul
from gacli.algebra.coerce import as_expr
from gacli.algebra.graph import postorder

_ZERO = sp.S.Zero


class Differentiator:
    """``D e = Σ_s ∂e/∂s · seeds[s]`` for the symbols ``s`` in ``seeds``; other symbols are constant.

    One instance keeps its memo for all the expressions it is applied to,
    so apply one instance to all the entries of a matrix.
    """

    def __init__(self, seeds: Mapping[sp.Symbol, sp.Expr], *, free: Mapping[sp.Basic, frozenset] | None = None):
        self._seeds = {s: as_expr(v) for s, v in seeds.items() if v != 0}
        # When given (see jacobian), the seed symbols in each subexpression: a
        # subexpression free of them has derivative zero without a walk.
        self._memo: dict[sp.Basic, sp.Expr] = {}
        if free is not None:
            seeds_here = frozenset(self._seeds)
            self._memo.update((node, _ZERO) for node, symbols in free.items() if not symbols & seeds_here)

    def __call__(self, expr) -> sp.Expr:
        expr = as_expr(expr)
        if not self._seeds:
            return _ZERO
        return self._derivative(expr)

    def _derivative(self, expr: sp.Basic) -> sp.Expr:
        known = self._memo.get(expr)
        if known is None:
            known = self._memo[expr] = self._rule(expr)
        return known

    def _rule(self, expr: sp.Basic) -> sp.Expr:
        if expr.is_Symbol:
            return self._seeds.get(expr, _ZERO)
        if expr.is_Atom:
            return _ZERO
        if expr.is_Add:
            return _sum([d for d in map(self._derivative, expr.args) if d is not _ZERO])
        if expr.is_Mul:
            return _product_rule(expr.args, [self._derivative(a) for a in expr.args])
        if expr.is_Pow:
            return self._power_rule(expr)
        if _has_plain_chain_rule(expr):
            return self._chain_rule(expr)
        return self._fallback(expr)

    def _power_rule(self, expr: sp.Pow) -> sp.Expr:
        base, exp = expr.args
        dbase, dexp = self._derivative(base), self._derivative(exp)
        if dexp is _ZERO:
            # d(b^e) = e b^(e-1) db for a constant exponent (the common case: squares, sqrt, 1/x).
            return _ZERO if dbase is _ZERO else exp * sp.Pow(base, exp - 1) * dbase
        return expr * (dexp * sp.log(base) + exp * dbase / base)

    def _chain_rule(self, expr: sp.Function) -> sp.Expr:
        # d f(a_1, ..., a_m) = Σ_i ∂f/∂a_i · d a_i, with ∂f/∂a_i = f.fdiff(i) (as Function._eval_derivative).
        terms = []
        for i, arg in enumerate(expr.args, start=1):
            darg = self._derivative(arg)
            if darg is _ZERO:
                continue
            partial = expr.fdiff(i)
            if partial.has(sp.Derivative):
                return self._fallback(expr)
            terms.append(mul(partial, darg))
        return _sum(terms)

    def _fallback(self, expr: sp.Basic) -> sp.Expr:
        # Anything with its own derivative rule (Piecewise, Abs, ...): SymPy's diff, symbol by symbol.
        free = expr.free_symbols
        return sp.Add(*[sp.diff(expr, s) * v for s, v in self._seeds.items() if s in free])


def _has_plain_chain_rule(expr: sp.Basic) -> bool:
    """Whether SymPy differentiates ``expr`` by the chain rule through ``fdiff`` (sin, cos, atan2, exp, ...)."""
    return isinstance(expr, sp.Function) and type(expr)._eval_derivative is sp.Function._eval_derivative


def _product_rule(factors: Sequence[sp.Expr], derivatives: Sequence[sp.Expr]) -> sp.Expr:
    terms = [mul(*factors[:i], d, *factors[i + 1:])
             for i, d in enumerate(derivatives) if d is not _ZERO]
    return _sum(terms)


def _sum(terms: list[sp.Expr]) -> sp.Expr:
    """``sp.Add(*terms)``, without SymPy's constructor and cache for no term or one.

    Most partial derivatives of a term are zero (a chain's position depends
    on one coordinate per term) and Add() is 0, Add(e) is e: the same objects.
    """
    if not terms:
        return _ZERO
    if len(terms) == 1:
        return terms[0]
    return sp.Add(*terms)


def jacobian(exprs: Iterable[sp.Expr], symbols: Sequence[sp.Symbol]) -> sp.Matrix:
    """∂e_i/∂s_j; one memoised walk per symbol, shared by all the expressions."""
    rows = jacobian_rows(exprs, symbols)
    return sp.Matrix(len(rows), len(symbols), [d for row in rows for d in row])


def jacobian_rows(exprs: Iterable[sp.Expr], symbols: Sequence[sp.Symbol]) -> list[list[sp.Expr]]:
    """:func:`jacobian` as a list of rows (no SymPy matrix to build)."""
    exprs = [as_expr(e) for e in exprs]
    free = _symbols_below(exprs, frozenset(symbols))
    present = frozenset().union(*(free[e] for e in exprs))
    zeros = [_ZERO] * len(exprs)
    columns = []
    for s in symbols:
        # A wide system's point depends on one coordinate of hundreds: a walk
        # per absent symbol would make the Jacobians of n points cost n².
        if s not in present:
            columns.append(zeros)
            continue
        partial = Differentiator({s: sp.S.One}, free=free)
        columns.append([partial(e) if s in free[e] else _ZERO for e in exprs])
    return [list(row) for row in zip(*columns)] if columns else [[] for _ in exprs]


def _symbols_below(exprs: Sequence[sp.Basic], wanted: frozenset) -> dict[sp.Basic, frozenset]:
    """For each distinct subexpression, which of ``wanted`` it contains (one walk, arguments first)."""
    below: dict[sp.Basic, frozenset] = {}
    empty: frozenset = frozenset()
    for node in postorder(exprs):
        if node.args:
            found = empty.union(*(below[a] for a in node.args))
        else:
            found = frozenset((node,)) if node in wanted else empty
        below[node] = found
    return below

