"""KanesMethod references for the l4_ linkages and carts (built from the physical definitions)."""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _rot(parent, name, q, u):
    """A frame turned about the parent's z by q, with rate u."""
    F = parent.orientnew(name, "Axis", [q, parent.z])
    F.set_ang_vel(parent, u * parent.z)
    return F


def _at(name, base, frame, vec, N):
    """A point fixed in `frame` at `vec` from `base` (base fixed in frame too)."""
    P = base.locatenew(name, vec)
    P.v2pt_theory(base, N, frame)
    return P


def _fixed(name, O, vec, N):
    P = O.locatenew(name, vec)
    P.set_vel(N, 0)
    return P


def _bar(name, frame, G, m, l, axis="x"):
    I = m * l**2 / 12
    inert = me.inertia(frame, 0, I, I) if axis == "x" else me.inertia(frame, I, 0, I)
    return me.RigidBody(name, G, frame, m, (inert, G))


def _plate(name, frame, G, m, J):
    return me.RigidBody(name, G, frame, m, (me.inertia(frame, J / 2, J / 2, J), G))


def _line(A, B, N, k=0, L0=0, c=0):
    """Force on B (and minus it on A) of a spring k (free length L0) and a damper c from A to B."""
    r = B.pos_from(A)
    length = sp.sqrt(r.dot(r))
    e = r / length
    ldot = (B.vel(N) - A.vel(N)).dot(e)
    return (-k * (length - L0) - c * ldot) * e


def _loop(P1, P2, N):
    gap = P1.pos_from(P2)
    v = P1.vel(N) - P2.vel(N)
    return [gap.dot(N.x), gap.dot(N.y)], [v.dot(N.x), v.dot(N.y)]


def _kane(N, q, u, n_ind, bodies, loads, configuration=(), velocity=()):
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    if velocity:
        kane = me.KanesMethod(N, q_ind=q[:n_ind], q_dependent=q[n_ind:], u_ind=u[:n_ind], u_dependent=u[n_ind:],
                              kd_eqs=kd, configuration_constraints=list(configuration),
                              velocity_constraints=list(velocity))
    else:
        kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return kane


def fourbar_abs() -> Reference:
    th1, th2, th3 = q = list(me.dynamicsymbols("th1 th2 th3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("d l1 l2 l3 m1 m2 m3 c g T")
    N = me.ReferenceFrame("N")
    A1, A2, A3 = (_rot(N, f"A{i}", qi, ui) for i, qi, ui in zip((1, 2, 3), q, u))
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    D = _fixed("D", O, P["d"] * N.x, N)
    B = _at("B", O, A1, P["l1"] * A1.x, N)
    C = _at("C", B, A2, P["l2"] * A2.x, N)
    Cr = _at("Cr", D, A3, P["l3"] * A3.x, N)
    G1 = _at("G1", O, A1, P["l1"] / 2 * A1.x, N)
    G2 = _at("G2", B, A2, P["l2"] / 2 * A2.x, N)
    G3 = _at("G3", D, A3, P["l3"] / 2 * A3.x, N)
    conf, vel = _loop(C, Cr, N)
    g = P["g"]
    bodies = [_bar("crank", A1, G1, P["m1"], P["l1"]), _bar("coupler", A2, G2, P["m2"], P["l2"]),
              _bar("rocker", A3, G3, P["m3"], P["l3"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (G3, -P["m3"] * g * N.y),
             (A1, P["T"] * N.z), (A3, -P["c"] * u[2] * N.z)]
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"th2": 0.9, "th3": 1.7})


def fourbar_rel() -> Reference:
    th, phi, psi = q = list(me.dynamicsymbols("th phi psi"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("d1 d2 l1 l2 l3 a b m1 m2 m3 J2 k L0 sx sy g T")
    N = me.ReferenceFrame("N")
    Cr = _rot(N, "Cr", th, u[0])
    Cp = _rot(Cr, "Cp", phi, u[1])
    Ro = _rot(N, "Ro", psi, u[2])
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    D = _fixed("D", O, P["d1"] * N.x + P["d2"] * N.y, N)
    S = _fixed("S", O, P["sx"] * N.x + P["sy"] * N.y, N)
    B = _at("B", O, Cr, P["l1"] * Cr.x, N)
    C = _at("C", B, Cp, P["l2"] * Cp.x, N)
    R = _at("R", D, Ro, P["l3"] * Ro.x, N)
    G1 = _at("G1", O, Cr, P["l1"] / 2 * Cr.x, N)
    G2 = _at("G2", B, Cp, P["a"] * Cp.x + P["b"] * Cp.y, N)
    G3 = _at("G3", D, Ro, P["l3"] / 2 * Ro.x, N)
    conf, vel = _loop(C, R, N)
    g = P["g"]
    fs = _line(S, G2, N, k=P["k"], L0=P["L0"])
    bodies = [_bar("crank", Cr, G1, P["m1"], P["l1"]), _plate("coupler", Cp, G2, P["m2"], P["J2"]),
              _bar("rocker", Ro, G3, P["m3"], P["l3"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y + fs), (G3, -P["m3"] * g * N.y),
             (Cr, P["T"] * N.z)]
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"phi": 0.0, "psi": 1.6})


def slider_crank_rel() -> Reference:
    th, phi, x = q = list(me.dynamicsymbols("th phi x"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("r rc L e m1 J1 m2 m3 c g T F")
    N = me.ReferenceFrame("N")
    A = _rot(N, "A", th, u[0])
    R = _rot(A, "R", phi, u[1])
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    pin = _at("pin", O, A, P["r"] * A.x, N)
    end = _at("end", pin, R, P["L"] * R.x, N)
    G1 = _at("G1", O, A, P["rc"] * A.x, N)
    G2 = _at("G2", pin, R, P["L"] / 2 * R.x, N)
    Sl = O.locatenew("Sl", x * N.x + P["e"] * N.y)
    Sl.set_vel(N, u[2] * N.x)
    conf, vel = _loop(end, Sl, N)
    g = P["g"]
    crank = me.RigidBody("crank", G1, A, P["m1"], (me.inertia(A, 0, 0, P["J1"]), G1))
    bodies = [crank, _bar("rod", R, G2, P["m2"], P["L"]), me.Particle("slider", Sl, P["m3"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y),
             (Sl, -P["m3"] * g * N.y + (P["F"] - P["c"] * u[2]) * N.x), (A, P["T"] * N.z)]
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"phi": 0.0, "x": 1.2})


def crank_rocker_spring(spring=True, damper=True) -> Reference:
    q1, q2, q3 = q = list(me.dynamicsymbols("q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("d l1 l2 l3 m1 m2 m3 k L0 kt q30 ax ay b g T")
    N = me.ReferenceFrame("N")
    A1, A2, A3 = (_rot(N, f"A{i}", qi, ui) for i, qi, ui in zip((1, 2, 3), q, u))
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    D = _fixed("D", O, P["d"] * N.x, N)
    An = _fixed("An", O, P["ax"] * N.x + P["ay"] * N.y, N)
    B = _at("B", O, A1, P["l1"] * A1.x, N)
    C = _at("C", B, A2, P["l2"] * A2.x, N)
    tip = _at("tip", D, A3, P["l3"] * A3.x, N)
    G1 = _at("G1", O, A1, P["l1"] / 2 * A1.x, N)
    G2 = _at("G2", B, A2, P["l2"] / 2 * A2.x, N)
    G3 = _at("G3", D, A3, P["l3"] / 2 * A3.x, N)
    conf, vel = _loop(C, tip, N)
    g = P["g"]
    fs = _line(An, tip, N, k=P["k"], L0=P["L0"]) if spring else 0 * N.x
    tj = -P["b"] * (u[2] - u[1]) if damper else 0  # joint damper torque on the rocker; its reaction on the coupler
    bodies = [_bar("crank", A1, G1, P["m1"], P["l1"]), _bar("coupler", A2, G2, P["m2"], P["l2"]),
              _bar("rocker", A3, G3, P["m3"], P["l3"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (G3, -P["m3"] * g * N.y), (tip, fs),
             (A1, P["T"] * N.z), (A3, (-P["kt"] * (q3 - P["q30"]) + tj) * N.z), (A2, -tj * N.z)]
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"q2": 0.9, "q3": 1.7})


def five_bar_rel() -> Reference:
    a1, a4, b1, b2 = q = list(me.dynamicsymbols("a1 a4 b1 b2"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("d l1 l2 l3 l4 m1 m2 m3 m4 g T1 T4 Te")
    N = me.ReferenceFrame("N")
    K1 = _rot(N, "K1", a1, u[0])
    K4 = _rot(N, "K4", a4, u[1])
    C1 = _rot(K1, "C1", b1, u[2])
    C3 = _rot(K4, "C3", b2, u[3])
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    E = _fixed("E", O, P["d"] * N.x, N)
    B = _at("B", O, K1, P["l1"] * K1.x, N)
    D = _at("D", E, K4, P["l4"] * K4.x, N)
    Al = _at("Al", B, C1, P["l2"] * C1.x, N)
    Ar = _at("Ar", D, C3, P["l3"] * C3.x, N)
    G1 = _at("G1", O, K1, P["l1"] / 2 * K1.x, N)
    G2 = _at("G2", B, C1, P["l2"] / 2 * C1.x, N)
    G3 = _at("G3", D, C3, P["l3"] / 2 * C3.x, N)
    G4 = _at("G4", E, K4, P["l4"] / 2 * K4.x, N)
    conf, vel = _loop(Al, Ar, N)
    g = P["g"]
    bodies = [_bar("crank1", K1, G1, P["m1"], P["l1"]), _bar("coupler1", C1, G2, P["m2"], P["l2"]),
              _bar("coupler3", C3, G3, P["m3"], P["l3"]), _bar("crank4", K4, G4, P["m4"], P["l4"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (G3, -P["m3"] * g * N.y),
             (G4, -P["m4"] * g * N.y), (K1, (P["T1"] - P["Te"]) * N.z), (K4, P["T4"] * N.z),
             (C1, P["Te"] * N.z)]
    kane = _kane(N, q, u, 2, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:2], u[2:], P, vel), _named(q), configuration=conf, q_dep=q[2:],
                     guess={"b1": 0.6, "b2": -0.6})


def cart_pole_incline() -> Reference:
    s, th = q = list(me.dynamicsymbols("s th"))
    u = list(me.dynamicsymbols("u1:3"))
    P = _symbols("alpha M m l w c bh g F")
    N = me.ReferenceFrame("N")
    S = N.orientnew("S", "Axis", [P["alpha"], N.z])
    Pf = _rot(S, "Pf", th, u[1])
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    stop = _fixed("stop", O, -P["w"] * S.x, N)
    cart = O.locatenew("cart", s * S.x)
    cart.set_vel(N, u[0] * S.x)
    G = _at("G", cart, Pf, P["l"] / 2 * Pf.y, N)
    g = P["g"]
    fd = _line(stop, cart, N, c=P["c"])
    bodies = [me.Particle("cart", cart, P["M"]), _bar("pole", Pf, G, P["m"], P["l"], axis="y")]
    loads = [(cart, -P["M"] * g * N.y + P["F"] * S.x + fd), (G, -P["m"] * g * N.y),
             (Pf, -P["bh"] * u[1] * S.z)]
    kane = _kane(N, q, u, 2, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def double_cart() -> Reference:
    x, a1, a2 = q = list(me.dynamicsymbols("x a1 a2"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("M m1 m2 l1 l2 k c b g F")
    N = me.ReferenceFrame("N")
    B1 = _rot(N, "B1", a1, u[1])
    B2 = _rot(B1, "B2", a2, u[2])
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    cart = O.locatenew("cart", x * N.x)
    cart.set_vel(N, u[0] * N.x)
    G1 = _at("G1", cart, B1, -P["l1"] / 2 * B1.y, N)
    elbow = _at("elbow", cart, B1, -P["l1"] * B1.y, N)
    G2 = _at("G2", elbow, B2, -P["l2"] / 2 * B2.y, N)
    g = P["g"]
    bodies = [me.Particle("cart", cart, P["M"]), _bar("bar1", B1, G1, P["m1"], P["l1"], axis="y"),
              _bar("bar2", B2, G2, P["m2"], P["l2"], axis="y")]
    loads = [(cart, (P["F"] - P["k"] * x - P["c"] * u[0]) * N.x), (G1, -P["m1"] * g * N.y),
             (G2, -P["m2"] * g * N.y), (B2, -P["b"] * u[2] * N.z), (B1, P["b"] * u[2] * N.z)]
    kane = _kane(N, q, u, 3, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def stephenson6() -> Reference:
    q = list(me.dynamicsymbols("th1 th2 th3 th4 th5"))
    u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("d l1 l2 l3 e1 e2 c2x c2y h1 h2 l4 l5 m1 m2 J2 m3 m4 m5 mt g T")
    N = me.ReferenceFrame("N")
    A1 = _rot(N, "A1", q[0], u[0])
    A2 = _rot(N, "A2", q[1], u[1])
    A3 = _rot(N, "A3", q[2], u[2])
    A4 = _rot(A2, "A4", q[3], u[3])
    A5 = _rot(N, "A5", q[4], u[4])
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    D = _fixed("D", O, P["d"] * N.x, N)
    H = _fixed("H", O, P["h1"] * N.x + P["h2"] * N.y, N)
    B = _at("B", O, A1, P["l1"] * A1.x, N)
    C = _at("C", B, A2, P["l2"] * A2.x, N)
    E = _at("E", B, A2, P["e1"] * A2.x + P["e2"] * A2.y, N)
    R = _at("R", D, A3, P["l3"] * A3.x, N)
    F4 = _at("F4", E, A4, P["l4"] * A4.x, N)
    F5 = _at("F5", H, A5, P["l5"] * A5.x, N)
    G1 = _at("G1", O, A1, P["l1"] / 2 * A1.x, N)
    G2 = _at("G2", B, A2, P["c2x"] * A2.x + P["c2y"] * A2.y, N)
    G3 = _at("G3", D, A3, P["l3"] / 2 * A3.x, N)
    G4 = _at("G4", E, A4, P["l4"] / 2 * A4.x, N)
    G5 = _at("G5", H, A5, P["l5"] / 2 * A5.x, N)
    c1, v1 = _loop(C, R, N)
    c2, v2 = _loop(F4, F5, N)
    conf, vel = c1 + c2, v1 + v2
    g = P["g"]
    bodies = [_bar("crank", A1, G1, P["m1"], P["l1"]), _plate("plate", A2, G2, P["m2"], P["J2"]),
              _bar("rocker", A3, G3, P["m3"], P["l3"]), _bar("link4", A4, G4, P["m4"], P["l4"]),
              _bar("link5", A5, G5, P["m5"], P["l5"]), me.Particle("tool", F4, P["mt"])]
    loads = [(Gi, -P[m] * g * N.y) for Gi, m in ((G1, "m1"), (G2, "m2"), (G3, "m3"), (G4, "m4"), (G5, "m5"),
                                                (F4, "mt"))]
    loads.append((A1, P["T"] * N.z))
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"th2": 0.9, "th3": 1.7, "th4": GUESS4, "th5": GUESS5})


GUESS4, GUESS5 = -0.3, -0.4

SYSTEMS = {
    "l4_fourbar_abs_f1": (HERE / "l4_fourbar_abs_f1.yaml", fourbar_abs,
                          "four-bar, absolute angles, explicit loop equations, format 1, motor, pivot damper"),
    "l4_fourbar_rel": (HERE / "l4_fourbar_rel.yaml", fourbar_rel,
                       "four-bar, coupler frame hung from the crank, plate coupler, spring, coincide"),
    "l4_slider_crank_rel_f1": (HERE / "l4_slider_crank_rel_f1.yaml", slider_crank_rel,
                               "offset slider-crank, rod angle relative to crank, format 1"),
    "l4_crank_rocker_spring": (HERE / "l4_crank_rocker_spring.yaml", crank_rocker_spring,
                               "crank-rocker, frames, loop as explicit equations, springs, joint damper"),
    "l4_five_bar_rel": (HERE / "l4_five_bar_rel.yaml", five_bar_rel,
                        "five-bar, couplers relative to cranks, coincide, elbow motor with reaction"),
    "l4_cart_pole_incline": (HERE / "l4_cart_pole_incline.yaml", cart_pole_incline,
                             "inverted pendulum on a cart on an incline, frames, dampers"),
    "l4_double_cart_f1": (HERE / "l4_double_cart_f1.yaml", double_cart,
                          "cart with double pendulum, relative elbow angle, format 1"),
    "l4_stephenson6": (HERE / "l4_stephenson6.yaml", stephenson6,
                       "Stephenson III six-bar, ternary coupler, link 4 relative, two coincides"),
}
