"""KanesMethod references for the l5_ linkages, chains and carts, built from the physics.

Each loop is closed from its definition (the two ends of a cut joint at the
same place), never from a gacli file's constraint rows.
"""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _frame(parent, name, q, u):
    F = parent.orientnew(name, "Axis", [q, parent.z])
    F.set_ang_vel(parent, u * parent.z)
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
    dyad = me.inertia(frame, 0, I, I) if along == "x" else me.inertia(frame, I, 0, I)
    return me.RigidBody(name, G, frame, m, (dyad, G))


def _plate(name, frame, G, m, J):
    return me.RigidBody(name, G, frame, m, (me.inertia(frame, J / 2, J / 2, J), G))


def _cut(P, Q, N):
    """A joint cut between P and Q: positions and velocities equal, in N's x and y."""
    r = P.pos_from(Q)
    v = P.vel(N) - Q.vel(N)
    return [r.dot(N.x), r.dot(N.y)], [v.dot(N.x), v.dot(N.y)]


def _line_force(A, B, N, k=0, L0=0, c=0):
    """Force on B (minus it on A) of a spring k with free length L0 and a damper c along A-B."""
    r = B.pos_from(A)
    length = sp.sqrt(r.dot(r))
    e = r / length
    rate = (B.vel(N) - A.vel(N)).dot(e)
    return (-k * (length - L0) - c * rate) * e


def _kane(N, q, u, n_ind, bodies, loads, conf=(), vel=()):
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    if vel:
        kane = me.KanesMethod(N, q_ind=q[:n_ind], q_dependent=q[n_ind:], u_ind=u[:n_ind],
                              u_dependent=u[n_ind:], kd_eqs=kd, configuration_constraints=list(conf),
                              velocity_constraints=list(vel))
    else:
        kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return kane


def _weights(bodies, g, N):
    return [(b.masscenter, -b.mass * g * N.y) for b in bodies]


# -- four-bar, SymPy docs, relative joint angles ----------------------------------

def fourbar_docs() -> Reference:
    q1, q2, q3 = q = list(me.dynamicsymbols("q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("l1 l2 l3 l4 rho g")
    l1, l2, l3, l4, rho, g = (P[n] for n in "l1 l2 l3 l4 rho g".split())
    N = me.ReferenceFrame("N")
    A = _frame(N, "A", q1, u[0])
    B = _frame(A, "B", q2, u[1])
    C = _frame(B, "C", q3, u[2])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    P2 = _point("P2", O, A, l1 * A.x, N)
    P3 = _point("P3", P2, B, l2 * B.x, N)
    P4 = _point("P4", P3, C, l3 * C.x, N)
    pivot = _ground("pivot", O, l4 * N.x, N)
    G1 = _point("G1", O, A, l1 / 2 * A.x, N)
    G2 = _point("G2", P2, B, l2 / 2 * B.x, N)
    G3 = _point("G3", P3, C, l3 / 2 * C.x, N)
    conf, vel = _cut(P4, pivot, N)
    bodies = [_bar("crank", A, G1, rho * l1, l1), _bar("coupler", B, G2, rho * l2, l2),
              _bar("rocker", C, G3, rho * l3, l3)]
    kane = _kane(N, q, u, 1, bodies, _weights(bodies, g, N), conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"q2": 1.0, "q3": -2.4})


# -- four-bar, absolute angles, plate coupler, motor and damper --------------------

def fourbar_hand() -> Reference:
    th1, th2, th3 = q = list(me.dynamicsymbols("th1 th2 th3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("d1 d2 l1 l2 l3 a b m1 m2 m3 J2 c g T")
    N = me.ReferenceFrame("N")
    A1, A2, A3 = (_frame(N, f"A{i}", qi, ui) for i, qi, ui in zip((1, 2, 3), q, u))
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    D = _ground("D", O, P["d1"] * N.x + P["d2"] * N.y, N)
    B = _point("B", O, A1, P["l1"] * A1.x, N)
    C = _point("C", B, A2, P["l2"] * A2.x, N)
    C3 = _point("C3", D, A3, P["l3"] * A3.x, N)
    G1 = _point("G1", O, A1, P["l1"] / 2 * A1.x, N)
    G2 = _point("G2", B, A2, P["a"] * A2.x + P["b"] * A2.y, N)
    G3 = _point("G3", D, A3, P["l3"] / 2 * A3.x, N)
    conf, vel = _cut(C, C3, N)
    bodies = [_bar("crank", A1, G1, P["m1"], P["l1"]), _plate("coupler", A2, G2, P["m2"], P["J2"]),
              _bar("rocker", A3, G3, P["m3"], P["l3"])]
    loads = _weights(bodies, P["g"], N) + [(A1, P["T"] * N.z), (A3, -P["c"] * u[2] * N.z)]
    kane = _kane(N, q, u, 1, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"th2": 1.15, "th3": 2.03})


# -- crank-slider with flywheel ----------------------------------------------------

def slider_flywheel() -> Reference:
    th, phi, x = q = list(me.dynamicsymbols("th phi x"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("r L e w Jf mf mr ms k L0 c g T")
    N = me.ReferenceFrame("N")
    W = _frame(N, "W", th, u[0])
    R = _frame(N, "R", phi, u[1])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    pin = _point("pin", O, W, P["r"] * W.x, N)
    end = _point("end", pin, R, P["L"] * R.x, N)
    Gr = _point("Gr", pin, R, P["L"] / 2 * R.x, N)
    S = O.locatenew("S", x * N.x + P["e"] * N.y)
    S.set_vel(N, u[2] * N.x)
    wall = _ground("wall", O, -P["w"] * N.x + P["e"] * N.y, N)
    conf, vel = _cut(end, S, N)
    flywheel = _plate("flywheel", W, O, P["mf"], P["Jf"])
    rod = _bar("rod", R, Gr, P["mr"], P["L"])
    block = me.Particle("block", S, P["ms"])
    line = _line_force(wall, S, N, P["k"], P["L0"], P["c"])
    loads = [(Gr, -P["mr"] * P["g"] * N.y), (S, -P["ms"] * P["g"] * N.y + line), (W, P["T"] * N.z),
             (O, -P["mf"] * P["g"] * N.y)]
    kane = _kane(N, q, u, 1, [flywheel, rod, block], loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=q[1:],
                     guess={"phi": 0.0, "x": 0.85})


# -- Watt six-bar ------------------------------------------------------------------

def watt6() -> Reference:
    th1, phi2, th3, phi4, phi5 = q = list(me.dynamicsymbols("th1 phi2 th3 phi4 phi5"))
    u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("d l1 l2 l3 ex ey fx fy l4 l5 m1 m2 m3 m4 m5 J2 J3 k g T")
    N = me.ReferenceFrame("N")
    F1 = _frame(N, "F1", th1, u[0])
    F2 = _frame(F1, "F2", phi2, u[1])
    F3 = _frame(N, "F3", th3, u[2])
    F4 = _frame(F2, "F4", phi4, u[3])
    F5 = _frame(F3, "F5", phi5, u[4])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    D = _ground("D", O, P["d"] * N.x, N)
    A = _point("A", O, F1, P["l1"] * F1.x, N)
    B2 = _point("B2", A, F2, P["l2"] * F2.x, N)
    B3 = _point("B3", D, F3, P["l3"] * F3.x, N)
    E = _point("E", A, F2, P["ex"] * F2.x + P["ey"] * F2.y, N)
    Fp = _point("Fp", D, F3, P["fx"] * F3.x + P["fy"] * F3.y, N)
    G4 = _point("G4", E, F4, P["l4"] * F4.x, N)
    G5 = _point("G5", Fp, F5, P["l5"] * F5.x, N)
    # centres: the crank's and the binary links' midpoints, the ternary links' triangle centroids
    C1 = _point("C1", O, F1, P["l1"] / 2 * F1.x, N)
    C2 = _point("C2", A, F2, (P["l2"] + P["ex"]) / 3 * F2.x + P["ey"] / 3 * F2.y, N)
    C3 = _point("C3", D, F3, (P["l3"] + P["fx"]) / 3 * F3.x + P["fy"] / 3 * F3.y, N)
    C4 = _point("C4", E, F4, P["l4"] / 2 * F4.x, N)
    C5 = _point("C5", Fp, F5, P["l5"] / 2 * F5.x, N)
    anchor = _ground("anchor", O, sp.Rational(1, 2) * N.x + sp.Rational(3, 2) * N.y, N)
    conf1, vel1 = _cut(B2, B3, N)
    conf2, vel2 = _cut(G4, G5, N)
    bodies = [_bar("crank", F1, C1, P["m1"], P["l1"]), _plate("coupler", F2, C2, P["m2"], P["J2"]),
              _plate("rocker", F3, C3, P["m3"], P["J3"]), _bar("link4", F4, C4, P["m4"], P["l4"]),
              _bar("link5", F5, C5, P["m5"], P["l5"])]
    loads = _weights(bodies, P["g"], N) + [(F1, P["T"] * N.z), (G4, _line_force(anchor, G4, N, P["k"]))]
    kane = _kane(N, q, u, 1, bodies, loads, conf1 + conf2, vel1 + vel2)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel1 + vel2), _named(q), configuration=conf1 + conf2,
                     q_dep=q[1:], guess={"phi2": 0.92, "th3": 1.69, "phi4": -1.08, "phi5": -0.95}, spread=0.8)


# -- PyDy's n-pendulum on a cart, relative angles ----------------------------------

def cart_pend4_rel() -> Reference:
    n = 4
    x, *qs = q = list(me.dynamicsymbols("x q1:5"))
    u = list(me.dynamicsymbols("u0:5"))
    P = _symbols("M m1 m2 m3 m4 l1 l2 l3 l4 g F")
    N = me.ReferenceFrame("N")
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    cart = O.locatenew("P0", x * N.x)
    cart.set_vel(N, u[0] * N.x)
    particles = [me.Particle("cart", cart, P["M"])]
    loads = [(cart, P["F"] * N.x)]
    frame, point = N, cart
    for i in range(1, n + 1):
        frame = _frame(frame, f"B{i}", qs[i - 1], u[i])
        point = _point(f"P{i}", point, frame, P[f"l{i}"] * frame.x, N)
        particles.append(me.Particle(f"p{i}", point, P[f"m{i}"]))
        loads.append((point, -P[f"m{i}"] * P["g"] * N.y))
    kane = _kane(N, q, u, len(q), particles, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- double pendulum on a cart, spring and damper to a wall -------------------------

def double_cart_wall() -> Reference:
    x, th1, th2 = q = list(me.dynamicsymbols("x th1 th2"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("M m1 m2 l1 l2 k L0 c cj h g F")
    N = me.ReferenceFrame("N")
    U = _frame(N, "U", th1, u[1])
    Lw = _frame(N, "Lw", th2, u[2])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    wall = _ground("wall", O, -N.x + P["h"] * N.y, N)
    pivot = O.locatenew("pivot", x * N.x)
    pivot.set_vel(N, u[0] * N.x)
    hook = pivot.locatenew("hook", P["h"] * N.y)
    hook.set_vel(N, u[0] * N.x)
    elbow = _point("elbow", pivot, U, -P["l1"] * U.y, N)
    G1 = _point("G1", pivot, U, -P["l1"] / 2 * U.y, N)
    G2 = _point("G2", elbow, Lw, -P["l2"] / 2 * Lw.y, N)
    upper = _bar("upper", U, G1, P["m1"], P["l1"], along="y")
    lower = _bar("lower", Lw, G2, P["m2"], P["l2"], along="y")
    cart = me.Particle("cart", pivot, P["M"])
    elbow_torque = -P["cj"] * (u[2] - u[1]) * N.z  # on the lower bar; minus it on the upper
    loads = [(pivot, P["F"] * N.x), (G1, -P["m1"] * P["g"] * N.y), (G2, -P["m2"] * P["g"] * N.y),
             (hook, _line_force(wall, hook, N, P["k"], P["L0"], P["c"])),
             (Lw, elbow_torque), (U, -elbow_torque)]
    kane = _kane(N, q, u, 3, [cart, upper, lower], loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- three-link chain with joint springs and dampers --------------------------------

def chain3_springs() -> Reference:
    q = list(me.dynamicsymbols("q1:4"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("m1 m2 m3 l1 l2 l3 k1 k2 k3 c1 c2 c3 a1 a2 a3 g")
    N = me.ReferenceFrame("N")
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    frames, bodies, loads = [], [], []
    parent, joint = N, O
    for i in range(3):
        F = _frame(parent, f"L{i + 1}", q[i], u[i])
        l, m = P[f"l{i + 1}"], P[f"m{i + 1}"]
        G = _point(f"G{i + 1}", joint, F, -l / 2 * F.y, N)
        bodies.append(_bar(f"link{i + 1}", F, G, m, l, along="y"))
        tau = (-P[f"k{i + 1}"] * (q[i] - P[f"a{i + 1}"]) - P[f"c{i + 1}"] * u[i]) * N.z
        loads.append((F, tau))
        if parent is not N:
            loads.append((parent, -tau))
        joint = _point(f"J{i + 2}", joint, F, -l * F.y, N)
        parent = F
    loads += _weights(bodies, P["g"], N)
    kane = _kane(N, q, u, 3, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- planar five-bar parallel manipulator --------------------------------------------

def parallel_fivebar() -> Reference:
    th1, th2, ph1, ph2 = q = list(me.dynamicsymbols("th1 th2 ph1 ph2"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("d a1 a2 b1 b2 m1 m2 m3 m4 mp g T1 T2")
    N = me.ReferenceFrame("N")
    C1 = _frame(N, "C1", th1, u[0])
    C2 = _frame(N, "C2", th2, u[1])
    D1 = _frame(C1, "D1", ph1, u[2])
    D2 = _frame(C2, "D2", ph2, u[3])
    O = _ground("O", me.Point("O0"), 0 * N.x, N)
    O2 = _ground("O2", O, P["d"] * N.x, N)
    E1 = _point("E1", O, C1, P["a1"] * C1.x, N)
    E2 = _point("E2", O2, C2, P["a2"] * C2.x, N)
    tip1 = _point("tip1", E1, D1, P["b1"] * D1.x, N)
    tip2 = _point("tip2", E2, D2, P["b2"] * D2.x, N)
    G1 = _point("G1", O, C1, P["a1"] / 2 * C1.x, N)
    G2 = _point("G2", O2, C2, P["a2"] / 2 * C2.x, N)
    G3 = _point("G3", E1, D1, P["b1"] / 2 * D1.x, N)
    G4 = _point("G4", E2, D2, P["b2"] / 2 * D2.x, N)
    conf, vel = _cut(tip1, tip2, N)
    bodies = [_bar("crank1", C1, G1, P["m1"], P["a1"]), _bar("crank2", C2, G2, P["m2"], P["a2"]),
              _bar("dist1", D1, G3, P["m3"], P["b1"]), _bar("dist2", D2, G4, P["m4"], P["b2"]),
              me.Particle("payload", tip1, P["mp"])]
    loads = _weights(bodies[:4], P["g"], N) + [(tip1, -P["mp"] * P["g"] * N.y),
                                               (C1, P["T1"] * N.z), (C2, P["T2"] * N.z)]
    kane = _kane(N, q, u, 2, bodies, loads, conf, vel)
    return Reference(KaneModel(kane, q, u[:2], u[2:], P, vel), _named(q), configuration=conf, q_dep=q[2:],
                     guess={"ph1": 1.28, "ph2": 1.86}, spread=0.6)


SYSTEMS = {
    "l5_fourbar_docs": (HERE / "l5_fourbar_docs.yaml", fourbar_docs, None),
    "l5_fourbar_hand": (HERE / "l5_fourbar_hand.yaml", fourbar_hand, None),
    "l5_slider_flywheel": (HERE / "l5_slider_flywheel.yaml", slider_flywheel, None),
    "l5_watt6": (HERE / "l5_watt6.yaml", watt6, None),
    "l5_cart_pend4_rel": (HERE / "l5_cart_pend4_rel.yaml", cart_pend4_rel, None),
    "l5_double_cart_wall": (HERE / "l5_double_cart_wall.yaml", double_cart_wall, None),
    "l5_chain3_joint_springs": (HERE / "l5_chain3_joint_springs.yaml", chain3_springs, None),
    "l5_parallel_fivebar": (HERE / "l5_parallel_fivebar.yaml", parallel_fivebar, None),
}
