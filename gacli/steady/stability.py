"""Linear stability of a steady motion on the constraint manifold (numbers or conditions).

The state is reduced first (:mod:`gacli.steady.manifold`): ignorable
coordinates out, held ones moved along the manifold. Numerically the
verdict reads the eigenvalues of the reduced A; the ones at zero (a
neighbouring steady motion of the same family: another speed, another spin)
are counted apart and do not decide. Symbolically the characteristic
polynomial of the reduced A gives conditions on the parameters
(:mod:`gacli.steady.hurwitz`); the verdict is "stable" in the sense of the
literature for these systems, no eigenvalue with a positive real part.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.mechanics.equations import Derivation
from gacli.steady.manifold import Reduction, reduce_state, restricted

LAMBDA = sp.Symbol("lambda")
# Relative to the size of A: the complex step is exact to rounding, so far above it.
_ZERO = 1e-9


@dataclass(frozen=True)
class Stability:
    """The reduced A at a point and what it says."""

    reduction: Reduction
    A: object                                   # numpy array, or SymPy Matrix (symbolic)
    point: Mapping[str, object]
    steady: bool                                # the point is a steady motion (kept rows of f zero)
    eigenvalues: np.ndarray | None = None       # numeric
    zero_roots: int = 0
    stable: bool | None = None                  # numeric verdict; None when symbolic
    polynomial: sp.Expr | None = None           # symbolic: det(λI − A)
    # "even" or "hurwitz"; None when no closed test applied: then the eigenvalues with the file's
    # values decide (symbolic), if the point has no symbol of its own, and conditions is empty.
    test: str | None = None
    conditions: tuple[sp.Expr, ...] = field(default=())   # each > 0, together: stable

    @property
    def state(self) -> tuple[str, ...]:
        return self.reduction.state


def stability(derivation: Derivation, at: Mapping[str, float] | None = None,
              parameters: Mapping[str, float] | None = None) -> Stability:
    """Eigenvalues of the reduced A at ``at`` (others 0), with the file's parameter values over ``parameters``."""
    from gacli.linearize import linearize, rates_at
    from gacli.sweep.work import resolved_parameters

    values = resolved_parameters(derivation.system, dict(parameters or {}))
    reduction = reduce_state(derivation, values)
    lin = linearize(derivation, at, values)
    A = np.array(restricted(lin.A, lin.state, reduction), dtype=float).reshape(len(reduction.state), -1)
    f = rates_at(derivation, at, values)
    steady = steady_numeric(f, reduction)
    eigenvalues, zero, stable = verdict(A)
    return Stability(reduction, A, dict(lin.point), steady, eigenvalues, zero, stable)


def verdict(A: np.ndarray, zero: int | None = None) -> tuple[np.ndarray, int, bool]:
    """Sorted eigenvalues, how many are at zero, and whether none of the others grows.

    ``zero``: the number of zero roots known (a sweep counts them once); else those within
    the tolerance here.
    """
    values = np.linalg.eigvals(A) if A.size else np.zeros(0, dtype=complex)
    values = values[np.lexsort((values.imag, values.real))]
    scale = max(1.0, float(np.abs(A).max())) if A.size else 1.0
    if zero is None:
        zero = int(np.sum(np.abs(values) <= _ZERO * scale))
    rest = np.sort_complex(values[np.argsort(np.abs(values), kind="stable")[zero:]])
    return values, zero, bool(np.all(rest.real <= _ZERO * scale))


def growth(A: np.ndarray, zero: int) -> float:
    """The largest real part once the ``zero`` eigenvalues nearest zero are set aside."""
    values = np.linalg.eigvals(A)
    rest = values[np.argsort(np.abs(values), kind="stable")[zero:]]
    return float(rest.real.max()) if rest.size else 0.0


def steady_numeric(f: Mapping[str, float], reduction: Reduction) -> bool:
    """Whether the kept rows of f = (q̇, u̇) vanish at the point: a steady motion."""
    rows = [f[c] for c in reduction.coordinates] + [f[u] for u in reduction.speeds]
    return bool(np.all(np.abs(rows) <= 1e-9 * max(1.0, float(np.abs(list(f.values())).max()))))


def stability_symbolic(derivation: Derivation, at: Mapping[str, sp.Expr] | None = None) -> Stability:
    """The reduced A and its characteristic polynomial at a point of expressions (others 0), and
    conditions on the parameters (and on the point's own symbols) for stability."""
    from gacli.emit.naming import parameter_defaults
    from gacli.steady import hurwitz, require_small, symbolic

    require_small(derivation, "symbolic stability")
    defaults = parameter_defaults(derivation.system.parameters)
    reduction = reduce_state(derivation, defaults)
    point = _symbolic_point(derivation, at or {})
    columns = reduction.coordinates + reduction.held + reduction.speeds
    full = symbolic.jacobian(derivation, point, columns, columns)
    A = sp.Matrix(restricted(full, columns, reduction)).applyfunc(sp.factor)
    rows = symbolic.residual(derivation, point, reduction.coordinates + reduction.speeds)
    steady = all(sp.simplify(e) == 0 for e in rows)
    polynomial = A.charpoly(LAMBDA).as_expr() if A.rows else sp.S.One
    coefficients = sp.Poly(polynomial, LAMBDA).all_coeffs()[::-1]
    zero = hurwitz.zero_roots(coefficients)
    found = hurwitz.conditions(coefficients[zero:], _signs(derivation, defaults))
    shown = {name: point[_symbol(name)] for name in reduction.state}
    if found:
        return Stability(reduction, A, shown, steady, zero_roots=zero, polynomial=sp.factor(polynomial),
                         test=found[0], conditions=tuple(found[1]))
    # No closed test: the numbers decide, with the file's values, where the point has no symbol of its own.
    numbers = A.xreplace({S.value(n): sp.Float(v) for n, v in defaults.items()})
    eigenvalues, stable = None, None
    if not numbers.free_symbols:
        eigenvalues, zero, stable = verdict(np.array(numbers.evalf().tolist(), dtype=float))
    return Stability(reduction, A, shown, steady, eigenvalues, zero, stable, polynomial=sp.factor(polynomial))


def _symbol(name: str) -> sp.Symbol:
    return sp.Symbol(name, real=True)


def _symbolic_point(derivation: Derivation, at: Mapping[str, sp.Expr]) -> dict[sp.Symbol, sp.Expr]:
    names = [c.name for c in derivation.system.coordinates] + [str(u) for u in derivation.speeds]
    point = {_symbol(n): _expr(at.get(n, 0)) for n in names}
    point.update({S.value(i.name): _expr(at.get(i.name, 0)) for i in derivation.system.inputs})
    point[S.T] = sp.S.Zero
    return point


def _expr(value) -> sp.Expr:
    if isinstance(value, sp.Basic):
        return value
    return sp.Integer(value) if float(value).is_integer() else sp.Float(value)


def _signs(derivation: Derivation, defaults: Mapping[str, float]) -> dict[sp.Symbol, sp.Symbol]:
    """Each parameter with a nonzero file value, to a symbol of that sign."""
    return {S.value(n): sp.Symbol(n, positive=True) if v > 0 else sp.Symbol(n, negative=True)
            for n, v in defaults.items() if v != 0}
