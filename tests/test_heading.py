"""A file without frames formed along the heading its stated rows turn with (program/heading.py).

A cart whose rows are stated in N's axes (cos θ ẋ + sin θ ẏ = r φ̇, −sin θ ẋ + cos θ ẏ = 0)
is solved along its heading (solve.turned_columns); its points are then formed along the
heading too. The program built so must agree with the chapter's closed forms (an independent
derivation) at random states: with a hitch off the pair's point, a force along N at a point
off it (turned back as the point is), a force that holds the state, and rows written with
either sense of the heading.
"""

from __future__ import annotations

import pytest

from gacli.loader.loading import loads
from gacli.mechanics.program.build import _program, independent_rates
from test_program import TOLERANCE, _closed, _relative, _states, run
from gacli.mechanics.equations import derive

CART = """
gacli: 1
name: towed_cart
parameters: {m: {value: 2}, J: {value: 0.3}, mt: {value: 0.7}, Jt: {value: 0.05}, r: {value: 0.1},
             d: {value: 0.4}, a: {value: 0.25}, k: {value: 0.6}, F: {value: 1.3}}
coordinates: [x, y, theta, phi, psi]
independent: [phi, theta, psi]
constraints:
  - cos(theta)*dx + sin(theta)*dy = r*dphi
  - SIDE
bodies:
  cart: {mass: m, position: [x + a*cos(theta), y + a*sin(theta), 0], inertia: J, rotation: dtheta}
  trailer:
    mass: mt
    position: [x - d*cos(theta) - d*cos(psi), y - d*sin(theta) - d*sin(psi), 0]
    inertia: Jt
    rotation: dpsi
loads:
  - {force: [F, -k*dot(x), 0], at: [x + a*cos(theta), y + a*sin(theta), 0]}
  - {force: [0, 0, -9.81*m], at: cart}
"""


@pytest.mark.parametrize("side", ["-sin(theta)*dx + cos(theta)*dy = 0", "sin(theta)*dx - cos(theta)*dy = 0"],
                         ids=["left", "right"])
def test_a_cart_formed_along_its_heading_agrees_with_the_closed_forms(side):
    system = loads(CART.replace("SIDE", side))
    program = _program(system, independent_rates(system), None, False, columns=True)
    assert program is not None  # its rows turn with θ on (ẋ, ẏ): the heading is found
    derivation = derive(system)
    states = _states(system, derivation.speeds)
    for ours, theirs in zip(run(program, states), _closed(derivation, states)):
        assert _relative(ours, theirs) < TOLERANCE
