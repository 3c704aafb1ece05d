"""KanesMethod references for the v47_ systems, built from the mechanics.

Every constraint is formed here from its definition (a loop's two ends at one
place, a knife edge's point not moving across its blade, the material points
in contact having one velocity), never from the gacli file's rows.
"""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


# -- helpers ---------------------------------------------------------------------------

def _turned(parent, name, angle, rate, axis="z"):
    F = parent.orientnew(name, "Axis", [angle, getattr(parent, axis)])
    F.set_ang_vel(parent, rate * getattr(parent, axis))
    return F


def _fixed(name, base, vec, N):
    P = base.locatenew(name, vec)
    P.set_vel(N, 0)
    return P


def _on(name, base, frame, vec, N):
    """A point fixed in ``frame`` at ``vec`` from ``base`` (also fixed in it)."""
    P = base.locatenew(name, vec)
    P.v2pt_theory(base, N, frame)
    return P


def _planar_bar(name, frame, G, m, l):
    return me.RigidBody(name, G, frame, m, (me.inertia(frame, 0, m * l**2 / 12, m * l**2 / 12), G))


def _planar(name, frame, G, m, J):
    return me.RigidBody(name, G, frame, m, (me.inertia(frame, 0, 0, J), G))


def _closure(P, Q, N, axes=("x", "y")):
    """Holonomic loop equations P = Q and their velocity form, along N's axes."""
    r = P.pos_from(Q)
    v = P.vel(N) - Q.vel(N)
    return [r.dot(getattr(N, a)) for a in axes], [v.dot(getattr(N, a)) for a in axes]


def _qdot_is_u(q, u):
    return [qi.diff(t) - ui for qi, ui in zip(q, u)]


# -- 1. inverted slider-crank, absolute angles --------------------------------------------

def inv_slider_crank() -> Reference:
    th, phi, s = q = list(me.dynamicsymbols("th phi s"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("r d L m1 m2 ms Js g T")
    N = me.ReferenceFrame("N")
    C = _turned(N, "C", th, u[0])     # crank
    Lv = _turned(N, "Lv", phi, u[1])  # slotted lever
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    D = _fixed("D", O, P["d"] * N.x, N)
    A = _on("A", O, C, P["r"] * C.x, N)          # crank pin (the block's centre)
    G1 = _on("G1", O, C, P["r"] / 2 * C.x, N)
    G2 = _on("G2", D, Lv, P["L"] / 2 * Lv.x, N)
    # the point of the slot at distance s from D: it slides along the lever
    S = D.locatenew("S", s * Lv.x)
    S.set_vel(N, u[2] * Lv.x + s * u[1] * Lv.y)
    conf, vel = _closure(A, S, N)
    crank = _planar_bar("crank", C, G1, P["m1"], P["r"])
    lever = _planar_bar("lever", Lv, G2, P["m2"], P["L"])
    block = _planar("block", Lv, A, P["ms"], P["Js"])   # turns with the lever, centre at the pin
    g = P["g"]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (A, -P["ms"] * g * N.y), (C, P["T"] * N.z)]
    kane = me.KanesMethod(N, q_ind=[th], q_dependent=[phi, s], u_ind=[u[0]], u_dependent=u[1:],
                          kd_eqs=_qdot_is_u(q, u), configuration_constraints=conf, velocity_constraints=vel)
    kane.kanes_equations([crank, lever, block], loads)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=[phi, s],
                     guess={"phi": 1.0, "s": 0.4})


# -- 2. four-bar, relative angles, coupler point mass, torsion spring ------------------------

def fourbar_coupler_spring() -> Reference:
    q1, q2, q3 = q = list(me.dynamicsymbols("q1:4"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("l0 l1 l2 l3 m1 m2 m3 mp a b k q10 g")
    N = me.ReferenceFrame("N")
    A = _turned(N, "A", q1, u[0])
    B = _turned(A, "B", q2, u[1])
    C = _turned(B, "C", q3, u[2])
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    D = _fixed("D", O, P["l0"] * N.x, N)
    Bp = _on("Bp", O, A, P["l1"] * A.x, N)
    Cp = _on("Cp", Bp, B, P["l2"] * B.x, N)
    end = _on("end", Cp, C, P["l3"] * C.x, N)
    G1 = _on("G1", O, A, P["l1"] / 2 * A.x, N)
    G2 = _on("G2", Bp, B, P["l2"] / 2 * B.x, N)
    G3 = _on("G3", Cp, C, P["l3"] / 2 * C.x, N)
    Pm = _on("Pm", Bp, B, P["a"] * B.x + P["b"] * B.y, N)
    conf, vel = _closure(end, D, N)
    bodies = [_planar_bar("crank", A, G1, P["m1"], P["l1"]), _planar_bar("coupler", B, G2, P["m2"], P["l2"]),
              _planar_bar("rocker", C, G3, P["m3"], P["l3"]), me.Particle("point", Pm, P["mp"])]
    g = P["g"]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (G3, -P["m3"] * g * N.y),
             (Pm, -P["mp"] * g * N.y), (A, -P["k"] * (q1 - P["q10"]) * N.z)]   # the spring, ground on crank
    kane = me.KanesMethod(N, q_ind=[q1], q_dependent=[q2, q3], u_ind=[u[0]], u_dependent=u[1:],
                          kd_eqs=_qdot_is_u(q, u), configuration_constraints=conf, velocity_constraints=vel)
    kane.kanes_equations(bodies, loads)
    # crank-rocker branch: coupler turned back up, rocker turned back towards D
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, vel), _named(q), configuration=conf, q_dep=[q2, q3],
                     guess={"q2": 0.2, "q3": 1.9})


# -- 3. five-bar with two motors, a tip mass and a line spring -------------------------------

def fivebar_motors() -> Reference:
    th1, th2, ph1, ph2 = q = list(me.dynamicsymbols("th1 th2 ph1 ph2"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("d h a1 a2 b1 b2 m1 m2 m3 m4 mt k L0 ax ay g T1 T2")
    N = me.ReferenceFrame("N")
    C1, C2, E1f, E2f = (_turned(N, n, qi, ui) for n, qi, ui in zip(("C1", "C2", "E1f", "E2f"), q, u))
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    D = _fixed("D", O, P["d"] * N.x + P["h"] * N.y, N)
    anchor = _fixed("anchor", O, P["ax"] * N.x + P["ay"] * N.y, N)
    E1 = _on("E1", O, C1, P["a1"] * C1.x, N)
    E2 = _on("E2", D, C2, P["a2"] * C2.x, N)
    tip1 = _on("tip1", E1, E1f, P["b1"] * E1f.x, N)
    tip2 = _on("tip2", E2, E2f, P["b2"] * E2f.x, N)
    G1 = _on("G1", O, C1, P["a1"] / 2 * C1.x, N)
    G2 = _on("G2", D, C2, P["a2"] / 2 * C2.x, N)
    G3 = _on("G3", E1, E1f, P["b1"] / 2 * E1f.x, N)
    G4 = _on("G4", E2, E2f, P["b2"] / 2 * E2f.x, N)
    conf, vel = _closure(tip1, tip2, N)
    bodies = [_planar_bar("crank1", C1, G1, P["m1"], P["a1"]), _planar_bar("crank2", C2, G2, P["m2"], P["a2"]),
              _planar_bar("link1", E1f, G3, P["m3"], P["b1"]), _planar_bar("link2", E2f, G4, P["m4"], P["b2"]),
              me.Particle("tip", tip1, P["mt"])]
    r = tip1.pos_from(anchor)
    length = sp.sqrt(r.dot(r))
    spring = -P["k"] * (length - P["L0"]) * r / length   # on the tip, pulling it towards the anchor
    g = P["g"]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (G3, -P["m3"] * g * N.y),
             (G4, -P["m4"] * g * N.y), (tip1, -P["mt"] * g * N.y + spring),
             (C1, P["T1"] * N.z), (C2, P["T2"] * N.z)]
    kane = me.KanesMethod(N, q_ind=[th1, th2], q_dependent=[ph1, ph2], u_ind=u[:2], u_dependent=u[2:],
                          kd_eqs=_qdot_is_u(q, u), configuration_constraints=conf, velocity_constraints=vel)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u[:2], u[2:], P, vel), _named(q), configuration=conf, q_dep=[ph1, ph2],
                     guess={"ph1": 1.1, "ph2": 2.0}, spread=0.6)


# -- 4. Chaplygin sleigh, forward speed and yaw rate -----------------------------------------

def sleigh_speeds() -> Reference:
    xc, yc, th = q = list(me.dynamicsymbols("xc yc th"))
    v, w, vs = u = list(me.dynamicsymbols("v w vs"))   # forward, yaw rate, sideways speed of G
    P = _symbols("m I b c F Tq")
    N = me.ReferenceFrame("N")
    S = _turned(N, "S", th, w)
    kd = [sp.cos(th) * xc.diff(t) + sp.sin(th) * yc.diff(t) - v,
          th.diff(t) - w,
          -sp.sin(th) * xc.diff(t) + sp.cos(th) * yc.diff(t) - vs]
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    G = O.locatenew("G", xc * N.x + yc * N.y)
    G.set_vel(N, v * S.x + vs * S.y)
    blade = G.locatenew("blade", -P["b"] * S.x)
    blade.v2pt_theory(G, N, S)
    vel = [blade.vel(N).dot(S.y)]        # the knife edge: no velocity across the blade
    body = _planar("sleigh", S, G, P["m"], P["I"])
    loads = [(G, (P["F"] - P["c"] * v) * S.x), (S, P["Tq"] * N.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[v, w], u_dependent=[vs], kd_eqs=kd, velocity_constraints=vel)
    kane.kanes_equations([body], loads)
    return Reference(KaneModel(kane, q, [v, w], [vs], P, vel), _named(q))


# -- 5. cart with a knife-edge wheel and a pendulum ------------------------------------------

def cart_pendulum_knife() -> Reference:
    x, y, psi, phi = q = list(me.dynamicsymbols("x y psi phi"))
    u = list(me.dynamicsymbols("u1:5"))   # x', psi', phi' independent; y' dependent
    ux, upsi, uphi, uy = u
    P = _symbols("M Ixx Iyy Izz b hc e hp m l g F Ts")
    N = me.ReferenceFrame("N")
    Cf = _turned(N, "Cf", psi, upsi, "z")
    Pf = _turned(Cf, "Pf", phi, uphi, "x")
    kd = [x.diff(t) - ux, psi.diff(t) - upsi, phi.diff(t) - uphi, y.diff(t) - uy]
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    Pw = O.locatenew("Pw", x * N.x + y * N.y)
    Pw.set_vel(N, ux * N.x + uy * N.y)
    Gc = _on("Gc", Pw, Cf, P["b"] * Cf.x + P["hc"] * Cf.z, N)
    pivot = _on("pivot", Pw, Cf, P["e"] * Cf.x + P["hp"] * Cf.z, N)
    Gp = _on("Gp", pivot, Pf, -P["l"] / 2 * Pf.z, N)
    vel = [Pw.vel(N).dot(Cf.y)]
    m, l, g = P["m"], P["l"], P["g"]
    cart = me.RigidBody("cart", Gc, Cf, P["M"], (me.inertia(Cf, P["Ixx"], P["Iyy"], P["Izz"]), Gc))
    pend = me.RigidBody("pend", Gp, Pf, m, (me.inertia(Pf, m * l**2 / 12, m * l**2 / 12, 0), Gp))
    loads = [(Gc, -P["M"] * g * N.z), (Gp, -m * g * N.z), (Pw, P["F"] * Cf.x), (Cf, P["Ts"] * Cf.z)]
    qs = [x, psi, phi, y]
    kane = me.KanesMethod(N, q_ind=qs, u_ind=[ux, upsi, uphi], u_dependent=[uy], kd_eqs=kd,
                          velocity_constraints=vel)
    kane.kanes_equations([cart, pend], loads)
    return Reference(KaneModel(kane, q, [ux, upsi, uphi], [uy], P, vel), _named(q))


# -- 6. disc rolling inside a freely turning ring ---------------------------------------------

def disc_in_ring() -> Reference:
    theta, phi, psi = q = list(me.dynamicsymbols("theta phi psi"))
    ut, uph, ups = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("M a R Jr Mr cr g c")
    M, a, R = P["M"], P["a"], P["R"]
    c = R - a   # the file's c has the value R - a; here it is formed from the geometry
    N = me.ReferenceFrame("N")
    E = _turned(N, "E", theta, ut)       # line of centres: E.x = (sin, -cos)?  use -E.y downward
    Df = _turned(N, "Df", phi, uph)
    Rf = _turned(N, "Rf", psi, ups)
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    # E turned by theta: -E.y is the direction from O to the disc centre (down at theta = 0)
    G = _on("G", O, E, -c * E.y, N)
    # contact point: on the ring at distance R from O along -E.y; material points of disc and ring there
    contact_disc = G.vel(N) + Df.ang_vel_in(N).cross(-a * E.y)
    contact_ring = Rf.ang_vel_in(N).cross(-R * E.y)
    slip = contact_disc - contact_ring
    vel = [slip.dot(E.x)]     # the tangential component; the normal one vanishes identically
    disc = _planar("disc", Df, G, M, M * a**2 / 2)
    ring = _planar("ring", Rf, O, P["Mr"], P["Jr"])
    loads = [(G, -M * P["g"] * N.y), (Rf, -P["cr"] * ups * N.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[ut, ups], u_dependent=[uph], kd_eqs=_qdot_is_u(q, u),
                          velocity_constraints=vel)
    kane.kanes_equations([disc, ring], loads)
    return Reference(KaneModel(kane, q, [ut, ups], [uph], P, vel), _named(q))


# -- 7. double pendulum, support driven along an incline ---------------------------------------

def incline_double_pendulum() -> Reference:
    q1, q2 = q = list(me.dynamicsymbols("q1 q2"))
    u = list(me.dynamicsymbols("u1 u2"))
    P = _symbols("m1 m2 l1 l2 alpha A w V g")
    N = me.ReferenceFrame("N")
    rail = N.orientnew("rail", "Axis", [P["alpha"], N.z])
    s = P["A"] * sp.sin(P["w"] * t) + P["V"] * t
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    S = O.locatenew("S", s * rail.x)
    S.set_vel(N, s.diff(t) * rail.x)
    R1 = _turned(N, "R1", q1, u[0])
    R2 = _turned(N, "R2", q2, u[1])
    P1 = _on("P1", S, R1, -P["l1"] * R1.y, N)
    P2 = _on("P2", P1, R2, -P["l2"] * R2.y, N)
    bodies = [me.Particle("bob1", P1, P["m1"]), me.Particle("bob2", P2, P["m2"])]
    loads = [(P1, -P["m1"] * P["g"] * N.y), (P2, -P["m2"] * P["g"] * N.y)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=_qdot_is_u(q, u))
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 8. gyroscope in a two-axis gimbal -----------------------------------------------------------

def gimbal_gyro() -> Reference:
    psi, theta, phi = q = list(me.dynamicsymbols("psi theta phi"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("A1 B1 C1 A2 B2 C2 m At Cr m1 m2 h g To Tm")
    N = me.ReferenceFrame("N")
    Fo = _turned(N, "Fo", psi, u[0], "z")
    Fi = _turned(Fo, "Fi", theta, u[1], "x")
    Fr = _turned(Fi, "Fr", phi, u[2], "z")
    O = _fixed("O", me.Point("O0"), 0 * N.x, N)
    Gr = _on("Gr", O, Fi, P["h"] * Fi.z, N)
    outer = me.RigidBody("outer", O, Fo, P["m1"], (me.inertia(Fo, P["A1"], P["B1"], P["C1"]), O))
    inner = me.RigidBody("inner", O, Fi, P["m2"], (me.inertia(Fi, P["A2"], P["B2"], P["C2"]), O))
    rotor = me.RigidBody("rotor", Gr, Fr, P["m"], (me.inertia(Fr, P["At"], P["At"], P["Cr"]), Gr))
    loads = [(Gr, -P["m"] * P["g"] * N.z), (Fo, P["To"] * Fo.z),
             (Fr, P["Tm"] * Fi.z), (Fi, -P["Tm"] * Fi.z)]   # rotor motor, reaction on the inner gimbal
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=_qdot_is_u(q, u))
    kane.kanes_equations([outer, inner, rotor], loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


SYSTEMS = {
    "v47_inv_slider_crank": (HERE / "v47_inv_slider_crank.yaml", inv_slider_crank,
                             "inverted slider-crank, absolute angles, format 1"),
    "v47_fourbar_coupler_spring": (HERE / "v47_fourbar_coupler_spring.yaml", fourbar_coupler_spring,
                                   "four-bar, relative angles written out, coupler mass, torsion spring"),
    "v47_fivebar_motors": (HERE / "v47_fivebar_motors.yaml", fivebar_motors,
                           "five-bar, frames, coincide, two motors, tip mass, line spring"),
    "v47_sleigh_speeds": (HERE / "v47_sleigh_speeds.yaml", sleigh_speeds,
                          "Chaplygin sleigh, forward speed and yaw rate, format 1"),
    "v47_cart_pendulum_knife": (HERE / "v47_cart_pendulum_knife.yaml", cart_pendulum_knife,
                                "cart with knife edge and pendulum, frames"),
    "v47_disc_in_ring": (HERE / "v47_disc_in_ring.yaml", disc_in_ring,
                         "disc rolling inside a freely turning ring, format 1"),
    "v47_incline_double_pendulum": (HERE / "v47_incline_double_pendulum.yaml", incline_double_pendulum,
                                    "double pendulum, support driven along an incline s(t), frames"),
    "v47_gimbal_gyro": (HERE / "v47_gimbal_gyro.yaml", gimbal_gyro,
                        "gyroscope in a two-axis gimbal, rotor motor with reaction, frames"),
}
