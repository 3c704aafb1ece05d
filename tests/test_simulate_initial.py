"""Initial states on the holonomic constraints (issue #29, item 7): completed where coordinates are left out, else refused.

The four-bar's loop (systems/four_bar_linkage.yaml) must close at the state
simulate starts from, checked here with the linkage's geometry written out
in NumPy; a quaternion body's Euler parameters must have unit length; a
state given whole that violates a constraint is refused with its residual.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

import gacli
from gacli.simulate.initial import InitialStateNote
from gacli.simulate.spec import SimulationError

ROOT = Path(__file__).resolve().parent.parent
FOUR_BAR = ROOT / "systems" / "four_bar_linkage.yaml"
QUATERNION = ROOT / "tests" / "cases" / "quaternion_body_rates.yaml"
l0, l1, l2, l3 = 1.0, 0.3, 1.0, 0.8


def _start(path, initial):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sim = gacli.simulate(path, initial=initial, t_end=0.01, points=3)
    notes = [str(w.message) for w in caught if issubclass(w.category, InitialStateNote)]
    return sim, notes


def test_the_four_bar_s_loop_is_closed_from_the_crank_angle_alone():
    sim, notes = _start(FOUR_BAR, {"th1": 0.2})
    th1, th2, th3 = (sim.column(q)[0] for q in ("th1", "th2", "th3"))
    assert th1 == 0.2 and notes and "th2" in notes[0] and "th3" in notes[0]
    coupler_end = l1 * np.array([np.cos(th1), np.sin(th1)]) + l2 * np.array([np.cos(th2), np.sin(th2)])
    rocker_end = np.array([l0, 0.0]) + l3 * np.array([np.cos(th3), np.sin(th3)])
    assert np.max(np.abs(coupler_end - rocker_end)) < 1e-9


def test_euler_parameters_left_out_are_put_on_the_unit_sphere():
    sim, notes = _start(QUATERNION, {"q0": 0.6})
    q = np.array([sim.column(f"q{i}")[0] for i in range(4)])
    assert q[0] == 0.6 and abs(np.dot(q, q) - 1.0) < 1e-9 and notes


def test_a_state_given_whole_off_the_loop_is_refused_with_its_residual():
    with pytest.raises(SimulationError, match=r"violates the constraint .* \(residual 0\.506\)"):
        _start(FOUR_BAR, {"th1": 0.2, "th2": 0.0, "th3": 0.0})


def test_a_state_on_the_constraints_is_left_as_given():
    sim, notes = _start(FOUR_BAR, {"th1": 0.2, "th2": 0.8326478947, "th3": 1.612133842})
    assert sim.column("th2")[0] == 0.8326478947 and not notes


def test_completed_angles_are_the_turns_nearest_where_they_started():
    # A reviewer's four-bar (relative angles, closed by coincide) was completed at q2 = -14.08,
    # q3 = 27.50: on the loop, but two and four turns from the -1.52 and 2.36 a reader expects.
    path = ROOT / "benchmarks" / "kane_set" / "variants" / "linkages5" / "l5_fourbar_docs.yaml"
    sim, notes = _start(path, {"q1": 0.3})
    q2, q3 = (sim.column(q)[0] for q in ("q2", "q3"))
    assert notes and abs(q2) <= np.pi and abs(q3) <= np.pi, (q2, q3)
    from gacli.algebra import symbols as S
    from gacli.numeric.parameters import parameter_values

    system = gacli.load(path)
    values = {**parameter_values(system)[0], S.value("q1"): 0.3, S.value("q2"): q2, S.value("q3"): q3}
    for c in system.constraints:
        if c.relation is not None:
            assert abs(float(c.relation.xreplace(values))) < 1e-8
