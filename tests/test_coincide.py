"""Loops closed by coincidence (issue #29, item 4): the four-bar of systems/ against SymPy's KanesMethod.

``systems/four_bar_linkage.yaml`` closes its loop with ``coincide:
[coupler_end, rocker_end]``; gacli forms the loop's holonomic constraints
itself. The reference is SymPy's four-bar written here from its
definition (configuration constraints of the loop, dependent speeds), and
both give the same crank acceleration and dependent rates at states on the
loop; plus the located errors of a coincidence that cannot constrain.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp
import sympy.physics.mechanics as me
from scipy.optimize import fsolve

from gacli.algebra import symbols as S
from gacli.errors import SystemFileError
from gacli.loader.loading import load, loads
from gacli.mechanics.equations import derive
from gacli.numeric import Program as Evaluator
from gacli.numeric.parameters import parameter_values

FILE = Path(__file__).resolve().parent.parent / "systems" / "four_bar_linkage.yaml"
VALUES = {"l0": 1.0, "l1": 0.3, "l2": 1.0, "l3": 0.8, "m1": 1.0, "m2": 2.0, "m3": 1.5, "g": 9.81}


def _kane():
    """The four-bar by Kane's method: bars as rigid bodies, the loop as configuration constraints."""
    q = me.dynamicsymbols("th1 th2 th3")
    u = me.dynamicsymbols("u1:4")
    l0, l1, l2, l3, m1, m2, m3, g = sp.symbols("l0 l1 l2 l3 m1 m2 m3 g")
    N = me.ReferenceFrame("N")
    A = [N.orientnew(f"A{i}", "Axis", [qi, N.z]) for i, qi in enumerate(q)]
    for frame, ui in zip(A, u):
        frame.set_ang_vel(N, ui * N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    D = O.locatenew("D", l0 * N.x)
    D.set_vel(N, 0)
    B = O.locatenew("B", l1 * A[0].x)
    B.v2pt_theory(O, N, A[0])
    centres = [O.locatenew("G1", l1 / 2 * A[0].x), B.locatenew("G2", l2 / 2 * A[1].x),
               D.locatenew("G3", l3 / 2 * A[2].x)]
    for G, origin, frame in zip(centres, (O, B, D), A):
        G.v2pt_theory(origin, N, frame)
    loop = (B.pos_from(O) + l2 * A[1].x) - (D.pos_from(O) + l3 * A[2].x)
    configuration = [loop.dot(N.x), loop.dot(N.y)]
    t = me.dynamicsymbols._t
    velocity = [c.diff(t).subs({qi.diff(t): ui for qi, ui in zip(q, u)}) for c in configuration]
    bodies = [me.RigidBody(f"b{i}", G, frame, m, (me.inertia(frame, 0, m * L ** 2 / 12, m * L ** 2 / 12), G))
              for i, (G, frame, m, L) in enumerate(zip(centres, A, (m1, m2, m3), (l1, l2, l3)))]
    loads_ = [(G, -m * g * N.y) for G, m in zip(centres, (m1, m2, m3))]
    kane = me.KanesMethod(N, q_ind=[q[0]], q_dependent=q[1:], u_ind=[u[0]], u_dependent=u[1:],
                          kd_eqs=[qi.diff(t) - ui for qi, ui in zip(q, u)],
                          configuration_constraints=configuration, velocity_constraints=velocity)
    kane.kanes_equations(bodies, loads_)
    return kane, q, u, configuration, velocity


def _on_the_loop(configuration, q, values, th1: float) -> list[float]:
    loop = sp.lambdify(q[1:], [c.subs(values).subs(q[0], th1) for c in configuration])
    return [th1, *fsolve(lambda x: loop(*x), [0.9, 1.7], xtol=1e-14)]


def test_the_coincident_four_bar_agrees_with_kane():
    kane, q, u, configuration, velocity = _kane()
    values = {sp.Symbol(k): v for k, v in VALUES.items()}
    d = derive(load(FILE))
    ours = Evaluator([*d.mass_matrix, *d.forcing, *(e for _, e in d.kinematic_equations)])
    rng = np.random.default_rng(29)
    for _ in range(3):
        angles = _on_the_loop(configuration, q, values, rng.uniform(-0.5, 0.5))
        speed = rng.uniform(-1, 1)
        at_q = {**values, **dict(zip(q, angles))}
        A = sp.Matrix(velocity).jacobian(u).subs(at_q)
        dependent = A[:, 1:].solve(-A[:, 0] * speed)
        at = {**at_q, u[0]: speed, u[1]: dependent[0], u[2]: dependent[1]}
        udot = np.array(kane.mass_matrix.subs(at).evalf(), dtype=float)
        udot = np.linalg.solve(udot, np.array(kane.forcing.subs(at).evalf(), dtype=float).ravel())
        state = {S.value(k): v for k, v in VALUES.items()}
        state.update({S.value(n): a for n, a in zip(("th1", "th2", "th3"), angles)})
        state[S.rate("th1")] = speed
        state[S.T] = 0.0
        M, F, *rates = np.real(np.array(ours(state)))
        assert abs(F / M - udot[0]) < 1e-9 * max(1.0, abs(udot[0]))
        assert np.allclose(rates[1:], [float(x) for x in dependent], rtol=1e-10, atol=1e-12)


TEXT = FILE.read_text(encoding="utf-8")


@pytest.mark.parametrize("old, new, message", [
    ("coincide: [coupler_end, rocker_end]", "coincide: [coupler_end, coupler_end]", "constrains nothing"),
    ("coincide: [coupler_end, rocker_end]", "coincide: [coupler_end, rocker_ed]", "rocker_ed"),
    ("coincide: [coupler_end, rocker_end]", "coincide: [coupler_end]", "expected two point names"),
    ("coincide: [coupler_end, rocker_end]", "{coincide: [coupler_end, rocker_end], along: [1, 0, 0]}",
     "'coincide': [A, B] alone"),
])
def test_a_coincidence_that_cannot_constrain_is_a_located_error(old, new, message):
    assert old in TEXT
    with pytest.raises(SystemFileError) as caught:
        loads(TEXT.replace(old, new))
    assert message in str(caught.value) and caught.value.diagnostics[0].location.line > 1


def test_the_loop_gives_two_constraints_and_one_degree_of_freedom():
    system = load(FILE)
    assert [c.text for c in system.constraints] == [
        "coupler_end and rocker_end coincide along N's x axis", "coupler_end and rocker_end coincide along N's y axis"]
    assert parameter_values(system)[0] and derive(system).k == 1
