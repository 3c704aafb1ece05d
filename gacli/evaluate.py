"""A bounded numeric evaluator: an expression's value at a point, or UndefinedValue.

sympy's evalf can run for hours on exp(exp(exp(100))); this walks the tree
once with mpmath and gives up on anything huge, complex or unknown. Split
out of :mod:`gacli.integrability`, which re-exports it.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

import mpmath
import sympy as sp

from gacli.coerce import as_expr

_DIGITS = 40
_RELATIVE_TOLERANCE = mpmath.mpf("1e-25")
_HUGE = mpmath.mpf("1e300")
_EXP_ARGUMENT_LIMIT = 1e4


class UndefinedValue(ValueError):
    """The expression has no finite real value at the point (or cannot be evaluated)."""


def evaluate(expr: sp.Expr, point: Mapping[sp.Symbol, float]) -> tuple[mpmath.mpf, mpmath.mpf]:
    """(value, scale) of ``expr`` at ``point``; ``scale`` bounds the size of the terms summed.

    Raises:
        UndefinedValue: outside the real domain, too large, or not evaluable.
    """
    if expr is sp.S.Zero:
        # Most entries of a wide system's M are zero: its check evaluates all k² of them.
        return mpmath.mpf(0), mpmath.mpf(0)
    with mpmath.workdps(_DIGITS):
        try:
            return _Evaluator(point).value(as_expr(expr))
        except (ZeroDivisionError, OverflowError, ValueError, TypeError, RecursionError) as exc:
            if isinstance(exc, UndefinedValue):
                raise
            raise UndefinedValue(str(exc)) from None


_ONE_ARGUMENT: dict[type, Callable] = {
    sp.sin: mpmath.sin, sp.cos: mpmath.cos, sp.tan: mpmath.tan, sp.asin: mpmath.asin,
    sp.acos: mpmath.acos, sp.atan: mpmath.atan, sp.sinh: mpmath.sinh, sp.cosh: mpmath.cosh,
    sp.tanh: mpmath.tanh, sp.exp: mpmath.exp, sp.log: mpmath.log, sp.Abs: abs, sp.sign: mpmath.sign,
    sp.cot: mpmath.cot, sp.sec: mpmath.sec, sp.csc: mpmath.csc,
}
_EXPONENTIAL = (sp.exp, sp.sinh, sp.cosh)


class _Evaluator:
    def __init__(self, point: Mapping[sp.Symbol, float]) -> None:
        self.point = point
        # Derived expressions share subexpressions (the bicycle's are millions of
        # nodes as trees): each distinct one is evaluated once.
        self.memo: dict[sp.Basic, tuple[mpmath.mpf, mpmath.mpf]] = {}

    def value(self, expr: sp.Expr) -> tuple[mpmath.mpf, mpmath.mpf]:
        value, scale = self._node(expr)
        return value, max(scale, abs(value))

    def _node(self, expr) -> tuple[mpmath.mpf, mpmath.mpf]:
        known = self.memo.get(expr)
        if known is None:
            known = self.memo[expr] = self._evaluate(expr)
        return known

    def _evaluate(self, expr) -> tuple[mpmath.mpf, mpmath.mpf]:
        if expr.is_Symbol:
            if expr not in self.point:
                raise UndefinedValue(f"no value for {expr}")
            return self._real(mpmath.mpf(self.point[expr]))
        if expr.is_Rational:
            return self._real(mpmath.mpf(expr.p) / expr.q)
        if expr.is_Float:
            return self._real(mpmath.mpf(expr))
        if expr is sp.pi:
            return self._real(+mpmath.pi)
        if expr is sp.E:
            return self._real(+mpmath.e)
        if expr.is_Add:
            parts = [self._node(a) for a in expr.args]
            return self._real(mpmath.fsum(v for v, _ in parts), sum(s for _, s in parts))
        if expr.is_Mul:
            parts = [self._node(a) for a in expr.args]
            return self._real(mpmath.fprod(v for v, _ in parts), mpmath.fprod(s for _, s in parts))
        if expr.is_Pow:
            return self._power(expr)
        if expr.func in _ONE_ARGUMENT and len(expr.args) == 1:
            return self._function(expr)
        if expr.func in (sp.DiracDelta, sp.Heaviside) and len(expr.args) == 1:
            return self._step(expr)
        if expr.func is sp.atan2:
            (y, sy), (x, sx) = self._node(expr.args[0]), self._node(expr.args[1])
            return self._real(mpmath.atan2(y, x), max(sy, sx))
        raise UndefinedValue(f"cannot evaluate {type(expr).__name__}")

    def _power(self, expr) -> tuple[mpmath.mpf, mpmath.mpf]:
        (base, sb), (exponent, se) = self._node(expr.base), self._node(expr.exp)
        if base == 0 and exponent <= 0:
            raise UndefinedValue("0 to a non-positive power")
        if base != 0 and abs(exponent * mpmath.log(abs(base))) > _EXP_ARGUMENT_LIMIT:
            raise UndefinedValue("power too large")
        return self._real(mpmath.power(base, exponent), max(sb, se))

    def _step(self, expr) -> tuple[mpmath.mpf, mpmath.mpf]:
        """DiracDelta and Heaviside (from differentiating sign and abs), away from their jump."""
        argument, _ = self._node(expr.args[0])
        if argument == 0:
            raise UndefinedValue("at the jump of a step")
        return self._real(mpmath.mpf(0) if expr.func is sp.DiracDelta else mpmath.mpf(argument > 0))

    def _function(self, expr) -> tuple[mpmath.mpf, mpmath.mpf]:
        argument, scale = self._node(expr.args[0])
        if expr.func in _EXPONENTIAL and abs(argument) > _EXP_ARGUMENT_LIMIT:
            raise UndefinedValue("exponential too large")
        return self._real(_ONE_ARGUMENT[expr.func](argument), scale)

    @staticmethod
    def _real(value, scale=None) -> tuple[mpmath.mpf, mpmath.mpf]:
        if isinstance(value, mpmath.mpc):
            if abs(value.imag) > _RELATIVE_TOLERANCE * max(abs(value.real), 1):
                raise UndefinedValue("outside the real domain")
            value = value.real
        value = mpmath.mpf(value)
        if not mpmath.isfinite(value) or abs(value) > _HUGE:
            raise UndefinedValue("not finite")
        return value, abs(value) if scale is None else max(abs(value), scale)
