"""`gacli verify`: the independent route (fundamental equation with multipliers) and the reactions."""

from __future__ import annotations

import ast
import dataclasses
import importlib
import inspect
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import gacli
from conftest import SYSTEMS, derived

from gacli.algebra import symbols as S
from gacli import reactions as R
from gacli import verify as V
from gacli.loader.loading import loads
from gacli.numeric.compiled import Compiled

ALL = sorted(p.stem for p in SYSTEMS.glob("*.yaml"))


def check(d, **options):
    return V.verify(d.system, d, **options)


# -- every shipped system passes ---------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_every_system_passes(name):
    d = derived(name)
    report = check(d)
    assert report.passed, "\n".join(V.format_report(report))
    assert report.samples == 20 and report.tol == 1e-9
    assert [x.equation for x in report.accelerations] == [S.rate_name(n, 2) for n in d.independent]
    assert [x.equation for x in report.rates] == [S.rate_name(n, 1) for n in d.rates.names]
    assert [x.equation for x in report.code] == ([S.rate_name(n, 2) for n in d.independent]
                                                 + [S.rate_name(c.name, 1) for c in d.system.coordinates])
    assert report.mass_symmetric and report.mass_positive_definite and not report.undetermined
    lines = V.format_report(report)
    assert lines[-1] == "verify: passed"
    assert all(isinstance(line, str) and "\n" not in line for line in lines)


def test_deterministic_and_seeded():
    d = derived("sphere_on_turntable")
    assert check(d, samples=4) == check(d, samples=4)
    assert check(d, samples=4, seed=7).seed == 7


def test_independent_route_imports_none_of_the_checked_code():
    """gacli.verify imports gacli.algebra and gacli.model: none of the derivation's code (gacli.mechanics)."""
    import pkgutil

    modules = [V] + [importlib.import_module(f"gacli.verify.{m.name}") for m in pkgutil.iter_modules(V.__path__)]
    assert len(modules) > 1
    for module in modules:
        _imports_none_of_the_checked_code(module)
    source = inspect.getsource(V.fundamental_equations)
    assert "derivation" not in source and "beta" not in source


def _imports_none_of_the_checked_code(module):
    tree = ast.parse(inspect.getsource(module))
    checked = {"gacli.mechanics.rates", "gacli.mechanics.motions", "gacli.mechanics.forces", "gacli.mechanics.equations", "gacli.mechanics.gibbs"}
    for node in tree.body:
        if isinstance(node, ast.ImportFrom) and node.module:
            assert node.module not in checked
            if node.module == "gacli":
                assert {a.name for a in node.names} <= {"symbols"}
    inner = [n for n in ast.walk(tree) if isinstance(n, (ast.Import, ast.ImportFrom))]
    modules = {n.module for n in inner if isinstance(n, ast.ImportFrom)}
    modules |= {a.name for n in inner if isinstance(n, ast.Import) for a in n.names}
    assert not modules & checked


# -- broken derivations fail, naming the equation --------------------------

def _failing(report) -> str:
    assert not report.passed
    return "\n".join(report.failures)


def _motions_terms(d, rates):
    """M and F rebuilt from a (possibly wrong) Rates, as equations.py does (eq. 14.19)."""
    from gacli.mechanics.forces import generalized_forces
    from gacli.mechanics.motions import body_motions

    motions = body_motions(d.system, rates)
    Q = generalized_forces(d.system, rates, motions)
    M, rest = sp.zeros(rates.k, rates.k), sp.zeros(rates.k, 1)
    u = sp.Matrix(rates.speeds)
    for mo in motions:
        Vp, m = mo.linear.partials, mo.body.mass
        M += m * Vp.T * Vp
        rest += m * Vp.T * mo.linear.acceleration_rest
        if mo.angular is not None:
            W, I = mo.angular.partials, mo.body.inertia
            w = W * u + mo.angular.velocity0
            M += W.T * I * W
            rest += W.T * (I * mo.angular.acceleration_rest + w.cross(I * w))
    return sp.ImmutableMatrix(M), sp.ImmutableMatrix(Q - rest), sp.ImmutableMatrix(Q)


def test_wrong_sign_in_beta_is_caught():
    d = derived("sphere_on_turntable")
    i, s = d.rates.names.index("q_y"), d.independent.index("x")
    beta = sp.Matrix(d.beta)
    assert beta[i, s] != 0
    beta[i, s] = -beta[i, s]
    bad_rates = dataclasses.replace(d.rates, beta=sp.ImmutableMatrix(beta))
    # only β changed: the row of dot(q_y) is wrong
    only_beta = dataclasses.replace(d, rates=bad_rates)
    report = check(only_beta, samples=5)
    assert "dot(q_y)" in _failing(report)
    assert [x.equation for x in report.rates if not x.passed] == ["dot(q_y)"]
    assert all(x.passed for x in report.accelerations)
    # M and F rederived with the wrong β: the accelerations are wrong too
    M, F, Q = _motions_terms(d, bad_rates)
    rederived = dataclasses.replace(d, rates=bad_rates, mass_matrix=M, forcing=F, generalized_forces=Q)
    report = check(rederived, samples=5)
    text = _failing(report)
    assert "ddot(x)" in text and "dot(q_y)" in text
    assert not {x.equation for x in report.accelerations if not x.passed} - {"ddot(x)", "ddot(y)"}


def _gyroscopic(d):
    """Σ Ωᵀ(ω × Iω) over the rigid bodies: the Koenig term of F (eq. 14.21)."""
    out = sp.zeros(d.k, 1)
    u = sp.Matrix(d.speeds)
    for mo in d.motions:
        if mo.angular is not None:
            W, I = mo.angular.partials, mo.body.inertia
            w = W * u + mo.angular.velocity0
            out += W.T * w.cross(I * w)
    return out


@pytest.mark.parametrize("name, caught", [
    ("rigid_body", {"ddot(q_1)", "ddot(q_2)", "ddot(q_3)"}),
    ("spinning_top", {"ddot(phi)", "ddot(theta)"}),
])
def test_dropped_koenig_term_is_caught(name, caught):
    d = derived(name)
    gyro = _gyroscopic(d)
    assert gyro != sp.zeros(d.k, 1)
    broken = dataclasses.replace(d, forcing=sp.ImmutableMatrix(d.forcing + gyro))
    report = check(broken, samples=5)
    _failing(report)
    assert {x.equation for x in report.accelerations if not x.passed} == caught
    assert all(x.passed for x in report.kinematics + report.rates)
    # F no longer follows from the displayed G either
    assert {x.equation for x in report.gibbs if not x.passed} == {f"∂G/∂{e}" for e in caught}


def test_wrong_generalized_force_mapping_is_caught():
    """Q_q = S r (δW read off with δθ in place of δq = r² δθ) instead of S/r (section 14.4)."""
    d = derived("particle_in_plane")
    s = d.independent.index("q")
    Sx, r = S.value("S"), S.value("r")
    assert sp.simplify(d.generalized_forces[s] - Sx / r) == 0
    Q = sp.Matrix(d.generalized_forces)
    Q[s] = Sx * r
    broken = dataclasses.replace(d, generalized_forces=sp.ImmutableMatrix(Q),
                                 forcing=sp.ImmutableMatrix(d.forcing - d.generalized_forces + Q))
    report = check(broken, samples=5)
    assert "ddot(q)" in _failing(report)
    assert {x.equation for x in report.accelerations if not x.passed} == {"ddot(q)"}


def test_wrong_moment_mapping_on_the_turntable_is_caught():
    """Q_x = F_x − M_y/a instead of F_x + M_y/a (eq. 14.28)."""
    d = derived("sphere_on_turntable")
    s = d.independent.index("x")
    shift = sp.Matrix.zeros(d.k, 1)
    shift[s] = -2 * S.value("M_y") / S.value("a")
    broken = dataclasses.replace(d, forcing=sp.ImmutableMatrix(d.forcing + shift),
                                 generalized_forces=sp.ImmutableMatrix(d.generalized_forces + shift))
    report = check(broken, samples=5)
    assert {x.equation for x in report.accelerations if not x.passed} == {"ddot(x)"}


def test_wrong_kinematic_equation_is_caught():
    d = derived("spinning_top")
    kin = tuple((n, e + (S.rate("theta") if n == "psi" else 0)) for n, e in d.kinematic_equations)
    report = check(dataclasses.replace(d, kinematic_equations=kin), samples=5)
    assert [x.equation for x in report.kinematics if not x.passed] == ["dot(psi)"]


@pytest.mark.parametrize("name", ["rolling_disk", "four_bar_linkage", "chaplygin_sleigh"])
def test_generated_code_is_checked_beside_the_closed_forms(name):
    """What users integrate (Derivation.code, the straight-line program's) is verified too: an F
    off by 1% in code alone fails the code group and nothing else."""
    d = dataclasses.replace(derived(name))
    code = d.code
    assert code.route == "program"
    d.__dict__["code"] = dataclasses.replace(code, forcing=tuple(f * sp.Rational(101, 100) for f in code.forcing))
    report = check(d, samples=5)
    assert not report.passed
    assert {x.equation for x in report.code if not x.passed} == {S.rate_name(n, 2) for n in d.independent}
    assert all(x.passed for group in (report.accelerations, report.kinematics, report.rates) for x in group)


def test_displayed_gibbs_function_is_checked():
    d = derived("sphere_on_turntable")
    extra = S.rate("y") * S.rate("x", 2)          # a wrong G₁ term
    broken = dataclasses.replace(d)
    broken.__dict__["gibbs"] = d.gibbs + extra     # Derivation.gibbs is a cached property
    report = check(broken, samples=5)
    assert [x.equation for x in report.gibbs if not x.passed] == ["∂G/∂ddot(x)"]
    assert all(x.passed for x in report.accelerations)
    assert "∂G/∂ddot(x)" in _failing(report)


def test_asymmetric_or_indefinite_mass_matrix_is_caught():
    d = derived("cylinder_in_cylinder")
    report = check(dataclasses.replace(d, mass_matrix=-d.mass_matrix, forcing=-d.forcing), samples=3)
    assert not report.mass_positive_definite and "positive definite" in _failing(report)
    assert all(x.passed for x in report.accelerations)
    d = derived("rigid_body")
    M = sp.Matrix(d.mass_matrix)
    M[0, 1] = 1
    report = check(dataclasses.replace(d, mass_matrix=sp.ImmutableMatrix(M)), samples=3)
    assert not report.mass_symmetric and "not symmetric" in _failing(report)


def test_format_report_names_the_failing_equation():
    d = derived("rigid_body")
    broken = dataclasses.replace(d, forcing=sp.ImmutableMatrix(d.forcing + _gyroscopic(d)))
    lines = V.format_report(check(broken, samples=3))
    assert any(line.startswith("verify: FAILED") for line in lines)
    assert any(line.strip().startswith("ddot(q_1)") and line.endswith("FAILED") for line in lines)


# -- systems beyond systems/: dependent rates in loads, quasi in the work -----

TOP_ON_A_SLIDER = """
gacli: 1
name: top_on_a_slider
parameters:
  m: {value: 1}
  g: 9.81
  l: 0.05
  A: 0.0005
  C: 0.0008
  c: damping
functions:
  Omega: {value: "sin(t)"}
  nu: drive
inputs: [T]
coordinates: [phi, theta, psi, s]
quasi_coordinates:
  q: dpsi + cos(theta)*dphi
constraints:
  - s = l*Omega*cos(theta) + nu
independent: [phi, theta, q]
bodies:
  top:
    mass: m
    position: [l*sin(theta)*sin(phi), -l*sin(theta)*cos(phi), l*cos(theta) + s]
    inertia: [A, A, C]
    rotation:
      - sin(theta)*sin(psi)*dphi + cos(psi)*dtheta
      - sin(theta)*cos(psi)*dphi - sin(psi)*dtheta
      - dpsi + cos(theta)*dphi
  slider: {mass: m, position: [s, 0, 0]}
loads:
  - force: [0, -c*dot(s), 0]
    at: [l*sin(theta), 0, s]
work: T*dq - c*dot(psi)*dpsi
potential: m*g*(l*cos(theta) + s)
"""


def test_holonomic_constraint_functions_and_quasi_in_the_work():
    from gacli.mechanics.equations import derive

    system = loads(TOP_ON_A_SLIDER)
    report = V.verify(system, derive(system), samples=6)
    assert report.passed, "\n".join(V.format_report(report))


def test_primitive_quasi_coordinate_in_nothing_is_reported_undetermined():
    from gacli.mechanics.equations import derive

    system = loads("""
gacli: 1
name: idle
parameters: [m]
coordinates: [x]
quasi_coordinates: [w]
independent: [x, w]
bodies: {ball: {mass: m, position: [x, 0, 0]}}
""")
    report = V.verify(system, derive(system), samples=3)
    assert report.undetermined == ("w",)
    assert not report.passed and not report.mass_positive_definite
    assert [x.equation for x in report.accelerations if x.undetermined] == ["ddot(w)"]
    assert [x.equation for x in report.accelerations if x.passed] == ["ddot(x)"]
    assert any("ddot(w)" in f and "undetermined" in f for f in report.failures)


# -- constraint forces ------------------------------------------------------

def test_cylinder_friction_force():
    """λ of a dφ − c dθ = 0 is the friction force: I φ̈ = λ a gives −M g sin θ / 3."""
    lam = R.constraint_forces(derived("cylinder_in_cylinder"))
    M, g, theta = (S.value(n) for n in ("M", "g", "theta"))
    assert lam.shape == (1, 1)
    assert sp.simplify(lam[0] + M * g * sp.sin(theta) / 3) == 0


def test_no_constraints_no_reactions():
    assert R.constraint_forces(derived("rigid_body")).shape == (0, 1)
    assert R.reactions_numeric(derived("spinning_top"), {}).shape == (0,)


def test_turntable_reactions_symbolic():
    """λ = (M ẍ − F_x, M ÿ − F_y) with ẍ, ÿ from eq. (14.29)."""
    d = derived("sphere_on_turntable")
    lam = R.constraint_forces(d)
    udot = sp.Matrix(d.mass_matrix).LUsolve(sp.Matrix(d.forcing))
    xdd, ydd = udot[d.independent.index("x")], udot[d.independent.index("y")]
    M = S.value("M")
    assert sp.simplify(lam[0] - (M * xdd - S.value("F_x"))) == 0
    assert sp.simplify(lam[1] - (M * ydd - S.value("F_y"))) == 0
    # the same as the multipliers of the fundamental equation, at a random state
    rng = np.random.default_rng(3)
    free = lam.free_symbols | {S.rate("q_x"), S.rate("q_y"), S.rate("q_z"), S.rate("Omega", 2)}
    free |= {S.value(i.name) for i in d.system.inputs}
    values = {s: float(rng.uniform(0.3, 1.7)) for s in free}
    values[S.rate("q_y")] = (values[S.rate("x")] + values[S.value("Omega")] * values[S.value("y")]) / values[S.value("a")]
    values[S.rate("q_x")] = (values[S.value("Omega")] * values[S.value("x")] - values[S.rate("y")]) / values[S.value("a")]
    values[S.value("I")] = 0.4 * values[S.value("M")] * values[S.value("a")] ** 2
    _, multipliers = R.multipliers_numeric(d.system, values)
    expected = [float(e.xreplace(values)) for e in lam]
    assert np.allclose(multipliers, expected, rtol=1e-12, atol=0)


def test_turntable_contact_forces_along_a_trajectory():
    """Simulate the sphere (scipy), then λ = M ẍ − F_x, M ÿ − F_y along the way."""
    from scipy.integrate import solve_ivp

    d = derived("sphere_on_turntable")
    Mv, av = 1.0, 0.1
    Iv = 2 / 5 * Mv * av**2
    params = {S.value("M"): Mv, S.value("a"): av, S.value("I"): Iv}

    def drive(t):
        return {"Omega": 0.8 + 0.3 * np.sin(t), "dot(Omega)": 0.3 * np.cos(t),
                "F_x": 0.2 * np.cos(t), "F_y": -0.1, "F_z": 0.0,
                "M_x": 0.01 * np.sin(2 * t), "M_y": 0.005, "M_z": 0.001}

    args = list(d.state) + [S.value(n) for n in ("Omega", "F_x", "F_y", "F_z", "M_x", "M_y", "M_z")]
    args += [S.rate("Omega")]
    M_f = sp.lambdify(args, d.mass_matrix.xreplace(params), "numpy")
    F_f = sp.lambdify(args, d.forcing.xreplace(params), "numpy")
    names = [s.name for s in args]

    def call(f, t, y):
        env = {**dict(zip(names[:len(y)], y)), **drive(t)}
        return np.array(f(*(env[n] for n in names)), dtype=float)

    nq = len(d.coordinates)

    def rhs(t, y):
        qdot = [float(e.xreplace({**params, **dict(zip(d.state, y)),
                                  S.value("Omega"): drive(t)["Omega"]}))
                for _, e in d.kinematic_equations]
        udot = np.linalg.solve(call(M_f, t, y), call(F_f, t, y)[:, 0])
        return np.concatenate([qdot, udot])

    y0 = [0.3, -0.2, 0.1, 0.2, 1.0]
    sol = solve_ivp(rhs, (0.0, 3.0), y0, rtol=1e-11, atol=1e-12, dense_output=True)
    assert sol.success
    reactions = R.reaction_function(d)
    ix, iy = nq + d.independent.index("x"), nq + d.independent.index("y")
    h = 1e-4
    for t in np.linspace(0.2, 2.8, 9):
        y = sol.sol(t)
        values = {**dict(zip(names[:len(y)], y)), **drive(t), "t": t}
        lam = reactions(values)
        xdd = (sol.sol(t + h)[ix] - sol.sol(t - h)[ix]) / (2 * h)
        ydd = (sol.sol(t + h)[iy] - sol.sol(t - h)[iy]) / (2 * h)
        dr = drive(t)
        assert lam[0] == pytest.approx(Mv * xdd - dr["F_x"], rel=1e-5, abs=1e-8)
        assert lam[1] == pytest.approx(Mv * ydd - dr["F_y"], rel=1e-5, abs=1e-8)
        # and the moment equations of the sphere: I q̈_y = M_y − a R_x (eq. 14.26 for q̈_y)
        x, yv, xd, yd = y[0], y[1], y[ix], y[iy]
        qydd = (xdd + dr["Omega"] * yd + dr["dot(Omega)"] * yv) / av
        qxdd = (-ydd + dr["Omega"] * xd + dr["dot(Omega)"] * x) / av
        assert lam[0] == pytest.approx((dr["M_y"] - Iv * qydd) / av, rel=1e-4, abs=1e-7)
        assert lam[1] == pytest.approx(-(dr["M_x"] - Iv * qxdd) / av, rel=1e-4, abs=1e-7)


def test_reactions_agree_with_the_multipliers_of_the_fundamental_equation():
    """λ from the dependent rates' equations (u̇ = M⁻¹F) = λ from the unreduced linear system."""
    from gacli.mechanics.equations import derive

    d = derive(loads(TOP_ON_A_SLIDER))
    fundamental = V.fundamental_equations(d.system)
    symbols = set().union(*(e.free_symbols for m in (fundamental.mass, fundamental.inertial, fundamental.loads,
                                                       fundamental.A, fundamental.relation_rest) for e in m))
    symbols |= set().union(*(e.free_symbols for e in list(d.mass_matrix) + list(d.forcing) + list(d.beta0)))
    dependent = [n for n in d.rates.names if n not in d.independent]
    rng = np.random.default_rng(11)
    reactions = R.reaction_function(d)
    for _ in range(3):
        values = {s: float(rng.uniform(0.3, 1.7)) for s in sorted(symbols, key=lambda s: s.name)}
        values.update({S.value(p.name): float(p.value) for p in d.system.parameters if p.value is not None})
        for n in dependent:
            values[S.rate(n)] = float(d.rates.rate(n).xreplace(values))
        _, multipliers = R.multipliers_numeric(d.system, values)
        lam = reactions(values)
        assert lam.shape == (1,)
        assert np.allclose(lam, multipliers[:1], rtol=1e-9, atol=1e-12)
        symbolic = R.constraint_forces(d, simplify=False)
        assert float(symbolic[0].xreplace(values)) == pytest.approx(multipliers[0], rel=1e-9)


def test_gibbs_check_can_be_skipped():
    d = derived("cylinder_in_cylinder")
    report = check(d, samples=2, gibbs=False)
    assert report.passed and report.gibbs == ()
    assert any("skipped" in n for n in report.notes)


def test_numeric_program_matches_sympy():
    """The straight-line evaluator (used for the checks) against evalf, functions of the grammar included."""
    import mpmath

    x, y = S.value("x"), S.rate("y")
    exprs = [sp.sin(x) ** 2 * sp.atan2(y, x) + sp.sqrt(x) / (1 + y**2), sp.exp(-x) * sp.Abs(y) * sp.pi,
             sp.log(x) + sp.sign(y) + sp.tanh(x) * sp.Rational(3, 7) + sp.acos(x / 2) + x ** sp.Rational(-3, 2)]
    with mpmath.workdps(30):
        values = {x: mpmath.mpf("0.7"), y: mpmath.mpf("-1.3")}
        got = Compiled({"e": sp.Matrix(exprs)})(values)["e"]
        exact = [e.xreplace({x: sp.Rational(7, 10), y: sp.Rational(-13, 10)}).evalf(40) for e in exprs]
        for i, e in enumerate(exact):
            assert abs(got[i] - mpmath.mpf(str(e))) < mpmath.mpf("1e-27")
    # an unknown function falls back to lambdify
    compiled = Compiled({"e": sp.Matrix([sp.Piecewise((x, x > 0), (0, True))])})
    with mpmath.workdps(30):
        assert compiled(values)["e"][0] == mpmath.mpf("0.7")


def test_a_derivation_that_cannot_be_evaluated_is_said_so_not_measured(tmp_path):
    # exp(exp(exp(100))) overflows every sample: there is no difference to report, only that.
    from typer.testing import CliRunner

    from gacli.cli import app

    path = tmp_path / "overflow.yaml"
    path.write_text("gacli: 1\nname: ee\nparameters: {m: {value: 1}}\ncoordinates: [x]\n"
                    "bodies:\n  b: {mass: m, position: [x, 0]}\npotential: exp(exp(exp(100)))*x\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["verify", "--samples", "2", str(path)])
    assert result.exit_code == 1 and "Traceback" not in result.output
    assert "could not be evaluated" in result.output
    assert "relative difference inf" not in result.output and "= inf" not in result.output


def test_a_ball_in_a_quaternion_frame_with_an_offset_centre_is_verified_on_its_sphere():
    """Its rolling row along the normal vanishes only where e·e = 1: verify drew coordinates off that
    sphere and ranked the rows there, kept the row, and failed equations that agree with Kane."""
    system = gacli.load(str(Path(__file__).parent / "cases" / "ball_quaternion_offset.yaml"))
    derivation = gacli.derive(system)
    report = V.verify(system, derivation, samples=5)
    assert report.passed, "\n".join(V.format_report(report))
    # The row that repeats the others is the rolling row, as derive says, not a quasi-coordinate's definition.
    repeated = [n for n in report.notes if "repeats the relations before it" in n]
    assert len(repeated) == 1 and repeated[0].startswith("constraints["), report.notes


def test_an_undefined_value_in_the_equations_fails_verify_without_a_traceback(tmp_path):
    """1/0 written in a position (sin² + cos² − 1 is zero): mpmath's compile met ComplexInfinity and raised."""
    d = gacli.derive(loads("gacli: 1\nname: z\nparameters: {m: {value: 1}}\ncoordinates: [x, th]\n"
                           "bodies:\n  a: {mass: m, position: [x, th/(sin(x)**2 + cos(x)**2 - 1), 0]}\n"))
    report = check(d, samples=2)
    assert not report.passed
    assert any("could not be evaluated" in f for f in report.failures)


def test_an_acceleration_zero_on_both_routes_passes():
    """s = a x + b x², nothing acting: ẍ is 0 by M u̇ = F and 1.6e-40 by the multipliers' solve, which the
    relative floor (1e-12 of the group's largest entry) made a difference of 1."""
    d = gacli.derive(loads("gacli: 1\nname: s\nparameters: {m: {value: 1}, a: {value: 2}, b: {value: 3}}\n"
                           "coordinates: [x, s]\nconstraints: [s = a*x + b*x**2]\n"
                           "bodies: {p: {mass: m, position: [x, 0, 0]}}\n"))
    report = check(d, samples=3)
    assert report.passed, "\n".join(V.format_report(report))


def test_masses_far_apart_are_positive_definite_for_verify_as_for_check(tmp_path):
    """A planet's 5.97e24 beside a probe's 1: verify said 'smallest eigenvalue / largest 1.68e-25
    FAILED' where check passed (a reviewer's file); both judge M scaled by its diagonal."""
    from typer.testing import CliRunner

    from gacli.cli import app

    path = tmp_path / "earth.yaml"
    path.write_text("gacli: 1\nname: s\nparameters: {M1: 5.97e24, m2: 1, k: 1}\ncoordinates: [x, y]\n"
                    "bodies:\n  earth: {mass: M1, position: [x, 0, 0]}\n  probe: {mass: m2, position: [y, 0, 0]}\n"
                    "potential: k*(x-y)**2/2\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["verify", str(path)])
    assert result.exit_code == 0 and "verify: passed" in result.output, result.output
