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

import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp

from gacli.mechanics.equations import Derivation
from gacli.errors import GacliError

_STEP = 1e-30
# Central differences where the complex step cannot go (abs, sign): at 70 digits a step of
# 1e-30 leaves rounding near 1e-40 and, at a kink, an error of the order of the step.
_DIGITS = 70
_CENTRAL_STEP_EXPONENT = 30


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
        idx = state_indices(names, self.state)
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

    Raises:
        OptionError: a name in ``at`` is neither a state nor an input (a usage error).
        SystemFileError: the equations cannot be evaluated at the point, located at the
            file (or the load) whose expressions fail there.
    """
    return linearizer(derivation)(at, parameters)


def linearizer(derivation: Derivation):
    """``linearize`` for one derivation at many points: the equations compiled once (a sweep)."""
    from gacli.emit.naming import layout

    lay = layout(derivation)
    compiled = _Equations.make(derivation, lay, {})

    def at_point(at: Mapping[str, float] | None = None,
                 parameters: Mapping[str, float] | None = None) -> Linearization:
        values = _parameter_values(lay, parameters or {})
        point = dict(at or {})
        _require_known(point, lay)
        x0 = [float(point.get(n, 0.0)) for n in lay.state]
        r0 = [float(point.get(n, 0.0)) for n in lay.r]
        equations = compiled.with_values(lay, values)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error", RuntimeWarning)  # numpy's overflow or 0/0 is a failure here
                A = equations.jacobian(x0, r0, wrt="x")
                B = equations.jacobian(x0, r0, wrt="r")
        except (ArithmeticError, ValueError, TypeError, RuntimeWarning, np.linalg.LinAlgError) as exc:
            raise _unevaluable(derivation, dict(zip(lay.state + lay.r, x0 + r0)), exc) from None
        return Linearization(lay.state, lay.r, A, B, dict(zip(lay.state, x0)))

    return at_point


def rates_at(derivation: Derivation, at: Mapping[str, float] | None = None,
             parameters: Mapping[str, float] | None = None) -> dict[str, float]:
    """f = (q̇, u̇) at the point, by state name (a steady motion's kept rows are zero)."""
    from gacli.emit.naming import layout

    lay = layout(derivation)
    values = _parameter_values(lay, parameters or {})
    point = dict(at or {})
    _require_known(point, lay)
    base = [float(point.get(n, 0.0)) for n in lay.state + lay.r]
    q_dot, M0, F0 = (np.real(np.asarray(a, dtype=complex)) for a in _Equations.make(derivation, lay, values)._at(base))
    return dict(zip(lay.state, [*q_dot, *np.linalg.solve(M0, F0)]))


def _require_known(point: Mapping[str, float], lay) -> None:
    from gacli.simulate.spec import OptionError

    unknown = sorted(set(point) - set(lay.state) - set(lay.r))
    if unknown:
        known = ", ".join(lay.state + lay.r)
        raise OptionError([f"--at: not a state or input: {', '.join(unknown)} (the state and inputs are {known})"])


def _unevaluable(derivation: Derivation, point: Mapping[str, float], exc: Exception):
    """One located error: at the first load whose expressions fail at the point, else at the file."""
    from gacli.errors import Diagnostic, SystemFileError

    where = ", ".join(f"{n} = {v:g}" if isinstance(v, float) else f"{n} = {v}" for n, v in point.items())
    reason = str(exc) or type(exc).__name__
    message = (f"linearize: the equations cannot be evaluated or differentiated at the operating point "
               f"{where} ({reason}); choose another operating point (linearize: --at)")
    return SystemFileError([Diagnostic(_failing_place(derivation, point), message)])


def _failing_place(derivation: Derivation, point: Mapping[str, float]):
    """The location of the first force or torque that is not finite at the point; the file's otherwise."""
    from gacli.algebra import symbols as S

    system = derivation.system
    values = {S.value(c.name): v for c, v in ((c, point.get(c.name, 0.0)) for c in system.coordinates)}
    values.update({S.rate(n): point.get(f"dot({n})", 0.0) for n in system.rate_names})
    for load in (*system.forces, *system.torques):
        if not all(_finite(e.xreplace(values)) for e in load.vector):
            return load.location
    return system.location


def _finite(value: sp.Expr) -> bool:
    """False when ``value`` is undefined or infinite (symbols left in it, the parameters of --symbolic, aside)."""
    if value.has(*_UNDEFINED):
        return False
    if value.free_symbols:
        return True
    try:
        return bool(np.isfinite(complex(sp.N(value, 15))))
    except (ArithmeticError, ValueError, TypeError):
        return False


def _parameter_values(lay, overrides: Mapping[str, float]) -> dict[str, float]:
    values = {**lay.defaults, **overrides}
    missing = [n for n in lay.parameters if n not in values]
    if missing:
        raise LinearizeError(f"no value for the parameters {', '.join(missing)} (give them with --set)")
    return values


def _code_equations(derivation: Derivation) -> tuple[list, list, list]:
    """q̇, M (row-major, k²) and F as generated code computes them (Derivation.code): the program of
    a derivation for code alone too, so numeric linearization never needs the closed forms."""
    code = derivation.code
    return [e for _, e in code.kinematic_equations], list(code.dense_mass_matrix()), list(code.forcing)


@dataclass(frozen=True)
class _Equations:
    """q̇, M and F as functions of the point (x, r), the parameters put in, and how to differentiate them.

    They run one compiled program over the distinct subexpressions
    (gacli.numeric), which stays small where the written-out trees are huge.
    By the complex step where every function has a complex form; otherwise
    (abs, sign: not analytic) by central differences in mpmath at 70 digits,
    whose step 1e-30 leaves an error far below double rounding; at a kink
    such as abs(0) this gives the mean of the one-sided slopes.
    """

    program: object
    arguments: tuple[sp.Symbol, ...]
    fixed: dict
    n: int
    k: int
    analytic: bool

    @staticmethod
    def make(derivation: Derivation, lay, values: Mapping[str, float]) -> "_Equations":
        from gacli.numeric import Program
        from gacli.numeric.evaluator import MPMATH

        kin, M, F = _code_equations(derivation)
        exprs = kin + M + F
        fixed = {sym: values[sym.name] for sym in lay.parameter_symbols if sym.name in values}
        fixed[sp.Symbol("t", real=True)] = 0.0
        arguments = tuple(lay.state_symbols) + tuple(lay.r_symbols)
        try:
            return _Equations(Program(exprs), arguments, fixed, len(kin), derivation.k, True)
        except TypeError:
            return _Equations(Program(exprs, MPMATH), arguments, fixed, len(kin), derivation.k, False)

    def with_values(self, lay, values: Mapping[str, float]) -> "_Equations":
        from dataclasses import replace

        fixed = {sym: values[sym.name] for sym in lay.parameter_symbols}
        return replace(self, fixed={**fixed, sp.Symbol("t", real=True): 0.0})

    def __call__(self, point) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        numbers = self.program({**self.fixed, **dict(zip(self.arguments, point))})
        n, k = self.n, self.k
        kind = complex if self.analytic else object
        return (np.array(numbers[:n], dtype=kind), np.array(numbers[n:n + k * k], dtype=kind).reshape(k, k),
                np.array(numbers[n + k * k:], dtype=kind))

    def jacobian(self, x0: list[float], r0: list[float], wrt: str) -> np.ndarray:
        n, m = len(x0), len(r0)
        base = x0 + r0
        columns = range(n) if wrt == "x" else range(n, n + m)
        derivative = self._complex_step if self.analytic else self._central
        _, M0, F0 = (np.real(np.asarray(a, dtype=complex)) for a in self._at(base))
        u_dot = np.linalg.solve(M0, F0)
        out = []
        for j in columns:
            dq, dM, dF = derivative(base, j)
            out.append(np.concatenate([dq, np.linalg.solve(M0, dF - dM @ u_dot)]))
        return np.array(out).T if out else np.zeros((n, 0))

    def _at(self, point):
        if self.analytic:
            return self([complex(v) for v in point])
        with mpmath.workdps(_DIGITS):
            return tuple(np.vectorize(float, otypes=[float])(a) if a.size else a.astype(float)
                         for a in self([mpmath.mpf(v) for v in point]))

    def _complex_step(self, base, j):
        point = [complex(v) for v in base]
        point[j] += 1j * _STEP
        return tuple(np.asarray(a, dtype=complex).imag / _STEP for a in self(point))

    def _central(self, base, j):
        with mpmath.workdps(_DIGITS):
            h = mpmath.mpf(10) ** -_CENTRAL_STEP_EXPONENT
            up = [mpmath.mpf(v) for v in base]
            down = list(up)
            up[j] += h
            down[j] -= h
            pairs = zip(self(up), self(down))
            return tuple(np.vectorize(lambda a, b: float((a - b) / (2 * h)), otypes=[float])(u, d)
                         if u.size else u.astype(float) for u, d in pairs)


def linearize_symbolic(derivation: Derivation, at: Mapping[str, sp.Expr] | None = None) -> tuple[sp.Matrix, sp.Matrix]:
    """A and B as expressions, at an operating point given by expressions (small systems)."""
    from gacli.emit.naming import layout
    from gacli.algebra.readable import displayable

    if not derivation.printable or not displayable(derivation):  # a program alone: no expressions to differentiate
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
    if any(entry.has(*_UNDEFINED) for entry in (*A, *B)):
        shown = {name: point[sym] for name, sym in zip(lay.state + lay.r, lay.state_symbols + lay.r_symbols)}
        raise _unevaluable(derivation, shown, ValueError("A or B is undefined there"))
    return A.applyfunc(sp.simplify), B.applyfunc(sp.simplify)


_UNDEFINED = (sp.zoo, sp.nan, sp.oo, -sp.oo)


def state_indices(names: Sequence[str], state: Sequence[str]) -> list[int]:
    """Where each named state is; a name unknown or given twice is an OptionError (--states)."""
    from gacli.simulate.spec import OptionError

    unknown = [n for n in names if n not in state]
    if unknown:
        raise OptionError([f"--states: not in the state: {', '.join(unknown)} (the state is {', '.join(state)})"])
    twice = sorted({n for n in names if list(names).count(n) > 1})
    if twice:
        raise OptionError([f"--states: {', '.join(repr(n) for n in twice)} given twice"])
    return [list(state).index(n) for n in names]


def symbolic_point(derivation: Derivation, pairs) -> dict[str, sp.Expr]:
    """An operating point of expressions in numbers and the parameters, kept as symbols (--symbolic --at).

    A name that is no parameter stands for itself, a new real symbol: "dot(spin)=omega" keeps the
    spin rate free, so that A, and the conditions read from it, are functions of it.
    """
    from gacli.emit.naming import layout
    from gacli.read.expr.build import BuildError, Scope, build
    from gacli.read.expr.grammar import ParseError
    from gacli.read.expr.parser import parse

    lay = layout(derivation)
    _require_known(dict(pairs), lay)
    out = {}
    for name, text in pairs:
        try:
            tree = parse(text)
            known = dict(zip(lay.parameters, lay.parameter_symbols))
            free = {n: sp.Symbol(n, real=True) for n in _names(tree) if n not in known and n != "pi"}
            out[name] = build(tree, Scope(values={**known, **free}, declared=frozenset(lay.state),
                                          rate_note="an --at value is in numbers and parameters, or new names"))
        except (ParseError, BuildError) as exc:
            raise LinearizeError(f"--at {name}={text}: {exc.message}") from None
    return out


def _names(node) -> set[str]:
    """The plain names in a parsed expression (the grammar's nodes are dataclasses)."""
    import dataclasses

    from gacli.read.expr.grammar import Name

    if isinstance(node, Name):
        return {node.id}
    out: set[str] = set()
    if dataclasses.is_dataclass(node):
        for f in dataclasses.fields(node):
            value = getattr(node, f.name)
            for child in value if isinstance(value, tuple) else (value,):
                out |= _names(child)
    return out


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
    return format_cells([[f"{v:.10g}" for v in row] for row in matrix], rows, columns)


def format_cells(cells: Sequence[Sequence[str]], rows: Sequence[str], columns: Sequence[str]) -> list[str]:
    """A labelled table of text cells as aligned lines (a symbolic A's entries too)."""
    width = max([len(c) for row in cells for c in row] + [len(c) for c in columns] + [1])
    label = max([len(r) for r in rows] + [1])
    lines = [" " * label + "  " + " ".join(c.rjust(width) for c in columns)]
    lines += [r.ljust(label) + "  " + " ".join(c.rjust(width) for c in row) for r, row in zip(rows, cells)]
    return lines
