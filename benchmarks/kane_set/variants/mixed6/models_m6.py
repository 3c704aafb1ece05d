"""KanesMethod references for the m6_ systems, built from the physics.

Loops are closed from their definition (the two ends of a cut joint at the
same place, a point held on its rail), rolling from the material contact
point at rest; never from a gacli file's constraint rows.
"""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _frame(parent, name, q, u, axis="z"):
    a = getattr(parent, axis)
    F = parent.orientnew(name, "Axis", [q, a])
    F.set_ang_vel(parent, u * a)
    return F


def _point(name, base, frame, vec, N):
    P = base.locatenew(name, vec)
    P.v2pt_theory(base, N, frame)
    return P


def _ground(name, O, vec, N):
    P = O.locatenew(name, vec)
    P.set_vel(N, 0)
    return P


def _bar(name, frame, G, m, l, along="x"):
    I = m * l**2 / 12
    dyad = {"x": me.inertia(frame, 0, I, I), "y": me.inertia(frame, I, 0, I),
            "z": me.inertia(frame, I, I, 0)}[along]
    return me.RigidBody(name, G, frame, m, (dyad, G))


def _cut(P, Q, N, axes=("x", "y")):
    r = P.pos_from(Q)
    v = P.vel(N) - Q.vel(N)
    return [r.dot(getattr(N, a)) for a in axes], [v.dot(getattr(N, a)) for a in axes]


def _line_force(A, B, N, k=0, L0=0, c=0):
    """Force on B (minus it on A) of a spring k, free length L0, and a damper c along A-B."""
    r = B.pos_from(A)
    length = sp.sqrt(r.dot(r))
    e = r / length
    rate = (B.vel(N) - A.vel(N)).dot(e)
    return (-k * (length - L0) - c * rate) * e


def _kane(N, q, u, n_ind, bodies, loads, conf=(), vel=(), q_ind=None, q_dep=None):
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    if vel:
        kane = me.KanesMethod(N, q_ind=q_ind if q_ind is not None else q[:n_ind],
                              q_dependent=q_dep if q_dep is not None else (q[n_ind:] if conf else []),
                              u_ind=u[:n_ind], u_dependent=u[n_ind:], kd_eqs=kd,
                              configuration_constraints=list(conf), velocity_constraints=list(vel))
    else:
        kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return kane


# -- offset slider-crank --------------------------------------------------------------

def offset_slider() -> Reference:
    th, phi = q = list(me.dynamicsymbols("th phi"))
    u = list(me.dynamicsymbols("u1:3"))
    P = _symbols("r L e m1 m2 ms k L0 w g T")
    N = me.ReferenceFrame("N")
    A = _frame(N, "A", th, u[0])
    R = _frame(N, "R", phi, u[1])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    pin = _point("pin", O, A, P["r"] * A.x, N)
    wrist = _point("wrist", pin, R, P["L"] * R.x, N)
    G1 = _point("G1", O, A, P["r"] / 2 * A.x, N)
    G2 = _point("G2", pin, R, P["L"] / 2 * R.x, N)
    wall = _ground("wall", O, P["w"] * N.x + P["e"] * N.y, N)
    rail = _ground("rail", O, P["e"] * N.y, N)
    # the wrist is on the horizontal line through (0, e)
    conf = [wrist.pos_from(rail).dot(N.y)]
    vel = [wrist.vel(N).dot(N.y)]
    bodies = [_bar("crank", A, G1, P["m1"], P["r"]), _bar("rod", R, G2, P["m2"], P["L"]),
              me.Particle("slider", wrist, P["ms"])]
    g = P["g"]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (wrist, -P["ms"] * g * N.y),
             (A, P["T"] * N.z), (wrist, _line_force(wall, wrist, N, P["k"], P["L0"]))]
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"phi": 0.1})


# -- quick return --------------------------------------------------------------------

def quick_return() -> Reference:
    th, psi, s = q = list(me.dynamicsymbols("th psi s"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("r d L m1 m2 ms Js c g T")
    N = me.ReferenceFrame("N")
    A = _frame(N, "A", th, u[0])
    R = _frame(N, "R", psi, u[1])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    D = _ground("D", O, -P["d"] * N.y, N)
    pin = _point("pin", O, A, P["r"] * A.x, N)
    block = D.locatenew("block", s * R.x)
    block.set_vel(N, u[2] * R.x + u[1] * R.z.cross(s * R.x))
    on_lever = _point("on_lever", D, R, s * R.x, N)  # the lever's material point under the block
    G1 = _point("G1", O, A, P["r"] / 2 * A.x, N)
    G2 = _point("G2", D, R, P["L"] / 2 * R.x, N)
    conf, vel = _cut(pin, block, N)
    bodies = [_bar("crank", A, G1, P["m1"], P["r"]), _bar("lever", R, G2, P["m2"], P["L"]),
              me.RigidBody("block", block, R, P["ms"], (me.inertia(R, P["Js"] / 2, P["Js"] / 2, P["Js"]), block))]
    g = P["g"]
    friction = -P["c"] * u[2] * R.x  # on the block; the lever takes minus it
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (block, -P["ms"] * g * N.y + friction),
             (on_lever, -friction), (A, P["T"] * N.z)]
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"psi": 1.2, "s": 0.65})


# -- four-bar with pivots at different heights, crank spring ---------------------------

def fourbar_heights() -> Reference:
    th1, ph2, th3 = q = list(me.dynamicsymbols("th1 ph2 th3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("dx dy l1 l2 l3 m1 m2 m3 kt th0 g")
    N = me.ReferenceFrame("N")
    A1 = _frame(N, "A1", th1, u[0])
    A2 = _frame(A1, "A2", ph2, u[1])
    A3 = _frame(N, "A3", th3, u[2])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    D = _ground("D", O, P["dx"] * N.x + P["dy"] * N.y, N)
    B = _point("B", O, A1, P["l1"] * A1.x, N)
    C = _point("C", B, A2, P["l2"] * A2.x, N)
    C3 = _point("C3", D, A3, P["l3"] * A3.x, N)
    G1 = _point("G1", O, A1, P["l1"] / 2 * A1.x, N)
    G2 = _point("G2", B, A2, P["l2"] / 2 * A2.x, N)
    G3 = _point("G3", D, A3, P["l3"] / 2 * A3.x, N)
    conf, vel = _cut(C, C3, N)
    bodies = [_bar("crank", A1, G1, P["m1"], P["l1"]), _bar("coupler", A2, G2, P["m2"], P["l2"]),
              _bar("rocker", A3, G3, P["m3"], P["l3"])]
    loads = [(b.masscenter, -b.mass * P["g"] * N.y) for b in bodies]
    loads.append((A1, -P["kt"] * (th1 - P["th0"]) * N.z))
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"ph2": 0.6, "th3": 1.9})


# -- drag-link four-bar cut at the rocker's ground pivot --------------------------------

def fourbar_rocker_cut() -> Reference:
    th1, th2, th3 = q = list(me.dynamicsymbols("th1 th2 th3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("l0 l1 l2 l3 m1 m2 m3 g T")
    N = me.ReferenceFrame("N")
    A1 = _frame(N, "A1", th1, u[0])
    A2 = _frame(N, "A2", th2, u[1])
    A3 = _frame(N, "A3", th3, u[2])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    D = _ground("D", O, P["l0"] * N.x, N)
    B = _point("B", O, A1, P["l1"] * A1.x, N)
    C = _point("C", B, A2, P["l2"] * A2.x, N)
    E = _point("E", C, A3, P["l3"] * A3.x, N)  # the rocker's free end: the cut joint at D
    G1 = _point("G1", O, A1, P["l1"] / 2 * A1.x, N)
    G2 = _point("G2", B, A2, P["l2"] / 2 * A2.x, N)
    G3 = _point("G3", C, A3, P["l3"] / 2 * A3.x, N)
    conf, vel = _cut(E, D, N)
    bodies = [_bar("crank", A1, G1, P["m1"], P["l1"]), _bar("coupler", A2, G2, P["m2"], P["l2"]),
              _bar("rocker", A3, G3, P["m3"], P["l3"])]
    loads = [(b.masscenter, -b.mass * P["g"] * N.y) for b in bodies] + [(A3, P["T"] * N.z)]
    # th3 independent: speeds ordered u3, u1, u2
    qo = [th3, th1, th2]
    uo = [u[2], u[0], u[1]]
    kane = _kane(N, qo, uo, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, qo, uo[:1], uo[1:], P, vel), _named(qo), configuration=conf,
                     q_dep=[th1, th2], guess={"th1": -1.86, "th2": 2.12})


# -- double four-bar sharing the crank ---------------------------------------------------

def double_fourbar() -> Reference:
    q = list(me.dynamicsymbols("th1:6"))
    u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("l1 l2 l3 l4 l5 dA dBx dBy m1 m2 m3 m4 m5 g T")
    N = me.ReferenceFrame("N")
    F = [_frame(N, f"A{i + 1}", qi, ui) for i, (qi, ui) in enumerate(zip(q, u))]
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    DA = _ground("DA", O, P["dA"] * N.x, N)
    DB = _ground("DB", O, -P["dBx"] * N.x + P["dBy"] * N.y, N)
    B = _point("B", O, F[0], P["l1"] * F[0].x, N)
    endA = _point("endA", B, F[1], P["l2"] * F[1].x, N)
    tipA = _point("tipA", DA, F[2], P["l3"] * F[2].x, N)
    endB = _point("endB", B, F[3], P["l4"] * F[3].x, N)
    tipB = _point("tipB", DB, F[4], P["l5"] * F[4].x, N)
    bases = [O, B, DA, B, DB]
    L = [P[f"l{i}"] for i in range(1, 6)]
    G = [_point(f"G{i + 1}", bases[i], F[i], L[i] / 2 * F[i].x, N) for i in range(5)]
    bodies = [_bar(f"b{i + 1}", F[i], G[i], P[f"m{i + 1}"], L[i]) for i in range(5)]
    c1, v1 = _cut(endA, tipA, N)
    c2, v2 = _cut(endB, tipB, N)
    loads = [(b.masscenter, -b.mass * P["g"] * N.y) for b in bodies] + [(F[0], P["T"] * N.z)]
    kane = _kane(N, q, u, 1, bodies, loads, c1 + c2, v1 + v2)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, v1 + v2), _named(q), configuration=c1 + c2,
                     q_dep=q[1:], guess={"th2": 0.9, "th3": 1.7, "th4": 2.2, "th5": 1.2})


# -- two carts, a pendulum and springs --------------------------------------------------

def two_carts() -> Reference:
    x1, x2, th = q = list(me.dynamicsymbols("x1 x2 th"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("M1 M2 m l dc k1 a1 k2 a2 k3 a3 c g F")
    N = me.ReferenceFrame("N")
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    left = _ground("left", O, -2 * N.x, N)
    right = _ground("right", O, 4 * N.x, N)
    c1 = O.locatenew("c1", x1 * N.x)
    c1.set_vel(N, u[0] * N.x)
    c2 = O.locatenew("c2", (P["dc"] + x2) * N.x)
    c2.set_vel(N, u[1] * N.x)
    B = _frame(N, "B", th, u[2])
    tip = _point("tip", c1, B, -P["l"] * B.y, N)
    G = _point("G", c1, B, -P["l"] / 2 * B.y, N)
    bodies = [me.Particle("cart1", c1, P["M1"]), me.Particle("cart2", c2, P["M2"]),
              _bar("bar", B, G, P["m"], P["l"], along="y")]
    g = P["g"]
    s1 = _line_force(left, c1, N, P["k1"], P["a1"])
    s2 = _line_force(tip, c2, N, P["k2"], P["a2"])
    s3 = _line_force(right, c2, N, P["k3"], P["a3"])
    d = _line_force(c1, c2, N, c=P["c"])
    loads = [(c1, -P["M1"] * g * N.y + s1 - d), (c2, -P["M2"] * g * N.y + P["F"] * N.x + s2 + s3 + d),
             (tip, -s2), (G, -P["m"] * g * N.y)]
    kane = _kane(N, q, u, 3, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- cart with a rolling wheel on a slope -----------------------------------------------

def slope_cart() -> Reference:
    s, phi, th = q = list(me.dynamicsymbols("s phi th"))
    us, uphi, uth = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("alpha r h M Ic mw mb l g T")
    N = me.ReferenceFrame("N")
    S = N.orientnew("S", "Axis", [P["alpha"], N.y])
    S.set_ang_vel(N, 0)
    W = _frame(S, "W", phi, uphi, axis="y")
    B = _frame(N, "B", th, uth, axis="y")
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    hub = O.locatenew("hub", s * S.x + P["r"] * S.z)
    hub.set_vel(N, us * S.x)
    body = hub.locatenew("body", P["h"] * S.z)
    body.set_vel(N, us * S.x)
    G = _point("G", body, B, -P["l"] / 2 * B.z, N)
    # the wheel's material point at the contact is at rest
    contact = hub.vel(N) + W.ang_vel_in(N).cross(-P["r"] * S.z)
    vel = [contact.dot(S.x)]
    cart = me.RigidBody("cart", body, S, P["M"], (me.inertia(S, P["Ic"], P["Ic"], P["Ic"]), body))
    wheel = me.RigidBody("wheel", hub, W, P["mw"],
                         (me.inertia(W, P["mw"] * P["r"]**2 / 4, P["mw"] * P["r"]**2 / 2, P["mw"] * P["r"]**2 / 4), hub))
    bar = _bar("bar", B, G, P["mb"], P["l"], along="z")
    g = P["g"]
    loads = [(body, -P["M"] * g * N.z), (hub, -P["mw"] * g * N.z), (G, -P["mb"] * g * N.z),
             (W, P["T"] * S.y), (S, -P["T"] * S.y)]
    qo, uo = [s, th, phi], [us, uth, uphi]
    kd = [qi.diff(t) - ui for qi, ui in zip(qo, uo)]
    kane = me.KanesMethod(N, q_ind=qo, u_ind=uo[:2], u_dependent=uo[2:], kd_eqs=kd, velocity_constraints=vel)
    kane.kanes_equations([cart, wheel, bar], loads)
    return Reference(KaneModel(kane, qo, uo[:2], uo[2:], P, vel), _named(qo))


# -- four-link pendulum, absolute angles -------------------------------------------------

def chain4_abs() -> Reference:
    q = list(me.dynamicsymbols("th1:5"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("L1 L2 L3 L4 m1 m2 m3 m4 k g")
    N = me.ReferenceFrame("N")
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    bodies, loads, joint, frames = [], [], O, []
    for i in range(4):
        F = _frame(N, f"B{i + 1}", q[i], u[i])
        frames.append(F)
        L, m = P[f"L{i + 1}"], P[f"m{i + 1}"]
        G = _point(f"G{i + 1}", joint, F, -L / 2 * F.y, N)
        bodies.append(_bar(f"link{i + 1}", F, G, m, L, along="y"))
        loads.append((G, -m * P["g"] * N.y))
        joint = _point(f"J{i + 2}", joint, F, -L * F.y, N)
    for i in range(3):  # joint spring between link i and link i+1
        tau = -P["k"] * (q[i + 1] - q[i]) * N.z  # on link i+1
        loads += [(frames[i + 1], tau), (frames[i], -tau)]
    kane = _kane(N, q, u, 4, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- rolling discs ------------------------------------------------------------------------

def _disc_yxy(yaw, lean, spin, uy, ul, us):
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    D.set_ang_vel(N, uy * N.z + ul * L.x + us * L.y)
    return N, Y, L, D


def _rolling_centre(N, L, D, x, y, ux, uy_, r, up):
    """Contact (x, y, 0), centre r along ``up``; returns centre, and the material contact velocity."""
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    contact = O.locatenew("C", x * N.x + y * N.y)
    contact.set_vel(N, ux * N.x + uy_ * N.y)
    centre = contact.locatenew("G", r * up)
    centre.set_vel(N, contact.vel(N) + L.ang_vel_in(N).cross(r * up))
    material = centre.vel(N) + D.ang_vel_in(N).cross(-r * up)
    return centre, material


def disc_pfaff() -> Reference:
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    ux, uy, uyaw, ulean, uspin = u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("m r g T")
    N, Y, L, D = _disc_yxy(yaw, lean, spin, uyaw, ulean, uspin)
    L.set_ang_vel(N, uyaw * N.z + ulean * L.x)
    centre, material = _rolling_centre(N, L, D, x, y, ux, uy, P["r"], L.z)
    vel = [material.dot(N.x), material.dot(N.y)]
    m, r = P["m"], P["r"]
    disc = me.RigidBody("disc", centre, D, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), centre))
    qo = [spin, lean, yaw, x, y]
    uo = [uspin, ulean, uyaw, ux, uy]
    kd = [qi.diff(t) - ui for qi, ui in zip(qo, uo)]
    kane = me.KanesMethod(N, q_ind=qo, u_ind=uo[:3], u_dependent=uo[3:], kd_eqs=kd, velocity_constraints=vel)
    kane.kanes_equations([disc], [(centre, -m * P["g"] * N.z), (D, P["T"] * L.y)])
    return Reference(KaneModel(kane, qo, uo[:3], uo[3:], P, vel), _named(qo))


def disc_zyx() -> Reference:
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    ux, uy, uyaw, ulean, uspin = u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("m r g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.y])
    D = L.orientnew("D", "Axis", [spin, L.x])
    L.set_ang_vel(N, uyaw * N.z + ulean * Y.y)
    D.set_ang_vel(N, uyaw * N.z + ulean * Y.y + uspin * L.x)
    # the centre is r above the contact along the wheel's upward in-plane direction,
    # (n - (n.a)a)/|n - (n.a)a| with n = N.z, a = D.x, which is L.z for |lean| < pi/2
    centre, material = _rolling_centre(N, L, D, x, y, ux, uy, P["r"], L.z)
    vel = [material.dot(N.x), material.dot(N.y)]
    m, r = P["m"], P["r"]
    disc = me.RigidBody("disc", centre, D, m, (me.inertia(D, m * r**2 / 2, m * r**2 / 4, m * r**2 / 4), centre))
    qo = [yaw, lean, spin, x, y]
    uo = [uyaw, ulean, uspin, ux, uy]
    kd = [qi.diff(t) - ui for qi, ui in zip(qo, uo)]
    kane = me.KanesMethod(N, q_ind=qo, u_ind=uo[:3], u_dependent=uo[3:], kd_eqs=kd, velocity_constraints=vel)
    kane.kanes_equations([disc], [(centre, -m * P["g"] * N.z)])
    return Reference(KaneModel(kane, qo, uo[:3], uo[3:], P, vel), _named(qo))


def hoop_mass() -> Reference:
    x, y, yaw, lean, spin = q = list(me.dynamicsymbols("x y yaw lean spin"))
    ux, uy, uyaw, ulean, uspin = u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("m mp r g")
    N, Y, L, D = _disc_yxy(yaw, lean, spin, uyaw, ulean, uspin)
    L.set_ang_vel(N, uyaw * N.z + ulean * L.x)
    centre, material = _rolling_centre(N, L, D, x, y, ux, uy, P["r"], L.z)
    vel = [material.dot(N.x), material.dot(N.y)]
    bead = _point("bead", centre, D, P["r"] * D.x, N)
    m, mp, r = P["m"], P["mp"], P["r"]
    hoop = me.RigidBody("hoop", centre, D, m, (me.inertia(D, m * r**2 / 2, m * r**2, m * r**2 / 2), centre))
    qo = [yaw, lean, spin, x, y]
    uo = [uyaw, ulean, uspin, ux, uy]
    kd = [qi.diff(t) - ui for qi, ui in zip(qo, uo)]
    kane = me.KanesMethod(N, q_ind=qo, u_ind=uo[:3], u_dependent=uo[3:], kd_eqs=kd, velocity_constraints=vel)
    kane.kanes_equations([hoop, me.Particle("bead", bead, mp)],
                         [(centre, -m * P["g"] * N.z), (bead, -mp * P["g"] * N.z)])
    return Reference(KaneModel(kane, qo, uo[:3], uo[3:], P, vel), _named(qo))


SYSTEMS = {
    "m6_offset_slider": (HERE / "m6_offset_slider.yaml", offset_slider, None),
    "m6_quick_return": (HERE / "m6_quick_return.yaml", quick_return, None),
    "m6_fourbar_heights": (HERE / "m6_fourbar_heights.yaml", fourbar_heights, None),
    "m6_fourbar_rocker_cut": (HERE / "m6_fourbar_rocker_cut.yaml", fourbar_rocker_cut, None),
    "m6_double_fourbar": (HERE / "m6_double_fourbar.yaml", double_fourbar, None),
    "m6_two_carts": (HERE / "m6_two_carts.yaml", two_carts, None),
    "m6_slope_cart": (HERE / "m6_slope_cart.yaml", slope_cart, None),
    "m6_chain4_abs": (HERE / "m6_chain4_abs.yaml", chain4_abs, None),
    "m6_disc_pfaff": (HERE / "m6_disc_pfaff.yaml", disc_pfaff, None),
    "m6_disc_zyx": (HERE / "m6_disc_zyx.yaml", disc_zyx, None),
    "m6_hoop_mass": (HERE / "m6_hoop_mass.yaml", hoop_mass, None),
}
