"""Build SymPy expressions from parsed trees, one whitelisted node at a time.

A :class:`Scope` says what each name means in the place the expression comes
from (a mass may name parameters only; a force may also name rates and
inputs). Numbers become exact rationals, so ``0.1`` is 1/10. Powers whose
numeric size would explode (``10**10**10**10``) are refused before SymPy
evaluates them.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp

from gacli.read.expr.grammar import BinOp, Call, Name, Neg, Node, Num, Rate, chain
from gacli.algebra.symbols import rate_name

MAX_EXPONENT = 100
_ADDITIVE = frozenset({"+", "-"})
_MULTIPLICATIVE = frozenset({"*", "/"})
MAX_DIGITS = 300

_FUNCTIONS = {
    "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "asin": sp.asin, "acos": sp.acos,
    "atan": sp.atan, "atan2": sp.atan2, "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh,
    "exp": sp.exp, "log": sp.log, "sqrt": sp.sqrt, "abs": sp.Abs, "sign": sp.sign,
}


class BuildError(Exception):
    """A name or construct that is not allowed where the expression stands."""

    def __init__(self, message: str, pos: int, hint: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.pos = pos
        self.hint = hint


@dataclass(frozen=True)
class Scope:
    """What names mean in one place of a system file.

    ``values`` maps a name to its expression, ``rates`` maps (name, order) to
    the expression of that time derivative, ``differentials`` maps ``dx`` to
    its symbol. ``refusals`` explains declared names that may not be used
    here; ``declared`` is every name the file declares (for "did you mean").
    """

    values: Mapping[str, sp.Expr]
    rates: Mapping[tuple[str, int], sp.Expr] = field(default_factory=dict)
    differentials: Mapping[str, sp.Symbol] = field(default_factory=dict)
    refusals: Mapping[str, str] = field(default_factory=dict)
    declared: frozenset[str] = frozenset()
    rate_note: str = ""


def build(node: Node, scope: Scope) -> sp.Expr:
    """Translate a parsed tree into SymPy under ``scope``; raises BuildError."""
    if isinstance(node, Num):
        return _number(node)
    if isinstance(node, Name):
        return _name(node, scope)
    if isinstance(node, Rate):
        return _rate(node, scope)
    if isinstance(node, Neg):
        return -build(node.operand, scope)
    if isinstance(node, Call):
        return _call(node, scope)
    if isinstance(node, BinOp):
        return _binop(node, scope)
    raise BuildError(f"unsupported expression node {type(node).__name__}", getattr(node, "pos", 0))


def _number(node: Num) -> sp.Expr:
    value = Fraction(node.text)
    return sp.Rational(value.numerator, value.denominator)


def _name(node: Name, scope: Scope) -> sp.Expr:
    if node.id in scope.values:
        return scope.values[node.id]
    if node.id in scope.differentials:
        return scope.differentials[node.id]
    if node.id == "pi":
        return sp.pi
    if node.id in scope.refusals:
        raise BuildError(scope.refusals[node.id], node.pos)
    if node.id == "t":  # always declared; a constant here (a mass, an inertia, a parameter's value)
        raise BuildError("'t' is not allowed here: this value may not depend on time", node.pos)
    raise BuildError(f"'{node.id}' is not declared", node.pos, _suggest(node.id, scope))


def _rate(node: Rate, scope: Scope) -> sp.Expr:
    key = (node.name, node.order)
    written = rate_name(node.name, node.order)
    if key in scope.rates:
        return scope.rates[key]
    if node.name == "t":  # t is no coordinate: its rate is 1
        raise BuildError(f"'{written}' is not allowed: t is time, not a coordinate (dot(t) would be 1)", node.pos)
    if node.name in scope.refusals or node.name in scope.declared:
        why = scope.refusals.get(node.name, "") or scope.rate_note
        reason = f"; {why}" if why else ""
        raise BuildError(f"'{written}' is not allowed here{reason}", node.pos)
    raise BuildError(f"'{node.name}' in '{written}' is not declared", node.pos, _suggest(node.name, scope))


def _suggest(word: str, scope: Scope) -> str:
    import difflib

    pool = sorted(set(scope.values) | set(scope.differentials) | set(scope.declared))
    close = difflib.get_close_matches(word, pool, n=1, cutoff=0.6)
    return f"did you mean '{close[0]}'?" if close else ""


def _call(node: Call, scope: Scope) -> sp.Expr:
    args = [build(arg, scope) for arg in node.args]
    try:
        value = _FUNCTIONS[node.func](*args)
    except (ArithmeticError, ValueError, TypeError, RecursionError):
        # SymPy evaluates numeric arguments eagerly and some extreme ones fail inside it.
        raise BuildError(f"{node.func}(...) cannot be evaluated for these arguments", node.pos) from None
    return _defined(value, node.pos)


def _defined(value: sp.Expr, pos: int) -> sp.Expr:
    """Refuse undefined numbers (0/0, log(0), atan2(0, 0)) where they appear."""
    if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise BuildError("the expression is undefined or infinite here", pos)
    return value


def _binop(node: BinOp, scope: Scope) -> sp.Expr:
    if node.op in _ADDITIVE:
        return _sum(node, scope)
    if node.op in _MULTIPLICATIVE:
        return _product(node, scope)
    left = build(node.left, scope)
    right = build(node.right, scope)
    _check_power(left, right, node.pos)
    return _defined(left**right, node.pos)


def _sum(node: BinOp, scope: Scope) -> sp.Expr:
    """A chain a ± b ± c ... as one Add of its terms.

    Adding term by term sorts and collects the growing sum again at every
    step, quadratic in its length; Add is associative (exact numbers, and
    each ``a - b`` is ``Add(a, -b)``), so the result is the same expression.
    The terms are built left to right, so the first error is the same too.
    """
    first, links = chain(node)
    terms = [build(first, scope)]
    for link in links:
        right = build(link.right, scope)
        terms.append(right if link.op == "+" else -right)
    return sp.Add(*terms)


def _product(node: BinOp, scope: Scope) -> sp.Expr:
    """A chain a * b / c ... as one Mul of its factors, each divisor refused where it is zero, as
    :func:`_sum` does for a sum (the same expression, built in one step)."""
    first, links = chain(node)
    factors = [build(first, scope)]
    for link in links:
        right = build(link.right, scope)
        if link.op == "/":
            if right == 0:
                raise BuildError("division by zero", link.pos)
            right = _defined(1 / right, link.pos)
        factors.append(right)
    return _defined(sp.Mul(*factors), node.pos)


def _check_power(base: sp.Expr, exponent: sp.Expr, pos: int) -> None:
    """Refuse powers whose evaluation would be huge, before SymPy tries it."""
    for part in (base, exponent):
        if part.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise BuildError("the expression is undefined or infinite here", pos)
    if not exponent.is_Number:
        return
    if abs(exponent) > MAX_EXPONENT:
        raise BuildError(f"exponent {_short(exponent)} is too large (the limit is {MAX_EXPONENT})", pos)
    if base.is_Number and base != 0:
        digits = _log10(base) * abs(float(exponent))
        if digits > MAX_DIGITS:
            raise BuildError(f"the number {_short(base)}**{_short(exponent)} is too large", pos)
    if base == 0 and exponent.is_negative:
        raise BuildError("division by zero (0 to a negative power)", pos)


def _log10(number: sp.Expr) -> float:
    """|log10 |number||, for exact rationals of any size (math.log10 takes big ints)."""
    if not number.is_Rational:
        return abs(math.log10(abs(float(number))))
    p, q = number.as_numer_denom()
    return abs(math.log10(abs(int(p))) - math.log10(int(q)))


def _short(value: sp.Expr) -> str:
    text = str(value)
    return text if len(text) <= 20 else text[:8] + "…" + text[-4:]
