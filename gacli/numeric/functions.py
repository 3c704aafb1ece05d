"""The one table of functions the numeric evaluator knows, per backend.

The grammar admits sin … tanh, exp, log, sqrt, abs, sign and atan2
(:mod:`gacli.read.expr.build`); differentiation adds Heaviside and DiracDelta
(from abs and sign) and simplification can add cot, sec and csc. A backend
without an entry refuses the function. In complex arithmetic abs and sign
are continued from the real line, |z| = z sign(Re z) and sign(Re z): the
complex step of :mod:`gacli.linearize` needs functions analytic in their
argument, and these are, away from Re z = 0, with the derivatives of |x|
and sign x there. So a spring along one axis, whose length is |x + d|, or
a dry friction −μ sign(ẋ), is evaluated at the program builder's generic
points and linearized by the complex step like any other load.
"""

from __future__ import annotations

import cmath
from collections.abc import Callable
from dataclasses import dataclass

import mpmath
import sympy as sp


@dataclass(frozen=True)
class Function:
    """One function in each backend; ``None`` where that backend refuses it."""

    complex: Callable | None
    mpmath: Callable | None


def _atan2(y: complex, x: complex) -> complex:
    """atan2 with the first-order complex part, so that the complex step sees its derivative."""
    real = cmath.phase(complex(x.real, y.real))
    return complex(real, (x.real * y.imag - y.real * x.imag) / (x.real ** 2 + y.real ** 2))


def _abs(z: complex) -> complex:
    """|x| continued from the real line: z or −z by the sign of Re z (see the module)."""
    return -z if z.real < 0 else z


def _sign(z: complex) -> complex:
    return complex((z.real > 0) - (z.real < 0))


FUNCTIONS: dict[type, Function] = {
    sp.sin: Function(cmath.sin, mpmath.sin), sp.cos: Function(cmath.cos, mpmath.cos),
    sp.tan: Function(cmath.tan, mpmath.tan), sp.asin: Function(cmath.asin, mpmath.asin),
    sp.acos: Function(cmath.acos, mpmath.acos), sp.atan: Function(cmath.atan, mpmath.atan),
    sp.sinh: Function(cmath.sinh, mpmath.sinh), sp.cosh: Function(cmath.cosh, mpmath.cosh),
    sp.tanh: Function(cmath.tanh, mpmath.tanh), sp.exp: Function(cmath.exp, mpmath.exp),
    sp.log: Function(cmath.log, mpmath.log), sp.atan2: Function(_atan2, mpmath.atan2),
    sp.Abs: Function(_abs, mpmath.fabs), sp.sign: Function(_sign, mpmath.sign),
    sp.cot: Function(None, mpmath.cot), sp.sec: Function(None, mpmath.sec), sp.csc: Function(None, mpmath.csc),
}

# The guarded evaluator refuses these past a bound on the argument: exp(1e6) is no number of a model.
EXPONENTIAL = (sp.exp, sp.sinh, sp.cosh)
# Derivatives of abs and sign; only the guarded evaluator takes them, away from their jump.
STEPS = (sp.DiracDelta, sp.Heaviside)


def complex_function(func) -> Callable | None:
    entry = FUNCTIONS.get(func)
    return entry.complex if entry else None


def mpmath_function(func) -> Callable | None:
    entry = FUNCTIONS.get(func)
    return entry.mpmath if entry else None
