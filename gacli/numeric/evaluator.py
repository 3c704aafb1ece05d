"""One evaluator over the expression graph: a straight-line program, three backends.

Derived expressions share their subexpressions (a solved rate appears in
every velocity), so as printed trees they can be millions of nodes while the
distinct subexpressions stay few. ``lambdify`` prints the trees and
``xreplace`` rebuilds them; a :class:`Program` is built by one walk of the
distinct nodes and then evaluated as often as needed. The walk is shared;
what a node becomes depends on the backend:

* ``COMPLEX``: Python complex numbers (the complex step of
  :mod:`gacli.linearize` needs them; the loader and conftest take ``.real``);
* ``MPMATH``: mpmath at the working precision (``gacli verify``, eq. 14.10);
* ``GUARDED``: mpmath pairs (value, scale) that refuse anything huge, complex
  or unknown with :class:`UndefinedValue` (sympy's evalf can run for hours on
  exp(exp(exp(100)))); ``scale`` bounds the size of the terms summed, which
  the zero tests of ``gacli check`` compare the value with.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import sympy as sp

from gacli.numeric import backends
from gacli.numeric.backends import Backend, UndefinedValue

COMPLEX: Backend = backends.Complex()
MPMATH: Backend = backends.Mpmath()
GUARDED: Backend = backends.Guarded()

__all__ = ["COMPLEX", "GUARDED", "MPMATH", "Program", "UndefinedValue", "straight_line"]


def straight_line(exprs: Sequence[sp.Basic], descend: Callable[[sp.Basic], bool]) -> tuple[list, list[int]]:
    """The distinct nodes of ``exprs`` in evaluation order, each with its arguments' slots.

    Post-order, left to right, each node once: the order a memoised recursive
    walk evaluates in, without its depth limit. ``descend(node)`` False keeps
    a node a leaf (the guarded backend does not look inside what it refuses).
    """
    slots: dict[sp.Basic, int] = {}
    nodes: list[tuple[sp.Basic, list[int]]] = []
    stack = [(e, False) for e in reversed(list(exprs))]
    while stack:
        node, ready = stack.pop()
        if node in slots:
            continue
        if node.args and not ready and descend(node):
            stack.append((node, True))
            stack.extend((a, False) for a in reversed(node.args) if a not in slots)
            continue
        slots[node] = len(nodes)
        nodes.append((node, [slots[a] for a in node.args] if ready else []))
    return nodes, [slots[e] for e in exprs]


class Program:
    """The expressions compiled once for a backend; ``program(values)`` gives their values.

    ``values`` maps every symbol to a number of the backend's kind (complex,
    mpf). Compiling raises the backend's refusal (``TypeError`` for complex,
    ``NotImplementedError`` for mpmath) for a function it has no entry for.
    """

    def __init__(self, exprs: Sequence[sp.Basic], backend: Backend = COMPLEX) -> None:
        nodes, self.outputs = straight_line(exprs, backend.descend)
        self.backend = backend
        self.code = [backend.instruction(node, args, nodes) for node, args in nodes]
        symbols = {node for node, _ in nodes if isinstance(node, sp.Symbol)}
        self.symbols = tuple(sorted(symbols, key=lambda s: s.name))

    def __call__(self, values: Mapping[sp.Symbol, object]) -> list:
        return self.backend.run(self.code, self.outputs, values)
