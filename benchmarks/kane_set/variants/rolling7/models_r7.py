"""KanesMethod references for the r7_ rolling bodies, built from the definitions.

Rolling constraints are the material point of the body at the contact at rest
(plane fixed), formed from the geometry here, never copied from a YAML file.
"""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _solve_rates(kd, q):
    qd = [qi.diff(t) for qi in q]
    return sp.solve(kd, qd, dict=True)[0]


def _vel(point, O, N, rates):
    return point.pos_from(O).dt(N).subs(rates)


def _build(N, O, q, u_ind, u_dep, kd, body_frame, w, G, contact, plane_axes, mass, inertia_dyadic,
           P, gravity_dir, extra=()):
    rates = _solve_rates(kd, q)
    body_frame.set_ang_vel(N, w)
    G.set_vel(N, _vel(G, O, N, rates))
    material = G.vel(N) + w.cross(contact.pos_from(G))
    constraints = [material.dot(e) for e in plane_axes]
    body = me.RigidBody("body", G, body_frame, mass, (inertia_dyadic, G))
    bodies = [body]
    loads = [(G, -mass * P["g"] * gravity_dir)]
    for name, point, mp in extra:
        point.set_vel(N, G.vel(N) + w.cross(point.pos_from(G)))
        bodies.append(me.Particle(name, point, mp))
        loads.append((point, -mp * P["g"] * gravity_dir))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u_ind, u_dependent=u_dep, kd_eqs=kd,
                          velocity_constraints=constraints)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u_ind, u_dep, P, constraints), _named(q))


def _ellipsoid_contact_offset(N_z, R, a, b, c):
    """P - C for an ellipsoid whose outward normal at P is -N_z: -E^2 mu / sqrt(mu^T E^2 mu)."""
    mu = [N_z.dot(R.x), N_z.dot(R.y), N_z.dot(R.z)]
    eps = sp.sqrt((a * mu[0])**2 + (b * mu[1])**2 + (c * mu[2])**2)
    return -(a**2 * mu[0] * R.x + b**2 * mu[1] * R.y + c**2 * mu[2] * R.z) / eps


# -- r7_a: rattleback, yaw-roll-pitch, full inertia, offset mass centre -------------------
def r7_a():
    yaw, roll, pitch, x, y = q = list(me.dynamicsymbols("yaw roll pitch x y"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("a b c e1 e2 h m Ixx Iyy Izz Ixy Iyz Ixz g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [roll, Y.x])
    R = L.orientnew("R", "Axis", [pitch, L.y])
    kd = [yaw.diff(t) - u1, roll.diff(t) - u2, pitch.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    w = u1 * N.z + u2 * Y.x + u3 * L.y
    O = me.Point("O"); O.set_vel(N, 0)
    contact = O.locatenew("P", x * N.x + y * N.y)
    Cg = contact.locatenew("C", -_ellipsoid_contact_offset(N.z, R, P["a"], P["b"], P["c"]))
    G = Cg.locatenew("G", -(P["e1"] * R.x + P["e2"] * R.y + P["h"] * R.z))
    I = me.inertia(R, P["Ixx"], P["Iyy"], P["Izz"], P["Ixy"], P["Iyz"], P["Ixz"])
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, R, w, G, contact, [N.x, N.y], P["m"], I, P, N.z)


# -- r7_b: rattleback, body XYZ angles, body rates ------------------------------------------
def r7_b():
    q1, q2, q3, x, y = q = list(me.dynamicsymbols("q1 q2 q3 x y"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("a b c h m A B C g")
    N = me.ReferenceFrame("N")
    R = N.orientnew("R", "Body", [q1, q2, q3], "XYZ")
    nat = R.ang_vel_in(N)  # in q'
    kd = [nat.dot(R.x) - u1, nat.dot(R.y) - u2, nat.dot(R.z) - u3, x.diff(t) - u4, y.diff(t) - u5]
    w = u1 * R.x + u2 * R.y + u3 * R.z
    O = me.Point("O"); O.set_vel(N, 0)
    contact = O.locatenew("P", x * N.x + y * N.y)
    Cg = contact.locatenew("C", -_ellipsoid_contact_offset(N.z, R, P["a"], P["b"], P["c"]))
    G = Cg.locatenew("G", -P["h"] * R.z)
    I = me.inertia(R, P["A"], P["B"], P["C"])
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, R, w, G, contact, [N.x, N.y], P["m"], I, P, N.z)


# -- r7_c: rattleback, ZYX, inertia along a skewed frame ---------------------------------------
def r7_c():
    yaw, pitch, roll, x, y = q = list(me.dynamicsymbols("yaw pitch roll x y"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("a b c h m A B C delta eps g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    Pt = Y.orientnew("Pt", "Axis", [pitch, Y.y])
    R = Pt.orientnew("R", "Axis", [roll, Pt.x])
    K1 = R.orientnew("K1", "Axis", [P["delta"], R.z])
    K = K1.orientnew("K", "Axis", [P["eps"], K1.x])
    kd = [yaw.diff(t) - u1, pitch.diff(t) - u2, roll.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    w = u1 * N.z + u2 * Y.y + u3 * Pt.x
    O = me.Point("O"); O.set_vel(N, 0)
    contact = O.locatenew("P", x * N.x + y * N.y)
    Cg = contact.locatenew("C", -_ellipsoid_contact_offset(N.z, R, P["a"], P["b"], P["c"]))
    G = Cg.locatenew("G", -P["h"] * R.z)
    I = me.inertia(K, P["A"], P["B"], P["C"])
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, R, w, G, contact, [N.x, N.y], P["m"], I, P, N.z)


# -- r7_d: thin disc on an inclined plane --------------------------------------------------------
def r7_d():
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r g alpha")
    N = me.ReferenceFrame("N")
    Pl = N.orientnew("Pl", "Axis", [P["alpha"], N.x])
    Y = Pl.orientnew("Y", "Axis", [yaw, Pl.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    w = u1 * Pl.z + u2 * Y.x + u3 * L.y
    O = me.Point("O"); O.set_vel(N, 0)
    contact = O.locatenew("P", x * Pl.x + y * Pl.y)
    G = contact.locatenew("G", P["r"] * L.z)
    m, r = P["m"], P["r"]
    I = me.inertia(D, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4)
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, D, w, G, contact, [Pl.x, Pl.y], m, I, P, N.z)


# -- r7_e: torus ----------------------------------------------------------------------------------
def r7_e():
    yaw, lean, spin, x, y = q = list(me.dynamicsymbols("yaw lean spin x y"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m R rho A C g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    w = u1 * N.z + u2 * Y.x + u3 * L.y
    O = me.Point("O"); O.set_vel(N, 0)
    contact = O.locatenew("P", x * N.x + y * N.y)
    # the tube's centre nearest the plane is R along L.z from... : hub = contact + rho N.z + R L.z
    G = contact.locatenew("G", P["rho"] * N.z + P["R"] * L.z)
    I = me.inertia(D, P["A"], P["C"], P["A"])
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, D, w, G, contact, [N.x, N.y], P["m"], I, P, N.z)


# -- r7_f: disc with a rim mass -------------------------------------------------------------------
def r7_f():
    yaw, lean, spin, x, y = q = list(me.dynamicsymbols("yaw lean spin x y"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m mp r g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    w = u1 * N.z + u2 * Y.x + u3 * L.y
    O = me.Point("O"); O.set_vel(N, 0)
    contact = O.locatenew("P", x * N.x + y * N.y)
    m, r = P["m"], P["r"]
    G = contact.locatenew("G", r * L.z)
    rim = G.locatenew("rim", r * D.x)
    I = me.inertia(D, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4)
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, D, w, G, contact, [N.x, N.y], m, I, P, N.z,
                  extra=[("bead", rim, P["mp"])])


# -- r7_g: unbalanced ball, unequal moments, ZYZ --------------------------------------------------
def r7_g():
    x, y, phi, theta, psi = q = list(me.dynamicsymbols("x y phi theta psi"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r e1 e3 A B C g")
    N = me.ReferenceFrame("N")
    R = N.orientnew("R", "Body", [phi, theta, psi], "ZYZ")
    nat = R.ang_vel_in(N)
    qd = {phi.diff(t): u1, theta.diff(t): u2, psi.diff(t): u3}
    w = nat.subs(qd)
    kd = [phi.diff(t) - u1, theta.diff(t) - u2, psi.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    O = me.Point("O"); O.set_vel(N, 0)
    contact = O.locatenew("P", x * N.x + y * N.y)
    Cg = contact.locatenew("C", P["r"] * N.z)
    G = Cg.locatenew("G", -(P["e1"] * R.x + P["e3"] * R.z))
    I = me.inertia(R, P["A"], P["B"], P["C"])
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, R, w, G, contact, [N.x, N.y], P["m"], I, P, N.z)


# -- r7_h: top sliding on a frictionless plane ----------------------------------------------------
def r7_h():
    x, y, phi, theta, psi = q = list(me.dynamicsymbols("x y phi theta psi"))
    u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("m l A C g")
    N = me.ReferenceFrame("N")
    R = N.orientnew("R", "Body", [phi, theta, psi], "ZXZ")
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    rates = _solve_rates(kd, q)
    R.set_ang_vel(N, R.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    tip = O.locatenew("T", x * N.x + y * N.y)
    G = tip.locatenew("G", P["l"] * R.z)
    G.set_vel(N, _vel(G, O, N, rates))
    body = me.RigidBody("top", G, R, P["m"], (me.inertia(R, P["A"], P["A"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- r7_i: rolling coin, centre coordinates -------------------------------------------------------
def r7_i():
    x, y, psi, theta, phi = q = list(me.dynamicsymbols("x y psi theta phi"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("m r A C g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [psi, N.z])
    L = Y.orientnew("L", "Axis", [theta, Y.x])
    D = L.orientnew("D", "Axis", [phi, L.y])
    kd = [psi.diff(t) - u1, theta.diff(t) - u2, phi.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    w = u1 * N.z + u2 * Y.x + u3 * L.y
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + P["r"] * sp.cos(theta) * N.z)
    contact = G.locatenew("P", -P["r"] * L.z)
    I = me.inertia(D, P["A"], P["C"], P["A"])
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, D, w, G, contact, [N.x, N.y], P["m"], I, P, N.z)


SYSTEMS = {
    f"r7_{k}": (HERE / f"r7_{k}.yaml", globals()[f"r7_{k}"], None) for k in "abcdefghi"
}


# -- r7_j: rattleback on an incline ---------------------------------------------------------------
def r7_j():
    yaw, lean, pitch, x, y = q = list(me.dynamicsymbols("yaw lean pitch x y"))
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    P = _symbols("a b c h m A B C Ixy alpha g")
    N = me.ReferenceFrame("N")
    Pl = N.orientnew("Pl", "Axis", [P["alpha"], N.y])
    Y = Pl.orientnew("Y", "Axis", [yaw, Pl.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    R = L.orientnew("R", "Axis", [pitch, L.y])
    kd = [yaw.diff(t) - u1, lean.diff(t) - u2, pitch.diff(t) - u3, x.diff(t) - u4, y.diff(t) - u5]
    w = u1 * Pl.z + u2 * Y.x + u3 * L.y
    O = me.Point("O"); O.set_vel(N, 0)
    contact = O.locatenew("P", x * Pl.x + y * Pl.y)
    Cg = contact.locatenew("C", -_ellipsoid_contact_offset(Pl.z, R, P["a"], P["b"], P["c"]))
    G = Cg.locatenew("G", -P["h"] * R.z)
    I = me.inertia(R, P["A"], P["B"], P["C"], P["Ixy"], 0, 0)
    return _build(N, O, q, [u1, u2, u3], [u4, u5], kd, R, w, G, contact, [Pl.x, Pl.y], P["m"], I, P, N.z)


SYSTEMS["r7_j"] = (HERE / "r7_j.yaml", r7_j, None)
