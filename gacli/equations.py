"""The Gibbs-Appell equations ∂G/∂u̇_s = Q_s (eq. 14.19) and the kinematic equations (14.20).

∂G/∂u̇_s is formed directly: for each body,
Σ M a·∂a/∂u̇_s + (Iα + ω × Iω)·∂α/∂u̇_s, and ∂a/∂u̇_s is the partial
velocity V_s. With a = V u̇ + a_rest and α = Ω u̇ + α_rest this gives

.. code:: text

    M(q, t) u̇ = F(q, u, t)
    M = Σ m VᵀV + Σ ΩᵀIΩ                                    (k × k, symmetric)
    F = Q − Σ m Vᵀa_rest − Σ Ωᵀ(I α_rest + ω × Iω)          (k × 1)
    q̇ = β u + β₀   for the coordinates                     (eq. 14.20)

so G is never expanded to find the equations.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from gacli import symbols as S
from gacli.errors import DerivationError
from gacli.forces import generalized_forces
from gacli.gibbs import gibbs_function
from gacli.kinematics import BodyMotion, Rates, body_motions, solve_rates
from gacli.model import System


@dataclass(frozen=True)
class Derivation:
    """Everything derived from a system; SymPy expressions in plain symbols.

    Symbols: a coordinate ``x`` is ``Symbol('x')``, its rate ``Symbol('dot(x)')``
    and its acceleration ``Symbol('ddot(x)')``; ``speeds`` are the independent
    rates u and ``speed_rates`` their derivatives u̇.
    """

    system: System
    rates: Rates
    motions: tuple[BodyMotion, ...]
    mass_matrix: sp.ImmutableMatrix
    forcing: sp.ImmutableMatrix
    generalized_forces: sp.ImmutableMatrix
    kinematic_equations: tuple[tuple[str, sp.Expr], ...]

    @functools.cached_property
    def gibbs(self) -> sp.Expr:
        """G with its acceleration-free terms dropped (eqs. 14.17, 14.21); built on first use."""
        return gibbs_function(self.system, self.rates, self.motions)

    @property
    def k(self) -> int:
        return self.rates.k

    @property
    def independent(self) -> tuple[str, ...]:
        return self.rates.independent

    @property
    def beta(self) -> sp.ImmutableMatrix:
        return self.rates.beta

    @property
    def beta0(self) -> sp.ImmutableMatrix:
        return self.rates.beta0

    @property
    def speeds(self) -> tuple[sp.Symbol, ...]:
        return self.rates.speeds

    @property
    def speed_rates(self) -> tuple[sp.Symbol, ...]:
        return self.rates.speed_rates

    @property
    def coordinates(self) -> tuple[sp.Symbol, ...]:
        return tuple(S.value(c.name) for c in self.system.coordinates)

    @property
    def state(self) -> tuple[sp.Symbol, ...]:
        """Coordinates in declaration order, then u in the order of ``independent``."""
        return self.coordinates + self.speeds

    @property
    def equations(self) -> tuple[sp.Eq, ...]:
        """∂G/∂u̇_s = Q_s written as M u̇ + (Q − F) = Q (eq. 14.19)."""
        lhs = self.mass_matrix * sp.Matrix(self.speed_rates) + (self.generalized_forces - self.forcing)
        return tuple(sp.Eq(lhs[s], self.generalized_forces[s], evaluate=False) for s in range(self.k))

    @property
    def mass_matrix_full(self) -> sp.ImmutableMatrix:
        """Block diagonal [I_n, M] for the state (q, u)."""
        n = len(self.system.coordinates)
        return sp.ImmutableMatrix(sp.diag(sp.eye(n), self.mass_matrix))

    @property
    def forcing_full(self) -> sp.ImmutableMatrix:
        """[q̇; F] so that mass_matrix_full · d(state)/dt = forcing_full."""
        qdot = sp.Matrix([e for _, e in self.kinematic_equations])
        return sp.ImmutableMatrix(qdot.col_join(sp.Matrix(self.forcing)))


def derive(system: System, *, progress: Callable[[str], None] | None = None) -> Derivation:
    """Derive the Gibbs-Appell equations of a loaded system (section 14.3).

    >>> import gacli
    >>> d = gacli.derive(gacli.loads('''
    ... gacli: 1
    ... name: falling
    ... parameters: [m, g]
    ... coordinates: [z]
    ... bodies: {ball: {mass: m, position: [0, 0, z]}}
    ... potential: m*g*z
    ... '''))
    >>> d.mass_matrix, d.forcing
    (Matrix([[m]]), Matrix([[-g*m]]))
    """
    current = ["start"]

    def step(name: str) -> None:
        current[0] = name
        if progress is not None:
            progress(name)

    try:
        return _derive(system, step)
    except (OverflowError, RecursionError) as exc:
        # Extreme numbers (cosh(cosh(1e300))) overflow inside SymPy's evaluation.
        raise DerivationError(f"{system.path}: the derivation failed at '{current[0]}': "
                              f"a number is too large to evaluate ({type(exc).__name__})") from None


def _derive(system: System, step: Callable[[str], None]) -> Derivation:
    step("rates in terms of the independent rates (14.7)")
    rates = solve_rates(system)
    step("velocities and accelerations (14.14)")
    motions = body_motions(system, rates)
    step("generalized forces (14.13)")
    Q = generalized_forces(system, rates, motions)
    step("Gibbs-Appell equations (14.19)")
    M, inertial = _mass_and_inertial_terms(motions, rates)
    kinematic = tuple((c.name, rates.rate(c.name)) for c in system.coordinates)
    return Derivation(
        system=system, rates=rates, motions=motions,
        mass_matrix=sp.ImmutableMatrix(M), forcing=sp.ImmutableMatrix(Q - inertial),
        generalized_forces=Q, kinematic_equations=kinematic,
    )


def _mass_and_inertial_terms(motions: tuple[BodyMotion, ...], rates: Rates) -> tuple[sp.Matrix, sp.Matrix]:
    """M and the u̇-free part of ∂G/∂u̇ (eq. 14.19 without expanding G)."""
    M = sp.zeros(rates.k, rates.k)
    rest = sp.zeros(rates.k, 1)
    u = sp.Matrix(rates.speeds)
    for motion in motions:
        V, m = motion.linear.partials, motion.body.mass
        M += m * (V.T * V)
        rest += m * (V.T * motion.linear.acceleration_rest)
        if motion.angular is not None:
            W, I = motion.angular.partials, motion.body.inertia
            w = W * u + motion.angular.velocity0
            M += W.T * I * W
            rest += W.T * (I * motion.angular.acceleration_rest + w.cross(I * w))
    return M, rest
