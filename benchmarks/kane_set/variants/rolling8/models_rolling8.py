"""Seven systems for the Kane set, written from mechanics definitions.

Each KanesMethod model uses the gacli file's coordinates, independent speeds
(in the same order) and parameter names. No-slip constraints are the
material point of the rolling body at the contact having zero velocity (the
plane is at rest); the contact point is found from the geometry here.
"""
from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from models import Reference, _named, _symbols
from bench_kane import KaneModel

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _qd_map(kd, q):
    qd = [qi.diff(t) for qi in q]
    return sp.solve(kd, qd, dict=True)[0]


def _set_vel(point, origin, N, rates):
    point.set_vel(N, point.pos_from(origin).dt(N).subs(rates))
    return point.vel(N)


def _set_ang(frame, N, rates):
    frame.set_ang_vel(N, frame.ang_vel_in(N).subs(rates))


def _material_rows(centre, frame, contact, N, directions):
    """Velocity of the body's material point at the contact, along the given directions."""
    v = centre.vel(N) + frame.ang_vel_in(N).cross(contact.pos_from(centre))
    return [sp.expand(v.dot(d)) for d in directions]


def _qkin(e, w):
    """Euler-parameter rates from body rates: e' = E^T w / 2 (e scalar first)."""
    e0, e1, e2, e3 = e
    E = sp.Matrix([[-e1, e0, e3, -e2], [-e2, -e3, e0, e1], [-e3, e2, -e1, e0]])
    return E.T * sp.Matrix(w) / 2


# 1 -- disc with a rim mass --------------------------------------------------------
def disc_rim_mass() -> Reference:
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    ux, uy, uyaw, ulean, uspin = u = list(me.dynamicsymbols("ux uy uyaw ulean uspin"))
    P = _symbols("m mp r g")
    m, mp, r, g = P["m"], P["mp"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    rates = _qd_map(kd, q)
    _set_ang(D, N, rates)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    G = Pc.locatenew("G", r * L.z)          # the hub: straight up from the contact in the disc's plane
    _set_vel(G, O, N, rates)
    Q = G.locatenew("Q", r * D.x)          # the rim mass
    _set_vel(Q, O, N, rates)
    cons = _material_rows(G, D, Pc, N, [N.x, N.y])
    disc = me.RigidBody("disc", G, D, m, (me.inertia(D, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), G))
    bead = me.Particle("bead", Q, mp)
    kane = me.KanesMethod(N, q_ind=q, u_ind=[uspin, ulean, uyaw], u_dependent=[ux, uy], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([disc, bead], [(G, -m * g * N.z), (Q, -mp * g * N.z)])
    return Reference(KaneModel(kane, q, [uspin, ulean, uyaw], [ux, uy], P, cons), _named(q))


# 2 -- thick coin on its rim edge ------------------------------------------------------
def thick_coin_edge() -> Reference:
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    ux, uy, uyaw, ulean, uspin = u = list(me.dynamicsymbols("ux uy uyaw ulean uspin"))
    P = _symbols("m r h g")
    m, r, h, g = P["m"], P["r"], P["h"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    rates = _qd_map(kd, q)
    _set_ang(D, N, rates)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    # The edge circle (radius r, in the plane through E normal to the axle L.y) touches the
    # plane at its lowest point: E - r * (unit of N.z's part in that plane) = E - r L.z.
    E = Pc.locatenew("E", r * L.z)
    G = E.locatenew("G", -h * L.y)          # the centre of mass, h back along the axle
    _set_vel(G, O, N, rates)
    cons = _material_rows(G, D, Pc, N, [N.x, N.y])
    A = m * (3 * r**2 + 4 * h**2) / 12
    coin = me.RigidBody("coin", G, D, m, (me.inertia(D, A, m * r**2 / 2, A), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[uyaw, ulean, uspin], u_dependent=[ux, uy], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([coin], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [uyaw, ulean, uspin], [ux, uy], P, cons), _named(q))


# 3, 4 -- eccentric ball --------------------------------------------------------------
def _eccentric_ball(N, B, x, y, ux, uy, P, rates):
    """Geometric centre at (x, y, r); mass centre at centre - (c1, c2, c3) in B; contact below."""
    O = me.Point("O"); O.set_vel(N, 0)
    Cg = O.locatenew("Cg", x * N.x + y * N.y + P["r"] * N.z)
    Cg.set_vel(N, ux * N.x + uy * N.y)
    G = Cg.locatenew("G", -(P["c1"] * B.x + P["c2"] * B.y + P["c3"] * B.z))
    G.v2pt_theory(Cg, N, B)
    contact = Cg.locatenew("Pc", -P["r"] * N.z)
    cons = _material_rows(G, B, contact, N, [N.x, N.y])
    body = me.RigidBody("ball", G, B, P["m"], (me.inertia(B, P["A"], P["B"], P["C"]), G))
    return body, G, cons


def eccentric_ball_zxz() -> Reference:
    x, y, phi, theta, psi = q = list(me.dynamicsymbols("x y phi theta psi"))
    ux, uy, u1, u2, u3 = u = list(me.dynamicsymbols("ux uy u1 u2 u3"))
    P = _symbols("m r c1 c2 c3 A B C g")
    N = me.ReferenceFrame("N")
    B = N.orientnew("B", "Body", [phi, theta, psi], "ZXZ")
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    rates = _qd_map(kd, q)
    _set_ang(B, N, rates)
    body, G, cons = _eccentric_ball(N, B, x, y, ux, uy, P, rates)
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[ux, uy], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [ux, uy], P, cons), _named(q))


def eccentric_ball_quat() -> Reference:
    x, y, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y e0 e1 e2 e3"))
    ux, uy, w1, w2, w3 = me.dynamicsymbols("ux uy w1 w2 w3")
    P = _symbols("m r c1 c2 c3 A B C g")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, [e0, e1, e2, e3])
    B.set_ang_vel(N, w1 * B.x + w2 * B.y + w3 * B.z)
    ed = _qkin([e0, e1, e2, e3], [w1, w2, w3])
    kd = [x.diff(t) - ux, y.diff(t) - uy] + [ei.diff(t) - ed[i] for i, ei in enumerate((e0, e1, e2, e3))]
    body, G, cons = _eccentric_ball(N, B, x, y, ux, uy, P, {})
    kane = me.KanesMethod(N, q_ind=q, u_ind=[w1, w2, w3], u_dependent=[ux, uy], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, [w1, w2, w3], [ux, uy], P, cons), _named(q),
                     configuration=norm, q_dep=[e0], spread=0.5)


# 5 -- free body on a spring, quaternion -----------------------------------------------
def quat_spring_body() -> Reference:
    x, y, z, q0, q1, q2, q3 = q = list(me.dynamicsymbols("x y z q0 q1 q2 q3"))
    w1, w2, w3, vx, vy, vz = u = list(me.dynamicsymbols("w1 w2 w3 vx vy vz"))
    P = _symbols("m A B C D p1 p2 p3 k L0 H g")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_quaternion(N, [q0, q1, q2, q3])
    Bf.set_ang_vel(N, w1 * Bf.x + w2 * Bf.y + w3 * Bf.z)
    ed = _qkin([q0, q1, q2, q3], [w1, w2, w3])
    kd = [x.diff(t) - vx, y.diff(t) - vy, z.diff(t) - vz] + [
        qi.diff(t) - ed[i] for i, qi in enumerate((q0, q1, q2, q3))]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, vx * N.x + vy * N.y + vz * N.z)
    tie = G.locatenew("tie", P["p1"] * Bf.x + P["p2"] * Bf.y + P["p3"] * Bf.z)
    tie.v2pt_theory(G, N, Bf)
    anchor = O.locatenew("anchor", P["H"] * N.z)
    d = tie.pos_from(anchor)
    length = sp.sqrt(d.dot(d))
    spring = -P["k"] * (length - P["L0"]) / length * d   # on the tie point, toward the anchor when stretched
    inertia = me.inertia(Bf, P["A"], P["B"], P["C"], P["D"], 0, 0)
    body = me.RigidBody("body", G, Bf, P["m"], (inertia, G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z), (tie, spring)])
    norm = [q0**2 + q1**2 + q2**2 + q3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[q0], spread=0.5)


# 6 -- cart with an inverted pendulum on its axle ------------------------------------------
def cart_pendulum_axle() -> Reference:
    x, y, theta, phiL, phiR, alpha = q = list(me.dynamicsymbols("x y theta phi_L phi_R alpha"))
    ux, uy, uth, uL, uR, ua = u = list(me.dynamicsymbols("ux uy uth uL uR ua"))
    P = _symbols("r w m_c Ic1 Ic2 Ic3 m_w A_w C_w m_p l Ip1 Ip2 Ip3 g T_L T_R")
    r, w = P["r"], P["w"]
    N = me.ReferenceFrame("N")
    C = N.orientnew("C", "Axis", [theta, N.z])
    WL = C.orientnew("WL", "Axis", [phiL, C.y])
    WR = C.orientnew("WR", "Axis", [phiR, C.y])
    Pd = C.orientnew("Pd", "Axis", [alpha, C.y])
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    rates = _qd_map(kd, q)
    for F in (C, WL, WR, Pd):
        _set_ang(F, N, rates)
    O = me.Point("O"); O.set_vel(N, 0)
    A = O.locatenew("A", x * N.x + y * N.y + r * N.z)
    HL = A.locatenew("HL", w * C.y)
    HR = A.locatenew("HR", -w * C.y)
    Bob = A.locatenew("Bob", P["l"] * Pd.z)
    for pt in (A, HL, HR, Bob):
        _set_vel(pt, O, N, rates)
    # Upright wheels: each touches the ground straight below its hub.
    CL = HL.locatenew("CL", -r * N.z)
    CR = HR.locatenew("CR", -r * N.z)
    left = _material_rows(HL, WL, CL, N, [C.x, C.y])
    right = _material_rows(HR, WR, CR, N, [C.x])     # its sideways row is the left one's
    cons = left + right
    bodies = [
        me.RigidBody("chassis", A, C, P["m_c"], (me.inertia(C, P["Ic1"], P["Ic2"], P["Ic3"]), A)),
        me.RigidBody("left", HL, WL, P["m_w"], (me.inertia(WL, P["A_w"], P["C_w"], P["A_w"]), HL)),
        me.RigidBody("right", HR, WR, P["m_w"], (me.inertia(WR, P["A_w"], P["C_w"], P["A_w"]), HR)),
        me.RigidBody("pendulum", Bob, Pd, P["m_p"], (me.inertia(Pd, P["Ip1"], P["Ip2"], P["Ip3"]), Bob)),
    ]
    TL, TR = P["T_L"], P["T_R"]
    loads = [(Bob, -P["m_p"] * P["g"] * N.z), (A, -P["m_c"] * P["g"] * N.z),
             (WL, TL * C.y), (WR, TR * C.y), (C, -(TL + TR) * C.y)]
    u_ind, u_dep = [ua, uL, uR], [ux, uy, uth]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u_ind, u_dependent=u_dep, kd_eqs=kd, velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u_ind, u_dep, P, cons), _named(q))


# 7 -- simplified bicycle -------------------------------------------------------------------
def simple_bicycle() -> Reference:
    names = "x y yaw roll pitch steer wheel_R wheel_F"
    x, y, yaw, roll, pitch, steer, wR, wF = q = list(me.dynamicsymbols(names))
    ux, uy, uyaw, uroll, upitch, usteer, uwR, uwF = u = list(
        me.dynamicsymbols("ux uy uyaw uroll upitch usteer uwR uwF"))
    P = _symbols("rR rF w lam bx bz mB IB1 IB2 IB3 hz mH IH1 IH2 IH3 mR AR CR mF AF CF g T")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [roll, Y.x])
    RW = L.orientnew("RW", "Axis", [wR, L.y])
    Bf = L.orientnew("Bf", "Axis", [pitch, L.y])
    Hd = Bf.orientnew("Hd", "Axis", [P["lam"], Bf.y])
    Fk = Hd.orientnew("Fk", "Axis", [steer, Hd.z])
    FW = Fk.orientnew("FW", "Axis", [wF, Fk.y])
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    rates = _qd_map(kd, q)
    for F in (Y, L, RW, Bf, Hd, Fk, FW):
        _set_ang(F, N, rates)
    O = me.Point("O"); O.set_vel(N, 0)
    PR = O.locatenew("PR", x * N.x + y * N.y)
    hubR = PR.locatenew("hubR", P["rR"] * L.z)
    hubF = hubR.locatenew("hubF", P["w"] * Bf.x)
    Gb = hubR.locatenew("Gb", P["bx"] * Bf.x + P["bz"] * Bf.z)
    Gh = hubF.locatenew("Gh", P["hz"] * Fk.z)
    for pt in (hubR, hubF, Gb, Gh):
        _set_vel(pt, O, N, rates)
    # Front contact: the point of the front rim lowest along N.z: from the hub, -rF times the
    # unit vector of N.z's part in the wheel's plane (normal to the axle Fk.y).
    a = Fk.y
    v = N.z - N.z.dot(a) * a
    PF = hubF.locatenew("PF", -P["rF"] * v / sp.sqrt(v.dot(v)))
    rear = _material_rows(hubR, RW, PR, N, [N.x, N.y])
    front = _material_rows(hubF, FW, PF, N, [N.x, N.y, N.z])
    cons = rear + front
    g = P["g"]
    bodies = [
        me.RigidBody("rear_wheel", hubR, RW, P["mR"], (me.inertia(RW, P["AR"], P["CR"], P["AR"]), hubR)),
        me.RigidBody("frame", Gb, Bf, P["mB"], (me.inertia(Bf, P["IB1"], P["IB2"], P["IB3"]), Gb)),
        me.RigidBody("fork", Gh, Fk, P["mH"], (me.inertia(Fk, P["IH1"], P["IH2"], P["IH3"]), Gh)),
        me.RigidBody("front_wheel", hubF, FW, P["mF"], (me.inertia(FW, P["AF"], P["CF"], P["AF"]), hubF)),
    ]
    loads = [(hubR, -P["mR"] * g * N.z), (Gb, -P["mB"] * g * N.z), (Gh, -P["mH"] * g * N.z),
             (hubF, -P["mF"] * g * N.z), (Fk, P["T"] * Fk.z), (Bf, -P["T"] * Fk.z)]
    u_ind = [uroll, usteer, uwR]
    u_dep = [ux, uy, uyaw, upitch, uwF]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u_ind, u_dependent=u_dep, kd_eqs=kd, velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    height = [PF.pos_from(O).dot(N.z)]
    return Reference(KaneModel(kane, q, u_ind, u_dep, P, cons), _named(q),
                     configuration=height, q_dep=[pitch], spread=0.3)


SYSTEMS = {
    "v47b_disc_rim_mass": (HERE / "v47b_disc_rim_mass.yaml", disc_rim_mass,
                           "disc with a rim point mass, rolling, u = spin', lean', yaw'"),
    "v47b_thick_coin_edge": (HERE / "v47b_thick_coin_edge.yaml", thick_coin_edge,
                             "thick coin on its rim edge: wheel with centre offset along the axle, by contact"),
    "v47b_eccentric_ball_zxz": (HERE / "v47b_eccentric_ball_zxz.yaml", eccentric_ball_zxz,
                                "eccentric ball (offset c1,c2,c3; A,B,C), ZXZ, u = angle rates"),
    "v47b_eccentric_ball_quat": (HERE / "v47b_eccentric_ball_quat.yaml", eccentric_ball_quat,
                                 "the same ball in a quaternion frame with body rates"),
    "v47b_quat_spring_body": (HERE / "v47b_quat_spring_body.yaml", quat_spring_body,
                              "free body, quaternion frame, gravity and a spring from a body point"),
    "v47b_cart_pendulum_axle": (HERE / "v47b_cart_pendulum_axle.yaml", cart_pendulum_axle,
                                "differential-drive cart with an inverted pendulum on the axle, motors"),
    "v47b_simple_bicycle": (HERE / "v47b_simple_bicycle.yaml", simple_bicycle,
                            "simplified bicycle: frame, fork (tilted steer axis), two thin wheels"),
}
