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
from gacli.algebra.coerce import as_expr
from gacli.mechanics.equations import Derivation
from gacli.display import printed
from gacli.mechanics.motions import motion_acceleration, motion_velocity
from gacli.algebra.readable import STEP_BUDGET_OPS, Tidy, show


@dataclass(frozen=True)
class Equation:
    lhs: sp.Expr
    rhs: sp.Expr
    label: str = ""  # the chapter's number for it, shared by the block it stands in
    head: sp.Expr | None = None  # the acceleration u̇_s of ∂G/∂u̇_s = Q_s, whose left side is written out


@dataclass(frozen=True)
class Formula:
    """Mathematics inside a sentence that is not a SymPy expression: its text and its LaTeX."""

    text: str
    tex: str


@dataclass(frozen=True)
class Names:
    """A list of declared names inside a sentence (``x, y, yaw``; LaTeX ``x, y, \\psi``)."""

    names: tuple[str, ...]


@dataclass(frozen=True)
class Sentence:
    """Prose (str) and mathematics (a SymPy expression, :class:`Formula`, :class:`Names`) in turn."""

    parts: tuple

    @property
    def text(self) -> str:
        return "".join(_text(p) for p in self.parts)


def _text(part) -> str:
    if isinstance(part, str):
        return part
    if isinstance(part, Formula):
        return part.text
    if isinstance(part, Names):
        return ", ".join(part.names) or "none"
    return show(part)


@dataclass(frozen=True)
class Load:
    """A force (at ``where``) or a torque (on ``where``), as the file gave it: its components along
    the axes of each frame named (``terms``), and the position of its point in N when the file gave one."""

    torque: bool
    terms: tuple[tuple[str, sp.Matrix], ...]
    where: str
    position: sp.Matrix | None = None


@dataclass(frozen=True)
class Step:
    title: str
    items: tuple[str | Sentence | Equation | Load, ...]


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
        equations_of_motion(d),
    )


def degrees_of_freedom(d: Derivation) -> Step:
    s = d.system
    n, p, ell = len(s.coordinates), len(s.quasi_coordinates), d.rates.constraints_used
    dq = sum(1 for q in s.quasi_coordinates if q.differential is not None)
    items = [
        Sentence((Formula(f"n = {n}", f"n = {n}"), " coordinates: ", _names(s.coordinates))),
        Sentence((Formula(f"p = {p}", f"p = {p}"), " quasi-coordinates: ", _names(s.quasi_coordinates))
                 + ((", of which ", Formula(f"d = {dq}", f"d = {dq}"), " are defined by a differential") if p else ())),
        Sentence((Formula(f"l = {ell}", f"l = {ell}"), " constraints (eq. 14.1)")),
        Sentence((Formula(f"k = n + p - d - l = {n} + {p} - {dq} - {ell} = {d.k}",
                          f"k = n + p - d - l = {n} + {p} - {dq} - {ell} = {d.k}"), " degrees of freedom")),
        Sentence(("independent: ", Names(tuple(d.independent)))
                 + ((" (chosen automatically: the earliest declared valid set)",) if d.rates.chosen_automatically else ())),
    ]
    return Step("Step 1. Degrees of freedom", tuple(items))


def _names(items) -> Names:
    return Names(tuple(i.name for i in items))


def rate_relations(d: Derivation, tidy: Tidy) -> Step:
    s, names = d.system, d.rates.names
    rates = {n: S.rate(n) for n in names}
    quasi = any(q.differential is not None for q in s.quasi_coordinates)
    items: list = ["The relations among the rates, from the constraints (14.1)"
                   + (" and the quasi-coordinates (14.2):" if quasi else ":")]
    for c in s.constraints:
        if c.rates is not None:  # not linear in the rates: shown as written (docs/nonlinear.md)
            items.append(Equation(c.rates.relation, sp.S.Zero, ""))
            continue
        lhs = sum((coef * rates[n] for n, coef in c.form.coefficients), sp.S.Zero) + c.form.dt
        items.append(Equation(printed.tidy(lhs), sp.S.Zero, "14.1"))
    for q in s.quasi_coordinates:
        if q.differential is not None:
            rhs = sum((coef * rates[n] for n, coef in q.differential.coefficients), sp.S.Zero) + q.differential.dt
            items.append(Equation(rates[q.name], rhs, "14.2"))
    dependent = [n for n in names if n not in d.independent]
    if dependent:
        items.append("Solved for the dependent rates in terms of the independent ones (eq. 14.7):")
        items += [Equation(rates[n], printed.tidy(d.rates.rate(n)), "14.7") for n in dependent]
        items.append(Sentence(("so virtual displacements satisfy (eqs. 14.8, 14.9)",) + ((
            "; for a rate given by a relation nonlinear in the rates, ",
            Formula("dot(r) = f(q, u, t)", r"\dot{r} = f(q, u, t)"), ", Chetaev's rule ",
            Formula("δr = Σ ∂f/∂u_s δq_s", r"\delta r = \sum_s \frac{\partial f}{\partial u_s}\, \delta q_s"), ":",
        ) if d.rates.nonlinear else (":",))))
        for n in dependent:
            i = names.index(n)
            rhs = sum((d.beta[i, j] * variation(u) for j, u in enumerate(d.independent)), sp.S.Zero)
            items.append(Equation(variation(n), tidy(rhs), "14.9"))
    else:
        items.append(Sentence(("Every rate is independent: the speeds are the rates of the coordinates, ",
                               Formula("u_s = dot(q_s)", r"u_s = \dot{q}_s"), ".")))
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
        items.append(Sentence(("Acceleration of ", body.name, " (centre of mass), components along ")
                              + _linear_axes(motion) + (":",)))
        items.append(Equation(sp.Symbol(f"a_{body.name}"), sp.Matrix([a]).T))
        whole += body.mass / 2 * sum(c**2 for c in a)
        if motion.angular is not None:
            w = motion_velocity(motion.angular, d.speeds)
            alpha = [tidy.collected(e, acc) for e in motion_acceleration(motion.angular, acc)]
            items.append(Sentence(("Angular acceleration of ", body.name, ", ") + _angular_axes(motion) + (":",)))
            items.append(Equation(sp.Symbol(f"alpha_{body.name}"), sp.Matrix([alpha]).T))
            I, al, wv = body.inertia, sp.Matrix(alpha), sp.Matrix([tidy(e) for e in w])
            whole += (al.T * I * al)[0] / 2 + tidy((al.T * wv.cross(I * wv))[0])
    G = sp.Symbol("G")
    rigid = any(m.angular is not None for m in d.motions)
    items.append("The Gibbs function (eq. 14.17, Koenig's analogue eq. 14.21 for rigid bodies):")
    items.append(Equation(G, whole, "14.21" if rigid else "14.17"))
    # G = G_2 + G_1 + G_0 in the chapter, unnumbered: eq. (14.19) differentiates G_2 + G_1.
    items.append("and without the terms free of accelerations, which do not enter eq. (14.19):")
    items.append(Equation(G, printed.gibbs(d)))
    return Step("Step 2b. Accelerations and the Gibbs function", tuple(items))


def _linear_axes(motion) -> tuple:
    if motion.heading == 0:
        return ("the inertial axes",)
    return ("the inertial axes turned by ", motion.heading, " about ", Formula("z", "z"), " (",
            Formula("a·a", r"\mathbf{a} \cdot \mathbf{a}"), " is the same in any axes)")


def _angular_axes(motion) -> tuple:
    if motion.spin is None:
        return ("body axes",)
    axis, angle = motion.spin
    return ("body axes turned back by ", angle, " about ", Formula(axis, axis),
            ", about which the inertia is symmetric (the body's non-spinning axes)")


def virtual_work(d: Derivation, tidy: Tidy) -> Step:
    s = d.system
    if s.work is None and not s.forces and not s.torques and (s.frames is None or not s.frames.loads) and s.potential == 0:
        items: list = [Sentence(("No load does work in a virtual displacement (", Formula("δt = 0", r"\delta t = 0"),
                                 "): every generalized force is zero (eq. 14.13).",))]
        items += [Equation(sp.Symbol(f"Q_{n}"), sp.S.Zero, "14.13") for n in d.independent]
        return Step("Step 3. Virtual work and generalized forces", tuple(items))
    items = [Sentence(("The work done in a virtual displacement (", Formula("δt = 0", r"\delta t = 0"), "):"))]
    if s.work is not None:
        written = sum((c * variation(n) for n, c in s.work.coefficients), sp.S.Zero)
        items.append(Equation(sp.Symbol("δW_work"), written))
    items += loads(s, tidy)
    if s.potential != 0:
        items.append(Equation(sp.Symbol("V"), s.potential))
    items.append(Sentence(("With eq. (14.9) every ", Formula("δ", r"\delta"), " is a combination of the independent ones, ",
                           Formula("δW = Σ Q_s δq_s", r"\delta W = \sum_s Q_s \, \delta q_s"), " (eq. 14.13):")))
    forces = printed.coefficients(d).forces
    reduced = sp.Add(*(q * variation(n) for n, q in zip(d.independent, forces)))
    items.append(Equation(sp.Symbol("δW"), reduced, "14.13"))
    items += [Equation(sp.Symbol(f"Q_{n}"), q, "14.13") for n, q in zip(d.independent, forces)]
    return Step("Step 3. Virtual work and generalized forces", tuple(items))


def loads(s, tidy: Tidy) -> list[Load]:
    """The forces and torques in the frames the file wrote them in, their components read as every expression is."""
    def column(triple) -> sp.Matrix:
        return sp.Matrix([tidy(as_expr(c)) for c in triple])

    if s.frames is not None:
        return [Load(load.torque, tuple((frame, column(v)) for frame, v in load.vector.terms),
                     load.body if load.torque else (load.point or ""))
                for load in s.frames.loads]
    out = [Load(False, (("N", column(f.vector)),), "", column(f.point)) for f in s.forces]
    return out + [Load(True, ((t.body, column(t.vector)),), t.body) for t in s.torques]


def equations_of_motion(d: Derivation) -> Step:
    items: list = [Sentence((Formula("∂G/∂u̇_s = Q_s", r"\partial G / \partial \dot{u}_s = Q_s"), " (eq. 14.19):"))]
    items += [Equation(*printed.equation(d, s), "14.19", d.speed_rates[s]) for s in range(d.k)]
    # q̇ = q̇ for an independent coordinate says nothing, and is not printed.
    kinematic = [Equation(S.rate(n), e, "14.20") for n, e in printed.kinematic(d)]
    if kinematic:
        items.append("with the kinematic equations (eq. 14.20):")
        items += kinematic
    else:
        items.append("Every coordinate is independent: its rate is one of the speeds, and there is no "
                     "kinematic equation (14.20) to add.")
    return Step("Step 4. Equations of motion", tuple(items))
