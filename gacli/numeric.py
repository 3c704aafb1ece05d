"""Evaluate SymPy expressions at a point, once per distinct node.

Derived expressions share their subexpressions (a solved rate appears in
every velocity), so as trees they can be millions of nodes while the graph of
distinct objects stays small. Printing them for ``lambdify`` or substituting
with ``xreplace`` walks the tree; this evaluator walks the graph, memoised by
object identity, in complex arithmetic (the complex step of
:mod:`gacli.linearize` needs it).
"""

from __future__ import annotations

import cmath
from collections.abc import Iterable, Mapping

import sympy as sp

_FUNCTIONS = {
    sp.sin: cmath.sin, sp.cos: cmath.cos, sp.tan: cmath.tan, sp.asin: cmath.asin, sp.acos: cmath.acos,
    sp.atan: cmath.atan, sp.sinh: cmath.sinh, sp.cosh: cmath.cosh, sp.tanh: cmath.tanh,
    sp.exp: cmath.exp, sp.log: cmath.log,
}


class Evaluator:
    """Values of expressions at one point; call it on many expressions to share the work."""

    def __init__(self, values: Mapping[sp.Symbol, complex]) -> None:
        self._values = dict(values)
        self._memo: dict[int, complex] = {}
        self._keep: list[sp.Basic] = []  # ids stay valid while the objects live

    def __call__(self, expr: sp.Basic) -> complex:
        stack = [(expr, False)]
        while stack:
            node, ready = stack.pop()
            if id(node) in self._memo:
                continue
            if ready or not node.args or node.is_Number:
                self._memo[id(node)] = self._value(node)
                self._keep.append(node)
                continue
            stack.append((node, True))
            stack.extend((arg, False) for arg in node.args if id(arg) not in self._memo)
        return self._memo[id(expr)]

    def many(self, exprs: Iterable[sp.Basic]) -> list[complex]:
        return [self(e) for e in exprs]

    def _arg(self, node: sp.Basic, i: int) -> complex:
        return self._memo[id(node.args[i])]

    def _value(self, node: sp.Basic) -> complex:
        if node.is_Symbol:
            return complex(self._values[node])
        if node.is_Number or node.is_NumberSymbol:
            return complex(node)
        args = [self._memo[id(a)] for a in node.args]
        if node.is_Add:
            return sum(args)
        if node.is_Mul:
            out = 1
            for a in args:
                out *= a
            return out
        if node.is_Pow:
            base, exponent = args
            if node.exp == sp.S.Half:
                return cmath.sqrt(base)
            if node.exp.is_Integer:
                return base ** int(node.exp)
            return base ** exponent
        return _function(node, args)


def _function(node: sp.Basic, args: list[complex]) -> complex:
    head = node.func
    if head in _FUNCTIONS:
        return _FUNCTIONS[head](*args)
    if head is sp.atan2:
        y, x = args
        # Analytic in both arguments, so the complex step sees its derivative.
        return cmath.phase(complex(x.real, y.real)) + (x.real * y.imag - y.real * x.imag) / (x.real ** 2 + y.real ** 2) * 1j
    if head is sp.Abs:
        return args[0] if args[0].real >= 0 else -args[0]
    if head is sp.sign:
        return complex((args[0].real > 0) - (args[0].real < 0))
    raise TypeError(f"cannot evaluate {head.__name__} numerically")
