"""The program on the vocabulary it took last (gacli.mechanics.program: frames, motion, contacts, forms).

A frame turned by a prescribed angle (a turntable), a point moved with time
(a plate's origin), a body rolling on the plane of such a frame, loads that
hold time, and constraints nonlinear in the rates: the program's q̇, M and
F agree with the closed forms (the chapter's route,
gacli.mechanics.equations) at random states and at random times, not only
at t = 0, where a term in sin(Ω t) would vanish unseen.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from gacli.algebra import symbols as S
from gacli.loader.loading import load, loads
from gacli.mechanics.equations import derive
from gacli.mechanics.program import build_program, unsupported

from test_program import _closed, _relative, _states, run

ROOT = Path(__file__).resolve().parent.parent
TOLERANCE = 1e-9

# A wheel with its mass off the axle, rolling on a table that a free function turns and another
# lifts (neither has a value: generated code takes them and their rates as arguments), the table
# also tilted by a constant angle.
DRIVEN_TABLE = """\
gacli: 1
name: driven_table
parameters:
  m: {value: 1}
  a: {value: 0.1}
  g: {value: 9.81}
  A: {value: 0.002}
  B: {value: 0.003}
  C: {value: 0.0025}
  h: {value: 0.05}
functions:
  alpha: {description: table angle}
  s: {description: table lift}
coordinates: [x, y, yaw, lean, spin]
independent: [yaw, lean, spin]
frames:
  table: {rotations: [[z, alpha], [x, 0.2]], origin: lift}
  heading: {parent: table, rotations: [[z, yaw]]}
  leaned: {parent: heading, rotations: [[x, lean]]}
  disc: {parent: leaned, rotations: [[y, spin]]}
points:
  lift: {N: [0.1*s, 0.05, s]}
  contact: {from: lift, table: [x, y, 0]}
  centre: {from: contact, leaned: [0, 0, a]}
  heavy: {from: centre, disc: [h, 0, 0]}
bodies:
  disc: {mass: m, position: heavy, frame: disc, inertia: [A, B, C]}
rolling:
  - {body: disc, radius: a, axle: [0, 1, 0], on: table, centre: {disc: [-h, 0, 0]}}
loads:
  - {force: {N: [0, 0, -m*g]}, at: disc}
"""

# An ellipsoid on a turntable whose angle is not linear in t; its height is a coordinate that
# the contact's normal row holds.
EGG_ON_TABLE = """\
gacli: 1
name: egg_on_table
parameters:
  m: {value: 1}
  g: {value: 9.81}
  W: {value: 1.3}
coordinates: [x, y, z, phi, theta, psi]
independent: [phi, theta, psi]
frames:
  table: {rotations: [[z, W*t + 0.1*t**2]]}
  body: {parent: table, sequence: ZXZ, angles: [phi, theta, psi]}
points:
  centre: {table: [x, y, z]}
bodies:
  egg: {mass: m, position: centre, frame: body, inertia: [0.02, 0.03, 0.04]}
rolling:
  - {body: egg, semi_axes: [0.3, 0.2, 0.1], on: table}
loads:
  - {force: {N: [0, 0, -m*g]}, at: egg}
"""

# A rolling disc pushed by a force that a function of time gives, twisted by a free function, and
# pulled by a force written from a point (its position joins the force's components).
PUSHED_DISC = """\
gacli: 1
name: pushed_disc
parameters:
  m: {value: 1}
  a: {value: 0.1}
  g: {value: 9.81}
  A: {value: 0.5}
  w: {value: 3}
functions:
  push: {value: "A*cos(w*t)"}
  twist: {}
coordinates: [x, y, yaw, lean, spin]
independent: [yaw, lean, spin]
frames:
  heading: {rotations: [[z, yaw]]}
  leaned: {parent: heading, rotations: [[x, lean]]}
  disc: {parent: leaned, rotations: [[y, spin]]}
points:
  contact: {N: [x, y, 0]}
  centre: {from: contact, leaned: [0, 0, a]}
bodies:
  disc: {mass: m, position: centre, frame: disc, inertia: ["m*a**2/4", "m*a**2/2", "m*a**2/4"]}
rolling:
  - {body: disc, radius: a, axle: [0, 1, 0]}
loads:
  - {force: {N: [push, 0, -m*g]}, at: disc}
  - {torque: {leaned: [0, twist*sin(t), 0]}, body: disc}
  - {force: {from: centre, leaned: [0, 0, 1]}, at: centre}
"""

FILES = ["tests/frames/unbalanced.yaml", "tests/frames/disk_tilted_plane.yaml", "systems/sphere_on_tilted_plane.yaml",
         "benchmarks/corpus/offset_coin_turntable.yaml", "benchmarks/corpus/ball_and_plate.yaml"]


def _agrees_at_random_times(system) -> None:
    program = build_program(system)
    assert program is not None, unsupported(system)
    derivation = derive(system)
    assert program.independent == derivation.independent
    states = _states(system, derivation.speeds)
    for state, t in zip(states, np.random.default_rng(7).uniform(0.2, 3.0, len(states))):
        state[S.T] = float(t)
    for ours, theirs in zip(run(program, states), _closed(derivation, states)):
        assert _relative(ours, theirs) < TOLERANCE


@pytest.mark.parametrize("name", FILES)
def test_moving_frames_and_planes_agree_at_any_time(name):
    _agrees_at_random_times(load(ROOT / name))


@pytest.mark.parametrize("text", [DRIVEN_TABLE, EGG_ON_TABLE, PUSHED_DISC], ids=["driven_table", "egg_on_table",
                                                                                "pushed_disc"])
def test_free_functions_curved_angles_and_loads_of_time(text):
    _agrees_at_random_times(loads(text))


@pytest.mark.parametrize("angle", ["t*yaw", "yaw + 0.3*sin(lean)", "yaw*lean"])
def test_angles_not_linear_in_the_coordinates(angle):
    # θ̈ with q̈ = 0 is then Σ ∂²θ/∂q∂q' q̇ q̇' + 2 Σ ∂²θ/∂q∂t q̇ + θ_tt (frames.held_acceleration).
    _agrees_at_random_times(loads(DRIVEN_TABLE.replace("[z, yaw]", f"[z, {angle}]")))


# The relations of tests/test_nonlinear.py (Appell-Hamel's particle, and rheonomic and implicit
# writings of it): the program solves the linearized row for ż with the relation's own solution
# in its coefficients (forms._solved).
RELATION_HEADER = """\
gacli: 1
name: ah
parameters: {m: {value: 1}, g: {value: 9.81}, c: {value: 0.5}, v: {value: 0.3}}
coordinates: [x, y, z]
bodies:
  p: {mass: m, position: [x, y, z]}
potential: m*g*z
constraints:
  - """


@pytest.mark.parametrize("relation", [
    "dz = -c*sqrt(dx**2 + dy**2)",
    "dot(z) = -c*sqrt(dot(x)**2 + dot(y)**2) + v*sin(t)",
    "c*sqrt(dot(x)**2 + dot(y)**2) + 2*dot(z) + x*dot(x) = 0",
])
def test_constraints_nonlinear_in_the_rates(relation):
    _agrees_at_random_times(loads(RELATION_HEADER + relation + "\n"))


def test_a_relation_holding_another_dependent_rate_is_refused():
    text = RELATION_HEADER.replace("[x, y, z]", "[x, y, z, w]", 1) + "dot(z) = -c*sqrt(dot(x)**2 + dot(w)**2)\n  - dw = y*dx\n"
    text = text.replace("coordinates: [x, y, z, w]", "coordinates: [x, y, z, w]\nindependent: [x, y]")
    assert "holds the dependent rate 'w'" in unsupported(loads(text))


QUATERNION_TOP = (ROOT / "benchmarks" / "kane_set" / "quaternion_frame_top.yaml").read_text(encoding="utf-8")


@pytest.mark.parametrize("inertia", ["[A, A, C]", "[A, A, A]"])
def test_a_quaternion_frame_on_a_turning_arm(inertia):
    # A frame turned by Euler parameters from a frame that turns: the units never carry an inertia
    # across the quaternion's edge (about no one axis, never constant), symmetric or not.
    text = QUATERNION_TOP.replace("coordinates: [q0, q1, q2, q3]", "coordinates: [q0, q1, q2, q3, a]")
    text = text.replace("independent: [w_1, w_2, w_3]", "independent: [w_1, w_2, w_3, a]")
    text = text.replace("frames:\n  top: {", "frames:\n  arm: {rotations: [[z, a], [x, 0.3]]}\n  top: {parent: arm, ")
    text = text.replace("inertia: [A, A, C]", f"inertia: {inertia}")
    text = text.replace("bodies:\n", "bodies:\n  arm: {mass: m, position: {arm: [0.1, 0, 0]}, frame: arm, inertia: [A, C, A]}\n")
    _agrees_at_random_times(loads(text))


_FREE_POSITIONS = {
    "rod_turned_by_f": "[x*cos(f), x*sin(f)]",  # a bead on a rod the function turns: m ẍ − m ḟ² x = 0
    "support_moved_by_f": "[x + f, 0]",
    "scaled_by_f": "[f*x, x**2]",
}


@pytest.mark.parametrize("position", _FREE_POSITIONS.values(), ids=_FREE_POSITIONS)
def test_a_position_written_with_a_free_function_moves_with_it(position):
    """A reviewer's bead on a rod turned by f(t), written in format 1: the program read f as a constant
    (m ẍ = 0) where the chapter's route has m ẍ − m ḟ² x = 0; code, printout and check agreed with it."""
    _agrees_at_random_times(loads(f"gacli: 1\nname: rod\nparameters: [m]\nfunctions: [f]\ncoordinates: [x]\n"
                                  f"bodies:\n  bead: {{mass: m, position: {position}}}\n"))
