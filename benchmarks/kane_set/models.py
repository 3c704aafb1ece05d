"""The set's systems written for SymPy's KanesMethod, one builder per system file.

Each builder builds the model as a SymPy user would (frames, points, rigid
bodies, loads, ``KanesMethod.kanes_equations``) with the system file's
coordinates, its independent speeds in the same order and its parameters
under the same names. Constraints are formed here from their definition
(the material contact point at rest, the loop closed), never copied from a
system file, so that agreement checks the file. The bicycle and the spatial
chain reuse ``benchmarks/bench_kane.py``.

A :class:`Reference` tells the harness how Kane's symbols meet gacli's:
``coordinates`` maps each Kane coordinate to a gacli coordinate name,
``model.u_ind`` is in the order of the file's ``independent``,
``dependent_rates`` maps a gacli coordinate whose rate Kane carries as a
dependent speed (the bicycle's wheel_F) to that speed, and
``configuration``/``q_dep`` are holonomic constraints the random states are
made to satisfy.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

import bench_kane
from bench_kane import KaneModel

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent


@dataclass
class Reference:
    model: KaneModel
    coordinates: dict  # Kane coordinate (dynamicsymbol) -> gacli coordinate name
    dependent_rates: dict = field(default_factory=dict)  # gacli coordinate name -> Kane dependent speed
    configuration: list = field(default_factory=list)  # f(q) = 0, in Kane's coordinates
    q_dep: list = field(default_factory=list)  # the coordinates solved from them
    spread: float = 1.0  # random coordinates in [-spread, spread]
    guess: dict = field(default_factory=dict)  # gacli name -> where to start solving for a dependent coordinate


def _symbols(names: str) -> dict[str, sp.Symbol]:
    return {s.name: s for s in sp.symbols(names, seq=True)}


def _named(q) -> dict:
    return {qi: qi.func.__name__ for qi in q}


def _solved_rates(kd, q) -> dict:
    """q' in terms of the speeds, from the kinematic differential equations (linear in q')."""
    qdots = [qi.diff(me.dynamicsymbols._t) for qi in q]
    return sp.solve(kd, qdots, dict=True)[0]


# -- the bicycle ---------------------------------------------------------------------

def bicycle() -> Reference:
    """SymPy's test_kane3.py bicycle; u3, u6 are the wheels' rates, u1, u4 yaw and pitch rates."""
    model = bench_kane.whipple_bicycle()
    q1, q2, q5, q4 = model.q
    u1, u4, u6 = model.u_dep
    return Reference(model, {q1: "yaw", q2: "roll", q5: "steer", q4: "pitch"}, {"wheel_F": u6},
                     list(getattr(model.kane, "_f_h", [])), [q4], spread=0.3)


# -- the rattleback -----------------------------------------------------------------

def _rattleback_geometry(P: dict, yaw, lean, pitch):
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    R = L.orientnew("R", "Axis", [pitch, L.y])
    mu = [N.z.dot(axis) for axis in (R.x, R.y, R.z)]
    eps = sp.sqrt((P["a"] * mu[0])**2 + (P["b"] * mu[1])**2 + (P["c"] * mu[2])**2)
    # The contact P is where the outward normal is -N.z: P - O = -E^2 mu / eps.
    offset = -(P["a"]**2 * mu[0] * R.x + P["b"]**2 * mu[1] * R.y + P["c"]**2 * mu[2] * R.z) / eps
    return N, R, offset


def rattleback(body_rates: bool = False) -> Reference:
    """PyDy's rattleback: yaw, lean, pitch and the contact point (x, y); u = q' or body rates."""
    yaw, lean, pitch, x, y = q = list(me.dynamicsymbols("yaw lean pitch x y"))
    u1, u2, u3, u4, u5 = u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("a b c d e f m Ixx Iyy Izz Ixy Iyz Ixz g")
    N, R, contact_from_centre = _rattleback_geometry(P, yaw, lean, pitch)
    t = me.dynamicsymbols._t
    if body_rates:
        R.set_ang_vel(N, u1 * R.x + u2 * R.y + u3 * R.z)
        w = R.ang_vel_in(N)
        natural = _natural_rates(N, R, yaw, lean, pitch)
        kd = [natural[i] - (u1, u2, u3)[i] for i in range(3)] + [x.diff(t) - u4, y.diff(t) - u5]
    else:
        R.set_ang_vel(N, u1 * N.z + u2 * _lean_axis(N, yaw) + u3 * R.y)
        w = R.ang_vel_in(N)
        kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    rates = _solved_rates(kd, q)
    O = me.Point("O")
    O.set_vel(N, 0)
    contact = O.locatenew("P", x * N.x + y * N.y)
    contact.set_vel(N, u4 * N.x + u5 * N.y)
    centre_from_contact = -contact_from_centre
    G = contact.locatenew("G", centre_from_contact + P["d"] * R.x + P["e"] * R.y + P["f"] * R.z)
    G.set_vel(N, contact.vel(N) + G.pos_from(contact).dt(N).subs(rates))
    material = G.vel(N) + w.cross(-G.pos_from(contact))
    constraints = [material.dot(N.x), material.dot(N.y)]
    inertia = me.inertia(R, P["Ixx"], P["Iyy"], P["Izz"], P["Ixy"], P["Iyz"], P["Ixz"])
    body = me.RigidBody("rattleback", G, R, P["m"], (inertia, G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=constraints)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, constraints), _named(q))


def _lean_axis(N, yaw):
    return sp.cos(yaw) * N.x + sp.sin(yaw) * N.y


def _natural_rates(N, R, yaw, lean, pitch):
    """The body-axis components of yaw' N.z + lean' L.x + pitch' R.y (R from N by z, x, y)."""
    t = me.dynamicsymbols._t
    L_x = _lean_axis(N, yaw)
    w = yaw.diff(t) * N.z + lean.diff(t) * L_x + pitch.diff(t) * R.y
    return [w.dot(R.x), w.dot(R.y), w.dot(R.z)]


# -- a free body in quaternions -----------------------------------------------------

def quaternion_body() -> Reference:
    """Euler parameters q0..q3 and body rates u4..u6 (Kane's explicit kinematics q' = E^T w / 2)."""
    x, y, z, q0, q1, q2, q3 = q = list(me.dynamicsymbols("x y z q0 q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:7"))
    P = _symbols("m A B C g")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, [q0, q1, q2, q3])
    B.set_ang_vel(N, u[3] * B.x + u[4] * B.y + u[5] * B.z)
    t = me.dynamicsymbols._t
    E = sp.Matrix([[-q1, q0, q3, -q2], [-q2, -q3, q0, q1], [-q3, q2, -q1, q0]])
    qdot = E.T * sp.Matrix(u[3:]) / 2
    kd = [x.diff(t) - u[0], y.diff(t) - u[1], z.diff(t) - u[2]] + [
        qi.diff(t) - qdot[i] for i, qi in enumerate((q0, q1, q2, q3))]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + z * N.z)
    G.set_vel(N, u[0] * N.x + u[1] * N.y + u[2] * N.z)
    body = me.RigidBody("body", G, B, P["m"], (me.inertia(B, P["A"], P["B"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    norm = [q0**2 + q1**2 + q2**2 + q3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[q0], spread=0.5)


def quaternion_top() -> Reference:
    """A heavy top about a fixed point: Euler parameters q0..q3, body rates u1..u3."""
    q0, q1, q2, q3 = q = list(me.dynamicsymbols("q0 q1 q2 q3"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("m l A C g")
    N = me.ReferenceFrame("N")
    B = me.ReferenceFrame("B")
    B.orient_quaternion(N, q)
    B.set_ang_vel(N, u[0] * B.x + u[1] * B.y + u[2] * B.z)
    t = me.dynamicsymbols._t
    E = sp.Matrix([[-q1, q0, q3, -q2], [-q2, -q3, q0, q1], [-q3, q2, -q1, q0]])
    qdot = E.T * sp.Matrix(u) / 2
    kd = [qi.diff(t) - qdot[i] for i, qi in enumerate(q)]
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", P["l"] * B.z)
    G.v2pt_theory(O, N, B)
    body = me.RigidBody("top", G, B, P["m"], (me.inertia(B, P["A"], P["A"], P["C"]), G))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([body], [(G, -P["m"] * P["g"] * N.z)])
    norm = [q0**2 + q1**2 + q2**2 + q3**2 - 1]
    return Reference(KaneModel(kane, q, u, [], P), _named(q), configuration=norm, q_dep=[q0], spread=0.5)


# -- linkages and chains --------------------------------------------------------------

def _bar(name, frame, centre, mass, length):
    return me.RigidBody(name, centre, frame, mass, (me.inertia(frame, 0, 0, mass * length**2 / 12), centre))


def four_bar() -> Reference:
    """Crank, coupler, rocker with absolute angles; th2, th3 dependent through the loop closure."""
    th1, th2, th3 = q = list(me.dynamicsymbols("th1 th2 th3"))
    u1, u2, u3 = u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("l0 l1 l2 l3 m1 m2 m3 g")
    N = me.ReferenceFrame("N")
    frames = [N.orientnew(f"A{i + 1}", "Axis", [qi, N.z]) for i, qi in enumerate(q)]
    for frame, ui in zip(frames, u):
        frame.set_ang_vel(N, ui * N.z)
    A1, A2, A3 = frames
    O = me.Point("O")
    O.set_vel(N, 0)
    D = O.locatenew("D", P["l0"] * N.x)
    D.set_vel(N, 0)
    B = O.locatenew("B", P["l1"] * A1.x)
    C = B.locatenew("C", P["l2"] * A2.x)
    G1 = O.locatenew("G1", P["l1"] / 2 * A1.x)
    G2 = B.locatenew("G2", P["l2"] / 2 * A2.x)
    G3 = D.locatenew("G3", P["l3"] / 2 * A3.x)
    G1.v2pt_theory(O, N, A1)
    B.v2pt_theory(O, N, A1)
    G2.v2pt_theory(B, N, A2)
    C.v2pt_theory(B, N, A2)
    G3.v2pt_theory(D, N, A3)
    loop = C.pos_from(O) - (D.pos_from(O) + P["l3"] * A3.x)
    configuration = [loop.dot(N.x), loop.dot(N.y)]
    t = me.dynamicsymbols._t
    rates = {qi.diff(t): ui for qi, ui in zip(q, u)}
    velocity = [sp.expand(c.diff(t).subs(rates)) for c in configuration]
    bodies = [_bar("crank", A1, G1, P["m1"], P["l1"]), _bar("coupler", A2, G2, P["m2"], P["l2"]),
              _bar("rocker", A3, G3, P["m3"], P["l3"])]
    loads = [(G, -m * P["g"] * N.y) for G, m in ((G1, P["m1"]), (G2, P["m2"]), (G3, P["m3"]))]
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=[th1], q_dependent=[th2, th3], u_ind=[u1], u_dependent=[u2, u3], kd_eqs=kd,
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads)
    model = KaneModel(kane, q, [u1], [u2, u3], P, velocity)
    # Started on the assembly branch above the ground link (crank-rocker: l1 + l2 < l0 + l3).
    return Reference(model, _named(q), configuration=configuration, q_dep=[th2, th3], guess={"th2": 0.9, "th3": 1.7})


def _hanging_bars(N, top, angles, speeds, masses, lengths, g):
    """Bars hanging from ``top`` with absolute angles from the downward vertical (about N.z)."""
    bodies, loads, joint = [], [], top
    for i, (qi, ui, m, L) in enumerate(zip(angles, speeds, masses, lengths)):
        frame = N.orientnew(f"B{i + 1}", "Axis", [qi, N.z])
        frame.set_ang_vel(N, ui * N.z)
        centre = joint.locatenew(f"G{i + 1}", -L / 2 * frame.y)
        centre.v2pt_theory(joint, N, frame)
        bodies.append(me.RigidBody(f"bar{i + 1}", centre, frame, m,
                                   (me.inertia(frame, m * L**2 / 12, 0, m * L**2 / 12), centre)))
        loads.append((centre, -m * g * N.y))
        following = joint.locatenew(f"J{i + 2}", -L * frame.y)
        following.v2pt_theory(joint, N, frame)
        joint = following
    return bodies, loads


def planar_chain() -> Reference:
    q = list(me.dynamicsymbols("th1:4"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("g m1 m2 m3 L1 L2 L3")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    bodies, loads = _hanging_bars(N, O, q, u, [P["m1"], P["m2"], P["m3"]], [P["L1"], P["L2"], P["L3"]], P["g"])
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def spatial_chain(links: int = 3) -> Reference:
    model = bench_kane.chain(links)
    return Reference(model, _named(model.q))


def _cart(N, x, ux, M, g):
    O = me.Point("O")
    O.set_vel(N, 0)
    cart = O.locatenew("cart", x * N.x)
    cart.set_vel(N, ux * N.x)
    return cart, me.Particle("cart", cart, M), (cart, -M * g * N.y)


def cart_pole() -> Reference:
    x, th = q = list(me.dynamicsymbols("x th"))
    u = list(me.dynamicsymbols("u1:3"))
    P = _symbols("M m l g")
    N = me.ReferenceFrame("N")
    cart, particle, weight = _cart(N, x, u[0], P["M"], P["g"])
    bodies, loads = _hanging_bars(N, cart, [th], [u[1]], [P["m"]], [P["l"]], P["g"])
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([particle, *bodies], [weight, *loads])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


def double_cart_pendulum() -> Reference:
    x, th1, th2 = q = list(me.dynamicsymbols("x th1 th2"))
    u = list(me.dynamicsymbols("u1:4"))
    P = _symbols("M m1 m2 l1 l2 g")
    N = me.ReferenceFrame("N")
    cart, particle, weight = _cart(N, x, u[0], P["M"], P["g"])
    bodies, loads = _hanging_bars(N, cart, [th1, th2], u[1:], [P["m1"], P["m2"]], [P["l1"], P["l2"]], P["g"])
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations([particle, *bodies], [weight, *loads])
    return Reference(KaneModel(kane, q, u, [], P), _named(q))


# -- rolling discs ------------------------------------------------------------------

def rolling_disc(lean_rates: bool = False) -> Reference:
    """SymPy's rolling disc with the contact point (x, y); u = q' or the lean frame's rates."""
    yaw, lean, spin, x, y = q = list(me.dynamicsymbols("yaw lean spin x y"))
    u1, u2, u3, u4, u5 = u = list(me.dynamicsymbols("u1:6"))
    P = _symbols("m r g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    t = me.dynamicsymbols._t
    if lean_rates:
        # SymPy's example: the disc's angular velocity along L's axes.
        D.set_ang_vel(N, u1 * L.x + u2 * L.y + u3 * L.z)
        natural = yaw.diff(t) * N.z + lean.diff(t) * L.x + spin.diff(t) * L.y
        kd = [natural.dot(L.x) - u1, natural.dot(L.y) - u2, natural.dot(L.z) - u3]
    else:
        D.set_ang_vel(N, u1 * N.z + u2 * L.x + u3 * L.y)
        kd = [yaw.diff(t) - u1, lean.diff(t) - u2, spin.diff(t) - u3]
    kd += [x.diff(t) - u4, y.diff(t) - u5]
    rates = _solved_rates(kd, q)
    O = me.Point("O")
    O.set_vel(N, 0)
    contact = O.locatenew("C", x * N.x + y * N.y)
    contact.set_vel(N, u4 * N.x + u5 * N.y)
    centre = contact.locatenew("G", P["r"] * L.z)
    centre.set_vel(N, contact.vel(N) + centre.pos_from(contact).dt(N).subs(rates))
    material = centre.vel(N) + D.ang_vel_in(N).cross(-P["r"] * L.z)
    constraints = [material.dot(N.x), material.dot(N.y)]
    m, r = P["m"], P["r"]
    disc = me.RigidBody("disc", centre, D, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), centre))
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=constraints)
    kane.kanes_equations([disc], [(centre, -m * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, [u1, u2, u3], [u4, u5], P, constraints), _named(q))


# name -> (system file, builder, what it is)
SYSTEMS = {
    "bicycle_angle_sum": (HERE / "bicycle_angle_sum.yaml", bicycle,
                          "Whipple bicycle, fork frame turned by pitch + htangle (SymPy's writing)"),
    "bicycle_two_frames": (ROOT / "systems" / "whipple_bicycle.yaml", bicycle,
                           "Whipple bicycle, the same rotation as two frames (systems/)"),
    "rattleback": (HERE / "rattleback.yaml", rattleback, "ellipsoid on a plane, Pfaffian no-slip rows, u = q'"),
    "rattleback_rates": (HERE / "rattleback_rates.yaml", lambda: rattleback(True),
                         "the same with body rates as speeds"),
    "quaternion_body": (HERE / "quaternion_body.yaml", quaternion_body,
                        "free body, Euler parameters, body rates, unit norm as a constraint"),
    "quaternion_top": (HERE / "quaternion_top.yaml", quaternion_top,
                       "heavy top about a fixed point, Euler parameters, body rates"),
    "quaternion_frame_body": (HERE / "quaternion_frame_body.yaml", quaternion_body,
                              "free body in a quaternion frame with rates (docs/frames.md)"),
    "quaternion_frame_top": (HERE / "quaternion_frame_top.yaml", quaternion_top,
                             "heavy top in a quaternion frame with rates (docs/frames.md)"),
    "four_bar": (HERE / "four_bar.yaml", four_bar, "four-bar linkage, two holonomic constraints"),
    "four_bar_coincide": (ROOT / "systems" / "four_bar_linkage.yaml", four_bar,
                          "the same with frames, closed by `coincide` (systems/)"),
    "planar_chain": (HERE / "planar_chain.yaml", planar_chain, "3 rigid bars in a plane"),
    "spatial_chain": (HERE / "spatial_chain.yaml", spatial_chain, "3 rigid links, ball joints, XYZ angles"),
    "spatial_chain6": (HERE / "spatial_chain6.yaml", lambda: spatial_chain(6),
                       "6 rigid links, ball joints, XYZ angles (a spatial arm)"),
    "cart_pole": (HERE / "cart_pole.yaml", cart_pole, "cart and pole (format 1)"),
    "double_cart_pendulum": (HERE / "double_cart_pendulum.yaml", double_cart_pendulum,
                             "cart and two bars (frames)"),
    "rolling_disc": (HERE / "rolling_disc.yaml", rolling_disc, "thin disc, `rolling`, u = q'"),
    "rolling_disc_rates": (HERE / "rolling_disc_rates.yaml", lambda: rolling_disc(True),
                           "thin disc, lean-frame rates as speeds"),
}
