"""r5 rolling bodies: KanesMethod references written from the physics.

Each model: the contact point's material velocity equals the surface's
velocity there (the plane at rest, or turning), rows along the plane's axes;
the body placed from geometry worked out here, not read from the gacli file.
"""
from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from models import Reference, _named, _symbols
from bench_kane import KaneModel

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _rates(kd, q):
    qd = [qi.diff(t) for qi in q]
    sol = sp.solve(kd, qd, dict=True)[0]
    return {k: sp.simplify(v) for k, v in sol.items()}


def _vel_from_position(point, origin, frame, rates):
    """v of a point from the time derivative of its position, q' replaced by the speeds."""
    v = point.pos_from(origin).dt(frame).subs(rates)
    point.set_vel(frame, v)
    return v


def _no_slip(centre, body_frame, contact, N, rows_along, surface_velocity=0):
    """Rows of the material point of the body at the contact minus the surface's velocity."""
    material = centre.vel(N) + body_frame.ang_vel_in(N).cross(contact.pos_from(centre))
    rel = material - surface_velocity if surface_velocity != 0 else material
    return [sp.trigsimp(sp.expand(rel.dot(e))) for e in rows_along]


# 1 ------------------------------------------------------------------------------
def disc_lrates() -> Reference:
    """SymPy test_kane: yaw z, lean x, spin y; u1..u3 = omega of R along L; x', y' dependent."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r g T")
    m, r, g, T = P["m"], P["r"], P["g"], P["T"]
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    R = L.orientnew("R", "Axis", [spin, L.y])
    w_qd = R.ang_vel_in(N)
    R.set_ang_vel(N, u1 * L.x + u2 * L.y + u3 * L.z)
    kd = [w_qd.dot(L.x) - u1, w_qd.dot(L.y) - u2, w_qd.dot(L.z) - u3,
          x.diff(t) - u4, y.diff(t) - u5]
    rates = _rates(kd, q)
    O = me.Point("O"); O.set_vel(N, 0)
    C = O.locatenew("C", x * N.x + y * N.y)
    Dmc = C.locatenew("Dmc", r * L.z)
    _vel_from_position(Dmc, O, N, rates)
    cons = _no_slip(Dmc, R, C, N, [N.x, N.y])
    disc = me.RigidBody("disc", Dmc, R, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), Dmc))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([disc], [(Dmc, -m * g * N.z), (R, T * L.y)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


# 2 ------------------------------------------------------------------------------
def disc_zyx_contact() -> Reference:
    """Disc axle D.x, D from N by body ZYX (yaw, lean, spin); u = [spin', yaw', lean']."""
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.y])
    D = L.orientnew("D", "Axis", [spin, L.x])
    kd = [spin.diff(t) - u1, yaw.diff(t) - u2, lean.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _rates(kd, q)
    D.set_ang_vel(N, D.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    # the disc's plane is spanned by L.y, L.z (axle L.x = D.x); N.z is in span(L.x, L.z),
    # so the in-plane direction nearest the vertical is L.z (cos(lean) > 0).
    G = Pc.locatenew("G", r * L.z)
    _vel_from_position(G, O, N, rates)
    cons = _no_slip(G, D, Pc, N, [N.x, N.y])
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, P["C"], P["A"], P["A"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


# 3 ------------------------------------------------------------------------------
def disc_pointmass() -> Reference:
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m mp e r g")
    m, mp, e, r, g = P["m"], P["mp"], P["e"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    W = L.orientnew("W", "Axis", [spin, L.y])
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _rates(kd, q)
    W.set_ang_vel(N, W.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    hub = Pc.locatenew("hub", r * L.z)
    lump = hub.locatenew("lump", e * W.x)
    _vel_from_position(hub, O, N, rates)
    _vel_from_position(lump, O, N, rates)
    cons = _no_slip(hub, W, Pc, N, [N.x, N.y])
    disc = me.RigidBody("disc", hub, W, m, (me.inertia(W, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), hub))
    weight = me.Particle("weight", lump, mp)
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([disc, weight], [(hub, -m * g * N.z), (lump, -mp * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


# 4 ------------------------------------------------------------------------------
def rattleback_zyx() -> Reference:
    """Ellipsoid, body ZYX (yaw, pitch, roll); contact (x, y); u = [roll', pitch', yaw']."""
    x, y, yaw, pitch, roll = q = list(me.dynamicsymbols("x y yaw pitch roll"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("a b c h m Ixx Iyy Izz Ixy g")
    a, b, c, h, m, g = (P[k] for k in "a b c h m g".split())
    N = me.ReferenceFrame("N")
    S = N.orientnew("S", "Body", [yaw, pitch, roll], "ZYX")
    kd = [roll.diff(t) - u1, pitch.diff(t) - u2, yaw.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _rates(kd, q)
    S.set_ang_vel(N, S.ang_vel_in(N).subs(rates))
    # the surface point whose outward normal is -N.z: in body axes p = -E n / sqrt(n^T E n)
    n = [N.z.dot(S.x), N.z.dot(S.y), N.z.dot(S.z)]
    E = [a**2, b**2, c**2]
    s = sp.sqrt(sum(Ei * ni**2 for Ei, ni in zip(E, n)))
    centre_from_contact = sum((Ei * ni / s * ax for Ei, ni, ax in zip(E, n, (S.x, S.y, S.z))), me.Vector(0))
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    Cg = Pc.locatenew("Cg", centre_from_contact)
    G = Cg.locatenew("G", -h * S.z)     # the mass centre h below the geometric centre
    _vel_from_position(G, O, N, rates)
    cons = _no_slip(G, S, Pc, N, [N.x, N.y])
    I = me.inertia(S, P["Ixx"], P["Iyy"], P["Izz"], P["Ixy"], 0, 0)
    body = me.RigidBody("rattleback", G, S, m, (I, G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


# 5 ------------------------------------------------------------------------------
def ball_tilted_turntable() -> Reference:
    """Ball A, B, C on a table tilted by beta about N.x, turning at Om about its normal."""
    x, y, q1, q2, q3 = q = list(me.dynamicsymbols("x y q1 q2 q3"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A B C beta Om g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    Tilt = N.orientnew("Tilt", "Axis", [P["beta"], N.x])
    Tb = Tilt.orientnew("Tb", "Axis", [P["Om"] * t, Tilt.z])
    Bf = Tb.orientnew("Bf", "Body", [q1, q2, q3], "XYZ")
    kd = [x.diff(t) - u1, y.diff(t) - u2, q3.diff(t) - u3, q1.diff(t) - u4, q2.diff(t) - u5]
    rates = _rates(kd, q)
    Bf.set_ang_vel(N, Bf.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * Tb.x + y * Tb.y + r * Tb.z)
    _vel_from_position(G, O, N, rates)
    Pc = G.locatenew("Pc", -r * Tb.z)
    table_point_velocity = Tb.ang_vel_in(N).cross(Pc.pos_from(O))
    cons = _no_slip(G, Bf, Pc, N, [Tb.x, Tb.y], table_point_velocity)
    body = me.RigidBody("ball", G, Bf, m, (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


# 6 ------------------------------------------------------------------------------
def cart_axle() -> Reference:
    """Chassis CoM (x, y), heading theta, wheels phi_L, phi_R; u1 = forward speed, u2 = theta'."""
    x, y, theta, phL, phR = q = list(me.dynamicsymbols("x y theta phi_L phi_R"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m_c I_c I_cx I_cy m_w A_w C_w r w d h T_L T_R")
    r, w, d, h = P["r"], P["w"], P["d"], P["h"]
    N = me.ReferenceFrame("N")
    Cf = N.orientnew("Cf", "Axis", [theta, N.z])
    WL = Cf.orientnew("WL", "Axis", [phL, Cf.y])
    WR = Cf.orientnew("WR", "Axis", [phR, Cf.y])
    kd = [u1 - (sp.cos(theta) * x.diff(t) + sp.sin(theta) * y.diff(t)), u2 - theta.diff(t),
          u3 - (-sp.sin(theta) * x.diff(t) + sp.cos(theta) * y.diff(t)), u4 - phL.diff(t), u5 - phR.diff(t)]
    rates = _rates(kd, q)
    for F in (Cf, WL, WR):
        F.set_ang_vel(N, F.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    cm = O.locatenew("cm", x * N.x + y * N.y + (r + h) * N.z)
    mid = cm.locatenew("mid", -d * Cf.x - h * N.z)
    hubL = mid.locatenew("hubL", w * Cf.y)
    hubR = mid.locatenew("hubR", -w * Cf.y)
    for pt in (cm, hubL, hubR):
        _vel_from_position(pt, O, N, rates)
    cL = hubL.locatenew("cL", -r * N.z)
    cR = hubR.locatenew("cR", -r * N.z)
    rowsL = _no_slip(hubL, WL, cL, N, [Cf.x, Cf.y])
    rowsR = _no_slip(hubR, WR, cR, N, [Cf.x])
    cons = rowsL + rowsR
    chassis = me.RigidBody("chassis", cm, Cf, P["m_c"], (me.inertia(Cf, P["I_cx"], P["I_cy"], P["I_c"]), cm))
    wl = me.RigidBody("wheel_L", hubL, WL, P["m_w"], (me.inertia(WL, P["A_w"], P["C_w"], P["A_w"]), hubL))
    wr = me.RigidBody("wheel_R", hubR, WR, P["m_w"], (me.inertia(WR, P["A_w"], P["C_w"], P["A_w"]), hubR))
    loads = [(WL, P["T_L"] * Cf.y), (WR, P["T_R"] * Cf.y), (Cf, -(P["T_L"] + P["T_R"]) * Cf.y)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2], u_dependent=[u3, u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([chassis, wl, wr], loads)
    return Reference(KaneModel(kane, q, [u1, u2], [u3, u4, u5], P, cons), _named(q))


# 7 ------------------------------------------------------------------------------
def torus_incline() -> Reference:
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m R rho A C alpha g")
    m, R, rho, g = P["m"], P["R"], P["rho"], P["g"]
    N = me.ReferenceFrame("N")
    I = N.orientnew("I", "Axis", [P["alpha"], N.y])
    H = I.orientnew("H", "Axis", [yaw, I.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    W = L.orientnew("W", "Axis", [spin, L.y])
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _rates(kd, q)
    W.set_ang_vel(N, W.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * I.x + y * I.y)
    # tube centre over the contact: rho along the incline's normal; torus centre R along
    # the wheel-plane direction perpendicular to the axle nearest that normal (L.z)
    G = Pc.locatenew("G", rho * I.z + R * L.z)
    _vel_from_position(G, O, N, rates)
    cons = _no_slip(G, W, Pc, N, [I.x, I.y])
    body = me.RigidBody("torus", G, W, m, (me.inertia(W, P["A"], P["C"], P["A"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


SYSTEMS = {
    "r5_disc_lrates": (HERE / "r5_disc_lrates.yaml", disc_lrates,
                       "disc, SymPy test_kane: lean-frame omega components as quasi-coordinate speeds, axle torque"),
    "r5_disc_zyx_contact": (HERE / "r5_disc_zyx_contact.yaml", disc_zyx_contact,
                            "disc, body ZYX sequence, axle x, placed by contact, u = q' (spin, yaw, lean)"),
    "r5_disc_pointmass": (HERE / "r5_disc_pointmass.yaml", disc_pointmass,
                          "disc carrying an off-centre point mass, frames + rolling, u = q'"),
    "r5_rattleback_zyx": (HERE / "r5_rattleback_zyx.yaml", rattleback_zyx,
                          "rattleback, ZYX angles, Ixy product, placed by contact, u = q' (roll, pitch, yaw)"),
    "r5_ball_tilted_turntable": (HERE / "r5_ball_tilted_turntable.yaml", ball_tilted_turntable,
                                 "ball A,B,C on a tilted turntable turning at Om, XYZ angles, u = x', y', q3'"),
    "r5_cart_axle": (HERE / "r5_cart_axle.yaml", cart_axle,
                     "two-wheeled cart, common axle, motors with reaction, speeds v and theta'"),
    "r5_torus_incline": (HERE / "r5_torus_incline.yaml", torus_incline,
                         "torus on an incline, placed by contact in the incline's axes, u = q'"),
}


# 8 ------------------------------------------------------------------------------
def disc_turntable() -> Reference:
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C Om g")
    m, r, g = P["m"], P["r"], P["g"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [lean, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    rates = _rates(kd, q)
    D.set_ang_vel(N, D.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)
    G = Pc.locatenew("G", r * L.z)
    _vel_from_position(G, O, N, rates)
    table_point = P["Om"] * N.z.cross(Pc.pos_from(O))   # the turntable's material point under the disc
    cons = _no_slip(G, D, Pc, N, [N.x, N.y], table_point)
    body = me.RigidBody("disc", G, D, m, (me.inertia(D, P["A"], P["C"], P["A"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, cons), _named(q))


SYSTEMS["r5_disc_turntable"] = (HERE / "r5_disc_turntable.yaml", disc_turntable,
                                "disc on a turntable turning at Om, angles from N, placed by contact, u = q'")

SYSTEMS["r5_disc_turntable_pts"] = (HERE / "r5_disc_turntable_pts.yaml", disc_turntable,
                                    "the same disc on a turntable, centre given as a point (no contact:)")

SYSTEMS["r5_torus_incline_pts"] = (HERE / "r5_torus_incline_pts.yaml", torus_incline,
                                   "the same torus, centre given as a point (no contact:)")
