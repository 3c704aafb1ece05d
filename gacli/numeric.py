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
from dataclasses import dataclass

import numpy as np
import sympy as sp

from gacli import symbols as S


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


# -- physical samples of the parameters -------------------------------------------
# gacli verify gives every parameter without a value a random number. Each one
# drawn alone in [0.5, 2] makes masses and lengths positive, but an inertia
# matrix of symbolic moments and products is then indefinite about half the
# time, and M with it: verify would blame the derivation for the sample.

PARAMETER_RANGE = (0.5, 2.0)   # masses, lengths, moments: positive, of order one
PRODUCT_RANGE = (-0.3, 0.3)    # a product of inertia alone in an entry: either sign, small
TRIES = 100


@dataclass(frozen=True)
class ParameterSample:
    """Float values of every parameter that has one; ``problem`` is "" when every body is physical."""

    values: dict[sp.Symbol, float]
    problem: str


def sample_parameters(system, rng) -> ParameterSample:
    """Parameters without a value drawn at random so that every body is physical.

    The first draw is one ``rng.uniform(0.5, 2)`` per such parameter in
    declaration order (the draw verify always made, so its samples of
    physical systems do not change); while a mass is not positive or an
    inertia matrix is not positive semidefinite with principal moments
    obeying the triangle inequalities, the parameters of masses and inertias
    are drawn again. ``problem`` says what is still wrong after ``TRIES``.
    """
    drawn = [S.value(p.name) for p in system.parameters if p.value is None]
    chosen = {s: rng.uniform(*PARAMETER_RANGE) for s in drawn}
    values = _parameter_floats(system, chosen)
    problem = unphysical(system, values)
    inertial, products = _inertial_parameters(system, set(drawn))
    for _ in range(TRIES if inertial else 0):
        if not problem:
            break
        chosen.update({s: rng.uniform(*(PRODUCT_RANGE if s in products else PARAMETER_RANGE)) for s in inertial})
        values = _parameter_floats(system, chosen)
        problem = unphysical(system, values)
    return ParameterSample(values, problem)


def _parameter_floats(system, chosen: Mapping[sp.Symbol, float]) -> dict[sp.Symbol, float]:
    """The chosen values, and the file's values (expressions in earlier parameters) as floats."""
    values: dict[sp.Symbol, float] = {}
    for p in system.parameters:
        symbol = S.value(p.name)
        number = chosen.get(symbol) if p.value is None else _float(p.value, values)
        if number is not None:
            values[symbol] = number
    return values


def _inertial_parameters(system, drawn: set) -> tuple[list[sp.Symbol], set[sp.Symbol]]:
    """Drawn parameters in masses and inertias (sorted), and those only in products of inertia."""
    diagonal, off = set(), set()
    for body in system.bodies:
        diagonal |= body.mass.free_symbols
        if body.inertia is not None:
            for i in range(3):
                for j in range(3):
                    (diagonal if i == j else off).update(body.inertia[i, j].free_symbols)
    inertial = sorted((diagonal | off) & drawn, key=lambda s: s.name)
    return inertial, (off - diagonal) & drawn


def unphysical(system, values: Mapping[sp.Symbol, float]) -> str:
    """What makes a body unphysical at these parameter values ("" when nothing does, or unknown)."""
    for body in system.bodies:
        mass = _float(body.mass, values)
        if mass is not None and not mass > 0:
            return f"the mass of {body.name} is {mass:.3g}"
        if body.inertia is None:
            continue
        entries = [_float(body.inertia[i, j], values) for i in range(3) for j in range(3)]
        if None in entries:
            continue
        moments = sorted(float(v) for v in np.linalg.eigvalsh(np.array(entries).reshape(3, 3)))
        slack = 1e-9 * max(abs(moments[-1]), 1e-300)
        shown = ", ".join(f"{v:.3g}" for v in moments)
        if moments[0] < -slack:
            return f"the inertia of {body.name} is not positive definite (principal moments {shown})"
        # A plane body gives only the moment about its axis: diag(0, 0, I) is no real body, but no fault.
        planar = moments[1] <= slack
        if not planar and moments[2] > moments[0] + moments[1] + slack:
            return f"the inertia of {body.name} breaks the triangle inequality (principal moments {shown})"
    return ""


def _float(expr: sp.Expr, values: Mapping[sp.Symbol, float]) -> float | None:
    """The real value of ``expr`` at ``values``; None when it has none there."""
    if not expr.free_symbols <= set(values):
        return None
    try:
        value = Program([expr])(values)[0]
    except (ArithmeticError, ValueError, TypeError):
        return None
    return value.real if value.imag == 0 else None
