"""abs() and sign() where the file's expression is differentiated (no impulse in the equations).

A position is differentiated twice in time, a potential once in the
coordinates, a constraint's and a quasi-coordinate's coefficients once in
time. d/dx sign(x) is 2 δ(x) and d²/dt² |x| holds it too, so an abs() of
something that moves, in a position, or a sign() of it in any of those
places, puts DiracDelta into the equations: no generated code can print
it, no evaluator can evaluate it, and the system has no acceleration where
the argument is 0. The loader refuses it where it is written, with its
column; forces, work and dampers are never differentiated and keep both
(dry friction's sign(dot(x)), a drag's abs(dot(x))).
"""

from __future__ import annotations

from collections.abc import Callable

import sympy as sp

from gacli.algebra.graph import postorder
from gacli.read.expr.grammar import Call, Node, walk

# How many times each place is differentiated → the functions whose derivatives then hold δ.
KINKED = {1: ("sign",), 2: ("abs", "sign")}

_TIMES = {1: "once", 2: "twice"}


def message(func: str, times: int) -> str:
    return (f"{func}() of something that moves: this expression is differentiated {_TIMES[times]}, "
            f"which gives an impulse (DiracDelta) where the argument is 0")


def hint(func: str, times: int) -> str:
    smooth = "sqrt(x**2 + eps**2)" if func == "abs" else "x/sqrt(x**2 + eps**2)"
    if times == 1:
        return f"write {func}(x) smoothly, as {smooth} (in a potential, k*x*sign(x) is k*abs(x))"
    return f"write {func}(x) smoothly, as {smooth}, or split the motion where x = 0"


def built_kink(expr, times: int, moves) -> str:
    """The name of an abs()/sign() SymPy made of what the file wrote (sqrt(x**2) is Abs(x) for a real
    x) whose argument ``moves``; "" when there is none."""
    kinked = tuple(_BUILT[name] for name in KINKED.get(times, ()))
    for node in postorder([expr]):
        if isinstance(node, kinked) and moves(node.args[0]):
            return "abs" if isinstance(node, sp.Abs) else "sign"
    return ""


_BUILT = {"abs": sp.Abs, "sign": sp.sign}


def kink(tree: Node, times: int, moves: Callable[[Node], bool]) -> Call | None:
    """The first abs()/sign() call in ``tree`` whose derivative, taken ``times`` times, holds an
    impulse: its argument ``moves`` (depends on a coordinate, a rate or t); None when there is none."""
    kinked = KINKED.get(times, ())
    for node in walk(tree):
        if isinstance(node, Call) and node.func in kinked and moves(node.args[0]):
            return node
    return None
