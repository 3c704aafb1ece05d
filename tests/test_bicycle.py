"""The Whipple bicycle benchmark (Meijaard, Papadopoulos, Ruina and Schwab 2007).

systems/whipple_bicycle.yaml is written with the frame and rolling
vocabulary; linearized at upright, straight-ahead motion it must give the
benchmark's linear equations. The reference is the matrix SymPy's own bicycle
test (test_kane3.py) holds from the paper, for the states roll, steer and
their rates, as a function of the forward speed v.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
import sympy as sp

from conftest import ROOT

BICYCLE = ROOT / "systems" / "whipple_bicycle.yaml"
STATES = ["roll", "steer", "dot(roll)", "dot(steer)"]
REAR_RADIUS = 0.3
# The paper's weave and capsize speeds (m/s).
PAPER_WEAVE, PAPER_CAPSIZE = 4.292382534, 6.024262018


def reference(v: float) -> np.ndarray:
    return np.array([
        [0, 0, 1.0, 0],
        [0, 0, 0, 1.0],
        [9.48977444677355, -0.891197738059089 * v**2 - 0.571523173729245, -0.105522449805691 * v,
         -0.330515398992311 * v],
        [11.7194768719633, -1.97171508499972 * v**2 + 30.9087533932407, 3.67680523332152 * v,
         -3.08486552743311 * v],
    ])


@functools.lru_cache(maxsize=1)
def bicycle():
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    return derive(load(BICYCLE))


def ours(v: float) -> np.ndarray:
    from gacli.linearize import linearize

    # Forward speed v: the rear wheel turns at v / r relative to the frame.
    return linearize(bicycle(), {"dot(wheel_R)": v / REAR_RADIUS}).block(STATES)


def sorted_eigenvalues(A: np.ndarray) -> np.ndarray:
    values = np.linalg.eigvals(A)
    return values[np.lexsort((values.imag, values.real))]


def test_bicycle_has_three_degrees_of_freedom():
    d = bicycle()
    assert d.independent == ("roll", "wheel_R", "steer")
    assert d.rates.constraints_used == 5  # rear wheel 2 rows, front wheel 3 (one holonomic)


@pytest.mark.parametrize("v", [0, 1, 2, 3, 4, 5])
def test_linearized_matrix_is_the_benchmarks(v):
    np.testing.assert_allclose(ours(v), reference(v), rtol=1e-10, atol=1e-10)


def test_eigenvalues_at_every_speed():
    for v in np.arange(0.0, 10.01, 0.5):
        np.testing.assert_allclose(sorted_eigenvalues(ours(v)), sorted_eigenvalues(reference(v)),
                                   rtol=1e-9, atol=1e-9)


def _weave(A_of):
    def real_part(v):
        values = np.linalg.eigvals(A_of(v))
        return values[np.abs(values.imag) > 1e-9].real.max()
    return real_part


def _capsize(A_of):
    def real_part(v):
        values = np.linalg.eigvals(A_of(v))
        return values[np.abs(values.imag) <= 1e-9].real.max()
    return real_part


def test_weave_and_capsize_speeds():
    from scipy.optimize import brentq

    weave = brentq(_weave(ours), 3.0, 5.0, xtol=1e-12)
    capsize = brentq(_capsize(ours), 5.0, 7.0, xtol=1e-12)
    assert abs(weave - brentq(_weave(reference), 3.0, 5.0, xtol=1e-12)) < 1e-6
    assert abs(capsize - brentq(_capsize(reference), 5.0, 7.0, xtol=1e-12)) < 1e-6
    assert abs(weave - PAPER_WEAVE) < 1e-6
    assert abs(capsize - PAPER_CAPSIZE) < 1e-6


def test_symbols_are_plain():
    assert all(isinstance(s, sp.Symbol) for s in bicycle().speeds)
