"""Generalized forces Q_s from the virtual work (step 3, eq. 14.13).

A virtual displacement has δt = 0 and moves the independent coordinates by
δq_s; every other δq_r follows from eq. (14.9), δq_r = Σ β_rs δq_s, and each
point moves by its partial velocities (eq. 14.8). So a force F at a point
contributes F·V_s, a body torque T contributes T·Ω_s, the ``work`` form
Σ c_r dq_r contributes Σ c_r β_rs, and a potential V contributes
−Σ ∂V/∂q_r β_rs.
"""

from __future__ import annotations

import sympy as sp

from gacli import symbols as S
from gacli.fastdiff import gradient
from gacli.graph import substitute
from gacli.kinematics import BodyMotion, Rates, point_partials, product
from gacli.model import System


def generalized_forces(system: System, rates: Rates, motions: tuple[BodyMotion, ...]) -> sp.ImmutableMatrix:
    """The column (Q_1, ..., Q_k), rates in loads replaced by β u + β₀."""
    Q = sp.zeros(rates.k, 1)
    Q += _from_forces(system, rates)
    Q += _from_torques(system, motions)
    Q += _from_work(system, rates)
    Q += _from_potential(system, rates)
    substitution = {S.rate(n): rates.rate(n) for n in rates.names if n not in rates.independent}
    return sp.ImmutableMatrix(Q.rows, 1, substitute(list(Q), substitution) if substitution else list(Q))


def _from_forces(system: System, rates: Rates) -> sp.Matrix:
    Q = sp.zeros(rates.k, 1)
    for force in system.forces:
        Q += point_partials(force.point, system, rates).T * sp.Matrix(force.vector)
    return Q


def _from_torques(system: System, motions: tuple[BodyMotion, ...]) -> sp.Matrix:
    by_name = {m.body.name: m for m in motions}
    k = motions[0].linear.partials.cols if motions else 0
    Q = sp.zeros(k, 1)
    for torque in system.torques:
        Q += by_name[torque.body].angular.partials.T * sp.Matrix(torque.vector)
    return Q


def _from_work(system: System, rates: Rates) -> sp.Matrix:
    if system.work is None:
        return sp.zeros(rates.k, 1)
    c = sp.Matrix([[system.work.coefficient(n) for n in rates.names]])
    return (c * rates.beta).T


def _from_potential(system: System, rates: Rates) -> sp.Matrix:
    if system.potential == 0:
        return sp.zeros(rates.k, 1)
    coords = [c.name for c in system.coordinates]
    b, _ = rates.rows(coords)
    return -product(gradient(system.potential, [S.value(n) for n in coords]), b).T
