"""KanesMethod references for the f7_* files, built from definitions (SymPy frames/points)."""
from __future__ import annotations

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
# This checkout's benchmarks, never a path of one machine: a fixed /work/main/benchmarks put that
# checkout's bench modules, and through them its gacli, under every variant run of another worktree.
for p in (str(HERE.parents[2]), str(HERE.parents[1])):
    if p not in sys.path:
        sys.path.append(p)

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference

t = me.dynamicsymbols._t


def _symbols(names):
    return {s.name: s for s in sp.symbols(names, seq=True)}


def _named(q):
    return {qi: qi.func.__name__ for qi in q}


def _kane(N, q, u, kd, bodies, loads):
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return kane


def _Ebody(e0, e1, e2, e3):
    return sp.Matrix([[-e1, e0, e3, -e2], [-e2, -e3, e0, e1], [-e3, e2, -e1, e0]])


def _Espace(e0, e1, e2, e3):
    return sp.Matrix([[-e1, e0, -e3, e2], [-e2, e3, e0, -e1], [-e3, -e2, e1, e0]])


def _line(A, B, k, L0, c, N):
    """Spring (k, free length L0) and damper c between points A and B: forces on both ends."""
    r = B.pos_from(A).to_matrix(N)
    l = sp.sqrt((r.T * r)[0])
    v = (B.vel(N) - A.vel(N)).to_matrix(N)
    ldot = (r.T * v)[0] / l
    tension = k * (l - L0) + c * ldot  # pulls the ends together
    e = B.pos_from(A) / l
    return [(A, tension * e), (B, -tension * e)]


def quat_scalar_last():
    x, y, z, qx, qy, qz, qw = q = list(me.dynamicsymbols("x y z qx qy qz qw"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m A B C D g")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("B")
    Bf.orient_quaternion(N, [qw, qx, qy, qz])
    Bf.set_ang_vel(N, u[3] * Bf.x + u[4] * Bf.y + u[5] * Bf.z)
    ed = _Ebody(qw, qx, qy, qz).T * sp.Matrix(u[3:]) / 2   # rates of (qw, qx, qy, qz)
    rate = {qw: ed[0], qx: ed[1], qy: ed[2], qz: ed[3]}
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [s.diff(t) - rate[s] for s in (qx, qy, qz, qw)]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    I = me.inertia(Bf, P["A"], P["B"], P["C"], ixy=P["D"])
    body = me.RigidBody("body", G, Bf, P["m"], (I, G))
    kane = _kane(N, q, u, kd, [body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=[qx**2 + qy**2 + qz**2 + qw**2 - 1],
                     q_dep=[qw], spread=0.5)


def quat_space_rates():
    x, y, z, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y z e0 e1 e2 e3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m A B C g")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("B")
    Bf.orient_quaternion(N, [e0, e1, e2, e3])
    Bf.set_ang_vel(N, u[3] * N.x + u[4] * N.y + u[5] * N.z)   # space-fixed components
    ed = _Espace(e0, e1, e2, e3).T * sp.Matrix(u[3:]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [s.diff(t) - ed[i] for i, s in enumerate((e0, e1, e2, e3))]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    body = me.RigidBody("body", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = _kane(N, q, u, kd, [body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=[e0**2 + e1**2 + e2**2 + e3**2 - 1],
                     q_dep=[e0], spread=0.5)


def thrust_f1():
    x, y, z, psi, theta, phi = q = list(me.dynamicsymbols("x y z psi theta phi"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m A B C g T h")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("B")
    Bf.orient_body_fixed(N, (psi, theta, phi), "ZYX")
    rates = {qi.diff(t): ui for qi, ui in zip(q, u)}
    Bf.set_ang_vel(N, Bf.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    Pt = G.locatenew("P", -P["h"] * Bf.z)
    Pt.v2pt_theory(G, N, Bf)
    body = me.RigidBody("rocket", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    loads = [(G, -P["m"] * P["g"] * N.z), (Pt, P["T"] * Bf.x)]
    kane = _kane(N, q, u, kd, [body], loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def quat_spring_damper():
    x, y, z, q0, q1, q2, q3 = q = list(me.dynamicsymbols("x y z q0 q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m A B C k c L0 a b")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("B")
    Bf.orient_quaternion(N, [q0, q1, q2, q3])
    Bf.set_ang_vel(N, u[3] * Bf.x + u[4] * Bf.y + u[5] * Bf.z)
    ed = _Ebody(q0, q1, q2, q3).T * sp.Matrix(u[3:]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [s.diff(t) - ed[i] for i, s in enumerate((q0, q1, q2, q3))]
    O = me.Point("O"); O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    H = G.locatenew("H", P["a"] * Bf.x + P["b"] * Bf.y)
    H.v2pt_theory(G, N, Bf)
    body = me.RigidBody("body", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    loads = _line(O, H, P["k"], P["L0"], P["c"], N)
    kane = _kane(N, q, u, kd, [body], loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=[q0**2 + q1**2 + q2**2 + q3**2 - 1],
                     q_dep=[q0], spread=0.5)


def chain3_quat():
    names = ["a", "b", "c"]
    q, u, conf, kd, qdep = [], [], [], [], []
    P = _symbols("g m1 L1 A1 B1 C1 m2 L2 A2 B2 C2 m3 L3 A3 B3 C3")
    N = me.ReferenceFrame("N")
    O = me.Point("O"); O.set_vel(N, 0)
    joint, bodies, loads = O, [], []
    speeds = [me.dynamicsymbols("p1 p2 p3"), me.dynamicsymbols("r1 r2 r3"), me.dynamicsymbols("s1 s2 s3")]
    for i, nm in enumerate(names, start=1):
        e = list(me.dynamicsymbols(f"{nm}0 {nm}1 {nm}2 {nm}3"))
        w = list(speeds[i - 1])
        q += e; u += w; qdep.append(e[0])
        F = me.ReferenceFrame(f"B{i}")
        F.orient_quaternion(N, e)
        F.set_ang_vel(N, w[0] * F.x + w[1] * F.y + w[2] * F.z)
        ed = _Ebody(*e).T * sp.Matrix(w) / 2
        kd += [s.diff(t) - ed[j] for j, s in enumerate(e)]
        conf.append(sum(s**2 for s in e) - 1)
        m, L, A, B, C = (P[f"{s}{i}"] for s in "mLABC")
        G = joint.locatenew(f"G{i}", -L / 2 * F.z); G.v2pt_theory(joint, N, F)
        bodies.append(me.RigidBody(f"link{i}", G, F, m, (me.inertia(F, A, B, C), G)))
        loads.append((G, -m * P["g"] * N.z))
        J = joint.locatenew(f"J{i + 1}", -L * F.z); J.v2pt_theory(joint, N, F)
        joint = J
    kane = _kane(N, q, u, kd, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=conf, q_dep=qdep, spread=0.5)


def _bars_on(N, top, angles, speeds, masses, lengths, g, sign=1):
    bodies, loads, joint = [], [], top
    for i, (qi, ui, m, L) in enumerate(zip(angles, speeds, masses, lengths)):
        F = N.orientnew(f"bar{i + 1}", "Axis", [qi, N.z]); F.set_ang_vel(N, ui * N.z)
        G = joint.locatenew(f"G{i + 1}", -L / 2 * F.y); G.v2pt_theory(joint, N, F)
        bodies.append(me.RigidBody(f"bar{i + 1}", G, F, m, (me.inertia(F, m * L**2 / 12, 0, m * L**2 / 12), G)))
        loads.append((G, -m * g * N.y))
        J = joint.locatenew(f"J{i + 2}", -L * F.y); J.v2pt_theory(joint, N, F)
        joint = J
    return bodies, loads


def cart_pend5_f1():
    q = list(me.dynamicsymbols("x th1:6"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("M g F b m1 l1 m2 l2 m3 l3 m4 l4 m5 l5")
    N = me.ReferenceFrame("N")
    O = me.Point("O"); O.set_vel(N, 0)
    cart = O.locatenew("cart", q[0] * N.x); cart.set_vel(N, u[0] * N.x)
    bodies, loads = _bars_on(N, cart, q[1:], u[1:], [P[f"m{i}"] for i in range(1, 6)], [P[f"l{i}"] for i in range(1, 6)], P["g"])
    bodies.insert(0, me.Particle("cart", cart, P["M"]))
    loads += [(cart, -P["M"] * P["g"] * N.y + (P["F"] - P["b"] * u[0]) * N.x)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = _kane(N, q, u, kd, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def two_carts_bridge():
    x1, x2, th = q = list(me.dynamicsymbols("x1 x2 th"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("M1 M2 m L k L0 k2 c g")
    N = me.ReferenceFrame("N")
    O = me.Point("O"); O.set_vel(N, 0)
    c1 = O.locatenew("c1", x1 * N.x); c1.set_vel(N, u[0] * N.x)
    c2 = O.locatenew("c2", x2 * N.x); c2.set_vel(N, u[1] * N.x)
    Fb = N.orientnew("bar", "Axis", [th, N.z]); Fb.set_ang_vel(N, u[2] * N.z)
    G = c1.locatenew("G", -P["L"] / 2 * Fb.y); G.v2pt_theory(c1, N, Fb)
    tip = c1.locatenew("tip", -P["L"] * Fb.y); tip.v2pt_theory(c1, N, Fb)
    bodies = [me.Particle("cart1", c1, P["M1"]), me.Particle("cart2", c2, P["M2"]),
              me.RigidBody("bar", G, Fb, P["m"], (me.inertia(Fb, P["m"] * P["L"]**2 / 12, 0, P["m"] * P["L"]**2 / 12), G))]
    loads = [(G, -P["m"] * P["g"] * N.y)]
    loads += _line(tip, c2, P["k"], P["L0"], 0, N)
    loads += _line(c1, c2, 0, 0, P["c"], N)
    loads += [(c2, -P["k2"] * x2 * N.x)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = _kane(N, q, u, kd, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def cart_pole_pointmass():
    x, th = q = list(me.dynamicsymbols("x th"))
    u = list(me.dynamicsymbols("u1:3"))
    P = _symbols("M m mb l g F b")
    N = me.ReferenceFrame("N")
    O = me.Point("O"); O.set_vel(N, 0)
    cart = O.locatenew("cart", x * N.x); cart.set_vel(N, u[0] * N.x)
    pole = N.orientnew("pole", "Axis", [-th, N.z]); pole.set_ang_vel(N, -u[1] * N.z)
    G = cart.locatenew("G", P["l"] / 2 * pole.y); G.v2pt_theory(cart, N, pole)
    tip = cart.locatenew("tip", P["l"] * pole.y); tip.v2pt_theory(cart, N, pole)
    ml2 = P["m"] * P["l"]**2 / 12
    bodies = [me.Particle("cart", cart, P["M"]), me.RigidBody("rod", G, pole, P["m"], (me.inertia(pole, ml2, 0, ml2), G)),
              me.Particle("bob", tip, P["mb"])]
    loads = [(G, -P["m"] * P["g"] * N.y), (tip, -P["mb"] * P["g"] * N.y), (cart, (P["F"] - P["b"] * u[0]) * N.x)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = _kane(N, q, u, kd, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def prismatic_double():
    th1, s, th2 = q = list(me.dynamicsymbols("th1 s th2"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("m1 l1 mc Jc m2 l2 ks s0 g")
    N = me.ReferenceFrame("N")
    O = me.Point("O"); O.set_vel(N, 0)
    B1 = N.orientnew("B1", "Axis", [th1, N.z]); B1.set_ang_vel(N, u[0] * N.z)
    B2 = N.orientnew("B2", "Axis", [th2, N.z]); B2.set_ang_vel(N, u[2] * N.z)
    G1 = O.locatenew("G1", -P["l1"] / 2 * B1.y); G1.v2pt_theory(O, N, B1)
    Cc = O.locatenew("Cc", -s * B1.y)
    Cc.set_vel(B1, -u[1] * B1.y); Cc.v1pt_theory(O, N, B1)
    G2 = Cc.locatenew("G2", -P["l2"] / 2 * B2.y); G2.v2pt_theory(Cc, N, B2)
    bodies = [me.RigidBody("bar1", G1, B1, P["m1"], (me.inertia(B1, P["m1"] * P["l1"]**2 / 12, 0, P["m1"] * P["l1"]**2 / 12), G1)),
              me.RigidBody("collar", Cc, B1, P["mc"], (me.inertia(B1, 0, 0, P["Jc"]), Cc)),
              me.RigidBody("bar2", G2, B2, P["m2"], (me.inertia(B2, P["m2"] * P["l2"]**2 / 12, 0, P["m2"] * P["l2"]**2 / 12), G2))]
    spring = -P["ks"] * (s - P["s0"])   # along +s, i.e. along -B1.y
    loads = [(G1, -P["m1"] * P["g"] * N.y), (Cc, -P["mc"] * P["g"] * N.y + spring * (-B1.y)), (G2, -P["m2"] * P["g"] * N.y)]
    # the spring's reaction on bar1 acts at the collar's location on bar1: a force along B1.y through O's line has
    # no moment about O, so it does no work on bar1 (its point moves perpendicular to B1.y).
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = _kane(N, q, u, kd, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def top_on_cart():
    x, phi, theta, psi = q = list(me.dynamicsymbols("x phi theta psi"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("M m l A C kx g")
    N = me.ReferenceFrame("N")
    Tf = me.ReferenceFrame("T")
    Tf.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
    rates = {qi.diff(t): ui for qi, ui in zip(q, u)}
    Tf.set_ang_vel(N, Tf.ang_vel_in(N).subs(rates))
    O = me.Point("O"); O.set_vel(N, 0)
    piv = O.locatenew("piv", x * N.x); piv.set_vel(N, u[0] * N.x)
    G = piv.locatenew("G", P["l"] * Tf.z); G.v2pt_theory(piv, N, Tf)
    bodies = [me.Particle("cart", piv, P["M"]), me.RigidBody("top", G, Tf, P["m"], (me.inertia(Tf, P["A"], P["A"], P["C"]), G))]
    loads = [(G, -P["m"] * P["g"] * N.z), (piv, -P["M"] * P["g"] * N.z - P["kx"] * x * N.x)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = _kane(N, q, u, kd, bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


SYSTEMS = {
    "f7_quat_scalar_last": (HERE / "f7_quat_scalar_last.yaml", quat_scalar_last, None),
    "f7_quat_space_rates": (HERE / "f7_quat_space_rates.yaml", quat_space_rates, None),
    "f7_thrust_f1": (HERE / "f7_thrust_f1.yaml", thrust_f1, None),
    "f7_quat_spring_damper": (HERE / "f7_quat_spring_damper.yaml", quat_spring_damper, None),
    "f7_chain3_quat": (HERE / "f7_chain3_quat.yaml", chain3_quat, None),
    "f7_cart_pend5_f1": (HERE / "f7_cart_pend5_f1.yaml", cart_pend5_f1, None),
    "f7_two_carts_bridge": (HERE / "f7_two_carts_bridge.yaml", two_carts_bridge, None),
    "f7_cart_pole_pointmass": (HERE / "f7_cart_pole_pointmass.yaml", cart_pole_pointmass, None),
    "f7_prismatic_double": (HERE / "f7_prismatic_double.yaml", prismatic_double, None),
    "f7_top_on_cart": (HERE / "f7_top_on_cart.yaml", top_on_cart, None),
}
