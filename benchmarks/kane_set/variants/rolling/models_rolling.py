"""Rolling bodies written as a new user would, with KanesMethod references built from definitions."""
from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from models import Reference, _named, _symbols, _solved_rates
from bench_kane import KaneModel

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def disc_zxz() -> Reference:
    """Coin: ZXZ (psi, theta, phi), axle = body z, (x, y) contact point, u = q'."""
    x, y, psi, theta, phi = q = list(me.dynamicsymbols("x y psi theta phi"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [psi, N.z])
    T = A.orientnew("T", "Axis", [theta, A.x])
    D = T.orientnew("D", "Axis", [phi, T.z])
    D.set_ang_vel(N, u1 * N.z + u2 * A.x + u3 * T.z)
    kd = [psi.diff(t) - u1, theta.diff(t) - u2, phi.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    C = O.locatenew("C", x * N.x + y * N.y)
    C.set_vel(N, u4 * N.x + u5 * N.y)
    # lowest point of the coin's rim: centre = contact + r * (unit vector in the coin plane most upward)
    G = C.locatenew("G", r * T.y)
    G.set_vel(N, C.vel(N) + G.pos_from(C).dt(N).subs(rates))
    material = G.vel(N) + D.ang_vel_in(N).cross(C.pos_from(G))
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("coin", G, D, m, (me.inertia(D, m * r**2 / 4, m * r**2 / 4, m * r**2 / 2), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def disc_body_rates() -> Reference:
    """Wheel: body ZXY (yaw, lean, spin), axle y, (x, y) the centre; u1..u3 wheel-fixed rates."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C c g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    D = me.ReferenceFrame("D")
    D.orient_body_fixed(N, (yaw, lean, spin), "ZXY")
    L = N.orientnew("L", "Body", (yaw, lean, 0), "ZXY")
    natural = D.ang_vel_in(N)  # in yaw', lean', spin'
    D.set_ang_vel(N, u1 * D.x + u2 * D.y + u3 * D.z)
    kd = [sp.trigsimp(natural.dot(a)) - ui for a, ui in zip((D.x, D.y, D.z), (u1, u2, u3))]
    kd += [x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + r * sp.cos(lean) * N.z)
    G.set_vel(N, (G.pos_from(O).dt(N)).subs(rates).subs({x.diff(t): u4, y.diff(t): u5}))
    # contact: the point of the rim straight below the centre, in the wheel plane
    contact_from_G = -r * L.z
    material = G.vel(N) + D.ang_vel_in(N).cross(contact_from_G)
    cons = [sp.simplify(material.dot(N.x)), sp.simplify(material.dot(N.y))]
    body = me.RigidBody("wheel", G, D, m, (me.inertia(D, P["A"], P["C"], P["A"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z), (D, -P["c"] * u2 * D.y)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def ball_offset_xyz() -> Reference:
    """Ball, XYZ body-fixed angles, inertial angular velocity components u1..u3; (x, y) geometric centre."""
    x, y, al, be, ga = q = list(me.dynamicsymbols("x y alpha beta gamma"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r d e A B C g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_body_fixed(N, (al, be, ga), "XYZ")
    natural = Bf.ang_vel_in(N)
    Bf.set_ang_vel(N, u1 * N.x + u2 * N.y + u3 * N.z)
    # simplify: SymPy's LU solve of the unsimplified rows gave wrong q' (zero-in-disguise pivots)
    kd = [sp.trigsimp(natural.dot(a)) - ui for a, ui in zip((N.x, N.y, N.z), (u1, u2, u3))]
    kd += [x.diff(t) - u4, y.diff(t) - u5]
    O = me.Point("O"); O.set_vel(N, 0)
    Cg = O.locatenew("Cg", x * N.x + y * N.y + r * N.z)
    Cg.set_vel(N, u4 * N.x + u5 * N.y)
    G = Cg.locatenew("G", P["d"] * Bf.x - P["e"] * Bf.z)
    G.v2pt_theory(Cg, N, Bf)
    contact = Cg.locatenew("Pc", -r * N.z)
    material = Cg.vel(N) + Bf.ang_vel_in(N).cross(contact.pos_from(Cg))
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("ball", G, Bf, m, (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def rattleback_zyx() -> Reference:
    """Ellipsoid, body-fixed ZYX (psi, theta, phi), (x, y) contact, mass centre (d, e, f) from the centre."""
    x, y, psi, theta, phi = q = list(me.dynamicsymbols("x y psi theta phi"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("a b c d e f m Ixx Iyy Izz Ixy g")
    m, g = P["m"], P["g"]
    N = me.ReferenceFrame("N")
    R = me.ReferenceFrame("R")
    R.orient_body_fixed(N, (psi, theta, phi), "ZYX")
    Z1 = N.orientnew("Z1", "Axis", [psi, N.z])
    Y2 = Z1.orientnew("Y2", "Axis", [theta, Z1.y])
    # omega = psi' N.z + theta' Z1.y + phi' R.x, with u = q'
    R.set_ang_vel(N, u1 * N.z + u2 * Z1.y + u3 * R.x)
    kd = [psi.diff(t) - u1, theta.diff(t) - u2, phi.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    mu = [sp.simplify(N.z.dot(ax)) for ax in (R.x, R.y, R.z)]  # upward normal in body axes
    eps = sp.sqrt((P["a"] * mu[0])**2 + (P["b"] * mu[1])**2 + (P["c"] * mu[2])**2)
    # the surface point whose outward normal is -N.z: P - centre = -E^2 mu / eps
    centre_from_contact = (P["a"]**2 * mu[0] * R.x + P["b"]**2 * mu[1] * R.y + P["c"]**2 * mu[2] * R.z) / eps
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    G = Pc.locatenew("G", centre_from_contact + P["d"] * R.x + P["e"] * R.y + P["f"] * R.z)
    G.set_vel(N, Pc.vel(N) + G.pos_from(Pc).dt(N).subs(rates))
    material = G.vel(N) + R.ang_vel_in(N).cross(Pc.pos_from(G))
    cons = [material.dot(N.x), material.dot(N.y)]
    inertia = me.inertia(R, P["Ixx"], P["Iyy"], P["Izz"], P["Ixy"], 0, 0)
    body = me.RigidBody("shell", G, R, m, (inertia, G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def diff_drive_knife() -> Reference:
    """Chassis + 2 wheels; speeds v (forward, of G), theta', lateral speed of G, wheel rates."""
    x, y, th, pL, pR = q = list(me.dynamicsymbols("x y theta phi_L phi_R"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m_c I_1 I_2 I_3 m_w A_w C_w r w d c T_L T_R")
    r, w, d = P["r"], P["w"], P["d"]
    N = me.ReferenceFrame("N")
    Ch = N.orientnew("Ch", "Axis", [th, N.z])
    L = Ch.orientnew("L", "Axis", [pL, Ch.y])
    R = Ch.orientnew("R", "Axis", [pR, Ch.y])
    Ch.set_ang_vel(N, u2 * N.z)
    L.set_ang_vel(Ch, u4 * Ch.y)
    R.set_ang_vel(Ch, u5 * Ch.y)
    kd = [sp.cos(th) * x.diff(t) + sp.sin(th) * y.diff(t) - u1, th.diff(t) - u2,
          -sp.sin(th) * x.diff(t) + sp.cos(th) * y.diff(t) - u3, pL.diff(t) - u4, pR.diff(t) - u5]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + r * N.z)
    G.set_vel(N, u1 * Ch.x + u3 * Ch.y)
    M = G.locatenew("M", -d * Ch.x); M.v2pt_theory(G, N, Ch)
    HL = M.locatenew("HL", w * Ch.y); HL.v2pt_theory(M, N, Ch)
    HR = M.locatenew("HR", -w * Ch.y); HR.v2pt_theory(M, N, Ch)
    cl = HL.vel(N) + L.ang_vel_in(N).cross(-r * N.z)   # material contact point of each wheel
    cr = HR.vel(N) + R.ang_vel_in(N).cross(-r * N.z)
    cons = [cl.dot(Ch.x), cl.dot(Ch.y), cr.dot(Ch.x)]
    bodies = [me.RigidBody("chassis", G, Ch, P["m_c"], (me.inertia(Ch, P["I_1"], P["I_2"], P["I_3"]), G)),
              me.RigidBody("left", HL, L, P["m_w"], (me.inertia(L, P["A_w"], P["C_w"], P["A_w"]), HL)),
              me.RigidBody("right", HR, R, P["m_w"], (me.inertia(R, P["A_w"], P["C_w"], P["A_w"]), HR))]
    loads = [(L, P["T_L"] * Ch.y), (R, P["T_R"] * Ch.y), (Ch, -(P["T_L"] + P["T_R"]) * Ch.y),
             (G, -P["c"] * u1 * Ch.x)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2], u_dependent=[u3, u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1, u2], [u3, u4, u5], P, cons), _named(q))


def sphere_zxz() -> Reference:
    """Ball, ZXZ (phi, theta, psi), u = q', (x, y) geometric centre, mass centre e below it."""
    x, y, ph, th, ps = q = list(me.dynamicsymbols("x y phi theta psi"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r e A B C g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_body_fixed(N, (ph, th, ps), "ZXZ")
    Z1 = N.orientnew("Z1", "Axis", [ph, N.z])
    Bf.set_ang_vel(N, u1 * N.z + u2 * Z1.x + u3 * Bf.z)
    kd = [ph.diff(t) - u1, th.diff(t) - u2, ps.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    O = me.Point("O"); O.set_vel(N, 0)
    Cg = O.locatenew("Cg", x * N.x + y * N.y + r * N.z)
    Cg.set_vel(N, u4 * N.x + u5 * N.y)
    G = Cg.locatenew("G", -P["e"] * Bf.z)
    G.v2pt_theory(Cg, N, Bf)
    Pc = Cg.locatenew("Pc", -r * N.z)
    Pc.v2pt_theory(Cg, N, Bf)  # the material point at the contact
    cons = [Pc.vel(N).dot(N.x), Pc.vel(N).dot(N.y)]
    body = me.RigidBody("ball", G, Bf, m, (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def torus_contact() -> Reference:
    """Torus wheel: yaw, lean, spin; (x, y) contact; u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m R rho A C g")
    m, g = P["m"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    W = L.orientnew("W", "Axis", [spin, L.y])
    W.set_ang_vel(N, u1 * N.z + u2 * H.x + u3 * L.y)
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    Cw = Pc.locatenew("Cw", P["rho"] * N.z + P["R"] * L.z)
    Cw.set_vel(N, Pc.vel(N) + Cw.pos_from(Pc).dt(N).subs(rates))
    material = Cw.vel(N) + W.ang_vel_in(N).cross(Pc.pos_from(Cw))
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("wheel", Cw, W, m, (me.inertia(W, P["A"], P["C"], P["A"]), Cw))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(Cw, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def unicycle() -> Reference:
    """Wheel (yaw, lean, spin) + rider pitching about the axle; (x, y) contact; u = q'."""
    x, y, yaw, lean, spin, pitch = q = list(me.dynamicsymbols("x y yaw lean spin pitch"))
    u1, u2, u3, u4, u5, u6 = me.dynamicsymbols("u1:7")
    P = _symbols("m_w r A_w C_w m_r l I_1 I_2 I_3 T g")
    r, g = P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    W = L.orientnew("W", "Axis", [spin, L.y])
    Rd = L.orientnew("Rd", "Axis", [pitch, L.y])
    L.set_ang_vel(N, u1 * N.z + u2 * H.x)
    W.set_ang_vel(L, u3 * L.y)
    Rd.set_ang_vel(L, u4 * L.y)
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, pitch.diff(t) - u4,
          x.diff(t) - u5, y.diff(t) - u6]
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u5 * N.x + u6 * N.y)
    hub = Pc.locatenew("hub", r * L.z)
    hub.v2pt_theory(Pc, N, L)  # contact point and hub both fixed in L's geometry... (Pc moves: see below)
    hub.set_vel(N, Pc.vel(N) + L.ang_vel_in(N).cross(r * L.z))
    seat = hub.locatenew("seat", P["l"] * Rd.z)
    seat.v2pt_theory(hub, N, Rd)
    material = hub.vel(N) + W.ang_vel_in(N).cross(-r * L.z)
    cons = [material.dot(N.x), material.dot(N.y)]
    bodies = [me.RigidBody("wheel", hub, W, P["m_w"], (me.inertia(W, P["A_w"], P["C_w"], P["A_w"]), hub)),
              me.RigidBody("rider", seat, Rd, P["m_r"], (me.inertia(Rd, P["I_1"], P["I_2"], P["I_3"]), seat))]
    loads = [(hub, -P["m_w"] * g * N.z), (seat, -P["m_r"] * g * N.z), (W, P["T"] * L.y), (Rd, -P["T"] * L.y)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3, u4], u_dependent=[u5, u6], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1, u2, u3, u4], [u5, u6], P, cons), _named(q))


def disc_auto() -> Reference:
    """The ZXZ coin with independent speeds x', psi', theta' (gacli's automatic choice); y', phi' dependent."""
    x, y, psi, theta, phi = q = list(me.dynamicsymbols("x y psi theta phi"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [psi, N.z])
    T = A.orientnew("T", "Axis", [theta, A.x])
    D = T.orientnew("D", "Axis", [phi, T.z])
    D.set_ang_vel(N, u2 * N.z + u3 * A.x + u5 * T.z)
    kd = [x.diff(t) - u1, psi.diff(t) - u2, theta.diff(t) - u3, y.diff(t) - u4, phi.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    C = O.locatenew("C", x * N.x + y * N.y)
    C.set_vel(N, u1 * N.x + u4 * N.y)
    G = C.locatenew("G", r * T.y)
    G.set_vel(N, C.vel(N) + G.pos_from(C).dt(N).subs(rates))
    material = G.vel(N) + D.ang_vel_in(N).cross(C.pos_from(G))
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("coin", G, D, m, (me.inertia(D, m * r**2 / 4, m * r**2 / 4, m * r**2 / 2), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def rattleback_xyz_rates() -> Reference:
    """Ellipsoid, body-fixed XYZ angles, body rates u1..u3, (x, y) contact, mass centre h below the centre."""
    x, y, al, be, ga = q = list(me.dynamicsymbols("x y alpha beta gamma"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("a b c h m A B C delta g")
    m, g, dl = P["m"], P["g"], P["delta"]
    N = me.ReferenceFrame("N")
    R = me.ReferenceFrame("R")
    R.orient_body_fixed(N, (al, be, ga), "XYZ")
    natural = R.ang_vel_in(N)
    R.set_ang_vel(N, u1 * R.x + u2 * R.y + u3 * R.z)
    kd = [sp.trigsimp(natural.dot(ax)) - ui for ax, ui in zip((R.x, R.y, R.z), (u1, u2, u3))]
    kd += [x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    mu = [sp.trigsimp(N.z.dot(ax)) for ax in (R.x, R.y, R.z)]
    eps = sp.sqrt((P["a"] * mu[0])**2 + (P["b"] * mu[1])**2 + (P["c"] * mu[2])**2)
    centre_from_contact = (P["a"]**2 * mu[0] * R.x + P["b"]**2 * mu[1] * R.y + P["c"]**2 * mu[2] * R.z) / eps
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    G = Pc.locatenew("G", centre_from_contact - P["h"] * R.z)
    G.set_vel(N, Pc.vel(N) + G.pos_from(Pc).dt(N).subs(rates))
    material = G.vel(N) + R.ang_vel_in(N).cross(Pc.pos_from(G))
    cons = [material.dot(N.x), material.dot(N.y)]
    A_, B_ = P["A"], P["B"]
    Ixx = A_ * sp.cos(dl)**2 + B_ * sp.sin(dl)**2
    Iyy = A_ * sp.sin(dl)**2 + B_ * sp.cos(dl)**2
    Ixy = (A_ - B_) * sp.sin(dl) * sp.cos(dl)
    body = me.RigidBody("rb", G, R, m, (me.inertia(R, Ixx, Iyy, P["C"], Ixy, 0, 0), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def disc_centre_q() -> Reference:
    """SymPy's disc (yaw, lean, spin), (x, y) the centre, u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    D.set_ang_vel(N, u1 * N.z + u2 * H.x + u3 * L.y)
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + r * sp.cos(lean) * N.z)
    G.set_vel(N, G.pos_from(O).dt(N).subs(rates))
    material = G.vel(N) + D.ang_vel_in(N).cross(-r * L.z)
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def disc_incline() -> Reference:
    """Disc on a slope turned by alpha about N.y; (x, y) contact in slope axes; u = q'."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r alpha g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    S = N.orientnew("S", "Axis", [P["alpha"], N.y])
    H = S.orientnew("H", "Axis", [yaw, S.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    D.set_ang_vel(N, u1 * S.z + u2 * H.x + u3 * L.y)
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * S.x + y * S.y)
    Pc.set_vel(N, u4 * S.x + u5 * S.y)
    G = Pc.locatenew("G", r * L.z)
    G.set_vel(N, Pc.vel(N) + G.pos_from(Pc).dt(N).subs(rates))
    material = G.vel(N) + D.ang_vel_in(N).cross(-r * L.z)
    cons = [material.dot(S.x), material.dot(S.y)]
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


def ball_quaternion() -> Reference:
    """Ball, orient_quaternion (e0..e3), body rates u1..u3, (x, y) geometric centre; x', y' dependent."""
    x, y, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y e0 e1 e2 e3"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r d e A B C g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_quaternion(N, [e0, e1, e2, e3])
    Bf.set_ang_vel(N, u1 * Bf.x + u2 * Bf.y + u3 * Bf.z)
    E = sp.Matrix([[-e1, e0, e3, -e2], [-e2, -e3, e0, e1], [-e3, e2, -e1, e0]])
    qdot = E.T * sp.Matrix([u1, u2, u3]) / 2
    kd = [x.diff(t) - u4, y.diff(t) - u5] + [qi.diff(t) - qdot[i] for i, qi in enumerate((e0, e1, e2, e3))]
    O = me.Point("O"); O.set_vel(N, 0)
    Cg = O.locatenew("Cg", x * N.x + y * N.y + r * N.z)
    Cg.set_vel(N, u4 * N.x + u5 * N.y)
    G = Cg.locatenew("G", P["d"] * Bf.x - P["e"] * Bf.z)
    G.v2pt_theory(Cg, N, Bf)
    Pc = Cg.locatenew("Pc", -r * N.z)
    Pc.v2pt_theory(Cg, N, Bf)
    cons = [Pc.vel(N).dot(N.x), Pc.vel(N).dot(N.y)]
    body = me.RigidBody("ball", G, Bf, m, (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q),
                     configuration=norm, q_dep=[e0], spread=0.5)


def disc_quaternion() -> Reference:
    """Disc in a quaternion frame, body rates u1..u3, (x, y) contact; centre = contact + r*unit(n - (n.a)a)."""
    x, y, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y e0 e1 e2 e3"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    D = me.ReferenceFrame("D")
    D.orient_quaternion(N, [e0, e1, e2, e3])
    D.set_ang_vel(N, u1 * D.x + u2 * D.y + u3 * D.z)
    E = sp.Matrix([[-e1, e0, e3, -e2], [-e2, -e3, e0, e1], [-e3, e2, -e1, e0]])
    qdot = E.T * sp.Matrix([u1, u2, u3]) / 2
    kd = [x.diff(t) - u4, y.diff(t) - u5] + [qi.diff(t) - qdot[i] for i, qi in enumerate((e0, e1, e2, e3))]
    rates = _solved_rates(kd, q)
    up = N.z - N.z.dot(D.y) * D.y        # the upward direction in the disc's plane
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Pc.set_vel(N, u4 * N.x + u5 * N.y)
    G = Pc.locatenew("G", r * up / sp.sqrt(up.dot(up)))
    G.set_vel(N, Pc.vel(N) + G.pos_from(Pc).dt(N).subs(rates))
    material = G.vel(N) + D.ang_vel_in(N).cross(Pc.pos_from(G))
    cons = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q),
                     configuration=norm, q_dep=[e0], spread=0.5)


def segway() -> Reference:
    """Self-balancing robot; body inertia given about the axle point (SymPy's RigidBody moves it)."""
    x, y, th, pitch, pL, pR = q = list(me.dynamicsymbols("x y theta pitch phi_L phi_R"))
    u1, u2, u3, u4, u5, u6 = me.dynamicsymbols("u1:7")
    P = _symbols("m_b J_1 J_2 J_3 l m_w A_w C_w r w T_L T_R g")
    r, w, g = P["r"], P["w"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [th, N.z])
    Bd = H.orientnew("Bd", "Axis", [pitch, H.y])
    L = H.orientnew("L", "Axis", [pL, H.y])
    R = H.orientnew("R", "Axis", [pR, H.y])
    H.set_ang_vel(N, u6 * N.z)
    Bd.set_ang_vel(H, u1 * H.y)
    L.set_ang_vel(H, u2 * H.y)
    R.set_ang_vel(H, u3 * H.y)
    kd = [pitch.diff(t) - u1, pL.diff(t) - u2, pR.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5, th.diff(t) - u6]
    O = me.Point("O"); O.set_vel(N, 0)
    Ax = O.locatenew("Ax", x * N.x + y * N.y + r * N.z)
    Ax.set_vel(N, u4 * N.x + u5 * N.y)
    G = Ax.locatenew("G", P["l"] * Bd.z); G.v2pt_theory(Ax, N, Bd)
    HL = Ax.locatenew("HL", w * H.y); HL.v2pt_theory(Ax, N, H)
    HR = Ax.locatenew("HR", -w * H.y); HR.v2pt_theory(Ax, N, H)
    cl = HL.vel(N) + L.ang_vel_in(N).cross(-r * N.z)
    cr = HR.vel(N) + R.ang_vel_in(N).cross(-r * N.z)
    cons = [cl.dot(N.x), cl.dot(N.y), cr.dot(H.x)]
    body = me.RigidBody("body", G, Bd, P["m_b"], (me.inertia(Bd, P["J_1"], P["J_2"], P["J_3"]), Ax))
    bodies = [body,
              me.RigidBody("left", HL, L, P["m_w"], (me.inertia(L, P["A_w"], P["C_w"], P["A_w"]), HL)),
              me.RigidBody("right", HR, R, P["m_w"], (me.inertia(R, P["A_w"], P["C_w"], P["A_w"]), HR))]
    loads = [(G, -P["m_b"] * g * N.z), (HL, -P["m_w"] * g * N.z), (HR, -P["m_w"] * g * N.z),
             (L, P["T_L"] * H.y), (R, P["T_R"] * H.y), (Bd, -(P["T_L"] + P["T_R"]) * H.y)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5, u6], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5, u6], P, cons), _named(q))


SYSTEMS = {
    "disc_zxz_pfaff": (HERE / "disc_zxz_pfaff.yaml", disc_zxz, "coin, ZXZ angles, axle z, hand no-slip rows, u = q'"),
    "disc_body_rates": (HERE / "disc_body_rates.yaml", disc_body_rates,
                        "wheel, wheel-fixed rates as speeds, centre coordinates, rolling key, drag"),
    "ball_offset_xyz": (HERE / "ball_offset_xyz.yaml", ball_offset_xyz,
                        "Chaplygin top, XYZ angles, inertial angular velocity as speeds, rolling + centre"),
    "rattleback_zyx": (HERE / "rattleback_zyx.yaml", rattleback_zyx,
                       "rattleback, ZYX angles, rolling semi_axes + contact + centre, u = q'"),
    "diff_drive_knife": (HERE / "diff_drive_knife.yaml", diff_drive_knife,
                         "differential drive, knife edge + hand rows, forward speed quasi-coordinate"),
    "disc_zxz_rolling": (HERE / "disc_zxz_rolling.yaml", disc_zxz, "coin, ZXZ angles, axle z, rolling key, u = q'"),
    "sphere_zxz_pfaff": (HERE / "sphere_zxz_pfaff.yaml", sphere_zxz,
                         "unbalanced ball A,B,C, ZXZ, hand no-slip rows, potential, u = q'"),
    "torus_contact": (HERE / "torus_contact.yaml", torus_contact,
                      "torus wheel, one frame chain, placed by contact, u = q'"),
    "unicycle": (HERE / "unicycle.yaml", unicycle, "unicycle: wheel + pitching rider, rolling, pedal torque, k = 4"),
    "disc_auto_independent": (HERE / "disc_auto_independent.yaml", disc_auto,
                              "ZXZ coin, hand rows, no `independent` (gacli picks x, psi, theta)"),
    "rattleback_xyz_rates": (HERE / "rattleback_xyz_rates.yaml", rattleback_xyz_rates,
                             "rattleback, XYZ angles, body rates, rolling semi_axes + contact + centre"),
    "disc_rows_mixed": (HERE / "disc_rows_mixed.yaml", disc_centre_q,
                        "disc, centre coordinates, forward/sideways hand rows (not solved for dx, dy)"),
    "disc_incline": (HERE / "disc_incline.yaml", disc_incline, "disc on a fixed incline, rolling on: slope, u = q'"),
    "ball_quaternion": (HERE / "ball_quaternion.yaml", ball_quaternion,
                        "Chaplygin top, quaternion frame with body rates, rolling + centre"),
    "disc_quaternion": (HERE / "disc_quaternion.yaml", disc_quaternion,
                        "thin disc, quaternion frame with body rates, rolling wheel placed by contact"),
    "segway_inertia_about": (HERE / "segway_inertia_about.yaml", segway,
                             "self-balancing robot, body inertia_about the axle, rolling wheels, motor torques"),
    "ball_quasi_rows": (HERE / "ball_quasi_rows.yaml", ball_offset_xyz,
                        "Chaplygin top, XYZ, inertial rates, rows dx = r*dw_y written by hand"),
}
