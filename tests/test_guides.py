"""Points kept on a line or in a plane of a frame (``moves_along``, ``moves_in``; issue #29, item 4).

Each is checked against equations derived by hand in this file, at random
states on the constraint, and its hostile forms are located errors.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from gacli.errors import SystemFileError
from gacli.loader.loading import loads
from gacli.mechanics.equations import derive
from gacli.algebra import symbols as S

ROD = """
gacli: 1
name: bead_on_a_rod
parameters: {m: {value: 0.7}, J: {value: 0.3}}
coordinates: [th, x, y]
independent: [th, x]
frames:
  rod: {rotations: [[z, th]]}
points:
  bead: {N: [x, y, 0]}
bodies:
  rod: {mass: 1, position: [0, 0, 0], frame: rod, inertia: [J, J, J]}
  bead: {mass: m, position: bead}
constraints:
  - {moves_along: [bead, rod, x]}
"""


def _accelerations(d, values: dict[str, float]):
    at = {**{S.value(n): v for n, v in values.items() if not n.startswith("dot(")},
          **{S.rate(n[4:-1]): v for n, v in values.items() if n.startswith("dot(")}}
    at.update({s: values[s.name] for s in d.mass_matrix.free_symbols | d.forcing.free_symbols if s.name in values})
    M = np.array(d.mass_matrix.xreplace(at), dtype=float)
    F = np.array(d.forcing.xreplace(at), dtype=float).ravel()
    return np.linalg.solve(M, F)


def test_a_bead_on_a_turning_rod_against_the_hand_derivation():
    # T = J θ'²/2 + m (r'² + r² θ'²)/2: r'' = r θ'², (J + m r²) θ'' = -2 m r r' θ' (no forces).
    d = derive(loads(ROD))
    assert d.k == 2 and len(d.system.constraints) == 1
    rng = np.random.default_rng(7)
    m, J = 0.7, 0.3
    for _ in range(5):
        th, r, w, rdot = rng.uniform(-1.2, 1.2, 4)
        c, s = math.cos(th), math.sin(th)
        values = {"m": m, "J": J, "th": th, "x": r * c, "y": r * s, "dot(th)": w, "dot(x)": rdot * c - r * w * s}
        ours = _accelerations(d, values)
        thdd = -2 * m * r * rdot * w / (J + m * r * r)
        rdd = r * w * w
        xdd = rdd * c - 2 * rdot * w * s - r * thdd * s - r * w * w * c
        assert np.allclose(ours, [thdd, xdd], rtol=1e-10, atol=1e-12)


SLOPE = """
gacli: 1
name: particle_on_a_slope
parameters: {m: {value: 2}, g: {value: 9.81}, alpha: {value: 0.4}}
coordinates: [x, y, z]
independent: [x, y]
frames:
  slope: {rotations: [[x, alpha]]}
points:
  p: {N: [x, y, z]}
bodies:
  particle: {mass: m, position: p}
constraints:
  - {moves_in: [p, slope, xy]}
loads:
  - {force: {N: [0, 0, -m*g]}, at: particle}
"""


def test_a_particle_in_a_tilted_plane_slides_down_it():
    # Along the slope's y axis, (0, cos α, sin α) in N, the particle falls at g sin α; along x not at all.
    d = derive(loads(SLOPE))
    assert d.k == 2
    g, alpha = 9.81, 0.4
    for s, sdot, xdot in [(0.3, -0.2, 0.5), (-1.1, 0.7, 0.0)]:
        values = {"m": 2.0, "g": g, "alpha": alpha, "x": 0.2, "y": s * math.cos(alpha), "z": s * math.sin(alpha),
                  "dot(x)": xdot, "dot(y)": sdot * math.cos(alpha)}
        assert np.allclose(_accelerations(d, values), [0.0, -g * math.sin(alpha) * math.cos(alpha)], atol=1e-12)


def test_a_guide_the_point_always_satisfies_is_an_error():
    with pytest.raises(SystemFileError, match="constrains nothing"):
        loads(ROD.replace("  bead: {N: [x, y, 0]}", "  bead: {N: [x, y, 0]}\n  tip: {rod: [1, 0, 0]}")
              .replace("[bead, rod, x]", "[tip, rod, x]"))
