"""Frobenius classification: holonomic constraints and quasi-coordinates that are coordinates."""

from __future__ import annotations

import signal
import time

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from gacli.check.integrability import classify
from gacli.numeric import UndefinedValue, evaluate
from gacli.numeric.zero import SIMPLIFY_MAX_OPS, Decision, decide_zero, time_limit
from gacli.loader.loading import load, loads

from conftest import SYSTEMS


def verdicts(system) -> dict[str, str]:
    return {c.where: c.verdict for c in classify(system)}


def system(constraints=(), quasi=None, extra="") -> object:
    quasi_text = "{" + ", ".join(f"{k}: '{v}'" for k, v in (quasi or {}).items()) + "}"
    return loads(f"""
gacli: 1
name: forms
parameters: [m, a]
functions: {{Omega: angular rate, w: {{value: a*t}}}}
coordinates: [x, y, z]
quasi_coordinates: {quasi_text}
constraints: [{", ".join(repr(c) for c in constraints)}]
bodies: {{p: {{mass: m, position: [x, y, z]}}}}
{extra}
""")


# -- the shipped systems ---------------------------------------------------------------------

def test_the_rolling_sphere_constraints_are_not_integrable():
    found = classify(load(SYSTEMS / "sphere_on_turntable.yaml"))
    assert [(c.where, c.kind, c.verdict) for c in found] == [
        ("constraints[0]", "constraint", "non-holonomic"),
        ("constraints[1]", "constraint", "non-holonomic"),
    ]
    assert found[0].text == "dx - a*dq_y = -Omega*y*dt"
    lines = (SYSTEMS / "sphere_on_turntable.yaml").read_text(encoding="utf-8").splitlines()
    assert found[0].text in lines[found[0].location.line - 1]


def test_the_rolling_cylinder_constraint_is_integrable():
    (found,) = classify(load(SYSTEMS / "cylinder_in_cylinder.yaml"))
    assert (found.where, found.integrable, found.verdict, found.method) == (
        "constraints[0]", True, "holonomic", "symbolic")


def test_the_areal_velocity_is_not_a_coordinate():
    (found,) = classify(load(SYSTEMS / "particle_in_plane.yaml"))
    assert (found.kind, found.where, found.verdict) == ("quasi_coordinate", "quasi_coordinates.q", "not a coordinate")


def test_the_spin_of_the_top_is_not_a_coordinate():
    assert verdicts(load(SYSTEMS / "spinning_top.yaml")) == {"quasi_coordinates.q": "not a coordinate"}


def test_primitive_quasi_coordinates_are_not_classified():
    assert classify(load(SYSTEMS / "rigid_body.yaml")) == ()


# -- forms written for the test ----------------------------------------------------------

@pytest.mark.parametrize("differential, verdict", [
    ("dx + dy", "a coordinate"),                    # q = x + y
    ("y*dx + x*dy", "a coordinate"),                # q = x y
    ("x*dt + t*dx", "a coordinate"),                # q = x t: t is one more variable
    ("cos(x)*dx - a*dy + Omega*dt", "a coordinate"),  # a free function of t is still exact in dt
    ("y*dx - x*dy", "not a coordinate"),
    ("w*dx", "not a coordinate"),                   # w = a*t is substituted: d(a t dx) = a dt^dx
    ("dx + dq", "a coordinate"),                    # another quasi-coordinate's differential: q2 = x + q
])
def test_quasi_coordinate(differential, verdict):
    found = verdicts(system(quasi={"q": "dz", "p": differential}))
    assert found["quasi_coordinates.p"] == verdict


@pytest.mark.parametrize("constraint, verdict", [
    ("x*dx + y*dy + z*dz = 0", "holonomic"),        # a sphere
    ("y*dx - x*dy = 0", "holonomic"),               # not closed, but 1/y**2 integrates it
    ("dz = y*dx", "non-holonomic"),                 # the standard contact form
    ("dx = t*dy", "non-holonomic"),                 # time is a variable too
    ("dx = Omega*dt", "holonomic"),                 # x = the integral of Omega
    ("dx = y*Omega*dt", "non-holonomic"),
    ("sin(w)*dx = cos(w)*dy", "non-holonomic"),     # a knife edge turned at the rate a
    ("sin(a)*dx = cos(a)*dy", "holonomic"),         # ... and one held at a fixed angle
    ("x**2 + y**2 = a**2", "holonomic"),            # a relation f(q, t) = 0
])
def test_constraint(constraint, verdict):
    found = classify(system([constraint]))[0]
    assert found.verdict == verdict
    if "d" not in constraint.replace("dot", ""):
        assert found.method == "relation"


def exact_forms():
    """df for small polynomials f(x, y, t): always closed; g df is always integrable."""
    x, y, t = (sp.Symbol(n, real=True) for n in "xyt")
    monomial = st.tuples(st.integers(-3, 3), st.integers(0, 2), st.integers(0, 2), st.integers(0, 2))
    return st.lists(monomial, min_size=1, max_size=4).map(
        lambda terms: sum(c * x**i * y**j * t**k for c, i, j, k in terms))


def form_text(f, factor=1) -> str:
    x, y, t = (sp.Symbol(n, real=True) for n in "xyt")
    parts = [f"({sp.sstr(factor * sp.diff(f, v))})*d{v.name}" for v in (x, y, t)]
    return " + ".join(parts)


@settings(max_examples=15, deadline=None, derandomize=True)
@given(f=exact_forms(), g=exact_forms())
def test_exact_forms_are_closed_and_their_multiples_integrable(f, g):
    if sp.diff(f, sp.Symbol("x", real=True)) == 0 and sp.diff(f, sp.Symbol("y", real=True)) == 0:
        return  # no dx or dy term: not a form over the coordinates
    s = system([form_text(f, 1 + g**2) + " = 0"], {"q": form_text(f)})
    assert verdicts(s) == {"constraints[0]": "holonomic", "quasi_coordinates.q": "a coordinate"}


# -- deciding zero ---------------------------------------------------------------------------

x, y = sp.symbols("x y", real=True)


def test_zero_by_simplify():
    assert decide_zero(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1) == Decision(True, "symbolic")
    assert decide_zero(sp.Integer(3)) == Decision(False, "symbolic")


def test_zero_by_points_when_too_big_to_simplify():
    big = sum(sp.sin(k * x + y) ** 2 + sp.cos(k * x + y) ** 2 for k in range(40)) - 40
    assert sp.count_ops(big) > SIMPLIFY_MAX_OPS
    assert decide_zero(big) == Decision(True, "numeric")
    assert decide_zero(big + sp.exp(-x) / 1000) == Decision(False, "numeric")


def test_abs_is_not_mistaken_for_the_identity():
    assert decide_zero(sp.Abs(x) - x).zero is False


def test_undecided_when_nothing_can_be_evaluated():
    assert decide_zero(sp.sqrt(-1 - x**2) * y).zero is None


def test_evaluation_refuses_huge_values_at_once():
    start = time.perf_counter()
    for expr in (sp.exp(sp.exp(sp.exp(100))) * x, sp.exp(sp.exp(sp.exp(sp.exp(x)))), x ** (10**50)):
        with pytest.raises(UndefinedValue):
            evaluate(expr, {x: 1.5})
    assert time.perf_counter() - start < 5


def test_a_slow_simplify_falls_back_to_points():
    omega = sp.Symbol("Omega", real=True)
    nasty = sp.atan2(sp.atan2(sp.atan2(omega, x), sp.pi - y), sp.sign(sp.Integer(10) ** 300 - sp.log(omega)))
    start = time.perf_counter()
    decide_zero(sp.diff(nasty, y) * x - y)
    assert time.perf_counter() - start < 30  # simplify alone runs for minutes


# -- nested time limits ----------------------------------------------------------------------------

class Outer(Exception):
    pass


class Inner(Exception):
    pass


def spin(seconds: float) -> None:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        pass


def test_an_inner_limit_fires_and_the_outer_one_survives():
    with pytest.raises(Outer):
        with time_limit(1.0, Outer) as armed:
            assert armed
            with pytest.raises(Inner):
                with time_limit(0.05, Inner):
                    spin(5)
            spin(5)


def test_an_outer_limit_that_ends_first_is_left_to_fire():
    with pytest.raises(Outer):
        with time_limit(0.1, Outer):
            with time_limit(5, Inner) as armed:
                assert not armed
                spin(5)
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)


def test_no_limit_means_no_alarm():
    with time_limit(0, Inner) as armed:
        assert not armed
        assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)


# -- primitive quasi-coordinates: the rotation group's structure (Maurer-Cartan) ---------------

phi, theta, psi = sp.symbols("phi theta psi", real=True)
ANGLES = (phi, theta, psi)


def zxz() -> sp.Matrix:
    """R = Rz(phi) Rx(theta) Rz(psi): body axes to inertial axes."""
    def rz(a):
        return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])
    rx = sp.Matrix([[1, 0, 0], [0, sp.cos(theta), -sp.sin(theta)], [0, sp.sin(theta), sp.cos(theta)]])
    return rz(phi) * rx * rz(psi)


def angular_forms(inertial: bool) -> list[list[sp.Expr]]:
    """The components of ω dt as coefficient rows on (dphi, dtheta, dpsi), from R alone.

    Body axes: Ω̂ = Rᵀ dR; inertial axes: ω̂ = dR Rᵀ (hat(w) has w_1 at [2, 1]).
    """
    r = zxz()
    rows = [[], [], []]
    for angle in ANGLES:
        dr = r.diff(angle)
        hat = sp.simplify(dr * r.T if inertial else r.T * dr)
        for i, (p, q) in enumerate([(2, 1), (0, 2), (1, 0)]):
            rows[i].append(hat[p, q])
    return rows


def d_form(row):
    """dα as {(i, j): c_ij}, i < j over the angles."""
    return {(i, j): sp.diff(row[j], ANGLES[i]) - sp.diff(row[i], ANGLES[j])
            for i in range(3) for j in range(i + 1, 3)}


def wedge(a, b):
    return {(i, j): a[i] * b[j] - a[j] * b[i] for i in range(3) for j in range(i + 1, 3)}


@pytest.mark.parametrize("inertial, sign", [(False, -1), (True, 1)])
def test_maurer_cartan_sign_from_euler_angles(inertial, sign):
    """dΩ_1 = −Ω_2 ∧ Ω_3 (cyclic) along body axes, and + along inertial ones: gacli/check/exterior.py's σ."""
    w = angular_forms(inertial)
    for i in range(3):
        left, right = d_form(w[i]), wedge(w[(i + 1) % 3], w[(i + 2) % 3])
        for key in left:
            assert sp.simplify(left[key] - sign * right[key]) == 0
            assert sp.simplify(left[key] + sign * right[key]) != 0 or right[key] == 0


def test_the_euler_body_forms_match_the_spec_and_the_top():
    """The hand-written forms of docs/system-file.md are the body-axis ones above."""
    w = angular_forms(inertial=False)
    written = [[sp.sin(theta) * sp.sin(psi), sp.cos(psi), 0],
               [sp.sin(theta) * sp.cos(psi), -sp.sin(psi), 0],
               [sp.cos(theta), 0, 1]]
    assert all(sp.simplify(w[i][j] - written[i][j]) == 0 for i in range(3) for j in range(3))


def euler_system(inertial: bool, inertia: str = "[A, B, C]") -> object:
    """A body with primitive rotation [dq_1, dq_2, dq_3] tied to Euler angles by three constraints."""
    w = angular_forms(inertial)
    lines = [" + ".join(f"({sp.sstr(c)})*d{a.name}" for c, a in zip(row, ANGLES)) for row in w]
    constraints = ", ".join(f"'dq_{i + 1} = {line}'" for i, line in enumerate(lines))
    return loads(f"""
gacli: 1
name: euler
parameters: [m, A, B, C]
coordinates: [phi, theta, psi]
quasi_coordinates: [q_1, q_2, q_3]
constraints: [{constraints}]
bodies:
  b: {{mass: m, position: [0, 0, 0], inertia: {inertia}, rotation: [dq_1, dq_2, dq_3]}}
""")


def test_primitive_rotation_tied_to_body_axis_euler_forms_is_holonomic():
    # R(angles) is a map: q = the body's orientation is a function of the angles, so the set integrates.
    found = classify(euler_system(inertial=False))
    assert [(c.verdict, c.test) for c in found] == [("holonomic", "set")] * 3


def test_primitive_rotation_tied_to_inertial_euler_forms_is_not():
    # The file's axes are body axes: inertial components tied to them contradict Maurer-Cartan.
    found = classify(euler_system(inertial=True))
    assert [c.verdict for c in found] == ["non-holonomic"] * 3


def test_equal_moments_leave_the_axes_open_and_the_verdict_undecided():
    for inertial in (False, True):
        found = classify(euler_system(inertial, inertia="[A, A, A]"))
        assert {c.verdict for c in found} == {"undecided"}
        assert all("body or inertial axes" in c.note for c in found)


FIXED_PLANE_SPHERE = """
gacli: 1
name: sphere
parameters: [M, a, I]
coordinates: [x, y]
quasi_coordinates: [q_x, q_y, q_z]
constraints: [{constraints}]
bodies:
  sphere: {{mass: M, position: [x, y, a], inertia: {inertia}, rotation: [dq_x, dq_y, dq_z]}}
"""


@pytest.mark.parametrize("inertia", ["[I, I, I]", "[A, B, C]"])
def test_the_sphere_on_a_fixed_plane_is_non_holonomic(inertia):
    """The chapter's standard example (eq. 14.23 with Omega = 0): dx = a dq_y, dy = -a dq_x."""
    text = FIXED_PLANE_SPHERE.format(constraints="'dx - a*dq_y = 0', 'dy + a*dq_x = 0'",
                                     inertia=inertia.replace("A", "I"))
    found = classify(loads(text.replace("parameters: [M, a, I]", "parameters: [M, a, I, B, C]")))
    assert [(c.where, c.verdict) for c in found] == [
        ("constraints[0]", "non-holonomic"), ("constraints[1]", "non-holonomic")]


def test_dq_y_is_not_exact_even_alone():
    """Without the rotation's structure dx - a*dq_y would be closed: the old, wrong 'holonomic'."""
    text = FIXED_PLANE_SPHERE.format(constraints="'dx - a*dq_y = 0'", inertia="[I, I, I]")
    assert verdicts(loads(text)) == {"constraints[0]": "non-holonomic"}


PLANAR = """
gacli: 1
name: planar
parameters: [m, a, J]
coordinates: [x, theta]
quasi_coordinates: [q_z]
constraints: [{constraint}]
bodies:
  disk: {{mass: m, position: [x, a, 0], inertia: {inertia}, rotation: {rotation}}}
"""


@pytest.mark.parametrize("rotation, inertia", [("dq_z", "J")])  # format 1 writes no zero component
@pytest.mark.parametrize("constraint, verdict", [
    ("dq_z - dtheta = 0", "holonomic"),              # q_z = theta + const
    ("dx + a*dq_z = 0", "holonomic"),                # a disk rolling on a line: x = -a q_z
    ("dx + x*dq_z = 0", "holonomic"),                # x e^{q_z} = const
    ("dx + theta*dq_z = 0", "non-holonomic"),        # d(theta dq_z) = dtheta ^ dq_z: not integrable
])
def test_rotation_about_a_fixed_axis_is_exact(rotation, inertia, constraint, verdict):
    """One nonzero component: its Maurer-Cartan right side vanishes, so d(dq_z) = 0."""
    text = PLANAR.format(constraint=repr(constraint), rotation=rotation, inertia=inertia)
    assert verdicts(loads(text)) == {"constraints[0]": verdict}


@pytest.mark.parametrize("bodies, why", [
    ("p: {mass: m, position: [x, y, 0]}", "in no body's rotation"),
    ("b1: {mass: m, position: [x, y, 0], inertia: [m, m, m], rotation: [dq_x, dq_y, dq_z]}\n"
     "  b2: {mass: m, position: [x, y, 1], inertia: [m, m, m], rotation: [dq_x, dq_y, dq_z]}", "in the rotations of"),
    ("b: {mass: m, position: [x, y, 0], inertia: [m, m, m], rotation: [dq_x, dq_y, dx]}", "only 3 in 3"),
])
def test_unknown_structure_is_undecided_never_holonomic(bodies, why):
    found = classify(loads(f"""
gacli: 1
name: unknown
parameters: [m, a]
coordinates: [x, y]
quasi_coordinates: [q_x, q_y, q_z]
constraints: ['dx - a*dq_y = 0']
bodies:
  {bodies}
"""))
    assert [(c.verdict, c.method) for c in found] == [("undecided", "undecided")]
    assert why in found[0].note


# -- the set of constraints ---------------------------------------------------------------------

def test_a_set_can_be_holonomic_when_a_row_alone_is_not():
    # x = const makes dz - x dy exact: z = x y + const on each leaf.
    found = classify(system(["dz = x*dy", "dx = 0"]))
    assert [(c.verdict, c.test) for c in found] == [("holonomic", "set"), ("holonomic", "alone")]


def test_a_row_whose_derivative_vanishes_on_the_set_is_not_called_holonomic():
    """dw = z dx, dz = y dx: d(dw - z dx) = dx ^ dz is zero where dz = y dx, yet brackets reach every
    direction (no relation holds), so 'integrable modulo the others' would be a false 'holonomic'."""
    found = classify(loads("""
gacli: 1
name: engel
parameters: [m]
coordinates: [x, y, z, w]
constraints: ['dw = z*dx', 'dz = y*dx']
bodies: {p: {mass: m, position: [x, y, z + w]}}
"""))
    assert [c.verdict for c in found] == ["non-holonomic", "non-holonomic"]


def test_the_set_test_by_points_agrees_with_the_symbolic_one(monkeypatch):
    import gacli.check.integrability as integrability
    monkeypatch.setattr(integrability, "_kernel", lambda rows: None)
    assert [c.verdict for c in classify(system(["dz = x*dy", "dx = 0"]))] == ["holonomic", "holonomic"]
    assert [c.verdict for c in classify(euler_system(inertial=False))] == ["holonomic"] * 3
    assert [c.verdict for c in classify(euler_system(inertial=True))] == ["non-holonomic"] * 3


@pytest.mark.parametrize("name, expected", [
    ("sphere_on_turntable", ["non-holonomic"] * 2),
    ("rolling_disk", ["non-holonomic"] * 2),
    ("differential_drive", ["non-holonomic"] * 4),
    ("chaplygin_sleigh", ["non-holonomic"]),              # the knife edge
    ("cylinder_in_cylinder", ["holonomic"]),
])
def test_rolling_examples(name, expected):
    found = [c.verdict for c in classify(load(SYSTEMS / f"{name}.yaml")) if c.kind == "constraint"]
    assert found == expected


# -- nonlinear constraints (no Pfaffian form) ----------------------------------------------------

def test_a_nonlinear_constraint_is_reported_not_tested():
    found = classify(system(["dz = y*dx", "dot(y) = sqrt(1 + dot(x)**2)"]))
    assert [(c.verdict, c.integrable) for c in found] == [
        ("non-holonomic", False), ("nonlinear (non-holonomic unless integrable; not tested)", None)]