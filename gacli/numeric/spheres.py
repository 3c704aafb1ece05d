"""Coordinates that the system itself keeps on a sphere: Euler parameters, e·e = 1.

A quaternion frame's parameters lie on the unit sphere by construction, and a
file without frames states the same as a holonomic constraint
``e0**2 + e1**2 + e2**2 + e3**2 = 1`` (eq. 14.1 in its finite form). The
motion never leaves that sphere, so an expression may be read on it: the
rows of body rates 2 G(e) ė and of the norm are orthogonal with squared
length 4 e·e, which is 4 there, and Kane's explicit ½ Eᵀ ω assumes the same.
This module names the spheres once, for every place that reads on them
(gacli.algebra.spheres): the numeric point that ranks the rows
(gacli.mechanics.rates), the program's solver (gacli.mechanics.program.build),
generated code (gacli.mechanics.code), and the random states that verify and
the tests draw: the equations hold where the motion is, on the sphere.

A Pfaffian row e·de = 0 alone keeps e·e constant, not equal to 1, so it
names no sphere (docs/program.md, "Divisions in generated code").
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.graph import is_small
from gacli.algebra.spheres import Sphere
from gacli.model import System


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


def on_spheres(point: dict, system: System, digits: int = 20) -> dict:
    """``point`` with each sphere's coordinates scaled onto it (to ``digits``), where the rows hold: a
    ball in a quaternion frame has a rolling row along the normal that vanishes only there (its
    centre's height is r whatever the attitude), and counted off it, it took a degree of freedom."""
    return scaled_onto(point, spheres(system), digits)


def scaled_onto(point: dict, kept: tuple[Sphere, ...], digits: int = 20) -> dict:
    """:func:`on_spheres` for spheres already named; values of any numeric type in, SymPy Floats out for
    the coordinates moved."""
    def number(v) -> sp.Expr:  # a value of the point: a SymPy number, or a float or mpf made one
        return v if isinstance(v, sp.Basic) else sp.Float(v, digits)

    for sphere in kept:
        if not all(x in point for x in sphere.symbols):
            continue
        radius2 = sphere.radius2.xreplace({k: number(point[k]) for k in sphere.radius2.free_symbols if k in point})
        if not (radius2.is_number and radius2.is_positive):  # no real point on it: nothing to scale
            continue
        x = [number(point[y]) for y in sphere.symbols]
        norm = sp.sqrt(sp.Add(*(c ** 2 for c in x)) / radius2)
        point.update({y: sp.Float(c / norm, digits) for y, c in zip(sphere.symbols, x)})
    return point
