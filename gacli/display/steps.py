"""The worked solution: section 14.3's four steps, each with its intermediate results.

This is data (prose and equations as SymPy objects), rendered as text by
:mod:`gacli.display.report` and as LaTeX by :mod:`gacli.emit.latex`. Expressions are
simplified for reading within a budget of operations per step (deterministic,
unlike a clock); a step that has spent it shows the rest as derived. Nothing here feeds the
code emitters.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.mechanics.equations import Derivation
from gacli.mechanics.gibbs import gibbs_entries
from gacli.mechanics.motions import motion_acceleration, motion_velocity
from gacli.algebra.readable import STEP_BUDGET_OPS, Tidy, show


@dataclass(frozen=True)
class Equation:
    lhs: sp.Expr
    rhs: sp.Expr
    label: str = ""


@dataclass(frozen=True)
class Step:
    title: str
    items: tuple[str | Equation, ...]


def variation(name: str) -> sp.Symbol:
    """δq, the virtual displacement of a coordinate or quasi-coordinate (eqs. 14.8, 14.9)."""
    return sp.Symbol(f"δ{name}", real=True)


def worked_solution(d: Derivation, budget: int = STEP_BUDGET_OPS) -> tuple[Step, ...]:
    """Section 14.3's procedure applied to ``d``'s system, step by step."""
    return (
        degrees_of_freedom(d),
        rate_relations(d, Tidy(budget)),
        accelerations_and_gibbs(d, Tidy(budget)),
        virtual_work(d, Tidy(budget)),
        equations_of_motion(d, Tidy(budget)),
    )


def degrees_of_freedom(d: Derivation) -> Step:
    s = d.system
    n, p, ell = len(s.coordinates), len(s.quasi_coordinates), d.rates.constraints_used
    dq = sum(1 for q in s.quasi_coordinates if q.differential is not None)
    items = [
        f"n = {n} coordinates: {_names(s.coordinates)}",
        f"p = {p} quasi-coordinates: {_names(s.quasi_coordinates)}"
        + (f", of which d = {dq} are defined by a differential" if p else ""),
        f"l = {ell} constraints (eq. 14.1)",
        f"k = n + p - d - l = {n} + {p} - {dq} - {ell} = {d.k} degrees of freedom",
        f"independent: {', '.join(d.independent)}"
        + (" (chosen automatically: the earliest declared valid set)" if d.rates.chosen_automatically else ""),
    ]
    return Step("Step 1. Degrees of freedom", tuple(items))


def _names(items) -> str:
    return ", ".join(i.name for i in items) or "none"


def rate_relations(d: Derivation, tidy: Tidy) -> Step:
    s, names = d.system, d.rates.names
    rates = {n: S.rate(n) for n in names}
    items: list[str | Equation] = ["The relations among the rates, from the constraints (14.1) and the quasi-coordinates (14.2):"]
    for c in s.constraints:
        if c.rates is not None:  # not linear in the rates: shown as written (docs/nonlinear.md)
            items.append(Equation(c.rates.relation, sp.S.Zero, ""))
            continue
        lhs = sum((coef * rates[n] for n, coef in c.form.coefficients), sp.S.Zero) + c.form.dt
        items.append(Equation(lhs, sp.S.Zero, "14.1"))
    for q in s.quasi_coordinates:
        if q.differential is not None:
            rhs = sum((coef * rates[n] for n, coef in q.differential.coefficients), sp.S.Zero) + q.differential.dt
            items.append(Equation(rates[q.name], rhs, "14.2"))
    dependent = [n for n in names if n not in d.independent]
    if dependent:
        items.append("Solved for the dependent rates in terms of the independent ones (eq. 14.7):")
        items += [Equation(rates[n], tidy(d.rates.rate(n)), "14.7") for n in dependent]
        items.append("so virtual displacements satisfy (eqs. 14.8, 14.9)" + (
            "; for a rate given by a relation nonlinear in the rates, ṙ = f(q, u, t), Chetaev's rule "
            "δr = Σ ∂f/∂u_s δq_s:" if d.rates.nonlinear else ":"))
        for n in dependent:
            i = names.index(n)
            rhs = sum((d.beta[i, j] * variation(u) for j, u in enumerate(d.independent)), sp.S.Zero)
            items.append(Equation(variation(n), tidy(rhs), "14.9"))
    else:
        items.append("Every rate is independent: ṙ = u.")
    return Step("Step 2a. Rates in terms of the independent rates", tuple(items))


def accelerations_and_gibbs(d: Derivation, tidy: Tidy) -> Step:
    """The accelerations as the derivation formed them (eq. 14.14), then G (eqs. 14.17, 14.21)."""
    acc = d.speed_rates
    items: list[str | Equation] = []
    if d.dependent_accelerations:
        items.append("Differentiating the rates gives the dependent accelerations (eq. 14.14):")
        items += [Equation(S.rate(n, 2), tidy.collected(e, acc), "14.14") for n, e in d.dependent_accelerations]
    whole = sp.S.Zero
    for motion in d.motions:
        body = motion.body
        a = [tidy.collected(e, acc) for e in motion_acceleration(motion.linear, acc)]
        items.append(f"Acceleration of {body.name} (centre of mass), components along {_linear_axes(motion)}:")
        items.append(Equation(sp.Symbol(f"a_{body.name}"), sp.Matrix([a]).T))
        whole += body.mass / 2 * sum(c**2 for c in a)
        if motion.angular is not None:
            w = motion_velocity(motion.angular, d.speeds)
            alpha = [tidy.collected(e, acc) for e in motion_acceleration(motion.angular, acc)]
            items.append(f"Angular acceleration of {body.name}, {_angular_axes(motion)}:")
            items.append(Equation(sp.Symbol(f"alpha_{body.name}"), sp.Matrix([alpha]).T))
            I, al, wv = body.inertia, sp.Matrix(alpha), sp.Matrix([tidy(e) for e in w])
            whole += (al.T * I * al)[0] / 2 + tidy((al.T * wv.cross(I * wv))[0])
    G = sp.Symbol("G")
    items.append("The Gibbs function (eq. 14.17, Koenig's analogue eq. 14.21 for rigid bodies):")
    items.append(Equation(G, whole, "14.21"))
    items.append("and without the terms free of accelerations, which do not enter eq. (14.19):")
    items.append(Equation(G, gibbs_polynomial(d, tidy), "14.19"))
    return Step("Step 2b. Accelerations and the Gibbs function", tuple(items))


def _linear_axes(motion) -> str:
    if motion.heading == 0:
        return "the inertial axes"
    return f"the inertial axes turned by {show(motion.heading)} about z (a·a is the same in any axes)"


def _angular_axes(motion) -> str:
    if motion.spin is None:
        return "body axes"
    axis, angle = motion.spin
    return (f"body axes turned back by {show(angle)} about {axis}, about which the inertia is symmetric "
            "(the body's non-spinning axes)")


def gibbs_polynomial(d: Derivation, tidy: Tidy) -> sp.Expr:
    """The acceleration terms of G, ½ Σ H_ii u̇_i² + Σ_{i<j} H_ij u̇_i u̇_j + Σ g_i u̇_i, tidied.

    Only the nonzero coefficients are visited and the sum is made once:
    adding k² terms one by one to a growing sum cost time ~k³ on wide systems.
    """
    H, g = gibbs_entries(d.gibbs, d.speed_rates)
    acc = d.speed_rates
    terms = []
    for (i, j), h in sorted(H.items()):
        terms.append(tidy(h / 2) * acc[i] ** 2 if i == j else tidy(h) * acc[i] * acc[j])
    terms += [tidy(c) * acc[i] for i, c in sorted(g.items())]
    return sp.Add(*terms)


def virtual_work(d: Derivation, tidy: Tidy) -> Step:
    s = d.system
    written = sp.S.Zero
    if s.work is not None:
        written += sum((c * variation(n) for n, c in s.work.coefficients), sp.S.Zero)
    items: list[str | Equation] = ["The work done in a virtual displacement (δt = 0):"]
    if s.work is not None:
        items.append(Equation(sp.Symbol("δW_work"), written))
    for f in s.forces:
        items.append(f"a force {list(f.vector)} at {list(f.point)}")
    for tq in s.torques:
        items.append(f"a torque {list(tq.vector)} on {tq.body} (body axes)")
    if s.potential != 0:
        items.append(Equation(sp.Symbol("V"), s.potential))
    items.append("With eq. (14.9) every δ is a combination of the independent ones, δW = Σ Q_s δq_s (eq. 14.13):")
    reduced = sum((tidy(q) * variation(n) for n, q in zip(d.independent, d.generalized_forces)), sp.S.Zero)
    items.append(Equation(sp.Symbol("δW"), reduced, "14.13"))
    items += [Equation(sp.Symbol(f"Q_{n}"), tidy(q), "14.13") for n, q in zip(d.independent, d.generalized_forces)]
    return Step("Step 3. Virtual work and generalized forces", tuple(items))


def equations_of_motion(d: Derivation, tidy: Tidy) -> Step:
    items: list[str | Equation] = ["∂G/∂u̇_s = Q_s (eq. 14.19):"]
    items += [equation_of_motion(d, s, tidy) for s in range(d.k)]
    # q̇ = q̇ for an independent coordinate says nothing, and is not printed.
    kinematic = [Equation(S.rate(n), tidy(e), "14.20") for n, e in d.kinematic_equations if e != S.rate(n)]
    if kinematic:
        items.append("with the kinematic equations (eq. 14.20):")
        items += kinematic
    else:
        items.append("Every coordinate is independent: the kinematic equations (14.20) say only q̇ = q̇.")
    return Step("Step 4. Equations of motion", tuple(items))


def equation_of_motion(d: Derivation, s: int, tidy: Tidy) -> Equation:
    """∂G/∂u̇_s = Q_s written as Σ_r M_sr u̇_r + (Q_s − F_s) = Q_s."""
    # Zero entries are skipped and the sum made once: tidying every entry of a
    # row, and growing the sum a term at a time, made this ~k² per row.
    row = d.mass_matrix.row(s).todok()
    terms = [tidy(row[0, r]) * d.speed_rates[r] for _, r in sorted(row)]
    lhs = sp.Add(*terms) + tidy(d.generalized_forces[s] - d.forcing[s])
    return Equation(lhs, tidy(d.generalized_forces[s]), "14.19")
