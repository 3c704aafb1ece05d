"""A bounded value of one expression at a point, or UndefinedValue.

sympy's evalf can run for hours on exp(exp(exp(100))); the guarded backend
of :mod:`gacli.numeric.evaluator` walks the graph once with mpmath and gives
up on anything huge, complex or unknown.
"""

from __future__ import annotations

from collections.abc import Mapping

import mpmath
import sympy as sp

from gacli.algebra.coerce import as_expr
from gacli.numeric.backends import RELATIVE_TOLERANCE, UndefinedValue
from gacli.numeric.evaluator import GUARDED, Program

DIGITS = 40

__all__ = ["DIGITS", "RELATIVE_TOLERANCE", "UndefinedValue", "evaluate"]


def evaluate(expr: sp.Expr, point: Mapping[sp.Symbol, float]) -> tuple[mpmath.mpf, mpmath.mpf]:
    """(value, scale) of ``expr`` at ``point``; ``scale`` bounds the size of the terms summed.

    Raises:
        UndefinedValue: outside the real domain, too large, or not evaluable.
    """
    if expr is sp.S.Zero:
        # Most entries of a wide system's M are zero: its check evaluates all k² of them.
        return mpmath.mpf(0), mpmath.mpf(0)
    with mpmath.workdps(DIGITS):
        try:
            (value, scale), = Program([as_expr(expr)], GUARDED)(point)
        except (ZeroDivisionError, OverflowError, ValueError, TypeError, RecursionError) as exc:
            if isinstance(exc, UndefinedValue):
                raise
            raise UndefinedValue(str(exc)) from None
        return value, max(scale, abs(value))  # at the working precision: abs rounds to it
