"""Which constraints are holonomic, which quasi-coordinates are coordinates (Frobenius).

A Pfaffian form ω = Σ a_i dx_i runs over the differentials of the
coordinates, of the quasi-coordinates and of t (time is one more variable);
its coefficients are functions of the coordinates and t (parameters and the
free functions of time ride along: a free function Omega has dOmega/dt =
dot(Omega)). Quasi-coordinates have no value, so no coefficient depends on
them. Then:

* a constraint ω = 0 is integrable (holonomic) iff ω ∧ dω = 0, the Frobenius
  condition for a single form;
* a quasi-coordinate dθ = ω is a true coordinate iff ω is closed, dω = 0
  (then, locally, ω = dθ for a function θ of the coordinates and t).

In components, with c_ij = ∂_i a_j − ∂_j a_i (dω = Σ_{i<j} c_ij dx_i ∧ dx_j)::

    dω = 0       ⇔  c_ij = 0                              for all i < j
    ω ∧ dω = 0   ⇔  a_i c_jk − a_j c_ik + a_k c_ij = 0     for all i < j < k

Each component is decided by :func:`decide_zero`: ``simplify`` while the
expression is small, and otherwise (or when simplify leaves something that
is not a number) by evaluating it at seeded random points.

Each form is tested on its own: a set of constraints can be integrable
together only if each one is integrable modulo the others, which this module
does not test.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import sympy as sp

from gacli import symbols as S
from gacli.coerce import as_expr
from gacli.errors import Location
from gacli.evaluate import UndefinedValue, evaluate  # noqa: F401 - re-exported
from gacli.zero import (  # noqa: F401 - re-exported
    SIMPLIFY_MAX_OPS, Decision, decide_zero, sample_points, time_limit,
)
from gacli.kinematics import function_chain
from gacli.model import Form, System

@dataclass(frozen=True)
class Classification:
    """The verdict on one constraint or one quasi-coordinate differential.

    ``kind`` is "constraint" or "quasi_coordinate"; ``integrable`` is True
    for a holonomic constraint or a quasi-coordinate that is a coordinate,
    None when undecided. ``method`` is "relation" (a constraint written as
    f(q, t) = 0), "symbolic", "numeric" or "undecided".
    """

    kind: str
    where: str
    text: str
    location: Location
    integrable: bool | None
    method: str

    @property
    def verdict(self) -> str:
        if self.integrable is None:
            return "undecided"
        if self.kind == "constraint":
            return "holonomic" if self.integrable else "non-holonomic"
        return "a coordinate" if self.integrable else "not a coordinate"


def classify(system: System) -> tuple[Classification, ...]:
    """Classify every constraint and every quasi-coordinate given by a differential."""
    out = []
    for i, constraint in enumerate(system.constraints):
        where = f"constraints[{i}]"
        if constraint.relation is not None:
            out.append(Classification("constraint", where, constraint.text, constraint.location, True, "relation"))
            continue
        decision = is_integrable(constraint.form, system)
        out.append(Classification("constraint", where, constraint.text, constraint.location,
                                  decision.zero, decision.method))
    for q in system.quasi_coordinates:
        if q.differential is None:
            continue
        decision = is_closed(q.differential, system)
        out.append(Classification("quasi_coordinate", f"quasi_coordinates.{q.name}", _form_text(q.differential),
                                  q.location, decision.zero, decision.method))
    return tuple(out)


def is_closed(form: Form, system: System) -> Decision:
    """dω = 0 ?"""
    exterior = _Exterior(form, system)
    return _all_zero(exterior.d_component(i, j) for i, j in itertools.combinations(exterior.variables, 2))


def is_integrable(form: Form, system: System) -> Decision:
    """ω ∧ dω = 0 ?"""
    exterior = _Exterior(form, system)
    return _all_zero(exterior.wedge_component(i, j, k)
                     for i, j, k in itertools.combinations(exterior.variables, 3))


class _Exterior:
    """The coefficients of one form and the derivatives its exterior derivative needs."""

    def __init__(self, form: Form, system: System) -> None:
        self.coordinates = {c.name for c in system.coordinates}
        self.chain = function_chain(system)
        self.a = {name: coefficient for name, coefficient in form.coefficients}
        self.a["t"] = form.dt
        self.variables = self._active(system)
        self._d: dict[tuple[str, str], sp.Expr] = {}

    def _active(self, system: System) -> list[str]:
        """Variables with a coefficient, or on which some coefficient depends (declaration order)."""
        free = set().union(*(as_expr(c).free_symbols for c in self.a.values()))
        timed = S.T in free or bool(free & set(self.chain))
        names = list(system.rate_names) + ["t"]
        return [n for n in names if self.a.get(n, 0) != 0 or S.value(n) in free and n in self.coordinates
                or n == "t" and timed]

    def partial(self, expr: sp.Expr, variable: str) -> sp.Expr:
        if variable == "t":
            return S.time_derivative(as_expr(expr), self.chain)
        if variable in self.coordinates:
            return sp.diff(expr, S.value(variable))
        return sp.S.Zero  # a quasi-coordinate has no value for a coefficient to depend on

    def d_component(self, i: str, j: str) -> sp.Expr:
        """c_ij = ∂_i a_j − ∂_j a_i."""
        if (i, j) not in self._d:
            self._d[(i, j)] = self.partial(self.a.get(j, 0), i) - self.partial(self.a.get(i, 0), j)
        return self._d[(i, j)]

    def wedge_component(self, i: str, j: str, k: str) -> sp.Expr:
        a = self.a
        return (a.get(i, 0) * self.d_component(j, k) - a.get(j, 0) * self.d_component(i, k)
                + a.get(k, 0) * self.d_component(i, j))


def _all_zero(components) -> Decision:
    """All components zero? The first one found nonzero decides; 'numeric' if any needed points."""
    method, undecided = "symbolic", False
    for component in components:
        decision = decide_zero(component)
        if decision.zero is False:
            return decision
        if decision.zero is None:
            undecided = True
        elif decision.method == "numeric":
            method = "numeric"
    return Decision(None, "undecided") if undecided else Decision(True, method)


def _form_text(form: Form) -> str:
    """The form in the file's grammar (``r**2*dtheta``), for reports."""
    terms = [c * sp.Symbol(f"d{n}") for n, c in form.coefficients]
    return sp.sstr(sp.Add(*terms, form.dt * sp.Symbol("dt")), order="none")
