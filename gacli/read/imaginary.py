"""Imaginary values in a system file's expressions, found where the expression is read.

gacli's quantities are real: G = ½ Σ m a·a squares components without
conjugating them, so an ``I`` in a position turns into a negative mass and
``asin(2)`` into a mass matrix that is complex. SymPy makes ``I`` out of
``sqrt(-1)`` and ``log(-1)`` as soon as they are built; ``asin(2)`` or
``(-2)**(1/3)`` stay as they are and are complex only when evaluated; and
``asin(2 + x**2)`` is complex at every state. :func:`imaginary_problem`
finds all three, and a number past the range of a double (``1e300*1e300``,
which generated code would turn into an infinity), so that ``gacli check``
and ``gacli derive`` stop with the place of the expression instead of
deriving nonsense.

Sampling is conservative: an expression is refused only when it is complex
at every sample point where it has a value, points of either sign and of
sizes from 1e-4 to 1e4 included, so that ``sqrt(1 - theta**2)`` (real for
small angles) and ``sqrt(l**2 - x**2)`` with ``l: 0.01`` are accepted.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import sympy as sp

from gacli.algebra.graph import postorder
from gacli.numeric import Program, sample_points

SAMPLES = 3          # unsigned points, and as many of either sign
# Each point also scaled: sqrt(l**2 - x**2) with l = 0.1 is real only for small x,
# sqrt(x - 10) only for large x; a file's lengths may be of any size.
SCALES = (1.0, 1e-2, 1e-4, 1e2, 1e4)
TOLERANCE = 1e-9     # relative size of an imaginary part taken as rounding


def imaginary_problem(expr: sp.Expr, known: Mapping[sp.Symbol, float]) -> str:
    """A message when ``expr`` is imaginary (exactly, or at every sample), else "".

    ``known`` gives the numeric values of the parameters that have one;
    every other symbol is sampled.
    """
    node = _imaginary_constant(expr)
    if node is not None and node.is_Number:
        return (f"the number {sp.Float(node, 3)} is beyond the range of a double (about 1.8e308): "
                "the generated code would compute with an infinity")
    if node is sp.I:
        return ("the expression is imaginary (a square root, power or logarithm of a negative number): "
                "positions, masses, inertias, forms and loads must be real")
    if node is not None:
        return (f"'{sp.sstr(node)}' is not a real number: positions, masses, inertias, forms "
                "and loads must be real")
    point = _always_complex(expr, known)
    if point is not None:
        values = {**{s: known[s] for s in expr.free_symbols if s in known}, **point}
        shown = ", ".join(f"{s.name}={v:.3g}" for s, v in sorted(values.items(), key=lambda i: i[0].name))
        at = f" (for example at {shown})" if shown else ""
        return f"the expression has no real value at any of the sample values tried{at}"
    return ""


def _imaginary_constant(expr: sp.Expr) -> sp.Basic | None:
    """The imaginary unit, a number too large for a double, or the first constant function
    or power that is complex.

    Evaluated in floating point, not by SymPy's ``is_extended_real``: that
    asks evalf, which raises or runs for hours on ``cosh(cosh(1e300))``.
    """
    constants = []
    for node in postorder([expr]):
        if node is sp.I or (node.is_Number and node.is_finite and abs(float(node)) == math.inf):
            return node
        if (node.is_Pow or node.is_Function) and not node.free_symbols:
            constants.append(node)
    for node in constants:
        if _complex(_program(node), {}):
            return node
    return None


def _program(expr: sp.Expr) -> Program | None:
    try:
        return Program([expr])
    except (ArithmeticError, ValueError, TypeError):  # a function Program lacks: not decided here
        return None


def _complex(program: Program | None, values) -> bool | None:
    """True or False when the program has a value at ``values``, None when it has none (or is unknown)."""
    if program is None:
        return None
    try:
        value = program(values)[0]
    except (ArithmeticError, ValueError, TypeError):
        return None
    return abs(value.imag) > TOLERANCE * max(1.0, abs(value.real))


# Functions that are real wherever a real argument gives them a value.
_REAL_FUNCTIONS = (sp.sin, sp.cos, sp.tan, sp.exp, sp.sinh, sp.cosh, sp.tanh, sp.atan, sp.Abs, sp.sign)


def _real_wherever_defined(expr: sp.Expr) -> bool:
    """Sums, products, integer powers and real functions of real symbols are never complex.

    Most expressions of a file are such (positions, masses, loads): they need
    no sampling, which was a third of a small system's first derivation.
    """
    for node in postorder([expr]):
        if node.is_Symbol or node.is_Number or node.is_NumberSymbol or node.is_Add or node.is_Mul or isinstance(node, _REAL_FUNCTIONS):
            continue
        if node.is_Pow and node.exp.is_Integer:
            continue
        return False
    return True


def _always_complex(expr: sp.Expr, known: Mapping[sp.Symbol, float]) -> dict | None:
    """A sample point where ``expr`` is complex, when it is complex at every one with a value."""
    if _real_wherever_defined(expr):
        return None
    free = expr.free_symbols - set(known)
    base = sample_points(free, SAMPLES) + sample_points(free, SAMPLES, seed=7, signed=True) if free else [{}]
    points = [{s: v * scale for s, v in point.items()} for scale in SCALES for point in base] if free else base
    example, program = None, _program(expr)
    for point in points:
        verdict = _complex(program, {**known, **point})
        if verdict is False:
            return None
        if verdict:
            example = example if example is not None else point
    return example
