"""KanesMethod references for the planar variants in this folder, built from the physical definitions
(frames, points, v2pt_theory), never from the gacli files. Speeds u = q' throughout."""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _planar_body(name, frame, centre, m, Izz):
    """A body moving in the N xy plane; only the moment about z matters (x, y moments given so it is physical)."""
    return me.RigidBody(name, centre, frame, m, (me.inertia(frame, Izz, 0, Izz), centre))


def _turn(parent, name, angle, speed):
    frame = parent.orientnew(name, "Axis", [angle, parent.z])
    frame.set_ang_vel(parent, speed * parent.z)
    return frame


def _kane(N, q, u, bodies, loads):
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return kane


def cart_double_f1() -> Reference:
    x, q1, q2 = q = list(me.dynamicsymbols("x q1 q2"))
    ux, u1, u2 = u = list(me.dynamicsymbols("ux u1 u2"))
    P = _symbols("M m1 m2 l1 l2 g F")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    H = O.locatenew("H", x * N.x)
    H.set_vel(N, ux * N.x)
    B1 = _turn(N, "B1", q1, u1)      # the bar hangs along -B1.y
    B2 = _turn(B1, "B2", q2, u2)
    G1 = H.locatenew("G1", -P["l1"] / 2 * B1.y)
    G1.v2pt_theory(H, N, B1)
    K = H.locatenew("K", -P["l1"] * B1.y)
    K.v2pt_theory(H, N, B1)
    G2 = K.locatenew("G2", -P["l2"] / 2 * B2.y)
    G2.v2pt_theory(K, N, B2)
    m1, m2, l1, l2, g = (P[n] for n in ("m1", "m2", "l1", "l2", "g"))
    bodies = [me.Particle("cart", H, P["M"]),
              _planar_body("bar1", B1, G1, m1, m1 * l1**2 / 12),
              _planar_body("bar2", B2, G2, m2, m2 * l2**2 / 12)]
    loads = [(H, P["F"] * N.x - P["M"] * g * N.y), (G1, -m1 * g * N.y), (G2, -m2 * g * N.y)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def acrobot() -> Reference:
    q1, q2 = q = list(me.dynamicsymbols("q1 q2"))
    u1, u2 = u = list(me.dynamicsymbols("u1 u2"))
    P = _symbols("m1 m2 l1 lc1 lc2 I1 I2 g tau")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    A = _turn(N, "A", q1, u1)
    B = _turn(A, "B", q2, u2)
    E = O.locatenew("E", -P["l1"] * A.y)
    E.v2pt_theory(O, N, A)
    C1 = O.locatenew("C1", -P["lc1"] * A.y)
    C1.v2pt_theory(O, N, A)
    C2 = E.locatenew("C2", -P["lc2"] * B.y)
    C2.v2pt_theory(E, N, B)
    g = P["g"]
    bodies = [_planar_body("link1", A, C1, P["m1"], P["I1"]), _planar_body("link2", B, C2, P["m2"], P["I2"])]
    loads = [(C1, -P["m1"] * g * N.y), (C2, -P["m2"] * g * N.y), (B, P["tau"] * N.z), (A, -P["tau"] * N.z)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def _chain(q, u, P, lengths, masses, direction, inertias=None):
    """A planar chain from a fixed pin; link i along `direction(frame)` from its proximal joint."""
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    parent, joint = N, O
    frames, centres, joints = [], [], []
    for i, (qi, ui) in enumerate(zip(q, u)):
        frame = _turn(parent, f"F{i + 1}", qi, ui)
        l = lengths[i]
        G = joint.locatenew(f"G{i + 1}", l / 2 * direction(frame))
        G.v2pt_theory(joint, N, frame)
        nxt = joint.locatenew(f"J{i + 1}", l * direction(frame))
        nxt.v2pt_theory(joint, N, frame)
        frames.append(frame)
        centres.append(G)
        joints.append(nxt)
        parent, joint = frame, nxt
    return N, O, frames, centres, joints


def chain5_torques_f1() -> Reference:
    q = list(me.dynamicsymbols("q1:6"))
    u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("g m1 m2 m3 m4 m5 l1 l2 l3 l4 l5 T1 T2 T3 T4 T5")
    ls = [P[f"l{i}"] for i in range(1, 6)]
    ms = [P[f"m{i}"] for i in range(1, 6)]
    N, O, frames, centres, _ = _chain(q, u, P, ls, ms, lambda f: f.x)
    bodies = [_planar_body(f"link{i + 1}", frames[i], centres[i], ms[i], ms[i] * ls[i]**2 / 12) for i in range(5)]
    loads = [(centres[i], -ms[i] * P["g"] * N.y) for i in range(5)]
    for i in range(5):
        T = P[f"T{i + 1}"]
        loads.append((frames[i], T * N.z))
        if i > 0:
            loads.append((frames[i - 1], -T * N.z))
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def chain3_expanded() -> Reference:
    q = list(me.dynamicsymbols("q1:4"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("g m1 m2 m3 l1 l2 l3")
    ls = [P[f"l{i}"] for i in range(1, 4)]
    ms = [P[f"m{i}"] for i in range(1, 4)]
    N, O, frames, centres, _ = _chain(q, u, P, ls, ms, lambda f: f.x)
    bodies = [_planar_body(f"link{i + 1}", frames[i], centres[i], ms[i], ms[i] * ls[i]**2 / 12) for i in range(3)]
    loads = [(centres[i], -ms[i] * P["g"] * N.y) for i in range(3)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def chain3_offsets() -> Reference:
    q1, q2, q3 = q = list(me.dynamicsymbols("q1:4"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("g m1 m2 m3 l1 l2 a3 b3 J3")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    A = N.orientnew("A", "Axis", [q1 + sp.pi / 6, N.z])   # link 1 at 30 degrees when q1 = 0
    A.set_ang_vel(N, u1 * N.z)
    B = _turn(A, "B", q2, u2)
    C = _turn(B, "C", q3, u3)
    G1 = O.locatenew("G1", P["l1"] / 2 * A.x)
    G1.v2pt_theory(O, N, A)
    J1 = O.locatenew("J1", P["l1"] * A.x)
    J1.v2pt_theory(O, N, A)
    G2 = J1.locatenew("G2", P["l2"] / 2 * B.x)
    G2.v2pt_theory(J1, N, B)
    J2 = J1.locatenew("J2", P["l2"] * B.x)
    J2.v2pt_theory(J1, N, B)
    G3 = J2.locatenew("G3", P["a3"] * C.x + P["b3"] * C.y)   # off the link's axis
    G3.v2pt_theory(J2, N, C)
    m1, m2, m3, l1, l2, g = (P[n] for n in ("m1", "m2", "m3", "l1", "l2", "g"))
    bodies = [_planar_body("link1", A, G1, m1, m1 * l1**2 / 12), _planar_body("link2", B, G2, m2, m2 * l2**2 / 12),
              _planar_body("link3", C, G3, m3, P["J3"])]
    loads = [(G1, -m1 * g * N.y), (G2, -m2 * g * N.y), (G3, -m3 * g * N.y)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def cart_incline_f1() -> Reference:
    s, th = q = list(me.dynamicsymbols("s th"))
    us, uth = u = list(me.dynamicsymbols("us uth"))
    P = _symbols("M m l alpha c g F")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    S = N.orientnew("S", "Axis", [-P["alpha"], N.z])   # S.x runs down the slope
    Cart = O.locatenew("Cart", s * S.x)
    Cart.set_vel(N, us * S.x)
    B = _turn(N, "B", th, uth)
    G = Cart.locatenew("G", -P["l"] / 2 * B.y)
    G.v2pt_theory(Cart, N, B)
    g, m = P["g"], P["m"]
    bodies = [me.Particle("cart", Cart, P["M"]), _planar_body("bar", B, G, m, m * P["l"]**2 / 12)]
    loads = [(Cart, -P["M"] * g * N.y + (P["F"] - P["c"] * us) * S.x), (G, -m * g * N.y)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def fourbar_tilted_f1() -> Reference:
    th1, th2, th3 = q = list(me.dynamicsymbols("th1 th2 th3"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("d1 d2 l1 l2 l3 m1 m2 m3 c g T")
    N = me.ReferenceFrame("N")
    A = _turn(N, "A", th1, u1)
    B = _turn(A, "B", th2, u2)
    C = _turn(B, "C", th3, u3)
    O = me.Point("O")
    O.set_vel(N, 0)
    D = O.locatenew("D", P["d1"] * N.x + P["d2"] * N.y)   # rocker's ground pivot
    D.set_vel(N, 0)
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
    gap = Pd.pos_from(D)
    configuration = [gap.dot(N.x), gap.dot(N.y)]
    vel = Pd.vel(N) - D.vel(N)
    velocity = [vel.dot(N.x), vel.dot(N.y)]
    m1, m2, m3, l1, l2, l3, g, c, T = (P[n] for n in ("m1", "m2", "m3", "l1", "l2", "l3", "g", "c", "T"))
    bodies = [_planar_body("crank", A, G1, m1, m1 * l1**2 / 12), _planar_body("coupler", B, G2, m2, m2 * l2**2 / 12),
              _planar_body("rocker", C, G3, m3, m3 * l3**2 / 12)]
    loads = [(G1, -m1 * g * N.y), (G2, -m2 * g * N.y), (G3, -m3 * g * N.y),
             (A, T * N.z),                                 # crank motor on the ground
             (B, -c * u2 * N.z), (A, c * u2 * N.z)]       # pin friction between crank and coupler
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=[th1], q_dependent=[th2, th3], u_ind=[u1], u_dependent=[u2, u3], kd_eqs=kd,
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [u1], [u2, u3], P, velocity), _named(q), configuration=configuration,
                     q_dep=[th2, th3], guess={"th2": 1.2, "th3": -2.4})


def chain3_particles() -> Reference:
    q = list(me.dynamicsymbols("q1:4"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("g m1 m2 m3 mj1 mj2 mt l1 l2 l3 k L0")
    ls = [P[f"l{i}"] for i in range(1, 4)]
    ms = [P[f"m{i}"] for i in range(1, 4)]
    N, O, frames, centres, joints = _chain(q, u, P, ls, ms, lambda f: -f.y)
    g = P["g"]
    bodies = [_planar_body(f"bar{i + 1}", frames[i], centres[i], ms[i], ms[i] * ls[i]**2 / 12) for i in range(3)]
    bodies += [me.Particle("joint1", joints[0], P["mj1"]), me.Particle("joint2", joints[1], P["mj2"]),
               me.Particle("tip", joints[2], P["mt"])]
    loads = [(centres[i], -ms[i] * g * N.y) for i in range(3)]
    loads += [(joints[0], -P["mj1"] * g * N.y), (joints[1], -P["mj2"] * g * N.y), (joints[2], -P["mt"] * g * N.y)]
    # spring between joint 1 and the tip: tension k (L - L0) along the line
    r = joints[2].pos_from(joints[0])
    L = sp.sqrt(r.dot(N.x)**2 + r.dot(N.y)**2)
    pull = P["k"] * (L - P["L0"]) / L * r        # on joint 1 towards the tip
    loads += [(joints[0], pull), (joints[2], -pull)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


SYSTEMS = {
    "cart_double_f1": (HERE / "cart_double_f1.yaml", cart_double_f1,
                       "cart + double pendulum of bars, relative angles, input force, format 1"),
    "acrobot_f1": (HERE / "acrobot_f1.yaml", acrobot, "acrobot, elbow torque as work, format 1"),
    "acrobot_frames": (HERE / "acrobot_frames.yaml", acrobot, "acrobot, elbow motor with reaction, frames"),
    "chain5_torques_f1": (HERE / "chain5_torques_f1.yaml", chain5_torques_f1,
                          "5-link chain, relative angles, joint torques as work, format 1"),
    "chain3_expanded": (HERE / "chain3_expanded.yaml", chain3_expanded,
                        "3-link chain, angle-sum products expanded, format 1"),
    "chain3_offsets": (HERE / "chain3_offsets.yaml", chain3_offsets,
                       "3-link chain, sums reordered, +pi/6 offset, off-axis centre, format 1"),
    "cart_incline_f1": (HERE / "cart_incline_f1.yaml", cart_incline_f1,
                        "cart on an incline with a pendulum bar, damping + force, format 1"),
    "fourbar_tilted_f1": (HERE / "fourbar_tilted_f1.yaml", fourbar_tilted_f1,
                          "four-bar, tilted ground, relative angles, 2 holonomic rows, motor + pin friction"),
    "chain3_particles": (HERE / "chain3_particles.yaml", chain3_particles,
                         "3 bars with joint/tip particles, spring across, format 1"),
}


def chain4_expanded() -> Reference:
    q = list(me.dynamicsymbols("q1:5"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("g m1 l1 m2 l2 m3 l3 m4 l4")
    ls = [P[f"l{i}"] for i in range(1, 5)]
    ms = [P[f"m{i}"] for i in range(1, 5)]
    N, O, frames, centres, _ = _chain(q, u, P, ls, ms, lambda f: f.x)
    bodies = [_planar_body(f"link{i + 1}", frames[i], centres[i], ms[i], ms[i] * ls[i]**2 / 12) for i in range(4)]
    loads = [(centres[i], -ms[i] * P["g"] * N.y) for i in range(4)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def double_moving_support() -> Reference:
    q1, q2 = q = list(me.dynamicsymbols("q1 q2"))
    u1, u2 = u = list(me.dynamicsymbols("u1 u2"))
    P = _symbols("m1 m2 l1 l2 A w c g")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    x0 = P["A"] * sp.sin(P["w"] * t)
    S = O.locatenew("S", x0 * N.x)
    S.set_vel(N, x0.diff(t) * N.x)
    B1 = _turn(N, "B1", q1, u1)
    B2 = _turn(B1, "B2", q2, u2)
    G1 = S.locatenew("G1", -P["l1"] / 2 * B1.y)
    G1.v2pt_theory(S, N, B1)
    K = S.locatenew("K", -P["l1"] * B1.y)
    K.v2pt_theory(S, N, B1)
    G2 = K.locatenew("G2", -P["l2"] / 2 * B2.y)
    G2.v2pt_theory(K, N, B2)
    m1, m2, l1, l2, g, c = (P[n] for n in ("m1", "m2", "l1", "l2", "g", "c"))
    bodies = [_planar_body("bar1", B1, G1, m1, m1 * l1**2 / 12), _planar_body("bar2", B2, G2, m2, m2 * l2**2 / 12)]
    loads = [(G1, -m1 * g * N.y), (G2, -m2 * g * N.y), (B2, -c * u2 * N.z), (B1, c * u2 * N.z)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def chain3_minus() -> Reference:
    q1, q2, q3 = q = list(me.dynamicsymbols("q1:4"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("g m1 m2 m3 l1 l2 l3")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    A = _turn(N, "A", q1, u1)
    B = A.orientnew("B", "Axis", [-q2, A.z])     # the middle joint counted the other way
    B.set_ang_vel(A, -u2 * A.z)
    C = _turn(B, "C", q3, u3)
    pts, joint = [], O
    for i, F in enumerate((A, B, C)):
        l = P[f"l{i + 1}"]
        G = joint.locatenew(f"G{i + 1}", -l / 2 * F.y)
        G.v2pt_theory(joint, N, F)
        nxt = joint.locatenew(f"J{i + 1}", -l * F.y)
        nxt.v2pt_theory(joint, N, F)
        pts.append(G)
        joint = nxt
    ms = [P[f"m{i}"] for i in range(1, 4)]
    ls = [P[f"l{i}"] for i in range(1, 4)]
    bodies = [_planar_body(f"bar{i + 1}", F, pts[i], ms[i], ms[i] * ls[i]**2 / 12) for i, F in enumerate((A, B, C))]
    loads = [(pts[i], -ms[i] * P["g"] * N.y) for i in range(3)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


def pendulum_flywheel() -> Reference:
    q1, q2 = q = list(me.dynamicsymbols("q1 q2"))
    u1, u2 = u = list(me.dynamicsymbols("u1 u2"))
    P = _symbols("m1 l mw R g T")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    A = _turn(N, "A", q1, u1)
    W = _turn(A, "W", q2, u2)
    G = O.locatenew("G", -P["l"] / 2 * A.y)
    G.v2pt_theory(O, N, A)
    H = O.locatenew("H", -P["l"] * A.y)
    H.v2pt_theory(O, N, A)
    bodies = [_planar_body("bar", A, G, P["m1"], P["m1"] * P["l"]**2 / 12),
              me.RigidBody("wheel", H, W, P["mw"], (me.inertia(W, P["mw"] * P["R"]**2 / 4, P["mw"] * P["R"]**2 / 4,
                                                              P["mw"] * P["R"]**2 / 2), H))]
    g = P["g"]
    loads = [(G, -P["m1"] * g * N.y), (H, -P["mw"] * g * N.y), (W, P["T"] * N.z), (A, -P["T"] * N.z)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


SYSTEMS.update({
    "chain4_expanded": (HERE / "chain4_expanded.yaml", chain4_expanded,
                        "4-link chain, every angle sum multiplied out (positions and potential), format 1"),
    "double_moving_support": (HERE / "double_moving_support.yaml", double_moving_support,
                              "double pendulum on a shaken support x0(t), joint friction, format 1"),
    "chain3_minus": (HERE / "chain3_minus.yaml", chain3_minus,
                     "3-bar chain, q1 - q2 + q3 angles, cos(a - pi/2) components, format 1"),
    "pendulum_flywheel": (HERE / "pendulum_flywheel.yaml", pendulum_flywheel,
                          "bar + flywheel at tip, motor as scalar torque loads, format 1"),
})

SYSTEMS["chain4_expanded_forces"] = (HERE / "chain4_expanded_forces.yaml", chain4_expanded,
                                     "the same 4-link chain multiplied out, gravity as forces")

SYSTEMS["chain3_sums"] = (HERE / "chain3_sums.yaml", chain3_expanded,
                          "chain3_expanded with the angle sums left as sums (control)")


def chain5_plain() -> Reference:
    q = list(me.dynamicsymbols("q1:6"))
    u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("g m1 l1 m2 l2 m3 l3 m4 l4 m5 l5")
    ls = [P[f"l{i}"] for i in range(1, 6)]
    ms = [P[f"m{i}"] for i in range(1, 6)]
    N, O, frames, centres, _ = _chain(q, u, P, ls, ms, lambda f: f.x)
    bodies = [_planar_body(f"link{i + 1}", frames[i], centres[i], ms[i], ms[i] * ls[i]**2 / 12) for i in range(5)]
    loads = [(centres[i], -ms[i] * P["g"] * N.y) for i in range(5)]
    return Reference(KaneModel(_kane(N, q, u, bodies, loads), q, u, [], P), _named(q))


SYSTEMS["chain5_expanded"] = (HERE / "chain5_expanded.yaml", chain5_plain,
                              "5-link chain, every angle sum multiplied out (sympy expand_trig), gravity as forces")
