"""Reading system files: every declaration form the spec allows, checked by its effect."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from conftest import SYSTEMS
from gacli.mechanics.equations import derive
from gacli.errors import SystemFileError
from gacli.loader.loading import load, loads


def sym(name):
    return sp.Symbol(name, real=True)


def zero(expr) -> bool:
    if isinstance(expr, sp.MatrixBase):
        return all(sp.simplify(e) == 0 for e in expr)
    return sp.simplify(expr) == 0


def test_both_declaration_forms_and_values():
    s = loads("""
gacli: 1
name: forms
parameters:
  m: mass
  k: {description: stiffness, value: 0.5, unit: N/m}
  w: {value: "sqrt(k/m)"}
coordinates: [x]
bodies: {p: {mass: m, position: [x, 0]}}
potential: k*x**2/2
""")
    assert [p.name for p in s.parameters] == ["m", "k", "w"]
    assert s.parameters[0].description == "mass"
    assert s.parameters[1].value == sp.Rational(1, 2)  # decimals are exact
    assert s.parameters[2].value == sp.sqrt(sym("k") / sym("m"))
    assert s.parameters[1].unit == "N/m"


def test_yaml_booleans_stay_names():
    s = loads("""
gacli: 1
name: words
parameters: [on, off, yes, no]
coordinates: [x]
bodies: {p: {mass: on + off + yes + no, position: [x, 0]}}
""")
    assert [p.name for p in s.parameters] == ["on", "off", "yes", "no"]


def test_function_with_value_is_substituted():
    text = (SYSTEMS / "sphere_on_turntable.yaml").read_text()
    given = text.replace("  Omega: angular rate of the plane", '  Omega: {value: "2 + sin(t)"}')
    free, fixed = derive(load(SYSTEMS / "sphere_on_turntable.yaml")), derive(loads(given))
    t = sym("t")
    substitution = {sym("Omega"): 2 + sp.sin(t), sym("dot(Omega)"): sp.cos(t)}
    assert zero(free.forcing.subs(substitution) - fixed.forcing)
    assert fixed.system.free_functions == ()


def test_finite_constraint_equals_its_differential():
    pfaffian = derive(load(SYSTEMS / "cylinder_in_cylinder.yaml"))
    text = (SYSTEMS / "cylinder_in_cylinder.yaml").read_text()
    finite = derive(loads(text.replace("a*dphi = c*dtheta", "a*phi = c*theta")))
    assert finite.system.constraints[0].relation is not None
    assert zero(pfaffian.mass_matrix[0] - finite.mass_matrix[0])
    assert zero(pfaffian.forcing[0] - finite.forcing[0])


def test_automatic_independent_set_is_earliest_valid():
    text = (SYSTEMS / "sphere_on_turntable.yaml").read_text().replace("independent: [x, y, q_z]\n", "")
    d = derive(loads(text))
    assert d.independent == ("x", "y", "q_z")
    assert d.rates.chosen_automatically


def test_quasi_coordinate_string_is_its_differential():
    s = load(SYSTEMS / "particle_in_plane.yaml")
    (q,) = s.quasi_coordinates
    assert q.differential.coefficient("theta") == sym("r") ** 2


def _euler_rhs(inertia, w, torque):
    """I ω̇ = M − ω × Iω, solved numerically."""
    return np.linalg.solve(inertia, torque - np.cross(w, inertia @ w))


def test_full_inertia_matrix_gives_eulers_equations(rng):
    d = derive(loads("""
gacli: 1
name: tumbling
parameters: [m, A, B, C, D, E, F]
inputs: [T1, T2, T3]
coordinates: [x, y, z]
quasi_coordinates: [w1, w2, w3]
bodies:
  b:
    mass: m
    position: [x, y, z]
    inertia: [[A, F, E], [F, B, D], [E, D, C]]
    rotation: [dw1, dw2, dw3]
loads:
  - {torque: [T1, T2, T3], body: b}
"""))
    names = "A B C D E F m T1 T2 T3 dot(w1) dot(w2) dot(w3)".split()
    f = sp.lambdify([sym(n) for n in names], [d.mass_matrix, d.forcing])
    for _ in range(10):
        A, B, C = rng.uniform(3, 4, 3)
        D, E, F = rng.uniform(-0.5, 0.5, 3)
        m, *rest = rng.uniform(0.5, 2, 7)
        torque, w = np.array(rest[:3]), np.array(rest[3:])
        M, Fv = (np.array(a, dtype=float) for a in f(A, B, C, D, E, F, m, *torque, *w))
        got = np.linalg.solve(M, Fv.ravel())[3:]
        inertia = np.array([[A, F, E], [F, B, D], [E, D, C]])
        np.testing.assert_allclose(got, _euler_rhs(inertia, w, torque), rtol=1e-12)


def test_plane_motion_shorthand_and_scalar_torque():
    d = derive(loads("""
gacli: 1
name: wheel
parameters: [m, J]
inputs: [T]
coordinates: [phi]
bodies:
  w: {mass: m, position: [0, 0], inertia: J, rotation: dphi}
loads:
  - {torque: T, body: w}
"""))
    assert d.mass_matrix[0] == sym("J")
    assert d.forcing[0] == sym("T")


def test_force_at_a_point_and_work_and_potential_add_up():
    d = derive(loads("""
gacli: 1
name: rod
parameters: [m, l, g, c]
inputs: [P]
coordinates: [theta]
bodies:
  rod: {mass: m, position: [l/2*sin(theta), -l/2*cos(theta)], inertia: m*l**2/12, rotation: dtheta}
loads:
  - {force: [P, 0], at: [l*sin(theta), -l*cos(theta)]}
work: -c*dot(theta)*dtheta
potential: -m*g*l/2*cos(theta)
"""))
    th, m, l, g, c, P = (sym(n) for n in ("theta", "m", "l", "g", "c", "P"))
    expected_Q = P * l * sp.cos(th) - c * sym("dot(theta)") - m * g * l / 2 * sp.sin(th)
    assert zero(d.generalized_forces[0] - expected_Q)
    assert zero(d.mass_matrix[0] - m * l**2 / 3)


def test_all_problems_are_reported_together():
    with pytest.raises(SystemFileError) as info:
        loads("""
gacli: 1
name: many
parameters: [m]
coordinates: [x]
bodies: {p: {mass: mm, position: [xx, 0]}}
""", "many.yaml")
    messages = [str(d) for d in info.value.diagnostics]
    assert len(messages) == 2
    assert messages[0].startswith("many.yaml:6:")
    assert "did you mean 'm'?" in messages[0] and "did you mean 'x'?" in messages[1]


POINTS = """\
gacli: 1
name: pts
parameters: {m: {value: 1}, l: {value: 1}}
coordinates: [x]
points:
%s
bodies:
  b: {mass: m, position: p}
"""


def test_a_point_may_be_given_from_a_later_one():
    system = loads(POINTS % "  p: {from: q, N: [l, 0, 0]}\n  q: {N: [x, 0, 0]}")
    assert [str(e) for e in system.bodies[0].position] == ["l + x", "0", "0"]


@pytest.mark.parametrize("points", [
    "  p: {from: q, N: [l, 0, 0]}\n  q: {from: p, N: [0, l, 0]}",
    "  p: {from: p, N: [l, 0, 0]}",
    "  p: {from: q, N: [l, 0, 0]}\n  q: {from: r, N: [0, l, 0]}\n  r: {from: p, N: [x, 0, 0]}",
])
def test_a_circle_of_points_is_one_clear_error(points):
    with pytest.raises(SystemFileError) as info:
        loads(POINTS % points, "f.yaml")
    (diagnostic,) = info.value.diagnostics
    assert "in a circle" in diagnostic.message and "is not a point" not in str(info.value)


_FRAMES = """gacli: 1
name: double_pendulum
parameters: [m, l]
coordinates: [a, b]
frames:
%s
points:
  P: {upper: [l, 0, 0]}
  Q: {from: P, lower: [l, 0, 0]}
bodies:
  p1: {mass: m, position: P}
  p2: {mass: m, position: Q}
"""


def test_a_frame_may_be_declared_before_its_parent():
    # As points may: a reviewer's bicycle declared its leaves first and got 16 errors.
    system = loads(_FRAMES % "  lower: {parent: upper, rotations: [[z, b]]}\n  upper: {rotations: [[z, a]]}")
    M = derive(system).mass_matrix
    m, l, b = sp.symbols("m l b", real=True)
    by_hand = m * l**2 * sp.Matrix([[3 + 2 * sp.cos(b), 1 + sp.cos(b)], [1 + sp.cos(b), 1]])
    names = {s.name: s for s in M.free_symbols}
    assert sp.simplify(M - by_hand.subs({m: names["m"], l: names["l"], b: names["b"]})) == sp.zeros(2, 2)


@pytest.mark.parametrize("frames, count", [
    ("  lower: {parent: upper, rotations: [[z, b]]}\n  upper: {parent: lower, rotations: [[z, a]]}", 2),
    ("  lower: {parent: upper, rotations: [[z, b]]}\n  upper: {rotations: [[z, a +]]}", 1),
])
def test_a_frame_in_error_is_reported_once_not_at_each_use(frames, count):
    with pytest.raises(SystemFileError) as info:
        loads(_FRAMES % frames, "f.yaml")
    assert len(info.value.diagnostics) == count, str(info.value)
    assert "is not a frame" not in str(info.value)
    assert count == 1 or all("in a circle" in d.message for d in info.value.diagnostics)


@pytest.mark.parametrize("error", [RecursionError, OverflowError])
def test_a_file_sympy_cannot_evaluate_is_one_located_error(error, monkeypatch):
    # A frame turned by 1e300*delta made SymPy recurse without end in a rolling row (a traceback
    # from every command before): the loader says so at the file, as any problem of the file.
    from gacli.errors import SystemFileError
    from gacli.loader import loading

    def fail(self):
        raise error("deep")

    monkeypatch.setattr(loading._Builder, "system", fail)
    with pytest.raises(SystemFileError, match=r"cannot be loaded: .* to evaluate") as caught:
        loading.loads("gacli: 1\nname: x\ncoordinates: [q]\nbodies: {b: {mass: 1, position: [q, 0, 0]}}\n",
                      path="bad.yaml")
    assert caught.value.diagnostics[0].location.path == "bad.yaml"


def test_a_rotation_component_may_be_zero():
    # A turret turning about the fixed vertical: its body rates are (0, 0, q1'), and a user writes the zeros.
    text = """gacli: 1
name: turret
parameters: [m, A, B, C, D]
coordinates: [q1]
bodies:
  turret: {mass: m, position: [0, 0, 0], inertia: [[A, D, 0], [D, B, 0], [0, 0, C]], rotation: [%s, 0*dq1, dq1]}
"""
    for zero in ("0", "dq1 - dq1"):
        body = loads(text % zero, "t.yaml").bodies[0]
        assert [f.coefficients for f in body.rotation] == [(), (), (("q1", 1),)]
    with pytest.raises(SystemFileError, match="found no differential"):
        loads(text % "q1", "t.yaml")


def test_a_comma_that_split_a_flow_mapping_s_text_is_pointed_at():
    # description: damper anchor on the cart, ahead of the hinge -> a key 'ahead of the hinge' with no value.
    text = """gacli: 1
name: comma
parameters:
  h: {value: 0.3, description: damper anchor on the cart, ahead of the hinge}
  m: {value: 1}
coordinates: [x]
bodies:
  b: {mass: m, position: [x, 0, h]}
"""
    with pytest.raises(SystemFileError, match=r"unknown key 'ahead of the hinge' \(a comma inside \{\.\.\.\} starts"):
        loads(text, "c.yaml")
    with pytest.raises(SystemFileError, match=r"unknown key 'valu' \(did you mean 'value'\?\)"):
        loads(text.replace("{value: 0.3,", "{valu: 0.3,"), "c.yaml")


def test_a_missing_file_is_said_to_be_missing(tmp_path):
    with pytest.raises(SystemFileError) as info:
        load(tmp_path / "missing.yaml")
    assert str(info.value).endswith("error: no such file")


def test_a_greek_letter_for_a_name_is_told_how_to_print_it():
    with pytest.raises(SystemFileError) as info:
        loads("gacli: 1\nname: g\ncoordinates: [\u03b8]\nparameters: [m]\nbodies: {p: {mass: m, position: [x, 0]}}\n")
    assert "'\u03b8' is not a valid name" in str(info.value) and "theta for \u03b8" in str(info.value)


def test_a_parameter_that_is_its_own_value_is_told_so():
    with pytest.raises(SystemFileError) as info:
        loads("gacli: 1\nname: g\ncoordinates: [x]\nparameters: {m: {value: 2*m}}\n"
              "bodies: {p: {mass: m, position: [x, 0]}}\n")
    assert "'m' cannot be its own value" in str(info.value) and "did you mean" not in str(info.value)
