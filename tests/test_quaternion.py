"""A free body in Euler parameters: generated code regular at every attitude (issue #28).

tests/cases/quaternion_body_rates.yaml has seven dependent rates (ṙ and the
four λ̇), more than one adjugate takes; they were solved by SymPy's LU,
whose pivot was λ₀, and the generated rhs divided by it (a ZeroDivisionError
at λ₀ = 0, an ordinary half-turn). The reference here is Newton's and
Euler's equations in body axes written by hand, with ṙ = R v and
λ̇ = ½ Eᵀ ω.
"""

from __future__ import annotations

import importlib.util
import math

import numpy as np
import pytest

from conftest import ROOT

CASE = ROOT / "tests" / "cases" / "quaternion_body_rates.yaml"
PARAMETERS = {"m": 2.0, "A": 1.0, "B": 2.0, "C": 3.0, "g": 9.81}


@pytest.fixture(scope="module")
def module(tmp_path_factory):
    import gacli

    text = gacli.emit(gacli.derive(gacli.load(CASE)), "python")
    (name, source), = text.items()
    path = tmp_path_factory.mktemp("quaternion") / name
    path.write_text(source)
    spec = importlib.util.spec_from_file_location("quaternion_body_rates", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def rotation(q: np.ndarray) -> np.ndarray:
    """Body axes → N for the unit quaternion q = (λ₀, λ₁, λ₂, λ₃)."""
    a, b, c, d = q
    return np.array([
        [a*a + b*b - c*c - d*d, 2*(b*c - a*d), 2*(b*d + a*c)],
        [2*(b*c + a*d), a*a - b*b + c*c - d*d, 2*(c*d - a*b)],
        [2*(b*d - a*c), 2*(c*d + a*b), a*a - b*b - c*c + d*d],
    ])


def reference(q: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
    m, g = PARAMETERS["m"], PARAMETERS["g"]
    inertia = np.array([PARAMETERS["A"], PARAMETERS["B"], PARAMETERS["C"]])
    R = rotation(q)
    a, b, c, d = q
    E = np.array([[-b, a, d, -c], [-c, -d, a, b], [-d, c, -b, a]])
    weight_in_body = R.T @ np.array([0.0, 0.0, -m * g])
    v_dot = weight_in_body / m - np.cross(w, v)
    w_dot = -np.cross(w, inertia * w) / inertia
    return np.concatenate([R @ v, E.T @ w / 2, v_dot, w_dot])


def attitude(q0: float, rng) -> np.ndarray:
    rest = rng.normal(size=3)
    rest *= math.sqrt(1 - q0 * q0) / np.linalg.norm(rest)
    return np.concatenate([[q0], rest])


@pytest.mark.parametrize("q0", [0.5, 1e-3, 1e-6, 1e-9, 0.0])
def test_generated_rhs_agrees_with_newton_euler_at_every_attitude(module, q0, rng):
    p = [PARAMETERS[name] for name in module.PARAMETERS]
    for _ in range(3):
        q, v, w = attitude(q0, rng), rng.normal(size=3), rng.normal(size=3)
        x = np.concatenate([rng.normal(size=3), q, v, w])
        got = np.asarray(module.rhs(0.0, x, p), dtype=float)
        expected = reference(q, v, w)
        assert np.all(np.isfinite(got))
        assert np.max(np.abs(got - expected)) <= 1e-9 * max(1.0, np.max(np.abs(expected)))
