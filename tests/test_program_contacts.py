"""A sphere's or an ellipsoid's rolling rows in generated code divide by nothing the system lacks.

Along the body's own axes, the two rows kept for the centre's rates divide by the body's z·n, zero
whenever that axis lies in the plane: a ball in a quaternion frame on a turntable had
1/(e0² − e1² − e2² + e3²) in its code (a division by zero at e = (1, 1, 0, 0)/√2), and a rattleback
on an incline gave wrong rates, silently, at pitch = π/2. The rows are now along the plane's axes
(gacli.mechanics.program.contacts.row_vectors). Each case: generated Python's rhs at attitudes on
that set against the chapter's closed forms, evaluated independently (issue #28, item 2).
"""

from __future__ import annotations

import importlib.util
import math

import numpy as np
import pytest

import gacli
from conftest import ROOT
from gacli.numeric import Program as Evaluator

TURNTABLE = """
gacli: 1
name: ball_on_turntable
parameters:
  m: {value: 1}
  r: {value: 0.1}
  W: {value: 1.5}
functions:
  beta: {value: "W*t"}
coordinates: [x, y, e0, e1, e2, e3]
quasi_coordinates: [w_1, w_2, w_3]
independent: [w_1, w_2, w_3]
frames:
  table: {rotations: [[z, beta]]}
  ball: {quaternion: [e0, e1, e2, e3], rates: [w_1, w_2, w_3]}
bodies:
  ball: {mass: m, position: [x, y, r], frame: ball, inertia: ["2/5*m*r**2", "2/5*m*r**2", "2/5*m*r**2"]}
rolling:
  - {body: ball, radius: r, on: table}
"""
HALF = 1 / math.sqrt(2)


def _module(path, tmp_path):
    (name, source), = gacli.emit(gacli.derive(gacli.load(path)), "python").items()
    (tmp_path / name).write_text(source)
    spec = importlib.util.spec_from_file_location(name[:-3], tmp_path / name)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _closed(path, values: dict) -> np.ndarray:
    """q̇ and u̇ = M⁻¹F of the closed forms (gacli.derive), evaluated by name at ``values``."""
    d = gacli.derive(gacli.load(path))
    k = d.k
    out = Evaluator([*(e for _, e in d.kinematic_equations), *d.mass_matrix, *d.forcing])
    symbols = {s.name: s for e in (*d.mass_matrix, *d.forcing, *(e for _, e in d.kinematic_equations))
               for s in e.free_symbols}
    numbers = np.real(np.array(out({symbols[n]: v for n, v in values.items() if n in symbols})))
    n = len(d.kinematic_equations)
    M, F = numbers[n:n + k * k].reshape(k, k), numbers[n + k * k:]
    return np.concatenate([numbers[:n], np.linalg.solve(M, F)])


@pytest.mark.parametrize("e", [(HALF, HALF, 0, 0), (HALF, 0, HALF, 0), (0.5, 0.5, 0.5, -0.5), (0.3, 0.1, -0.4, 0.2)])
def test_a_ball_in_a_quaternion_frame_on_a_turntable_has_code_at_every_attitude(e, tmp_path):
    path = tmp_path / "ball.yaml"
    path.write_text(TURNTABLE)
    module = _module(path, tmp_path)
    e = np.array(e) / np.linalg.norm(e)
    state = np.array([0.2, -0.1, *e, 0.5, -0.3, 0.7])
    params = [module.DEFAULTS[p] for p in module.PARAMETERS]
    ours = module.rhs(0.4, state, params)
    values = dict(zip(module.STATE, state), **module.DEFAULTS, t=0.4)
    values.update({"beta": 1.5 * 0.4, "dot(beta)": 1.5, "ddot(beta)": 0.0})
    assert np.all(np.isfinite(ours))
    assert np.max(np.abs(ours - _closed(path, values))) < 1e-10


@pytest.mark.parametrize("pitch", [0.2, math.pi / 2, -math.pi / 2])
def test_a_rattleback_on_an_incline_on_its_end(pitch, tmp_path):
    path = ROOT / "benchmarks" / "kane_set" / "variants" / "rolling7" / "r7_j.yaml"
    module = _module(path, tmp_path)
    state = np.array([0.1, 0.2, pitch, 0.0, 0.0, 0.3, 0.2, 0.1])
    ours = module.rhs(0.0, state, [module.DEFAULTS[p] for p in module.PARAMETERS])
    theirs = _closed(path, dict(zip(module.STATE, state), **module.DEFAULTS))
    assert np.max(np.abs(ours - theirs) / np.maximum(1.0, np.abs(theirs))) < 1e-9
