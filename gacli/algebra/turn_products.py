"""Sums of products of sines and cosines of whole combinations of angles, read as turns by a loop.

gacli.algebra.turns reads Σ c_m e^(i m·q) by writing every sine and cosine
through exponentials and calling SymPy's expand, which multiplies out the
whole expression: quadratic in the length of a position written as products
(a seven-link chain's angle sums multiplied out, 64 products of seven factors
in one coordinate, took a second at six links and was refused at seven). Here
each product is multiplied out on its own, as a table {m: c} whose numbers are
exact fractions, and the tables are added as they come, so the work is each
product's 2^(factors) terms and cancellation happens at once. Only the
coefficients that are left are made SymPy expressions. What this does not
read (an angle plus an offset, a float, an angle outside a sine or cosine) is
left to SymPy's expand, within its own smaller bound.
"""

from __future__ import annotations

from fractions import Fraction

import sympy as sp

# Tree nodes of an expression read here: each product costs 2^(its factors), at most TRIG_FACTORS.
PRODUCTS_NODES = 40_000
TRIG_FACTORS = 8

# A table: {(m, rest): (re, im)}, the term (re + i im)·rest·e^(i m·q); rest free of the angles, no number.
_ONE = (Fraction(1), Fraction(0))


class NotTurned(Exception):
    """An expression that holds the angles other than in sines and cosines of whole combinations."""


def products(expr: sp.Expr, angles: list[sp.Symbol]) -> dict[tuple, sp.Expr]:
    """{m: c_m} of gacli.algebra.turns.turns, c_m expanded; NotTurned where this reading does not apply."""
    index = {q: i for i, q in enumerate(angles)}
    table = _table(sp.S(expr), index, (0,) * len(angles))
    grouped: dict[tuple, list] = {}
    for (m, rest), (re, im) in table.items():
        if re or im:
            grouped.setdefault(m, []).append((sp.Rational(re.numerator, re.denominator)
                                              + sp.I * sp.Rational(im.numerator, im.denominator)) * rest)
    out = {}
    for m, parts in grouped.items():
        c = sp.expand(sp.Add(*parts))
        if c != 0:
            out[tuple(sp.Integer(k) for k in m)] = c
    return out


def _table(expr: sp.Expr, index: dict, zero: tuple) -> dict:
    if not expr.free_symbols & index.keys():
        return _constant(expr, zero)
    if expr.is_Add:
        out: dict = {}
        for term in expr.args:
            _add(out, _table(term, index, zero))
        return out
    if expr.is_Mul:
        out = {(zero, sp.S.One): _ONE}
        if sum(isinstance(f, (sp.sin, sp.cos)) for f in expr.args) > TRIG_FACTORS:
            raise NotTurned
        for factor in expr.args:
            out = _product(out, _table(factor, index, zero))
        return out
    if expr.is_Pow and expr.exp.is_Integer and 0 < expr.exp <= TRIG_FACTORS:
        base, out = _table(expr.base, index, zero), {(zero, sp.S.One): _ONE}
        for _ in range(int(expr.exp)):
            out = _product(out, base)
        return out
    if isinstance(expr, (sp.sin, sp.cos)):
        return _trig(expr, index, zero)
    raise NotTurned


def _constant(expr: sp.Expr, zero: tuple) -> dict:
    number, rest = expr.as_coeff_Mul()
    if number.is_Rational:
        return {(zero, rest): (Fraction(number.p, number.q), Fraction(0))}
    if number is sp.I or (number.is_Mul and number.args == (sp.S.NegativeOne, sp.I)):
        return {(zero, rest): (Fraction(0), Fraction(1 if number is sp.I else -1))}
    if number.is_Float:
        raise NotTurned  # SymPy's arithmetic of floats, not exact fractions: left to its expand
    return {(zero, expr): _ONE}


def _trig(f: sp.Expr, index: dict, zero: tuple) -> dict:
    m = list(zero)
    for term in sp.Add.make_args(f.args[0]):
        k, q = term.as_coeff_Mul()
        if q not in index or not k.is_Integer:
            raise NotTurned  # an offset, or a multiple that is not whole
        m[index[q]] += int(k)
    up, down = tuple(m), tuple(-k for k in m)
    half = Fraction(1, 2)
    if isinstance(f, sp.cos):  # (e^(iφ) + e^(−iφ))/2
        return {(up, sp.S.One): (half, Fraction(0)), (down, sp.S.One): (half, Fraction(0))}
    return {(up, sp.S.One): (Fraction(0), -half), (down, sp.S.One): (Fraction(0), half)}  # (e^(iφ) − e^(−iφ))/2i


def _add(into: dict, table: dict) -> None:
    for key, (re, im) in table.items():
        a, b = into.get(key, (0, 0))
        into[key] = (a + re, b + im)


def _product(left: dict, right: dict) -> dict:
    out: dict = {}
    one = sp.S.One
    for (m1, r1), (a, b) in left.items():
        for (m2, r2), (c, d) in right.items():
            rest = r2 if r1 is one else r1 if r2 is one else r1 * r2
            key = (tuple(x + y for x, y in zip(m1, m2)), rest)
            e, f = out.get(key, (0, 0))
            # Most factors are real or imaginary: a product of zeros is skipped, not computed.
            re = (a * c if a and c else 0) - (b * d if b and d else 0)
            im = (a * d if a and d else 0) + (b * c if b and c else 0)
            out[key] = (e + re, f + im)
    return out
