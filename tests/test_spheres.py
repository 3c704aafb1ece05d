"""The spheres a system keeps its coordinates on (gacli.numeric.spheres), and code read on them."""

from __future__ import annotations

import sympy as sp

from gacli.loader.loading import loads
from gacli.algebra.spheres import remainder_on
from gacli.numeric.spheres import spheres

FREE_BODY = """
gacli: 1
name: free_body
parameters:
  m: {value: 2}
  A: {value: 1}
  B: {value: 2}
  C: {value: 3}
coordinates: [x, y, z, e0, e1, e2, e3]
quasi_coordinates:
  w1: 2*(-e1*de0 + e0*de1 + e3*de2 - e2*de3)
  w2: 2*(-e2*de0 - e3*de1 + e0*de2 + e1*de3)
  w3: 2*(-e3*de0 + e2*de1 - e1*de2 + e0*de3)
constraints:
  - %s
independent: [x, y, z, w1, w2, w3]
bodies:
  b: {mass: m, position: [x, y, z], inertia: [A, B, C], rotation: [dw1, dw2, dw3]}
"""


def _system(constraint: str):
    return loads(FREE_BODY % constraint, "free_body.yaml")


def test_a_stated_unit_norm_is_a_sphere_and_its_differential_alone_is_not():
    (sphere,) = spheres(_system("e0**2 + e1**2 + e2**2 + e3**2 = 1"))
    assert sorted(map(str, sphere.symbols)) == ["e0", "e1", "e2", "e3"] and sphere.radius2 == 1
    (sphere,) = spheres(_system("2*e0**2 + 2*e1**2 + 2*e2**2 + 2*e3**2 - 2"))
    assert sphere.radius2 == 1
    # e·de = 0 keeps e·e constant, not 1: nothing may be read on a sphere.
    assert spheres(_system("e0*de0 + e1*de1 + e2*de2 + e3*de3 = 0")) == ()


def test_code_of_euler_parameters_written_out_divides_by_nothing():
    import gacli

    derivation = gacli.derive(_system("e0**2 + e1**2 + e2**2 + e3**2 = 1"))
    code = derivation.code
    for _, rate in code.kinematic_equations:
        assert sp.fraction(sp.together(rate))[1].is_number, rate


def test_a_remainder_is_taken_only_where_the_expression_is_a_polynomial_in_the_sphere():
    x, y, L, th = sp.symbols("x y L th")
    (sphere,) = spheres(_system("e0**2 + e1**2 + e2**2 + e3**2 = 1"))
    e0, e1, e2, e3 = sphere.symbols
    assert remainder_on(L * (e0**2 + e1**2 + e2**2 + e3**2) ** 2, (sphere,)) == L
    assert remainder_on(sp.cos(e0) * x, (sphere,)) == sp.cos(e0) * x
    assert remainder_on(x * sp.cos(th) + y, (sphere,)) == x * sp.cos(th) + y
