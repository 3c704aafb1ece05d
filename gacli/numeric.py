"""Evaluate SymPy expressions as a straight-line program over their distinct subexpressions.

Derived expressions share their subexpressions (a solved rate appears in
every velocity), so as printed trees they can be millions of nodes while the
distinct subexpressions stay few. ``lambdify`` prints the trees and
``xreplace`` rebuilds them; a :class:`Program` is built by one walk of the
distinct nodes and then evaluated as often as needed, in complex arithmetic
(the complex step of :mod:`gacli.linearize` needs it).
"""

from __future__ import annotations

import cmath
from collections.abc import Mapping, Sequence

import sympy as sp


_FUNCTIONS = {
    sp.sin: cmath.sin, sp.cos: cmath.cos, sp.tan: cmath.tan, sp.asin: cmath.asin, sp.acos: cmath.acos,
    sp.atan: cmath.atan, sp.sinh: cmath.sinh, sp.cosh: cmath.cosh, sp.tanh: cmath.tanh,
    sp.exp: cmath.exp, sp.log: cmath.log,
}


class Program:
    """The expressions compiled once; ``program(values)`` gives their complex values."""

    def __init__(self, exprs: Sequence[sp.Basic]) -> None:
        slots: dict[sp.Basic, int] = {}
        self.code: list[tuple] = []
        stack = [(e, False) for e in reversed(list(exprs))]
        while stack:
            node, ready = stack.pop()
            if node in slots:
                continue
            if node.args and not node.is_Number and not ready:
                stack.append((node, True))
                stack.extend((a, False) for a in reversed(node.args) if a not in slots)
                continue
            slots[node] = len(self.code)
            self.code.append(_instruction(node, [slots[a] for a in node.args] if node.args else []))
        self.outputs = [slots[e] for e in exprs]

    def __call__(self, values: Mapping[sp.Symbol, complex]) -> list[complex]:
        out: list = [0j] * len(self.code)
        for i, (kind, payload, args) in enumerate(self.code):
            if kind == "add":
                out[i] = sum(out[a] for a in args)
            elif kind == "mul":
                value = 1
                for a in args:
                    value *= out[a]
                out[i] = value
            elif kind == "ipow":
                out[i] = out[args[0]] ** payload
            elif kind == "sqrt":
                out[i] = cmath.sqrt(out[args[0]])
            elif kind == "pow":
                out[i] = out[args[0]] ** out[args[1]]
            elif kind == "symbol":
                out[i] = complex(values[payload])
            elif kind == "number":
                out[i] = payload
            else:
                out[i] = payload(*(out[a] for a in args))
        return [out[o] for o in self.outputs]


def _instruction(node: sp.Basic, args: list[int]) -> tuple:
    if node.is_Symbol:
        return ("symbol", node, args)
    if node.is_Number or node.is_NumberSymbol:
        return ("number", complex(node), args)
    if node.is_Add:
        return ("add", None, args)
    if node.is_Mul:
        return ("mul", None, args)
    if node.is_Pow:
        if node.exp.is_Integer:
            return ("ipow", int(node.exp), args)
        if node.exp == sp.S.Half:
            return ("sqrt", None, args)
        return ("pow", None, args)
    if node.func in _FUNCTIONS:
        return ("call", _FUNCTIONS[node.func], args)
    if node.func is sp.atan2:
        return ("call", _atan2, args)
    raise TypeError(f"cannot evaluate {node.func.__name__} numerically")


def _atan2(y: complex, x: complex) -> complex:
    """atan2 with the first-order complex part, so that the complex step sees its derivative."""
    real = cmath.phase(complex(x.real, y.real))
    return complex(real, (x.real * y.imag - y.real * x.imag) / (x.real ** 2 + y.real ** 2))
