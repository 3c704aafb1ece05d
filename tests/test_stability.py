"""Stability of steady motions against the textbook results (docs/steady.md).

Each published condition is written here and compared with what gacli
reads from the characteristic polynomial of the reduced A.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
import sympy as sp
from typer.testing import CliRunner

from conftest import SYSTEMS, derived
from gacli.cli import app
from gacli.steady.stability import stability, stability_symbolic

W = sp.Symbol("omega", real=True)


def _p(name: str) -> sp.Symbol:
    return sp.Symbol(name, real=True)


def _agrees(conditions, literature, symbols, rng, samples=200) -> None:
    """Every condition > 0 together holds exactly where the literature's inequality does."""
    for _ in range(samples):
        values = {s: float(rng.uniform(0.1, 3.0)) for s in symbols}
        values[W] = float(rng.uniform(-6.0, 6.0))
        ours = all(float(c.xreplace(values)) > 0 for c in conditions)
        assert ours == bool(literature.xreplace(values)), values


def test_upright_disk_is_stable_iff_spin_squared_exceeds_g_over_3r(rng):
    """Thin disk (I_axle = mr²/2, I_diameter = mr²/4): stable iff ω² > g/(3r) (e.g. Neimark and Fufaev)."""
    m, r, g = _p("m"), _p("r"), _p("g")
    result = stability_symbolic(derived("rolling_disk"), {"dot(spin)": W})
    assert result.steady and result.test == "even"
    assert result.reduction.ignorable == ("x", "y", "yaw", "spin")
    assert len(result.conditions) == 1
    condition = result.conditions[0]
    # The boundary is the literature's, and the sign is right on either side of it.
    assert sp.simplify(condition.subs(W, sp.sqrt(g / (3 * r)))) == 0
    _agrees(result.conditions, sp.Gt(W**2, g / (3 * r)), (m, r, g), rng)


def test_sleeping_top_is_stable_iff_c2w2_exceeds_4amgl(rng):
    """Klein and Sommerfeld's condition for the sleeping top: C²ω² > 4 A m g l (A about the fixed point)."""
    m, g, l, A, C = (_p(n) for n in ("m", "g", "l", "A", "C"))
    d = __import__("gacli").derive(__import__("gacli").load(SYSTEMS / "sleeping_top.yaml"))
    result = stability_symbolic(d, {"dot(spin)": W})
    assert result.steady and result.test == "even"
    _agrees(result.conditions, sp.Gt(C**2 * W**2, 4 * A * m * g * l), (m, g, l, A, C), rng)


def test_sleigh_runs_straight_one_way_only():
    """Chaplygin's sleigh: straight motion is stable iff the centre of mass leads the blade (b v > 0)."""
    v = sp.Symbol("v", real=True)
    result = stability_symbolic(derived("chaplygin_sleigh"), {"dot(s)": v})
    assert result.reduction.ignorable == ("x", "y", "theta")
    assert result.test == "hurwitz"
    assert [sp.simplify(c / v) > 0 for c in result.conditions] == [True]  # b > 0 in the file: v > 0
    forward, backward = stability(derived("chaplygin_sleigh"), {"dot(s)": 1.0}), \
        stability(derived("chaplygin_sleigh"), {"dot(s)": -1.0})
    assert forward.steady and backward.steady
    assert forward.stable and not backward.stable
    # The turning mode's rate, -m b v / (I + m b²) (Bloch 2003, 1.7), with the file's m, I, b.
    np.testing.assert_allclose(sorted(backward.eigenvalues.real), [0.0, 1 * 0.3 * 1 / (0.1 + 1 * 0.3**2)],
                               atol=1e-12)


def test_disk_numeric_verdict_on_either_side_of_the_threshold():
    threshold = np.sqrt(9.81 / (3 * 0.3))
    assert stability(derived("rolling_disk"), {"dot(spin)": 1.01 * threshold}).stable
    assert not stability(derived("rolling_disk"), {"dot(spin)": 0.99 * threshold}).stable


def test_a_point_that_is_not_steady_is_said_to_be_so():
    assert not stability(derived("rolling_disk"), {"lean": 0.3, "dot(spin)": 1.0}).steady


def test_linearize_symbolic_honours_at_set_and_states():
    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "rolling_disk.yaml"), "--symbolic",
                                      "--at", "dot(spin)=w", "--set", "g=10,r=0.5", "--states", "lean,dot(lean)"])
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[1].split() == ["lean", "dot(lean)"]
    assert lines[2].split() == ["lean", "0", "1"]
    # d(dot(lean))/d(lean) = 4 g / (5 r) at upright (the disk's lean equation), with g = 10, r = 0.5.
    assert lines[3].split()[0] == "dot(lean)" and float(lines[3].split()[1]) == pytest.approx(16.0)


def test_linearize_symbolic_keeps_a_named_rate_free():
    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "rolling_disk.yaml"), "--symbolic",
                                      "--at", "dot(spin)=w", "--states", "dot(yaw),dot(lean)"])
    assert result.exit_code == 0, result.output
    assert "-2*w" in result.output


def test_sweep_option_is_checked_before_work():
    bad = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "rolling_disk.yaml"), "--sweep", "dot(spin)=3:1"])
    assert bad.exit_code == 2 and "START < STOP" in bad.output
    bad = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "rolling_disk.yaml"), "--sweep", "nothing=0:1"])
    assert bad.exit_code == 2 and "not a state, input or parameter: nothing" in bad.output


def test_disk_sweep_finds_the_threshold():
    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "rolling_disk.yaml"),
                                      "--sweep", "dot(spin)=0:8:9"])
    assert result.exit_code == 0, result.output
    threshold = np.sqrt(9.81 / (3 * 0.3))
    found = re.search(r"stable for dot\(spin\) in \[([-0-9.e]+), ([-0-9.e]+)\]", result.output)
    assert found and float(found.group(1)) == pytest.approx(threshold, abs=1e-8) and float(found.group(2)) == 8


def test_sweep_over_a_parameter():
    """At spin ω the disk stands while g < 3 r ω² (the same threshold read the other way): 22.5 at ω = 5."""
    from gacli.steady.sweep import sweep

    result = sweep(derived("rolling_disk"), "g", 1.0, 40.0, at={"dot(spin)": 5.0}, points=9)
    assert len(result.intervals) == 1
    low, high = result.intervals[0]
    assert low == 1.0 and high == pytest.approx(3 * 0.3 * 25, abs=1e-8)


def test_bicycle_pitch_is_held_not_a_state():
    """The front wheel's contact fixes the pitch: it is no direction of its own (docs/steady.md)."""
    result = stability(derived("whipple_bicycle"), {"dot(wheel_R)": 5.0 / 0.3})
    assert result.reduction.held == ("pitch",)
    assert result.reduction.coordinates == ("roll", "steer") and result.stable


def test_sweep_says_when_the_point_is_no_steady_motion():
    # Leaning at 0.2 rad without turning, the disk falls: the eigenvalues describe no steady motion.
    result = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "rolling_disk.yaml"),
                                      "--sweep", "dot(spin)=1:5:3", "--at", "lean=0.2"])
    assert result.exit_code == 0 and "not a steady motion" in result.output
    fine = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "rolling_disk.yaml"), "--sweep", "dot(spin)=1:5:3"])
    assert "not a steady motion" not in fine.output


def test_a_swept_parameter_without_a_value_needs_no_set(tmp_path):
    # 'no value for the parameters k (give them with --set)' for the very parameter swept.
    from gacli.loader.loading import loads
    from gacli.mechanics.equations import derive
    from gacli.steady.sweep import sweep

    system = loads("gacli: 1\nname: spring\nparameters: {m: {value: 1}, k: {}}\ncoordinates: [x]\n"
                   "bodies: {b: {mass: m, position: [x, 0, 0]}}\npotential: k*x**2/2\n")
    result = sweep(derive(system), "k", -1.0, 1.0, points=5)
    assert result.stable[-1] and not result.stable[0]  # m x'' = -k x: a spring for k > 0 only


def test_a_sweep_goes_on_past_a_value_where_the_equations_are_singular():
    """Euler angles are singular with the top upright (theta = 0): that row is undefined, the others
    are linearized; the sweep stopped there with an error before."""
    from gacli.steady.sweep import sweep

    result = sweep(derived("spinning_top"), "theta", -0.5, 0.5, at={"dot(q)": 20.0}, points=5)
    assert result.stable[2] is None and all(v is not None for i, v in enumerate(result.stable) if i != 2)
    assert np.isnan(result.eigenvalues[2]).all() and np.isfinite(result.eigenvalues[[0, 1, 3, 4]]).all()
    assert "Singular matrix" in result.undefined
    cli = CliRunner().invoke(app, ["linearize", str(SYSTEMS / "spinning_top.yaml"), "--sweep", "theta=-0.5:0.5:5",
                                   "--at", "dot(q)=20"])
    assert cli.exit_code == 0, cli.output
    assert re.search(r"^\s+0\s+-\s+not defined here$", cli.output, re.M) and "1 of the 5 values is not defined" in cli.output


ROD = """
gacli: 1
name: rod
parameters:
  m: {value: 1}
functions:
  Omega: rate of the rod
coordinates: [r, theta]
constraints:
  - dtheta = Omega*dt
independent: [r]
bodies:
  bead: {mass: m, position: [r*cos(theta), r*sin(theta)]}
"""


def test_a_coordinate_a_function_of_time_multiplies_is_not_ignorable(tmp_path):
    # r'' = Ω² r: a bead flung out along a rod turned at Ω. With Ω probed at 0, r looked ignorable,
    # and the sweep said 'stable for Omega in [0.5, 3]'; the eigenvalues are ±Ω.
    path = tmp_path / "rod.yaml"
    path.write_text(ROD)
    import gacli

    result = gacli.stability(str(path), {"Omega": 2.0})
    assert not result.stable and "r" in result.state
    assert np.allclose(sorted(result.eigenvalues.real), [-2.0, 2.0])
    out = CliRunner().invoke(app, ["linearize", str(path), "--sweep", "Omega=0.5:3:6"])
    assert out.exit_code == 0 and "stable nowhere in [0.5, 3]" in out.output
