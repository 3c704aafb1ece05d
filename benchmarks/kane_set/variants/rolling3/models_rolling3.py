"""Third set of rolling / nonholonomic variants, each with a KanesMethod reference built from definitions."""
from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from models import Reference, _named, _symbols, _solved_rates
from bench_kane import KaneModel

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def sleigh_f1() -> Reference:
    """Sleigh: (x, y) centre of mass, blade b behind; u1 = x', u2 = theta' independent, u3 = y'."""
    x, y, th = q = list(me.dynamicsymbols("x y theta"))
    u1, u2, u3 = me.dynamicsymbols("u1:4")
    P = _symbols("m I b c F")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [th, N.z])
    A.set_ang_vel(N, u2 * N.z)
    kd = [x.diff(t) - u1, th.diff(t) - u2, y.diff(t) - u3]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y)
    G.set_vel(N, u1 * N.x + u3 * N.y)
    Pb = G.locatenew("Pb", -P["b"] * A.x)
    Pb.v2pt_theory(G, N, A)
    cons = [Pb.vel(N).dot(A.y)]
    body = me.RigidBody("sleigh", G, A, P["m"], (me.inertia(A, 0, 0, P["I"]), G))
    loads = [(Pb, P["F"] * A.x), (A, -P["c"] * u2 * N.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2], u_dependent=[u3], kd_eqs=kd, velocity_constraints=cons)
    kane.kanes_equations([body], loads)
    return Reference(KaneModel(kane, q, [u1, u2], [u3], P, cons), _named(q))


def sleigh_incline() -> Reference:
    """Sleigh on a slope: (x, y) blade in slope axes; u1 = forward speed, u2 = theta', u3 = lateral speed."""
    x, y, th = q = list(me.dynamicsymbols("x y theta"))
    u1, u2, u3 = me.dynamicsymbols("u1:4")
    P = _symbols("m I_3 a e alpha g")
    N = me.ReferenceFrame("N")
    S = N.orientnew("S", "Axis", [P["alpha"], N.y])
    A = S.orientnew("A", "Axis", [th, S.z])
    A.set_ang_vel(N, u2 * S.z)
    kd = [sp.cos(th) * x.diff(t) + sp.sin(th) * y.diff(t) - u1, th.diff(t) - u2,
          -sp.sin(th) * x.diff(t) + sp.cos(th) * y.diff(t) - u3]
    O = me.Point("O"); O.set_vel(N, 0)
    Bl = O.locatenew("Bl", x * S.x + y * S.y)
    Bl.set_vel(N, u1 * A.x + u3 * A.y)
    G = Bl.locatenew("G", P["a"] * A.x + P["e"] * A.y)
    G.v2pt_theory(Bl, N, A)
    cons = [Bl.vel(N).dot(A.y)]
    body = me.RigidBody("sleigh", G, A, P["m"], (me.inertia(A, sp.Rational(1, 10), sp.Rational(1, 10), P["I_3"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2], u_dependent=[u3], kd_eqs=kd, velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2], [u3], P, cons), _named(q))


def disc_axle_x() -> Reference:
    """Disc: yaw about z, lean about heading y, spin about the leaned x (axle); (x, y) contact; u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C g T")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.y])
    D = L.orientnew("D", "Axis", [spin, L.x])
    D.set_ang_vel(N, u1 * N.z + u2 * H.y + u3 * L.x)
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    # the lowest point of the rim: the in-plane direction closest to N.z is L.z (cos(lean) > 0)
    up = N.z - N.z.dot(L.x) * L.x
    comps = [sp.trigsimp(up.dot(ax)) for ax in (L.x, L.y, L.z)]       # 0, 0, cos(lean)
    norm = sp.sqrt(sum(c**2 for c in comps))
    unit = [sp.simplify(sp.refine(c / norm, sp.Q.positive(sp.cos(lean)))) for c in comps]
    assert unit == [0, 0, 1] or unit == [0, 0, sp.cos(lean) / sp.Abs(sp.cos(lean))], unit
    G = Pc.locatenew("G", r * L.z)   # the in-plane unit vector nearest N.z, for cos(lean) > 0
    G.set_vel(N, Pc.vel(N) + G.pos_from(Pc).dt(N).subs(rates))
    material = G.vel(N) + D.ang_vel_in(N).cross(Pc.pos_from(G))
    cons = [sp.simplify(material.dot(N.x)), sp.simplify(material.dot(N.y))]
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, P["C"], P["A"], P["A"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z), (D, P["T"] * L.x)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def disc_contact_speeds() -> Reference:
    """Disc ZXY (yaw, lean, spin), axle y, (x, y) contact; independent x', yaw', lean'; y', spin' dependent."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    ux, uyaw, ulean, uy, uspin = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    D.set_ang_vel(N, uyaw * N.z + ulean * H.x + uspin * L.y)
    kd = [x.diff(t) - ux, yaw.diff(t) - uyaw, lean.diff(t) - ulean, y.diff(t) - uy, spin.diff(t) - uspin]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, ux * N.x + uy * N.y)
    G = Pc.locatenew("G", r * L.z)
    G.set_vel(N, Pc.vel(N) + G.pos_from(Pc).dt(N).subs(rates))
    material = G.vel(N) + D.ang_vel_in(N).cross(Pc.pos_from(G))
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, P["A"], P["C"], P["A"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[ux, uyaw, ulean], u_dependent=[uy, uspin], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [ux, uyaw, ulean], [uy, uspin], P, cons), _named(q))


def castor_robot() -> Reference:
    """Differential drive + ball castor; independent wheel rates and the ball's vertical spin."""
    x, y, th, pL, pR = q = list(me.dynamicsymbols("x y theta phi_L phi_R"))
    uL, uR, wz, ux, uy, uth, wx, wy = me.dynamicsymbols("u1:9")
    P = _symbols("m_c I_1 I_2 I_3 d h m_w A_w C_w r w m_b I_b rb a T_L T_R")
    r, w, a, rb = P["r"], P["w"], P["a"], P["rb"]
    N = me.ReferenceFrame("N")
    Ch = N.orientnew("Ch", "Axis", [th, N.z])
    Lw = Ch.orientnew("Lw", "Axis", [pL, Ch.y])
    Rw = Ch.orientnew("Rw", "Axis", [pR, Ch.y])
    Bb = N.orientnew("Bb", "Axis", [0, N.z])   # a uniform ball: its axes do not matter; omega set below
    Ch.set_ang_vel(N, uth * N.z)
    Lw.set_ang_vel(Ch, uL * Ch.y)
    Rw.set_ang_vel(Ch, uR * Ch.y)
    Bb.set_ang_vel(N, wx * N.x + wy * N.y + wz * N.z)
    kd = [x.diff(t) - ux, y.diff(t) - uy, th.diff(t) - uth, pL.diff(t) - uL, pR.diff(t) - uR]
    O = me.Point("O"); O.set_vel(N, 0)
    M = O.locatenew("M", x * N.x + y * N.y)          # axle midpoint on the floor
    M.set_vel(N, ux * N.x + uy * N.y)
    Gc = M.locatenew("Gc", P["d"] * Ch.x + P["h"] * N.z); Gc.v2pt_theory(M, N, Ch)
    HL = M.locatenew("HL", w * Ch.y + r * N.z); HL.v2pt_theory(M, N, Ch)
    HR = M.locatenew("HR", -w * Ch.y + r * N.z); HR.v2pt_theory(M, N, Ch)
    Bc = M.locatenew("Bc", -a * Ch.x + rb * N.z); Bc.v2pt_theory(M, N, Ch)
    cl = HL.vel(N) + Lw.ang_vel_in(N).cross(-r * N.z)
    cr = HR.vel(N) + Rw.ang_vel_in(N).cross(-r * N.z)
    cb = Bc.vel(N) + Bb.ang_vel_in(N).cross(-rb * N.z)
    cons = [cl.dot(Ch.x), cl.dot(Ch.y), cr.dot(Ch.x), cb.dot(N.x), cb.dot(N.y)]
    bodies = [me.RigidBody("chassis", Gc, Ch, P["m_c"], (me.inertia(Ch, P["I_1"], P["I_2"], P["I_3"]), Gc)),
              me.RigidBody("left", HL, Lw, P["m_w"], (me.inertia(Lw, P["A_w"], P["C_w"], P["A_w"]), HL)),
              me.RigidBody("right", HR, Rw, P["m_w"], (me.inertia(Rw, P["A_w"], P["C_w"], P["A_w"]), HR)),
              me.RigidBody("castor", Bc, Bb, P["m_b"], (me.inertia(Bb, P["I_b"], P["I_b"], P["I_b"]), Bc))]
    loads = [(Lw, P["T_L"] * Ch.y), (Rw, P["T_R"] * Ch.y), (Ch, -(P["T_L"] + P["T_R"]) * Ch.y)]
    udep = [ux, uy, uth, wx, wy]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[uL, uR, wz], u_dependent=udep, kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [uL, uR, wz], udep, P, cons), _named(q))


def ball_turntable() -> Reference:
    """Chaplygin ball, ZXZ relative to N, (x, y) centre in N, table angle beta(t); u = q'."""
    x, y, ph, th, ps = q = list(me.dynamicsymbols("x y phi theta psi"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A B C W E nu")
    r = P["r"]
    beta = P["W"] * t + P["E"] * sp.sin(P["nu"] * t)
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_body_fixed(N, (ph, th, ps), "ZXZ")
    Z1 = N.orientnew("Z1", "Axis", [ph, N.z])
    Bf.set_ang_vel(N, u1 * N.z + u2 * Z1.x + u3 * Bf.z)
    kd = [ph.diff(t) - u1, th.diff(t) - u2, ps.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + r * N.z)
    G.set_vel(N, u4 * N.x + u5 * N.y)
    Pc = G.locatenew("Pc", -r * N.z)
    material = G.vel(N) + Bf.ang_vel_in(N).cross(Pc.pos_from(G))
    table_point = beta.diff(t) * N.z.cross(Pc.pos_from(O))   # the table's own point under the ball
    slip = material - table_point
    cons = [slip.dot(N.x), slip.dot(N.y)]
    body = me.RigidBody("ball", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def eccentric_in_cylinder() -> Reference:
    """Unbalanced cylinder inside a cylinder: phi' independent, theta' dependent."""
    th, ph = q = list(me.dynamicsymbols("theta phi"))
    u1, u2 = me.dynamicsymbols("u1:3")   # u1 = phi', u2 = theta'
    P = _symbols("M J a b e k g")
    a, b = P["a"], P["b"]
    N = me.ReferenceFrame("N")
    Cy = N.orientnew("Cy", "Axis", [ph, N.z])
    Cy.set_ang_vel(N, u1 * N.z)
    Lc = N.orientnew("Lc", "Axis", [th, N.z])   # line of centres: -Lc.y points from the big axis to C
    Lc.set_ang_vel(N, u2 * N.z)
    kd = [ph.diff(t) - u1, th.diff(t) - u2]
    O = me.Point("O"); O.set_vel(N, 0)
    C = O.locatenew("C", -(b - a) * Lc.y); C.v2pt_theory(O, N, Lc)
    G = C.locatenew("G", P["e"] * Cy.x); G.v2pt_theory(C, N, Cy)
    contact = C.locatenew("Pc", -a * Lc.y)
    material = C.vel(N) + Cy.ang_vel_in(N).cross(contact.pos_from(C))
    cons = [material.dot(Lc.x)]
    body = me.RigidBody("cyl", G, Cy, P["M"], (me.inertia(Cy, 0, 0, P["J"]), G))
    loads = [(G, -P["M"] * P["g"] * N.y), (Cy, -P["k"] * u1 * N.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1], u_dependent=[u2], kd_eqs=kd, velocity_constraints=cons)
    kane.kanes_equations([body], loads)
    return Reference(KaneModel(kane, q, [u1], [u2], P, cons), _named(q))


def coin_offset() -> Reference:
    """Weighted coin: yaw, lean, spin (axle y), (x, y) contact, mass centre (e, f, 0) in the coin; u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r e f I_1 I_2 I_3 g")
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
    Hub.set_vel(N, Pc.vel(N) + Hub.pos_from(Pc).dt(N).subs(rates))
    G = Hub.locatenew("G", P["e"] * D.x + P["f"] * D.y)
    G.v2pt_theory(Hub, N, D)
    material = Hub.vel(N) + D.ang_vel_in(N).cross(Pc.pos_from(Hub))
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("coin", G, D, m, (me.inertia(D, P["I_1"], P["I_2"], P["I_3"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def car_steer() -> Reference:
    """Kinematic car with inertia: u1 = forward speed of the rear axle, u2 = delta'; theta', lateral dependent."""
    x, y, th, de = q = list(me.dynamicsymbols("x y theta delta"))
    u1, u2, u3, u4 = me.dynamicsymbols("u1:5")   # v, delta', theta', lateral speed
    P = _symbols("m I b L m_f J P S")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [th, N.z])
    Fr = A.orientnew("Fr", "Axis", [de, A.z])
    A.set_ang_vel(N, u3 * N.z)
    Fr.set_ang_vel(A, u2 * A.z)
    kd = [sp.cos(th) * x.diff(t) + sp.sin(th) * y.diff(t) - u1, de.diff(t) - u2, th.diff(t) - u3,
          -sp.sin(th) * x.diff(t) + sp.cos(th) * y.diff(t) - u4]
    O = me.Point("O"); O.set_vel(N, 0)
    R = O.locatenew("R", x * N.x + y * N.y)
    R.set_vel(N, u1 * A.x + u4 * A.y)
    G = R.locatenew("G", P["b"] * A.x); G.v2pt_theory(R, N, A)
    F = R.locatenew("F", P["L"] * A.x); F.v2pt_theory(R, N, A)
    cons = [R.vel(N).dot(A.y), F.vel(N).dot(Fr.y)]
    bodies = [me.RigidBody("chassis", G, A, P["m"], (me.inertia(A, 0, 0, P["I"]), G)),
              me.RigidBody("front", F, Fr, P["m_f"], (me.inertia(Fr, 0, 0, P["J"]), F))]
    loads = [(R, P["P"] * A.x), (Fr, P["S"] * N.z), (A, -P["S"] * N.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2], u_dependent=[u3, u4], kd_eqs=kd, velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1, u2], [u3, u4], P, cons), _named(q))


SYSTEMS = {
    "r3_sleigh_f1": (HERE / "r3_sleigh_f1.yaml", sleigh_f1,
                     "Chaplygin sleigh, format 1, CoM coordinates, knife row by hand, u = x', theta'"),
    "r3_sleigh_incline": (HERE / "r3_sleigh_incline.yaml", sleigh_incline,
                          "Chaplygin sleigh on a slope, frames + knife edge, offset CoM, forward speed quasi"),
    "r3_disc_axle_x_f1": (HERE / "r3_disc_axle_x_f1.yaml", disc_axle_x,
                          "disc, axle body x (z, y, x angles), format 1, rows in N by hand, axle torque"),
    "r3_disc_contact_speeds": (HERE / "r3_disc_contact_speeds.yaml", disc_contact_speeds,
                               "disc placed by contact, ZXY sequence, independent x', yaw', lean'"),
    "r3_castor_robot_f1": (HERE / "r3_castor_robot_f1.yaml", castor_robot,
                           "differential drive + ball castor (primitive quasi-coordinates), format 1 rows"),
    "r3_ball_turntable_frames": (HERE / "r3_ball_turntable_frames.yaml", ball_turntable,
                                 "Chaplygin ball on a turntable with prescribed angle beta(t), rolling on: table"),
    "r3_eccentric_in_cylinder_f1": (HERE / "r3_eccentric_in_cylinder_f1.yaml", eccentric_in_cylinder,
                                    "unbalanced cylinder inside a cylinder, planar format 1, phi independent"),
    "r3_coin_offset": (HERE / "r3_coin_offset.yaml", coin_offset,
                       "weighted coin, frames + rolling with centre offset in the coin plane and along the axle"),
    "r3_car_steer_f1": (HERE / "r3_car_steer_f1.yaml", car_steer,
                        "car-like robot with steered front assembly, rows by hand, v quasi-coordinate"),
}

SYSTEMS["r3_sleigh_frames_x"] = (HERE / "r3_sleigh_frames_x.yaml", sleigh_f1,
                                 "the r3_sleigh_f1 sleigh with frames + knife edge, u = x', theta'")


def snakeboard() -> Reference:
    """Snakeboard: u1 = forward speed, u2 = psi', u3 = phi'; theta' and lateral speed dependent."""
    x, y, th, ps, ph = q = list(me.dynamicsymbols("x y theta psi phi"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")   # v, psi', phi', theta', lateral
    P = _symbols("m J J_r m_w J_w l tau_psi tau_phi")
    l = P["l"]
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [th, N.z])
    Rt = A.orientnew("Rt", "Axis", [ps, A.z])
    Ff = A.orientnew("Ff", "Axis", [ph, A.z])
    Fb = A.orientnew("Fb", "Axis", [-ph, A.z])
    A.set_ang_vel(N, u4 * N.z)
    Rt.set_ang_vel(A, u2 * A.z)
    Ff.set_ang_vel(A, u3 * A.z)
    Fb.set_ang_vel(A, -u3 * A.z)
    kd = [sp.cos(th) * x.diff(t) + sp.sin(th) * y.diff(t) - u1, ps.diff(t) - u2, ph.diff(t) - u3,
          th.diff(t) - u4, -sp.sin(th) * x.diff(t) + sp.cos(th) * y.diff(t) - u5]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y)
    G.set_vel(N, u1 * A.x + u5 * A.y)
    F = G.locatenew("F", l * A.x); F.v2pt_theory(G, N, A)
    Bk = G.locatenew("Bk", -l * A.x); Bk.v2pt_theory(G, N, A)
    cons = [F.vel(N).dot(Ff.y), Bk.vel(N).dot(Fb.y)]
    bodies = [me.RigidBody("board", G, A, P["m"], (me.inertia(A, 0, 0, P["J"]), G)),
              me.RigidBody("rotor", G, Rt, 0, (me.inertia(Rt, 0, 0, P["J_r"]), G)),
              me.RigidBody("front", F, Ff, P["m_w"], (me.inertia(Ff, 0, 0, P["J_w"]), F)),
              me.RigidBody("back", Bk, Fb, P["m_w"], (me.inertia(Fb, 0, 0, P["J_w"]), Bk))]
    loads = [(Rt, P["tau_psi"] * N.z), (A, -P["tau_psi"] * N.z - P["tau_phi"] * N.z), (Ff, P["tau_phi"] * N.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def wheel_turntable() -> Reference:
    """Wheel yaw/lean/spin on a turntable beta(t); (x, y) contact; u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C g W E nu")
    m, r, g = P["m"], P["r"], P["g"]
    beta = P["W"] * t + P["E"] * sp.sin(P["nu"] * t)
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
    G = Pc.locatenew("G", r * L.z)
    G.set_vel(N, Pc.vel(N) + G.pos_from(Pc).dt(N).subs(rates))
    material = G.vel(N) + D.ang_vel_in(N).cross(Pc.pos_from(G))
    slip = material - beta.diff(t) * N.z.cross(Pc.pos_from(O))
    cons = [slip.dot(N.x), slip.dot(N.y)]
    body = me.RigidBody("wheel", G, D, m, (me.inertia(D, P["A"], P["C"], P["A"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


SYSTEMS["r3_snakeboard_f1"] = (HERE / "r3_snakeboard_f1.yaml", snakeboard,
                               "snakeboard, rotor + coupled axles, rows by hand, forward speed quasi")
SYSTEMS["r3_wheel_turntable"] = (HERE / "r3_wheel_turntable.yaml", wheel_turntable,
                                 "thin wheel on a turntable beta(t), frames + rolling on: table")
