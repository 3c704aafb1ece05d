"""The plain SymPy symbols that stand for time, coordinates and their rates.

gacli never uses SymPy functions of time: a coordinate ``x`` is the symbol
``x``, its rate the symbol ``dot(x)``, its acceleration ``ddot(x)``, and the
time derivative is our own operator :func:`time_derivative`, which follows the
chain q → dot(q) → ddot(q) and Omega → dot(Omega) → ... The symbol names are
written in the system file's own grammar, so a printed equation can be read
back as an expression.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping

import sympy as sp

# SymPy's Add.flatten imports sympy.tensor.tensor (and with it
# sympy.combinatorics, about 25 ms of CPU) the first time any program adds two
# expressions; nothing in ``import sympy`` does. Every command that loads this
# module goes on to add expressions, so the import is part of loading SymPy for
# gacli, as it is for ``sympy.physics.mechanics``, whose own import adds some.
# Here it is counted as an import, not as the first derivation's work; it moves
# the cost, it does not remove it.
import sympy.tensor.tensor  # noqa: E402, F401

from gacli.algebra.fastdiff import Differentiator

T = sp.Symbol("t", real=True)

_ORDER_PREFIX = {0: "", 1: "dot", 2: "ddot"}
# A rate's name as rate_name writes it: prefix, the order of a d3(...) or higher, the name.
RATE_NAME = re.compile(r"^(dot|ddot|d(\d+))\((.+)\)$")


def rate_name(name: str, order: int) -> str:
    """``x``, ``dot(x)``, ``ddot(x)``, then ``d3(x)``, ``d4(x)`` ..."""
    if order == 0:
        return name
    prefix = _ORDER_PREFIX.get(order, f"d{order}")
    return f"{prefix}({name})"


def value(name: str) -> sp.Symbol:
    return sp.Symbol(name, real=True)


def rate(name: str, order: int = 1) -> sp.Symbol:
    return sp.Symbol(rate_name(name, order), real=True)


def differential(name: str) -> sp.Symbol:
    # Brackets keep it apart from any user symbol: 'dx' may not be declared
    # beside 'x', but a user may still declare a name like 'd'.
    return sp.Symbol(f"d[{name}]", real=True)


DT = differential("t")


def time_derivative(expr: sp.Expr, chain: Mapping[sp.Symbol, sp.Expr]) -> sp.Expr:
    """Total time derivative: ∂e/∂t + Σ ∂e/∂s · ṡ over the symbols in ``chain``.

    ``chain`` maps a symbol to its rate expressed however the caller needs
    (for a dependent coordinate, its rate in terms of the independent rates,
    eq. (14.7)). Symbols absent from ``chain`` are constant.
    """
    return time_differentiator(chain)(expr)


def time_differentiator(chain: Mapping[sp.Symbol, sp.Expr]) -> Differentiator:
    """d/dt as one memoised walk (see :mod:`gacli.algebra.fastdiff`); reuse it for all entries of a matrix."""
    return Differentiator({T: sp.S.One, **chain})


def time_chain(functions: Iterable[str]) -> dict[sp.Symbol, sp.Expr]:
    """d/dt of what holds time apart from the coordinates: t → 1, each free function → its rate."""
    return {T: sp.S.One, **function_chain(functions)}


def function_chain(names: Iterable[str], orders: int = 4) -> dict[sp.Symbol, sp.Symbol]:
    """d/dt of free functions of time up to ``orders`` derivatives: Omega → dot(Omega) → ddot(Omega) → ..."""
    return {rate(n, o): rate(n, o + 1) for n in names for o in range(orders)}
