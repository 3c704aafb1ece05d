"""Step 2: velocities and accelerations of every body in u and u̇ (eqs. 14.6, 14.14).

Each body's velocity is V u + v₀ and its acceleration V u̇ + a_rest, where V
holds the partial velocities (the α_rs of eq. 14.6) and a_rest is free of
the u̇; the dependent accelerations r̈ = β u̇ + γ come from the differentiated
relations among the rates.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra import trig
from gacli.algebra.fastdiff import jacobian_rows
from gacli.algebra.graph import is_small
from gacli.algebra.matrices import dot, nonzero, product_rows, solve_linear
from gacli.model import Body, System
from gacli.mechanics.rates import Rates, configuration_chain, function_chain, rate_symbols_chain

_ZERO = sp.S.Zero


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
    """A body's motions. ``linear`` is along N's axes turned by ``heading`` about N's z
    (0: N's own axes); ``angular`` along the body's axes, as its rotation forms give it."""

    body: Body
    linear: Motion
    angular: Motion | None
    heading: sp.Expr = sp.S.Zero
    # (axis, angle): ``angular`` is along the body's axes turned back by ``angle``
    # about that body axis, about which the inertia is symmetric (a wheel's spin).
    spin: tuple[str, sp.Expr] | None = None


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
    if not rates.nonlinear and all(is_small(rates.rate(n), _SMALL_RATE) for n in dependent):
        gamma.update(_differentiated_rates(system, rates, dependent))
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


# Solved rates up to this many nodes are differentiated themselves for γ.
_SMALL_RATE = 300


def _differentiated_rates(system: System, rates: Rates, dependent: list[str]) -> dict[str, sp.Expr]:
    """γ = d/dt(β u + β₀) with u held fixed, for rates small enough to differentiate as solved.

    A robot's solved rates are short (ẋ = r(φ̇_L + φ̇_R) cos θ / 2) where the
    constraints they come from are not; solving the differentiated
    constraints again, as for a bicycle, divided by pivots such as cos θ
    that no identity removes afterwards. The two are equal: both are r̈ at u̇ = 0.
    """
    d_dt = S.time_differentiator(configuration_chain(system, rates))
    return {n: trig.reduce(d_dt(rates.rate(n))) for n in dependent}




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
        {S.rate(n): e for n, e in rates.dependent()})


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
    velocity_symbols = [dot(row, context.coordinate_rates) + e for row, e in zip(rows, explicit)]
    rest = [dot(row, context.coordinate_gamma) + d
            for row, d in zip(rows, _rest_of_derivative(velocity_symbols, context))]
    velocity0 = [v + e for (v,), e in zip(product_rows(rows, b0, 1), explicit)]
    return make_motion(product_rows(rows, b, rates.k), velocity0, rest)


def motion_velocity(motion: Motion, speeds: Sequence[sp.Symbol]) -> list[sp.Expr]:
    """partials · u + velocity0 (eq. 14.6)."""
    return _along_partials(motion.partials, speeds, motion.velocity0)


def motion_acceleration(motion: Motion, speed_rates: Sequence[sp.Symbol]) -> list[sp.Expr]:
    """partials · u̇ + acceleration_rest (eq. 14.14)."""
    return _along_partials(motion.partials, speed_rates, motion.acceleration_rest)


def _along_partials(partials, symbols: Sequence[sp.Symbol], rest) -> list[sp.Expr]:
    """partials · symbols + rest, from the nonzero partials only (a body of a wide system moves few speeds)."""
    terms: list[list[sp.Expr]] = [[] for _ in range(partials.rows)]
    for (i, j), p in sorted(partials.todok().items()):
        terms[i].append(p * symbols[j])
    return [sp.Add(*t, r) for t, r in zip(terms, rest)]


def make_motion(partials: list[list[sp.Expr]], velocity0: list[sp.Expr], rest: list[sp.Expr]) -> Motion:
    # Sparse partials: a body of a wide system moves few of the k speeds, and a
    # dense matrix per body would cost k entries each.
    n, k = len(partials), len(partials[0]) if partials else 0
    entries = {(i, j): e for i, row in enumerate(partials) for j, e in enumerate(row) if nonzero(e)}
    # SymPy's ImmutableSparseMatrix sorts its entries into a canonical Dict,
    # walking every tree (3 s of the bicycle's 4); the mutable one does not,
    # and nothing mutates a Motion's partials.
    return Motion(sp.SparseMatrix(n, k, entries), sp.ImmutableMatrix(n, 1, velocity0),
                  sp.ImmutableMatrix(n, 1, rest))


def _moves(expr: sp.Expr, system: System) -> bool:
    """Whether ``expr`` depends on time explicitly (through t or a prescribed function)."""
    return bool(system.free_functions) or S.T in expr.free_symbols


def rotation_motion(rotation, system: System, rates: Rates, context: MotionContext | None = None) -> Motion:
    """ω = W β u + (W β₀ + W₀) from the rotation forms; α = W β u̇ + (W γ + Ẇ ṙ + Ẇ₀)."""
    context = context or motion_context(system, rates)
    names = rates.names
    W = [[c.get(n, _ZERO) for n in names] for c in (dict(form.coefficients) for form in rotation)]
    W0 = [form.dt for form in rotation]
    omega_symbols = [dot(row, context.rate_symbols) + w0 for row, w0 in zip(W, W0)]
    gamma = [context.gamma[n] for n in names]
    rest = [dot(row, gamma) + d for row, d in zip(W, _rest_of_derivative(omega_symbols, context))]
    b, b0 = rates.row_lists(names)
    velocity0 = [v + w0 for (v,), w0 in zip(product_rows(W, b0, 1), W0)]
    return make_motion(product_rows(W, b, rates.k), velocity0, rest)


def _rest_of_derivative(vector, context: MotionContext) -> list[sp.Expr]:
    """d/dt of expressions linear in the rates, without their r̈ terms, the rates then put as β u + β₀.

    The context's d/dt is shared between bodies, so that their common terms
    are differentiated once.
    """
    derivative = [context.differentiate(e) for e in vector]
    return [e.xreplace(context.dependent) for e in derivative] if context.dependent else derivative


def body_motions(system: System, rates: Rates, context: MotionContext | None = None) -> tuple[BodyMotion, ...]:
    context = context or motion_context(system, rates)
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
