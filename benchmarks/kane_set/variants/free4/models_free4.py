"""Kane models for reviewer c's f4_* systems (free bodies in quaternions, chains, spatial)."""
from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from models import Reference, _named, _symbols
from bench_kane import KaneModel

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _E(e0, e1, e2, e3):
    return sp.Matrix([[-e1, e0, e3, -e2], [-e2, -e3, e0, e1], [-e3, e2, -e1, e0]])


def _quat_kd(e, w):
    """e' = E^T w / 2: Euler parameter rates from body rates."""
    edot = _E(*e).T * sp.Matrix(w) / 2
    return [ei.diff(t) - edot[i] for i, ei in enumerate(e)]


def free_quat() -> Reference:
    """Free body: gravity at G, body-axis torque T; quaternion attitude, body rates."""
    x, y, z, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y z e0 e1 e2 e3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g A B C T1 T2 T3")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, [e0, e1, e2, e3])
    B.set_ang_vel(N, u[3] * B.x + u[4] * B.y + u[5] * B.z)
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + _quat_kd([e0, e1, e2, e3], u[3:])
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    body = me.RigidBody("box", G, B, P["m"], (me.inertia(B, P["A"], P["B"], P["C"]), G))
    loads = [(G, -P["m"] * P["g"] * N.z), (B, P["T1"] * B.x + P["T2"] * B.y + P["T3"] * B.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], loads)
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e0], spread=0.5)


def qtop_offset() -> Reference:
    """Heavy top on a fixed pivot at (p_x, p_y, p_z); G at a B.x + l B.z from it; central moments."""
    e = q = list(me.dynamicsymbols("e0 e1 e2 e3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("m g p_x p_y p_z a l A B C")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_quaternion(N, e)
    Bf.set_ang_vel(N, u[0] * Bf.x + u[1] * Bf.y + u[2] * Bf.z)
    kd = _quat_kd(e, u)
    O = me.Point("O")
    O.set_vel(N, 0)
    pivot = O.locatenew("pivot", P["p_x"] * N.x + P["p_y"] * N.y + P["p_z"] * N.z)
    pivot.set_vel(N, 0)
    G = pivot.locatenew("G", P["a"] * Bf.x + P["l"] * Bf.z)
    G.v2pt_theory(pivot, N, Bf)
    top = me.RigidBody("top", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([top], [(G, -P["m"] * P["g"] * N.z)])
    norm = [e[0]**2 + e[1]**2 + e[2]**2 + e[3]**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e[0]], spread=0.5)


def gyrostat_quat() -> Reference:
    """Hub (full inertia with an xy product) + a wheel at d H.y, axle H.z, motor T wheel/hub."""
    x, y, z, e0, e1, e2, e3, phi = q = list(me.dynamicsymbols("x y z e0 e1 e2 e3 phi"))
    u = list(me.dynamicsymbols("u1:8"))
    P = _symbols("M I1 I2 I3 I12 mw J K d T")
    N = me.ReferenceFrame("N")
    H = me.ReferenceFrame("H")
    H.orient_quaternion(N, [e0, e1, e2, e3])
    H.set_ang_vel(N, u[3] * H.x + u[4] * H.y + u[5] * H.z)
    W = H.orientnew("W", "Axis", [phi, H.z])
    W.set_ang_vel(H, u[6] * H.z)
    kd = ([x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]]
          + _quat_kd([e0, e1, e2, e3], u[3:6]) + [phi.diff(t) - u[6]])
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    Cw = G.locatenew("Cw", P["d"] * H.y)
    Cw.v2pt_theory(G, N, H)
    hub = me.RigidBody("hub", G, H, P["M"], (me.inertia(H, P["I1"], P["I2"], P["I3"], P["I12"], 0, 0), G))
    wheel = me.RigidBody("wheel", Cw, W, P["mw"], (me.inertia(W, P["K"], P["K"], P["J"]), Cw))
    loads = [(W, P["T"] * H.z), (H, -P["T"] * H.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([hub, wheel], loads)
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e0], spread=0.5)


def triple_spherical() -> Reference:
    names = "a1 b1 c1 a2 b2 c2 a3 b3 c3"
    q = list(me.dynamicsymbols(names))
    u = list(me.dynamicsymbols("u1:10"))
    P = _symbols("g m1 m2 m3 L1 L2 L3 A1 A2 A3 C1 C2 C3")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    parent, joint = N, O
    bodies, loads = [], []
    for i in range(3):
        F = me.ReferenceFrame(f"L{i + 1}")
        F.orient_body_fixed(parent, tuple(q[3 * i:3 * i + 3]), "XYZ")
        L, m = P[f"L{i + 1}"], P[f"m{i + 1}"]
        G = joint.locatenew(f"G{i + 1}", -L / 2 * F.z)
        G.v2pt_theory(joint, N, F)
        nxt = joint.locatenew(f"J{i + 2}", -L * F.z)
        nxt.v2pt_theory(joint, N, F)
        I = me.inertia(F, P[f"A{i + 1}"], P[f"A{i + 1}"], P[f"C{i + 1}"])
        bodies.append(me.RigidBody(f"link{i + 1}", G, F, m, (I, G)))
        loads.append((G, -m * P["g"] * N.z))
        parent, joint = F, nxt
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def chain4_springs() -> Reference:
    q = list(me.dynamicsymbols("th1:5"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("g m1 m2 m3 m4 L1 L2 L3 L4 k1 k2 k3 k4")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    joint, bodies, loads, frames = O, [], [], []
    for i in range(4):
        F = N.orientnew(f"B{i + 1}", "Axis", [q[i], N.z])
        F.set_ang_vel(N, u[i] * N.z)
        L, m = P[f"L{i + 1}"], P[f"m{i + 1}"]
        G = joint.locatenew(f"G{i + 1}", -L / 2 * F.y)
        G.v2pt_theory(joint, N, F)
        nxt = joint.locatenew(f"J{i + 2}", -L * F.y)
        nxt.v2pt_theory(joint, N, F)
        bodies.append(me.RigidBody(f"bar{i + 1}", G, F, m, (me.inertia(F, m * L**2 / 12, 0, m * L**2 / 12), G)))
        loads.append((G, -m * P["g"] * N.y))
        # torsional spring at the joint above bar i: torque on bar i, reaction on the bar above
        rel = q[i] - (q[i - 1] if i else 0)
        tau = -P[f"k{i + 1}"] * rel * N.z
        loads.append((F, tau))
        if i:
            loads.append((frames[i - 1], -tau))
        frames.append(F)
        joint = nxt
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def double_relative() -> Reference:
    q1, q2 = q = list(me.dynamicsymbols("q1 q2"))
    u1, u2 = u = list(me.dynamicsymbols("u1 u2"))
    P = _symbols("g m1 m2 L1 L2 c")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [q1, N.z])
    A.set_ang_vel(N, u1 * N.z)
    B = A.orientnew("B", "Axis", [q2, A.z])
    B.set_ang_vel(A, u2 * A.z)
    kd = [q1.diff(t) - u1, q2.diff(t) - u2]
    O = me.Point("O")
    O.set_vel(N, 0)
    G1 = O.locatenew("G1", -P["L1"] / 2 * A.y)
    G1.v2pt_theory(O, N, A)
    E = O.locatenew("E", -P["L1"] * A.y)
    E.v2pt_theory(O, N, A)
    G2 = E.locatenew("G2", -P["L2"] / 2 * B.y)
    G2.v2pt_theory(E, N, B)
    b1 = me.RigidBody("bar1", G1, A, P["m1"], (me.inertia(A, 0, 0, P["m1"] * P["L1"]**2 / 12), G1))
    b2 = me.RigidBody("bar2", G2, B, P["m2"], (me.inertia(B, 0, 0, P["m2"] * P["L2"]**2 / 12), G2))
    damp = -P["c"] * u2 * N.z   # on bar 2; the reaction on bar 1
    loads = [(G1, -P["m1"] * P["g"] * N.y), (G2, -P["m2"] * P["g"] * N.y), (B, damp), (A, -damp)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([b1, b2], loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def arm3_spatial() -> Reference:
    q1, q2, q3 = q = list(me.dynamicsymbols("q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("g h mt m1 m2 L1 L2 Jt Kt J1 K1 J2 K2 T1 T2 T3")
    N = me.ReferenceFrame("N")
    Tt = N.orientnew("Tt", "Axis", [q1, N.z])
    Tt.set_ang_vel(N, u[0] * N.z)
    U = Tt.orientnew("U", "Axis", [q2, Tt.y])
    U.set_ang_vel(Tt, u[1] * Tt.y)
    F = U.orientnew("F", "Axis", [q3, U.y])
    F.set_ang_vel(U, u[2] * U.y)
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    O = me.Point("O")
    O.set_vel(N, 0)
    Gt = O.locatenew("Gt", P["h"] / 2 * N.z)
    Gt.set_vel(N, 0)
    S = O.locatenew("S", P["h"] * N.z)
    S.set_vel(N, 0)
    G1 = S.locatenew("G1", P["L1"] / 2 * U.x)
    G1.v2pt_theory(S, N, U)
    El = S.locatenew("El", P["L1"] * U.x)
    El.v2pt_theory(S, N, U)
    G2 = El.locatenew("G2", P["L2"] / 2 * F.x)
    G2.v2pt_theory(El, N, F)
    turret = me.RigidBody("turret", Gt, Tt, P["mt"], (me.inertia(Tt, P["Jt"], P["Jt"], P["Kt"]), Gt))
    upper = me.RigidBody("upper", G1, U, P["m1"], (me.inertia(U, P["J1"], P["K1"], P["K1"]), G1))
    fore = me.RigidBody("fore", G2, F, P["m2"], (me.inertia(F, P["J2"], P["K2"], P["K2"]), G2))
    loads = [(Gt, -P["mt"] * P["g"] * N.z), (G1, -P["m1"] * P["g"] * N.z), (G2, -P["m2"] * P["g"] * N.z),
             (Tt, P["T1"] * N.z),
             (U, P["T2"] * Tt.y), (Tt, -P["T2"] * Tt.y),
             (F, P["T3"] * U.y), (U, -P["T3"] * U.y)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([turret, upper, fore], loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


SYSTEMS = {
    "f4_free_quat_frame": (HERE / "f4_free_quat_frame.yaml", free_quat,
                           "free body, quaternion frame + body rates, gravity, body torques (inputs)"),
    "f4_free_quat_f1": (HERE / "f4_free_quat_f1.yaml", free_quat,
                        "the same in format 1: finite unit-norm constraint, dw = 2E de by hand, potential + work"),
    "f4_qtop_offset": (HERE / "f4_qtop_offset.yaml", qtop_offset,
                       "heavy asymmetric top, pivot at (p_x, p_y, p_z), quaternion frame, G off-axis"),
    "f4_gyrostat_quat": (HERE / "f4_gyrostat_quat.yaml", gyrostat_quat,
                         "quaternion hub (xy product of inertia), one offset reaction wheel, motor with reaction"),
    "f4_triple_spherical": (HERE / "f4_triple_spherical.yaml", triple_spherical,
                            "triple spherical pendulum, relative body-fixed XYZ angles per joint, k = 9"),
    "f4_chain4_springs": (HERE / "f4_chain4_springs.yaml", chain4_springs,
                          "planar 4-bar chain, absolute angles, torsional joint springs as a potential"),
    "f4_double_rel_f1": (HERE / "f4_double_rel_f1.yaml", double_relative,
                         "double pendulum, relative 2nd angle, format 1 with cos(q1 + q2), elbow damper work"),
    "f4_arm3_spatial": (HERE / "f4_arm3_spatial.yaml", arm3_spatial,
                        "yaw-shoulder-elbow arm, frames, joint torques with reactions"),
}
