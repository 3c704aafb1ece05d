"""Linearization about an operating point: ẋ ≈ A δx + B δr.

The state is the generated code's (coordinates, then the independent rates
u); r holds the inputs and the free functions' values. The equations are
f(x, r) = [q̇ = β u + β₀ (eq. 14.20); u̇ = M⁻¹F (eq. 14.19)], and

.. code:: text

    A = ∂f/∂x,  B = ∂f/∂r,  with  ∂u̇/∂x_j = M⁻¹ (∂F/∂x_j − ∂M/∂x_j u̇)

Numerically the derivatives are taken by the complex step
(f(x + i h e_j) has imaginary part h ∂f/∂x_j to rounding, for h = 1e-30), so
A is as accurate as M and F themselves: no finite-difference error. The
symbolic form differentiates u̇ = M⁻¹F exactly, for small systems.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import sympy as sp

from gacli.mechanics.equations import Derivation
from gacli.errors import GacliError

_STEP = 1e-30


class LinearizeError(GacliError, ValueError):
    """An operating point or a selection of states that cannot be used."""


@dataclass(frozen=True)
class Linearization:
    """A and B at an operating point, with the names of their rows and columns."""

    state: tuple[str, ...]
    inputs: tuple[str, ...]
    A: np.ndarray
    B: np.ndarray
    point: Mapping[str, float]

    def block(self, names: Sequence[str]) -> np.ndarray:
        """The rows and columns of A for the named states, in that order."""
        unknown = [n for n in names if n not in self.state]
        if unknown:
            raise LinearizeError(f"not in the state: {', '.join(unknown)} (the state is {', '.join(self.state)})")
        idx = [self.state.index(n) for n in names]
        return self.A[np.ix_(idx, idx)]

    def eigenvalues(self, names: Sequence[str] | None = None) -> np.ndarray:
        """Eigenvalues of A (or of the block of the named states), sorted by real part, then imaginary."""
        matrix = self.A if not names else self.block(names)
        values = np.linalg.eigvals(matrix)
        return values[np.lexsort((values.imag, values.real))]


def linearize(derivation: Derivation, at: Mapping[str, float] | None = None,
              parameters: Mapping[str, float] | None = None) -> Linearization:
    """A and B at the operating point ``at`` (state and r names; others 0).

    Parameter values are the file's defaults, overridden by ``parameters``.
    """
    from gacli.emit.naming import layout

    lay = layout(derivation)
    values = _parameter_values(lay, parameters or {})
    point = dict(at or {})
    unknown = sorted(set(point) - set(lay.state) - set(lay.r))
    if unknown:
        raise LinearizeError(f"not a state or input: {', '.join(unknown)} (the state is {', '.join(lay.state)})")
    x0 = np.array([point.get(n, 0.0) for n in lay.state], dtype=complex)
    r0 = np.array([point.get(n, 0.0) for n in lay.r], dtype=complex)
    kinematic, mass, forcing = _numeric_functions(derivation, lay, values)
    try:
        A = _jacobian(kinematic, mass, forcing, x0, r0, wrt="x")
        B = _jacobian(kinematic, mass, forcing, x0, r0, wrt="r")
    except (ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
        # e.g. sqrt(dot(x)**2 + dot(y)**2) of a nonlinear constraint, not differentiable where it vanishes
        raise LinearizeError(f"the equations cannot be evaluated or differentiated at this operating point "
                             f"({exc}); choose another with --at") from None
    return Linearization(lay.state, lay.r, A, B, {**{n: float(v.real) for n, v in zip(lay.state, x0)}})


def _parameter_values(lay, overrides: Mapping[str, float]) -> dict[str, float]:
    values = {**lay.defaults, **overrides}
    missing = [n for n in lay.parameters if n not in values]
    if missing:
        raise LinearizeError(f"no value for the parameters {', '.join(missing)} (give them with --set)")
    return values


def _numeric_functions(derivation: Derivation, lay, values: Mapping[str, float]):
    """Functions of (x, r) for q̇, M and F, the parameters put in.

    They run one compiled program over the distinct subexpressions
    (gacli.numeric), which stays small where the written-out trees are huge.
    """
    from gacli.numeric import Program

    fixed = {sym: complex(values[sym.name]) for sym in lay.parameter_symbols}
    fixed[sp.Symbol("t", real=True)] = 0j
    args = list(lay.state_symbols) + list(lay.r_symbols)
    kin = [e for _, e in derivation.kinematic_equations]
    n, k = len(kin), derivation.k
    program = Program(kin + list(derivation.mass_matrix) + list(derivation.forcing))
    cache: dict[tuple, list[complex]] = {}

    def evaluate(point) -> list[complex]:
        key = tuple(point)
        if key not in cache:
            cache.clear()
            cache[key] = program({**fixed, **dict(zip(args, point))})
        return cache[key]

    def kinematic(*point):
        return np.array(evaluate(point)[:n])

    def mass(*point):
        return np.array(evaluate(point)[n:n + k * k]).reshape(k, k)

    def forcing(*point):
        return np.array(evaluate(point)[n + k * k:])

    return kinematic, mass, forcing


def _jacobian(kinematic, mass, forcing, x0, r0, wrt: str) -> np.ndarray:
    n, m = len(x0), len(r0)
    base = np.concatenate([x0, r0])
    M0 = np.array(mass(*base), dtype=complex).real
    F0 = np.array(forcing(*base), dtype=complex).real.ravel()
    u_dot = np.linalg.solve(M0, F0)
    columns = range(n) if wrt == "x" else range(n, n + m)
    out = []
    for j in columns:
        point = base.copy()
        point[j] += 1j * _STEP
        dq = np.array(kinematic(*point), dtype=complex).imag.ravel() / _STEP
        dM = np.array(mass(*point), dtype=complex).imag / _STEP
        dF = np.array(forcing(*point), dtype=complex).imag.ravel() / _STEP
        du = np.linalg.solve(M0, dF - dM @ u_dot)
        out.append(np.concatenate([dq, du]))
    return np.array(out).T if out else np.zeros((n, 0))


def linearize_symbolic(derivation: Derivation, at: Mapping[str, sp.Expr] | None = None) -> tuple[sp.Matrix, sp.Matrix]:
    """A and B as expressions, at an operating point given by expressions (small systems)."""
    from gacli.emit.naming import layout
    from gacli.algebra.readable import displayable

    if not displayable(derivation):
        raise LinearizeError("--symbolic: the equations of this system are too large for a symbolic "
                             "linearization (millions of terms as trees); leave out --symbolic for A and B "
                             "as numbers, exact to rounding")
    lay = layout(derivation)
    u_dot = derivation.mass_matrix.LUsolve(derivation.forcing)
    f = sp.Matrix([e for _, e in derivation.kinematic_equations]).col_join(u_dot)
    given = dict(at or {})
    point = {sym: _expression(given.get(name, 0))
             for name, sym in zip(lay.state + lay.r, lay.state_symbols + lay.r_symbols)}
    A = f.jacobian(list(lay.state_symbols)).xreplace(point)
    B = f.jacobian(list(lay.r_symbols)).xreplace(point) if lay.r else sp.zeros(len(lay.state), 0)
    return A.applyfunc(sp.simplify), B.applyfunc(sp.simplify)


def _expression(value) -> sp.Expr:
    return value if isinstance(value, sp.Basic) else sp.Float(value)


def evaluate_assignments(pairs, parameters: Mapping[str, float], option: str) -> dict[str, float]:
    """Numbers from ``name=expression`` pairs; expressions in numbers and parameters (safe parser)."""
    from gacli.read.expr.build import BuildError, Scope, build
    from gacli.read.expr.grammar import ParseError
    from gacli.read.expr.parser import parse

    scope = Scope(values={n: sp.Float(v, 30) for n, v in parameters.items()})
    out = {}
    for name, text in pairs:
        try:
            value = build(parse(text), scope)
        except (ParseError, BuildError) as exc:
            raise LinearizeError(f"{option} {name}={text}: {exc.message}") from None
        if value.free_symbols or not value.is_real:
            raise LinearizeError(f"{option} {name}={text}: not a real number")
        out[name] = float(value)
    return out


def format_matrix(matrix: np.ndarray, rows: Sequence[str], columns: Sequence[str]) -> list[str]:
    """A labelled matrix as aligned text lines, %.10g entries."""
    cells = [[f"{v:.10g}" for v in row] for row in matrix]
    width = max([len(c) for row in cells for c in row] + [len(c) for c in columns] + [1])
    label = max([len(r) for r in rows] + [1])
    lines = [" " * label + "  " + " ".join(c.rjust(width) for c in columns)]
    lines += [r.ljust(label) + "  " + " ".join(c.rjust(width) for c in row) for r, row in zip(rows, cells)]
    return lines
