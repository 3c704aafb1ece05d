"""Frames oriented by a quaternion (docs/frames.md, "Quaternions") against SymPy's KanesMethod.

The references are built here from SymPy's own quaternion orientation
(``orient_quaternion``) and its quaternion kinematic equations
(``kinematic_equations(..., 'quaternion')``), not from gacli's formulas; they
are compared at random unit quaternions, e0 = 0 (a half turn) among them.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
import sympy.physics.mechanics as me

from conftest import ROOT
from gacli.algebra import symbols as S
from gacli.loader.loading import load
from gacli.mechanics.equations import derive
from test_frames import close, gacli_accelerations, kane_accelerations

KANE_SET = ROOT / "benchmarks" / "kane_set"
E = ("q0", "q1", "q2", "q3")
W = ("w_1", "w_2", "w_3")


def kane_body(top: bool):
    """A rigid body turned by a quaternion, body rates as speeds: fixed at a point l below its centre
    (a top, moments A, A, C) or free (moments A, B, C, its centre at x, y, z), under gravity."""
    q = me.dynamicsymbols("q0:4")
    u = me.dynamicsymbols("w_1:4")
    m, g, l, A, B, C = sp.symbols("m g l A B C")
    N = me.ReferenceFrame("N")
    body = me.ReferenceFrame("body")
    body.orient_quaternion(N, q)
    body.set_ang_vel(N, u[0] * body.x + u[1] * body.y + u[2] * body.z)
    kd = list(me.kinematic_equations(u, q, "quaternion"))
    O = me.Point("O")
    O.set_vel(N, 0)
    if top:
        G = O.locatenew("G", l * body.z)
        G.v2pt_theory(O, N, body)
        inertia, coordinates, speeds = me.inertia(body, A, A, C), list(q), list(u)
    else:
        r = me.dynamicsymbols("x y z")
        v = me.dynamicsymbols("v_x v_y v_z")
        G = O.locatenew("G", r[0] * N.x + r[1] * N.y + r[2] * N.z)
        G.set_vel(N, v[0] * N.x + v[1] * N.y + v[2] * N.z)
        kd += [a.diff() - b for a, b in zip(r, v)]
        inertia, coordinates, speeds = me.inertia(body, A, B, C), list(r) + list(q), list(v) + list(u)
    rigid = me.RigidBody("body", G, body, m, (inertia, G))
    kane = me.KanesMethod(N, q_ind=coordinates, u_ind=speeds, kd_eqs=kd)
    kane.kanes_equations([rigid], [(G, -m * g * N.z)])
    return kane, coordinates, speeds, (m, g, l, A, B, C)


def unit_quaternion(rng, e0: float) -> np.ndarray:
    rest = rng.normal(size=3)
    return np.concatenate([[e0], rest * np.sqrt(1 - e0 * e0) / np.linalg.norm(rest)])


def agree(d, kane, coordinates, speeds, constants, rng, e0: float) -> None:
    numbers = dict(zip("m g l A B C".split(), (1.3, 9.81, 0.4, 0.7, 1.1, 0.5)))
    values = dict(numbers)
    values.update(zip(E, unit_quaternion(rng, e0)))
    values.update({n: rng.normal() for n in ("x", "y", "z")})
    rates = {n: rng.normal() for n in W + ("x", "y", "z")}
    values.update({f"dot({n})": v for n, v in rates.items()})
    point = {s: values[str(s)] for s in constants}
    point.update({c: values[c.name] for c in coordinates})
    names = {"v_x": "x", "v_y": "y", "v_z": "z"}
    point.update({s: rates[names.get(s.name, s.name)] for s in speeds})
    assert close(gacli_accelerations(d, values), kane_accelerations(kane, point))
    # The kinematic equations: q̇ of gacli against SymPy's quaternion kinematics solved for q̇.
    qdot = kane.kindiffdict()
    for name, rate in d.kinematic_equations:
        expected = float(me.msubs(qdot[me.dynamicsymbols(name).diff()], point))
        got = float(rate.xreplace({s: values[s.name] for s in rate.free_symbols}))
        assert abs(got - expected) <= 1e-10 * max(1.0, abs(expected))


@pytest.fixture(scope="module")
def top():
    return derive(load(KANE_SET / "quaternion_frame_top.yaml")), kane_body(top=True)


@pytest.fixture(scope="module")
def free_body():
    return derive(load(KANE_SET / "quaternion_frame_body.yaml")), kane_body(top=False)


@pytest.mark.parametrize("e0", [0.8, 0.3, 0.0])
def test_a_top_in_a_quaternion_frame_against_kane(top, rng, e0):
    d, (kane, coordinates, speeds, constants) = top
    for _ in range(3):
        agree(d, kane, coordinates, speeds, constants, rng, e0)


@pytest.mark.parametrize("e0", [0.8, 0.3, 0.0])
def test_a_free_body_in_a_quaternion_frame_against_kane(free_body, rng, e0):
    d, (kane, coordinates, speeds, constants) = free_body
    for _ in range(3):
        agree(d, kane, coordinates, speeds, constants, rng, e0)


def test_the_unit_norm_is_a_holonomic_constraint_and_the_rates_are_quasi_coordinates():
    system = load(KANE_SET / "quaternion_frame_top.yaml")
    e = [S.value(n) for n in E]
    norm, = system.constraints
    assert sp.expand(norm.relation - (sum(x * x for x in e) - 1)) == 0
    assert {w.name for w in system.quasi_coordinates if w.differential is not None} == set(W)


def test_simulate_refuses_a_start_off_the_unit_sphere_and_completes_one_left_open():
    from typer.testing import CliRunner

    from gacli.cli import app

    path = str(KANE_SET / "quaternion_frame_top.yaml")
    off = CliRunner().invoke(app, ["simulate", path, "--init", "q0=1,q1=0.5,q2=0,q3=0", "--t-end", "0.1"])
    assert off.exit_code == 1 and "Traceback" not in off.output
    assert "unit quaternion of frame top" in off.output and "residual 0.25" in off.output
    left = CliRunner().invoke(app, ["simulate", path, "--init", "q0=0.6,q2=0,q3=0,dot(w_1)=1", "--t-end", "0.1"])
    assert left.exit_code == 0, left.output
    assert "q1 = 0.8" in left.output


@pytest.fixture(scope="module")
def body_module(tmp_path_factory):
    import importlib.util

    import gacli

    (name, source), = gacli.emit(gacli.derive(gacli.load(KANE_SET / "quaternion_frame_body.yaml")), "python").items()
    path = tmp_path_factory.mktemp("quaternion_frame") / name
    path.write_text(source)
    spec = importlib.util.spec_from_file_location("quaternion_frame_body", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("e0", [0.5, 1e-3, 1e-6, 1e-9, 0.0])
def test_generated_code_is_regular_at_every_attitude(body_module, rng, e0):
    """The generated rhs against Newton's and Euler's equations written here: ẋ = v, v̇ = −g z,
    I ẇ = −w × I w, and SymPy-free quaternion kinematics ė = ½ Eᵀ w."""
    values = {"m": 2.0, "A": 1.0, "B": 2.0, "C": 3.0, "g": 9.81}
    p = [values[n] for n in body_module.PARAMETERS]
    inertia = np.array([values["A"], values["B"], values["C"]])
    for _ in range(3):
        e, v, w = unit_quaternion(rng, e0), rng.normal(size=3), rng.normal(size=3)
        a, b, c, d = e
        E = np.array([[-b, a, d, -c], [-c, -d, a, b], [-d, c, -b, a]])
        expected = np.concatenate([v, E.T @ w / 2, [0.0, 0.0, -values["g"]], -np.cross(w, inertia * w) / inertia])
        got = np.asarray(body_module.rhs(0.0, np.concatenate([rng.normal(size=3), e, v, w]), p), dtype=float)
        assert np.all(np.isfinite(got))
        assert np.max(np.abs(got - expected)) <= 1e-9 * max(1.0, np.max(np.abs(expected)))


@pytest.fixture(scope="module")
def top_module(tmp_path_factory):
    import importlib.util

    import gacli

    derivation = gacli.derive(gacli.load(KANE_SET / "quaternion_frame_top.yaml"))
    assert derivation.code.operations < 100  # the program's ω × r in body axes, not the polynomial position
    (name, source), = gacli.emit(derivation, "python").items()
    path = tmp_path_factory.mktemp("quaternion_frame_top") / name
    path.write_text(source)
    spec = importlib.util.spec_from_file_location("quaternion_frame_top", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("e0", [0.5, 1e-3, 1e-6, 1e-9, 0.0])
def test_the_top_s_generated_code_is_regular_at_every_attitude(top_module, rng, e0):
    """Euler's equations about the fixed point written here: I_O ẇ = l e_z × Rᵀ(−m g N_z) − w × I_O w,
    with R from SciPy (scalar last) and ė = ½ Eᵀ w."""
    from scipy.spatial.transform import Rotation

    values = {"m": 1.0, "l": 0.2, "A": 0.01, "C": 0.004, "g": 9.81}
    p = [values[n] for n in top_module.PARAMETERS]
    m, l, g = values["m"], values["l"], values["g"]
    inertia = np.array([values["A"] + m * l * l, values["A"] + m * l * l, values["C"]])
    for _ in range(3):
        e, w = unit_quaternion(rng, e0), rng.normal(size=3)
        a, b, c, d = e
        E = np.array([[-b, a, d, -c], [-c, -d, a, b], [-d, c, -b, a]])
        weight = Rotation.from_quat([b, c, d, a]).as_matrix().T @ np.array([0.0, 0.0, -m * g])
        torque = np.cross([0.0, 0.0, l], weight)
        expected = np.concatenate([E.T @ w / 2, (torque - np.cross(w, inertia * w)) / inertia])
        got = np.asarray(top_module.rhs(0.0, np.concatenate([e, w]), p), dtype=float)
        assert np.all(np.isfinite(got))
        assert np.max(np.abs(got - expected)) <= 1e-9 * max(1.0, np.max(np.abs(expected)))


GIMBAL = """
gacli: 1
name: quaternion_on_turntable
parameters: [m, g, l, A, B, C, J]
coordinates: [phi, q0, q1, q2, q3]
quasi_coordinates: [w_1, w_2, w_3]
independent: [phi, w_1, w_2, w_3]
frames:
  table: {rotations: [[z, phi]]}
  top: {parent: table, quaternion: [q0, q1, q2, q3], rates: [w_1, w_2, w_3]}
bodies:
  table: {mass: m, position: [0, 0, 0], frame: table, inertia: [J, J, 2*J]}
  top: {mass: m, position: {top: [0, 0, l]}, frame: top, inertia: [A, B, C]}
loads:
  - {force: {N: [0, 0, -m*g]}, at: top}
"""


def kane_gimbal():
    """A top whose quaternion orients it from a turntable (rates relative to the table), about a fixed point."""
    phi, u0 = me.dynamicsymbols("phi u_0")
    q = me.dynamicsymbols("q0:4")
    u = me.dynamicsymbols("w_1:4")
    m, g, l, A, B, C, J = sp.symbols("m g l A B C J")
    N = me.ReferenceFrame("N")
    table = N.orientnew("table", "Axis", [phi, N.z])
    table.set_ang_vel(N, u0 * N.z)
    top = me.ReferenceFrame("top")
    top.orient_quaternion(table, q)
    top.set_ang_vel(table, u[0] * top.x + u[1] * top.y + u[2] * top.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", l * top.z)
    G.v2pt_theory(O, N, top)
    bodies = [me.RigidBody("table", O, table, m, (me.inertia(table, J, J, 2 * J), O)),
              me.RigidBody("top", G, top, m, (me.inertia(top, A, B, C), G))]
    kd = [phi.diff() - u0] + list(me.kinematic_equations(u, q, "quaternion"))
    kane = me.KanesMethod(N, q_ind=[phi, *q], u_ind=[u0, *u], kd_eqs=kd)
    kane.kanes_equations(bodies, [(G, -m * g * N.z)])
    return kane, [phi, *q], [u0, *u], (m, g, l, A, B, C, J)


def test_a_quaternion_frame_turned_from_a_turning_frame_against_kane(rng):
    from gacli.loader.loading import loads

    d = derive(loads(GIMBAL))
    kane, coordinates, speeds, constants = kane_gimbal()
    for e0 in (0.6, 0.0):
        values = dict(zip("m g l A B C J".split(), (1.3, 9.81, 0.4, 0.7, 1.1, 0.5, 0.9)))
        values.update(zip(E, unit_quaternion(rng, e0)), phi=rng.normal())
        rates = dict(zip(("phi", *W), rng.normal(size=4)))
        values.update({f"dot({n})": v for n, v in rates.items()})
        point = {s: values[str(s)] for s in constants}
        point.update({c: values[c.name] for c in coordinates})
        point.update(dict(zip(speeds, (rates[n] for n in ("phi", *W)))))
        assert close(gacli_accelerations(d, values), kane_accelerations(kane, point))
