"""Exterior derivatives of the forms of a system file, primitive quasi-coordinates included.

A form runs over the differentials of the coordinates, of the
quasi-coordinates and of t; its coefficients depend on the coordinates and
t. A quasi-coordinate given by a differential is replaced by it (so
``dq`` with ``q: r**2*dtheta`` is ``r**2*dtheta``). A primitive one (no
differential) has no value to differentiate, but it is not a free symbol
either: it is a component of a rigid body's rotation ω dt, and those obey
the Maurer-Cartan equations of the rotation group. With R the body's
orientation, the body-axis components Ω (Ω̂ = Rᵀ dR) and the inertial ones
ω (ω̂ = dR Rᵀ) satisfy dΩ̂ = −Ω̂ ∧ Ω̂ and dω̂ = +ω̂ ∧ ω̂, that is::

    dΩ_1 = −Ω_2 ∧ Ω_3   (and cyclically)      body axes,  sign σ = −1
    dω_1 = +ω_2 ∧ ω_3   (and cyclically)      inertial axes, σ = +1

(checked against ZXZ Euler angles in tests/test_integrability.py). A body's
rotation ρ = A + P dπ (π its primitive quasi-coordinates, A the rest) then
gives dπ = P⁻¹ (σ ρ×ρ − dA − dP ∧ dπ), when the three components are free
(three primitives, P invertible). A body turning about one fixed axis has
one nonzero component, whose right side is zero: dπ = −(dA + dp ∧ dπ)/p.
The file's axes are body axes (σ = −1), except that a body with equal
principal moments may give inertial components: both signs are tried and
:mod:`gacli.check.integrability` keeps a verdict only when they agree.

Anything else (a primitive in no rotation, in several, or in a rotation of
another shape) has no known structure: a form that involves it is
undecided, never holonomic.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.algebra.fastdiff import jacobian_rows
from gacli.mechanics.rates import function_chain
from gacli.model import Body, Form, System

OneForm = dict[str, sp.Expr]
TwoForm = dict[tuple[str, str], sp.Expr]

BODY_AXES, INERTIAL_AXES = -1, 1
# Each body with equal moments doubles the number of structures tried.
MAX_AMBIGUOUS_BODIES = 3


@dataclass(frozen=True)
class Structure:
    """dπ for each primitive quasi-coordinate whose structure is known; why not for the others."""

    derivatives: Mapping[str, TwoForm]
    unknown: Mapping[str, str]


class Calculus:
    """Partial and exterior derivatives on the configuration (coordinates and t)."""

    def __init__(self, system: System) -> None:
        self.coordinates = {c.name for c in system.coordinates}
        self.chain = function_chain(system)
        self.order = {name: i for i, name in enumerate(list(system.rate_names) + ["t"])}
        self.defined = {q.name: q.differential for q in system.quasi_coordinates if q.differential is not None}
        self.primitive = tuple(q.name for q in system.quasi_coordinates if q.differential is None)

    def one_form(self, form: Form) -> OneForm:
        """The form's coefficients, quasi-coordinates given by a differential replaced by it."""
        out: OneForm = {}
        self._add(out, form, sp.S.One, depth=len(self.defined))
        return {n: c for n, c in out.items() if c != 0}

    def _add(self, out: OneForm, form: Form, factor, depth: int) -> None:
        for name, coefficient in list(form.coefficients) + [("t", form.dt)]:
            term = factor * as_expr(coefficient)
            if name in self.defined and depth > 0:
                self._add(out, self.defined[name], term, depth - 1)
            else:
                out[name] = out.get(name, sp.S.Zero) + term

    def partial(self, expr, variable: str) -> sp.Expr:
        if variable == "t":
            return S.time_derivative(as_expr(expr), self.chain)
        if variable in self.coordinates:
            return sp.diff(expr, S.value(variable))
        return sp.S.Zero  # a quasi-coordinate has no value for a coefficient to depend on

    def gradient(self, expr) -> OneForm:
        names = [n for n in self.order if n in self.coordinates or n == "t"]
        # One memoised walk for every coordinate (a bicycle's rolling rows: sp.diff per coordinate
        # was two thirds of check's time).
        coordinates = [n for n in names if n != "t"]
        rows = jacobian_rows([as_expr(expr)], [S.value(n) for n in coordinates])[0] if coordinates else []
        partials = dict(zip(coordinates, rows))
        return {n: d for n in names if (d := partials[n] if n != "t" else self.partial(expr, n)) != 0}

    def wedge(self, a: OneForm, b: OneForm) -> TwoForm:
        out: TwoForm = {}
        for (i, ai), (j, bj) in itertools.product(a.items(), b.items()):
            if i != j:
                key, sign = ((i, j), 1) if self.order[i] < self.order[j] else ((j, i), -1)
                out[key] = out.get(key, sp.S.Zero) + sign * ai * bj
        return out

    def d_coefficients(self, a: OneForm) -> TwoForm:
        """Σ d(a_j) ∧ dx_j: the exterior derivative but for the primitives' own dπ."""
        out: TwoForm = {}
        for name, coefficient in a.items():
            _accumulate(out, self.wedge(self.gradient(coefficient), {name: sp.S.One}))
        return out


def _accumulate(out: TwoForm, form: TwoForm, factor=sp.S.One) -> None:
    for key, value in form.items():
        out[key] = out.get(key, sp.S.Zero) + factor * value


def structures(system: System, calculus: Calculus) -> tuple[Structure, ...]:
    """One Structure per choice of axes (σ) for the bodies with equal moments; one when none."""
    owners = {name: [] for name in calculus.primitive}
    rows_of: dict[str, list[OneForm]] = {}
    for body in system.bodies:
        if body.rotation is None:
            continue
        rows_of[body.name] = [calculus.one_form(f) for f in body.rotation]
        for name in sorted({n for row in rows_of[body.name] for n in row if n in owners}, key=calculus.order.get):
            owners[name].append(body)
    unknown, bodies = _unowned(owners), {}
    for name, found in owners.items():
        if len(found) == 1:
            bodies.setdefault(found[0].name, (found[0], []))[1].append(name)
    ambiguous = [b for b, _ in bodies.values() if _isotropic(b) and _free_rotation(rows_of[b.name])]
    if len(ambiguous) > MAX_AMBIGUOUS_BODIES:
        for b in ambiguous[MAX_AMBIGUOUS_BODIES:]:
            unknown.update((n, f"'{b.name}' has equal moments: its axes may be inertial or its own")
                           for n in bodies.pop(b.name)[1])
        ambiguous = ambiguous[:MAX_AMBIGUOUS_BODIES]
    out = []
    for signs in itertools.product((BODY_AXES, INERTIAL_AXES), repeat=len(ambiguous)):
        sigma = {b.name: s for b, s in zip(ambiguous, signs)}
        derivatives, why = {}, dict(unknown)
        for body, prims in bodies.values():
            found = _body_derivatives(rows_of[body.name], prims, sigma.get(body.name, BODY_AXES), calculus)
            if isinstance(found, str):
                why.update((n, f"{found} (body '{body.name}')") for n in prims)
            else:
                derivatives.update(found)
        out.append(Structure(derivatives, why))
    return tuple(out)


def _unowned(owners: Mapping[str, list[Body]]) -> dict[str, str]:
    why = {}
    for name, found in owners.items():
        if not found:
            why[name] = "in no body's rotation, so its exterior derivative is unknown"
        elif len(found) > 1:
            why[name] = f"in the rotations of {', '.join(repr(b.name) for b in found)}"
    return why


def _isotropic(body: Body) -> bool:
    """Equal principal moments: the file may give inertial components (docs/system-file.md)."""
    m = body.inertia
    if m is None:
        return False
    off = [m[i, j] for i in range(3) for j in range(3) if i != j]
    return all(sp.simplify(e) == 0 for e in off + [m[0, 0] - m[1, 1], m[1, 1] - m[2, 2]])


def _free_rotation(rows: list[OneForm]) -> bool:
    # Only three nonzero components bring in ρ×ρ, the one term whose sign σ is.
    return sum(1 for row in rows if row) == 3


def _body_derivatives(rows: list[OneForm], prims: list[str], sigma: int, calc: Calculus) -> dict[str, TwoForm] | str:
    """dπ for the body's primitives, or why the structure is unknown."""
    foreign = sorted({n for row in rows for n in row if n in calc.primitive and n not in prims})
    if foreign:
        return f"its rotation also involves {', '.join('d' + n for n in foreign)}"
    nonzero = [r for r, row in enumerate(rows) if row]
    if len(nonzero) == 3 and len(prims) == 3:
        right = [_times(sigma, calc.wedge(rows[(r + 1) % 3], rows[(r + 2) % 3])) for r in range(3)]
    elif len(nonzero) == 1 and len(prims) == 1:
        rows, right = [rows[nonzero[0]]], [{}]
    else:
        return (f"its rotation has {len(nonzero)} nonzero components in {len(prims)} primitive "
                "quasi-coordinates: only 3 in 3 (free) or 1 in 1 (a fixed axis) have a known structure")
    p = sp.Matrix([[row.get(n, sp.S.Zero) for n in prims] for row in rows])
    if sp.simplify(p.det()) == 0:
        return "its rotation components are not independent in the primitive quasi-coordinates"
    known = []
    for row, rhs in zip(rows, right):
        # P dπ = dρ − dA − dP ∧ dπ, and d of ρ's own coefficients is exactly dA + dP ∧ dπ.
        known.append(dict(rhs))
        _accumulate(known[-1], calc.d_coefficients(row), -1)
    inverse = p.inv()
    out: dict[str, TwoForm] = {}
    for m, name in enumerate(prims):
        out[name] = {}
        for r, form in enumerate(known):
            _accumulate(out[name], form, inverse[m, r])
        out[name] = {k: v for k, v in out[name].items() if v != 0}
    return out


def _times(factor, form: TwoForm) -> TwoForm:
    return {k: factor * v for k, v in form.items()}
