"""The energy along the path and whether it must be conserved; rates differentiated from the path."""

from __future__ import annotations

import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.mechanics.equations import Derivation
from gacli.algebra.graph import free_symbols

_FD_FRACTION = 0.01          # finite-difference step, as a fraction of the solver's step


# -- energy and its conservation ----------------------------------------------------

def conservation_problems(derivation: Derivation) -> list[str]:
    """Why E = T + V need not be constant along a motion; empty when it must be.

    E is conserved when nothing external works on the system and nothing
    depends on time: no inputs, no free functions, no ``work`` form and no
    torques; forces only constant ones (given a potential −F·r); and no t in
    the positions, the rotations, the constraints or the potential, with
    every velocity homogeneous in u (no β₀ terms, v = V u and ω = W u).
    """
    system = derivation.system
    out = []
    if system.inputs:
        out.append("inputs " + ", ".join(i.name for i in system.inputs))
    if system.free_functions:
        out.append("free functions " + ", ".join(f.name for f in system.free_functions))
    if system.work is not None:
        out.append("a work form (write conservative forces as a potential)")
    if system.torques:
        out.append("torques")
    if any(_free(e) - _parameter_symbols(system) for force in system.forces for e in force.vector):
        out.append("forces that are not constant")
    if S.T in _free(system.potential):
        out.append("a potential that depends on t")
    if any(S.T in _free(*force.point) for force in system.forces):  # −F·r then depends on t
        out.append("a force at a point that moves with t")
    if any(_timed(c.form) for c in system.constraints if c.rates is None):
        out.append("constraints that depend on t")
    if any(c.form.dt != 0 for c in system.constraints if c.rates is not None):  # a₀ = g − A ṙ ≠ 0
        out.append("a constraint nonlinear in the rates and not homogeneous of degree one in them")
    if moving_support(system):
        out.append(MOVING_SUPPORT)
    return out


MOVING_SUPPORT = "velocities with terms free of the independent rates (a moving support)"


def moving_support(system) -> bool:
    """Whether some velocity has a term free of the independent rates (v = V u + v₀ with v₀ ≠ 0):
    t in a body's position or rotation, or a form with a dt term (a rotation, a quasi-coordinate's
    differential or a constraint, whose β₀ then enters the dependent rates, eq. 14.7).

    Read from the file's declarations, not from the chapter's motions, so that a derivation by the
    program alone (a bicycle's simulate) says the same: for every system of the repository both agree."""
    forms = [c.form for c in system.constraints if c.rates is None]  # nonlinear ones: said of their own
    forms += [q.differential for q in system.quasi_coordinates if q.differential is not None]
    for body in system.bodies:
        if S.T in _free(*body.position):
            return True
        forms += list(body.rotation or ())
    return any(_timed(f) for f in forms)


def _timed(form) -> bool:
    """A form with a dt term or t in a coefficient."""
    return form.dt != 0 or S.T in _free(*(c for _, c in form.coefficients))


def _free(*exprs) -> set[sp.Symbol]:
    return free_symbols([as_expr(e) for e in exprs])


def _parameter_symbols(system) -> set[sp.Symbol]:
    return {S.value(p.name) for p in system.parameters}


def energy_expressions(derivation: Derivation) -> tuple[sp.Expr, sp.Expr]:
    """T = Σ ½ m v·v + ½ ω·Iω with v = V u + v₀, ω = W u + ω₀ from the closed route's motions; and V."""
    if not derivation.closed:  # read off the program or for code alone: no motions, T would read 0
        raise ValueError("energy_expressions needs the closed route's motions (gacli.pipeline's STEPS or CLOSED)")
    # Terms gathered and added once: `total += term` rebuilds the growing sum each time,
    # quadratic in the number of bodies and loads (1,000 loads took over 20 s).
    u = sp.Matrix(derivation.speeds)
    kinetic = []
    for motion in derivation.motions:
        v = motion.linear.partials * u + motion.linear.velocity0
        kinetic.append(motion.body.mass * v.dot(v) / 2)
        if motion.angular is not None:
            w = motion.angular.partials * u + motion.angular.velocity0
            kinetic.append((w.T * motion.body.inertia * w)[0, 0] / 2)
    return sp.Add(*kinetic), potential_energy(derivation.system)


def potential_energy(system) -> sp.Expr:
    """V: the file's potential and −F·r of each force, constant where E is conserved."""
    return sp.Add(system.potential, *(-sp.Matrix(f.vector).dot(sp.Matrix(f.point)) for f in system.forces))


def kinetic_energy(mass_matrix, t: np.ndarray, states: np.ndarray, k: int) -> np.ndarray:
    """T = ½ uᵀ M u at each state, M from generated code's ``mass_matrix(t, x)``.

    Where E is conserved no velocity has a term free of u (:func:`moving_support`), so
    T = ½ Σ m (V u)·(V u) + ½ (W u)·I(W u) is the quadratic form of M = Σ m VᵀV + WᵀIW
    (eq. 14.19): the same whichever route derived M, and for a constraint nonlinear in the
    rates too, which is conservative only when homogeneous of degree one in them."""
    out = np.empty(len(t))
    for i, (ti, x) in enumerate(zip(t, states)):
        u = np.asarray(x[len(x) - k:], dtype=float)
        out[i] = 0.5 * u @ np.asarray(mass_matrix(ti, x), dtype=float) @ u
    return out


# -- rates along the path -------------------------------------------------------------

def path_rates(dense, t: np.ndarray, n: int) -> np.ndarray:
    """d/dt of the first ``n`` states at ``t``, differentiated from the dense solution.

    Each time is differentiated inside the polynomial of its own solver step
    (``dense.interpolants``) by the five-point central difference with a step
    of 1% of that solver step, so no kink between steps enters the result.
    """
    ts = dense.ts
    segment = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, len(dense.interpolants) - 1)
    out = np.empty((len(t), n))
    for j in np.unique(segment):
        mask = segment == j
        tj, h = t[mask], _FD_FRACTION * abs(ts[j + 1] - ts[j])
        f = dense.interpolants[j]
        d = (f(tj - 2 * h) - 8 * f(tj - h) + 8 * f(tj + h) - f(tj + 2 * h)) / (12 * h)
        out[mask] = np.atleast_2d(d)[:n].T
    return out
