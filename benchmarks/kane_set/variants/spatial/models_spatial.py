"""KanesMethod references for the spatial variants in /tmp/variants2/spatial.

Each builder is written from the physical definition (frames, points,
v2pt_theory, rigid bodies, loads), never from the gacli file; only the names
of coordinates, parameters, inputs and the choice of independent speeds are
shared with it.
"""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _full_inertia(frame, P, prefix):
    return me.inertia(frame, P[f"{prefix}xx"], P[f"{prefix}yy"], P[f"{prefix}zz"],
                      P[f"{prefix}xy"], P[f"{prefix}yz"], P[f"{prefix}xz"])


# -- 1. RRR arm ------------------------------------------------------------------------

def rrr_arm(damper: bool = False) -> Reference:
    q1, q2, q3 = q = list(me.dynamicsymbols("q1 q2 q3"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    names = ("L2 cd ax ay " if damper else "") + "g h L1 m0 m1 m2 b0 c1 a2 c2 T1 T2 T3 " + " ".join(
        f"I{i}{c}" for i in range(3) for c in ("xx", "yy", "zz", "xy", "xz", "yz"))
    P = _symbols(names)
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [q1, N.z])      # turret
    A.set_ang_vel(N, u1 * N.z)
    B = A.orientnew("B", "Axis", [q2, A.y])      # upper arm
    B.set_ang_vel(A, u2 * A.y)
    C = B.orientnew("C", "Axis", [q3, B.y])      # forearm
    C.set_ang_vel(B, u3 * B.y)
    O = me.Point("O")
    O.set_vel(N, 0)
    S = O.locatenew("S", P["h"] * N.z)
    S.set_vel(N, 0)
    G0 = O.locatenew("G0", P["b0"] * A.x + P["h"] / 2 * A.z)
    G0.v2pt_theory(O, N, A)
    G1 = S.locatenew("G1", P["L1"] / 2 * B.x + P["c1"] * B.z)
    G1.v2pt_theory(S, N, B)
    E = S.locatenew("E", P["L1"] * B.x)
    E.v2pt_theory(S, N, B)
    G2 = E.locatenew("G2", P["a2"] * C.x + P["c2"] * C.y)
    G2.v2pt_theory(E, N, C)
    bodies = [me.RigidBody("turret", G0, A, P["m0"], (_full_inertia(A, P, "I0"), G0)),
              me.RigidBody("upper", G1, B, P["m1"], (_full_inertia(B, P, "I1"), G1)),
              me.RigidBody("fore", G2, C, P["m2"], (_full_inertia(C, P, "I2"), G2))]
    g = P["g"]
    loads = [(G0, -P["m0"] * g * N.z), (G1, -P["m1"] * g * N.z), (G2, -P["m2"] * g * N.z),
             (A, P["T1"] * N.z),
             (B, P["T2"] * A.y), (A, -P["T2"] * A.y),
             (C, P["T3"] * B.y), (B, -P["T3"] * B.y)]
    if damper:
        W = E.locatenew("W", P["L2"] * C.x)
        W.v2pt_theory(E, N, C)
        r = W.pos_from(O) - P["ax"] * N.x - P["ay"] * N.y
        length = sp.sqrt(r.dot(r))
        rate = W.vel(N).dot(r) / length
        loads.append((W, -P["cd"] * rate * r / length))
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))




# -- 2. rigid spherical pendulum, ZYX ---------------------------------------------------

def spherical_zyx() -> Reference:
    yaw, pitch, roll = q = list(me.dynamicsymbols("yaw pitch roll"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("m g l d Ixx Iyy Izz Ixy Ixz Iyz")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_body_fixed(N, (yaw, pitch, roll), "ZYX")
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", P["d"] * B.x - P["l"] * B.z)
    G.v2pt_theory(O, N, B)
    body = me.RigidBody("bob", G, B, P["m"], (_full_inertia(B, P, "I"), G))
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 3. gyroscope in two gimbals ----------------------------------------------------------

def gyro_gimbal() -> Reference:
    a, b, s = q = list(me.dynamicsymbols("a b s"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("g e mo mi mr Ao Bo Co Ai Bi Ci J K Ta Ts")
    N = me.ReferenceFrame("N")
    Fo = N.orientnew("Fo", "Axis", [a, N.z])
    Fo.set_ang_vel(N, u1 * N.z)
    Fi = Fo.orientnew("Fi", "Axis", [b, Fo.x])
    Fi.set_ang_vel(Fo, u2 * Fo.x)
    Fr = Fi.orientnew("Fr", "Axis", [s, Fi.y])
    # u3 is the rotor's angular velocity along its axle (absolute): s' = u3 - (Fi's w).Fi.y
    spin_rel = u3 - Fi.ang_vel_in(N).dot(Fi.y)
    Fr.set_ang_vel(Fi, spin_rel * Fi.y)
    O = me.Point("O")
    O.set_vel(N, 0)
    Gr = O.locatenew("Gr", P["e"] * Fi.z)
    Gr.v2pt_theory(O, N, Fi)
    bodies = [me.RigidBody("outer", O, Fo, P["mo"], (me.inertia(Fo, P["Ao"], P["Bo"], P["Co"]), O)),
              me.RigidBody("inner", O, Fi, P["mi"], (me.inertia(Fi, P["Ai"], P["Bi"], P["Ci"]), O)),
              me.RigidBody("rotor", Gr, Fr, P["mr"], (me.inertia(Fr, P["K"], P["J"], P["K"]), Gr))]
    loads = [(Gr, -P["mr"] * P["g"] * N.z), (Fr, P["Ts"] * Fi.y), (Fi, -P["Ts"] * Fi.y), (Fo, P["Ta"] * N.z)]
    kd = [a.diff(t) - u1, b.diff(t) - u2, s.diff(t) - spin_rel]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 4. SCARA ------------------------------------------------------------------------------

def scara() -> Reference:
    q1, q2, d3 = q = list(me.dynamicsymbols("q1 q2 d3"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("g H L1 L2 m1 m2 m3 r1 r2 s2 h3 I1 A2 B2 Iq Jq T1 T2 F3")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [q1, N.z])
    A.set_ang_vel(N, u1 * N.z)
    B = A.orientnew("B", "Axis", [q2, A.z])
    B.set_ang_vel(A, u2 * A.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    base = O.locatenew("base", P["H"] * N.z)
    base.set_vel(N, 0)
    elbow = base.locatenew("elbow", P["L1"] * A.x)
    elbow.v2pt_theory(base, N, A)
    wrist = elbow.locatenew("wrist", P["L2"] * B.x)
    wrist.v2pt_theory(elbow, N, B)
    G1 = base.locatenew("G1", P["r1"] * A.x)
    G1.v2pt_theory(base, N, A)
    G2 = elbow.locatenew("G2", P["r2"] * B.x + P["s2"] * B.y)
    G2.v2pt_theory(elbow, N, B)
    G3 = wrist.locatenew("G3", -(d3 + P["h3"]) * N.z)
    G3.set_vel(N, wrist.vel(N) - u3 * N.z)   # the quill slides in link 2, which turns about N.z
    bodies = [me.RigidBody("link1", G1, A, P["m1"], (me.inertia(A, P["I1"] / 10, P["I1"], P["I1"]), G1)),
              me.RigidBody("link2", G2, B, P["m2"], (me.inertia(B, P["A2"], P["B2"], P["B2"]), G2)),
              me.RigidBody("quill", G3, B, P["m3"], (me.inertia(B, P["Iq"], P["Iq"], P["Jq"]), G3))]
    g = P["g"]
    loads = [(G1, -P["m1"] * g * N.z), (G2, -P["m2"] * g * N.z), (G3, -(P["m3"] * g + P["F3"]) * N.z),
             (wrist, P["F3"] * N.z), (A, P["T1"] * N.z), (B, P["T2"] * N.z), (A, -P["T2"] * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 5. free body, XYZ angles, body rates ------------------------------------------------

def free_xyz_rates() -> Reference:
    x, y, z, q1, q2, q3 = q = list(me.dynamicsymbols("x y z q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g a Ixx Iyy Izz Ixy Ixz Iyz M1 M2 M3 F")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_body_fixed(N, (q1, q2, q3), "XYZ")
    natural = B.ang_vel_in(N)
    rows = [sp.trigsimp(natural.dot(v)) for v in (B.x, B.y, B.z)]
    B.set_ang_vel(N, u[3] * B.x + u[4] * B.y + u[5] * B.z)
    # solve the body-rate rows for q' by hand (no LU pivots left to KanesMethod)
    qd = [qi.diff(t) for qi in (q1, q2, q3)]
    sol = sp.solve([r - ui for r, ui in zip(rows, u[3:])], qd, dict=True)[0]
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [qdi - sp.trigsimp(sol[qdi]) for qdi in qd]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    T = G.locatenew("T", P["a"] * B.x)
    T.v2pt_theory(G, N, B)
    body = me.RigidBody("craft", G, B, P["m"], (_full_inertia(B, P, "I"), G))
    loads = [(G, -P["m"] * P["g"] * N.z), (T, P["F"] * B.z),
             (B, P["M1"] * B.x + P["M2"] * B.y + P["M3"] * B.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 6. two links with universal joints ---------------------------------------------------

def universal2() -> Reference:
    a1, b1, a2, b2 = q = list(me.dynamicsymbols("a1 b1 a2 b2"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("g m1 m2 L1 L2 A1 B1 C1 A2 B2 C2")
    N = me.ReferenceFrame("N")
    Ux = N.orientnew("Ux", "Axis", [a1, N.x])
    Ux.set_ang_vel(N, u[0] * N.x)
    U = Ux.orientnew("U", "Axis", [b1, Ux.y])
    U.set_ang_vel(Ux, u[1] * Ux.y)
    Wy = U.orientnew("Wy", "Axis", [a2, U.y])
    Wy.set_ang_vel(U, u[2] * U.y)
    W = Wy.orientnew("W", "Axis", [b2, Wy.x])
    W.set_ang_vel(Wy, u[3] * Wy.x)
    O = me.Point("O")
    O.set_vel(N, 0)
    G1 = O.locatenew("G1", -P["L1"] / 2 * U.z)
    G1.v2pt_theory(O, N, U)
    K = O.locatenew("K", -P["L1"] * U.z)
    K.v2pt_theory(O, N, U)
    G2 = K.locatenew("G2", -P["L2"] / 2 * W.z)
    G2.v2pt_theory(K, N, W)
    bodies = [me.RigidBody("upper", G1, U, P["m1"], (me.inertia(U, P["A1"], P["B1"], P["C1"]), G1)),
              me.RigidBody("lower", G2, W, P["m2"], (me.inertia(W, P["A2"], P["B2"], P["C2"]), G2))]
    loads = [(G1, -P["m1"] * P["g"] * N.z), (G2, -P["m2"] * P["g"] * N.z)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 7. pan-tilt head on a rolling ship -----------------------------------------------------

def pan_tilt(strut: bool = True, ship: bool = True, joint_damping: bool = True, spring: bool = False) -> Reference:
    pan, tilt = q = list(me.dynamicsymbols("pan tilt"))
    u1, u2 = u = list(me.dynamicsymbols("u1:3"))
    P = _symbols("g A w ph hm hp mp ep hq Ap Bp Cp mc cx cz Icxx Icyy Iczz Icxz mw_ dw cp ct cs sb Tp Tt")
    N = me.ReferenceFrame("N")
    S = N.orientnew("S", "Axis", [P["A"] * sp.sin(P["w"] * t + P["ph"]) if ship else 0, N.x])
    Fp = S.orientnew("Fp", "Axis", [pan, S.z])
    Fp.set_ang_vel(S, u1 * S.z)
    Fc = Fp.orientnew("Fc", "Axis", [tilt, Fp.y])
    Fc.set_ang_vel(Fp, u2 * Fp.y)
    O = me.Point("O")
    O.set_vel(N, 0)
    mount = O.locatenew("mount", P["hm"] * S.z)
    mount.v2pt_theory(O, N, S)
    pivot = mount.locatenew("pivot", P["hp"] * Fp.z)
    pivot.v2pt_theory(mount, N, Fp)
    Gp = mount.locatenew("Gp", P["ep"] * Fp.x + P["hq"] * Fp.z)
    Gp.v2pt_theory(mount, N, Fp)
    Gc = pivot.locatenew("Gc", P["cx"] * Fc.x + P["cz"] * Fc.z)
    Gc.v2pt_theory(pivot, N, Fc)
    Wt = pivot.locatenew("Wt", -P["dw"] * Fc.x)
    Wt.v2pt_theory(pivot, N, Fc)
    foot = mount.locatenew("foot", -P["sb"] * Fp.x)
    foot.v2pt_theory(mount, N, Fp)
    Ic = me.inertia(Fc, P["Icxx"], P["Icyy"], P["Iczz"], 0, 0, P["Icxz"])
    bodies = [me.RigidBody("stage", Gp, Fp, P["mp"], (me.inertia(Fp, P["Ap"], P["Bp"], P["Cp"]), Gp)),
              me.RigidBody("camera", Gc, Fc, P["mc"], (Ic, Gc)),
              me.Particle("counterweight", Wt, P["mw_"])]
    g = P["g"]
    # strut: a linear damper between foot and Wt, force c*dl/dt along the line, pulling together when extending
    r = Wt.pos_from(foot)
    length = sp.sqrt(r.dot(r))
    rate = (Wt.vel(N) - foot.vel(N)).dot(r) / length
    strut = -P["cs"] * rate * r / length if strut else 0 * N.x   # on Wt
    if spring:  # ablation only: the strut as a spring of stiffness cs and free length sb
        strut = -P["cs"] * (length - P["sb"]) * r / length
    loads = [(Gp, -P["mp"] * g * N.z), (Gc, -P["mc"] * g * N.z), (Wt, -P["mw_"] * g * N.z + strut),
             (foot, -strut),
             (Fp, (P["Tp"] - int(joint_damping) * P["cp"] * u1) * Fp.z),
             (Fc, (P["Tt"] - int(joint_damping) * P["ct"] * u2) * Fp.y), (Fp, -(P["Tt"] - int(joint_damping) * P["ct"] * u2) * Fp.y)]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 8. box on two springs ------------------------------------------------------------------

def _E(q0, q1, q2, q3):
    return sp.Matrix([[-q1, q0, q3, -q2], [-q2, -q3, q0, q1], [-q3, q2, -q1, q0]])


def two_spring(quaternion: bool) -> Reference:
    if quaternion:
        x, y, z, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y z e0 e1 e2 e3"))
    else:
        x, y, z, phi, theta, psi = q = list(me.dynamicsymbols("x y z phi theta psi"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m g A B C k1 k2 L1 L2 hx h px py pz")
    N = me.ReferenceFrame("N")
    Bf = me.ReferenceFrame("Bf")
    if quaternion:
        Bf.orient_quaternion(N, [e0, e1, e2, e3])
        Bf.set_ang_vel(N, u[3] * Bf.x + u[4] * Bf.y + u[5] * Bf.z)
        qdot = _E(e0, e1, e2, e3).T * sp.Matrix(u[3:]) / 2
        kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [
            qi.diff(t) - qdot[i] for i, qi in enumerate((e0, e1, e2, e3))]
    else:
        Bf.orient_body_fixed(N, (phi, theta, psi), "ZXZ")
        kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    O = me.Point("O")
    O.set_vel(N, 0)
    hooks = [O.locatenew("H1", -P["hx"] * N.x + P["h"] * N.z), O.locatenew("H2", P["hx"] * N.x + P["h"] * N.z)]
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    corners = [G.locatenew("C1", -P["px"] * Bf.x + P["py"] * Bf.y + P["pz"] * Bf.z),
               G.locatenew("C2", P["px"] * Bf.x - P["py"] * Bf.y + P["pz"] * Bf.z)]
    loads = [(G, -P["m"] * P["g"] * N.z)]
    for hook, corner, k, L in zip(hooks, corners, (P["k1"], P["k2"]), (P["L1"], P["L2"])):
        corner.v2pt_theory(G, N, Bf)
        r = corner.pos_from(hook)
        length = sp.sqrt(r.dot(r))
        loads.append((corner, -k * (length - L) * r / length))
    body = me.RigidBody("box", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], loads)
    if quaternion:
        norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
        return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e0], spread=0.5)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


SYSTEMS = {
    "rrr_arm": (HERE / "rrr_arm.yaml", rrr_arm, "RRR arm (yaw, pitch, pitch), full inertias, motors, frames"),
    "rrr_arm_f1_expanded": (HERE / "rrr_arm_f1_expanded.yaml", rrr_arm, "the same, format 1, angle sums multiplied out"),
    "rrr_arm_damper": (HERE / "rrr_arm_damper.yaml", lambda: rrr_arm(True), "RRR arm + damper wrist-to-floor, frames"),
    "rrr_arm_f1": (HERE / "rrr_arm_f1.yaml", rrr_arm, "the same arm in format 1 (turret by the plane shorthand)"),
    "spherical_zyx_f1": (HERE / "spherical_zyx_f1.yaml", spherical_zyx, "rigid spherical pendulum, ZYX angles, format 1"),
    "gyro_gimbal": (HERE / "gyro_gimbal.yaml", gyro_gimbal, "gyroscope in two massive gimbals, spin rate quasi-coord, frames"),
    "scara": (HERE / "scara.yaml", scara, "SCARA R-R-P, motors and quill actuator, frames"),
    "free_xyz_rates_f1": (HERE / "free_xyz_rates_f1.yaml", free_xyz_rates, "free body, XYZ angles, body rates, torque + offset thrust, format 1"),
    "universal2_f1": (HERE / "universal2_f1.yaml", universal2, "two-link pendulum, universal joints, format 1"),
    "pan_tilt": (HERE / "pan_tilt.yaml", pan_tilt, "pan-tilt head on a rolling ship, damping work + strut damper, frames"),
    "two_spring_quat": (HERE / "two_spring_quat.yaml", lambda: two_spring(True), "box on two springs, quaternion frame"),
    "two_spring_zxz": (HERE / "two_spring_zxz.yaml", lambda: two_spring(False), "box on two springs, ZXZ frame"),
}
