"""Rolling on a plane given by a frame (tilted, translating, turning) and with an offset centre (#19).

Each system is checked against an independent reference written here:
SymPy's KanesMethod with the no-slip conditions stated from scratch (the
material point at the contact moves with the surface point there), or a
conservation law integrated by gacli's simulator and evaluated here by hand.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
import sympy.physics.mechanics as me

from conftest import derived
from gacli.mechanics.equations import derive
from gacli.loader.loading import loads
from test_frames import close, gacli_accelerations, kane_accelerations

T = me.dynamicsymbols._t


def kane_ball_on_plane(plane_of, origin_of, offset: bool = False, moments=None, gravity: bool = True):
    """KanesMethod for a ball on a moving plane, in the coordinates of the systems here.

    The plane frame P is ``plane_of(N)`` with origin ``origin_of(N)`` (functions of t);
    the ball's axes are ZXZ angles (phi, theta, psi) from P; (x, y) place the geometric
    centre C on the plane, C = O + x P.x + y P.y + r P.z; the centre of mass is
    G = C − e B.z (``offset``); inertia diag(A, B, C) (or ``moments``) about G in the
    ball's axes. Returns Kane's equations and the two no-slip rows, linear in the speeds.
    """
    x, y, phi, theta, psi = me.dynamicsymbols("x y phi theta psi")
    q = (phi, theta, psi, x, y)
    u = me.dynamicsymbols("u1:6")                     # the Euler rates, then dx, dy
    m, r, g, e = sp.symbols("m r g e")
    moments = moments or sp.symbols("A B C")
    N = me.ReferenceFrame("N")
    P = plane_of(N)
    Ball = P.orientnew("Ball", "Body", [phi, theta, psi], "ZXZ")
    to_u = {qi.diff(T): ui for qi, ui in zip(q, u)}
    O_pos = origin_of(N)
    C_pos = O_pos + x * P.x + y * P.y + r * P.z
    G_pos = C_pos - (e if offset else 0) * Ball.z
    G = me.Point("G")
    G.set_vel(N, G_pos.dt(N).subs(to_u))
    omega = Ball.ang_vel_in(N).subs(to_u)
    Ball.set_ang_vel(N, omega)
    contact = C_pos - r * P.z
    v_body = G.vel(N) + omega.cross(contact - G_pos)            # the ball's material point at the contact
    v_surface = O_pos.dt(N) + P.ang_vel_in(N).cross(contact - O_pos)   # the plane's point there
    slip = v_body - v_surface.subs(to_u)
    constraints = [slip.dot(P.x), slip.dot(P.y)]
    ball = me.RigidBody("ball", G, Ball, m, (me.inertia(Ball, *moments), G))
    kd = [qi.diff(T) - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=u[:3], u_dependent=u[3:],
                          velocity_constraints=constraints, kd_eqs=kd)
    kane.kanes_equations([ball], [(G, -m * g * N.z)] if gravity else [])
    return kane, q, u, constraints


def random_state(rng, **fixed) -> dict[str, float]:
    v = {"x": rng.uniform(-1, 1), "y": rng.uniform(-1, 1), "phi": rng.uniform(-3, 3),
         "theta": rng.uniform(0.3, 2.8), "psi": rng.uniform(-3, 3), "t": rng.uniform(0, 3),
         "m": rng.uniform(0.5, 2), "r": rng.uniform(0.1, 1), "g": 9.81, "e": rng.uniform(0.01, 0.3),
         "A": rng.uniform(0.2, 1), "B": rng.uniform(0.2, 1), "C": rng.uniform(0.2, 1)}
    v.update(fixed)
    v.update({f"dot({n})": w for n, w in zip(("phi", "theta", "psi"), rng.uniform(-2, 2, 3))})
    return v


def kane_point(kane, q, u, constraints, v: dict[str, float]) -> dict:
    """Kane's arguments at the state ``v``: the dependent speeds from the no-slip rows."""
    symbols = set().union(*(c.free_symbols for c in constraints), kane.mass_matrix.free_symbols,
                          kane.forcing.free_symbols)
    # The functions of t first, then t itself (else u4(t) becomes u4(0.7)).
    point = {qi: v[qi.name] for qi in q}
    point.update({ui: v[f"dot({n})"] for ui, n in zip(u[:3], ("phi", "theta", "psi"))})
    constants = {s: v[s.name] for s in symbols if isinstance(s, sp.Symbol)}
    dependent = sp.symbols("dx dy")
    rows = [me.msubs(c, point, dict(zip(u[3:], dependent))).xreplace(constants) for c in constraints]
    solution = sp.solve(rows, dependent)
    point.update({ui: solution[s] for ui, s in zip(u[3:], dependent)})
    return point, constants


def kane_udot(kane, point) -> np.ndarray:
    point, constants = point
    M, F = (np.array(me.msubs(X, point).xreplace(constants).evalf(30).tolist(), dtype=float)
            for X in (kane.mass_matrix, kane.forcing))
    return np.linalg.solve(M, F.ravel())


def assert_agrees(d, kane, q, u, constraints, rng, count: int = 8, **fixed) -> None:
    for _ in range(count):
        v = random_state(rng, **fixed)
        assert close(gacli_accelerations(d, v), kane_udot(kane, kane_point(kane, q, u, constraints, v)))


# -- the plane tilted and shaken along its slope -----------------------------------

def test_sphere_on_a_tilted_translating_plane_against_kane(rng):
    d = derived("sphere_on_tilted_plane")
    assert d.independent == ("phi", "theta", "psi")
    alpha, amplitude, w, m, r = sp.symbols("alpha A w m r")
    tilted = lambda N: N.orientnew("P", "Axis", [alpha, N.y])
    slide = lambda N: amplitude * sp.sin(w * T) * tilted(N).x
    sphere = (sp.Rational(2, 5) * m * r**2,) * 3
    kane, q, u, rows = kane_ball_on_plane(tilted, slide, moments=sphere)
    for _ in range(3):
        fixed = {"alpha": rng.uniform(-1, 1), "A": rng.uniform(0, 0.5), "w": rng.uniform(1, 8)}
        assert_agrees(d, kane, q, u, rows, rng, count=4, **fixed)


def test_on_the_tilted_plane_at_rest_the_centre_runs_down_at_five_sevenths_g_sin_alpha():
    from gacli.simulate import simulate, spec_from_options

    sim = simulate(derived("sphere_on_tilted_plane"),
                   spec_from_options(set=["A=0"], init=["theta=1"], t_end=1.0, rtol=1e-11, atol=1e-13))
    p = sim.parameters
    x = sim.column("x")
    expected = 5 / 14 * p["g"] * np.sin(p["alpha"]) * sim.t**2
    assert np.max(np.abs(x - x[0] - expected)) < 1e-9
    assert np.max(np.abs(sim.column("y") - sim.column("y")[0])) < 1e-9


# -- a plane turning about moving axes, a ball with unequal moments and an offset centre ------

TURNING = """
gacli: 1
name: ball_on_turning_plane
parameters: [m, r, g, e, A, B, C, b, c, w, a0, h]
functions:
  tilt: {value: "b*sin(w*t)"}
coordinates: [x, y, phi, theta, psi]
independent: [phi, theta, psi]
frames:
  swing: {rotations: [[y, tilt], [x, c*t]], origin: O}
  ball: {parent: swing, sequence: ZXZ, angles: [phi, theta, psi]}
points:
  O: {N: [a0*sin(t), 0, h*cos(t)]}
  centre: {from: O, swing: [x, y, r]}
  mass_centre: {from: centre, ball: [0, 0, -e]}
bodies:
  ball: {mass: m, position: mass_centre, frame: ball, inertia: [A, B, C]}
rolling:
  - {body: ball, radius: r, on: swing, centre: [0, 0, e]}
loads:
  - {force: {N: [0, 0, -m*g]}, at: ball}
"""


def test_an_unbalanced_ball_on_a_plane_turning_about_moving_axes_against_kane(rng):
    d = derive(loads(TURNING))
    b, c, w, a0, h = sp.symbols("b c w a0 h")
    swing = lambda N: N.orientnew("P", "Body", [b * sp.sin(w * T), c * T, 0], "YXZ")
    origin = lambda N: a0 * sp.sin(T) * N.x + h * sp.cos(T) * N.z
    kane, q, u, rows = kane_ball_on_plane(swing, origin, offset=True)
    fixed = lambda: {"b": rng.uniform(-1, 1), "c": rng.uniform(-2, 2), "w": rng.uniform(0.5, 3),
                     "a0": rng.uniform(-1, 1), "h": rng.uniform(-1, 1)}
    for _ in range(3):
        assert_agrees(d, kane, q, u, rows, rng, count=3, **fixed())
    assert [c.text for c in d.system.constraints] == ["rolling of ball (x of swing)", "rolling of ball (y of swing)"]


# -- Routh's sphere ------------------------------------------------------------------------

def test_routh_sphere_against_kane(rng):
    d = derived("routh_sphere")
    A, C = sp.symbols("A C")
    kane, q, u, rows = kane_ball_on_plane(lambda N: N, lambda N: 0 * N.x, offset=True, moments=(A, A, C))
    assert_agrees(d, kane, q, u, rows, rng, count=12, B=None)


def test_routh_sphere_keeps_its_energy():
    from gacli.simulate import simulate, spec_from_options

    sim = simulate(derived("routh_sphere"), spec_from_options(
        init=["theta=0.8,dot(phi)=2,dot(theta)=0.5,dot(psi)=10"], t_end=3.0, rtol=1e-12, atol=1e-14))
    assert sim.energy_relative_drift < 1e-9
    assert np.ptp(sim.column("theta")) > 0.05          # it nutates: the energy is not trivially constant
    assert all(res.max_abs < 1e-8 for res in sim.residuals.values())


# -- Chaplygin's ball --------------------------------------------------------------------------

def test_chaplygin_ball_keeps_its_energy_and_its_angular_momentum_about_the_contact():
    from gacli.simulate import simulate, spec_from_options

    sim = simulate(derived("chaplygin_ball"), spec_from_options(
        init=["theta=1.1,dot(phi)=1.5,dot(theta)=-0.7,dot(psi)=4"], t_end=3.0, rtol=1e-12, atol=1e-14))
    p = sim.parameters
    phi, theta, psi = (sim.column(n) for n in ("phi", "theta", "psi"))
    dphi, dtheta, dpsi = (sim.column(f"dot({n})") for n in ("phi", "theta", "psi"))
    # ω in N from the Euler rates: about N's z, the line of nodes, and the body's z axis.
    nodes = np.stack([np.cos(phi), np.sin(phi), 0 * phi], axis=1)
    axis = np.stack([np.sin(theta) * np.sin(phi), -np.sin(theta) * np.cos(phi), np.cos(theta)], axis=1)
    omega = dphi[:, None] * np.array([0, 0, 1]) + dtheta[:, None] * nodes + dpsi[:, None] * axis
    up = np.array([0, 0, p["r"]])                       # from the contact to the centre
    velocity = np.cross(omega, up)                      # no slip: the contact point is at rest
    for k, name in enumerate("xy"):                     # and the simulated centre moves so
        assert np.max(np.abs(np.gradient(sim.column(name), sim.t, edge_order=2) - velocity[:, k])) < 1e-4
    momentum = np.empty_like(omega)
    energy = np.empty(len(phi))
    for i in range(len(phi)):
        R = zxz(phi[i], theta[i], psi[i])
        inertia = R @ np.diag([p["A"], p["B"], p["C"]]) @ R.T
        momentum[i] = inertia @ omega[i] + p["m"] * np.cross(up, velocity[i])
        energy[i] = 0.5 * omega[i] @ inertia @ omega[i] + 0.5 * p["m"] * velocity[i] @ velocity[i]
    assert np.allclose(R[:, 2], axis[-1])
    assert np.max(np.abs(momentum - momentum[0])) < 1e-9 * np.linalg.norm(momentum[0])
    assert np.max(np.abs(energy - energy[0])) < 1e-9 * energy[0]
    assert sim.energy_relative_drift < 1e-9
    assert np.ptp(theta) > 0.05 and np.ptp(omega[:, 0]) > 0.1    # the motion is not a steady one


def zxz(phi: float, theta: float, psi: float) -> np.ndarray:
    def turn(axis: int, angle: float) -> np.ndarray:
        c, s = np.cos(angle), np.sin(angle)
        i, j = [k for k in range(3) if k != axis]
        R = np.eye(3)
        R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
        return R
    return turn(2, phi) @ turn(0, theta) @ turn(2, psi)


# -- a wheel on an incline -------------------------------------------------------------------

DISK_ON_INCLINE = """
gacli: 1
name: disk_on_incline
parameters: [m, r, g, alpha]
coordinates: [x, y, yaw, lean, spin]
independent: [yaw, lean, spin]
frames:
  plane: {rotations: [[y, alpha]]}
  heading: {parent: plane, rotations: [[z, yaw]]}
  leaned: {parent: heading, rotations: [[x, lean]]}
  disk: {parent: leaned, rotations: [[y, spin]]}
points:
  contact: {plane: [x, y, 0]}
  centre: {from: contact, leaned: [0, 0, r]}
bodies:
  disk: {mass: m, position: centre, frame: disk, inertia: [m*r**2/4, m*r**2/2, m*r**2/4]}
rolling:
  - {body: disk, radius: r, axle: [0, 1, 0], on: plane}
loads:
  - {force: {N: [0, 0, -m*g]}, at: disk}
"""


def test_a_disk_rolling_on_an_incline_against_kane(rng):
    d = derive(loads(DISK_ON_INCLINE))
    assert [c.text for c in d.system.constraints] == ["rolling of disk (forward)", "rolling of disk (sideways)"]
    yaw, lean, spin = q = me.dynamicsymbols("yaw lean spin")
    u = me.dynamicsymbols("u1:4")
    m, r, g, alpha = sp.symbols("m r g alpha")
    N = me.ReferenceFrame("N")
    P = N.orientnew("P", "Axis", [alpha, N.y])
    Y = P.orientnew("Y", "Axis", [yaw, P.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    R = L.orientnew("R", "Axis", [spin, L.y])
    C = me.Point("C")
    C.set_vel(N, 0)                      # the material point at the contact: the incline is at rest
    D = C.locatenew("D", r * L.z)
    D.v2pt_theory(C, N, R)
    disk = me.RigidBody("disk", D, R, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), D))
    kane = me.KanesMethod(N, q_ind=list(q), u_ind=list(u), kd_eqs=[qi.diff(T) - ui for qi, ui in zip(q, u)])
    kane.kanes_equations([disk], [(D, -m * g * N.z)])
    for _ in range(12):
        v = {"x": rng.uniform(-1, 1), "y": rng.uniform(-1, 1), "yaw": rng.uniform(-3, 3),
             "lean": rng.uniform(-1.2, 1.2), "spin": rng.uniform(-3, 3), "m": rng.uniform(0.5, 2),
             "r": rng.uniform(0.2, 1), "g": 9.81, "alpha": rng.uniform(-1, 1)}
        rates = rng.uniform(-2, 2, 3)
        v.update({f"dot({n})": w for n, w in zip(("yaw", "lean", "spin"), rates)})
        point = {**{qi: v[qi.name] for qi in q}, **dict(zip(u, rates)), m: v["m"], r: v["r"], g: 9.81,
                 alpha: v["alpha"]}
        assert close(gacli_accelerations(d, v), kane_accelerations(kane, point))


def test_a_child_frame_without_an_origin_has_its_parents(rng):
    # Rolling on a frame turned about the plane's normal, declared without an origin, is
    # rolling on the same moving plane: the same motion, rows along other axes.
    from conftest import SYSTEMS

    text = (SYSTEMS / "sphere_on_tilted_plane.yaml").read_text(encoding="utf-8")
    turned = text.replace("  ball: {parent: plane,", "  turned: {parent: plane, rotations: [[z, 0.4]]}\n"
                          "  ball: {parent: plane,").replace("on: plane}", "on: turned}")
    assert turned.count("turned") == 2
    d, e = derived("sphere_on_tilted_plane"), derive(loads(turned))
    for _ in range(5):
        v = random_state(rng, alpha=rng.uniform(-1, 1), A=rng.uniform(0, 0.5), w=rng.uniform(1, 8))
        assert close(gacli_accelerations(e, v), gacli_accelerations(d, v))


# -- a wheel on a tilted, shaken plane -----------------------------------------------------------
# The same wheel twice: on a plane tilted by alpha and shaken along its own x axis
# (the path for a plane whose normal is not N's z), and on a level plane shaken the
# same way under gravity tilted by alpha (the level path, with a moving origin).
# A constant tilt of the whole scene changes nothing, so M, F and the kinematic
# equations in the same coordinates must be equal.

WHEEL_ON_INCLINE = """\
gacli: 1
name: disk_on_shaken_incline
parameters:
  m: {value: 2}
  r: {value: 0.3}
  g: {value: 9.81}
  alpha: {value: 0.3}
  A: {value: 0.05}
  w: {value: 6}
functions:
  s: {value: "A*sin(w*t)"}
coordinates: [x, y, yaw, lean, spin]
independent: [yaw, lean, spin]
frames:
  tilted: {rotations: [[y, alpha]]}
  plane: {parent: tilted, origin: slide}
  heading: {parent: plane, rotations: [[z, yaw]]}
  leaned: {parent: heading, rotations: [[x, lean]]}
  disk: {parent: leaned, rotations: [[y, spin]]}
points:
  slide: {tilted: [s, 0, 0]}
  contact: {from: slide, plane: [x, y, 0]}
  centre: {from: contact, leaned: [0, 0, r]}
bodies:
  disk: {mass: m, position: centre, frame: disk, inertia: [m*r**2/4, m*r**2/2, m*r**2/4]}
rolling:
  - {body: disk, radius: r, axle: [0, 1, 0], on: plane}
loads:
  - {force: {N: [0, 0, -m*g]}, at: disk}"""

# The same file with the tilt moved from the plane into gravity: only these lines differ.
WHEEL_UNDER_TILTED_GRAVITY = (
    WHEEL_ON_INCLINE.replace("name: disk_on_shaken_incline", "name: disk_on_shaken_plane_tilted_gravity")
    .replace("  tilted: {rotations: [[y, alpha]]}\n  plane: {parent: tilted, origin: slide}",
             "  plane: {origin: slide}")
    .replace("slide: {tilted: [s, 0, 0]}", "slide: {N: [s, 0, 0]}")
    .replace("{N: [0, 0, -m*g]}", "{N: [m*g*sin(alpha), 0, -m*g*cos(alpha)]}"))


def test_a_wheel_on_a_tilted_shaken_plane_is_the_level_wheel_under_tilted_gravity(rng):
    assert WHEEL_UNDER_TILTED_GRAVITY.count("alpha") == WHEEL_ON_INCLINE.count("alpha") + 1  # every replacement took
    tilted, level = derive(loads(WHEEL_ON_INCLINE)), derive(loads(WHEEL_UNDER_TILTED_GRAVITY))
    exprs = [*tilted.mass_matrix, *tilted.forcing, *level.mass_matrix, *level.forcing,
             *(e for _, e in tilted.kinematic_equations), *(e for _, e in level.kinematic_equations)]
    symbols = sorted(set().union(*(e.free_symbols for e in exprs)), key=lambda s: s.name)
    assert any(s.name == "alpha" for s in symbols)
    for _ in range(4):
        values = {s: sp.Float(rng.uniform(0.2, 1.1), 30) for s in symbols}
        for a, b in [(tilted.mass_matrix, level.mass_matrix), (tilted.forcing, level.forcing),
                     (sp.Matrix([e for _, e in tilted.kinematic_equations]),
                      sp.Matrix([e for _, e in level.kinematic_equations]))]:
            A = np.array(a.xreplace(values).evalf(), dtype=float)
            B = np.array(b.xreplace(values).evalf(), dtype=float)
            assert np.max(np.abs(A - B)) <= 1e-12 * max(1.0, np.max(np.abs(B)))
