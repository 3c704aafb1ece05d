"""Expressions compiled for many evaluations: matrices in mpmath, and lambdify's code for simulate.

:class:`Compiled` evaluates several matrices at once with the mpmath
backend of :class:`~gacli.numeric.evaluator.Program`; only for a function
outside :mod:`gacli.numeric.functions` (a Piecewise a user built) does it
fall back to ``lambdify``. :func:`vectorized` and :func:`scalar` are the
"compile" backend: ``gacli simulate`` evaluates the energy and residuals at
a thousand samples and the inputs at every step, where printed NumPy or
``math`` code is faster than any walk of the graph.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import mpmath
import sympy as sp

from gacli.algebra.graph import is_large, shared_subexpressions
from gacli.numeric.evaluator import MPMATH, Program


class Compiled:
    """Several symbolic matrices turned into one function of a values dict (mpmath).

    Values are mpf, evaluated at the working precision; the result maps each
    name to an ``mpmath.matrix`` (None for an empty one).
    """

    def __init__(self, matrices: Mapping[str, sp.MatrixBase]):
        self.shapes = {k: (m.rows, m.cols) for k, m in matrices.items()}
        flat: list[sp.Expr] = []
        for m in matrices.values():
            flat.extend(m)
        try:
            program = Program(flat, MPMATH)
            self.symbols = program.symbols
            self.function = program
        except NotImplementedError:
            self.symbols = tuple(sorted(set().union(*(e.free_symbols for e in flat)), key=lambda s: s.name))
            compiled = sp.lambdify(self.symbols, flat, modules="mpmath", cse=True)
            self.function = lambda values: compiled(*(values[s] for s in self.symbols))

    def __call__(self, values: Mapping[sp.Symbol, object]) -> dict[str, mpmath.matrix | None]:
        missing = [s.name for s in self.symbols if s not in values]
        if missing:
            raise KeyError(f"no value for {', '.join(missing)}")
        flat = list(self.function(values))
        out, i = {}, 0
        for key, (r, c) in self.shapes.items():
            chunk = [mpmath.mpmathify(x) for x in flat[i:i + r * c]]
            i += r * c
            out[key] = mpmath.matrix([chunk[a * c:(a + 1) * c] for a in range(r)]) if r * c else None
        return out


def scalar(arguments: Sequence[sp.Symbol], exprs: Sequence[sp.Expr]) -> Callable:
    """A function of ``arguments`` giving the list of ``exprs`` as floats (``math``), for every step."""
    return sp.lambdify(list(arguments), list(exprs), modules="math", dummify=True)


def vectorized(arguments: Sequence[sp.Symbol], expr: sp.Expr) -> Callable:
    """A NumPy function of ``arguments`` (arrays of samples) giving ``expr``.

    The arguments (``dot(x)`` is no Python name) are renamed here, in each shared subexpression,
    not by lambdify's ``dummify``, which looks for a free name in the whole expression once per
    argument: 3 s for a bicycle's five rolling rows, against milliseconds.
    """
    replacements, expr = _shared(expr)
    names = dict(zip(arguments, sp.symbols(f"_arg0:{len(arguments)}")))
    replacements = [(s, e.xreplace(names)) for s, e in replacements]
    return sp.lambdify(list(names.values()), expr.xreplace(names), modules="numpy", dummify=False,
                       cse=(lambda e: (replacements, e)) if replacements else False)


def _shared(expr: sp.Expr) -> tuple[list[tuple[sp.Symbol, sp.Expr]], sp.Expr]:
    """(shared subexpressions, the expression in them) for lambdify, when ``expr`` is large.

    The bicycle's energy is millions of nodes as a tree; lambdify walks and
    prints the tree, so it is handed the few thousand distinct subexpressions
    as assignments instead (gacli.algebra.graph).
    """
    if not is_large(expr):
        return [], expr
    replacements, (reduced,) = shared_subexpressions([expr], sp.numbered_symbols("_s"))
    return replacements, reduced
