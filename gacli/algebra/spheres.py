"""Polynomials read on a sphere Σ x_i² = r²: their remainder by x·x − r².

Euler parameters lie on the unit sphere, and an expression in them may be
read there (the motion never leaves it): a top's m l² (e·e)² is m l², a
squared row length 4 e·e is 4. The remainder of a polynomial by x·x − r²
(x_0² and its higher powers written through r² − x_1² − …) is one normal
form of its values on the sphere. The loader reads a quaternion frame's
moved inertia so (gacli.loader.inertia), the program its rows' squared
lengths and generated code its polynomials (gacli.numeric.spheres names
which spheres a system keeps).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.polys.polyerrors import CoercionFailed, GeneratorsNeeded, PolynomialError


@dataclass(frozen=True)
class Sphere:
    """Σ x_i² = radius² over the coordinates ``symbols`` (radius² free of every coordinate)."""

    symbols: tuple[sp.Symbol, ...]
    radius2: sp.Expr


def remainder_on(expr: sp.Expr, all_spheres: tuple[Sphere, ...]) -> sp.Expr:
    """``expr``'s remainder by each sphere's x·x − radius² where it is a polynomial in x (x_0² and its
    higher powers written through radius² − x_1² − …): a top's m l² (e·e)² is m l² on the sphere."""
    for sphere in all_spheres:
        x = sphere.symbols
        if not expr.free_symbols & set(x) or not expr.is_polynomial(*x):
            continue
        # Functions free of x (a turntable's sin β) as symbols: SymPy reduces over their expressions
        # as coefficients in its slowest domain (600 nodes, 2 s), over symbols in a polynomial ring.
        named = {f: sp.Dummy() for f in sorted(expr.atoms(sp.Function), key=sp.default_sort_key)}
        try:
            reduced = sp.reduced(sp.expand(expr.xreplace(named)), [sp.Add(*(y ** 2 for y in x)) - sphere.radius2], *x)[1]
        except (PolynomialError, CoercionFailed, GeneratorsNeeded):
            continue
        expr = reduced.xreplace({d: f for f, d in named.items()})
    return expr


def read_on(expr: sp.Expr, all_spheres: tuple[Sphere, ...]) -> sp.Expr | None:
    """``expr`` read on the spheres when that leaves none of their coordinates in it (a squared row
    length 4 e·e is 4, (e·e)² is 1); None otherwise."""
    on = remainder_on(expr, all_spheres)
    return None if on.free_symbols & {x for s in all_spheres for x in s.symbols} else on
