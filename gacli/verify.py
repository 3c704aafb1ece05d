"""Check a derivation by an independent route, and compute the constraint forces.

The Gibbs-Appell route (:mod:`gacli.equations`) eliminates the dependent
rates first (eq. 14.7) and never sees a constraint force. This module derives
the motion a second way that shares none of that code: the fundamental
equation (eq. 14.10) over ALL n + p rates ṙ (coordinates and
quasi-coordinates), with one Lagrange multiplier per constraint (eq. 14.1)
and per quasi-coordinate definition (eq. 14.2),

.. code:: text

    Σ_bodies [ m a·∂v/∂ṙ_j + (Iα + ω×Iω)·∂ω/∂ṙ_j ] − Q̃_j = Σ_i λ_i A_ij    (j = 1..n+p)
    A r̈ + (d/dt A) ṙ + d/dt a₀ = 0                                         (the relations, differentiated)

where A ṙ + a₀ = 0 holds the constraints, then θ̇ − C q̇ − C₀ = 0 for each
quasi-coordinate with a differential, and Q̃_j is the generalized force on
the unreduced rate j. At random admissible states this linear system is
solved numerically (30 significant digits) for r̈ and λ, and compared with
the derivation: u̇ = M⁻¹F, the kinematic equations (14.20), every row of
ṙ = β u + β₀ (14.7), the displayed G (∂G/∂u̇_s = Q_s, eq. 14.19), and M
symmetric positive definite. See docs/verify.md.

API (all pure; nothing is printed)::

    report = verify(system, derivation, samples=20, tol=1e-9, seed=DEFAULT_SEED, gibbs=True)
    report.passed              # bool
    report.failures            # tuple of one-line messages naming the equation
    format_report(report)      # list of lines for the CLI

    constraint_forces(derivation)       # sympy column λ, one per constraint
    reaction_system(derivation)         # K z = b for z = (r̈, λ): λ of a large system, solved numerically
    redundant_relations(fundamental_equations(system))   # rows that repeat others: λ not unique (min-norm)
    reaction_function(derivation)       # values -> numpy array of λ (prepared once)
    reactions_numeric(derivation, values)

Sign convention of the reactions: λ_i multiplies constraint i written as
Σ_j A_ij dr_j + A_i dt = 0 with A = (left side − right side) of the file's
``lhs = rhs``; the reaction's generalized force on the rate r_j is
Σ_i λ_i A_ij, and it acts with the given loads: (m a − F) projected on
∂v/∂ṙ_j equals it. So λ_i is in the units of force (or torque) that make
λ_i · (Σ_j A_ij δr_j) a virtual work; for the sphere on the turntable
λ = (R_x, R_y), the horizontal force the plane exerts on the sphere,
R_x = M ẍ − F_x and R_y = M ÿ − F_y. A rolling or knife-edge row built
from the geometry is a velocity component of the contact point, so its λ
is the contact force on the body along that direction.

Imports: none of the derivation's modules (kinematics, forces, equations,
gibbs; a test checks it), only symbols, model and helpers (errors, graph,
readable); the derivation is read through the ``Derivation`` it is given.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp

from gacli import symbols as S
from gacli.errors import DerivationError
from gacli.graph import substitute
from gacli.model import Body, Form, System
from gacli.numeric import parameter_values, precise_parameter_values, sample_parameters
from gacli.numeric.compiled import Compiled
from gacli.readable import displayable

DEFAULT_SEED = 1410
DEFAULT_SAMPLES = 20
DEFAULT_TOL = 1e-9

_DPS = 30                 # working precision of the numerical check
_FUNCTION_ORDERS = 6      # derivatives of free functions followed by d/dt
_RANK_TOL = mpmath.mpf("1e-20")
_SCALE_FLOOR = 1e-12      # of the largest entry of the same group, for near-zero entries
_CANCEL_OPS = 3000        # reactions: rational cancellation up to this size (operations, not seconds)
_SIMPLIFY_OPS = 150       # and sympy.simplify up to this size after it


# =============================================================================
# The independent route: the fundamental equation over all rates
# =============================================================================

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


def fundamental_equations(system: System) -> FundamentalEquations:
    """Build the unreduced equations of a system (eqs. 14.1, 14.2, 14.10)."""
    names = system.rate_names
    N = len(names)
    coords = [c.name for c in system.coordinates]
    q = [S.value(c) for c in coords]
    qdot = sp.Matrix([S.rate(c) for c in coords]) if coords else sp.zeros(0, 1)
    accelerations = [S.rate(n, 2) for n in names]
    functions = {S.rate(f.name, o): S.rate(f.name, o + 1)
                 for f in system.free_functions for o in range(_FUNCTION_ORDERS)}
    # Full total derivative: q → q̇, every ṙ → r̈, the free functions, t.
    chain = {S.value(c): S.rate(c) for c in coords}
    chain.update({S.rate(n): S.rate(n, 2) for n in names})
    chain.update(functions)

    def d_dt(m: sp.Matrix) -> sp.Matrix:
        return m.applyfunc(lambda e: S.time_derivative(e, chain))

    def velocity(position) -> sp.Matrix:
        r = sp.Matrix(position)
        J = r.jacobian(q) if q else sp.zeros(3, 0)
        return J * qdot + r.applyfunc(lambda e: S.time_derivative(e, functions))

    def angular_velocity(rotation: tuple[Form, Form, Form]) -> sp.Matrix:
        return sp.Matrix([sum((f.coefficient(n) * S.rate(n) for n in names), f.dt) for f in rotation])

    def along(vector: sp.Matrix, v: sp.Matrix) -> list[sp.Expr]:
        """vector · ∂v/∂ṙ_j for every rate j."""
        return [(vector.T * v.diff(S.rate(n)))[0] for n in names]

    lhs = [sp.S.Zero] * N
    bodies: dict[str, Body] = {b.name: b for b in system.bodies}
    for body in system.bodies:
        v = velocity(body.position)
        for j, term in enumerate(along(body.mass * d_dt(v), v)):
            lhs[j] += term
        if body.is_rigid:
            w = angular_velocity(body.rotation)
            I = sp.Matrix(body.inertia)
            euler = I * d_dt(w) + w.cross(I * w)
            for j, term in enumerate(along(euler, w)):
                lhs[j] += term

    loads = [sp.S.Zero] * N
    for force in system.forces:
        for j, term in enumerate(along(sp.Matrix(force.vector), velocity(force.point))):
            loads[j] += term
    for torque in system.torques:
        w = angular_velocity(bodies[torque.body].rotation)
        for j, term in enumerate(along(sp.Matrix(torque.vector), w)):
            loads[j] += term
    if system.work is not None:
        for j, n in enumerate(names):
            loads[j] += system.work.coefficient(n)
    for j, n in enumerate(names):
        if n in coords and system.potential != 0:
            loads[j] -= sp.diff(system.potential, S.value(n))

    lhs_m = sp.Matrix(lhs)
    zero = {a: 0 for a in accelerations}
    mass = lhs_m.jacobian(accelerations) if N else sp.zeros(0, 0)
    inertial = lhs_m.xreplace(zero)

    rows: list[tuple[str, Form]] = [(f"constraints[{i}]", c.form) for i, c in enumerate(system.constraints)]
    for qc in system.quasi_coordinates:
        if qc.differential is not None:
            C = qc.differential
            coefficients = tuple((n, (1 if n == qc.name else 0) - C.coefficient(n)) for n in names)
            rows.append((f"quasi_coordinates.{qc.name}", Form(coefficients, -C.dt)))
    A = sp.Matrix([[form.coefficient(n) for n in names] for _, form in rows]) if rows else sp.zeros(0, N)
    a0 = sp.Matrix([form.dt for _, form in rows]) if rows else sp.zeros(0, 1)
    relation = A * sp.Matrix([S.rate(n) for n in names]) + a0 if rows else sp.zeros(0, 1)
    relation_rest = d_dt(relation).xreplace(zero) if rows else sp.zeros(0, 1)

    return FundamentalEquations(
        names=tuple(names), relations=tuple(r for r, _ in rows), constraint_count=len(system.constraints),
        mass=sp.ImmutableMatrix(mass), inertial=sp.ImmutableMatrix(inertial),
        loads=sp.ImmutableMatrix(sp.Matrix(loads)), A=sp.ImmutableMatrix(A), a0=sp.ImmutableMatrix(a0),
        relation_rest=sp.ImmutableMatrix(relation_rest),
    )


# =============================================================================
# Numerical evaluation (mpmath, 30 digits): gacli.numeric's Compiled
# =============================================================================

def _mp(x) -> mpmath.mpf:
    return mpmath.mpf(x)


def _column(m, size: int) -> list:
    return [m[i, 0] for i in range(size)] if size else []


def _solve(K: mpmath.matrix, b: mpmath.matrix) -> tuple[mpmath.matrix, list[int]]:
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

    Decided at a random configuration, at 30 digits: a generic rank. Such a
    row changes no acceleration; its multiplier is not determined (the
    reaction is statically indeterminate between it and the rows it repeats).
    """
    A = fundamental.A
    if A.rows == 0:
        return ()
    rng = np.random.default_rng(seed)
    symbols = sorted(A.free_symbols, key=lambda s: s.name)
    with mpmath.workdps(_DPS):
        point = {s: sp.Float(rng.uniform(0.4, 1.6), _DPS) for s in symbols}
        numeric = [[mpmath.mpf(str(sp.N(e.xreplace(point), _DPS))) for e in A.row(i)] for i in range(A.rows)]
        kept: list[list] = []
        redundant = []
        for i, row in enumerate(numeric):
            if _rank(kept + [row]) > len(kept):
                kept.append(row)
            else:
                redundant.append(i)
    return tuple(redundant)


def _rank(rows: list[list]) -> int:
    if not rows:
        return 0
    s = mpmath.svd_r(mpmath.matrix(rows), compute_uv=False)
    biggest = max(abs(x) for x in s)
    return sum(1 for x in s if biggest and abs(x) > _RANK_TOL * biggest)


# =============================================================================
# The report
# =============================================================================

@dataclass(frozen=True)
class Difference:
    """The largest relative difference of one equation over the samples."""

    equation: str
    max_relative: float
    tol: float
    undetermined: bool = False  # the fundamental equation leaves this acceleration free

    @property
    def passed(self) -> bool:
        return not self.undetermined and math.isfinite(self.max_relative) and self.max_relative <= self.tol


@dataclass(frozen=True)
class VerifyReport:
    """What :func:`verify` found. Relative differences are |a − b| / max(|a|, |b|, floor)."""

    system: str
    samples: int
    tol: float
    seed: int
    accelerations: tuple[Difference, ...]  # u̇: Gibbs-Appell M⁻¹F vs the fundamental equation (14.10)
    kinematics: tuple[Difference, ...]     # q̇: kinematic equations (14.20) vs the relations
    rates: tuple[Difference, ...]          # every ṙ: β u + β₀ (14.7) vs the relations
    gibbs: tuple[Difference, ...]          # ∂G/∂u̇_s − Q_s vs (M u̇ − F)_s  (14.19)
    mass_asymmetry: float                  # max over samples of max|M − Mᵀ| / max|M|
    mass_min_eigenvalue: float             # min over samples of λ_min(M) / λ_max(M)
    undetermined: tuple[str, ...]          # rates whose acceleration the fundamental equation leaves free
    notes: tuple[str, ...] = ()
    unphysical: str = ""                   # what was wrong with the parameters of some samples
    physical_min_eigenvalue: float = math.inf  # the minimum over the other samples (inf: none)

    GROUPS = (
        ("accelerations", "accelerations u̇: fundamental equation (14.10) with multipliers vs M u̇ = F (14.19)"),
        ("kinematics", "kinematic equations (14.20) vs the relations (14.1, 14.2)"),
        ("rates", "every rate ṙ = β u + β₀ (14.7) vs the relations (14.1, 14.2)"),
        ("gibbs", "the displayed G: ∂G/∂u̇_s − Q_s vs (M u̇ − F)_s (14.19)"),
    )

    @property
    def mass_symmetric(self) -> bool:
        return math.isfinite(self.mass_asymmetry) and self.mass_asymmetry <= self.tol

    @property
    def mass_positive_definite(self) -> bool:
        """Judged on the samples whose parameters are physical: M of a negative mass is the sample's fault."""
        if self.unphysical:
            value = self.physical_min_eigenvalue
            return value == math.inf or (math.isfinite(value) and value > 1e-24)
        return math.isfinite(self.mass_min_eigenvalue) and self.mass_min_eigenvalue > 1e-24

    @property
    def failures(self) -> tuple[str, ...]:
        out = []
        for key, title in self.GROUPS:
            for d in getattr(self, key):
                if not d.passed and not d.undetermined:
                    # inf: not evaluated at some sample (the notes say why), not a measured difference
                    found = ("could not be evaluated at some samples" if d.max_relative == math.inf
                             else f"relative difference {d.max_relative:.3g} > {self.tol:g}")
                    out.append(f"{d.equation}: {found} ({title})")
        if not self.mass_symmetric:
            out.append(f"M is not symmetric: relative asymmetry {self.mass_asymmetry:.3g}")
        if self.mass_min_eigenvalue == math.inf and not self.unphysical:
            out.append("M could not be evaluated at any sample (see the notes)")
        elif not self.mass_positive_definite:
            out.append(f"M is not positive definite: smallest eigenvalue / largest = {self.mass_min_eigenvalue:.3g}")
        for name in self.undetermined:
            out.append(f"{S.rate_name(name, 2)}: the fundamental equation leaves it undetermined "
                       f"(no body and no relation fixes the motion of {name})")
        return tuple(out)

    @property
    def passed(self) -> bool:
        return not self.failures


def format_report(report: VerifyReport) -> list[str]:
    """The report as lines of text for the command line."""
    lines = [(f"verify {report.system}: {report.samples} random admissible states (seed {report.seed}), "
              f"tolerance {report.tol:g}, largest relative difference per equation")]
    for key, title in report.GROUPS:
        diffs = getattr(report, key)
        if not diffs:
            continue
        lines.append(f"  {title}")
        width = max(len(d.equation) for d in diffs)
        for d in diffs:
            if d.undetermined:
                lines.append(f"    {d.equation:<{width}}  {'-':>9}  undetermined")
            else:
                lines.append(f"    {d.equation:<{width}}  {d.max_relative:9.2e}  {'ok' if d.passed else 'FAILED'}")
    lines.append(f"  M symmetric: relative asymmetry {report.mass_asymmetry:.2e}  "
                 f"{'ok' if report.mass_symmetric else 'FAILED'}")
    shown, which = report.mass_min_eigenvalue, ""
    if report.unphysical:  # the note says why the other samples do not count
        shown, which = report.physical_min_eigenvalue, " (over the physical samples)"
    if shown == math.inf:
        lines.append("  M positive definite: not judged (no sample had physical parameters)")
    else:
        lines.append(f"  M positive definite{which}: smallest eigenvalue / largest {shown:.3g}  "
                     f"{'ok' if report.mass_positive_definite else 'FAILED'}")
    for note in report.notes:
        lines.append(f"  note: {note}")
    if report.passed:
        lines.append("verify: passed")
    else:
        lines.append(f"verify: FAILED ({len(report.failures)})")
        lines.extend(f"  {f}" for f in report.failures)
    return lines


# =============================================================================
# verify
# =============================================================================

def _relative(a, b, floor) -> float:
    diff = abs(a - b)
    if diff == 0:
        return 0.0
    scale = max(abs(a), abs(b), floor)
    if not (mpmath.isfinite(diff) and mpmath.isfinite(scale)) or scale == 0:
        return math.inf
    return float(diff / scale)


def _group_floor(*vectors) -> mpmath.mpf:
    biggest = max((abs(x) for v in vectors for x in v if mpmath.isfinite(x)), default=mpmath.mpf(0))
    return max(biggest * _SCALE_FLOOR, mpmath.mpf("1e-300"))


class _Worst:
    """Running maxima of relative differences, by equation name (in order)."""

    def __init__(self, names):
        self.values = {n: 0.0 for n in names}
        self.undetermined: set[str] = set()

    def add(self, name, a, b, floor):
        value = _relative(a, b, floor)
        if math.isnan(value) or value > self.values[name]:
            self.values[name] = math.inf if math.isnan(value) else value

    def fail_all(self):
        for n in self.values:
            self.values[n] = math.inf

    def result(self, tol) -> tuple[Difference, ...]:
        return tuple(Difference(n, v, tol, n in self.undetermined) for n, v in self.values.items())


def verify(system: System, derivation, *, samples: int = DEFAULT_SAMPLES, tol: float = DEFAULT_TOL,
           seed: int = DEFAULT_SEED, gibbs: bool = True) -> VerifyReport:
    """Check ``derivation`` of ``system`` against the fundamental equation at random states.

    Deterministic for a given seed. Never raises for a wrong derivation: the
    report says what differs (``report.passed``, ``report.failures``).
    ``gibbs=False`` skips the check of the displayed G (building G can cost
    more than the derivation itself for large systems); the report says so.
    """
    fundamental = fundamental_equations(system)
    names = fundamental.names
    N, m = len(names), len(fundamental.relations)
    independent = tuple(derivation.independent)
    notes: list[str] = []
    redundant = redundant_relations(fundamental, seed)
    for i in redundant:
        notes.append(f"{fundamental.relations[i]} repeats the relations before it: no acceleration changes, "
                     "and its multiplier is not determined")
    unknown = [n for n in independent if n not in names]
    if unknown:
        raise ValueError(f"the derivation's independent rates {unknown} are not rates of {system.name}")
    dependent = [n for n in names if n not in independent]
    ind_idx = [names.index(n) for n in independent]
    dep_idx = [names.index(n) for n in dependent]
    coords = [c.name for c in system.coordinates]
    rates = derivation.rates
    k = len(independent)

    relations = Compiled({"A": fundamental.A, "a0": fundamental.a0})
    ours = Compiled({
        "mass": fundamental.mass, "inertial": fundamental.inertial, "loads": fundamental.loads,
        "A": fundamental.A, "rest": fundamental.relation_rest,
    })
    speed_rates = [S.rate(n, 2) for n in independent]
    # ∂G/∂u̇_s of the displayed G (eq. 14.19), at the sample's random u̇
    skipped = "the check of the displayed G was skipped"
    if gibbs and not displayable(derivation):
        gibbs, skipped = False, skipped + " (G is not displayed for a system this large)"
    if gibbs:
        gradient = sp.Matrix([sp.diff(derivation.gibbs, a) for a in speed_rates])
    else:
        gradient = sp.zeros(k, 1)
        notes.append(skipped)
    theirs = Compiled({
        "M": sp.Matrix(derivation.mass_matrix), "F": sp.Matrix(derivation.forcing),
        "Q": sp.Matrix(derivation.generalized_forces),
        "kin": sp.Matrix([e for _, e in derivation.kinematic_equations]) if derivation.kinematic_equations
        else sp.zeros(0, 1),
        "rates": sp.Matrix([rates.rate(n) for n in rates.names]),
        "dG": gradient,
    })
    kin_names = [S.rate_name(n, 1) for n, _ in derivation.kinematic_equations]
    worst_acc = _Worst([S.rate_name(n, 2) for n in independent])
    worst_kin = _Worst(kin_names)
    worst_rates = _Worst([S.rate_name(n, 1) for n in rates.names])
    worst_gibbs = _Worst([f"∂G/∂{S.rate_name(n, 2)}" for n in independent] if gibbs else [])
    asymmetry, min_eig, physical_eig, bad_sample = 0.0, math.inf, math.inf, ""
    undetermined: set[str] = set()
    nonlinear = any(c.rates is not None for c in system.constraints)

    rng = np.random.default_rng(seed)
    function_symbols = [S.rate(f.name, o) for f in system.free_functions for o in range(_FUNCTION_ORDERS + 1)]
    input_symbols = [S.value(i.name) for i in system.inputs]
    with mpmath.workdps(_DPS):
        for sample in range(samples):
            sample_drawn = sample_parameters(system, rng)
            values, unphysical = precise_parameter_values(system, sample_drawn, _DPS + 5), sample_drawn.problem
            bad_sample = bad_sample or unphysical
            values.update({S.value(c): _mp(rng.uniform(0.3, 1.7)) for c in coords})
            values.update({s: _mp(rng.uniform(-1.5, 1.5)) for s in function_symbols + input_symbols})
            values[S.T] = _mp(rng.uniform(0.0, 2.0))
            values.update({S.rate(n): _mp(rng.uniform(-1.5, 1.5)) for n in independent})
            values.update({a: _mp(rng.uniform(-1.5, 1.5)) for a in speed_rates})
            # Dependent rates from the relations A ṙ + a₀ = 0: the state is admissible.
            try:
                # A row nonlinear in the rates (A = ∂g/∂ṙ) is evaluated at the rates found so far: the
                # Pfaffian rows settle in the first pass, the nonlinear ones in the next.
                for _ in range(3 if nonlinear else 1):
                    part = relations({s: values.get(s, 0) for s in relations.symbols})
                    if not dependent:
                        break
                    A, a0 = part["A"], part["a0"]
                    rhs = mpmath.matrix([-a0[i] - sum(A[i, j] * values[S.rate(names[j])] for j in ind_idx)
                                         for i in range(m)])
                    Adep = mpmath.matrix([[A[i, j] for j in dep_idx] for i in range(m)])
                    solved = mpmath.lu_solve(Adep, rhs)
                    values.update({S.rate(n): solved[r] for r, n in enumerate(dependent)})
                extra = [s for s in set(ours.symbols) | set(theirs.symbols) if s not in values]
                for s in sorted(extra, key=lambda s: s.name):
                    values[s] = _mp(rng.uniform(-1.5, 1.5))
                    if sample == 0:
                        notes.append(f"symbol {s.name} has no role in the system; given random values")
                ours_v = ours(values)
                rdd, free = _kkt(ours_v, N, m, force_svd=bool(redundant))
                undetermined.update(names[j] for j in free if j < N)
            except (ZeroDivisionError, ValueError, ArithmeticError) as exc:
                notes.append(f"the fundamental equation could not be solved at some samples ({exc})")
                worst_acc.fail_all()
                continue

            try:
                th = theirs(values)
                if not all(mpmath.isfinite(e) for e in (*th["M"], *th["F"])):
                    # A number in the file overflows (exp(exp(exp(100)))): nothing can be compared.
                    raise ArithmeticError("M or F is infinite or not a number there")
            except (ZeroDivisionError, ArithmeticError) as exc:
                note = f"the derivation could not be evaluated at some samples ({exc})"
                notes.extend([note] if note not in notes else [])
                for w in (worst_acc, worst_kin, worst_rates, worst_gibbs):
                    w.fail_all()
                continue

            # kinematic equations and β rows against the admissible rates
            actual_kin = [values[S.rate(n)] for n, _ in derivation.kinematic_equations]
            got_kin = _column(th["kin"], len(kin_names))
            floor = _group_floor(actual_kin, got_kin)
            for name, a, b in zip(kin_names, got_kin, actual_kin):
                worst_kin.add(name, a, b, floor)
            actual_rates = [values[S.rate(n)] for n in rates.names]
            got_rates = _column(th["rates"], len(rates.names))
            floor = _group_floor(actual_rates, got_rates)
            for n, a, b in zip(rates.names, got_rates, actual_rates):
                worst_rates.add(S.rate_name(n, 1), a, b, floor)

            # M: symmetric, positive definite; u̇ = M⁻¹F against r̈ of the independent names
            M, F = th["M"], th["F"]
            if k:
                biggest = max(abs(M[i, j]) for i in range(k) for j in range(k))
                asym = max(abs(M[i, j] - M[j, i]) for i in range(k) for j in range(k))
                asymmetry = max(asymmetry, float(asym / biggest) if biggest else math.inf)
                try:
                    eig = mpmath.eigsy((M + M.T) / 2, eigvals_only=True)
                    lo, hi = min(eig), max(abs(x) for x in eig)
                    ratio = float(lo / hi) if hi else -math.inf
                except (ZeroDivisionError, ArithmeticError, ValueError):
                    ratio = -math.inf
                min_eig = min(min_eig, ratio)
                physical_eig = physical_eig if unphysical else min(physical_eig, ratio)
            singular: list[int] = []
            try:
                udot = _column(mpmath.lu_solve(M, F), k) if k else []
            except (ZeroDivisionError, ArithmeticError, ValueError):
                solution, singular = _solve(M, F)  # least squares; the M check reports it
                udot = _column(solution, k)
                notes.append("M is singular: u̇ = M⁻¹F compared by least squares where determined")
            independent_rdd = [rdd[j] for j in ind_idx]
            floor = _group_floor(udot, independent_rdd)
            for j, n in enumerate(independent):
                if names.index(n) in free:
                    worst_acc.undetermined.add(S.rate_name(n, 2))
                    continue
                if j in singular:
                    worst_acc.add(S.rate_name(n, 2), mpmath.inf, 0, floor)
                    continue
                worst_acc.add(S.rate_name(n, 2), udot[j], independent_rdd[j], floor)

            # ∂G/∂u̇_s − Q_s against M u̇ − F, at random u̇ (eq. 14.19)
            if k and gibbs:
                ud = mpmath.matrix([values[a] for a in speed_rates])
                from_g = th["dG"] - th["Q"]
                direct = M * ud - F
                a_, b_ = _column(from_g, k), _column(direct, k)
                floor = _group_floor(a_, b_)
                for j, n in enumerate(independent):
                    worst_gibbs.add(f"∂G/∂{S.rate_name(n, 2)}", a_[j], b_[j], floor)

    return VerifyReport(
        system=system.name, samples=samples, tol=tol, seed=seed,
        accelerations=worst_acc.result(tol), kinematics=worst_kin.result(tol),
        rates=worst_rates.result(tol), gibbs=worst_gibbs.result(tol),
        mass_asymmetry=asymmetry, mass_min_eigenvalue=min_eig if k else 1.0,
        undetermined=tuple(n for n in names if n in undetermined),
        notes=tuple(dict.fromkeys(notes + _unphysical_note(bad_sample, min_eig))),
        unphysical=bad_sample, physical_min_eigenvalue=physical_eig if k else 1.0,
    )


def _unphysical_note(problem: str, min_eig: float) -> list[str]:
    if not problem:
        return []
    verdict = ("M is not positive definite there: the sample, not the derivation, is at fault"
               if not (math.isfinite(min_eig) and min_eig > 1e-24) else "M stayed positive definite")
    return [f"no physical parameter values were found for some samples ({problem}); {verdict}"]


def _kkt_entries(mass, A, loads, inertial, rest, N: int, m: int, zero) -> tuple[list[list], list]:
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


def _kkt(v: dict, N: int, m: int, force_svd: bool = False) -> tuple[list, list[int]]:
    """Solve [mass −Aᵀ; A 0] [r̈; λ] = [loads − inertial; −rest]; r̈ then λ."""
    rows, column = _kkt_entries(v["mass"], v["A"], v["loads"], v["inertial"], v["rest"], N, m, mpmath.mpf(0))
    K, b = mpmath.matrix(rows), mpmath.matrix(column)
    if not force_svd:
        try:
            x = mpmath.lu_solve(K, b)
            return [x[i] for i in range(N + m)], []
        except ZeroDivisionError:
            pass  # singular: least squares, and say which unknowns are free
    x, free = _solve(K, b)
    return [x[i] for i in range(N + m)], free


def multipliers_numeric(system: System, values: Mapping[sp.Symbol, object]) -> tuple[list, list]:
    """(r̈, λ) of the fundamental equation at one admissible state (all rates given), 30 digits.

    λ holds one multiplier per relation: the constraints, then the
    quasi-coordinate definitions. For tests and cross-checks.
    """
    fundamental = fundamental_equations(system)
    N, m = len(fundamental.names), len(fundamental.relations)
    compiled = Compiled({
        "mass": fundamental.mass, "inertial": fundamental.inertial, "loads": fundamental.loads,
        "A": fundamental.A, "rest": fundamental.relation_rest,
    })
    with mpmath.workdps(_DPS):
        x, _ = _kkt(compiled({s: _mp(values[s]) for s in compiled.symbols}), N, m,
                    force_svd=bool(redundant_relations(fundamental)))
    return [float(e) for e in x[:N]], [float(e) for e in x[N:]]


# =============================================================================
# Constraint forces
# =============================================================================

def _multipliers_in_state(derivation) -> tuple[sp.Matrix, FundamentalEquations]:
    """All multipliers λ (constraints, then quasi definitions) in q, u, u̇ and the rest.

    The equations of the dependent rates are linear in λ:
    E_dep = A_depᵀ λ, with E = mass r̈ + inertial − loads after every rate is
    put in terms of u (ṙ = β u + β₀) and r̈ = d/dt(β u + β₀).
    """
    system = derivation.system
    fundamental = fundamental_equations(system)
    rates = derivation.rates
    names = fundamental.names
    independent = set(rates.independent)
    dependent = [n for n in names if n not in independent]
    functions = {S.rate(f.name, o): S.rate(f.name, o + 1)
                 for f in system.free_functions for o in range(_FUNCTION_ORDERS)}
    chain = {S.value(c.name): rates.rate(c.name) for c in system.coordinates}
    chain.update(dict(zip(rates.speeds, rates.speed_rates)))
    chain.update(functions)
    accelerations = {S.rate(n, 2): S.time_derivative(rates.rate(n), chain) for n in dependent}
    velocities = {S.rate(n): rates.rate(n) for n in dependent}
    r_dd = sp.Matrix([S.rate(n, 2) for n in names])
    E = fundamental.mass * r_dd + fundamental.inertial - fundamental.loads
    E = E.xreplace(accelerations).xreplace(velocities)
    dep = [names.index(n) for n in dependent]
    E_dep = E.extract(dep, [0])
    A_dep = fundamental.A.extract(list(range(fundamental.A.rows)), dep)
    if not dep:
        return sp.zeros(0, 1), fundamental
    if redundant_relations(fundamental):
        # A_depᵀ λ = E_dep has more unknowns than equations: the minimum-norm λ
        return A_dep * (A_dep.T * A_dep).LUsolve(E_dep), fundamental
    return A_dep.T.LUsolve(E_dep), fundamental


def _tidy(expr: sp.Expr) -> sp.Expr:
    """Cancel, then simplify what has become small (a budget in operations, not seconds)."""
    if sp.count_ops(expr) > _CANCEL_OPS:
        return expr
    expr = sp.cancel(expr)
    return sp.simplify(expr) if sp.count_ops(expr) <= _SIMPLIFY_OPS else expr


def constraint_forces(derivation, *, solved: bool = True, simplify: bool = True) -> sp.ImmutableMatrix:
    """The multipliers λ, one per constraint (in file order), as a sympy column.

    Expressions in the state (q, u), parameters, inputs, functions and t:
    u̇ is replaced by the derivation's M⁻¹F when ``solved`` (a symbolic
    solve: compact for small k, but it grows fast: ~10⁴ operations per entry
    for the differential drive), otherwise left as ddot(...) symbols, which
    stays compact (λ in the state and the accelerations). Sign
    convention: see the module docstring (λ acts with the given loads;
    for the sphere on the turntable λ = (M ẍ − F_x, M ÿ − F_y)).

    When a constraint repeats the others (:func:`redundant_relations`, e.g.
    the lateral rolling conditions of two wheels on one axle) rigid-body
    dynamics does not determine how the reaction is shared among them; λ is
    then the minimum-norm solution (for two equal wheels: an equal share).
    """
    if not displayable(derivation):
        raise DerivationError(
            f"{derivation.system.path}: the constraint forces are not derived in closed form for a system "
            "this large: they need a symbolic solve of equations that are millions of terms as trees "
            "(reaction_system gives the linear system that generated code solves numerically)")
    lam, fundamental = _multipliers_in_state(derivation)
    lam = lam[:fundamental.constraint_count, :]
    if solved and lam.rows:
        udot = sp.Matrix(derivation.mass_matrix).LUsolve(sp.Matrix(derivation.forcing))
        lam = lam.xreplace(dict(zip(derivation.speed_rates, udot)))
    if simplify:
        lam = lam.applyfunc(_tidy)
    return sp.ImmutableMatrix(lam)


@dataclass(frozen=True)
class ReactionSystem:
    """K z = b for z = (r̈, λ) at a state, the form in which generated code finds λ numerically.

    Eq. (14.10) over all N rates with the relations differentiated, as
    :func:`_kkt` solves it:

    .. code:: text

        [ mass  −Aᵀ ] [ r̈ ]   [ loads − inertial ]
        [ A      0  ] [ λ  ] = [ −relation_rest    ]

    with the dependent rates put as β u + β₀, so every entry is in the
    state (q, u), parameters, inputs, functions and t. λ of the
    constraints is z[N], ..., z[N + constraint_count − 1].
    """

    K: sp.ImmutableMatrix
    b: sp.ImmutableMatrix
    rates: int
    constraint_count: int
    redundant: bool  # rows of A repeat others: K is singular and λ is the minimum-norm one


def reaction_system(derivation) -> ReactionSystem:
    """The linear system of :class:`ReactionSystem` for a derivation.

    For systems whose multipliers are too large to solve for symbolically
    (:func:`constraint_forces`): the fundamental equations in all the rates
    share their subexpressions about as much as M and F do (the bicycle's K
    and b have 1,928 distinct ones, M and F 2,114), so generated code can
    evaluate them, and a numeric solve of N + m unknowns costs little.
    """
    fundamental = fundamental_equations(derivation.system)
    names, m = fundamental.names, len(fundamental.relations)
    N = len(names)
    rates = derivation.rates
    velocities = {S.rate(n): rates.rate(n) for n in rates.names if n not in rates.independent}
    K, b = _kkt_entries(fundamental.mass, fundamental.A, fundamental.loads, fundamental.inertial,
                        fundamental.relation_rest, N, m, sp.S.Zero)
    flat = [e for row in K for e in row] + b
    # substitute walks the expressions as graphs: the dependent rates are large DAGs.
    flat = substitute(flat, velocities) if velocities else flat
    size = (N + m) ** 2
    return ReactionSystem(sp.ImmutableMatrix(N + m, N + m, flat[:size]), sp.ImmutableMatrix(N + m, 1, flat[size:]),
                          N, fundamental.constraint_count, bool(redundant_relations(fundamental)))


def reaction_function(derivation) -> Callable[[Mapping], np.ndarray]:
    """A function values → λ (numpy array, one per constraint), prepared once.

    ``values`` maps names or symbols (``"x"``, ``"dot(x)"``, ``"Omega"``,
    ``"dot(Omega)"``, inputs, ``"t"``) to numbers; parameters default to
    their file values. u̇ is solved numerically from M u̇ = F (30 digits).
    """
    system = derivation.system
    lam = constraint_forces(derivation, solved=False, simplify=False)
    compiled = Compiled({"M": sp.Matrix(derivation.mass_matrix), "F": sp.Matrix(derivation.forcing)})
    lam_f = Compiled({"lam": sp.Matrix(lam)})
    defaults, _ = parameter_values(system)  # those without a value (or in one) must be given
    speed_rates = derivation.speed_rates

    def evaluate(values: Mapping) -> np.ndarray:
        if not lam.rows:
            return np.zeros(0)
        with mpmath.workdps(_DPS):
            v = {s: _mp(x) for s, x in defaults.items()}
            for key, val in values.items():
                v[S.T if key == "t" else (key if isinstance(key, sp.Symbol) else S.value(key))] = _mp(float(val))
            MF = compiled(v)
            udot = _column(mpmath.lu_solve(MF["M"], MF["F"]), len(speed_rates)) if speed_rates else []
            v.update(dict(zip(speed_rates, udot)))
            result = lam_f(v)["lam"]
            return np.array([float(result[i, 0]) for i in range(lam.rows)])

    return evaluate


def reactions_numeric(derivation, values: Mapping) -> np.ndarray:
    """λ at one state: ``reaction_function(derivation)(values)`` (compile once for many states)."""
    return reaction_function(derivation)(values)
