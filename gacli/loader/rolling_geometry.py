"""Rolling shapes, and declarations whose geometry is degenerate, refused before their rows are built.

A wheel of radius 0, a zero axle or an axle along the plane's normal (a
wheel lying flat) makes :func:`gacli.loader.frames.contact_point` divide by zero
or put the contact at the centre: the rolling rows then vanish or become
``zoo`` and the constraints are lost without a word. Each function returns
the message of the problem, or "" when there is none.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import sympy as sp

from gacli.loader.frames import rotate
from gacli.numeric import UndefinedValue, evaluate, sample_points


NOT_POSITIVE = "the radius must be positive: with a radius of 0 or less there is no contact point below the centre"


def radius_problem(radius: sp.Expr, known: Mapping[sp.Symbol, float]) -> str:
    """A radius that is not positive: a number <= 0, an expression SymPy knows is, or one
    whose parameters' values (``known``) make it so."""
    if radius.is_nonpositive or radius.is_extended_real is False:
        return NOT_POSITIVE
    if not radius.free_symbols <= set(known):
        return ""
    try:
        value = evaluate(radius, known)[0]
    except UndefinedValue:
        return "the radius has no real value"
    return "" if value > 0 else NOT_POSITIVE


def axle_problem(local: sp.Matrix, dcm: sp.Matrix, known: Mapping[sp.Symbol, float]) -> str:
    """A zero axle, or one along the plane's normal at every configuration tried."""
    if _vanishes_everywhere(local.dot(local), known):
        if all(c == 0 for c in local):
            return "the axle is the zero vector: it gives no direction"
        # Not zero, only too short to tell its direction from rounding (1e-7 along x, say).
        return ("the axle is too short to give a direction (its length squared is under 1e-12); "
                "write its direction with components of order one, e.g. [0, 1, 0]")
    # As lists, not a Matrix product: the product's entries are only evaluated here, and a Matrix
    # product of a fork's direction cosines was a tenth of a bicycle's loading.
    world = rotate(dcm.tolist(), list(local))
    if _vanishes_everywhere(world[0] ** 2 + world[1] ** 2, known):
        return ("the axle is along the plane's normal: the wheel lies flat on the plane "
                "and has no single contact point")
    return ""


def _vanishes_everywhere(expr: sp.Expr, known: Mapping[sp.Symbol, float]) -> bool:
    """Zero (exactly, or within 1e-12 at three generic points, parameters at their values);
    cheap, never simplify()."""
    if expr == 0:
        return True
    free = expr.free_symbols - set(known)
    return all(_near_zero(expr, {**known, **point}) for point in sample_points(free, 3))


def _near_zero(expr: sp.Expr, point) -> bool:
    try:
        value, scale = evaluate(expr, point)
    except UndefinedValue:
        return False
    return abs(value) <= 1e-12 * max(1, scale)


@dataclass(frozen=True)
class Shape:
    """A rolling body's shape as parsed: a sphere (radius), a wheel (radius, axle), a torus
    (radius, axle, tube) or an ellipsoid (semi-axes along the body's axes)."""

    radius: sp.Expr | None
    axle: sp.ImmutableMatrix | None = None  # in the body's axes, as written
    tube: sp.Expr = sp.S.Zero
    semi_axes: tuple[sp.Expr, sp.Expr, sp.Expr] | None = None


def size_problem(value: sp.Expr, what: str, known: Mapping[sp.Symbol, float]) -> str:
    """:func:`radius_problem` for any length that must be positive (a semi-axis, say)."""
    problem = radius_problem(value, known)
    if problem == NOT_POSITIVE:
        return f"{what} must be positive: with one of 0 or less the body has no single contact point"
    return problem.replace("the radius", what)


def tube_problem(tube: sp.Expr, radius: sp.Expr, known: Mapping[sp.Symbol, float]) -> str:
    """A negative tube, or one as large as the wheel (the torus would close over its axle and
    the contact below the centre is no longer on the outer surface)."""
    if tube.is_negative or tube.is_extended_real is False:
        return "the tube radius must be 0 (a thin wheel) or positive"
    if not (tube.free_symbols | radius.free_symbols) <= set(known):
        return ""
    try:
        rho, r = float(evaluate(tube, known)[0]), float(evaluate(radius, known)[0])
    except UndefinedValue:
        return "the tube radius has no real value"
    if rho < 0:
        return "the tube radius must be 0 (a thin wheel) or positive"
    if rho >= r:
        return (f"the tube radius ({rho:g}) must be smaller than the wheel's radius ({r:g}), "
                "the radius of the circle of the tube's centres")
    return ""


def ellipsoid_lift(normal: Sequence[sp.Expr], semi_axes: Sequence[sp.Expr]) -> sp.Matrix:
    """The geometric centre from the contact, along the body's axes: E n / √(nᵀ E n),
    E = diag(a², b², c²), n the plane's normal along the body's axes (the outward normal at
    the contact is −n). A sphere's (a = b = c = r) is r n."""
    if semi_axes[0] == semi_axes[1] == semi_axes[2]:
        # A sphere: √(r² (n·n)) is |r| once n·n = 1 is seen, and |r| evaluates nowhere numerically.
        return sp.Matrix([semi_axes[0] * x for x in normal])
    squares = [s ** 2 for s in semi_axes]
    height = sp.sqrt(sp.Add(*(e * x ** 2 for e, x in zip(squares, normal))))
    return sp.Matrix([e * x / height for e, x in zip(squares, normal)])


def ellipsoid_contact(dcm: sp.Matrix, semi_axes: Sequence[sp.Expr]) -> sp.Matrix:
    """The contact from the geometric centre along the plane's axes, ``dcm`` the body's axes
    in the plane's: −R E n_b / √(n_bᵀ E n_b), n_b = Rᵀ z the plane's normal in the body's axes."""
    normal = [dcm[2, j] for j in range(3)]
    return -(dcm * ellipsoid_lift(normal, semi_axes))
