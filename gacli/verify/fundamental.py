"""The fundamental equation (eq. 14.10) over all n + p rates, with one multiplier per relation.

Shared by the independent check (:mod:`gacli.verify`) and the constraint
reactions (:mod:`gacli.reactions`). Imports none of the derivation's modules
(kinematics, forces, equations, gibbs; a test checks it): the motion is
built again here from the system's records alone.
"""

from __future__ import annotations

from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp

from gacli.algebra import fastdiff
from gacli.algebra import symbols as S
from gacli.algebra.canonical import mul
from gacli.model import Form, System
from gacli.numeric.compiled import Compiled
from gacli.numeric.spheres import scaled_onto, spheres

DEFAULT_SEED = 1410
DPS = 30                  # working precision of the numerical check
FUNCTION_ORDERS = 6       # derivatives of free functions followed by d/dt
_RANK_TOL = mpmath.mpf("1e-20")


@dataclass(frozen=True)
class FundamentalEquations:
    """Eq. (14.10) over all n + p rates, with one multiplier per relation.

    .. code:: text

        mass · r̈ + inertial − loads = Aᵀ λ
        A r̈ + relation_rest = 0          (the derivative of A ṙ + a₀ = 0)

    ``names`` are the rates (coordinates, then quasi-coordinates); the
    relations are the constraints (``constraint_count`` of them) then the
    quasi-coordinate definitions. Expressions are in the plain symbols
    x, dot(x), ddot(x) of every rate, with no rate eliminated.
    """

    names: tuple[str, ...]
    relations: tuple[str, ...]
    constraint_count: int
    mass: sp.ImmutableMatrix
    inertial: sp.ImmutableMatrix
    loads: sp.ImmutableMatrix
    A: sp.ImmutableMatrix
    a0: sp.ImmutableMatrix
    relation_rest: sp.ImmutableMatrix
    # The spheres the file keeps coordinates on (Euler parameters, gacli.numeric.spheres): rows are
    # ranked there, where the motion is.
    spheres: tuple = ()


def function_rates(system: System) -> dict[sp.Symbol, sp.Symbol]:
    """Each free function's rate of order o to the next one: d/dt of the free functions."""
    return S.function_chain((f.name for f in system.free_functions), FUNCTION_ORDERS)


class _Motion:
    """Each velocity as partials and rest, v = P ṙ + v₀, with no rate eliminated.

    The mass and inertial terms are formed from P and from d/dt of v at
    r̈ = 0, never by differentiating Σ m a·∂v/∂ṙ with respect to r̈: that
    expression is a product of every body's chain of rotations, and its
    Jacobian cost minutes for ten frames with origins. The derivatives are
    memoised walks (:mod:`gacli.algebra.fastdiff`), shared by all bodies,
    so a chain's common subexpressions are differentiated once.
    """

    def __init__(self, system: System) -> None:
        self.names = system.rate_names
        coords = {c.name for c in system.coordinates}
        # The partials ∂r/∂ṙ_j: a position moves with its coordinates only.
        self.q = [S.value(n) if n in coords else None for n in self.names]
        self.functions = function_rates(system)
        # d/dt at r̈ = 0: q → q̇, the free functions, t; the rates are held.
        chain = {S.value(c): S.rate(c) for c in coords}
        chain.update(self.functions)
        self.d_dt_rest = S.time_differentiator(chain)
        self.d_dt_functions = S.time_differentiator(self.functions)

    def partials(self, position) -> sp.Matrix:
        """∂r/∂ṙ_j = ∂r/∂q_j for the coordinates, zero for the quasi-coordinates (3 × N)."""
        symbols = [s for s in self.q if s is not None]
        rows = fastdiff.jacobian_rows(position, symbols) if symbols else [[] for _ in range(3)]
        out = sp.zeros(3, len(self.names))
        for j, col in enumerate(i for i, s in enumerate(self.q) if s is not None):
            for i in range(3):
                out[i, col] = rows[i][j]
        return out

    def velocity(self, position, P: sp.Matrix) -> sp.Matrix:
        rates = sp.Matrix([S.rate(n) for n in self.names]) if self.names else sp.zeros(0, 1)
        return _transposed_times(P.T, rates) + sp.Matrix(position).applyfunc(self.d_dt_functions)

    def rotation_partials(self, rotation: tuple[Form, Form, Form]) -> tuple[sp.Matrix, sp.Matrix]:
        """W and ω = W ṙ + ω₀ of a rotation's forms."""
        W = sp.Matrix(3, len(self.names), lambda i, j: rotation[i].coefficient(self.names[j]))
        rates = sp.Matrix([S.rate(n) for n in self.names]) if self.names else sp.zeros(0, 1)
        return W, _transposed_times(W.T, rates) + sp.Matrix([f.dt for f in rotation])

    def rest(self, m: sp.Matrix) -> sp.Matrix:
        """d/dt of ``m`` at r̈ = 0."""
        return m.applyfunc(self.d_dt_rest)


def _transposed_times(U: sp.Matrix, v: sp.Matrix, scale=sp.S.One) -> sp.Matrix:
    """scale · Uᵀ v, each entry one sum of canonical products.

    SymPy's matrix product asks the assumptions of every product of two
    large sums (is it zero?), which cost more than all the derivatives of a
    chain of ten frames.
    """
    out = sp.zeros(U.cols, v.cols)
    for i in range(U.cols):
        for j in range(v.cols):
            out[i, j] = sp.Add(*(mul(scale, U[k, i], v[k, j]) for k in range(U.rows) if U[k, i] != 0 and v[k, j] != 0))
    return out


def _inertia_terms(system: System, motion: _Motion) -> tuple[sp.Matrix, sp.Matrix]:
    """Σ_bodies m PᵀP + WᵀIW and Σ m Pᵀ a₀ + Wᵀ(I α₀ + ω×Iω): the mass and the rest at r̈ = 0."""
    N = len(motion.names)
    mass, inertial = sp.zeros(N, N), sp.zeros(N, 1)
    for body in system.bodies:
        P = motion.partials(body.position)
        mass += _transposed_times(P, P, body.mass)
        inertial += _transposed_times(P, motion.rest(motion.velocity(body.position, P)), body.mass)
        if body.is_rigid:
            W, w = motion.rotation_partials(body.rotation)
            I = sp.Matrix(body.inertia)
            mass += _transposed_times(W, _transposed_times(I.T, W))
            inertial += _transposed_times(W, _transposed_times(I.T, motion.rest(w)) + w.cross(_transposed_times(I.T, w)))
    return mass, inertial


def _load_terms(system: System, motion: _Motion) -> sp.Matrix:
    """Q̃_j, the generalized force of the loads on every unreduced rate j (eq. 14.13)."""
    names = motion.names
    loads = sp.zeros(len(names), 1)
    bodies = {b.name: b for b in system.bodies}
    for force in system.forces:
        loads += _transposed_times(motion.partials(force.point), sp.Matrix(force.vector))
    for torque in system.torques:
        W, _ = motion.rotation_partials(bodies[torque.body].rotation)
        loads += _transposed_times(W, sp.Matrix(torque.vector))
    if system.work is not None:
        loads += sp.Matrix([system.work.coefficient(n) for n in names])
    if system.potential != 0:
        gradient = motion.partials([system.potential, 0, 0])
        loads -= gradient[0, :].T
    return loads


def _relations(system: System, names) -> list[tuple[str, Form]]:
    """The constraints (eq. 14.1), then θ̇ − C q̇ − C₀ = 0 for each quasi-coordinate's differential (14.2)."""
    rows: list[tuple[str, Form]] = [(f"constraints[{i}]", c.form) for i, c in enumerate(system.constraints)]
    for qc in system.quasi_coordinates:
        if qc.differential is not None:
            C = qc.differential
            coefficients = tuple((n, (1 if n == qc.name else 0) - C.coefficient(n)) for n in names)
            rows.append((f"quasi_coordinates.{qc.name}", Form(coefficients, -C.dt)))
    return rows


def fundamental_equations(system: System) -> FundamentalEquations:
    """Build the unreduced equations of a system (eqs. 14.1, 14.2, 14.10)."""
    motion = _Motion(system)
    names = motion.names
    N = len(names)
    mass, inertial = _inertia_terms(system, motion)
    rows = _relations(system, names)
    A = sp.Matrix([[form.coefficient(n) for n in names] for _, form in rows]) if rows else sp.zeros(0, N)
    a0 = sp.Matrix([form.dt for _, form in rows]) if rows else sp.zeros(0, 1)
    relation = A * sp.Matrix([S.rate(n) for n in names]) + a0 if rows else sp.zeros(0, 1)
    # d/dt at r̈ = 0 is the rest; a row nonlinear in the rates has A = ∂g/∂ṙ, and holding them is the same.
    relation_rest = motion.rest(relation) if rows else sp.zeros(0, 1)
    return FundamentalEquations(
        names=tuple(names), relations=tuple(r for r, _ in rows), constraint_count=len(system.constraints),
        mass=sp.ImmutableMatrix(mass), inertial=sp.ImmutableMatrix(inertial),
        loads=sp.ImmutableMatrix(_load_terms(system, motion)), A=sp.ImmutableMatrix(A),
        a0=sp.ImmutableMatrix(a0), relation_rest=sp.ImmutableMatrix(relation_rest), spheres=spheres(system),
    )


# -- solving it numerically ---------------------------------------------------------

def solve_least_squares(K: mpmath.matrix, b: mpmath.matrix) -> tuple[mpmath.matrix, list[int]]:
    """x minimizing |Kx − b| (minimum norm), and the unknowns left free by K (its null space)."""
    n = K.rows
    if n == 0:
        return mpmath.matrix(0, 1), []
    U, s, V = mpmath.svd_r(K)
    smax = max(abs(x) for x in s) if n else 0
    x = mpmath.matrix(n, 1)
    free: set[int] = set()
    for i in range(len(s)):
        if smax == 0 or abs(s[i]) <= _RANK_TOL * smax:
            for j in range(n):
                if abs(V[i, j]) > mpmath.mpf("1e-12"):
                    free.add(j)
            continue
        coef = sum(U[r, i] * b[r] for r in range(n)) / s[i]
        for j in range(n):
            x[j] += coef * V[i, j]
    return x, sorted(free)


def redundant_relations(fundamental: FundamentalEquations, seed: int = DEFAULT_SEED) -> tuple[int, ...]:
    """Rows of A that repeat the rows before them (e.g. two wheels on one axle).

    Decided at a random configuration on the file's spheres, at 30 digits: a generic rank. Such a
    row changes no acceleration; its multiplier is not determined (the
    reaction is statically indeterminate between it and the rows it repeats).
    """
    A = fundamental.A
    if A.rows == 0:
        return ()
    rng = np.random.default_rng(seed)
    symbols = sorted(A.free_symbols, key=lambda s: s.name)
    with mpmath.workdps(DPS):
        point = {s: mpmath.mpf(rng.uniform(0.4, 1.6)) for s in symbols}
        point.update({s: mpmath.mpf(v) for s, v in scaled_onto(dict(point), fundamental.spheres, DPS + 5).items()})
        values = Compiled({"A": A})(point)["A"]
        numeric = [[values[i, j] for j in range(A.cols)] for i in range(A.rows)]
        kept: list[list] = []
        redundant = []
        # A quasi-coordinate's definition first: a rolling row that repeats them (a ball's along the
        # normal in a quaternion frame) is the one said to repeat, as derive and check say it.
        count = fundamental.constraint_count
        for i in [*range(count, len(numeric)), *range(count)]:
            row = numeric[i]
            if _rank(kept + [row]) > len(kept):
                kept.append(row)
            else:
                redundant.append(i)
    return tuple(sorted(redundant))


def _rank(rows: list[list]) -> int:
    if not rows:
        return 0
    s = mpmath.svd_r(mpmath.matrix(rows), compute_uv=False)
    biggest = max(abs(x) for x in s)
    return sum(1 for x in s if biggest and abs(x) > _RANK_TOL * biggest)


def kkt_entries(mass, A, loads, inertial, rest, N: int, m: int, zero) -> tuple[list[list], list]:
    """[mass −Aᵀ; A 0] and [loads − inertial; −rest] as rows and a column, of SymPy or mpmath entries."""
    K = [[zero] * (N + m) for _ in range(N + m)]
    b = [zero] * (N + m)
    for i in range(N):
        for j in range(N):
            K[i][j] = mass[i, j]
        for r in range(m):
            K[i][N + r] = -A[r, i]
        b[i] = loads[i, 0] - inertial[i, 0]
    for r in range(m):
        for j in range(N):
            K[N + r][j] = A[r, j]
        b[N + r] = -rest[r, 0]
    return K, b


def kkt(v: dict, N: int, m: int, force_svd: bool = False) -> tuple[list, list[int]]:
    """Solve [mass −Aᵀ; A 0] [r̈; λ] = [loads − inertial; −rest]; r̈ then λ."""
    rows, column = kkt_entries(v["mass"], v["A"], v["loads"], v["inertial"], v["rest"], N, m, mpmath.mpf(0))
    K, b = mpmath.matrix(rows), mpmath.matrix(column)
    if not force_svd:
        try:
            x = mpmath.lu_solve(K, b)
            return [x[i] for i in range(N + m)], []
        except (ZeroDivisionError, TypeError):  # mpmath's LU of a zero column compares None with 0
            pass  # singular: least squares, and say which unknowns are free
    x, free = solve_least_squares(K, b)
    return [x[i] for i in range(N + m)], free


def column(m, size: int) -> list:
    """The first ``size`` entries of an mpmath column (none of an empty one, which is None)."""
    return [m[i, 0] for i in range(size)] if size else []
