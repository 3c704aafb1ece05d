"""Constraints nonlinear in the rates (docs/nonlinear.md), against an independent derivation.

The reference is written here without gacli's machinery: Lagrange's
equations with one multiplier under Chetaev's rule, m a = F + λ ∂g/∂ṙ,
together with the differentiated constraint dg/dt = 0, solved numerically
for the accelerations at random states. gacli's u̇ = M⁻¹F must agree.
"""

from __future__ import annotations

import importlib.util

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad, solve_ivp

from conftest import SYSTEMS
from gacli.emit import emit_python
from gacli.mechanics.equations import derive
from gacli.errors import SystemFileError
from gacli.loader.loading import load, loads

HEADER = """\
gacli: 1
name: ah
parameters: {m: {value: 1}, g: {value: 9.81}, c: {value: 0.5}, v: {value: 0.3}}
coordinates: [x, y, z]
"""
BODY = """
bodies:
  p: {mass: m, position: [x, y, z]}
potential: m*g*z
"""

x, y, z, t = (sp.Symbol(n, real=True) for n in "xyzt")
xd, yd, zd = (sp.Symbol(f"dot({n})", real=True) for n in "xyz")
m, g, c, v = (sp.Symbol(n, real=True) for n in "mgcv")


def system_with(constraint: str):
    return loads(HEADER + "constraints:\n  - " + constraint + "\n" + BODY)


def reference_accelerations(relation, values):
    """(ẍ, ÿ, z̈) of m a = (0, 0, -m g) + λ ∂g/∂ṙ with dg/dt = 0, at ``values`` (x, y, z, ẋ, ẏ, params, t)."""
    xdd, ydd, zdd, lam = sp.symbols("xdd ydd zdd lam")
    rates = (xd, yd, zd)
    normal = [sp.diff(relation, r) for r in rates]
    dg_dt = sum(sp.diff(relation, r) * a for r, a in zip(rates, (xdd, ydd, zdd))) + sp.diff(relation, t) \
        + sum(sp.diff(relation, q) * r for q, r in zip((x, y, z), rates))
    equations = [m * xdd - lam * normal[0], m * ydd - lam * normal[1], m * zdd + m * g - lam * normal[2], dg_dt]
    # ż from the constraint itself at this state (it is linear in ż in every case tested here).
    zdot = sp.solve(relation.xreplace(values), zd)[0]
    numeric = [e.xreplace(values).xreplace({zd: zdot}) for e in equations]
    solution = sp.solve(numeric, [xdd, ydd, zdd, lam], dict=True)[0]
    return [float(solution[a]) for a in (xdd, ydd)], float(zdot)


def gacli_accelerations(derivation, values):
    M = np.array(derivation.mass_matrix.xreplace(values).evalf(), dtype=float)
    F = np.array(derivation.forcing.xreplace(values).evalf(), dtype=float).ravel()
    zdot = float(dict(derivation.kinematic_equations)["z"].xreplace(values))
    return list(np.linalg.solve(M, F)), zdot


RELATIONS = {
    "dz = -c*sqrt(dx**2 + dy**2)": zd + c * sp.sqrt(xd**2 + yd**2),
    "dot(z) = -c*sqrt(dot(x)**2 + dot(y)**2)": zd + c * sp.sqrt(xd**2 + yd**2),
    # rheonomic: the drum also turns by a prescribed rate
    "dot(z) = -c*sqrt(dot(x)**2 + dot(y)**2) + v*sin(t)": zd + c * sp.sqrt(xd**2 + yd**2) - v * sp.sin(t),
    # solved for ż though ż is not alone on the left
    "c*sqrt(dot(x)**2 + dot(y)**2) + 2*dot(z) + x*dot(x) = 0": c * sp.sqrt(xd**2 + yd**2) + 2 * zd + x * xd,
}


@pytest.mark.parametrize("written", sorted(RELATIONS))
def test_equations_agree_with_lagrange_and_chetaev(written, rng):
    derivation = derive(system_with(written))
    assert derivation.independent == ("x", "y")
    for _ in range(5):
        values = {x: rng.uniform(-1, 1), y: rng.uniform(-1, 1), z: rng.uniform(-1, 1),
                  xd: rng.uniform(0.2, 1.5), yd: rng.uniform(-1.5, -0.2),
                  m: rng.uniform(0.5, 2), g: rng.uniform(5, 10), c: rng.uniform(0.1, 1), v: rng.uniform(0, 1),
                  t: rng.uniform(0, 3)}
        values = {s: sp.Float(val, 30) for s, val in values.items()}
        ours, our_zdot = gacli_accelerations(derivation, values)
        theirs, their_zdot = reference_accelerations(RELATIONS[written], values)
        np.testing.assert_allclose(ours, theirs, rtol=1e-10)
        assert our_zdot == pytest.approx(their_zdot, rel=1e-12)


def _module(derivation, tmp_path):
    (name, text), = emit_python(derivation).items()
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_simulation_conserves_energy_and_keeps_the_constraint(tmp_path):
    derivation = derive(load(SYSTEMS / "appell_hamel.yaml"))
    module = _module(derivation, tmp_path)
    p = [module.DEFAULTS[n] for n in module.PARAMETERS]
    mass, grav, sink = p
    x0 = [0.0, 0.0, 10.0, 1.0, 0.5]  # x, y, z, dot(x), dot(y)
    solution = solve_ivp(lambda time, s: module.rhs(time, s, p), (0, 10), x0, method="DOP853",
                         rtol=1e-12, atol=1e-12, dense_output=True)
    assert solution.success

    def energy(s):
        zdot = -sink * np.hypot(s[3], s[4])
        return 0.5 * mass * (s[3] ** 2 + s[4] ** 2 + zdot**2) + mass * grav * s[2]

    energies = np.array([energy(s) for s in solution.y.T])
    assert np.max(np.abs(energies - energies[0])) <= 1e-9 * abs(energies[0])
    # The constraint integrated on its own: z(T) − z(0) = −c ∫ |v_horizontal| dt.
    travelled, _ = quad(lambda time: np.hypot(*solution.sol(time)[3:5]), 0, 10, epsabs=1e-13, epsrel=1e-13, limit=200)
    assert abs(solution.y[2, -1] - (10.0 - sink * travelled)) < 1e-8


@pytest.mark.parametrize(("constraint", "words"), [
    ("dot(x)**2 + dot(y)**2 = v**2", "cannot be solved for a dependent rate"),
    ("dx**2 + dy**2 = v**2*dt**2", "nor homogeneous of degree one"),
    ("dz = -c*sqrt(dot(x)**2 + dy**2)", "either with differentials"),
])
def test_a_relation_that_cannot_be_used_is_a_located_error(constraint, words):
    with pytest.raises(SystemFileError) as info:
        system_with(constraint)
    (d,) = info.value.diagnostics
    assert words in d.message and d.location.line == 6


def test_a_nonlinear_rate_may_not_be_independent_or_in_a_pfaffian_row():
    text = HEADER + "independent: [x, z]\nconstraints:\n  - dot(z) = -c*sqrt(dot(x)**2 + dot(y)**2)\n" + BODY
    with pytest.raises(SystemFileError, match="it cannot be independent"):
        derive(loads(text))
    text = HEADER + "constraints:\n  - dot(z) = -c*sqrt(dot(x)**2 + dot(y)**2)\n  - dy = z*dz\n" + BODY
    with pytest.raises(SystemFileError, match="a Pfaffian relation may not involve it"):
        derive(loads(text))


def test_check_reports_a_nonlinear_constraint_as_such():
    from gacli.check.integrability import classify

    (verdict,) = classify(load(SYSTEMS / "appell_hamel.yaml"))
    assert verdict.verdict.startswith("nonlinear")


def test_a_relation_written_with_rates_but_linear_in_them_is_a_pfaffian_row(tmp_path):
    # dot(x) = dot(y) was a 'nonlinear' constraint, 'not linear in the rates' and not tested for
    # integrability; it is dx - dy = 0, holonomic.
    from typer.testing import CliRunner
    from gacli.cli import app

    path = tmp_path / "dd.yaml"
    path.write_text("gacli: 1\nname: dd\nparameters: {m: {value: 1}, r: {value: 2}}\ncoordinates: [x, y, phi]\n"
                    "constraints:\n  - dot(x) = dot(y)\n  - dot(x) = r*dot(phi)*cos(y) + 1\n"
                    "bodies: {b: {mass: m, position: [x, y, phi]}}\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["check", "--format", "json", str(path)])
    import json

    verdicts = [c["verdict"] for c in json.loads(result.stdout)["files"][0]["classifications"]]
    assert verdicts == ["holonomic", "non-holonomic"], result.stdout
