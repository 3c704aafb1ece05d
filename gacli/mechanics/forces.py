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

from gacli.algebra import symbols as S
from gacli.algebra import trig
from gacli.algebra.fastdiff import jacobian_rows
from gacli.algebra.graph import substitute
from gacli.algebra.matrices import product_rows
from gacli.mechanics.axes import spin_back
from gacli.mechanics.motions import BodyMotion
from gacli.mechanics.rates import Rates
from gacli.model import System


def generalized_forces(system: System, rates: Rates, motions: tuple[BodyMotion, ...]) -> sp.ImmutableMatrix:
    """The column (Q_1, ..., Q_k), rates in loads replaced by β u + β₀."""
    # Terms collected per Q_s and summed once: adding matrices load by load
    # re-flattens the sums and builds a SymPy matrix each time.
    terms: list[list[sp.Expr]] = [[] for _ in range(rates.k)]
    for contribution in (*_from_forces(system, rates), *_from_torques(system, motions),
                         _from_work(system, rates), _from_potential(system, rates)):
        for s, Q_s in enumerate(contribution):
            terms[s].append(Q_s)
    Q = [sp.Add(*t) for t in terms]
    substitution = {S.rate(n): e for n, e in rates.dependent()}
    Q = substitute(Q, substitution) if substitution else Q
    # A torque carried through a chain of frames gives T·sin² + T·cos² − T; a format-1
    # file's loads are as its author wrote them (the display still reduces them).
    return sp.ImmutableMatrix(rates.k, 1, [trig.reduce(e) for e in Q] if system.uses_frames else Q)


def _from_forces(system: System, rates: Rates) -> list[list[sp.Expr]]:
    """F·V_s of each force, one list per force."""
    coords = [c.name for c in system.coordinates]
    values, beta = [S.value(c) for c in coords], rates.row_lists(coords)[0]
    # Fᵀ (J β), J β being the point's partial velocities (eq. 14.8), by product_rows,
    # which skips zeros: a force on one particle of many touches one Q_s.
    return [product_rows([list(force.vector)], product_rows(jacobian_rows(force.point, values), beta, rates.k),
                         rates.k)[0]
            for force in system.forces]


def _from_torques(system: System, motions: tuple[BodyMotion, ...]) -> list[list[sp.Expr]]:
    """T·Ω_s of each torque, one list per torque."""
    by_name = {m.body.name: m for m in motions}
    out = []
    for torque in system.torques:
        motion = by_name[torque.body]
        # Along the axes the body's Ω is given in (turned back by a wheel's spin): T·Ω is unchanged.
        vector = spin_back(torque.vector, motion.spin)
        out.append(list(motion.angular.partials.T * sp.Matrix(vector)))
    return out


def _from_work(system: System, rates: Rates) -> list[sp.Expr]:
    if system.work is None:
        return []
    c = sp.Matrix([[system.work.coefficient(n) for n in rates.names]])
    return list(c * rates.beta)


def _from_potential(system: System, rates: Rates) -> list[sp.Expr]:
    if system.potential == 0:
        return []
    coords = [c.name for c in system.coordinates]
    b, _ = rates.row_lists(coords)
    gradient = jacobian_rows([system.potential], [S.value(n) for n in coords])
    return [-Q_s for Q_s in product_rows(gradient, b, rates.k)[0]]
