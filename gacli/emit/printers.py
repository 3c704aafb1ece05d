"""SymPy code printers for gacli's generated Python, C, Octave and JAX.

Each subclasses SymPy's printer for its language. They all take the map
symbol → code name in ``__init__`` (see :mod:`gacli.emit.naming`) and
print every symbol through it, so that ``dot(q_z)`` reads ``dot_q_z``.
They keep SymPy's ``strict`` mode: a node without a rendering raises :class:`UnsupportedNode` (an
:class:`~gacli.errors.EmitError` that names the node's type) instead of
leaving a comment in the code; :func:`print_code` adds the equation it
came from.

>>> import sympy as sp
>>> theta, a = sp.symbols("theta a", real=True)
>>> GacliCPrinter({theta: "theta", a: "a"}).doprint(sp.pi * a * sp.sin(theta) / 2)
'(1.0/2.0)*3.1415926535897932*a*sin(theta)'
>>> GacliPythonPrinter({theta: "theta", a: "a"}).doprint(sp.pi * a * sp.sin(theta) / 2)
'(1/2)*math.pi*a*math.sin(theta)'
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

import sympy as sp
from sympy.printing.c import C99CodePrinter
from sympy.printing.codeprinter import PrintMethodNotImplementedError
from sympy.printing.numpy import JaxPrinter
from sympy.printing.octave import OctaveCodePrinter
from sympy.printing.pycode import PythonCodePrinter

from gacli.algebra.coerce import as_expr
from gacli.algebra.graph import common_subexpressions, free_symbols
from gacli.errors import EmitError

# What generated code may depend on.
PYTHON_MODULES = frozenset({"math", "numpy"})
JAX_MODULES = frozenset({"jax", "jax.numpy"})
C_HEADERS = frozenset({"math.h"})


class UnsupportedNode(EmitError):
    """A SymPy node that a printer cannot render; ``node`` is the node."""

    def __init__(self, node: sp.Basic, language: str, reason: str = "") -> None:
        self.node = node
        self.language = language
        super().__init__(reason or f"{type(node).__name__} cannot be printed as {language}: {node}")


class _NamedSymbols:
    """Mixin: symbols print as the code names given in ``__init__``; no fallback."""

    language: str

    def _init_names(self, names: Mapping[sp.Symbol, str]) -> None:
        self.names = dict(names)

    def _print_Symbol(self, expr: sp.Symbol) -> str:
        try:
            return self.names[expr]
        except KeyError:
            raise UnsupportedNode(expr, self.language, f"the symbol {expr} has no slot in x, p or r") from None

    def _print_not_supported(self, expr) -> str:
        raise UnsupportedNode(expr, self.language)

    def _print(self, expr, **kwargs) -> str:
        # Some of SymPy's methods raise on their own (``_print_Derivative``):
        # name the innermost node that failed.
        try:
            return super()._print(expr, **kwargs)
        except PrintMethodNotImplementedError:
            raise UnsupportedNode(expr, self.language) from None


# Integers beyond 2**53 are not exact in a double anyway; past ~19 digits a C
# compiler refuses the integer literal, and Python's int * float overflows
# past 1e308. Derivations can make exact rationals of hundreds of digits.
EXACT_LIMIT = 2 ** 53


def wide(number: sp.Rational) -> bool:
    """True when the numerator or denominator does not fit in a double's 53 bits."""
    return abs(int(number.p)) >= EXACT_LIMIT or int(number.q) >= EXACT_LIMIT


class _Numbers:
    """Mixin: wide integers and rationals print as a floating literal, the nearest double.

    Small ones keep SymPy's exact printing (``1.0/3.0``, ``1/3``), so the
    code of ordinary systems is unchanged.
    """

    infinity: str  # the language's name for an infinite double

    def _wide_literal(self, number: sp.Rational) -> str:
        value = float(number)  # correctly rounded by SymPy, inf past the double range
        if value in (float("inf"), float("-inf")):
            text = self.infinity
            return f"(-{text})" if value < 0 else text
        text = repr(value)
        return f"({text})" if value < 0 else text

    def _print_Rational(self, expr: sp.Rational) -> str:
        return self._wide_literal(expr) if wide(expr) else super()._print_Rational(expr)

    def _print_Integer(self, expr: sp.Integer) -> str:
        return self._wide_literal(expr) if wide(expr) else super()._print_Integer(expr)


class GacliPythonPrinter(_Numbers, _NamedSymbols, PythonCodePrinter):
    """Python (``math`` module) code for scalar expressions."""

    language = "Python"
    infinity = "math.inf"

    def __init__(self, names: Mapping[sp.Symbol, str], settings: dict | None = None) -> None:
        super().__init__({"fully_qualified_modules": True, **(settings or {}), "strict": True})
        self._init_names(names)

    def imports(self) -> list[str]:
        """The modules the printed code uses, sorted; only math and numpy are allowed."""
        modules = sorted(self.module_imports)
        extra = [m for m in modules if m not in PYTHON_MODULES]
        if extra:
            raise EmitError(f"the generated Python would need {', '.join(extra)}")
        return modules


class GacliCPrinter(_Numbers, _NamedSymbols, C99CodePrinter):
    """C99 code: no ``M_PI``-style macros (they fail under ``-std=c99 -pedantic``)."""

    language = "C"
    infinity = "HUGE_VAL"  # <math.h>, C99

    def __init__(self, names: Mapping[sp.Symbol, str], settings: dict | None = None) -> None:
        super().__init__({**(settings or {}), "math_macros": {}, "strict": True})
        self._init_names(names)

    def _print_NumberSymbol(self, expr: sp.NumberSymbol) -> str:
        return self._print_Float(sp.Float(expr.evalf(self._settings["precision"]), self._settings["precision"]))

    def _print_Pi(self, expr: sp.NumberSymbol) -> str:
        return self._print_NumberSymbol(expr)

    def _print_Exp1(self, expr: sp.NumberSymbol) -> str:
        return self._print_NumberSymbol(expr)

    def includes(self) -> list[str]:
        """The headers the printed code uses, sorted; only <math.h> is allowed."""
        headers = sorted(set(self.headers) | C_HEADERS)
        extra = [h for h in headers if h not in C_HEADERS]
        if extra or self.macros:
            raise EmitError(f"the generated C would need {', '.join(extra + sorted(self.macros))}")
        return headers


class GacliOctavePrinter(_Numbers, _NamedSymbols, OctaveCodePrinter):
    """GNU Octave and MATLAB code for scalar expressions (SymPy prints the element-wise operators)."""

    language = "Octave"
    infinity = "Inf"

    def __init__(self, names: Mapping[sp.Symbol, str], settings: dict | None = None) -> None:
        super().__init__({**(settings or {}), "strict": True})
        self._init_names(names)


class GacliJaxPrinter(_Numbers, _NamedSymbols, JaxPrinter):
    """``jax.numpy`` code for scalar expressions: traceable by jit, vmap and grad."""

    language = "JAX"
    infinity = "jax.numpy.inf"

    def __init__(self, names: Mapping[sp.Symbol, str], settings: dict | None = None) -> None:
        super().__init__({"fully_qualified_modules": True, **(settings or {}), "strict": True})
        self._init_names(names)

    def imports(self) -> list[str]:
        """The modules the printed code uses, sorted; only jax and jax.numpy are allowed."""
        modules = sorted(self.module_imports)
        extra = [m for m in modules if m not in JAX_MODULES]
        if extra:
            raise EmitError(f"the generated JAX would need {', '.join(extra)}")
        return modules


def print_code(printer, expr: sp.Expr, where: Callable[[sp.Basic], str] | str) -> str:
    """``printer.doprint(expr)``; an unsupported node becomes an EmitError naming ``where``.

    ``where`` is the equation's name, or a function from the failing node to
    the name of the equation that holds it (for expressions after CSE).
    """
    try:
        return printer.doprint(expr)
    except UnsupportedNode as error:
        place = where if isinstance(where, str) else where(error.node)
        raise EmitError(f"{place}: {error}") from None


def locate(node: sp.Basic, equations: Iterable[tuple[str, sp.Expr]]) -> str:
    """The name of the first equation that holds ``node``."""
    for name, expr in equations:
        if as_expr(expr).has(node):
            return name
    return "an equation"


# -- blocks of code with shared subexpressions --------------------------------

@dataclass(frozen=True)
class Block:
    """Equations printed after common-subexpression elimination.

    ``temporaries`` are ``(name, code)`` assignments in dependency order,
    ``results`` the code of each equation in the order given, and
    ``symbols`` the symbols of the equations (before CSE).
    """

    temporaries: tuple[tuple[str, str], ...]
    results: tuple[str, ...]
    symbols: frozenset[sp.Symbol]


CSE_PREFIX = "_c"  # user identifiers never start with '_' (see naming.py)


def print_block(printer_class, names: Mapping[sp.Symbol, str],
                equations: Sequence[tuple[str, sp.Expr]], prefix: str = CSE_PREFIX) -> tuple[Block, object]:
    """CSE over the equations, in their order, then print; returns the block and the printer.

    The printer is returned so that callers can read what the code needs
    (``imports()``, ``includes()``). Temporaries are named ``<prefix>0``,
    ``<prefix>1`` ...: the prefix must be one that no name in ``names`` has.
    The CSE is :func:`gacli.algebra.graph.common_subexpressions`, whose operations
    :attr:`gacli.mechanics.code.CodeEquations.operations` counts.
    """
    exprs = [as_expr(expr) for _, expr in equations]
    names_of_temporaries = sp.numbered_symbols(prefix)
    replacements, reduced = common_subexpressions(exprs, names_of_temporaries)
    printer = printer_class({**names, **{sym: sym.name for sym, _ in replacements}})
    where = functools.partial(locate, equations=equations)
    temporaries = tuple((sym.name, print_code(printer, value, where)) for sym, value in replacements)
    # Each distinct result printed once: a wide system's M is mostly zeros.
    printed: dict[sp.Expr, str] = {}
    results = tuple(printed[e] if e in printed else printed.setdefault(e, print_code(printer, e, where))
                    for e in reduced)
    symbols = frozenset(free_symbols(exprs))
    return Block(temporaries, results, symbols), printer
