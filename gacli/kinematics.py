"""Rates, velocities and accelerations in terms of the independent rates.

Step 1 of the chapter's solution procedure: the constraints (eq. 14.1) and the
quasi-coordinate definitions (eq. 14.2) are linear in the n + p rates; with k
of them chosen as the independent rates u, the others follow as
ṙ = β u + β₀ (eqs. 14.4, 14.7). Then each body's velocity is V u + v₀ and its
acceleration V u̇ + a_rest (eq. 14.14), where V holds the partial velocities
(the α_rs of eq. 14.6) and a_rest is free of the u̇.
"""

from __future__ import annotations

import random
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import sympy as sp

from gacli import nonlinear as NL
from gacli import symbols as S
from gacli import trig
from gacli.errors import Diagnostic, SystemFileError
from gacli.fastdiff import jacobian_rows
from gacli.graph import is_small
from gacli.model import Body, Form, System

# Ranks are decided at a random configuration: a generic rank of a matrix of
# functions equals its rank at almost every point. Fixed seed: same answer
# every run.
_SEED = 20261122
_RANK_TOL = 1e-9


_ZERO = sp.S.Zero


@dataclass(frozen=True)
class Rates:
    """ṙ = β u + β₀ for every coordinate and quasi-coordinate (eq. 14.7)."""

    names: tuple[str, ...]
    independent: tuple[str, ...]
    chosen_automatically: bool
    beta: sp.ImmutableMatrix
    beta0: sp.ImmutableMatrix
    constraints_used: int = 0
    relations: sp.ImmutableMatrix = sp.ImmutableMatrix(0, 0, [])
    relations_dt: sp.ImmutableMatrix = sp.ImmutableMatrix(0, 1, [])
    # (name, f(q, u, t)) for each rate a nonlinear constraint determines (β u + β₀ equals it;
    # f is how the reader wrote it).
    nonlinear: tuple[tuple[str, sp.Expr], ...] = ()

    @property
    def k(self) -> int:
        return len(self.independent)

    @cached_property  # asked for by every body: once, not k symbols each time
    def speeds(self) -> tuple[sp.Symbol, ...]:
        """The independent rates u."""
        return tuple(S.rate(n) for n in self.independent)

    @cached_property
    def speed_rates(self) -> tuple[sp.Symbol, ...]:
        """Their time derivatives u̇."""
        return tuple(S.rate(n, 2) for n in self.independent)

    def rate(self, name: str) -> sp.Expr:
        for n, f in self.nonlinear:
            if n == name:
                return f
        i = self._index[name]
        return sp.Add(*[b * u for b, u in zip(self._beta_rows[i], self.speeds) if _nonzero(b)], self._beta0_column[i])

    def row_lists(self, names) -> tuple[list[tuple[sp.Expr, ...]], list[tuple[sp.Expr]]]:
        """The rows of β and β₀ for ``names``, for the list arithmetic of :func:`product_rows`."""
        idx = [self._index[n] for n in names]
        return [self._beta_rows[i] for i in idx], [(self._beta0_column[i],) for i in idx]

    # Tuples, computed once: indexing a SymPy matrix entry by entry costs more than
    # the arithmetic done with the entries, and callers share them.
    @cached_property
    def _index(self) -> dict[str, int]:
        return {n: i for i, n in enumerate(self.names)}

    @cached_property
    def _beta_rows(self) -> tuple[tuple[sp.Expr, ...], ...]:
        return tuple(tuple(row) for row in self.beta.tolist())

    @cached_property
    def _beta0_column(self) -> tuple[sp.Expr, ...]:
        return tuple(self.beta0)


@dataclass(frozen=True)
class Motion:
    """Velocity and acceleration of a point, or angular ones of a body, in u and u̇.

    velocity = partials · u + velocity0; acceleration = partials · u̇ + acceleration_rest.
    """

    partials: sp.ImmutableMatrix
    velocity0: sp.ImmutableMatrix
    acceleration_rest: sp.ImmutableMatrix


@dataclass(frozen=True)
class BodyMotion:
    body: Body
    linear: Motion
    angular: Motion | None


# -- step 1: solve the linear relations among the rates ----------------------

def relation_rows(system: System) -> tuple[list[tuple[str, object, Form]], list[str]]:
    """The rows A ṙ + a₀ = 0: constraints (14.1) then quasi definitions (14.2).

    A derived row (rolling contact) that depends on the rows before it is left
    out: it says again what they say.
    """
    rows = []
    kept = np.zeros((0, len(system.rate_names)))
    for i, c in enumerate(system.constraints):
        if c.derived:
            numeric = _numeric(sp.Matrix([[c.form.coefficient(n) for n in system.rate_names]]), system)
            if _rank(np.vstack([kept, numeric])) == kept.shape[0]:
                continue
            kept = np.vstack([kept, numeric])
        rows.append((f"constraints[{i}]", c.location, c.form))
    for q in system.quasi_coordinates:
        if q.differential is not None:
            own = Form(((q.name, sp.S.One),))
            rows.append((f"quasi_coordinates.{q.name}", q.location, _subtract(own, q.differential)))
    return rows, list(system.rate_names)


def _subtract(a: Form, b: Form) -> Form:
    names = list(dict.fromkeys(a.names + b.names))
    coefficients = tuple((n, a.coefficient(n) - b.coefficient(n)) for n in names)
    return Form(tuple((n, c) for n, c in coefficients if c != 0), a.dt - b.dt)


def solve_rates(system: System) -> Rates:
    """Every rate in terms of the k independent rates: affine (eq. 14.7), or through a nonlinear relation."""
    rows, names = relation_rows(system)
    A = sp.Matrix([[form.coefficient(n) for n in names] for _, _, form in rows]) if rows else sp.zeros(0, len(names))
    a0 = sp.Matrix([form.dt for _, _, form in rows]) if rows else sp.zeros(0, 1)
    k = len(names) - len(rows)
    numeric = _numeric(A, system)
    _check_rank(system, rows, numeric)
    if k <= 0:
        raise _error(system, system.location, "",
                     f"the system has no degree of freedom: k = n + p - d - ℓ = {k}")
    # A rate a nonlinear constraint determines is solved from it afterwards
    # (docs/nonlinear.md); the Pfaffian rows are solved for the rest as before.
    nonlinear = _nonlinear_rates(system, rows)
    linear = [i for i, (where, _, _) in enumerate(rows) if where not in nonlinear.values()]
    names_lin = [n for n in names if n not in nonlinear]
    columns = [names.index(n) for n in names_lin]
    A_lin, a0_lin = A.extract(linear, columns), a0.extract(linear, [0])
    independent, automatic = _choose_independent(system, names_lin, numeric[np.ix_(linear, columns)], k)
    dependent = [n for n in names_lin if n not in independent]
    beta_lin, beta0_lin = _solve(A_lin, a0_lin, names_lin, independent, dependent)
    beta, beta0, solved = _with_nonlinear(system, names, names_lin, independent, beta_lin, beta0_lin, nonlinear)
    used = sum(1 for where, _, _ in rows if where.startswith("constraints"))
    return Rates(tuple(names), tuple(independent), automatic, beta, beta0, used,
                 sp.ImmutableMatrix(A), sp.ImmutableMatrix(a0), solved)


def _nonlinear_rates(system: System, rows) -> dict[str, str]:
    """{rate a nonlinear constraint determines: that constraint's row label}, checked."""
    out: dict[str, str] = {}
    for i, c in enumerate(system.constraints):
        if c.rates is None:
            continue
        d, where = c.rates.dependent, f"constraints[{i}]"
        if d in out:
            raise _error(system, c.location, where, f"dot({d}) is already determined by {out[d]}",
                         "solve each nonlinear constraint for a different rate")
        if system.independent is not None and d in system.independent:
            raise _error(system, system.independent_location, "independent",
                         f"dot({d}) is determined by the nonlinear constraint {where}; it cannot be independent")
        out[d] = where
    for where, location, form in rows:
        clash = [d for d in out if where not in out.values() and form.coefficient(d) != 0]
        if clash:
            raise _error(system, location, where,
                         f"dot({clash[0]}) is determined by the nonlinear constraint {out[clash[0]]}; "
                         "a Pfaffian relation may not involve it too")
    return out


def _with_nonlinear(system: System, names, names_lin, independent, beta_lin, beta0_lin, nonlinear):
    """β and β₀ over all rates: the Pfaffian solution, then each nonlinear rate's f(q, u, t) split by NL.split."""
    if not nonlinear:  # names_lin is names, in order
        return beta_lin, beta0_lin, ()
    speeds = [S.rate(n) for n in independent]
    # Lists, not matrix entries set one by one: SymPy's setitem costs k per row.
    rows = dict(zip(names_lin, beta_lin.tolist()))
    rests = dict(zip(names_lin, beta0_lin))
    rates = {S.rate(n): sp.Add(*[b * u for b, u in zip(rows[n], speeds) if b != 0], rests[n]) for n in names_lin}
    by_where = {where: d for d, where in nonlinear.items()}
    solved = []
    for i, c in enumerate(system.constraints):
        d = by_where.get(f"constraints[{i}]")
        if d is None:
            continue
        f = c.rates.solution.xreplace(rates)
        if f.free_symbols & {S.rate(other) for other in nonlinear}:
            raise _error(system, c.location, f"constraints[{i}]",
                         "a nonlinear constraint may involve only rates that the others do not determine nonlinearly")
        rows[d], rests[d] = NL.split(f, speeds)
        solved.append((d, f))
    k = len(independent)
    return (sp.ImmutableMatrix(len(names), k, [e for n in names for e in rows[n]]),
            sp.ImmutableMatrix(len(names), 1, [rests[n] for n in names]), tuple(solved))


def _numeric(A: sp.Matrix, system: System) -> np.ndarray:
    """A at a generic point, complex allowed; a few points are tried until every entry is finite."""
    if A.rows == 0:
        return np.zeros((0, A.cols))
    for attempt in range(5):
        point = random_point(A.free_symbols, _SEED + attempt)
        try:
            values = np.array(A.xreplace(point).evalf(20).tolist(), dtype=complex)
        except (TypeError, ValueError, ArithmeticError):
            continue
        if np.all(np.isfinite(values)):
            return values
    raise _error(system, system.location, "",
                 "the coefficients of the constraints and quasi-coordinates cannot be evaluated "
                 "to finite numbers at generic points")


def random_point(symbols, seed: int = _SEED) -> dict[sp.Symbol, sp.Float]:
    """Deterministic generic values in [0.4, 1.6] for the given symbols."""
    rng = random.Random(seed)
    ordered = sorted(symbols, key=lambda s: s.name)
    return {s: sp.Float(rng.uniform(0.4, 1.6)) for s in ordered}


def _rank(matrix: np.ndarray) -> int:
    if matrix.size == 0:
        return 0
    return int(np.linalg.matrix_rank(matrix, tol=_RANK_TOL * max(1.0, np.abs(matrix).max())))


def _check_rank(system: System, rows, numeric: np.ndarray) -> None:
    """The matrix [B; C] must have full rank (the condition below eq. 14.3)."""
    if _rank(numeric) == numeric.shape[0]:
        return
    kept: list[int] = []
    diagnostics = []
    for i, (where, location, _) in enumerate(rows):
        if _rank(numeric[kept + [i]]) > len(kept):
            kept.append(i)
            continue
        others = ", ".join(rows[j][0] for j in kept) or "nothing"
        message = ("this relation is not independent of the others (the matrix of constraint and "
                   "quasi-coordinate coefficients must have full rank)")
        diagnostics.append(Diagnostic(location, message, where, f"it depends on {others}"))
    raise SystemFileError(diagnostics)


def _choose_independent(system: System, names: list[str], numeric: np.ndarray, k: int) -> tuple[list[str], bool]:
    automatic = _earliest_independent(names, numeric)
    if system.independent is None:
        return automatic, True
    given = list(system.independent)
    if len(given) != k:
        raise _error(system, system.independent_location, "independent",
                     f"expected {k} independent names (k = n + p - d - ℓ = {k}), found {len(given)}",
                     f"for example: [{', '.join(automatic)}]")
    dependent = [names.index(n) for n in names if n not in given]
    if _rank(numeric[:, dependent]) < len(dependent):
        dep = ", ".join(names[i] for i in dependent)
        raise _error(system, system.independent_location, "independent",
                     f"the rates of {', '.join(given)} cannot all be chosen freely: "
                     f"the constraints do not determine {dep} from them",
                     f"a valid choice is [{', '.join(automatic)}]")
    return given, False


def _earliest_independent(names: list[str], numeric: np.ndarray) -> list[str]:
    """The earliest-declared valid independent set.

    The dependent rates must index a basis of the columns; taking columns
    greedily from the last leaves the earliest names independent.
    """
    basis: list[int] = []
    for j in reversed(range(len(names))):
        if _rank(numeric[:, basis + [j]]) > len(basis):
            basis.append(j)
    return [n for j, n in enumerate(names) if j not in basis]


def _solve(A, a0, names, independent, dependent):
    n, k = len(names), len(independent)
    beta = sp.zeros(n, k)
    beta0 = sp.zeros(n, 1)
    for s, name in enumerate(independent):
        beta[names.index(name), s] = 1
    if dependent:
        Ad = A.extract(list(range(A.rows)), [names.index(d) for d in dependent])
        Ai = A.extract(list(range(A.rows)), [names.index(i) for i in independent])
        rhs = (-Ai).row_join(-a0)
        solution = solve_linear(Ad, rhs).applyfunc(_tidy)
        for r, name in enumerate(dependent):
            beta[names.index(name), :] = solution[r, :k]
            beta0[names.index(name), 0] = solution[r, k]
    return sp.ImmutableMatrix(beta), sp.ImmutableMatrix(beta0)


def solve_linear(A: sp.Matrix, B: sp.Matrix) -> sp.Matrix:
    """A⁻¹ B as adj(A) B / det(A), without pivots.

    Gaussian elimination divides by pivots chosen as "not identically zero";
    such a pivot (sin(yaw), say) can vanish at an ordinary configuration where
    A is regular, and the solved rates then read 0/0 there (a bicycle going
    straight north). The adjugate divides only by det A, which vanishes only
    where the rates are truly undetermined.
    """
    if A.rows == 1:
        return B / A[0, 0]
    if A.rows > _ADJUGATE_MAX:
        return A.LUsolve(B)
    minor = _minors(A)
    everything = tuple(range(A.rows))
    # Reduced by sin² + cos² = 1: a sleigh's determinant is sin(θ)² + cos(θ)², which is 1.
    det = trig.reduce(minor(everything, everything))

    def entry(i: int, c: int) -> sp.Expr:
        # (adj A)_ij = (-1)^(i+j) det(A without row j and column i)
        terms = [(-1) ** (i + j) * minor(_without(everything, j), _without(everything, i)) * B[j, c]
                 for j in range(A.rows) if B[j, c] != 0]
        return trig.reduce(sp.Add(*terms)) / det

    return sp.Matrix(A.rows, B.cols, entry)


def _without(indices: tuple[int, ...], i: int) -> tuple[int, ...]:
    return tuple(j for j in indices if j != i)


def _minors(A: sp.Matrix):
    """det of the submatrix on (rows, columns), by Laplace expansion along the first row.

    Memoised over the submatrices, skipping zero entries: the constraint
    matrices are sparse, and SymPy's Berkowitz determinant goes through its
    matrix product, which multiplies the zeros too (0·expr asks whether expr
    is finite, a walk of the whole tree).
    """
    memo: dict[tuple[tuple[int, ...], tuple[int, ...]], sp.Expr] = {}

    def det(rows: tuple[int, ...], columns: tuple[int, ...]) -> sp.Expr:
        if not rows:
            return sp.S.One
        known = memo.get((rows, columns))
        if known is None:
            terms = []
            for position, c in enumerate(columns):
                a = A[rows[0], c]
                if a != 0:
                    rest = det(rows[1:], columns[:position] + columns[position + 1:])
                    if rest != 0:
                        terms.append((-1) ** position * a * rest)
            known = memo[(rows, columns)] = sp.Add(*terms)
        return known

    return det


_ADJUGATE_MAX = 6


def _tidy(expr: sp.Expr) -> sp.Expr:
    """Cancel rational clutter that elimination leaves, while it is cheap."""
    return sp.cancel(expr) if is_small(expr, 400) else expr


def _error(system: System, location, where: str, message: str, hint: str = "") -> SystemFileError:
    return SystemFileError([Diagnostic(location, message, where, hint)])


# -- step 2: velocities and accelerations ------------------------------------

def function_chain(system: System) -> dict[sp.Symbol, sp.Symbol]:
    """d/dt of the free functions of time: Omega → dot(Omega) → ddot(Omega) → ..."""
    return {S.rate(f.name, o): S.rate(f.name, o + 1) for f in system.free_functions for o in range(4)}


def configuration_chain(system: System, rates: Rates) -> dict[sp.Symbol, sp.Expr]:
    """d/dt of each symbol that moves, holding u fixed: q̇ = β u + β₀ and the functions."""
    chain: dict[sp.Symbol, sp.Expr] = {S.value(c.name): rates.rate(c.name) for c in system.coordinates}
    chain.update(function_chain(system))
    return chain


def rate_symbols_chain(system: System) -> dict[sp.Symbol, sp.Symbol]:
    """d/dt with the rates kept as plain symbols: q → dot(q), and the functions."""
    chain: dict[sp.Symbol, sp.Symbol] = {S.value(c.name): S.rate(c.name) for c in system.coordinates}
    chain.update(function_chain(system))
    return chain


def dependent_acceleration_rest(system: System, rates: Rates) -> dict[str, sp.Expr]:
    """γ with r̈ = β u̇ + γ for every rate (γ = 0 for the independent ones).

    The relations A ṙ + a₀ = 0 are differentiated, A r̈ + Ȧ ṙ + ȧ₀ = 0, and
    solved for the dependent accelerations; differentiating the constraints
    rather than the solved β keeps the expressions small.
    """
    names = list(rates.names)
    gamma = {n: sp.S.Zero for n in names}
    dependent = [n for n in names if n not in rates.independent]
    if not dependent:
        return gamma
    A, a0 = sp.Matrix(rates.relations), sp.Matrix(rates.relations_dt)
    chain = rate_symbols_chain(system)
    velocity = sp.Matrix([S.rate(n) for n in names])
    c = (A * velocity + a0).applyfunc(S.time_differentiator(chain))
    c = c.xreplace({S.rate(n): rates.rate(n) for n in dependent})
    # A nonlinear constraint's row (∂g/∂ṙ) holds rates: the dependent ones are put as functions of u.
    Ad = A.extract(list(range(A.rows)), [names.index(d) for d in dependent]).xreplace(
        {S.rate(n): rates.rate(n) for n in dependent})
    solution = solve_linear(Ad, -c)
    gamma.update({n: solution[i] for i, n in enumerate(dependent)})
    return gamma


@dataclass(frozen=True)
class MotionContext:
    """What every body's motion needs of the system, made once for all bodies.

    Made per body, these lists and maps cost n² for n bodies (each has an
    entry per coordinate or rate), the steepest part of a wide derivation.
    """

    coordinates: tuple[str, ...]
    coordinate_values: tuple[sp.Symbol, ...]
    coordinate_rates: tuple[sp.Symbol, ...]
    coordinate_gamma: tuple[sp.Expr, ...]
    gamma: dict[str, sp.Expr]
    rate_symbols: tuple[sp.Symbol, ...]  # dot(r) for every name of ``rates``, in order
    differentiate: object  # d/dt over the rates as symbols (rate_symbols_chain), memo shared by bodies
    dependent: dict[sp.Symbol, sp.Expr]  # dot(r) → β u + β₀ for the dependent rates


def motion_context(system: System, rates: Rates) -> MotionContext:
    coords = tuple(c.name for c in system.coordinates)
    gamma = dependent_acceleration_rest(system, rates)
    return MotionContext(
        coords, tuple(S.value(c) for c in coords), tuple(S.rate(c) for c in coords),
        tuple(gamma[c] for c in coords), gamma, tuple(S.rate(n) for n in rates.names),
        S.time_differentiator(rate_symbols_chain(system)),
        {S.rate(n): rates.rate(n) for n in rates.names if n not in rates.independent})


def point_motion(position, system: System, rates: Rates, context: MotionContext | None = None, J=None) -> Motion:
    """v = J β u + (J β₀ + ∂r/∂t); a = J β u̇ + (J γ + J̇ q̇ + ...) (eqs. 14.6, 14.14).

    ``J`` is ∂r/∂q when the caller has it (see :func:`body_motions`).
    """
    context = context or motion_context(system, rates)
    # Lists, not SymPy matrices, in between: at a few entries per body the
    # matrices' construction costs more than the arithmetic.
    rows = J if J is not None else jacobian_rows(position, context.coordinate_values)
    b, b0 = rates.row_lists(context.coordinates)
    moving = S.time_differentiator(function_chain(system))
    explicit = [moving(e) if _moves(e, system) else sp.S.Zero for e in position]
    velocity_symbols = [_dot(row, context.coordinate_rates) + e for row, e in zip(rows, explicit)]
    rest = [_dot(row, context.coordinate_gamma) + d
            for row, d in zip(rows, _rest_of_derivative(velocity_symbols, context))]
    velocity0 = [v + e for (v,), e in zip(product_rows(rows, b0, 1), explicit)]
    return _motion(product_rows(rows, b, rates.k), velocity0, rest)


def motion_velocity(motion: Motion, speeds: Sequence[sp.Symbol]) -> list[sp.Expr]:
    """partials · u + velocity0, from the nonzero partials only (a body of a wide system moves few speeds)."""
    terms: list[list[sp.Expr]] = [[] for _ in range(motion.partials.rows)]
    for (i, j), p in sorted(motion.partials.todok().items()):
        terms[i].append(p * speeds[j])
    return [sp.Add(*t, v0) for t, v0 in zip(terms, motion.velocity0)]


def _motion(partials: list[list[sp.Expr]], velocity0: list[sp.Expr], rest: list[sp.Expr]) -> Motion:
    # Sparse partials: a body of a wide system moves few of the k speeds, and a
    # dense matrix per body would cost k entries each.
    n, k = len(partials), len(partials[0]) if partials else 0
    entries = {(i, j): e for i, row in enumerate(partials) for j, e in enumerate(row) if _nonzero(e)}
    # SymPy's ImmutableSparseMatrix sorts its entries into a canonical Dict,
    # walking every tree (3 s of the bicycle's 4); the mutable one does not,
    # and nothing mutates a Motion's partials.
    return Motion(sp.SparseMatrix(n, k, entries), sp.ImmutableMatrix(n, 1, velocity0),
                  sp.ImmutableMatrix(n, 1, rest))


def _moves(expr: sp.Expr, system: System) -> bool:
    """Whether ``expr`` depends on time explicitly (through t or a prescribed function)."""
    return bool(system.free_functions) or S.T in expr.free_symbols


def _nonzero(e) -> bool:
    # The identity test first: S.Zero is a singleton, and SymPy's == costs far more.
    return e is not _ZERO and e != 0


def _dot(row: Sequence[sp.Expr], column: Sequence[sp.Expr]) -> sp.Expr:
    """Σ row_r column_r over the nonzero pairs."""
    return sp.Add(*[a * c for a, c in zip(row, column) if _nonzero(a) and _nonzero(c)])


def rotation_motion(rotation, system: System, rates: Rates, context: MotionContext | None = None) -> Motion:
    """ω = W β u + (W β₀ + W₀) from the rotation forms; α = W β u̇ + (W γ + Ẇ ṙ + Ẇ₀)."""
    context = context or motion_context(system, rates)
    names = rates.names
    W = [[c.get(n, _ZERO) for n in names] for c in (dict(form.coefficients) for form in rotation)]
    W0 = [form.dt for form in rotation]
    omega_symbols = [_dot(row, context.rate_symbols) + w0 for row, w0 in zip(W, W0)]
    gamma = [context.gamma[n] for n in names]
    rest = [_dot(row, gamma) + d for row, d in zip(W, _rest_of_derivative(omega_symbols, context))]
    b, b0 = rates.row_lists(names)
    velocity0 = [v + w0 for (v,), w0 in zip(product_rows(W, b0, 1), W0)]
    return _motion(product_rows(W, b, rates.k), velocity0, rest)


def product(A: sp.Matrix, B: sp.Matrix) -> sp.Matrix:
    """A B that skips zero factors and takes a unit entry of B as a plain selection.

    β is mostly a selection: an independent coordinate's row of β is a unit
    row (eq. 14.7), so J β mostly copies columns of J; forming every J_ir β_rs
    product and sum, as the general matrix product does, costs far more.
    """
    if A.cols != B.rows:
        raise ValueError(f"cannot multiply {A.rows}x{A.cols} by {B.rows}x{B.cols}")
    # Plain lists: indexing a SymPy matrix entry by entry costs more than the products.
    entries = [e for row in product_rows(A.tolist(), B.tolist(), B.cols) for e in row]
    return sp.Matrix(A.rows, B.cols, entries)


def product_rows(rows: Sequence[Sequence[sp.Expr]], b: Sequence[Sequence[sp.Expr]],
                 columns: int) -> list[list[sp.Expr]]:
    """:func:`product` on lists of rows; B has ``columns`` columns (its rows may be none).

    Sparse on both sides: a particle's row of the Jacobian has one nonzero
    entry and each row of β a few, so the work is the nonzero products,
    not rows × columns × the length of B (cubic in the width of a system of
    n uncoupled bodies, where every body's product scanned all of β).
    """
    out = []
    sparse: dict[int, list[tuple[int, sp.Expr]]] = {}  # per call: a cache across derivations would
    for row in rows:                                   # compare equal huge expressions node by node
        terms: dict[int, list[sp.Expr]] = {}
        for r, a in enumerate(row):
            if a is _ZERO or a == 0:
                continue
            if r not in sparse:
                sparse[r] = [(j, v) for j, v in enumerate(b[r]) if v is not _ZERO and v != 0]
            for j, v in sparse[r]:
                terms.setdefault(j, []).append(a if v is sp.S.One else a * v)
        out.append([(t[0] if len(t) == 1 else sp.Add(*t)) if (t := terms.get(j)) else _ZERO
                    for j in range(columns)])
    return out


def _rest_of_derivative(vector, context: MotionContext) -> list[sp.Expr]:
    """d/dt of expressions linear in the rates, without their r̈ terms, the rates then put as β u + β₀.

    The context's d/dt is shared between bodies, so that their common terms
    are differentiated once.
    """
    derivative = [context.differentiate(e) for e in vector]
    return [e.xreplace(context.dependent) for e in derivative] if context.dependent else derivative


def body_motions(system: System, rates: Rates) -> tuple[BodyMotion, ...]:
    context = motion_context(system, rates)
    # One Jacobian of all the positions: the bodies of a chain repeat each
    # other's terms, and one memo per coordinate differentiates each term once.
    positions = [e for body in system.bodies for e in body.position]
    J = jacobian_rows(positions, context.coordinate_values)
    out = []
    for i, body in enumerate(system.bodies):
        linear = point_motion(body.position, system, rates, context, J=J[3 * i:3 * i + 3])
        angular = rotation_motion(body.rotation, system, rates, context) if body.is_rigid else None
        out.append(BodyMotion(body, linear, angular))
    return tuple(out)
