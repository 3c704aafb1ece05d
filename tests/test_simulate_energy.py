"""gacli.simulate.energy: when E is conserved, and T where it is, without the chapter's closed route.

simulate integrates generated code, and for a large system (a bicycle) the
pipeline forms no closed forms at all. What it reports of the energy must
not depend on that: whether some velocity has a term free of the
independent rates is read from the file's declarations, and T is
½ uᵀ M u with M from generated code. Both are compared here with the
chapter's motions (v = V u + v₀, eq. 14.14), an independent computation.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from conftest import ROOT, SYSTEMS, derived_file
from gacli.algebra import symbols as S
from gacli.numeric import parameter_values
from gacli.simulate.energy import MOVING_SUPPORT, conservation_problems, energy_expressions, kinetic_energy
from gacli.simulate.run import load_generated

pytest.importorskip("scipy")

VARIANTS = ROOT / "benchmarks" / "kane_set" / "variants"
MOVING_OR_NOT = [
    SYSTEMS / "sphere_on_turntable.yaml",  # a constraint with a dt term, eq. (14.23)
    SYSTEMS / "bead_on_rotating_hoop.yaml",
    SYSTEMS / "spinning_top.yaml",
    SYSTEMS / "appell_hamel.yaml",  # nonlinear in the rates, homogeneous of degree one
    SYSTEMS / "chaplygin_sleigh.yaml",
    ROOT / "tests" / "frames" / "unbalanced.yaml",  # a frame turned by W*t
    VARIANTS / "rolling3" / "r3_wheel_turntable.yaml",
]
CONSERVATIVE = [
    SYSTEMS / "spinning_top.yaml",
    SYSTEMS / "rolling_disk.yaml",
    SYSTEMS / "cylinder_in_cylinder.yaml",
    SYSTEMS / "chaplygin_ball.yaml",
    SYSTEMS / "appell_hamel.yaml",
    SYSTEMS / "four_bar_linkage.yaml",
    ROOT / "tests" / "cases" / "quaternion_body_rates.yaml",
]


def _motions_move(derivation) -> bool:
    """Some velocity of the closed route has a term free of the rates, or depends on t."""
    parts = [m.linear for m in derivation.motions] + [m.angular for m in derivation.motions if m.angular]
    return any(S.T in sp.Matrix(p.partials).free_symbols | sp.Matrix(p.velocity0).free_symbols
               or any(sp.simplify(e) != 0 for e in p.velocity0) for p in parts)


@pytest.mark.parametrize("path", MOVING_OR_NOT, ids=lambda p: Path(p).stem)
def test_a_moving_support_is_read_from_the_file_as_the_chapter_s_motions_show_it(path):
    derivation = derived_file(path)
    said = MOVING_SUPPORT in conservation_problems(derivation)
    assert said == _motions_move(derivation)


@pytest.mark.parametrize("path", CONSERVATIVE, ids=lambda p: Path(p).stem)
def test_where_energy_is_conserved_T_is_half_u_M_u_of_generated_code(path, rng):
    derivation = derived_file(path)
    assert conservation_problems(derivation) == []
    system, k = derivation.system, derivation.k
    module = load_generated(derivation)
    values, missing = parameter_values(system)
    assert not missing
    p = [float(values[S.value(n)]) for n in module.PARAMETERS]
    T = energy_expressions(derivation)[0]  # Σ ½ m v·v + ½ ω·Iω from the closed route's motions
    states = rng.uniform(-1, 1, (4, len(module.STATE)))
    for name in ("q0", "q1", "q2", "q3"):  # Euler parameters on their sphere, as the file keeps them
        if name in module.STATE:
            i = module.STATE.index(name)
            states[:, i:i + 4] /= np.linalg.norm(states[:, i:i + 4], axis=1)[:, None]
            break
    ours = kinetic_energy(lambda t, x: module.mass_matrix(t, x, p, ()), np.zeros(4), states, k)
    for x, value in zip(states, ours):
        at = {S.value(n): v for n, v in zip(module.STATE, x)} | values | {S.T: 0.0}
        expected = float(sp.N(T.xreplace(at)))
        assert value == pytest.approx(expected, rel=1e-9, abs=1e-12)


def test_a_large_system_simulates_from_generated_code_without_the_closed_forms(monkeypatch):
    from typer.testing import CliRunner

    import gacli.pipeline as pipeline
    from gacli.cli import app

    def refused(*args, **kwargs):
        raise AssertionError("the closed route ran")

    monkeypatch.setattr(pipeline, "derive", refused)
    result = CliRunner().invoke(app, ["simulate", str(SYSTEMS / "whipple_bicycle.yaml"), "--t-end", "0.2",
                                      "--init", "dot(wheel_R)=-8,roll=0.02", "--points", "21"])
    assert result.exit_code == 0, result.output
    drift = float(result.output.split("relative ")[1].split(")")[0])
    assert drift < 1e-8


def _system(tmp_path, text):
    from gacli.pipeline import STEPS, run

    path = tmp_path / "s.yaml"
    path.write_text(text, encoding="utf-8")
    return run(path, needs=STEPS).derivation


def test_a_constant_force_at_a_point_that_moves_with_t_is_no_conservative_load(tmp_path):
    """−F·r depends on t when r does: E then drifts, and was reported as conserved (a reviewer's file)."""
    d = _system(tmp_path, "gacli: 1\nname: s\nparameters: {m: {value: 1}, k: {value: 4}, F: {value: 3}}\n"
                          "coordinates: [x]\nbodies: {p: {mass: m, position: [x, 0, 0]}}\npotential: k*x**2/2\n"
                          "loads:\n  - {force: [F, 0, 0], at: [x + sin(t), 0, 0]}\n")
    assert conservation_problems(d) == ["a force at a point that moves with t"]


def test_a_constraint_nonlinear_in_the_rates_is_said_so_not_said_to_depend_on_t(tmp_path):
    d = _system(tmp_path, "gacli: 1\nname: s\nparameters: {m: {value: 1}, g: {value: 9.81}, c: {value: 0.5}}\n"
                          "coordinates: [x, y, z]\nconstraints:\n  - dot(z) = -c*(dot(x)**2 + dot(y)**2)\n"
                          "bodies:\n  p: {mass: m, position: [x, y, z]}\npotential: m*g*z\n")
    assert conservation_problems(d) == ["a constraint nonlinear in the rates and not homogeneous of degree one in them"]
