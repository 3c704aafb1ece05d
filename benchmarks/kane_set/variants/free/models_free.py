"""Kane models for the free / gyroscopic variants (helper 'free')."""
from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from models import Reference, _named, _symbols
from bench_kane import KaneModel

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _E(q0, q1, q2, q3):
    return sp.Matrix([[-q1, q0, q3, -q2], [-q2, -q3, q0, q1], [-q3, q2, -q1, q0]])


def free_quat_loads() -> Reference:
    x, y, z, q0, q1, q2, q3 = q = list(me.dynamicsymbols("x y z q0 q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m I1 I2 I3 a b c T1 T2 T3 F1 F2 F3")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, [q0, q1, q2, q3])
    B.set_ang_vel(N, u[3] * B.x + u[4] * B.y + u[5] * B.z)
    qdot = _E(q0, q1, q2, q3).T * sp.Matrix(u[3:]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [
        qi.diff(t) - qdot[i] for i, qi in enumerate((q0, q1, q2, q3))]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    Pt = G.locatenew("Pt", P["a"] * B.x + P["b"] * B.y + P["c"] * B.z)
    Pt.v2pt_theory(G, N, B)
    body = me.RigidBody("craft", G, B, P["m"], (me.inertia(B, P["I1"], P["I2"], P["I3"]), G))
    loads = [(B, P["T1"] * B.x + P["T2"] * B.y + P["T3"] * B.z),
             (Pt, P["F1"] * B.x + P["F2"] * B.y + P["F3"] * B.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], loads)
    norm = [q0**2 + q1**2 + q2**2 + q3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[q0], spread=0.5)


def free_zxz_full() -> Reference:
    x, y, z, phi, theta, psi = q = list(me.dynamicsymbols("x y z phi theta psi"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g Ixx Iyy Izz Ixy Iyz Ixz")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    I = me.inertia(B, P["Ixx"], P["Iyy"], P["Izz"], P["Ixy"], P["Iyz"], P["Ixz"])
    body = me.RigidBody("block", G, B, P["m"], (I, G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def gyrostat_xyz() -> Reference:
    x, y, z, q1, q2, q3, a1, a2 = q = list(me.dynamicsymbols("x y z q1 q2 q3 a1 a2"))
    u = list(me.dynamicsymbols("u1:9"))
    P = _symbols("M I1 I2 I3 mw J K d T1 T2")
    N = me.ReferenceFrame("N")
    H = me.ReferenceFrame("H")
    H.orient_body_fixed(N, (q1, q2, q3), "XYZ")
    natural = H.ang_vel_in(N)
    H.set_ang_vel(N, u[3] * H.x + u[4] * H.y + u[5] * H.z)
    R1 = H.orientnew("R1", "Axis", [a1, H.x])
    R1.set_ang_vel(H, u[6] * H.x)
    R2 = H.orientnew("R2", "Axis", [a2, H.y])
    R2.set_ang_vel(H, u[7] * H.y)
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2],
          natural.dot(H.x) - u[3], natural.dot(H.y) - u[4], natural.dot(H.z) - u[5],
          a1.diff(t) - u[6], a2.diff(t) - u[7]]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    C1 = G.locatenew("C1", P["d"] * H.x)
    C1.v2pt_theory(G, N, H)
    C2 = G.locatenew("C2", P["d"] * H.y)
    C2.v2pt_theory(G, N, H)
    hub = me.RigidBody("hub", G, H, P["M"], (me.inertia(H, P["I1"], P["I2"], P["I3"]), G))
    r1 = me.RigidBody("rotor1", C1, R1, P["mw"], (me.inertia(R1, P["J"], P["K"], P["K"]), C1))
    r2 = me.RigidBody("rotor2", C2, R2, P["mw"], (me.inertia(R2, P["K"], P["J"], P["K"]), C2))
    loads = [(R1, P["T1"] * H.x), (H, -P["T1"] * H.x), (R2, P["T2"] * H.y), (H, -P["T2"] * H.y)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([hub, r1, r2], loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def top_euler(central: bool = False) -> Reference:
    phi, theta, psi = q = list(me.dynamicsymbols("phi theta psi"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("m g l A0 B0 C")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", P["l"] * B.z)
    G.v2pt_theory(O, N, B)
    # inertia about the pivot; SymPy moves it to G
    if central:  # the leanest Kane writing: moments about G typed by hand
        ml2 = P["m"] * P["l"]**2
        top = me.RigidBody("top", G, B, P["m"], (me.inertia(B, P["A0"] - ml2, P["B0"] - ml2, P["C"]), G))
    else:
        top = me.RigidBody("top", G, B, P["m"], (me.inertia(B, P["A0"], P["B0"], P["C"]), O))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([top], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def quat_spring(zero_length: bool = False, damper: bool = False, no_spring: bool = False) -> Reference:
    x, y, z, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y z e0 e1 e2 e3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g k L0 h A B C px py pz cd")
    if not damper:
        P.pop("cd")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_quaternion(N, [e0, e1, e2, e3])
    Bf.set_ang_vel(N, u[3] * Bf.x + u[4] * Bf.y + u[5] * Bf.z)
    qdot = _E(e0, e1, e2, e3).T * sp.Matrix(u[3:]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [
        qi.diff(t) - qdot[i] for i, qi in enumerate((e0, e1, e2, e3))]
    O = me.Point("O")
    O.set_vel(N, 0)
    hook = O.locatenew("hook", P["h"] * N.z)
    hook.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    corner = G.locatenew("corner", P["px"] * Bf.x + P["py"] * Bf.y + P["pz"] * Bf.z)
    corner.v2pt_theory(G, N, Bf)
    r = corner.pos_from(hook)
    length = sp.sqrt(r.dot(r))
    if zero_length:
        P.pop("L0")
        spring = -P["k"] * r
    else:
        spring = -P["k"] * (length - P["L0"]) * r / length  # on the corner, towards the hook when stretched
    if no_spring:
        P.pop("k"), P.pop("L0")
        spring = 0 * N.x
    if damper:
        rate = corner.vel(N).dot(r) / length   # dl/dt
        spring = spring - P["cd"] * rate * r / length
    body = me.RigidBody("block", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z), (corner, spring)])
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e0], spread=0.5)


def quat_scalar_last() -> Reference:
    """Scalar-last quaternion (q4 scalar), body rates u4..u6, full inertia, gravity."""
    x, y, z, q1, q2, q3, q4 = q = list(me.dynamicsymbols("x y z q1 q2 q3 q4"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g Ixx Iyy Izz Ixy Ixz Iyz")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, [q4, q1, q2, q3])
    B.set_ang_vel(N, u[3] * B.x + u[4] * B.y + u[5] * B.z)
    qdot = _E(q4, q1, q2, q3).T * sp.Matrix(u[3:]) / 2   # (q4', q1', q2', q3')
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2],
          q4.diff(t) - qdot[0], q1.diff(t) - qdot[1], q2.diff(t) - qdot[2], q3.diff(t) - qdot[3]]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    I = me.inertia(B, P["Ixx"], P["Iyy"], P["Izz"], P["Ixy"], P["Iyz"], P["Ixz"])
    body = me.RigidBody("body", G, B, P["m"], (I, G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    norm = [q1**2 + q2**2 + q3**2 + q4**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[q4], spread=0.5)


def quat_full(scalar_first: bool = True) -> Reference:
    """Scalar-first quaternion q0..q3, body rates u4..u6, full inertia, gravity."""
    x, y, z, q0, q1, q2, q3 = q = list(me.dynamicsymbols("x y z q0 q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g Ixx Iyy Izz Ixy Ixz Iyz")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, [q0, q1, q2, q3])
    B.set_ang_vel(N, u[3] * B.x + u[4] * B.y + u[5] * B.z)
    qdot = _E(q0, q1, q2, q3).T * sp.Matrix(u[3:]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [
        qi.diff(t) - qdot[i] for i, qi in enumerate((q0, q1, q2, q3))]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    I = me.inertia(B, P["Ixx"], P["Iyy"], P["Izz"], P["Ixy"], P["Iyz"], P["Ixz"])
    body = me.RigidBody("body", G, B, P["m"], (I, G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    norm = [q0**2 + q1**2 + q2**2 + q3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[q0], spread=0.5)


def offset_force_n() -> Reference:
    """Free body, quaternion + body rates, a constant N-component force at a body point (a, b, c)."""
    x, y, z, q0, q1, q2, q3 = q = list(me.dynamicsymbols("x y z q0 q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m I1 I2 I3 a b c F1 F2 F3")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, [q0, q1, q2, q3])
    B.set_ang_vel(N, u[3] * B.x + u[4] * B.y + u[5] * B.z)
    qdot = _E(q0, q1, q2, q3).T * sp.Matrix(u[3:]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [
        qi.diff(t) - qdot[i] for i, qi in enumerate((q0, q1, q2, q3))]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    Pt = G.locatenew("Pt", P["a"] * B.x + P["b"] * B.y + P["c"] * B.z)
    Pt.v2pt_theory(G, N, B)
    body = me.RigidBody("craft", G, B, P["m"], (me.inertia(B, P["I1"], P["I2"], P["I3"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(Pt, P["F1"] * N.x + P["F2"] * N.y + P["F3"] * N.z)])
    norm = [q0**2 + q1**2 + q2**2 + q3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[q0], spread=0.5)


def orbit_quat() -> Reference:
    e0, e1, e2, e3 = q = list(me.dynamicsymbols("e0 e1 e2 e3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("n Rc m I1 I2 I3")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [P["n"] * t, N.z])
    B = me.ReferenceFrame("B")
    B.orient_quaternion(A, q)
    B.set_ang_vel(A, u[0] * B.x + u[1] * B.y + u[2] * B.z)
    qdot = _E(*q).T * sp.Matrix(u) / 2
    kd = [qi.diff(t) - qdot[i] for i, qi in enumerate(q)]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", P["Rc"] * A.x)
    G.v2pt_theory(O, N, A)
    I = me.inertia(B, P["I1"], P["I2"], P["I3"])
    body = me.RigidBody("sat", G, B, P["m"], (I, G))
    c = A.x.express(B)   # radial unit vector
    torque = 3 * P["n"]**2 * c.cross(I.dot(c))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(B, torque)])
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e0], spread=0.5)


def gyrostat_pyramid() -> Reference:
    x, y, z, e0, e1, e2, e3, a1, a2, a3 = q = list(me.dynamicsymbols("x y z e0 e1 e2 e3 a1 a2 a3"))
    u = list(me.dynamicsymbols("u1:10"))
    P = _symbols("M I1 I2 I3 mw J K d beta T1 T2 T3")
    N = me.ReferenceFrame("N")
    H = me.ReferenceFrame("H")
    H.orient_quaternion(N, [e0, e1, e2, e3])
    H.set_ang_vel(N, u[3] * H.x + u[4] * H.y + u[5] * H.z)
    qdot = _E(e0, e1, e2, e3).T * sp.Matrix(u[3:6]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [
        qi.diff(t) - qdot[i] for i, qi in enumerate((e0, e1, e2, e3))] + [
        a1.diff(t) - u[6], a2.diff(t) - u[7], a3.diff(t) - u[8]]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    bodies = [me.RigidBody("hub", G, H, P["M"], (me.inertia(H, P["I1"], P["I2"], P["I3"]), G))]
    loads = []
    for k, (ak, uk, Tk) in enumerate(zip((a1, a2, a3), u[6:], (P["T1"], P["T2"], P["T3"]))):
        Mk = me.ReferenceFrame(f"M{k}")
        Mk.orient_body_fixed(H, (2 * sp.pi * k / 3, P["beta"], 0), "ZYX")
        Wk = Mk.orientnew(f"W{k}", "Axis", [ak, Mk.x])
        Wk.set_ang_vel(Mk, uk * Mk.x)
        Ck = G.locatenew(f"C{k}", P["d"] * Mk.x)
        Ck.v2pt_theory(G, N, H)
        bodies.append(me.RigidBody(f"wheel{k}", Ck, Wk, P["mw"], (me.inertia(Wk, P["J"], P["K"], P["K"]), Ck)))
        loads += [(Wk, Tk * Mk.x), (H, -Tk * Mk.x)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e0], spread=0.5)


def top_rates() -> Reference:
    phi, theta, psi = q = list(me.dynamicsymbols("phi theta psi"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("m g l A B C")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    natural = Bf.ang_vel_in(N)
    Bf.set_ang_vel(N, u[0] * Bf.x + u[1] * Bf.y + u[2] * Bf.z)
    kd = [natural.dot(Bf.x) - u[0], natural.dot(Bf.y) - u[1], natural.dot(Bf.z) - u[2]]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", P["l"] * Bf.z)
    G.v2pt_theory(O, N, Bf)
    top = me.RigidBody("top", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([top], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def zxz_offset() -> Reference:
    x, y, z, phi, theta, psi = q = list(me.dynamicsymbols("x y z phi theta psi"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m I1 I2 I3 a b c F1 F2 F3")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    Pt = G.locatenew("Pt", P["a"] * B.x + P["b"] * B.y + P["c"] * B.z)
    Pt.v2pt_theory(G, N, B)
    body = me.RigidBody("block", G, B, P["m"], (me.inertia(B, P["I1"], P["I2"], P["I3"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(Pt, P["F1"] * N.x + P["F2"] * N.y + P["F3"] * N.z)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def zxz_spring0() -> Reference:
    x, y, z, phi, theta, psi = q = list(me.dynamicsymbols("x y z phi theta psi"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g k h A B C px py pz")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    O = me.Point("O")
    O.set_vel(N, 0)
    hook = O.locatenew("hook", P["h"] * N.z)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    corner = G.locatenew("corner", P["px"] * Bf.x + P["py"] * Bf.y + P["pz"] * Bf.z)
    corner.v2pt_theory(G, N, Bf)
    body = me.RigidBody("block", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z), (corner, -P["k"] * corner.pos_from(hook))])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def free_space_rates() -> Reference:
    phi, theta, psi = q = list(me.dynamicsymbols("phi theta psi"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("A B C")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    natural = Bf.ang_vel_in(N)
    Bf.set_ang_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    # SymPy's own LU solve of these kd (zero pivot in the first column) gives a wrong kindiffdict
    # (phi' = 1.8 where the truth is 0.263), so the user inverts J by hand: q' = J^-1 W.
    qd = [qi.diff(t) for qi in q]
    J = sp.Matrix([[natural.dot(v).diff(d) for d in qd] for v in (N.x, N.y, N.z)])
    Jinv = J.inv().applyfunc(sp.trigsimp)
    solved = Jinv * sp.Matrix(u)
    kd = [qd[i] - solved[i] for i in range(3)]
    O = me.Point("O")
    O.set_vel(N, 0)
    body = me.RigidBody("body", O, Bf, 1, (me.inertia(Bf, P["A"], P["B"], P["C"]), O))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def qtop_about() -> Reference:
    q0, q1, q2, q3 = q = list(me.dynamicsymbols("q0 q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("m g l A0 B0 C")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, q)
    B.set_ang_vel(N, u[0] * B.x + u[1] * B.y + u[2] * B.z)
    qdot = _E(*q).T * sp.Matrix(u) / 2
    kd = [qi.diff(t) - qdot[i] for i, qi in enumerate(q)]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", P["l"] * B.z)
    G.v2pt_theory(O, N, B)
    top = me.RigidBody("top", G, B, P["m"], (me.inertia(B, P["A0"], P["B0"], P["C"]), O))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([top], [(G, -P["m"] * P["g"] * N.z)])
    norm = [q0**2 + q1**2 + q2**2 + q3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[q0], spread=0.5)


def zxz_spring_damper() -> Reference:
    x, y, z, phi, theta, psi = q = list(me.dynamicsymbols("x y z phi theta psi"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g k L0 cd h A B C px py pz")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    O = me.Point("O")
    O.set_vel(N, 0)
    hook = O.locatenew("hook", P["h"] * N.z)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    corner = G.locatenew("corner", P["px"] * Bf.x + P["py"] * Bf.y + P["pz"] * Bf.z)
    corner.v2pt_theory(G, N, Bf)
    r = corner.pos_from(hook)
    length = sp.sqrt(r.dot(r))
    rate = corner.vel(N).dot(r) / length
    force = -(P["k"] * (length - P["L0"]) + P["cd"] * rate) * r / length
    body = me.RigidBody("block", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z), (corner, force)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def gyrostat_quat2() -> Reference:
    x, y, z, e0, e1, e2, e3, a1, a2 = q = list(me.dynamicsymbols("x y z e0 e1 e2 e3 a1 a2"))
    u = list(me.dynamicsymbols("u1:9"))
    P = _symbols("M I1 I2 I3 mw J K d T1 T2")
    N = me.ReferenceFrame("N")
    H = me.ReferenceFrame("H")
    H.orient_quaternion(N, [e0, e1, e2, e3])
    H.set_ang_vel(N, u[3] * H.x + u[4] * H.y + u[5] * H.z)
    qdot = _E(e0, e1, e2, e3).T * sp.Matrix(u[3:6]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [
        qi.diff(t) - qdot[i] for i, qi in enumerate((e0, e1, e2, e3))] + [a1.diff(t) - u[6], a2.diff(t) - u[7]]
    R1 = H.orientnew("R1", "Axis", [a1, H.x])
    R1.set_ang_vel(H, u[6] * H.x)
    R2 = H.orientnew("R2", "Axis", [a2, H.y])
    R2.set_ang_vel(H, u[7] * H.y)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    C1 = G.locatenew("C1", P["d"] * H.x)
    C1.v2pt_theory(G, N, H)
    C2 = G.locatenew("C2", P["d"] * H.y)
    C2.v2pt_theory(G, N, H)
    hub = me.RigidBody("hub", G, H, P["M"], (me.inertia(H, P["I1"], P["I2"], P["I3"]), G))
    r1 = me.RigidBody("rotor1", C1, R1, P["mw"], (me.inertia(R1, P["J"], P["K"], P["K"]), C1))
    r2 = me.RigidBody("rotor2", C2, R2, P["mw"], (me.inertia(R2, P["K"], P["J"], P["K"]), C2))
    loads = [(R1, P["T1"] * H.x), (H, -P["T1"] * H.x), (R2, P["T2"] * H.y), (H, -P["T2"] * H.y)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([hub, r1, r2], loads)
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e0], spread=0.5)


SYSTEMS = {
    "free_quat_loads": (HERE / "free_quat_loads.yaml", free_quat_loads,
                        "free body, quaternion frame, body torque + body-axis force at offset point (inputs)"),
    "free_zxz_full": (HERE / "free_zxz_full.yaml", free_zxz_full, "free body, ZXZ frame, u = q', full inertia"),
    "free_zxz_full_f1": (HERE / "free_zxz_full_f1.yaml", free_zxz_full, "the same, format 1, potential"),
    "gyrostat_xyz": (HERE / "gyrostat_xyz.yaml", gyrostat_xyz, "gyrostat, 2 offset wheels, XYZ frame, body rates as quasi-coords"),
    "top_frames": (HERE / "top_frames.yaml", top_euler, "heavy top, ZXZ frame, G from pivot point, inertia_about pivot"),
    "top_f1": (HERE / "top_f1.yaml", top_euler, "the same top in format 1, position written out, force load"),
    "top_f1_lean": (HERE / "top_f1.yaml", lambda: top_euler(True), "top_f1 against a Kane model with central inertia"),
    "quat_spring": (HERE / "quat_spring.yaml", quat_spring, "quaternion frame block, gravity, spring from fixed hook to a body point"),
    "quat_f1_pfaff": (HERE / "quat_f1_pfaff.yaml", quat_scalar_last, "format 1, scalar-last quaternion, norm as Pfaffian row, full inertia"),
    "quat_f1_full": (HERE / "quat_f1_full.yaml", quat_full, "format 1 quaternion (scalar first, as shipped) + full inertia"),
    "quat_frame_full": (HERE / "quat_frame_full.yaml", quat_full, "quaternion frame with rates + full inertia"),
    "free_quat_loads_f1": (HERE / "free_quat_loads_f1.yaml", free_quat_loads, "format 1: work for torque, force/at written out with direction cosines"),
    "v_offset_min": (HERE / "v_offset_min.yaml", offset_force_n, "minimal: constant N force at a body point written out in quaternions"),
    "v_offset_frame": (HERE / "v_offset_frame.yaml", offset_force_n, "the same with a quaternion frame and a point"),
}
SYSTEMS["orbit_quat"] = (HERE / "orbit_quat.yaml", orbit_quat, "quaternion frame under a turning orbit frame, gravity-gradient torque written out")
SYSTEMS["gyrostat_pyramid"] = (HERE / "gyrostat_pyramid.yaml", gyrostat_pyramid, "quaternion hub, pyramid of 3 tilted offset wheels, motors")
SYSTEMS["top_rates"] = (HERE / "top_rates.yaml", top_rates, "heavy top, ZXZ frame, body rates as quasi-coordinates")
SYSTEMS["zxz_offset_f1"] = (HERE / "zxz_offset_f1.yaml", zxz_offset, "format 1 ZXZ free body, N force at offset point written out")
SYSTEMS["quat_spring_f1"] = (HERE / "quat_spring_f1.yaml", lambda: quat_spring(True), "format 1 quaternion, zero-length spring to a corner as a potential")

from models import quaternion_top as _quaternion_top  # noqa: E402
SYSTEMS["v_qtop_force"] = (HERE / "v_qtop_force.yaml", _quaternion_top, "shipped quaternion_top with gravity as a force instead of a potential")
SYSTEMS["v_quat_spring0"] = (HERE / "v_quat_spring0.yaml", lambda: quat_spring(True), "quat_spring with zero free length (frames)")
SYSTEMS["v_zxz_spring0"] = (HERE / "v_zxz_spring0.yaml", zxz_spring0, "ZXZ frame, zero-length spring hook-corner")
SYSTEMS["free_space_rates"] = (HERE / "free_space_rates.yaml", free_space_rates, "torque-free body, ZXZ frame, space-fixed rates as speeds")
SYSTEMS["qtop_about"] = (HERE / "qtop_about.yaml", qtop_about, "asymmetric heavy top, quaternion frame, inertia_about pivot")
SYSTEMS["quat_spring_damper"] = (HERE / "quat_spring_damper.yaml", lambda: quat_spring(damper=True), "quat_spring plus a damper on the same line")
SYSTEMS["v_zxz_spring_damper"] = (HERE / "v_zxz_spring_damper.yaml", zxz_spring_damper, "ZXZ frame, spring + damper hook-corner")
SYSTEMS["v_quat_damper"] = (HERE / "v_quat_damper.yaml", lambda: quat_spring(damper=True, no_spring=True), "quaternion block, damper only")
SYSTEMS["gyrostat_quat_f1"] = (HERE / "gyrostat_quat_f1.yaml", gyrostat_quat2, "format 1 gyrostat, Euler parameters, offset wheels by direction cosines, motor work")
