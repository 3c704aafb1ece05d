"""A format-1 wheel's rotation read along the axes that do not spin with it (program/despun.py).

The rule is checked by what it must keep: the program built with it agrees
with the chapter's closed forms (an independent derivation) at random
states, for wheels spinning either way, with torques given along the wheel's
own axes both as turned vectors and as fixed ones; and a body that is not
symmetric about an axis, or does not spin about it, is left as it is.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp

from gacli.algebra import symbols as S
from gacli.loader.loading import load, loads
from gacli.mechanics.program.despun import despin
from gacli.model import Form
from test_program import _assert_taken_and_agrees

PHI, THETA = S.value("phi"), S.value("theta")
ROOT = Path(__file__).resolve().parent.parent


def _forms(x, y, z) -> tuple[Form, ...]:
    """Rotation forms from {rate name: coefficient} per component."""
    return tuple(Form(tuple(c.items())) for c in (x, y, z))


def test_a_wheel_on_a_turning_chassis_is_read_without_its_spin():
    wheel = _forms({"theta": -sp.sin(PHI)}, {"phi": sp.S.One}, {"theta": sp.cos(PHI)})
    turn = despin([[1, 0, 0], [0, 2, 0], [0, 0, 1]], wheel, ["theta", "phi"])
    assert (turn.axis, turn.coordinate) == (1, "phi")
    x, y, z = turn.forms(wheel)
    assert (x.coefficients, y.coefficients, z.coefficients) == ((), (("phi", 1),), (("theta", 1),))
    # A torque turning with the wheel is constant along the axes that do not spin.
    assert turn.vector((-3 * sp.sin(PHI), 0, 3 * sp.cos(PHI))) == (0, 0, 3)
    # One fixed in the wheel is turned back: the wheel's x axis, turned by φ about y, read along the
    # axes that do not spin (the chassis'), is (cos φ, 0, −sin φ).
    fixed = turn.vector((sp.S(5), sp.S.Zero, sp.S.Zero))
    assert all(sp.simplify(a - b) == 0 for a, b in zip(fixed, (5 * sp.cos(PHI), 0, -5 * sp.sin(PHI))))


@pytest.mark.parametrize("inertia", [[[1, 0, 0], [0, 2, 0], [0, 0, 3]], [[2, 0, 0], [0, 2, 0], [0, 0, 2]],
                                     [[1, 0, 0.1], [0, 2, 0], [0.1, 0, 1]]], ids=["three", "sphere", "products"])
def test_a_body_without_one_symmetry_axis_is_left_alone(inertia):
    wheel = _forms({"theta": -sp.sin(PHI)}, {"phi": sp.S.One}, {"theta": sp.cos(PHI)})
    assert despin(inertia, wheel, ["theta", "phi"]) is None


def test_a_body_that_does_not_spin_about_its_axis_is_left_alone():
    tilted = _forms({"theta": sp.sin(PHI)}, {"phi": sp.S.One}, {"theta": sp.sin(PHI) * sp.cos(PHI)})
    assert despin([[1, 0, 0], [0, 2, 0], [0, 0, 1]], tilted, ["theta", "phi"]) is None


CART = """
gacli: 1
name: wheel_on_a_turning_cart
parameters: {m: {value: 2}, J: {value: 0.3}, mw: {value: 0.5}, A: {value: 0.01}, C: {value: 0.02},
             r: {value: 0.1}, b: {value: 0.2}, T: {value: 0.4}, K: {value: 0.3}, P: {value: 0.2}}
coordinates: [x, y, theta, phi]
constraints:
  - -sin(theta)*dx + cos(theta)*dy = 0
  - cos(theta)*dx + sin(theta)*dy + b*dtheta = SIGN*r*dphi
bodies:
  cart: {mass: m, position: [x, y, 0], inertia: J, rotation: dtheta}
  wheel:
    mass: mw
    position: [x - b*sin(theta), y + b*cos(theta), 0]
    inertia: [A, C, A]
    rotation: [SIGN*-sin(phi)*dtheta, dphi, SIGN*cos(phi)*dtheta]
loads:
  - {torque: [SIGN*-T*sin(phi), K, SIGN*T*cos(phi)], body: wheel}
  - {torque: [P, 0, 0], body: wheel}
  - {torque: [0, 0, -T], body: cart}
"""


@pytest.mark.parametrize("sign", ["1", "-1"])
def test_the_program_with_the_wheel_read_so_agrees_with_the_closed_forms(sign):
    system = loads(CART.replace("SIGN", f"({sign})"))
    wheel = next(b for b in system.bodies if b.name == "wheel")
    assert despin(wheel.inertia.tolist(), wheel.rotation, [c.name for c in system.coordinates]) is not None
    _assert_taken_and_agrees(system)


def test_a_symmetric_top_is_read_along_the_axes_that_do_not_spin():
    # Its transverse ω along those axes has two components (θ̇ and φ̇ sin θ): the rate of the axes,
    # σ ψ̇ e × ω, is in α, and a wrong sign there would not agree.
    system = load(ROOT / "systems" / "spinning_top.yaml")
    top = system.bodies[0]
    turn = despin(top.inertia.tolist(), top.rotation, [c.name for c in system.coordinates])
    assert turn is not None and turn.axis == 2
    _assert_taken_and_agrees(system)
