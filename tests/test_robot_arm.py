"""The robot arm of systems/ (motors, a spring, a damper declared) against SymPy's KanesMethod with its actuators.

The reference is written here from SymPy's own load vocabulary:
``TorqueActuator`` for the motors (the elbow's with the upper arm as its
reaction frame), ``LinearSpring`` and ``LinearDamper`` along a
``LinearPathway``. The accelerations agree at random states and inputs; with
the motors and the damper off, the energy is conserved in simulation.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import sympy as sp
import sympy.physics.mechanics as me

import gacli
from gacli.algebra import symbols as S
from gacli.numeric import Program as Evaluator

FILE = Path(__file__).resolve().parent.parent / "systems" / "robot_arm.yaml"
VALUES = {"m1": 2.0, "m2": 1.2, "L1": 0.6, "L2": 0.5, "g": 9.81, "k": 40.0, "L0": 0.3, "c": 1.5}


def _kane():
    q = me.dynamicsymbols("th1 th2")
    u = me.dynamicsymbols("u1 u2")
    m1, m2, L1, L2, g, k, L0, c, T1, T2 = sp.symbols("m1 m2 L1 L2 g k L0 c T1 T2")
    N = me.ReferenceFrame("N")
    A = [N.orientnew(f"A{i}", "Axis", [qi, N.z]) for i, qi in enumerate(q)]
    for frame, ui in zip(A, u):
        frame.set_ang_vel(N, ui * N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    elbow = O.locatenew("E", L1 * A[0].x)
    elbow.v2pt_theory(O, N, A[0])
    wrist = elbow.locatenew("W", L2 * A[1].x)
    wrist.v2pt_theory(elbow, N, A[1])
    G1 = O.locatenew("G1", L1 / 2 * A[0].x)
    G1.v2pt_theory(O, N, A[0])
    G2 = elbow.locatenew("G2", L2 / 2 * A[1].x)
    G2.v2pt_theory(elbow, N, A[1])
    anchor = O
    floor = O.locatenew("F", N.x - N.y)
    floor.set_vel(N, 0)
    bodies = [me.RigidBody("b1", G1, A[0], m1, (me.inertia(A[0], 0, m1 * L1 ** 2 / 12, m1 * L1 ** 2 / 12), G1)),
              me.RigidBody("b2", G2, A[1], m2, (me.inertia(A[1], 0, m2 * L2 ** 2 / 12, m2 * L2 ** 2 / 12), G2))]
    loads = [(G1, -m1 * g * N.y), (G2, -m2 * g * N.y)]
    loads += me.TorqueActuator(T1, N.z, A[0]).to_loads()
    loads += me.TorqueActuator(T2, N.z, A[1], A[0]).to_loads()
    loads += me.LinearSpring(k, me.LinearPathway(anchor, wrist), L0).to_loads()
    loads += me.LinearDamper(c, me.LinearPathway(elbow, floor)).to_loads()
    t = me.dynamicsymbols._t
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[qi.diff(t) - ui for qi, ui in zip(q, u)])
    kane.kanes_equations(bodies, loads)
    return kane, q, u, (T1, T2)


def test_the_declared_arm_agrees_with_kane_s_actuators():
    kane, q, u, inputs = _kane()
    d = gacli.derive(gacli.load(FILE))
    ours = Evaluator([*d.mass_matrix, *d.forcing])
    rng = np.random.default_rng(7)
    for _ in range(4):
        angles, speeds, torques = rng.uniform(-2, 2, 2), rng.uniform(-1, 1, 2), rng.uniform(-1, 1, 2)
        at = {sp.Symbol(n): v for n, v in VALUES.items()}
        at.update({**dict(zip(q, angles)), **dict(zip(u, speeds)), **dict(zip(inputs, torques))})
        M = np.array(kane.mass_matrix.subs(at).evalf(), dtype=float)
        udot = np.linalg.solve(M, np.array(kane.forcing.subs(at).evalf(), dtype=float).ravel())
        state = {S.value(n): v for n, v in VALUES.items()}
        state.update({S.value("th1"): angles[0], S.value("th2"): angles[1], S.rate("th1"): speeds[0],
                      S.rate("th2"): speeds[1], S.value("T1"): torques[0], S.value("T2"): torques[1], S.T: 0.0})
        out = np.real(np.array(ours(state)))
        mine = np.linalg.solve(out[:4].reshape(2, 2), out[4:])
        assert np.allclose(mine, udot, rtol=1e-10, atol=1e-10)


def test_with_the_motors_and_the_damper_off_the_energy_is_conserved():
    sim = gacli.simulate(FILE, parameters={"c": 0}, inputs={"T1": 0, "T2": 0}, initial={"th1": 0.3, "th2": -0.4},
                         t_end=2.0, points=201)
    m1, m2, L1, L2, g, k, L0 = (VALUES[n] for n in ("m1", "m2", "L1", "L2", "g", "k", "L0"))
    a, b = sim.column("th1"), sim.column("th2")
    wa, wb = sim.column("dot(th1)"), sim.column("dot(th2)")
    e = lambda angle: np.array([np.cos(angle), np.sin(angle)])  # noqa: E731
    de = lambda angle: np.array([-np.sin(angle), np.cos(angle)])  # noqa: E731
    v1, v2 = L1 / 2 * de(a) * wa, L1 * de(a) * wa + L2 / 2 * de(b) * wb
    kinetic = (m1 * (v1 ** 2).sum(0) + m1 * L1 ** 2 / 12 * wa ** 2 + m2 * (v2 ** 2).sum(0)
               + m2 * L2 ** 2 / 12 * wb ** 2) / 2
    wrist = L1 * e(a) + L2 * e(b)
    stretch = np.hypot(wrist[0], wrist[1]) - L0
    potential = m1 * g * L1 / 2 * np.sin(a) + m2 * g * (L1 * np.sin(a) + L2 / 2 * np.sin(b)) + k * stretch ** 2 / 2
    energy = kinetic + potential
    assert np.ptp(energy) < 1e-6 * max(1.0, abs(energy[0])) and np.ptp(a) > 0.1
