"""gacli simulate: the generated module integrated against closed forms and invariants.

The sphere on a turntable turning at a constant rate moves on a circle
(eq. 14.30); the cylinder in a cylinder oscillates with the period
2π sqrt(3c/(2g)); the heavy top keeps its energy and its angular momentum
about the vertical. Then the options (comma splitting, missing values named),
the CSV, the plot and the message when the extra is not installed.
"""

from __future__ import annotations

import math
import re
import sys

import numpy as np
import pytest

from conftest import derived
from gacli.errors import GacliError
from gacli.simulate import (
    MissingExtraError, SimulationError, conservation_problems, parse_assignments, simulate,
    spec_from_options, split_top_level, summary_lines, to_csv,
)

pytest.importorskip("scipy")

SPHERE_AT_REST = ["F_x=0,F_y=0,F_z=0", "M_x=0,M_y=0,M_z=0"]
SPRING = """
gacli: 1
name: spring
parameters: [m, k]
coordinates: [x]
bodies: {mass: {mass: m, position: [x, 0]}}
potential: k*x**2/2
"""


def run(name, **options):
    return simulate(derived(name), spec_from_options(**options))


def sphere(omega: str, t_end: float, **options):
    init = "x=0.3,y=-0.1,dot(x)=0.2,dot(y)=0.1,dot(q_z)=1"
    return run("sphere_on_turntable", init=[init], function=[f"Omega={omega}"], input=SPHERE_AT_REST,
               t_end=t_end, **options)


# -- physics --------------------------------------------------------------------

def test_sphere_on_turntable_moves_on_the_circle_of_14_30():
    # Omega const, no force: 7 x'' + 2 Omega y' = 0, 7 y'' - 2 Omega x' = 0, so (x', y')
    # turns at w = 2 Omega/7 and the centre runs on a circle of radius |v0|/w about
    # c = p0 + k x v0 / w, with p(t) = c - k x v(t) / w.
    omega = 2.0
    sim = sphere(str(omega), t_end=6.0, rtol=1e-11, atol=1e-13)
    x0, y0, vx0, vy0 = sim.states[0, :4]
    w = 2 * omega / 7
    centre = np.array([x0 - vy0 / w, y0 + vx0 / w])
    radius = math.hypot(vx0, vy0) / w
    assert radius == pytest.approx(7 * math.hypot(0.2, 0.1) / (2 * omega))
    c, s = np.cos(w * sim.t), np.sin(w * sim.t)
    vx, vy = c * vx0 - s * vy0, s * vx0 + c * vy0
    expected = np.column_stack([centre[0] + vy / w, centre[1] - vx / w])
    path = sim.states[:, :2]
    assert np.max(np.abs(np.hypot(*(path - centre).T) - radius)) < 1e-9
    assert np.max(np.abs(path - expected)) < 1e-9
    assert np.allclose(sim.column("dot(q_z)"), 1.0, rtol=0, atol=1e-12)  # M_z = 0: the spin keeps
    assert sim.energy is None and any("inputs" in why for why in sim.not_conservative)
    assert set(sim.residuals) == {"constraints[0]", "constraints[1]"}
    assert all(r.max_abs < 1e-8 for r in sim.residuals.values())


def test_a_varying_rate_enters_with_its_derivative():
    # Omega = 2 + sin(t): 7/5 x'' = -2/5 (Omega y' + Omega' y), 7/5 y'' = 2/5 (Omega x' + Omega' x)
    from scipy.integrate import solve_ivp

    sim = sphere("2 + sin(t)", t_end=3.0, rtol=1e-11, atol=1e-13)

    def by_hand(t, s):
        x, y, vx, vy = s
        omega, domega = 2 + math.sin(t), math.cos(t)
        return [vx, vy, -2 / 7 * (omega * vy + domega * y), 2 / 7 * (omega * vx + domega * x)]

    reference = solve_ivp(by_hand, (0, 3.0), [0.3, -0.1, 0.2, 0.1], method="DOP853",
                          rtol=1e-12, atol=1e-14, t_eval=sim.t)
    assert np.max(np.abs(sim.states[:, :4] - reference.y.T)) < 1e-9


def test_cylinder_in_cylinder_small_oscillations_have_the_period_2pi_sqrt_3c_over_2g():
    sim = run("cylinder_in_cylinder", init=["theta=0.001"], t_end=5.0, points=5001)
    theta = sim.column("theta")
    i = np.nonzero(np.sign(theta[:-1]) != np.sign(theta[1:]))[0]
    crossings = sim.t[i] - theta[i] * (sim.t[i + 1] - sim.t[i]) / (theta[i + 1] - theta[i])
    periods = crossings[2:] - crossings[:-2]
    c, g = 0.5 - 0.1, 9.81
    assert len(periods) >= 4
    assert np.allclose(periods, 2 * math.pi * math.sqrt(3 * c / (2 * g)), rtol=1e-6)
    assert sim.energy_relative_drift < 1e-8
    assert sim.residuals["constraints[0]"].max_abs < 1e-10


def test_heavy_top_keeps_its_energy_and_its_vertical_angular_momentum():
    # About the fixed point the transverse moment is A + m l^2 and the axial C; with
    # body-axis omega = (phi' sin(theta) sin(psi) + theta' cos(psi), phi' sin(theta) cos(psi)
    # - theta' sin(psi), q') and the vertical (sin(theta) sin(psi), sin(theta) cos(psi),
    # cos(theta)) in body axes, L_z = (A + m l^2) phi' sin^2(theta) + C q' cos(theta).
    sim = run("spinning_top", init=["theta=0.5,dot(phi)=3,dot(theta)=0.2,dot(q)=60"], t_end=3.0,
              rtol=1e-11, atol=1e-13)
    p = sim.parameters
    assert conservation_problems(derived("spinning_top")) == []
    theta, dphi, dq = sim.column("theta"), sim.column("dot(phi)"), sim.column("dot(q)")
    lz = (p["A"] + p["m"] * p["l"] ** 2) * dphi * np.sin(theta) ** 2 + p["C"] * dq * np.cos(theta)
    assert np.max(np.abs(lz - lz[0])) < 1e-9 * abs(lz[0])
    assert sim.energy_relative_drift < 1e-9
    assert np.ptp(theta) > 0.1  # it nutates: the invariants are not trivially constant


@pytest.mark.parametrize("speed, stable", [(5.0, True), (3.0, False)])
def test_the_bicycle_is_self_stable_between_its_weave_and_capsize_speeds(speed, stable):
    """The benchmark's linear analysis (weave 4.29 m/s, capsize 6.02 m/s) seen in the nonlinear motion:
    a push in roll rate dies out at 5 m/s and grows into a weave at 3 m/s."""
    sim = run("whipple_bicycle", init=[f"dot(wheel_R)={speed / 0.3},dot(roll)=0.1"], t_end=4.0, points=401)
    late = np.abs(sim.column("dot(roll)"))[sim.t >= 3.0].max()
    assert (late < 0.02) if stable else (late > 0.2)
    assert sim.energy_relative_drift < 1e-9
    assert all(np.max(np.abs(r.values)) < 1e-6 for r in sim.residuals.values())


def test_inputs_may_feed_back_the_state():
    # A central force keeps the areal rate q' = r^2 theta' (the state entry dot(q)).
    sim = run("particle_in_plane", init=["r=1.5,dot(r)=0,dot(q)=1"], input=["R=-4*(r-1)-dot(r)", "S=0"],
              t_end=4.0)
    assert np.allclose(sim.column("dot(q)"), 1.0, rtol=0, atol=1e-10)
    assert np.ptp(sim.column("r")) > 0.1


def test_energy_of_a_conservative_system_without_file_values():
    import gacli

    d = gacli.derive(gacli.loads(SPRING))
    sim = simulate(d, spec_from_options(set=["m=2,k=2*m"], init=["x=1"], t_end=3.0, points=31))
    assert np.allclose(sim.column("x"), np.cos(math.sqrt(2) * sim.t), atol=1e-8)
    assert sim.energy[0] == pytest.approx(2.0)
    assert sim.energy_drift < 1e-8


# -- options ----------------------------------------------------------------------

def test_splitting_on_commas_respects_parentheses():
    assert parse_assignments("a=1,b=f(1,2)") == [("a", "1"), ("b", "f(1,2)")]
    assert parse_assignments(" x = 1 , dot(x)=atan2(1, (2)), ") == [("x", "1"), ("dot(x)", "atan2(1, (2))")]
    assert split_top_level("x, dot(x)") == ["x", "dot(x)"]
    for bad, message in (("a=1,b=(", "unclosed '('"), ("a=1)", "unmatched ')'"), ("a", "expected name=value")):
        with pytest.raises(SimulationError, match=re.escape(message)):
            parse_assignments(bad, "--set")


def test_a_missing_value_is_an_error_that_names_it():
    with pytest.raises(SimulationError) as caught:
        run("sphere_on_turntable", t_end=1.0)
    text = str(caught.value)
    assert "free function 'Omega' has no value" in text and "--function" in text
    assert "'F_x', 'F_y', 'F_z', 'M_x', 'M_y', 'M_z' have no values" in text
    import gacli

    with pytest.raises(SimulationError, match="parameter 'k' has no value: give it with --set"):
        simulate(gacli.derive(gacli.loads(SPRING)), spec_from_options(set=["m=1"]))


def test_wrong_names_are_errors_that_say_why():
    with pytest.raises(SimulationError) as caught:
        run("cylinder_in_cylinder", init=["dot(phi)=1,x=2"], set=["G=1,c=a+c"], show="theta,dot(psi)")
    problems = caught.value.problems
    assert any("'dot(phi)' is not in the state: its rate follows from the constraints" in p for p in problems)
    assert any("--init x: 'x' is not in the state" in p for p in problems)
    assert any("'G' is not a parameter of cylinder_in_cylinder (did you mean 'g'?)" in p for p in problems)
    assert any("the values of c refer to each other" in p for p in problems)
    assert any("--show dot(psi)" in p for p in problems)
    with pytest.raises(SimulationError, match="'t' is time"):
        run("cylinder_in_cylinder", set=["a=t"])
    with pytest.raises(SimulationError, match="not a method"):
        run("cylinder_in_cylinder", method="Euler")


def test_a_file_value_follows_the_parameters_it_names():
    sim = run("cylinder_in_cylinder", set=["b=0.7"], init=["theta=0.1"], t_end=0.1, points=3)
    assert sim.parameters["c"] == pytest.approx(0.6)


# -- results ---------------------------------------------------------------------

def test_csv_has_t_then_the_state_names():
    sim = run("cylinder_in_cylinder", init=["theta=0.1"], t_end=1.0, points=11)
    lines = to_csv(sim).splitlines()
    assert lines[0] == "t,theta,phi,dot(theta)"
    assert len(lines) == 12
    assert lines[1] == "0.0,0.1,0.0,0.0"
    last = [float(v) for v in lines[-1].split(",")]
    assert last[0] == 1.0 and last[1:] == list(sim.states[-1])


def test_summary_and_progress():
    seen = []
    sim = simulate(derived("cylinder_in_cylinder"), spec_from_options(init=["theta=0.1"], t_end=2.0),
                   progress=seen.append)
    assert seen == sorted(seen) and seen[-1] == 2.0 and len(seen) > 5
    lines = summary_lines(sim)
    assert lines[0].startswith("cylinder_in_cylinder: t = 0 to 2 with DOP853")
    assert any(line.startswith("energy: E(0) = ") for line in lines)
    assert any(line.startswith("constraints[0] a*dphi = c*dtheta: max |residual| = ") for line in lines)


def test_console_is_quiet_when_piped(capsys):
    from gacli.simulate import console as simulate_console

    with simulate_console.progress(1.0) as advance:
        assert advance is None
    simulate_console.summary(run("cylinder_in_cylinder", t_end=0.5, points=3))
    out, err = capsys.readouterr()
    assert out.startswith("cylinder_in_cylinder: t = 0 to 0.5") and err == ""


def test_the_generated_module_is_not_left_behind():
    before = set(sys.modules)
    run("cylinder_in_cylinder", t_end=0.1, points=3)
    assert not any(name.startswith("_gacli_simulate") for name in set(sys.modules) - before)


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_plot_file_is_written(tmp_path, suffix):
    pytest.importorskip("matplotlib")
    from gacli.simulate.plot import plot

    sim = sphere("2", t_end=2.0, points=101)
    target = tmp_path / "out" / f"sphere{suffix}"
    assert plot(sim, target, show=("x", "y"), phase=("x", "y")) == target
    assert target.stat().st_size > 1000
    assert [p.name for p in target.parent.iterdir()] == [target.name]  # no temporary left
    header = target.read_bytes()[:100]
    assert header.startswith(b"\x89PNG") if suffix == ".png" else b"<svg" in target.read_bytes()[:1000] or b"<?xml" in header


def test_plot_refuses_other_formats(tmp_path):
    from gacli.simulate.plot import check

    with pytest.raises(SimulationError, match=r"\.png or \.svg"):
        check(tmp_path / "plot.pdf")


def test_without_the_extra_the_error_says_what_to_install(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "scipy", None)
    monkeypatch.setitem(sys.modules, "scipy.integrate", None)
    with pytest.raises(MissingExtraError, match=r"pip install 'gacli\[sim\]'") as caught:
        run("cylinder_in_cylinder", t_end=0.1)
    assert isinstance(caught.value, GacliError) and "scipy" in str(caught.value)
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    from gacli.simulate.plot import check

    with pytest.raises(MissingExtraError, match=r"plotting needs matplotlib.*pip install 'gacli\[sim\]'"):
        check(tmp_path / "plot.png")


def test_an_input_that_cannot_be_evaluated_stops_with_the_time_and_the_state():
    with pytest.raises(SimulationError, match=r"cannot be evaluated at t = 1\.\d*: math domain error; "
                                              r"the state there: r = [-\d.]+, theta = "):
        run("particle_in_plane", init=["r=1,dot(q)=1"], input=["R=sqrt(1-t),S=0"], t_end=2.0)


def test_a_bicycle_that_falls_flat_stops_at_the_singular_configuration():
    # Ridden backwards it is unstable; lying flat, its rolling constraints lose rank and M is singular.
    # Either M stops being positive definite, or (the generated code solving for the dependent rates
    # as numbers, docs/program.md) its condition grows without bound and the integrator gives up.
    with pytest.raises(SimulationError, match=r"the motion has reached a configuration where the model is "
                                              r"singular.*; the state there: .*roll = 1\.5"):
        run("whipple_bicycle", init=["dot(wheel_R)=-16.6667,dot(roll)=0.1"], t_end=4.0, points=11)


def test_a_mass_matrix_wrong_from_the_start_blames_no_configuration():
    # Negative mass: the parameters are at fault at t = 0, not a motion that reached a singular point.
    with pytest.raises(SimulationError, match=r"at t = 0: the mass matrix is not positive definite; the state") as caught:
        run("cylinder_in_cylinder", set=["M=-1"], t_end=1.0)
    assert "configuration" not in str(caught.value)


def test_an_rtol_below_scipy_s_floor_is_raised_and_the_run_says_the_one_it_used():
    from gacli.simulate.run import RTOL_FLOOR, ToleranceNote

    with pytest.warns(ToleranceNote, match="--rtol 1e-20 is below what double precision resolves"):
        sim = run("cylinder_in_cylinder", init=["theta=0.1"], t_end=0.05, rtol=1e-20)
    assert sim.rtol == RTOL_FLOOR == pytest.approx(2.220446e-14)
    assert "rtol 2.22045e-14" in summary_lines(sim)[0]


def test_a_bad_tolerance_from_a_sweep_is_named_as_a_number():
    """A sweep hands NumPy floats: the message read 'found np.float64(-1.0)'."""
    with pytest.raises(GacliError, match=r"--rtol: expected a positive number, found -1\.0$"):
        run("cylinder_in_cylinder", init=["theta=0.1"], t_end=0.05, rtol=np.float64(-1.0))
