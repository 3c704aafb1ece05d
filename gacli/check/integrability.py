"""Which constraints are holonomic, which quasi-coordinates are coordinates (Frobenius).

A Pfaffian form ω = Σ a_i dx_i runs over the differentials of the
coordinates, of the quasi-coordinates and of t (time is one more variable);
its coefficients are functions of the coordinates and t (parameters and the
free functions of time ride along: a free function Omega has dOmega/dt =
dot(Omega)). Its exterior derivative dω is computed by :mod:`gacli.check.exterior`:
a quasi-coordinate given by a differential is replaced by it, and a
primitive one is a component of a body's rotation, whose d follows from the
Maurer-Cartan equations of the rotation group (d(dq_x) is not zero for a
body turning freely). Then:

* a quasi-coordinate dθ = ω is a true coordinate iff dω = 0;
* one constraint ω = 0 is integrable on its own iff ω ∧ dω = 0;
* the Pfaffian constraints ω_1 = … = ω_l = 0 are integrable together iff
  dω_a ∧ ω_1 ∧ … ∧ ω_l = 0 for every a (Frobenius for the set), that is,
  iff each dω_a vanishes on the kernel of the constraints.

A constraint is reported holonomic when it is integrable alone or the whole
set is, non-holonomic when neither holds, and undecided otherwise (a
primitive quasi-coordinate whose structure is unknown, or a test no point
could decide). "Integrable modulo the others" is not used for one row: it
can hold for a row of a set whose brackets reach every direction
(dw = z dx, dz = y dx), where no relation holds at all.

In components, with c_ij the coefficients of dω = Σ_{i<j} c_ij dx_i ∧ dx_j::

    dω = 0       ⇔  c_ij = 0                              for all i < j
    ω ∧ dω = 0   ⇔  a_i c_jk − a_j c_ik + a_k c_ij = 0     for all i < j < k
    set          ⇔  dω_a(X, Y) = 0 for X, Y in a basis of the kernel

Each component is decided by :func:`decide_zero`: ``simplify`` while the
expression is small, and otherwise (or when simplify leaves something that
is not a number) by evaluating it at seeded random points. When the
kernel's basis takes too long symbolically (the bicycle), the set's test
is made at seeded points with the kernel's orthogonal projection.

A nonlinear constraint (not linear in the rates) has no Pfaffian form: it is
reported "nonlinear", not tested, and left out of the set.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, replace
from functools import partial

import mpmath
import sympy as sp

from gacli.algebra.coerce import as_expr
from gacli.errors import GacliError, Location
from gacli.check.exterior import Calculus, OneForm, Structure, structures
from gacli.model import Form, System
from gacli.numeric import UndefinedValue, evaluate, sample_points
from gacli.numeric.guarded import DIGITS as _DIGITS
from gacli.numeric.guarded import RELATIVE_TOLERANCE as _RELATIVE_TOLERANCE
from gacli.numeric.zero import _MIN_VALID_POINTS, _SEED, Decision, decide_zero, time_limit

# The set's test needs a basis of the constraints' kernel; sympy's rref can
# take minutes on the bicycle's rows, and seeded points decide as well.
KERNEL_SECONDS = 2.0
_NUMERIC_POINTS = 6
NONLINEAR_VERDICT = "nonlinear (non-holonomic unless integrable; not tested)"
_AXES_NOTE = ("the verdict depends on whether the rotation components are along body or inertial axes "
              "(equal moments allow both)")


@dataclass(frozen=True)
class Classification:
    """The verdict on one constraint or one quasi-coordinate differential.

    ``kind`` is "constraint" or "quasi_coordinate"; ``integrable`` is True
    for a holonomic constraint or a quasi-coordinate that is a coordinate,
    None when undecided or not tested. ``method`` is "relation" (a constraint
    written as f(q, t) = 0), "symbolic", "numeric", "undecided" or "not
    tested". ``test`` says which condition decided: "alone" (ω ∧ dω = 0),
    "set" (Frobenius for all the Pfaffian constraints together), "closed"
    (dω = 0), "relation" or "nonlinear"; ``note`` says why when undecided.
    """

    kind: str
    where: str
    text: str
    location: Location
    integrable: bool | None
    method: str
    test: str = ""
    note: str = ""

    @property
    def verdict(self) -> str:
        if self.test == "nonlinear":
            return NONLINEAR_VERDICT
        if self.integrable is None:
            return "undecided"
        if self.kind == "constraint":
            return "holonomic" if self.integrable else "non-holonomic"
        return "a coordinate" if self.integrable else "not a coordinate"


def is_nonlinear(constraint) -> bool:
    """A constraint not linear in the rates (docs/nonlinear.md): its form is a linearization, not a Pfaffian form."""
    return constraint.rates is not None


def classify(system: System) -> tuple[Classification, ...]:
    """Classify every constraint and every quasi-coordinate given by a differential.

    With bodies of equal moments, whose rotation may be in body or inertial
    axes, each choice is tried and a verdict kept only when all agree.
    """
    calculus = Calculus(system)
    options = [_classify_with(system, calculus, s) for s in structures(system, calculus)]
    return tuple(_agreed(found) for found in zip(*options))


def _agreed(found: tuple[Classification, ...]) -> Classification:
    first = found[0]
    if all(f.integrable == first.integrable for f in found[1:]):
        return first
    return replace(first, integrable=None, method="undecided", note=_AXES_NOTE)


def _classify_with(system: System, calculus: Calculus, structure: Structure) -> list[Classification]:
    pfaffian = {i: c for i, c in enumerate(system.constraints) if not is_nonlinear(c)}
    exteriors = {i: _Exterior(calculus.one_form(c.form), calculus, structure) for i, c in pfaffian.items()}
    alone = {i: _integrable(exteriors[i]) for i, c in pfaffian.items() if c.relation is None}
    together = None
    if len(pfaffian) > 1 and any(d.zero is not True for d in alone.values()):
        together = set_integrable(list(exteriors.values()), calculus)
    out = [_constraint_verdict(i, c, alone.get(i), together, exteriors.get(i))
           for i, c in enumerate(system.constraints)]
    for q in system.quasi_coordinates:
        if q.differential is None:
            continue
        exterior = _Exterior(calculus.one_form(q.differential), calculus, structure)
        decision = _closed(exterior)
        out.append(Classification("quasi_coordinate", f"quasi_coordinates.{q.name}", _form_text(q.differential),
                                  q.location, decision.zero, decision.method, "closed", exterior.note))
    return out


def _constraint_verdict(i: int, c, own: Decision | None, together: Decision | None,
                        exterior: _Exterior | None) -> Classification:
    """Holonomic when integrable alone or with the others; non-holonomic only when both tests say no."""
    found = partial(Classification, "constraint", f"constraints[{i}]", c.text, c.location)
    if exterior is None:
        return found(None, "not tested", "nonlinear",
                     "not linear in the rates: no Pfaffian form for the Frobenius test")
    if c.relation is not None:
        return found(True, "relation", "relation")
    if own.zero is True:
        return found(True, own.method, "alone")
    if together is not None and together.zero is True:
        return found(True, together.method, "set")
    if own.zero is False and (together is None or together.zero is False):
        return found(False, own.method, "alone")
    note = exterior.note or "not integrable alone, and the test of the whole set is undecided"
    return found(None, "undecided", "set" if exterior.note == "" else "alone", note)


def is_closed(form: Form, system: System) -> Decision:
    """dω = 0 ? (body axes for every rotation)"""
    calculus = Calculus(system)
    return _closed(_Exterior(calculus.one_form(form), calculus, structures(system, calculus)[0]))


def is_integrable(form: Form, system: System) -> Decision:
    """ω ∧ dω = 0 ? (body axes for every rotation)"""
    calculus = Calculus(system)
    return _integrable(_Exterior(calculus.one_form(form), calculus, structures(system, calculus)[0]))


def _closed(exterior: _Exterior) -> Decision:
    if exterior.unknown:
        return Decision(None, "undecided")
    return _all_zero(exterior.d_component(i, j) for i, j in itertools.combinations(exterior.variables, 2))


def _integrable(exterior: _Exterior) -> Decision:
    if exterior.unknown:
        return Decision(None, "undecided")
    return _all_zero(exterior.wedge_component(i, j, k) for i, j, k in itertools.combinations(exterior.variables, 3))


class _Exterior:
    """One form ω = Σ a_i dx_i and its exterior derivative dω = Σ_{i<j} c_ij dx_i ∧ dx_j.

    c_ij = ∂_i a_j − ∂_j a_i, plus a_π times the components of dπ for each
    primitive quasi-coordinate π (its structure, :mod:`gacli.check.exterior`).
    """

    def __init__(self, a: OneForm, calculus: Calculus, structure: Structure) -> None:
        self.a = a
        self.unknown = [n for n in a if n in structure.unknown]
        self.note = "; ".join(f"d{n}: {structure.unknown[n]}" for n in self.unknown)
        d = calculus.d_coefficients(a)
        for name, coefficient in a.items():
            for key, value in structure.derivatives.get(name, {}).items():
                d[key] = d.get(key, sp.S.Zero) + coefficient * value
        self.d = {key: value for key, value in d.items() if value != 0}
        self.variables = sorted(set(a) | {v for key in self.d for v in key}, key=calculus.order.get)

    def d_component(self, i: str, j: str) -> sp.Expr:
        return self.d.get((i, j), sp.S.Zero)

    def wedge_component(self, i: str, j: str, k: str) -> sp.Expr:
        a = self.a
        return (a.get(i, 0) * self.d_component(j, k) - a.get(j, 0) * self.d_component(i, k)
                + a.get(k, 0) * self.d_component(i, j))


# -- the set of constraints ------------------------------------------------------------------

def set_integrable(exteriors: list[_Exterior], calculus: Calculus) -> Decision:
    """Frobenius for the set ω_1 = … = ω_l = 0: dω_a ∧ ω_1 ∧ … ∧ ω_l = 0 for every a.

    Equivalently dω_a vanishes on the kernel D of the constraints:
    dω_a(X, Y) = 0 for X, Y in a basis of D (the form is zero on D ⇔ its
    wedge with all the ω's is zero).
    """
    if any(e.unknown for e in exteriors):
        return Decision(None, "undecided")
    variables = sorted(set().union(*(e.variables for e in exteriors)), key=calculus.order.get)
    rows = sp.Matrix([[e.a.get(v, sp.S.Zero) for v in variables] for e in exteriors])
    kernel = _kernel(rows)
    if kernel is None:
        return _numeric_set(exteriors, variables)
    index = {v: n for n, v in enumerate(variables)}
    return _all_zero(component for e in exteriors for component in _on_kernel(e, kernel, index))


class _TooSlow(Exception):
    pass


def _kernel(rows: sp.Matrix) -> list[sp.Matrix] | None:
    """A basis of the kernel, pivots chosen by decide_zero (rref's default test misses sin² + cos² − 1)."""
    try:
        with time_limit(KERNEL_SECONDS, _TooSlow):
            return rows.nullspace(iszerofunc=lambda e: decide_zero(e).zero)
    except GacliError:
        raise
    except Exception:  # noqa: BLE001 - _TooSlow, or SymPy gave up: points decide
        return None


def _on_kernel(exterior: _Exterior, kernel: list[sp.Matrix], index: dict[str, int]):
    for x, y in itertools.combinations(kernel, 2):
        yield sp.Add(*(c * (x[index[i]] * y[index[j]] - x[index[j]] * y[index[i]])
                       for (i, j), c in exterior.d.items()))


def _numeric_set(exteriors: list[_Exterior], variables: list[str]) -> Decision:
    """The set's test at seeded points: P C_a P = 0, with P the orthogonal projection on D."""
    entries = [c for e in exteriors for c in list(e.a.values()) + list(e.d.values())]
    symbols = set().union(*(as_expr(c).free_symbols for c in entries))
    points = (sample_points(symbols, _NUMERIC_POINTS // 2)
              + sample_points(symbols, _NUMERIC_POINTS // 2, seed=_SEED + 1, signed=True))
    valid = 0
    for point in points:
        with mpmath.workdps(_DIGITS):
            try:
                residual, scale = _projected(exteriors, variables, point)
            except (UndefinedValue, ZeroDivisionError):
                continue
            valid += 1
            if residual > _RELATIVE_TOLERANCE * max(scale, 1):
                return Decision(False, "numeric")
    return Decision(True, "numeric") if valid >= _MIN_VALID_POINTS else Decision(None, "undecided")


def _projected(exteriors: list[_Exterior], variables: list[str], point) -> tuple[mpmath.mpf, mpmath.mpf]:
    """(largest entry of P C_a P, largest entry of C_a) over the constraints a."""
    n = len(variables)
    projection = mpmath.eye(n)
    for row in _orthonormal([[_value(e.a.get(v), point) for v in variables] for e in exteriors]):
        projection -= row.T * row
    residual = scale = mpmath.mpf(0)
    for e in exteriors:
        c = mpmath.matrix(n, n)
        for (i, j), value in e.d.items():
            v = _value(value, point)
            c[variables.index(i), variables.index(j)], c[variables.index(j), variables.index(i)] = v, -v
        r = projection * c * projection
        residual = max([residual] + [abs(r[p, q]) for p in range(n) for q in range(n)])
        scale = max([scale] + [abs(c[p, q]) for p in range(n) for q in range(n)])
    return residual, scale


def _orthonormal(rows: list[list[mpmath.mpf]]) -> list[mpmath.matrix]:
    """Gram-Schmidt, dropping a row that repeats the others (two wheels on one axle)."""
    basis: list[mpmath.matrix] = []
    for values in rows:
        row = mpmath.matrix([values])
        size = mpmath.norm(row)
        for u in basis:
            row -= (row * u.T)[0, 0] * u
        if mpmath.norm(row) > _RELATIVE_TOLERANCE * max(size, 1):
            basis.append(row / mpmath.norm(row))
    return basis


def _value(expr, point) -> mpmath.mpf:
    return mpmath.mpf(0) if expr is None else evaluate(as_expr(expr), point)[0]


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
