"""The Gibbs function G = ½ Σ m a² (eq. 14.17), Koenig's analogue for bodies (eq. 14.21).

For a rigid body with centre-of-mass acceleration a, angular velocity ω and
angular acceleration α (body axes, inertia I about the centre of mass),
G = ½ M a² + ½ α·Iα + α·(ω × Iω) + terms free of accelerations. The
equations of motion do not need G (:mod:`gacli.mechanics.equations` takes ∂G/∂u̇_s
directly); it is built here for display and as an independent check.
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.graph import is_small
from gacli.algebra import trig
from gacli.mechanics.motions import BodyMotion, motion_velocity
from gacli.mechanics.rates import Rates, configuration_chain
from gacli.model import System


def acceleration_chain(system: System, rates: Rates) -> dict[sp.Symbol, sp.Expr]:
    """d/dt of everything, u included: u → u̇."""
    chain = configuration_chain(system, rates)
    chain.update(dict(zip(rates.speeds, rates.speed_rates)))
    return chain


def gibbs_function(system: System, rates: Rates, motions: tuple[BodyMotion, ...], whole: bool = False) -> sp.Expr:
    """G in the u̇ (eq. 14.17 with 14.21); only its acceleration terms unless ``whole``.

    Accelerations are differentiated afresh from the velocities (not taken
    from the split V u̇ + a_rest), so G checks the direct route.
    """
    # One d/dt for all bodies: a differentiator is built from the whole chain,
    # so one per body would cost n² for n bodies.
    d_dt = S.time_differentiator(acceleration_chain(system, rates))
    # Reduced body by body: a·a of a point carried through rotations is full of sin² + cos².
    G = sp.Add(*[trig.reduce(_body_gibbs(motion, rates, d_dt, bool(rates.nonlinear))) for motion in motions])
    if whole:
        return G
    return G - G.xreplace({a: 0 for a in rates.speed_rates})


def _body_gibbs(motion: BodyMotion, rates: Rates, d_dt, nonlinear: bool = False) -> sp.Expr:
    v = sp.Matrix(motion_velocity(motion.linear, rates.speeds))
    if nonlinear:
        # β u + β₀ of a nonlinear rate is f(q, u) written as ∂f/∂u·u + rest (Chetaev's split);
        # put back together it is f again, and its derivative stays as short.
        v = v.applyfunc(lambda e: sp.cancel(e) if is_small(e, 400) else e)
    a = sp.Matrix([trig.reduce(e) for e in _derivative_in_heading(v, motion.heading, d_dt)])
    G = motion.body.mass * (a.T * a)[0] / 2
    if motion.angular is not None:
        I = motion.body.inertia
        w = sp.Matrix(motion_velocity(motion.angular, rates.speeds))
        alpha = sp.Matrix([trig.reduce(e) for e in _derivative_unspun(w, motion.spin, d_dt)])
        G += (alpha.T * I * alpha)[0] / 2 + (alpha.T * w.cross(I * w))[0]
    return G


def _derivative_in_heading(v, heading: sp.Expr, d_dt) -> list[sp.Expr]:
    """d/dt of a vector given along axes turned by ``heading`` about N's z, along the same axes.

    The transport theorem: the axes turn at ω = (d heading/dt) z, so
    a = dv/dt + ω × v, with dv/dt taken component by component.
    """
    derivative = [d_dt(e) for e in v]
    if heading == 0:
        return derivative
    w = d_dt(heading)
    return [derivative[0] - w * v[1], derivative[1] + w * v[0], derivative[2]]


def _derivative_unspun(w, spin, d_dt) -> list[sp.Expr]:
    """α from ω given along axes turned back by a spin φ about axis a: dω/dt − φ̇ a × ω.

    With ω' = R ω_B, α' = R ω̇_B = dω'/dt − Ṙ Rᵀ ω', and Ṙ Rᵀ ω' = φ̇ a × ω'.
    """
    derivative = [d_dt(e) for e in w]
    if spin is None:
        return derivative
    axis, angle = spin
    i = "xyz".index(axis)
    j, k = (i + 1) % 3, (i + 2) % 3
    rate = d_dt(angle)
    derivative[j] += rate * w[k]
    derivative[k] -= rate * w[j]
    return derivative


def gibbs_coefficients(G: sp.Expr, rates: Rates) -> tuple[sp.Matrix, sp.Matrix]:
    """(H, g) with G = ½ u̇ᵀ H u̇ + gᵀ u̇ + (terms free of u̇)."""
    k = len(rates.speed_rates)
    H_entries, g_entries = gibbs_entries(G, rates.speed_rates)
    H, g = sp.zeros(k, k), sp.zeros(k, 1)
    for (i, j), value in H_entries.items():
        H[i, j] = H[j, i] = value
    for i, value in g_entries.items():
        g[i] = value
    return H, g


def gibbs_entries(G: sp.Expr, acc) -> tuple[dict[tuple[int, int], sp.Expr], dict[int, sp.Expr]]:
    """The nonzero entries of :func:`gibbs_coefficients`: H by (i, j) with i <= j, g by i.

    Each term of G is differentiated only by the accelerations it contains:
    differentiating the whole of G by every pair cost time ~k² times the
    size of G (n³ for n uncoupled particles). The sum of the terms'
    derivatives is the derivative of the sum, so the entries are the same.
    """
    index = {a: i for i, a in enumerate(acc)}
    zero = {a: 0 for a in acc}
    h_parts: dict[tuple[int, int], list] = {}
    g_parts: dict[int, list] = {}
    for term in sp.Add.make_args(G):
        present = sorted((index[s] for s in term.free_symbols if s in index))
        for i in present:
            first = sp.diff(term, acc[i])
            g_parts.setdefault(i, []).append(first.xreplace(zero))
            for j in present[present.index(i):]:
                h_parts.setdefault((i, j), []).append(sp.diff(first, acc[j]))
    H = {key: total for key, parts in h_parts.items() if (total := sp.Add(*parts)) != 0}
    g = {i: total for i, parts in g_parts.items() if (total := sp.Add(*parts)) != 0}
    return H, g
