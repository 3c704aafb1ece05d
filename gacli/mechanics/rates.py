"""Step 1 of the chapter's solution procedure: every rate in terms of the independent ones.

The constraints (eq. 14.1) and the quasi-coordinate definitions (eq. 14.2)
are linear in the n + p rates; with k of them chosen as the independent
rates u, the others follow as ṙ = β u + β₀ (eqs. 14.4, 14.7). A constraint
nonlinear in the rates determines one rate as f(q, u, t) (docs/nonlinear.md).
The chains of time derivatives that the later steps differentiate with are
here too.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import sympy as sp

from gacli.loader import nonlinear as NL
from gacli.algebra import symbols as S
from gacli.algebra import trig
from gacli.algebra.angles import relative
from gacli.errors import Diagnostic, SystemFileError
from gacli.algebra.graph import is_small
from gacli.algebra.matrices import nonzero, rank, solve_linear
from gacli.model import Form, System
from gacli.numeric.spheres import on_spheres
from gacli.numeric.samples import SEED, random_point


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
        return sp.Add(*[b * u for b, u in zip(self._beta_rows[i], self.speeds) if nonzero(b)], self._beta0_column[i])

    def dependent(self) -> tuple[tuple[str, sp.Expr], ...]:
        """(name, β u + β₀) of each rate that is not a speed (eq. 14.7), in declaration order."""
        return tuple((n, self.rate(n)) for n in self.names if n not in self.independent)

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


def relation_rows(system: System) -> tuple[list[tuple[str, object, Form]], list[str]]:
    """The rows A ṙ + a₀ = 0: constraints (14.1) then quasi definitions (14.2).

    A derived row (rolling contact) that depends on the rows the file states (its constraints and
    quasi-coordinates) and the derived rows before it is left out: it says again what they say (a
    ball in a quaternion frame: its row along the normal is the unit norm's, on the unit sphere).
    """
    names = list(system.rate_names)
    stated = [c.form for c in system.constraints if not c.derived]
    stated += [q.definition for q in system.quasi_coordinates if q.definition is not None]
    derived = [c.form for c in system.constraints if c.derived]
    # One point for every row: rows evaluated apart draw their symbols' values apart.
    numeric = (_numeric(sp.Matrix([[f.coefficient(n) for n in names] for f in (*stated, *derived)]), system)
               if derived else np.zeros((0, len(names))))
    kept, later = numeric[:len(stated)], iter(numeric[len(stated):])
    rows = []
    for i, c in enumerate(system.constraints):
        if c.derived:
            row = next(later)[None, :]
            if rank(np.vstack([kept, row])) == rank(kept):
                continue
            kept = np.vstack([kept, row])
        rows.append((f"constraints[{i}]", c.location, c.form))
    for q in system.quasi_coordinates:
        if q.definition is not None:
            rows.append((f"quasi_coordinates.{q.name}", q.location, q.definition))
    return rows, names


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
        point = on_spheres(random_point(A.free_symbols, SEED + attempt), system)
        try:
            values = np.array(A.xreplace(point).evalf(20).tolist(), dtype=complex)
        except (TypeError, ValueError, ArithmeticError):
            continue
        if np.all(np.isfinite(values)):
            return values
    raise _error(system, system.location, "",
                 "the coefficients of the constraints and quasi-coordinates cannot be evaluated "
                 "to finite numbers at generic points")


def _check_rank(system: System, rows, numeric: np.ndarray) -> None:
    """The matrix [B; C] must have full rank (the condition below eq. 14.3)."""
    if rank(numeric) == numeric.shape[0]:
        return
    kept: list[int] = []
    diagnostics = []
    for i, (where, location, _) in enumerate(rows):
        if rank(numeric[kept + [i]]) > len(kept):
            kept.append(i)
            continue
        if not np.any(numeric[i]):  # 1 = 0, or a relation in the parameters alone: no rate in its row
            diagnostics.append(Diagnostic(location, "this relation constrains no coordinate or rate: every "
                                          "coefficient of its differential is zero", where,
                                          "a relation must depend on the coordinates; 1 = 0 is never true"))
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
    if rank(numeric[:, dependent]) < len(dependent):
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
        if rank(numeric[:, basis + [j]]) > len(basis):
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


def _tidy(expr: sp.Expr) -> sp.Expr:
    """Cancel rational clutter that elimination leaves, while it is cheap.

    ``cancel`` knows no trigonometry: a determinant too large to reduce
    whole (a four-wheeled robot's) can come out of it as a factor
    sin² θ + cos² θ of the denominator, which every later product would
    carry. Numerator and denominator are reduced after it, and cancelled
    again when that changed them.
    """
    if not is_small(expr, 400):
        return expr
    cancelled = sp.cancel(expr)
    numerator, denominator = sp.fraction(cancelled)
    below = trig.reduce(denominator)
    # A trailer's rate, a function of θ − θ_T alone, is written so (gacli.algebra.angles).
    reduced = relative(trig.reduce(numerator), beside=below), below
    if reduced == (numerator, denominator):
        return cancelled
    return sp.cancel(reduced[0] / reduced[1])


def _error(system: System, location, where: str, message: str, hint: str = "") -> SystemFileError:
    return SystemFileError([Diagnostic(location, message, where, hint)])


def function_chain(system: System) -> dict[sp.Symbol, sp.Symbol]:
    """d/dt of the free functions of time: Omega → dot(Omega) → ddot(Omega) → ..."""
    return S.function_chain(f.name for f in system.free_functions)


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

