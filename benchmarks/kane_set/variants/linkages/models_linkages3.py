"""KanesMethod references for the l3_ linkages and carts (written from the physical definitions)."""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _bar_x(name, frame, centre, m, l):
    return me.RigidBody(name, centre, frame, m, (me.inertia(frame, 0, m * l**2 / 12, m * l**2 / 12), centre))


def _bar_y(name, frame, centre, m, l):
    return me.RigidBody(name, centre, frame, m, (me.inertia(frame, m * l**2 / 12, 0, m * l**2 / 12), centre))


def _turn(parent, name, q, u):
    frame = parent.orientnew(name, "Axis", [q, parent.z])
    frame.set_ang_vel(parent, u * parent.z)
    return frame


def _gap_rows(P1, P2, N):
    gap = P1.pos_from(P2)
    v = P1.vel(N) - P2.vel(N)
    return [gap.dot(N.x), gap.dot(N.y)], [v.dot(N.x), v.dot(N.y)]


def slider_crank_f1() -> Reference:
    th, beta, x = q = list(me.dynamicsymbols("th beta x"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("r L e m1 m2 m3 c g T")
    N = me.ReferenceFrame("N")
    A = _turn(N, "A", th, u1)
    R = _turn(N, "R", beta, u2)
    O = me.Point("O")
    O.set_vel(N, 0)
    pin = O.locatenew("pin", P["r"] * A.x)
    pin.v2pt_theory(O, N, A)
    end = pin.locatenew("end", P["L"] * R.x)
    end.v2pt_theory(pin, N, R)
    G1 = O.locatenew("G1", P["r"] / 2 * A.x)
    G1.v2pt_theory(O, N, A)
    G2 = pin.locatenew("G2", P["L"] / 2 * R.x)
    G2.v2pt_theory(pin, N, R)
    S = O.locatenew("S", x * N.x + P["e"] * N.y)
    S.set_vel(N, u3 * N.x)
    configuration, velocity = _gap_rows(end, S, N)
    g = P["g"]
    bodies = [_bar_x("crank", A, G1, P["m1"], P["r"]), _bar_x("rod", R, G2, P["m2"], P["L"]),
              me.Particle("slider", S, P["m3"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (S, -P["m3"] * g * N.y - P["c"] * u3 * N.x),
             (A, P["T"] * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=[th], q_dependent=[beta, x], u_ind=[u1], u_dependent=[u2, u3], kd_eqs=kd,
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1], [u2, u3], P, velocity), _named(q), configuration=configuration,
                     q_dep=[beta, x], guess={"beta": 0.0, "x": 1.0})


def five_bar(absolute: bool = False) -> Reference:
    q1, q2, q3, q4 = q = list(me.dynamicsymbols("q1 q2 q3 q4"))
    u1, u2, u3, u4 = u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("d l1 l2 l3 l4 m1 m2 m3 m4 g T1 T4")
    N = me.ReferenceFrame("N")
    A1 = _turn(N, "A1", q1, u1)
    A2 = _turn(N, "A2", q2, u2)
    A4 = _turn(N, "A4", q4, u4)
    A3 = _turn(N, "A3", q3, u3) if absolute else _turn(A4, "A3", q3, u3)
    O = me.Point("O")
    O.set_vel(N, 0)
    E = O.locatenew("E", P["d"] * N.x)
    E.set_vel(N, 0)
    B = O.locatenew("B", P["l1"] * A1.x)
    B.v2pt_theory(O, N, A1)
    D = E.locatenew("D", P["l4"] * A4.x)
    D.v2pt_theory(E, N, A4)
    Cl = B.locatenew("Cl", P["l2"] * A2.x)
    Cl.v2pt_theory(B, N, A2)
    Cr = D.locatenew("Cr", P["l3"] * A3.x)
    Cr.v2pt_theory(D, N, A3)
    G1 = O.locatenew("G1", P["l1"] / 2 * A1.x)
    G1.v2pt_theory(O, N, A1)
    G2 = B.locatenew("G2", P["l2"] / 2 * A2.x)
    G2.v2pt_theory(B, N, A2)
    G3 = D.locatenew("G3", P["l3"] / 2 * A3.x)
    G3.v2pt_theory(D, N, A3)
    G4 = E.locatenew("G4", P["l4"] / 2 * A4.x)
    G4.v2pt_theory(E, N, A4)
    configuration, velocity = _gap_rows(Cl, Cr, N)
    g = P["g"]
    bodies = [_bar_x("crank1", A1, G1, P["m1"], P["l1"]), _bar_x("coupler2", A2, G2, P["m2"], P["l2"]),
              _bar_x("coupler3", A3, G3, P["m3"], P["l3"]), _bar_x("crank4", A4, G4, P["m4"], P["l4"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (G3, -P["m3"] * g * N.y),
             (G4, -P["m4"] * g * N.y), (A1, P["T1"] * N.z), (A4, P["T4"] * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=[q1, q4], q_dependent=[q2, q3], u_ind=[u1, u4], u_dependent=[u2, u3],
                          kd_eqs=kd, configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1, u4], [u2, u3], P, velocity), _named(q), configuration=configuration,
                     q_dep=[q2, q3], guess={"q2": 1.0, "q3": 2.0})


def four_bar_motor() -> Reference:
    th1, th2, th3 = q = list(me.dynamicsymbols("th1 th2 th3"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("d1 d2 l1 l2 l3 a b m1 m2 m3 J2 c g T")
    N = me.ReferenceFrame("N")
    A1, A2, A3 = (_turn(N, f"A{i + 1}", qi, ui) for i, (qi, ui) in enumerate(zip(q, u)))
    O = me.Point("O")
    O.set_vel(N, 0)
    D = O.locatenew("D", P["d1"] * N.x + P["d2"] * N.y)
    D.set_vel(N, 0)
    B = O.locatenew("B", P["l1"] * A1.x)
    B.v2pt_theory(O, N, A1)
    C = D.locatenew("C", P["l3"] * A3.x)
    C.v2pt_theory(D, N, A3)
    Bc = C.locatenew("Bc", P["l2"] * A2.x)
    Bc.v2pt_theory(C, N, A2)
    G1 = O.locatenew("G1", P["l1"] / 2 * A1.x)
    G1.v2pt_theory(O, N, A1)
    G2 = C.locatenew("G2", P["a"] * A2.x + P["b"] * A2.y)
    G2.v2pt_theory(C, N, A2)
    G3 = D.locatenew("G3", P["l3"] / 2 * A3.x)
    G3.v2pt_theory(D, N, A3)
    configuration, velocity = _gap_rows(B, Bc, N)
    g, J2 = P["g"], P["J2"]
    bodies = [_bar_x("crank", A1, G1, P["m1"], P["l1"]),
              me.RigidBody("coupler", G2, A2, P["m2"], (me.inertia(A2, J2 / 2, J2 / 2, J2), G2)),
              _bar_x("rocker", A3, G3, P["m3"], P["l3"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (G3, -P["m3"] * g * N.y),
             (A1, P["T"] * N.z), (A3, -P["c"] * u3 * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=[th1], q_dependent=[th2, th3], u_ind=[u1], u_dependent=[u2, u3], kd_eqs=kd,
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1], [u2, u3], P, velocity), _named(q), configuration=configuration,
                     q_dep=[th2, th3], guess={"th2": -2.2, "th3": 1.7})


def watt_six_bar() -> Reference:
    q = list(me.dynamicsymbols("th1 th2 th3 th4 th5"))
    u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("d l1 l2 l3 e1 e2 c3x c3y h1 h2 l4 l5 p1 p2 m1 m2 m3 J3 m4 m5 mp g T")
    N = me.ReferenceFrame("N")
    A1, A2, A3, A4, A5 = (_turn(N, f"A{i + 1}", qi, ui) for i, (qi, ui) in enumerate(zip(q, u)))
    O = me.Point("O")
    O.set_vel(N, 0)
    D = O.locatenew("D", P["d"] * N.x)
    D.set_vel(N, 0)
    H = O.locatenew("H", P["h1"] * N.x + P["h2"] * N.y)
    H.set_vel(N, 0)

    def on(name, base, frame, vec):
        pt = base.locatenew(name, vec)
        pt.v2pt_theory(base, N, frame)
        return pt

    B = on("B", O, A1, P["l1"] * A1.x)
    C = on("C", B, A2, P["l2"] * A2.x)
    Cr = on("Cr", D, A3, P["l3"] * A3.x)
    E = on("E", D, A3, P["e1"] * A3.x + P["e2"] * A3.y)
    F = on("F", E, A4, P["l4"] * A4.x)
    F5 = on("F5", H, A5, P["l5"] * A5.x)
    G1 = on("G1", O, A1, P["l1"] / 2 * A1.x)
    G2 = on("G2", B, A2, P["l2"] / 2 * A2.x)
    G3 = on("G3", D, A3, P["c3x"] * A3.x + P["c3y"] * A3.y)
    G4 = on("G4", E, A4, P["l4"] / 2 * A4.x)
    G5 = on("G5", H, A5, P["l5"] / 2 * A5.x)
    tool = on("tool", E, A4, P["p1"] * A4.x + P["p2"] * A4.y)
    c1, v1 = _gap_rows(C, Cr, N)
    c2, v2 = _gap_rows(F, F5, N)
    configuration, velocity = c1 + c2, v1 + v2
    g, J3 = P["g"], P["J3"]
    bodies = [_bar_x("crank", A1, G1, P["m1"], P["l1"]), _bar_x("coupler", A2, G2, P["m2"], P["l2"]),
              me.RigidBody("rocker", G3, A3, P["m3"], (me.inertia(A3, J3 / 2, J3 / 2, J3), G3)),
              _bar_x("link4", A4, G4, P["m4"], P["l4"]), _bar_x("link5", A5, G5, P["m5"], P["l5"]),
              me.Particle("tool", tool, P["mp"])]
    loads = [(G, -P[m] * g * N.y) for G, m in ((G1, "m1"), (G2, "m2"), (G3, "m3"), (G4, "m4"), (G5, "m5"),
                                              (tool, "mp"))]
    loads.append((A1, P["T"] * N.z))
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q[:1], q_dependent=q[1:], u_ind=u[:1], u_dependent=u[1:], kd_eqs=kd,
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u[:1], u[1:], P, velocity), _named(q), configuration=configuration,
                     q_dep=q[1:], guess={"th2": 0.9, "th3": 1.7, "th4": 0.0, "th5": -1.4})


def cart_inverted_double() -> Reference:
    x, a1, a2 = q = list(me.dynamicsymbols("x a1 a2"))
    ux, u1, u2 = u = list(me.dynamicsymbols("ux u1 u2"))
    P = _symbols("M m1 m2 l1 l2 k L0 w cw cd h b1 b2 g F")
    N = me.ReferenceFrame("N")
    L1 = _turn(N, "L1", a1, u1)
    L2 = _turn(L1, "L2", a2, u2)
    O = me.Point("O")
    O.set_vel(N, 0)
    wall = O.locatenew("wall", -P["w"] * N.x)
    wall.set_vel(N, 0)
    hinge = O.locatenew("hinge", x * N.x)
    hinge.set_vel(N, ux * N.x)
    anchor = hinge.locatenew("anchor", P["h"] * N.x)
    anchor.set_vel(N, ux * N.x)
    elbow = hinge.locatenew("elbow", P["l1"] * L1.y)
    elbow.v2pt_theory(hinge, N, L1)
    G1 = hinge.locatenew("G1", P["l1"] / 2 * L1.y)
    G1.v2pt_theory(hinge, N, L1)
    G2 = elbow.locatenew("G2", P["l2"] / 2 * L2.y)
    G2.v2pt_theory(elbow, N, L2)
    g = P["g"]
    # wall spring and damper, along the line wall -> hinge
    r = hinge.pos_from(wall)
    length = sp.sqrt(r.dot(r))
    e = r / length
    ldot = (hinge.vel(N) - wall.vel(N)).dot(e)
    f_wall = -P["k"] * (length - P["L0"]) * e - P["cw"] * ldot * e
    # diagonal damper anchor -> elbow
    r2 = elbow.pos_from(anchor)
    e2 = r2 / sp.sqrt(r2.dot(r2))
    ldot2 = (elbow.vel(N) - anchor.vel(N)).dot(e2)
    f_d = -P["cd"] * ldot2 * e2
    bodies = [me.Particle("cart", hinge, P["M"]), _bar_y("lower", L1, G1, P["m1"], P["l1"]),
              _bar_y("upper", L2, G2, P["m2"], P["l2"])]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (hinge, P["F"] * N.x + f_wall),
             (elbow, f_d), (anchor, -f_d),
             (L1, -P["b1"] * u1 * N.z + P["b2"] * u2 * N.z), (L2, -P["b2"] * u2 * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def two_carts() -> Reference:
    x1, x2, th1, th2 = q = list(me.dynamicsymbols("x1 x2 th1 th2"))
    v1, v2, w1, w2 = u = list(me.dynamicsymbols("v1 v2 w1 w2"))
    P = _symbols("M1 M2 m1 m2 l1 l2 k1 k2 k12 s c1 c2 g F")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    C1 = O.locatenew("C1", x1 * N.x)
    C1.set_vel(N, v1 * N.x)
    C2 = O.locatenew("C2", (P["s"] + x2) * N.x)
    C2.set_vel(N, v2 * N.x)
    B1 = _turn(N, "B1", th1, w1)
    B2 = _turn(N, "B2", th2, w2)
    G1 = C1.locatenew("G1", -P["l1"] / 2 * B1.y)
    G1.v2pt_theory(C1, N, B1)
    G2 = C2.locatenew("G2", -P["l2"] / 2 * B2.y)
    G2.v2pt_theory(C2, N, B2)
    g = P["g"]
    coupling = P["k12"] * (x2 - x1)
    bodies = [me.Particle("cart1", C1, P["M1"]), me.Particle("cart2", C2, P["M2"]),
              _bar_y("bar1", B1, G1, P["m1"], P["l1"]), _bar_y("bar2", B2, G2, P["m2"], P["l2"])]
    loads = [(C1, (P["F"] - P["k1"] * x1 + coupling - P["c1"] * v1) * N.x),
             (C2, (-P["k2"] * x2 - coupling - P["c2"] * v2) * N.x),
             (G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def scotch_yoke() -> Reference:
    th, x = q = list(me.dynamicsymbols("th x"))
    u1, u2 = u = list(me.dynamicsymbols("u1 u2"))
    P = _symbols("r rc m J My k c g T")
    N = me.ReferenceFrame("N")
    A = _turn(N, "A", th, u1)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", P["rc"] * A.x)
    G.v2pt_theory(O, N, A)
    pin = O.locatenew("pin", P["r"] * A.x)
    pin.v2pt_theory(O, N, A)
    Y = O.locatenew("Y", x * N.x)
    Y.set_vel(N, u2 * N.x)
    # the pin stays in the yoke's slot: the x of the pin is the yoke's x
    configuration = [pin.pos_from(Y).dot(N.x)]
    velocity = [(pin.vel(N) - Y.vel(N)).dot(N.x)]
    m = P["m"]
    crank = me.RigidBody("crank", G, A, m, (me.inertia(A, 0, 0, P["J"] - m * P["rc"]**2), G))
    bodies = [crank, me.Particle("yoke", Y, P["My"])]
    loads = [(G, -m * P["g"] * N.y), (Y, (-P["k"] * x - P["c"] * u2) * N.x), (A, P["T"] * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=[th], q_dependent=[x], u_ind=[u1], u_dependent=[u2], kd_eqs=kd,
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1], [u2], P, velocity), _named(q), configuration=configuration,
                     q_dep=[x], guess={"x": 0.1})


def crane() -> Reference:
    x, L, th = q = list(me.dynamicsymbols("x L th"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("M m Jl c g F S")
    N = me.ReferenceFrame("N")
    C = _turn(N, "C", th, u3)
    O = me.Point("O")
    O.set_vel(N, 0)
    trolley = O.locatenew("trolley", x * N.x)
    trolley.set_vel(N, u1 * N.x)
    hook = trolley.locatenew("hook", -L * C.y)
    rates = {x.diff(t): u1, L.diff(t): u2, th.diff(t): u3}
    hook.set_vel(N, hook.pos_from(O).dt(N).subs(rates))
    Jl = P["Jl"]
    bodies = [me.Particle("trolley", trolley, P["M"]),
              me.RigidBody("load", hook, C, P["m"], (me.inertia(C, Jl, Jl, Jl), hook))]
    loads = [(trolley, (P["F"] - P["c"] * u1) * N.x - P["S"] * C.y),
             (hook, -P["m"] * P["g"] * N.y + P["S"] * C.y)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


SYSTEMS = {
    "l3_slider_crank_f1": (HERE / "l3_slider_crank_f1.yaml", slider_crank_f1,
                           "offset slider-crank, absolute rod angle, slider x, holonomic loop, format 1"),
    "l3_five_bar": (HERE / "l3_five_bar.yaml", five_bar, "five-bar, two driven cranks, coincide, frames"),
    "l3_four_bar_motor": (HERE / "l3_four_bar_motor.yaml", four_bar_motor,
                          "four-bar, absolute angles, plate coupler hung from rocker, motor, pivot damping"),
    "l3_watt_six_bar": (HERE / "l3_watt_six_bar.yaml", watt_six_bar,
                        "Watt II six-bar, ternary rocker, tool mass, two coincides"),
    "l3_cart_inverted_double": (HERE / "l3_cart_inverted_double.yaml", cart_inverted_double,
                                "cart + inverted double pendulum, spring/damper lines, joint friction"),
    "l3_two_carts_f1": (HERE / "l3_two_carts_f1.yaml", two_carts, "two spring-coupled carts with pendulums, format 1"),
    "l3_scotch_yoke": (HERE / "l3_scotch_yoke.yaml", scotch_yoke, "scotch yoke, x = r cos(th) holonomic, spring"),
    "l3_crane": (HERE / "l3_crane.yaml", crane, "overhead crane, variable cable length, hook block"),
}


def rack_pinion() -> Reference:
    phi, x, th = q = list(me.dynamicsymbols("phi x th"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("R Jp Mr m l c g T")
    N = me.ReferenceFrame("N")
    A = _turn(N, "A", phi, u1)
    B = _turn(N, "B", th, u3)
    O = me.Point("O")
    O.set_vel(N, 0)
    rack = O.locatenew("rack", x * N.x + P["R"] * N.y)
    rack.set_vel(N, u2 * N.x)
    G = rack.locatenew("G", -P["l"] / 2 * B.y)
    G.v2pt_theory(rack, N, B)
    # no slip at the mesh: the pinion's material point under the rack moves with the rack
    tooth = O.locatenew("tooth", P["R"] * N.y)
    tooth.v2pt_theory(O, N, A)
    velocity = [(tooth.vel(N) - rack.vel(N)).dot(N.x)]
    m, l = P["m"], P["l"]
    bodies = [me.RigidBody("pinion", O, A, 1, (me.inertia(A, 0, 0, P["Jp"]), O)),
              me.Particle("rack", rack, P["Mr"]), _bar_y("bar", B, G, m, l)]
    loads = [(A, P["T"] * N.z), (rack, -P["c"] * u2 * N.x), (G, -m * P["g"] * N.y)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u3], u_dependent=[u2], kd_eqs=kd, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1, u3], [u2], P, velocity), _named(q))


def crane_winch() -> Reference:
    x, th, phi, L = q = list(me.dynamicsymbols("x th phi L"))
    u1, u2, u3, u4 = u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("M m rd Jd c g F Tm")
    N = me.ReferenceFrame("N")
    C = _turn(N, "C", th, u2)
    D = _turn(N, "D", phi, u3)
    O = me.Point("O")
    O.set_vel(N, 0)
    trolley = O.locatenew("trolley", x * N.x)
    trolley.set_vel(N, u1 * N.x)
    load = trolley.locatenew("load", -L * C.y)
    rates = {x.diff(t): u1, th.diff(t): u2, phi.diff(t): u3, L.diff(t): u4}
    load.set_vel(N, load.pos_from(O).dt(N).subs(rates))
    # the cable pays out from the drum: its length grows by rd per radian of the drum
    velocity = [u4 - P["rd"] * u3]
    bodies = [me.Particle("trolley", trolley, P["M"]),
              me.RigidBody("drum", trolley, D, 0, (me.inertia(D, 0, 0, P["Jd"]), trolley)),
              me.Particle("load", load, P["m"])]
    loads = [(trolley, (P["F"] - P["c"] * u1) * N.x), (D, P["Tm"] * N.z), (load, -P["m"] * P["g"] * N.y)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4], kd_eqs=kd,
                          velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4], P, velocity), _named(q))


SYSTEMS["l3_five_bar_abs"] = (HERE / "l3_five_bar_abs.yaml", lambda: five_bar(True),
                              "the five-bar with both couplers at absolute angles")
SYSTEMS["l3_slider_crank_frames"] = (HERE / "l3_slider_crank_frames.yaml", slider_crank_f1,
                                     "the offset slider-crank with frames + coincide")
SYSTEMS["l3_rack_pinion"] = (HERE / "l3_rack_pinion.yaml", rack_pinion,
                             "rack and pinion (Pfaffian dx = -R dphi) carrying a pendulum, format 1")
SYSTEMS["l3_crane_winch_f1"] = (HERE / "l3_crane_winch_f1.yaml", crane_winch,
                                "crane with winch drum, dL = rd dphi, format 1")
