"""gacli.linearize and gacli.simulate in the Python API, checked against the textbook.

A cylinder of radius a rolling inside one of radius b swings as a pendulum
of frequency sqrt(2g/(3c)), c = b - a (chapter 14, section 14.4): the
linearization's eigenvalues are +-i times it, and a small swing follows
theta0 cos(omega t). The file computes c from b, so setting b moves c.
"""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

from conftest import ROOT, SYSTEMS, derived

import gacli

CYLINDER = SYSTEMS / "cylinder_in_cylinder.yaml"


def omega(b: float, a: float = 0.1, g: float = 9.81) -> float:
    return math.sqrt(2 * g / (3 * (b - a)))


@pytest.mark.parametrize("system", [str(CYLINDER), CYLINDER, "loaded", "derived"])
def test_linearize_takes_a_path_a_system_or_a_derivation(system):
    system = {"loaded": gacli.load(CYLINDER), "derived": derived("cylinder_in_cylinder")}.get(system, system)
    result = gacli.linearize(system, parameters={"b": 0.7})
    np.testing.assert_allclose(result.eigenvalues(["theta", "dot(theta)"]),
                               [-1j * omega(0.7), 1j * omega(0.7)], atol=1e-12)


def test_simulate_swings_as_the_pendulum():
    theta0 = 1e-3
    run = gacli.simulate(CYLINDER, parameters={"b": "0.4 + 0.2"}, initial={"theta": theta0}, t_end=2.0, points=5)
    np.testing.assert_allclose(run.column("theta"), theta0 * np.cos(omega(0.6) * run.t), rtol=0, atol=1e-9)
    assert run.parameters["c"] == pytest.approx(0.5)


def test_the_modules_of_the_same_names_still_work_and_calls_repeat():
    from gacli import linearize as module

    assert callable(module.linearize_symbolic)
    first = gacli.linearize(CYLINDER).A
    second = gacli.linearize(CYLINDER).A   # the first call imported the module: it must stay callable
    np.testing.assert_array_equal(first, second)
    assert {"linearize", "simulate"} <= set(gacli.__all__) and {"linearize", "simulate"} <= set(dir(gacli))


def test_a_module_imported_first_is_callable_too():
    code = ("import gacli.linearize, gacli.simulate, gacli; "
            f"print(gacli.linearize({str(CYLINDER)!r}).A.shape, callable(gacli.simulate))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300,
                          env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["(3,", "3)", "True"]


def test_importing_gacli_stays_light():
    code = "import sys, gacli; print('sympy' in sys.modules, 'numpy' in sys.modules)"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60,
                          env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    assert done.stdout.split() == ["False", "False"], done.stderr
