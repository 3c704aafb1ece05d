"""What each node of a straight-line program does, in complex, mpmath and guarded arithmetic.

An instruction is ``(kind, payload, args)``; a backend turns a node into one
(:meth:`Backend.instruction`) and runs the list (:meth:`Backend.run`). The
functions come from the one table in :mod:`gacli.numeric.functions`.
"""

from __future__ import annotations

import cmath
from collections.abc import Mapping

import mpmath
import sympy as sp

from gacli.numeric.functions import EXPONENTIAL, FUNCTIONS, STEPS, complex_function, mpmath_function

RELATIVE_TOLERANCE = mpmath.mpf("1e-25")  # an imaginary part below this, relative, is rounding
_HUGE = mpmath.mpf("1e300")
_EXP_ARGUMENT_LIMIT = 1e4


class UndefinedValue(ValueError):
    """The expression has no finite real value at the point (or cannot be evaluated)."""


class Backend:
    """Arithmetic for a :class:`gacli.numeric.evaluator.Program`."""

    def descend(self, node: sp.Basic) -> bool:
        return True

    def instruction(self, node: sp.Basic, args: list[int], nodes: list) -> tuple:
        raise NotImplementedError

    def run(self, code: list[tuple], outputs: list[int], values: Mapping) -> list:
        raise NotImplementedError


class Complex(Backend):
    """Python complex numbers; numbers converted once, when compiled."""

    def instruction(self, node, args, nodes) -> tuple:
        if node.is_Symbol:
            return ("symbol", node, args)
        if node is sp.S.ComplexInfinity:  # a file's 1/0: undefined, as NaN is, never a compile error
            return ("number", complex("nan"), args)
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
        function = complex_function(node.func)
        if function is not None:
            return ("call", function, args)
        raise TypeError(f"cannot evaluate {node.func.__name__} numerically")

    def run(self, code, outputs, values) -> list[complex]:
        out: list = [0j] * len(code)
        for i, (kind, payload, args) in enumerate(code):
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
        return [out[o] for o in outputs]


def mp_number(node: sp.Basic):
    """A SymPy number as mpmath at the working precision (NaN and infinities as nan)."""
    if node.is_Rational:
        return mpmath.mpf(int(node.p)) / int(node.q)
    if node is sp.S.Pi:
        return +mpmath.pi
    if node is sp.S.Exp1:
        return +mpmath.e
    if node is sp.S.NaN or node.is_infinite:
        return mpmath.nan
    return mpmath.mpf(str(sp.N(node, mpmath.mp.dps + 5)))


class Mpmath(Backend):
    """mpmath at the working precision; numbers converted when run (the precision is the caller's)."""

    def instruction(self, node, args, nodes) -> tuple:
        if isinstance(node, sp.Symbol):
            return ("symbol", node, args)
        if isinstance(node, sp.Add):
            return ("add", None, args)
        if isinstance(node, sp.Mul):
            return ("mul", None, args)
        if isinstance(node, sp.Pow):
            exponent = nodes[args[1]][0]
            return ("ipow", int(exponent), args) if exponent.is_Integer else ("pow", None, args)
        if node.is_Number or node.is_NumberSymbol or node is sp.S.ComplexInfinity:  # mp_number: nan
            return ("number", node, args)
        function = mpmath_function(node.func)
        if function is not None:
            return ("call", function, args)
        raise NotImplementedError(f"cannot evaluate {type(node).__name__} numerically")

    def run(self, code, outputs, values) -> list:
        out: list = [None] * len(code)
        for i, (kind, payload, args) in enumerate(code):
            if kind == "add":
                out[i] = mpmath.fsum(out[a] for a in args)
            elif kind == "mul":
                out[i] = mpmath.fprod(out[a] for a in args)
            elif kind == "ipow":
                out[i] = out[args[0]] ** payload
            elif kind == "pow":
                out[i] = mpmath.power(out[args[0]], out[args[1]])
            elif kind == "symbol":
                out[i] = values[payload]
            elif kind == "number":
                out[i] = mp_number(payload)
            else:
                out[i] = payload(*(out[a] for a in args))
        return [out[o] for o in outputs]


class Guarded(Backend):
    """mpmath pairs (value, scale), real and bounded, or :class:`UndefinedValue`.

    A node it cannot evaluate stays a leaf that raises when reached, so that
    the message names what a walk from the top meets first.
    """

    def descend(self, node) -> bool:
        if node.is_Add or node.is_Mul or node.is_Pow or node.func is sp.atan2:
            return True
        known = mpmath_function(node.func) is not None or node.func in STEPS
        return known and len(node.args) == 1

    def instruction(self, node, args, nodes) -> tuple:
        if node.is_Symbol:
            return ("symbol", node, args)
        if node.is_Rational or node.is_Float or node is sp.pi or node is sp.E:
            return ("number", node, args)
        if node.is_Add or node.is_Mul or node.is_Pow:
            return ("add" if node.is_Add else "mul" if node.is_Mul else "pow", None, args)
        if node.func in STEPS and len(args) == 1:
            return ("step", node.func, args)
        if args and node.func in FUNCTIONS:
            return ("call", node.func, args)
        return ("refuse", f"cannot evaluate {type(node).__name__}", args)

    def run(self, code, outputs, values) -> list:
        out: list = [None] * len(code)
        for i, (kind, payload, args) in enumerate(code):
            out[i] = getattr(self, "_" + kind)(payload, [out[a] for a in args], values)
        return [out[o] for o in outputs]

    @staticmethod
    def _symbol(symbol, parts, values):
        if symbol not in values:
            raise UndefinedValue(f"no value for {symbol}")
        return real(mpmath.mpf(values[symbol]))

    @staticmethod
    def _number(node, parts, values):
        if node.is_Rational:
            return real(mpmath.mpf(node.p) / node.q)
        if node.is_Float:
            return real(mpmath.mpf(node))
        return real(+mpmath.pi if node is sp.pi else +mpmath.e)

    @staticmethod
    def _add(payload, parts, values):
        return real(mpmath.fsum(v for v, _ in parts), sum(s for _, s in parts))

    @staticmethod
    def _mul(payload, parts, values):
        return real(mpmath.fprod(v for v, _ in parts), mpmath.fprod(s for _, s in parts))

    @staticmethod
    def _pow(payload, parts, values):
        (base, sb), (exponent, se) = parts
        if base == 0 and exponent <= 0:
            raise UndefinedValue("0 to a non-positive power")
        if base != 0 and abs(exponent * mpmath.log(abs(base))) > _EXP_ARGUMENT_LIMIT:
            raise UndefinedValue("power too large")
        return real(mpmath.power(base, exponent), max(sb, se))

    @staticmethod
    def _step(func, parts, values):
        """DiracDelta and Heaviside (from differentiating sign and abs), away from their jump."""
        argument = parts[0][0]
        if argument == 0:
            raise UndefinedValue("at the jump of a step")
        return real(mpmath.mpf(0) if func is sp.DiracDelta else mpmath.mpf(argument > 0))

    @staticmethod
    def _call(func, parts, values):
        if func in EXPONENTIAL and abs(parts[0][0]) > _EXP_ARGUMENT_LIMIT:
            raise UndefinedValue("exponential too large")
        return real(mpmath_function(func)(*(v for v, _ in parts)), max(s for _, s in parts))

    @staticmethod
    def _refuse(message, parts, values):
        raise UndefinedValue(message)


def real(value, scale=None) -> tuple[mpmath.mpf, mpmath.mpf]:
    """(value, scale) when ``value`` is real and finite, else UndefinedValue."""
    if isinstance(value, mpmath.mpc):
        if abs(value.imag) > RELATIVE_TOLERANCE * max(abs(value.real), 1):
            raise UndefinedValue("outside the real domain")
        value = value.real
    value = mpmath.mpf(value)
    if not mpmath.isfinite(value) or abs(value) > _HUGE:
        raise UndefinedValue("not finite")
    return value, abs(value) if scale is None else max(abs(value), scale)
