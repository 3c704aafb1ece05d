"""r4 rolling / nonholonomic systems, each with a KanesMethod reference built from definitions."""
from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from models import Reference, _named, _symbols, _solved_rates
from bench_kane import KaneModel

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _disc_contact_rows(Pc, centre, D, rates, N):
    """The material point of D at the contact Pc has zero velocity (rows along N.x, N.y)."""
    centre.set_vel(N, Pc.vel(N) + centre.pos_from(Pc).dt(N).subs(rates))
    material = centre.vel(N) + D.ang_vel_in(N).cross(Pc.pos_from(centre))
    return [material.dot(N.x), material.dot(N.y)]


def disc_zxz_pfaff() -> Reference:
    """Disc: ZXZ (yaw, lean = nutation, spin), axle D.z, (x, y) contact; u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C g T")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.z])
    D.set_ang_vel(N, u1 * N.z + u2 * H.x + u3 * L.z)
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    G = Pc.locatenew("G", r * L.y)    # L.y: the in-plane direction nearest the vertical (sin(lean) > 0)
    cons = _disc_contact_rows(Pc, G, D, rates, N)
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, P["A"], P["A"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z), (D, P["T"] * D.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def disc_bodyrates() -> Reference:
    """Disc: yaw z, lean heading x, spin leaned y (axle); speeds = body-axis omega; x', y' dependent."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C g T")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    natural = yaw.diff(t) * N.z + lean.diff(t) * H.x + spin.diff(t) * L.y
    D.set_ang_vel(N, u1 * D.x + u2 * D.y + u3 * D.z)
    kd = [natural.dot(D.x) - u1, natural.dot(D.y) - u2, natural.dot(D.z) - u3,
          x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    G = Pc.locatenew("G", r * L.z)
    cons = _disc_contact_rows(Pc, G, D, rates, N)
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, P["A"], P["C"], P["A"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z), (D, P["T"] * D.y)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def disc_offset_zxz() -> Reference:
    """Disc: ZXZ with nutation pi/2 + lean, axle D.z; lean from vertical; (x, y) contact; u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [sp.pi / 2 + lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.z])
    D.set_ang_vel(N, u1 * N.z + u2 * H.x + u3 * L.z)
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    # in-plane up: N.z - (N.z . L.z) L.z, normalised; it is L.y since N.z . L.y = cos(lean) > 0
    assert sp.simplify(N.z.dot(L.y) - sp.cos(lean)) == 0 and sp.simplify(N.z.dot(L.x)) == 0
    G = Pc.locatenew("G", r * L.y)
    cons = _disc_contact_rows(Pc, G, D, rates, N)
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, P["A"], P["A"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def sleigh_quasi() -> Reference:
    """Sleigh, (x, y) centre of mass, blade b behind; u1 = forward speed, u2 = theta', u3 = lateral speed."""
    x, y, th = q = list(me.dynamicsymbols("x y theta"))
    u1, u2, u3 = me.dynamicsymbols("u1:4")
    P = _symbols("m I b c F")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [th, N.z])
    A.set_ang_vel(N, u2 * N.z)
    kd = [sp.cos(th) * x.diff(t) + sp.sin(th) * y.diff(t) - u1, th.diff(t) - u2,
          -sp.sin(th) * x.diff(t) + sp.cos(th) * y.diff(t) - u3]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y)
    G.set_vel(N, u1 * A.x + u3 * A.y)
    Bl = G.locatenew("Bl", -P["b"] * A.x)
    Bl.v2pt_theory(G, N, A)
    cons = [Bl.vel(N).dot(A.y)]
    body = me.RigidBody("sleigh", G, A, P["m"], (me.inertia(A, 0, 0, P["I"]), G))
    loads = [(Bl, P["F"] * A.x), (A, -P["c"] * u2 * N.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2], u_dependent=[u3], kd_eqs=kd, velocity_constraints=cons)
    kane.kanes_equations([body], loads)
    return Reference(KaneModel(kane, q, [u1, u2], [u3], P, cons), _named(q))


def segway() -> Reference:
    """Two wheels + pitching chassis; wheel angles relative to the chassis; u = pitch', phi_L', phi_R'."""
    x, y, th, pt, pL, pR = q = list(me.dynamicsymbols("x y theta pitch phi_L phi_R"))
    up, uL, uR, ux, uy, uth = me.dynamicsymbols("u1:7")
    P = _symbols("m_c I_1 I_2 I_3 l m_w A_w C_w r w g T_L T_R")
    r, w, g = P["r"], P["w"], P["g"]
    N = me.ReferenceFrame("N")
    Hd = N.orientnew("Hd", "Axis", [th, N.z])
    Ch = Hd.orientnew("Ch", "Axis", [pt, Hd.y])
    Lw = Ch.orientnew("Lw", "Axis", [pL, Ch.y])
    Rw = Ch.orientnew("Rw", "Axis", [pR, Ch.y])
    Hd.set_ang_vel(N, uth * N.z)
    Ch.set_ang_vel(Hd, up * Hd.y)
    Lw.set_ang_vel(Ch, uL * Ch.y)
    Rw.set_ang_vel(Ch, uR * Ch.y)
    kd = [x.diff(t) - ux, y.diff(t) - uy, th.diff(t) - uth, pt.diff(t) - up, pL.diff(t) - uL, pR.diff(t) - uR]
    O = me.Point("O"); O.set_vel(N, 0)
    M = O.locatenew("M", x * N.x + y * N.y + r * N.z)
    M.set_vel(N, ux * N.x + uy * N.y)
    Gc = M.locatenew("Gc", P["l"] * Ch.z); Gc.v2pt_theory(M, N, Ch)
    HL = M.locatenew("HL", w * Hd.y); HL.v2pt_theory(M, N, Hd)
    HR = M.locatenew("HR", -w * Hd.y); HR.v2pt_theory(M, N, Hd)
    cl = HL.vel(N) + Lw.ang_vel_in(N).cross(-r * N.z)
    cr = HR.vel(N) + Rw.ang_vel_in(N).cross(-r * N.z)
    cons = [cl.dot(Hd.x), cl.dot(Hd.y), cr.dot(Hd.x)]
    bodies = [me.RigidBody("chassis", Gc, Ch, P["m_c"], (me.inertia(Ch, P["I_1"], P["I_2"], P["I_3"]), Gc)),
              me.RigidBody("left", HL, Lw, P["m_w"], (me.inertia(Lw, P["A_w"], P["C_w"], P["A_w"]), HL)),
              me.RigidBody("right", HR, Rw, P["m_w"], (me.inertia(Rw, P["A_w"], P["C_w"], P["A_w"]), HR))]
    loads = [(Gc, -P["m_c"] * g * N.z), (HL, -P["m_w"] * g * N.z), (HR, -P["m_w"] * g * N.z),
             (Lw, P["T_L"] * Lw.y), (Rw, P["T_R"] * Rw.y), (Ch, -(P["T_L"] + P["T_R"]) * Ch.y)]
    udep = [ux, uy, uth]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[up, uL, uR], u_dependent=udep, kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [up, uL, uR], udep, P, cons), _named(q))


def ball_quat() -> Reference:
    """Unbalanced ball, Euler parameters e0..e3, body rates u1..u3; (x, y) centre; x', y' dependent."""
    x, y, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y e0 e1 e2 e3"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r e A B C g")
    r = P["r"]
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_quaternion(N, [e0, e1, e2, e3])
    Bf.set_ang_vel(N, u1 * Bf.x + u2 * Bf.y + u3 * Bf.z)
    E = sp.Matrix([[-e1, e0, e3, -e2], [-e2, -e3, e0, e1], [-e3, e2, -e1, e0]])
    edot = E.T * sp.Matrix([u1, u2, u3]) / 2
    kd = [x.diff(t) - u4, y.diff(t) - u5] + [qi.diff(t) - edot[i] for i, qi in enumerate((e0, e1, e2, e3))]
    O = me.Point("O"); O.set_vel(N, 0)
    Cg = O.locatenew("Cg", x * N.x + y * N.y + r * N.z)     # geometric centre
    Cg.set_vel(N, u4 * N.x + u5 * N.y)
    G = Cg.locatenew("G", -P["e"] * Bf.z); G.v2pt_theory(Cg, N, Bf)
    Pc = Cg.locatenew("Pc", -r * N.z)
    material = Cg.vel(N) + Bf.ang_vel_in(N).cross(Pc.pos_from(Cg))
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("ball", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q),
                     configuration=norm, q_dep=[e0], spread=0.5)


def coin_offcentre() -> Reference:
    """Coin: yaw, lean, spin (axle y), (x, y) contact, mass centre e along the coin's x; u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r e I_1 I_2 I_3 g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    D.set_ang_vel(N, u1 * N.z + u2 * H.x + u3 * L.y)
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    Hub = Pc.locatenew("Hub", r * L.z)
    cons = _disc_contact_rows(Pc, Hub, D, rates, N)
    G = Hub.locatenew("G", P["e"] * D.x); G.v2pt_theory(Hub, N, D)
    body = me.RigidBody("coin", G, D, m, (me.inertia(D, P["I_1"], P["I_2"], P["I_3"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def knife_incline() -> Reference:
    """Knife edge on a slope (alpha about N.y): (x, y) blade in slope axes; u1 = x', u2 = phi', u3 = y'."""
    x, y, ph = q = list(me.dynamicsymbols("x y phi"))
    u1, u2, u3 = me.dynamicsymbols("u1:4")
    P = _symbols("m I_1 I_2 I_3 a h alpha g")
    N = me.ReferenceFrame("N")
    S = N.orientnew("S", "Axis", [P["alpha"], N.y])
    Bl = S.orientnew("Bl", "Axis", [ph, S.z])
    Bl.set_ang_vel(N, u2 * S.z)
    kd = [x.diff(t) - u1, ph.diff(t) - u2, y.diff(t) - u3]
    O = me.Point("O"); O.set_vel(N, 0)
    Pb = O.locatenew("Pb", x * S.x + y * S.y)
    Pb.set_vel(N, u1 * S.x + u3 * S.y)
    G = Pb.locatenew("G", P["a"] * Bl.x + P["h"] * Bl.z); G.v2pt_theory(Pb, N, Bl)
    cons = [Pb.vel(N).dot(Bl.y)]
    body = me.RigidBody("knife", G, Bl, P["m"], (me.inertia(Bl, P["I_1"], P["I_2"], P["I_3"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2], u_dependent=[u3], kd_eqs=kd, velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2], [u3], P, cons), _named(q))


SYSTEMS = {
    "r4_disc_zxz_pfaff": (HERE / "r4_disc_zxz_pfaff.yaml", disc_zxz_pfaff,
                          "disc, ZXZ Euler angles, format 1, no-slip rows and rotation forms by hand, axle torque"),
    "r4_disc_bodyrates": (HERE / "r4_disc_bodyrates.yaml", disc_bodyrates,
                          "disc, frames + rolling, body-axis rates w_1..w_3 as quasi-coordinate speeds"),
    "r4_disc_offset_zxz": (HERE / "r4_disc_offset_zxz.yaml", disc_offset_zxz,
                           "disc, one ZXZ frame with nutation pi/2 + lean, axle z, placed by contact"),
    "r4_sleigh_quasi": (HERE / "r4_sleigh_quasi.yaml", sleigh_quasi,
                        "Chaplygin sleigh, format 1, CoM coordinates, speeds v (forward) and w = dtheta"),
    "r4_segway": (HERE / "r4_segway.yaml", segway,
                  "two-wheeled robot, no castor: pitching chassis, wheel angles relative to it, motors"),
    "r4_ball_quat": (HERE / "r4_ball_quat.yaml", ball_quat,
                     "unbalanced ball with A, B, C, quaternion frame + body rates, rolling with centre offset"),
    "r4_coin_offcentre": (HERE / "r4_coin_offcentre.yaml", coin_offcentre,
                          "coin with mass centre on a radius, frames + rolling, centre given in frames"),
    "r4_knife_incline": (HERE / "r4_knife_incline.yaml", knife_incline,
                         "knife edge on an inclined plane, frames + velocity_of, CoM ahead and above, u = x', phi'"),
}
