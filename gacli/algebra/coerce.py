"""Internal values to SymPy objects, never from text."""

from __future__ import annotations

import sympy as sp


def as_expr(value) -> sp.Basic:
    """A SymPy object from a SymPy object or a Python number, and never from text.

    Internal code uses this where it would call ``sympify``: text from a system
    file is parsed only by :mod:`gacli.read.expr`, and a string here is a bug.
    """
    if isinstance(value, sp.Basic):
        return value
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"not an expression: {type(value).__name__}")
    return sp.Integer(value) if isinstance(value, int) else sp.Float(value)
