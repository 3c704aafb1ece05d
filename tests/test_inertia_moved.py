"""Inertia about any point and in any frame (issue #29, item 5): the parallel-axis theorem and a turn, by the textbook.

A uniform rod of mass m and length L has moments m L²/3 about axes through
its end perpendicular to it and m L²/12 through its centre; a body's
moments in a frame turned a quarter turn about z are its x and y moments
swapped. A rod pendulum's mass matrix about its pivot is m L²/3.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp

from gacli.errors import SystemFileError
from gacli.loader.loading import load, loads
from gacli.mechanics.equations import derive

FILE = Path(__file__).resolve().parent / "lines" / "inertia_moved.yaml"
TEXT = FILE.read_text(encoding="utf-8")
m, L, A, B, C = sp.symbols("m L A B C", real=True)


def test_the_rod_about_its_end_and_the_turned_disc_reach_their_centres_by_the_textbook():
    bodies = {b.name: b for b in load(FILE).bodies}
    assert sp.simplify(bodies["rod"].inertia - sp.diag(m * L ** 2 / 12, 0, m * L ** 2 / 12)) == sp.zeros(3)
    assert sp.simplify(bodies["disc"].inertia - sp.diag(B, A, C)) == sp.zeros(3)


def test_the_pendulum_about_its_pivot_has_mass_m_l_squared_over_three():
    d = derive(load(FILE))
    th = d.independent.index("th")
    assert sp.simplify(d.mass_matrix[th, th] - m * L ** 2 / 3) == 0


@pytest.mark.parametrize("old, new, message", [
    ("inertia: [A, B, C], inertia_in: turned", "inertia: [A, B, 5], inertia_in: turned", "triangle inequality"),
    ("inertia: [m*L**2/3, 0, m*L**2/3]", "inertia: [m*L**2/3, 0, m*L**2/30]", "negative principal moment"),
    ("inertia_in: turned", "inertia_in: rod", "turns relative to the body's frame"),
    ("inertia_in: turned", "inertia_in: trned", "'trned' is not a frame"),
    ("inertia_about: top", "inertia_about: moving", "not fixed in the body"),
    ("position: centre, frame: rod, inertia: [m*L**2/3, 0, m*L**2/3], inertia_about: top",
     "position: centre, inertia: m*L**2/3, rotation: dth, inertia_about: top", "needs a body with a 'frame'"),
])
def test_an_inertia_no_body_has_or_that_cannot_be_carried_is_a_located_error(old, new, message):
    text = TEXT.replace("  centre: {rod: [0, -L/2, 0]}\n", "  centre: {rod: [0, -L/2, 0]}\n  moving: {disc: [0, 1, 0]}\n")
    assert old in text
    with pytest.raises(SystemFileError) as caught:
        loads(text.replace(old, new))
    assert message in str(caught.value) and caught.value.diagnostics[0].location.line > 1


QUATERNION_TOP = """
gacli: 1
name: quaternion_top_about
parameters: [m, g, l, A0, B0, C]
coordinates: [q0, q1, q2, q3]
quasi_coordinates: [w1, w2, w3]
independent: [w1, w2, w3]
frames:
  top: {quaternion: [q0, q1, q2, q3], rates: [w1, w2, w3]}
  cad: {parent: top, rotations: [[z, pi/2]]}
points:
  pivot: {N: [0, 0, 0]}
  G: {from: pivot, top: [0, 0, l]}
bodies:
  top: {mass: m, position: G, frame: top, inertia: [B0, A0, C], inertia_about: pivot, inertia_in: cad}
loads:
  - {force: {N: [0, 0, -m*g]}, at: G}
"""


def test_a_quaternion_frame_body_takes_its_inertia_about_a_point_and_in_a_frame_fixed_in_it():
    # Its turns are homogeneous quadratics in e: C_Bᵀ C_B is (e·e)² E, the identity on the unit
    # sphere, and the loader reduces by it (it refused both as "moves" and "turns" before).
    m_, l_, A0, B0 = sp.symbols("m l A0 B0", real=True)
    (top,) = loads(QUATERNION_TOP).bodies
    expected = sp.diag(A0 - m_ * l_ ** 2, B0 - m_ * l_ ** 2, C)
    assert sp.simplify(top.inertia - expected) == sp.zeros(3)
