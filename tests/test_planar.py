"""A planar file without frames read as the frames its angle sums turn (program/planar.py)."""

from __future__ import annotations

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


def test_a_pendulum_hangs_along_its_frame_and_an_ellipse_is_not_turned():
    hanging = planar_frames(loads(PENDULUM % ("l*sin(q)", "-l*cos(q)", "-l*cos(q)"), "p.yaml"))
    assert hanging is None  # one frame alone gains nothing over the positions' derivatives
    ellipse = loads(PENDULUM % ("a*cos(q) + b*cos(2*q)", "b*sin(q)", "b*sin(q)"), "e.yaml")
    assert planar_frames(ellipse) is None
    out_of_plane = loads(PENDULUM % ("l*sin(q)", "0, l*cos(q)", "l*cos(q)"), "z.yaml")
    assert planar_frames(out_of_plane) is None
