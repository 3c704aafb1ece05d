"""A wheel with a round tyre rolling on a plane (`rolling: tube`): a torus.

The torus's reference is a KanesMethod model written here: the hub at
R L.z + ρ N.z above the contact (L the leaned frame, its z axis in the
wheel's plane), the material point's velocity v_G + ω × (P − G) zero. gacli
forms its rows from the torus's closed form and places the wheel from its
contact point. The bicycle with round tyres (systems/toroidal_bicycle.yaml)
must give the benchmark's linearized eigenvalues (Meijaard et al. 2007, as in
tests/test_bicycle.py) when the tyres go to zero, and approach them as they do.
"""

from __future__ import annotations

import sys

import numpy as np
import pytest
import sympy as sp
from sympy.physics import mechanics as me

from conftest import ROOT

for _path in (ROOT / "benchmarks" / "kane_set", ROOT / "benchmarks"):
    if str(_path) not in sys.path:
        sys.path.insert(0, str(_path))

import gacli  # noqa: E402

TOLERANCE = 1e-10

WHEEL = """
gacli: 1
name: toroidal_wheel
parameters: [m, R, rho, A, B, g]
coordinates: [yaw, lean, spin, x, y]
independent: [yaw, lean, spin]
frames:
  heading: {rotations: [[z, yaw]]}
  leaned: {parent: heading, rotations: [[x, lean]]}
  wheel: {parent: leaned, rotations: [[y, spin]]}
bodies:
  wheel: {mass: m, frame: wheel, inertia: [A, B, A]}
rolling:
  - {body: wheel, radius: R, tube: rho, axle: [0, 1, 0], contact: {N: [x, y, 0]}}
loads:
  - {force: {N: [0, 0, -m*g]}, at: wheel}
"""


def kane_torus():
    """The torus by KanesMethod, u = q' of yaw, lean, spin; x', y' dependent."""
    from bench_kane import KaneModel
    from models import Reference

    yaw, lean, spin, x, y = q = list(me.dynamicsymbols("yaw lean spin x y"))
    u = list(me.dynamicsymbols("u1:6"))
    P = {s.name: s for s in sp.symbols("m R rho A B g")}
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    D = L.orientnew("D", "Axis", [spin, L.y])
    t = me.dynamicsymbols._t
    D.set_ang_vel(N, u[0] * N.z + u[1] * _x(N, yaw) + u[2] * L.y)
    kd = [qi.diff(t) - ui for qi, ui in zip(q, u)]
    rates = sp.solve(kd, [qi.diff(t) for qi in q], dict=True)[0]
    O = me.Point("O")
    O.set_vel(N, 0)
    contact = O.locatenew("C", x * N.x + y * N.y)
    contact.set_vel(N, u[3] * N.x + u[4] * N.y)
    hub = contact.locatenew("G", P["R"] * L.z + P["rho"] * N.z)
    hub.set_vel(N, contact.vel(N) + hub.pos_from(contact).dt(N).subs(rates))
    material = hub.vel(N) + D.ang_vel_in(N).cross(contact.pos_from(hub))
    constraints = [material.dot(N.x), material.dot(N.y)]
    body = me.RigidBody("wheel", hub, D, P["m"], (me.inertia(D, P["A"], P["B"], P["A"]), hub))
    kane = me.KanesMethod(N, q_ind=q, u_ind=u[:3], u_dependent=u[3:], kd_eqs=kd,
                          velocity_constraints=constraints)
    kane.kanes_equations([body], [(hub, -P["m"] * P["g"] * N.z)])
    return Reference(KaneModel(kane, q, u[:3], u[3:], P, constraints), {qi: qi.func.__name__ for qi in q},
                     spread=1.0)


def _x(N, yaw):
    """The heading frame's x axis, about which the wheel leans."""
    return sp.cos(yaw) * N.x + sp.sin(yaw) * N.y


def test_torus_agrees_with_kanes_method(rng):
    from bench_kane_set import GacliSide, KaneSide, compare, random_state

    reference = kane_torus()
    kane = KaneSide(reference)
    derivation = gacli.derive(gacli.loads(WHEEL))
    ours = GacliSide(derivation, derivation.kinematic_equations, derivation.mass_matrix.todok(),
                     list(derivation.forcing))
    for _ in range(3):
        values = random_state(derivation, reference, rng)
        # A tube smaller than the wheel, as the loader requires of values it knows.
        values["parameters"]["rho"] = 0.3 * values["parameters"]["R"]
        values = random_state_with(derivation, values)
        assert compare(ours.evaluate(values), kane.evaluate(values)) < TOLERANCE


def test_the_program_agrees_with_kanes_method(rng):
    from bench_kane_set import KaneSide, compare, random_state
    from test_rolling_ellipsoid import program_side

    reference = kane_torus()
    kane = KaneSide(reference)
    derivation, ours = program_side(WHEEL)
    for _ in range(3):
        values = random_state(derivation, reference, rng)
        values["parameters"]["rho"] = 0.3 * values["parameters"]["R"]
        values = random_state_with(derivation, values)
        assert compare(ours.evaluate(values), kane.evaluate(values)) < TOLERANCE


def random_state_with(derivation, values):
    """``values`` with gacli's symbols refreshed from the (edited) names."""
    from gacli.algebra import symbols as S

    values["gacli"].update({S.value(n): v for n, v in values["parameters"].items()})
    return values


# -- the bicycle with round tyres ---------------------------------------------------------

BIKE_STATES = ["roll", "steer", "dot(roll)", "dot(steer)"]
SPEEDS = np.arange(0.0, 10.01, 1.0)


@pytest.fixture(scope="module")
def bike():
    from gacli.linearize import linearizer

    return linearizer(gacli.derive(gacli.load(ROOT / "systems" / "toroidal_bicycle.yaml")))


def _eigenvalue_gap(bike, tyre: float) -> float:
    """The largest distance of the linearized eigenvalues from the benchmark's over the speeds."""
    from test_bicycle import REAR_RADIUS, reference, sorted_eigenvalues

    gap = 0.0
    for v in SPEEDS:
        # Upright, the tyred wheel touches W below its hub: forward speed v is a wheel rate v / W.
        A = bike({"dot(wheel_R)": v / REAR_RADIUS}, {"tyreR": tyre, "tyreF": tyre}).block(BIKE_STATES)
        gap = max(gap, float(np.max(np.abs(sorted_eigenvalues(A) - sorted_eigenvalues(reference(v))))))
    return gap


def test_without_tyres_the_eigenvalues_are_the_benchmarks(bike):
    assert _eigenvalue_gap(bike, 0.0) < 1e-9


def test_as_the_tyres_shrink_the_eigenvalues_approach_the_benchmarks(bike):
    gaps = [_eigenvalue_gap(bike, tyre) for tyre in (1e-2, 1e-3, 1e-4)]
    assert gaps[0] > 1e-2  # a 1 cm tyre changes the bicycle's modes: the tube enters the rows
    # About first order in the tube radius (less near the weave speed, where two eigenvalues meet
    # and move as a square root): a tenth of the tyre, about a tenth of the change.
    for larger, smaller in zip(gaps, gaps[1:]):
        assert 0 < smaller < larger / 5


def test_the_rolling_torus_keeps_its_energy():
    pytest.importorskip("scipy")
    from gacli.simulate import simulate, spec_from_options

    spec = spec_from_options(set=["m=2,R=0.3,rho=0.05,A=0.05,B=0.09,g=9.81"],
                             init=["lean=0.3,dot(yaw)=1,dot(lean)=0.2,dot(spin)=8"], t_end=3,
                             rtol=1e-10, atol=1e-12)
    sim = simulate(gacli.derive(gacli.loads(WHEEL)), spec)
    assert sim.not_conservative == ()
    assert abs(sim.energy_relative_drift) < 1e-7
    # It rolls: the contact has moved, and the lean has changed.
    assert np.hypot(*sim.states[-1, 3:5] - sim.states[0, 3:5]) > 0.1
