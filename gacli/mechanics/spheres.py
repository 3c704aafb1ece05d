"""Coordinates that the system itself keeps on a sphere: Euler parameters, e·e = 1.

A quaternion frame's parameters lie on the unit sphere by construction, and a
file without frames states the same as a holonomic constraint
``e0**2 + e1**2 + e2**2 + e3**2 = 1`` (eq. 14.1 in its finite form). The
motion never leaves that sphere, so an expression may be read on it: the
rows of body rates 2 G(e) ė and of the norm are orthogonal with squared
length 4 e·e, which is 4 there, and Kane's explicit ½ Eᵀ ω assumes the same.
This module names the spheres once, for every place that reads on them: the
numeric point that ranks the rows (gacli.mechanics.rates), the program's
solver (gacli.mechanics.program.build) and the tests' random states.

A Pfaffian row e·de = 0 alone keeps e·e constant, not equal to 1, so it
names no sphere (docs/program.md, "Divisions in generated code").
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.polys.polyerrors import CoercionFailed, GeneratorsNeeded, PolynomialError

from gacli.algebra import symbols as S
from gacli.algebra.graph import is_small
from gacli.model import System


@dataclass(frozen=True)
class Sphere:
    """Σ x_i² = radius² over the coordinates ``symbols`` (radius² free of every coordinate)."""

    symbols: tuple[sp.Symbol, ...]
    radius2: sp.Expr


def spheres(system: System) -> tuple[Sphere, ...]:
    """The quaternion frames' unit spheres, then the spheres the file's constraints state."""
    out = [Sphere(tuple(edge.quaternion), sp.S.One)
           for edge in (system.frames.edges if system.frames is not None else ())
           if edge.quaternion is not None and all(x.is_Symbol for x in edge.quaternion)]
    coordinates = {S.value(c.name) for c in system.coordinates}
    for c in system.constraints:
        if c.relation is not None and c.rates is None and not c.derived:
            sphere = _stated(c.relation, coordinates)  # a frame's own unit norm is its sphere already
            if sphere is not None and set(sphere.symbols) not in [set(s.symbols) for s in out]:
                out.append(sphere)
    return tuple(out)


def _stated(relation: sp.Expr, coordinates: set) -> Sphere | None:
    """a Σ x_i² + b = 0 with a, b constants and b ≠ 0, as a sphere; None for any other relation (one
    too large, or with a power past 2, is not expanded to see)."""
    if not is_small(relation, 200) or any(p.is_Pow and not (p.exp.is_Integer and abs(p.exp) <= 2)
                                          for p in sp.preorder_traversal(relation)):
        return None
    f = sp.expand(relation)
    moving = sorted(f.free_symbols & coordinates, key=str)
    if len(moving) < 2 or S.T in f.free_symbols or not f.is_polynomial(*moving):
        return None
    poly = sp.Poly(f, *moving)
    b = poly.coeff_monomial(1)
    squares = [poly.coeff_monomial(x ** 2) for x in moving]
    a = squares[0]
    if b == 0 or any(s != a for s in squares) or len(poly.terms()) != len(moving) + 1:
        return None
    return Sphere(tuple(moving), sp.cancel(-b / a))


def on_spheres(point: dict, system: System) -> dict:
    """``point`` with each sphere's coordinates scaled onto it, where the rows hold: a ball in a
    quaternion frame has a rolling row along the normal that vanishes only there (its centre's height
    is r whatever the attitude), and counted off it, it took a degree of freedom."""
    for sphere in spheres(system):
        if not all(x in point for x in sphere.symbols):
            continue
        radius2 = sphere.radius2.xreplace(point)
        if not (radius2.is_number and radius2.is_positive):  # no real point on it: nothing to scale
            continue
        norm = sp.sqrt(sum(point[x] ** 2 for x in sphere.symbols) / radius2)
        point.update({x: sp.Float(point[x] / norm, 20) for x in sphere.symbols})
    return point


def read_on(expr: sp.Expr, all_spheres: tuple[Sphere, ...]) -> sp.Expr:
    """``expr`` (expanded) with x_0² written radius² − x_1² − …, when that leaves none of a sphere's
    coordinates in it (a squared row length 4 e·e becomes 4); ``expr`` itself otherwise."""
    closed = sp.expand(expr)
    for sphere in all_spheres:
        x = sphere.symbols
        on = sp.expand(closed.xreplace({x[0] ** 2: sphere.radius2 - sp.Add(*(y ** 2 for y in x[1:]))}))
        if not on.free_symbols & set(x):
            return on
    on = remainder_on(closed, all_spheres)  # (e·e)², a translation's rows along the body's axes
    return on if not on.free_symbols & {x for s in all_spheres for x in s.symbols} else expr


def remainder_on(expr: sp.Expr, all_spheres: tuple[Sphere, ...]) -> sp.Expr:
    """``expr``'s remainder by each sphere's x·x − radius² where it is a polynomial in x (x_0² and its
    higher powers written through radius² − x_1² − …): a top's m l² (e·e)² is m l² on the sphere."""
    for sphere in all_spheres:
        x = sphere.symbols
        if not expr.free_symbols & set(x) or not expr.is_polynomial(*x):
            continue
        try:
            expr = sp.reduced(sp.expand(expr), [sp.Add(*(y ** 2 for y in x)) - sphere.radius2], *x)[1]
        except (PolynomialError, CoercionFailed, GeneratorsNeeded):
            continue
    return expr

