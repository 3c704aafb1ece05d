"""systems/satellite_reaction_wheels.yaml: a free satellite in a quaternion frame with three reaction wheels.

Against SymPy's KanesMethod built here from SymPy's quaternion orientation
and kinematics, at random states (e0 = 0 among them), with the motors on;
and in simulation, the angular momentum about N's origin and the linear
momentum computed here from the path (the attitude by SciPy's Rotation) stay
constant with the motors on, and the energy too with them off.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
import sympy.physics.mechanics as me
from scipy.spatial.transform import Rotation

from conftest import derived
from test_frames import close, gacli_accelerations, kane_accelerations

NUMBERS = {"M": 100.0, "I_1": 20.0, "I_2": 30.0, "I_3": 40.0, "m_w": 2.0, "J": 0.05, "K": 0.03}
AXES = ("x", "y", "z")


def kane_satellite():
    q = me.dynamicsymbols("e0:4")
    w = me.dynamicsymbols("w_1:4")
    a = me.dynamicsymbols("a_1:4")
    s = me.dynamicsymbols("s_1:4")       # the wheels' rates
    r = me.dynamicsymbols("x y z")
    v = me.dynamicsymbols("v_x v_y v_z")
    M, m_w, J, K = sp.symbols("M m_w J K")
    I = sp.symbols("I_1:4")
    T = sp.symbols("T_1:4")
    N = me.ReferenceFrame("N")
    hub = me.ReferenceFrame("hub")
    hub.orient_quaternion(N, q)
    hub.set_ang_vel(N, w[0] * hub.x + w[1] * hub.y + w[2] * hub.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    C = O.locatenew("C", r[0] * N.x + r[1] * N.y + r[2] * N.z)
    C.set_vel(N, v[0] * N.x + v[1] * N.y + v[2] * N.z)
    bodies = [me.RigidBody("hub", C, hub, M, (me.inertia(hub, *I), C))]
    loads = []
    axes = (hub.x, hub.y, hub.z)
    for i in range(3):
        wheel = hub.orientnew(f"wheel_{i + 1}", "Axis", [a[i], axes[i]])
        wheel.set_ang_vel(hub, s[i] * axes[i])
        moments = [K, K, K]
        moments[i] = J
        bodies.append(me.RigidBody(f"wheel_{i + 1}", C, wheel, m_w, (me.inertia(wheel, *moments), C)))
        loads += [(wheel, T[i] * axes[i]), (hub, -T[i] * axes[i])]
    kd = list(me.kinematic_equations(w, q, "quaternion"))
    kd += [x.diff() - y for x, y in zip(r, v)] + [x.diff() - y for x, y in zip(a, s)]
    kane = me.KanesMethod(N, q_ind=list(r) + list(q) + list(a), u_ind=list(v) + list(w) + list(s), kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return kane, list(r) + list(q) + list(a), list(v) + list(w) + list(s), (M, m_w, J, K, *I, *T)


@pytest.fixture(scope="module")
def kane():
    return kane_satellite()


@pytest.mark.parametrize("e0", [0.9, 0.2, 0.0])
def test_the_satellite_agrees_with_kane(kane, rng, e0):
    reference, coordinates, speeds, constants = kane
    d = derived("satellite_reaction_wheels")
    speed_names = ["x", "y", "z", "w_1", "w_2", "w_3", "a_1", "a_2", "a_3"]
    for _ in range(3):
        rest = rng.normal(size=3)
        e = np.concatenate([[e0], rest * np.sqrt(1 - e0 * e0) / np.linalg.norm(rest)])
        values = dict(NUMBERS, **{f"T_{i}": rng.normal() for i in (1, 2, 3)})
        values.update(dict(zip(("e0", "e1", "e2", "e3"), e)))
        values.update({n: rng.normal() for n in ("x", "y", "z", "a_1", "a_2", "a_3")})
        rates = dict(zip(speed_names, rng.normal(size=9) * 3))
        values.update({f"dot({n})": x for n, x in rates.items()})
        point = {c: values[str(c)] for c in constants}
        point.update({c: values[c.name] for c in coordinates})
        point.update(dict(zip(speeds, (rates[n] for n in speed_names))))
        assert close(gacli_accelerations(d, values), kane_accelerations(reference, point))


def momenta(sim) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Linear momentum, angular momentum about N's origin and kinetic energy along the path,
    from the state alone: the hub's attitude by SciPy (scalar last), each wheel at the hub's centre."""
    p = sim.parameters
    e = np.stack([sim.column(n) for n in ("e1", "e2", "e3", "e0")], axis=1)
    R = Rotation.from_quat(e).as_matrix()                     # hub axes → N
    w = np.stack([sim.column(f"dot(w_{i})") for i in (1, 2, 3)], axis=1)
    spins = np.stack([sim.column(f"dot(a_{i})") for i in (1, 2, 3)], axis=1)
    centre = np.stack([sim.column(n) for n in AXES], axis=1)
    velocity = np.stack([sim.column(f"dot({n})") for n in AXES], axis=1)
    omega = np.einsum("tij,tj->ti", R, w)
    hub = np.diag([p["I_1"], p["I_2"], p["I_3"]])
    H = np.cross(centre, p["M"] * velocity) + np.einsum("tij,jk,tlk,tl->ti", R, hub, R, omega)
    L = p["M"] * velocity
    energy = 0.5 * p["M"] * np.sum(velocity ** 2, axis=1) + 0.5 * np.einsum("ti,ij,tj->t", w, hub, w)
    for i in range(3):
        moments = np.full(3, p["K"])
        moments[i] = p["J"]
        position, v = centre, velocity
        spin = w.copy()
        spin[:, i] += spins[:, i]                               # the wheel's ω along hub (= wheel, up to its turn) axes
        local = moments * spin                                  # a wheel's inertia is axisymmetric about its axle
        H += np.cross(position, p["m_w"] * v) + np.einsum("tij,tj->ti", R, local)
        L += p["m_w"] * v
        energy += 0.5 * p["m_w"] * np.sum(v ** 2, axis=1) + 0.5 * np.sum(spin * local, axis=1)
    return L, H, energy


INIT = ("e0=0.6,e1=0.48,e2=0.64,e3=0,dot(w_1)=0.3,dot(w_2)=-0.2,dot(w_3)=0.5,"
        "dot(x)=0.1,dot(a_1)=20,dot(a_2)=-10,dot(a_3)=5")


@pytest.mark.parametrize("motors", [False, True])
def test_the_satellite_keeps_its_momentum_and_with_the_motors_off_its_energy(motors):
    from gacli.simulate import simulate, spec_from_options

    torques = ["T_1=0.3,T_2=-0.2,T_3=0.1"] if motors else ["T_1=0,T_2=0,T_3=0"]
    sim = simulate(derived("satellite_reaction_wheels"), spec_from_options(
        init=[INIT], input=torques, t_end=4.0, rtol=1e-12, atol=1e-14))
    L, H, energy = momenta(sim)
    assert np.max(np.abs(L - L[0])) < 1e-9 * np.linalg.norm(L[0])
    assert np.max(np.abs(H - H[0])) < 1e-9 * np.linalg.norm(H[0])
    e = np.stack([sim.column(n) for n in ("e0", "e1", "e2", "e3")], axis=1)
    assert np.max(np.abs(np.sum(e * e, axis=1) - 1)) < 1e-9
    drift = np.max(np.abs(energy - energy[0])) / energy[0]
    if motors:
        assert drift > 1e-3                                    # the motors do work
    else:
        assert drift < 1e-9
    w = np.stack([sim.column(f"dot(w_{i})") for i in (1, 2, 3)], axis=1)
    assert np.ptp(w[:, 0]) > 0.01                              # the hub tumbles: no steady motion
