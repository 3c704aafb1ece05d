"""KanesMethod models for the chains/linkages/carts variants (written after SymPy's docs)."""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _bar_x(name, frame, centre, m, l):
    """Uniform bar along the frame's x axis."""
    return me.RigidBody(name, centre, frame, m, (me.inertia(frame, 0, m * l**2 / 12, m * l**2 / 12), centre))


def _bar_y(name, frame, centre, m, l):
    """Uniform bar along the frame's y axis."""
    return me.RigidBody(name, centre, frame, m, (me.inertia(frame, m * l**2 / 12, 0, m * l**2 / 12), centre))


def chain4_relative() -> Reference:
    q = list(me.dynamicsymbols("q1:5"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("g m1 m2 m3 m4 l1 l2 l3 l4")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    parent, joint = N, O
    bodies, loads = [], []
    for i in range(4):
        frame = parent.orientnew(f"F{i + 1}", "Axis", [q[i], parent.z])
        frame.set_ang_vel(parent, u[i] * parent.z)
        m, l = P[f"m{i + 1}"], P[f"l{i + 1}"]
        G = joint.locatenew(f"G{i + 1}", l / 2 * frame.x)
        G.v2pt_theory(joint, N, frame)
        nxt = joint.locatenew(f"P{i + 1}", l * frame.x)
        nxt.v2pt_theory(joint, N, frame)
        bodies.append(_bar_x(f"link{i + 1}", frame, G, m, l))
        loads.append((G, -m * P["g"] * N.y))
        parent, joint = frame, nxt
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def slider_crank() -> Reference:
    th, phi, x = q = list(me.dynamicsymbols("th phi x"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("r L m1 m2 m3 T c g")
    N = me.ReferenceFrame("N")
    C = N.orientnew("C", "Axis", [th, N.z])
    C.set_ang_vel(N, u1 * N.z)
    R = C.orientnew("R", "Axis", [phi, C.z])
    R.set_ang_vel(C, u2 * C.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    pin = O.locatenew("pin", P["r"] * C.x)
    pin.v2pt_theory(O, N, C)
    end = pin.locatenew("end", P["L"] * R.x)
    end.v2pt_theory(pin, N, R)
    S = O.locatenew("S", x * N.x)
    S.set_vel(N, u3 * N.x)
    G1 = O.locatenew("G1", P["r"] / 2 * C.x)
    G1.v2pt_theory(O, N, C)
    G2 = pin.locatenew("G2", P["L"] / 2 * R.x)
    G2.v2pt_theory(pin, N, R)
    gap = end.pos_from(S)
    configuration = [gap.dot(N.x), gap.dot(N.y)]
    vgap = end.vel(N) - S.vel(N)
    velocity = [vgap.dot(N.x), vgap.dot(N.y)]
    bodies = [_bar_x("crank", C, G1, P["m1"], P["r"]), _bar_x("rod", R, G2, P["m2"], P["L"]),
              me.Particle("block", S, P["m3"])]
    g = P["g"]
    loads = [(G1, -P["m1"] * g * N.y), (G2, -P["m2"] * g * N.y), (S, -P["m3"] * g * N.y - P["c"] * u3 * N.x),
             (C, P["T"] * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=[th], q_dependent=[phi, x], u_ind=[u1], u_dependent=[u2, u3], kd_eqs=kd,
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1], [u2, u3], P, velocity), _named(q), configuration=configuration,
                     q_dep=[phi, x], guess={"phi": 0.0, "x": 1.0})


def cart_chain3_springs() -> Reference:
    x, q1, q2, q3 = q = list(me.dynamicsymbols("x q1 q2 q3"))
    ux, u1, u2, u3 = u = list(me.dynamicsymbols("ux u1 u2 u3"))
    P = _symbols("M m1 m2 m3 l1 l2 l3 k1 k2 k3 c1 c2 c3 kx d L0 F g")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    H = O.locatenew("H", x * N.x)
    H.set_vel(N, ux * N.x)
    bodies = [me.Particle("cart", H, P["M"])]
    length = x + P["d"]  # distance from the wall at -d
    loads = [(H, P["F"] * N.x - P["kx"] * (length - P["L0"]) * N.x)]
    parent, joint, frames = N, H, []
    for i, (qi, ui) in enumerate(zip((q1, q2, q3), (u1, u2, u3))):
        frame = parent.orientnew(f"B{i + 1}", "Axis", [qi, parent.z])
        frame.set_ang_vel(parent, ui * parent.z)
        m, l = P[f"m{i + 1}"], P[f"l{i + 1}"]
        G = joint.locatenew(f"G{i + 1}", -l / 2 * frame.y)
        G.v2pt_theory(joint, N, frame)
        nxt = joint.locatenew(f"J{i + 1}", -l * frame.y)
        nxt.v2pt_theory(joint, N, frame)
        bodies.append(_bar_y(f"bar{i + 1}", frame, G, m, l))
        loads.append((G, -m * P["g"] * N.y))
        torque = -P[f"k{i + 1}"] * qi - P[f"c{i + 1}"] * ui
        loads.append((frame, torque * N.z))
        if parent is not N:
            loads.append((parent, -torque * N.z))
        frames.append(frame)
        parent, joint = frame, nxt
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def spatial_double_zxy() -> Reference:
    q = list(me.dynamicsymbols("a1 b1 c1 a2 b2 c2"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("g m1 m2 L1 L2 Ia1 Ib1 Ic1 Ia2 Ib2 Ic2")
    N = me.ReferenceFrame("N")
    U = me.ReferenceFrame("U")
    U.orient_body_fixed(N, q[:3], "ZXY")
    W = me.ReferenceFrame("W")
    W.orient_body_fixed(U, q[3:], "ZXY")
    O = me.Point("O")
    O.set_vel(N, 0)
    G1 = O.locatenew("G1", -P["L1"] / 2 * U.z)
    G1.v2pt_theory(O, N, U)
    E = O.locatenew("E", -P["L1"] * U.z)
    E.v2pt_theory(O, N, U)
    G2 = E.locatenew("G2", -P["L2"] / 2 * W.z)
    G2.v2pt_theory(E, N, W)
    bodies = [me.RigidBody("upper", G1, U, P["m1"], (me.inertia(U, P["Ia1"], P["Ib1"], P["Ic1"]), G1)),
              me.RigidBody("lower", G2, W, P["m2"], (me.inertia(W, P["Ia2"], P["Ib2"], P["Ic2"]), G2))]
    loads = [(G1, -P["m1"] * P["g"] * N.z), (G2, -P["m2"] * P["g"] * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


SYSTEMS = {
    "chain4_relative": (HERE / "chain4_relative.yaml", chain4_relative, "4-link planar chain, relative angles, frames"),
    "chain4_format1": (HERE / "chain4_format1.yaml", chain4_relative, "the same chain written out (format 1)"),
    "slider_crank": (HERE / "slider_crank.yaml", slider_crank, "slider-crank, relative rod angle, coincide"),
    "cart_chain3_springs": (HERE / "cart_chain3_springs.yaml", cart_chain3_springs,
                            "cart + 3 bars, relative angles, joint springs/dampers, wall spring"),
    "spatial_double_zxy": (HERE / "spatial_double_zxy.yaml", spatial_double_zxy,
                           "spatial double pendulum, relative body-fixed ZXY"),
}

SYSTEMS["cart_chain3_potential"] = (HERE / "cart_chain3_potential.yaml", cart_chain3_springs,
                                    "the same, the wall spring as a potential")


def four_bar_relative() -> Reference:
    th1, th2, th3 = q = list(me.dynamicsymbols("th1 th2 th3"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("l0 l1 l2 l3 m1 m2 m3 g")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [th1, N.z])
    A.set_ang_vel(N, u1 * N.z)
    B = A.orientnew("B", "Axis", [th2, A.z])
    B.set_ang_vel(A, u2 * A.z)
    C = B.orientnew("C", "Axis", [th3, B.z])
    C.set_ang_vel(B, u3 * B.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    Pb = O.locatenew("Pb", P["l1"] * A.x)
    Pb.v2pt_theory(O, N, A)
    Pc = Pb.locatenew("Pc", P["l2"] * B.x)
    Pc.v2pt_theory(Pb, N, B)
    Pd = Pc.locatenew("Pd", P["l3"] * C.x)
    Pd.v2pt_theory(Pc, N, C)
    G1 = O.locatenew("G1", P["l1"] / 2 * A.x)
    G1.v2pt_theory(O, N, A)
    G2 = Pb.locatenew("G2", P["l2"] / 2 * B.x)
    G2.v2pt_theory(Pb, N, B)
    G3 = Pc.locatenew("G3", P["l3"] / 2 * C.x)
    G3.v2pt_theory(Pc, N, C)
    gap = Pd.pos_from(O) - P["l0"] * N.x
    configuration = [gap.dot(N.x), gap.dot(N.y)]
    vel = Pd.vel(N)
    velocity = [vel.dot(N.x), vel.dot(N.y)]
    bodies = [_bar_x("crank", A, G1, P["m1"], P["l1"]), _bar_x("coupler", B, G2, P["m2"], P["l2"]),
              _bar_x("rocker", C, G3, P["m3"], P["l3"])]
    loads = [(G, -P[m] * P["g"] * N.y) for G, m in ((G1, "m1"), (G2, "m2"), (G3, "m3"))]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=[th1], q_dependent=[th2, th3], u_ind=[u1], u_dependent=[u2, u3], kd_eqs=kd,
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    # upper assembly branch: coupler about 1 rad above x, rocker turned back about -2.3 rad from it
    return Reference(KaneModel(kane, q, [u1], [u2, u3], P, velocity), _named(q), configuration=configuration,
                     q_dep=[th2, th3], guess={"th2": 1.0, "th3": -2.3})


def universal_double() -> Reference:
    q = list(me.dynamicsymbols("al1 be1 al2 be2"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("g m1 m2 L1 L2 A1 C1 A2 C2")
    N = me.ReferenceFrame("N")
    U = N.orientnew("U", "Body", [q[0], q[1], 0], "XYZ")
    W = U.orientnew("W", "Body", [q[2], q[3], 0], "XYZ")
    O = me.Point("O")
    O.set_vel(N, 0)
    G1 = O.locatenew("G1", -P["L1"] / 2 * U.z)
    G1.v2pt_theory(O, N, U)
    K = O.locatenew("K", -P["L1"] * U.z)
    K.v2pt_theory(O, N, U)
    G2 = K.locatenew("G2", -P["L2"] / 2 * W.z)
    G2.v2pt_theory(K, N, W)
    bodies = [me.RigidBody("upper", G1, U, P["m1"], (me.inertia(U, P["A1"], P["A1"], P["C1"]), G1)),
              me.RigidBody("lower", G2, W, P["m2"], (me.inertia(W, P["A2"], P["A2"], P["C2"]), G2))]
    loads = [(G1, -P["m1"] * P["g"] * N.z), (G2, -P["m2"] * P["g"] * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


SYSTEMS["four_bar_relative"] = (HERE / "four_bar_relative.yaml", four_bar_relative,
                                "four-bar, relative angles, frames + coincide")
SYSTEMS["four_bar_relative_f1"] = (HERE / "four_bar_relative_f1.yaml", four_bar_relative,
                                   "four-bar, relative angles, format 1")
SYSTEMS["universal_double"] = (HERE / "universal_double.yaml", universal_double,
                               "double pendulum, universal joints, relative angles, potential")

SYSTEMS["slider_crank_guide"] = (HERE / "slider_crank_guide.yaml", slider_crank,
                                 "slider-crank, slider at the rod end on a moves_along guide")
SYSTEMS["slider_crank_explicit"] = (HERE / "slider_crank_explicit.yaml", slider_crank,
                                    "slider-crank, loop eliminated by hand (sqrt), format 1")
