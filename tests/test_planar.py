"""A planar file without frames read as the frames its angle sums turn (program/planar.py)."""

from __future__ import annotations

import pytest
import sympy as sp
from conftest import ROOT

from gacli.frame_model import INERTIAL
from gacli.loader.loading import load, loads
from gacli.mechanics.program.planar import planar_frames

CHAIN = ROOT / "benchmarks" / "kane_set" / "variants" / "chains" / "chain4_format1.yaml"

PENDULUM = """
gacli: 1
name: pendulum
parameters: [m, l, a, b, g]
coordinates: [q]
bodies:
  bob: {mass: m, position: [%s, %s]}
potential: m*g*(%s)
"""


def test_a_chain_of_relative_angles_is_a_chain_of_frames_sharing_its_joints():
    model = planar_frames(load(CHAIN))
    by_name = {e.name: e for e in model.edges}
    angles = [str(e.angle) for e in model.edges]
    assert angles == ["q1", "q2", "q3", "q4"], angles  # each frame turned from the one before by one joint
    assert [e.parent for e in model.edges] == [INERTIAL] + [e.name for e in model.edges[:-1]]
    assert all(e.axis == 2 for e in by_name.values())
    # Four bodies, four centres; the joints l1, l1 + l2 ... are links the later centres share.
    links = {p.name: p for p in model.points}
    assert len(links) == 7
    for i, body in enumerate(model.bodies[1:], start=1):
        joint = links[links[body.point].parent]
        assert str(joint.components[0]) == f"l{i}" and joint.frame == model.edges[i - 1].name
    assert [b.frame for b in model.bodies] == [e.name for e in model.edges]


def _composed(model, point: str) -> tuple:
    """The N position of a point link, its links turned back through the frames they are along."""
    edges = {e.name: e for e in model.edges}
    links = {p.name: p for p in model.points}

    def turned(frame: str) -> sp.Expr:
        return sp.S.Zero if frame == INERTIAL else edges[frame].angle + turned(edges[frame].parent)

    x = y = sp.S.Zero
    while point is not None:
        link = links[point]
        phi = turned(link.frame)
        u, v, _ = link.components
        x, y = x + u * sp.cos(phi) - v * sp.sin(phi), y + u * sp.sin(phi) + v * sp.cos(phi)
        point = link.parent
    return x, y


@pytest.mark.parametrize("x, y", [
    ("l1*cos(q1) + l2*cos(q1 + q2)", "l1*sin(q1) + l2*sin(q2 + q1)"),
    ("l1*cos(q1) + l2*(cos(q1)*cos(q2) - sin(q1)*sin(q2))", "l1*sin(q1) + l2*(sin(q1)*cos(q2) + cos(q1)*sin(q2))"),
    ("l1*cos(q1 + pi/6) - b*sin(q1 + q2 + pi/6)", "l1*sin(pi/6 + q1) + b*cos(q2 + q1 + pi/6)"),
    ("a*cos(q1) + b*cos(2*q2)", "b*sin(q1) - a*sin(q1 - q2)"),
    ("x + l1*sin(q1)", "-l1*cos(q1) + l2*sin(q1 - q2)"),
])
def test_each_position_is_the_sum_of_its_links_turned_by_their_frames(x, y):
    text = TWO_BODIES % (x, y)
    system = loads(text, "t.yaml")
    model = planar_frames(system)
    assert model is not None
    body = next(b for b in model.bodies if b.name == "tip")
    position = next(b for b in system.bodies if b.name == "tip").position
    for written, composed in zip(position, _composed(model, body.point)):
        assert sp.simplify(sp.expand_trig(written - composed)) == 0


TWO_BODIES = """
gacli: 1
name: two
parameters: [m, l1, l2, a, b, g]
coordinates: [x, q1, q2]
bodies:
  cart: {mass: m, position: [x, 0]}
  bar: {mass: m, position: [l1*cos(q1), l1*sin(q1)], inertia: m*l1**2/12, rotation: dq1}
  tip: {mass: m, position: ["%s", "%s"]}
potential: m*g*x
"""


def test_what_is_not_planar_or_turns_by_part_of_an_angle_is_not_read():
    hanging = planar_frames(loads(PENDULUM % ("l*sin(q)", "-l*cos(q)", "-l*cos(q)"), "p.yaml"))
    assert hanging is None  # one frame alone gains nothing over the positions' derivatives
    half = loads(PENDULUM % ("a*cos(2*q) + b*cos(q/2)", "b*sin(q)", "b*sin(q)"), "e.yaml")
    assert planar_frames(half) is None
    out_of_plane = loads(PENDULUM % ("l*sin(q)", "0, l*cos(q)", "l*cos(q)"), "z.yaml")
    assert planar_frames(out_of_plane) is None
