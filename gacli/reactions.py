"""The constraint forces: the multipliers λ of the fundamental equation (eq. 14.10).

The Gibbs-Appell route (:mod:`gacli.mechanics.equations`) eliminates the dependent
rates first (eq. 14.7) and never sees a constraint force; the generated
code's ``reactions`` (:mod:`gacli.emit.assembly`) takes it from here, and so
do the text report and :func:`reaction_function` for tests.

API (all pure; nothing is printed)::

    constraint_forces(derivation)       # sympy column λ, one per constraint
    reaction_system(derivation)         # K z = b for z = (r̈, λ): λ of a large system, solved numerically
    redundant_relations(fundamental_equations(system))   # rows that repeat others: λ not unique (min-norm)
    reaction_function(derivation)       # values -> numpy array of λ (prepared once)
    reactions_numeric(derivation, values)
    multipliers_numeric(system, values) # (r̈, λ) at one admissible state, for cross-checks

Sign convention: λ_i multiplies constraint i written as
Σ_j A_ij dr_j + A_i dt = 0 with A = (left side − right side) of the file's
``lhs = rhs``; the reaction's generalized force on the rate r_j is
Σ_i λ_i A_ij, and it acts with the given loads: (m a − F) projected on
∂v/∂ṙ_j equals it. So λ_i is in the units of force (or torque) that make
λ_i · (Σ_j A_ij δr_j) a virtual work; for the sphere on the turntable
λ = (R_x, R_y), the horizontal force the plane exerts on the sphere,
R_x = M ẍ − F_x and R_y = M ÿ − F_y. A rolling or knife-edge row built
from the geometry is a velocity component of the contact point, so its λ
is the contact force on the body along that direction.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.errors import DerivationError
from gacli.algebra.graph import substitute
from gacli.model import System
from gacli.numeric import parameter_values
from gacli.numeric.compiled import Compiled
from gacli.algebra.readable import displayable, solved_tidy
from gacli.verify.fundamental import (
    DPS, FundamentalEquations, column, function_rates, fundamental_equations, kkt, kkt_entries, redundant_relations,
)


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
    functions = function_rates(system)
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
        # Over the graph: λ's entries share their subexpressions, which xreplace rebuilds at every occurrence.
        lam = sp.Matrix(lam.rows, 1, substitute(list(lam), dict(zip(derivation.speed_rates, udot))))
    if simplify:
        lam = lam.applyfunc(solved_tidy)
    return sp.ImmutableMatrix(lam)


@dataclass(frozen=True)
class ReactionSystem:
    """K z = b for z = (r̈, λ) at a state, the form in which generated code finds λ numerically.

    Eq. (14.10) over all N rates with the relations differentiated, as
    :func:`gacli.verify.fundamental.kkt` solves it:

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
    velocities = {S.rate(n): e for n, e in rates.dependent()}
    K, b = kkt_entries(fundamental.mass, fundamental.A, fundamental.loads, fundamental.inertial,
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
        with mpmath.workdps(DPS):
            v = {s: mpmath.mpf(x) for s, x in defaults.items()}
            for key, val in values.items():
                v[S.T if key == "t" else (key if isinstance(key, sp.Symbol) else S.value(key))] = mpmath.mpf(float(val))
            MF = compiled(v)
            udot = column(mpmath.lu_solve(MF["M"], MF["F"]), len(speed_rates)) if speed_rates else []
            v.update(dict(zip(speed_rates, udot)))
            result = lam_f(v)["lam"]
            return np.array([float(result[i, 0]) for i in range(lam.rows)])

    return evaluate


def reactions_numeric(derivation, values: Mapping) -> np.ndarray:
    """λ at one state: ``reaction_function(derivation)(values)`` (compile once for many states)."""
    return reaction_function(derivation)(values)


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
    with mpmath.workdps(DPS):
        x, _ = kkt(compiled({s: mpmath.mpf(values[s]) for s in compiled.symbols}), N, m,
                   force_svd=bool(redundant_relations(fundamental)))
    return [float(e) for e in x[:N]], [float(e) for e in x[N:]]

