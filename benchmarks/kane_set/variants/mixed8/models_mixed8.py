"""KanesMethod references for the v48_ systems, built from the mechanics.

Every constraint is formed here from its definition (the material points in
contact having one velocity, a knife edge's point not moving across its
blade), never from the gacli file's rows. Names of coordinates, parameters
and inputs are the files'; Kane's independent speeds are in the order of the
file's ``independent``.
"""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


# -- helpers ---------------------------------------------------------------------------

def _fixed_origin(N):
    O = me.Point("O")
    O.set_vel(N, 0)
    return O


def _on(name, base, frame, vec, N):
    """A point fixed in ``frame`` at ``vec`` from ``base`` (also fixed in it)."""
    P = base.locatenew(name, vec)
    P.v2pt_theory(base, N, frame)
    return P


def _qdot_is_u(q, u):
    return [qi.diff(t) - ui for qi, ui in zip(q, u)]


def _quaternion_rates(e, w):
    """e' = 1/2 G^T w, w the body-axis angular velocity (scalar part first)."""
    e0, e1, e2, e3 = e
    G = sp.Matrix([[-e1, e0, e3, -e2], [-e2, -e3, e0, e1], [-e3, e2, -e1, e0]])
    return list(G.T * sp.Matrix(w) / 2)


# -- 1. unbalanced ball on a driven turntable, quaternion attitude -------------------------------

def ball_turntable_quat() -> Reference:
    x, y, e0, e1, e2, e3 = q = list(me.dynamicsymbols("x y e0 e1 e2 e3"))
    w1, w2, w3, ux, uy = me.dynamicsymbols("w1:4 ux uy")
    P = _symbols("m r e A B C g W E nu")
    r = P["r"]
    beta = P["W"] * t + P["E"] * sp.sin(P["nu"] * t)
    N = me.ReferenceFrame("N")
    Tb = N.orientnew("Tb", "Axis", [beta, N.z])          # the table
    Bf = me.ReferenceFrame("Bf")
    Bf.orient_quaternion(N, [e0, e1, e2, e3])
    Bf.set_ang_vel(N, w1 * Bf.x + w2 * Bf.y + w3 * Bf.z)
    edot = _quaternion_rates((e0, e1, e2, e3), (w1, w2, w3))
    kd = [x.diff(t) - ux, y.diff(t) - uy] + [qi.diff(t) - edot[i] for i, qi in enumerate((e0, e1, e2, e3))]
    O = _fixed_origin(N)
    Cg = O.locatenew("Cg", x * N.x + y * N.y + r * N.z)     # geometric centre
    Cg.set_vel(N, ux * N.x + uy * N.y)
    G = _on("G", Cg, Bf, -P["e"] * Bf.z, N)                 # mass centre
    Pc = Cg.locatenew("Pc", -r * N.z)                       # contact, on the table's plane
    ball_point = Cg.vel(N) + Bf.ang_vel_in(N).cross(Pc.pos_from(Cg))
    table_point = Tb.ang_vel_in(N).cross(Pc.pos_from(O))
    slip = ball_point - table_point
    cons = [slip.dot(N.x), slip.dot(N.y)]
    body = me.RigidBody("ball", G, Bf, P["m"], (me.inertia(Bf, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[w1, w2, w3], u_dependent=[ux, uy], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, [w1, w2, w3], [ux, uy], P, cons), _named(q),
                     configuration=norm, q_dep=[e0], spread=0.5)


# -- 2. three-link spatial pendulum with Cardan joints --------------------------------------------

def cardan_chain3() -> Reference:
    q = list(me.dynamicsymbols("a1 b1 a2 b2 a3 b3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("g m1 m2 m3 L1 L2 L3 C1 C2 C3 k c")
    N = me.ReferenceFrame("N")
    O = _fixed_origin(N)
    parent, joint = N, O
    bodies, loads = [], []
    previous_frame = None
    for i in range(3):
        a, b = q[2 * i], q[2 * i + 1]
        ua, ub = u[2 * i], u[2 * i + 1]
        Fa = parent.orientnew(f"F{i + 1}a", "Axis", [a, parent.x])
        Fb = Fa.orientnew(f"F{i + 1}", "Axis", [b, Fa.y])
        m, L, C = P[f"m{i + 1}"], P[f"L{i + 1}"], P[f"C{i + 1}"]
        Gi = _on(f"G{i + 1}", joint, Fb, -L / 2 * Fb.z, N)
        bodies.append(me.RigidBody(f"link{i + 1}", Gi, Fb, m, (me.inertia(Fb, m * L**2 / 12, m * L**2 / 12, C), Gi)))
        loads.append((Gi, -m * P["g"] * N.z))
        # joint torque: spring and damper on each joint angle, along the joint's two (orthogonal) axes
        tau = (-P["k"] * a - P["c"] * ua) * parent.x + (-P["k"] * b - P["c"] * ub) * Fa.y
        loads.append((Fb, tau))
        if previous_frame is not None:
            loads.append((previous_frame, -tau))
        previous_frame = Fb
        joint = _on(f"J{i + 2}", joint, Fb, -L * Fb.z, N)
        parent = Fb
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=_qdot_is_u(q, u))
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 3. cone rolling on a free tilted turntable ------------------------------------------------------

def cone_turntable() -> Reference:
    psi, yaw, spin = q = list(me.dynamicsymbols("psi yaw spin"))
    upsi, uyaw, uspin = u = list(me.dynamicsymbols("upsi uyaw uspin"))
    P = _symbols("m h beta M Jt Kt alpha c g T")
    m, h, beta = P["m"], P["h"], P["beta"]
    R = h * sp.tan(beta)
    N = me.ReferenceFrame("N")
    Tl = N.orientnew("Tl", "Axis", [P["alpha"], N.x])
    Tab = Tl.orientnew("Tab", "Axis", [psi, Tl.z])
    H = Tab.orientnew("H", "Axis", [yaw, Tab.z])
    Ax = H.orientnew("Ax", "Axis", [-beta, H.y])
    Co = Ax.orientnew("Co", "Axis", [spin, Ax.x])
    O = _fixed_origin(N)                                    # apex, on the table's axis
    G = _on("G", O, Co, 3 * h / 4 * Ax.x, N)
    # the contact: on the slant line of the cone that lies on the table, at the base rim
    Pc = O.locatenew("Pc", h / sp.cos(beta) * H.x)
    cone_point = Co.ang_vel_in(N).cross(Pc.pos_from(O))
    table_point = Tab.ang_vel_in(N).cross(Pc.pos_from(O))
    rates = {qi.diff(t): ui for qi, ui in zip(q, u)}
    slip = (cone_point - table_point).express(H)
    comps = [sp.simplify(slip.dot(v).subs(rates)) for v in (H.x, H.y, H.z)]
    assert comps[0] == 0 and comps[2] == 0, comps
    cons = [comps[1]]
    A_ax = sp.Rational(3, 10) * m * R**2
    A_tr = sp.Rational(3, 20) * m * R**2 + sp.Rational(3, 80) * m * h**2
    cone = me.RigidBody("cone", G, Co, m, (me.inertia(Co, A_ax, A_tr, A_tr), G))
    table = me.RigidBody("table", O, Tab, P["M"], (me.inertia(Tab, P["Kt"], P["Kt"], P["Jt"]), O))
    loads = [(G, -m * P["g"] * N.z), (Tab, (P["T"] - P["c"] * upsi) * Tab.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[upsi, uyaw], u_dependent=[uspin], kd_eqs=_qdot_is_u(q, u),
                          velocity_constraints=cons)
    kane.kanes_equations([cone, table], loads)
    return Reference(KaneModel(kane, q, [upsi, uyaw], [uspin], P, cons), _named(q))


# -- 4. rolling hoop, lean from the horizontal -------------------------------------------------------

def hoop_lean_horizontal() -> Reference:
    x, y, yaw, theta, spin = q = list(me.dynamicsymbols("x y yaw theta spin"))
    uyaw, uth, uspin, ux, uy = u = list(me.dynamicsymbols("uyaw uth uspin ux uy"))
    P = _symbols("m r c g")
    m, r = P["m"], P["r"]
    N = me.ReferenceFrame("N")
    H = N.orientnew("H", "Axis", [yaw, N.z])
    L = H.orientnew("L", "Axis", [sp.pi / 2 - theta, H.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    kd = [yaw.diff(t) - uyaw, theta.diff(t) - uth, spin.diff(t) - uspin, x.diff(t) - ux, y.diff(t) - uy]
    rates = sp.solve(kd, [qi.diff(t) for qi in (yaw, theta, spin, x, y)], dict=True)[0]
    O = _fixed_origin(N)
    Pc = O.locatenew("Pc", x * N.x + y * N.y)              # the geometric contact point
    Pc.set_vel(N, ux * N.x + uy * N.y)
    C = Pc.locatenew("C", r * L.z)
    C.set_vel(N, Pc.vel(N) + (r * L.z).dt(N).subs(rates))
    w = D.ang_vel_in(N).subs(rates)
    material = C.vel(N) + w.cross(Pc.pos_from(C))
    cons = [material.dot(N.x), material.dot(N.y)]
    hoop = me.RigidBody("hoop", C, D, m, (me.inertia(D, m * r**2 / 2, m * r**2, m * r**2 / 2), C))
    loads = [(C, -m * P["g"] * N.z), (D, -P["c"] * uspin * L.y)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[uyaw, uth, uspin], u_dependent=[ux, uy], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations([hoop], loads)
    return Reference(KaneModel(kane, q, [uyaw, uth, uspin], [ux, uy], P, cons), _named(q))


# -- 5. double pendulum, relative angles ---------------------------------------------------------------

def double_pendulum_origins() -> Reference:
    q1, q2 = q = list(me.dynamicsymbols("q1 q2"))
    u1, u2 = u = list(me.dynamicsymbols("u1 u2"))
    P = _symbols("m1 m2 mt L1 L2 k q20 c2 g T1 T2")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [q1, N.z])
    B = A.orientnew("B", "Axis", [q2, A.z])
    O = _fixed_origin(N)
    elbow = _on("elbow", O, A, -P["L1"] * A.y, N)
    c1 = _on("c1", O, A, -P["L1"] / 2 * A.y, N)
    c2 = _on("c2", elbow, B, -P["L2"] / 2 * B.y, N)
    tip = _on("tip", elbow, B, -P["L2"] * B.y, N)
    m1, m2, mt, g = P["m1"], P["m2"], P["mt"], P["g"]
    bodies = [me.RigidBody("upper", c1, A, m1, (me.inertia(A, m1 * P["L1"]**2 / 12, 0, m1 * P["L1"]**2 / 12), c1)),
              me.RigidBody("lower", c2, B, m2, (me.inertia(B, m2 * P["L2"]**2 / 12, 0, m2 * P["L2"]**2 / 12), c2)),
              me.Particle("tipmass", tip, mt)]
    elbow_torque = (P["T2"] - P["k"] * (q2 - P["q20"]) - P["c2"] * u2) * N.z
    loads = [(c1, -m1 * g * N.y), (c2, -m2 * g * N.y), (tip, -mt * g * N.y),
             (A, P["T1"] * N.z), (B, elbow_torque), (A, -elbow_torque)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=_qdot_is_u(q, u))
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 6. spring-mass-damper chain of four carts --------------------------------------------------------

def smd_chain4() -> Reference:
    q = list(me.dynamicsymbols("x1:5"))
    u = list(me.dynamicsymbols("u1:5"))
    P = _symbols("m1 m2 m3 m4 k1 k2 k3 k4 c1 c2 c3 c4 L0 alpha A w g F")
    N = me.ReferenceFrame("N")
    Tr = N.orientnew("Tr", "Axis", [-P["alpha"], N.y])
    O = _fixed_origin(N)
    w0 = P["A"] * sp.sin(P["w"] * t)
    wall = O.locatenew("wall", w0 * Tr.x)
    wall.set_vel(N, w0.diff(t) * Tr.x)
    carts = []
    for i in range(4):
        p = O.locatenew(f"p{i + 1}", q[i] * Tr.x)
        p.set_vel(N, u[i] * Tr.x)
        carts.append(p)
    bodies = [me.Particle(f"cart{i + 1}", p, P[f"m{i + 1}"]) for i, p in enumerate(carts)]
    loads = [(p, -P[f"m{i + 1}"] * P["g"] * N.z) for i, p in enumerate(carts)]
    loads.append((carts[3], P["F"] * Tr.x))
    ends = [wall, *carts]
    for i in range(4):
        a, b = ends[i], ends[i + 1]
        rvec = b.pos_from(a)
        length = sp.sqrt(rvec.dot(rvec))
        rate = rvec.dot(b.vel(N) - a.vel(N)) / length
        f = -(P[f"k{i + 1}"] * (length - P["L0"]) + P[f"c{i + 1}"] * rate) * rvec / length   # on b
        loads.append((b, f))
        if a is not wall:
            loads.append((a, -f))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=_qdot_is_u(q, u))
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- 7. free satellite with one skewed, offset reaction wheel -----------------------------------------

def satellite_skew_wheel() -> Reference:
    x, y, z, e0, e1, e2, e3, a = q = list(me.dynamicsymbols("x y z e0 e1 e2 e3 a"))
    ux, uy, uz, w1, w2, w3, ua = u = list(me.dynamicsymbols("ux uy uz w1 w2 w3 ua"))
    P = _symbols("M I1 I2 I3 I12 mw J K d gam dl lx T P")
    N = me.ReferenceFrame("N")
    Hb = me.ReferenceFrame("Hb")
    Hb.orient_quaternion(N, [e0, e1, e2, e3])
    Hb.set_ang_vel(N, w1 * Hb.x + w2 * Hb.y + w3 * Hb.z)
    M1 = Hb.orientnew("M1", "Axis", [P["gam"], Hb.z])
    Mt = M1.orientnew("Mt", "Axis", [P["dl"], M1.y])
    Wh = Mt.orientnew("Wh", "Axis", [a, Mt.x])
    edot = _quaternion_rates((e0, e1, e2, e3), (w1, w2, w3))
    kd = [x.diff(t) - ux, y.diff(t) - uy, z.diff(t) - uz] + \
         [qi.diff(t) - edot[i] for i, qi in enumerate((e0, e1, e2, e3))] + [a.diff(t) - ua]
    O = _fixed_origin(N)
    C = O.locatenew("C", x * N.x + y * N.y + z * N.z)
    C.set_vel(N, ux * N.x + uy * N.y + uz * N.z)
    Wc = _on("Wc", C, Hb, P["d"] * Hb.y, N)
    Th = _on("Th", C, Hb, P["lx"] * Hb.x, N)
    hub = me.RigidBody("hub", C, Hb, P["M"], (me.inertia(Hb, P["I1"], P["I2"], P["I3"], P["I12"]), C))
    wheel = me.RigidBody("wheel", Wc, Wh, P["mw"], (me.inertia(Wh, P["J"], P["K"], P["K"]), Wc))
    loads = [(Wh, P["T"] * Mt.x), (Hb, -P["T"] * Mt.x), (Th, P["P"] * Hb.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([hub, wheel], loads)
    norm = [e0**2 + e1**2 + e2**2 + e3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[e0], spread=0.5)


# -- 8. car-like robot with a trailer, three knife edges ----------------------------------------------

def car_trailer() -> Reference:
    x, y, th, de, ph = q = list(me.dynamicsymbols("x y theta delta phi"))
    v, ud, vs, wth, wph = me.dynamicsymbols("v ud vs wth wph")
    P = _symbols("m I b L mf Jf hb mt It Lt ct Pd S")
    N = me.ReferenceFrame("N")
    Car = N.orientnew("Car", "Axis", [th, N.z])
    St = Car.orientnew("St", "Axis", [de, Car.z])
    Tr = N.orientnew("Tr", "Axis", [ph, N.z])
    Car.set_ang_vel(N, wth * N.z)
    St.set_ang_vel(Car, ud * Car.z)
    Tr.set_ang_vel(N, wph * N.z)
    kd = [sp.cos(th) * x.diff(t) + sp.sin(th) * y.diff(t) - v,
          -sp.sin(th) * x.diff(t) + sp.cos(th) * y.diff(t) - vs,
          th.diff(t) - wth, de.diff(t) - ud, ph.diff(t) - wph]
    O = _fixed_origin(N)
    R = O.locatenew("R", x * N.x + y * N.y)
    R.set_vel(N, v * Car.x + vs * Car.y)
    F = _on("F", R, Car, P["L"] * Car.x, N)
    G = _on("G", R, Car, P["b"] * Car.x, N)
    H = _on("H", R, Car, -P["hb"] * Car.x, N)
    Gt = _on("Gt", H, Tr, -P["ct"] * Tr.x, N)
    Ta = _on("Ta", H, Tr, -P["Lt"] * Tr.x, N)
    cons = [R.vel(N).dot(Car.y), F.vel(N).dot(St.y), Ta.vel(N).dot(Tr.y)]
    bodies = [me.RigidBody("car", G, Car, P["m"], (me.inertia(Car, 0, 0, P["I"]), G)),
              me.RigidBody("front", F, St, P["mf"], (me.inertia(St, 0, 0, P["Jf"]), F)),
              me.RigidBody("trailer", Gt, Tr, P["mt"], (me.inertia(Tr, 0, 0, P["It"]), Gt))]
    loads = [(R, P["Pd"] * Car.x), (St, P["S"] * Car.z), (Car, -P["S"] * Car.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[v, ud], u_dependent=[vs, wth, wph], kd_eqs=kd,
                          velocity_constraints=cons)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, [v, ud], [vs, wth, wph], P, cons), _named(q))


SYSTEMS = {
    "v48_ball_turntable_quat": (HERE / "v48_ball_turntable_quat.yaml", ball_turntable_quat,
                                "unbalanced ball on a driven turntable, quaternion frame, offset centre"),
    "v48_cardan_chain3": (HERE / "v48_cardan_chain3.yaml", cardan_chain3,
                          "three-link spatial pendulum, Cardan joints, frame origins, joint springs/dampers"),
    "v48_cone_turntable": (HERE / "v48_cone_turntable.yaml", cone_turntable,
                           "cone rolling (rim as wheel, offset centre) on a free tilted turntable, apex pinned"),
    "v48_hoop_lean_horizontal": (HERE / "v48_hoop_lean_horizontal.yaml", hoop_lean_horizontal,
                                 "rolling hoop, lean from the horizontal (pi/2 - theta), axle damping"),
    "v48_double_pendulum_origins": (HERE / "v48_double_pendulum_origins.yaml", double_pendulum_origins,
                                    "double pendulum, relative angles, frame origins, motors, elbow spring"),
    "v48_smd_chain4": (HERE / "v48_smd_chain4.yaml", smd_chain4,
                       "four carts, springs and dampers between points, incline, shaken wall w0(t)"),
    "v48_satellite_skew_wheel": (HERE / "v48_satellite_skew_wheel.yaml", satellite_skew_wheel,
                                 "free satellite, quaternion, one skewed offset reaction wheel, thruster"),
    "v48_car_trailer": (HERE / "v48_car_trailer.yaml", car_trailer,
                        "car-like robot with a trailer, three knife edges, forward-speed quasi-coordinate"),
}
