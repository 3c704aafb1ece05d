"""The generated code against SymPy, against each other, and against physics.

For every system in systems/ (and the tests' own, see EXTRA): the
generated Python module and the C library (gcc, and clang when installed)
give M, F and rhs that agree with direct SymPy evaluation of the derivation
at 20 seeded random states, to 1e-12 relative. Then the Python module is
integrated with SciPy and checked against closed forms: the sphere on a
turntable turning at a constant rate moves on a circle (eq. 14.30), and
the cylinder in a cylinder and the heavy top conserve energy.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from conftest import SYSTEMS, derived, evaluate
from gacli.algebra import symbols as S
from gacli.emit.naming import layout
from gacli.numeric.spheres import spheres
from test_emit_c import COMPILERS, CLibrary, compile_c
from test_emit_python import EXTRA, extra, write_python

CASES = sorted(p.stem for p in SYSTEMS.glob("*.yaml")) + sorted(EXTRA)
STATES = 20
RTOL = 1e-12


def derivation(name):
    return extra(name) if name in EXTRA else derived(name)


def close(a, b, rtol=RTOL) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return np.linalg.norm(a - b) <= rtol * max(1.0, np.linalg.norm(b))


def random_states(d, seed):
    """20 (t, x, p, r) drawn from a seeded generator; every value in [0.3, 1.2].

    The range keeps angles away from 0 and π/2, where coordinates such as
    the rolling disk's lean make M singular.
    """
    lay = layout(d)
    rng = np.random.default_rng(seed)
    # The two routes to Euler parameters' equations agree on their unit sphere, where they hold.
    on = [([lay.state.index(str(e)) for e in s.symbols], float(s.radius2)) for s in spheres(d.system)]
    for _ in range(STATES):
        x = rng.uniform(0.3, 1.2, len(lay.state))
        for i, radius2 in on:
            x[i] *= np.sqrt(radius2) / np.linalg.norm(x[i])
        yield (rng.uniform(0.3, 1.2), x, rng.uniform(0.3, 1.2, len(lay.parameters)), rng.uniform(0.3, 1.2, len(lay.r)))


def sympy_values(d, t, x, p, r):
    """M, F and [q', u'] by substituting the floats into the derivation itself (30 digits, see evaluate)."""
    lay = layout(d)
    values = {S.T: sp.Float(t, 30)}
    for symbols, numbers in ((lay.state_symbols, x), (lay.parameter_symbols, p), (lay.r_symbols, r)):
        values.update({s: sp.Float(v, 30) for s, v in zip(symbols, numbers)})

    k = d.k
    M = evaluate(d.mass_matrix, values).reshape(k, k)
    F = evaluate(d.forcing, values)
    qdot = evaluate([e for _, e in d.kinematic_equations], values)
    return M, F, np.concatenate([qdot, np.linalg.solve(M, F)])


def rhs_agrees(value, M, F, xdot, n) -> bool:
    """q' to RTOL; u' solves M u' = F with backward error below RTOL, and is near the exact u'.

    A solve's forward error is bounded by cond(M) times its backward error;
    up to cond(M) = 100 the bound asked for is RTOL, beyond it grows with cond(M).
    """
    value = np.asarray(value, dtype=float)
    u = value[n:]
    residual = np.linalg.norm(M @ u - F) <= RTOL * (np.linalg.norm(M) * np.linalg.norm(u) + np.linalg.norm(F))
    forward = close(u, xdot[n:], RTOL * max(1.0, np.linalg.cond(M) / 100))
    return close(value[:n], xdot[:n]) and residual and forward


@pytest.fixture(scope="module")
def python_module(tmp_path_factory):
    cache = {}

    def get(name):
        if name not in cache:
            cache[name] = write_python(derivation(name), tmp_path_factory.mktemp(f"py_{name}"))
        return cache[name]

    return get


@functools.cache
def reference(name):
    """The seeded states of a system with SymPy's M, F and [q', u'] at each (computed once)."""
    d = derivation(name)
    return [(state, sympy_values(d, *state)) for state in random_states(d, 1000 + CASES.index(name))]


@pytest.mark.parametrize("name", CASES)
def test_python_agrees_with_sympy(name, python_module):
    d, module = derivation(name), python_module(name)
    for seed, ((t, x, p, r), (M, F, xdot)) in enumerate(reference(name)):
        assert close(module.mass_matrix(t, x, p, r), M), (seed, "M")
        assert close(module.forcing(t, x, p, r), F), (seed, "F")
        assert rhs_agrees(module.rhs(t, x, p, r), M, F, xdot, len(d.coordinates)), (seed, "rhs")


@pytest.mark.parametrize("compiler", COMPILERS)
@pytest.mark.parametrize("name", CASES)
def test_c_agrees_with_python_and_sympy(name, compiler, python_module, tmp_path):
    d, module = derivation(name), python_module(name)
    lib = CLibrary(compile_c(d, tmp_path, compiler), d)
    for seed, ((t, x, p, r), (M, F, xdot)) in enumerate(reference(name)):
        c_xdot, status = lib.rhs(t, x, p, r)
        assert status == 0
        for label, c_value, py_value, exact in (
            ("M", lib.mass_matrix(t, x, p, r), module.mass_matrix(t, x, p, r), M),
            ("F", lib.forcing(t, x, p, r), module.forcing(t, x, p, r), F),
        ):
            assert close(c_value, py_value), (seed, label, "C vs Python")
            assert close(c_value, exact), (seed, label, "C vs SymPy")
        n, tolerance = len(d.coordinates), RTOL * max(1.0, np.linalg.cond(M) / 100)
        assert close(c_xdot, module.rhs(t, x, p, r), tolerance), (seed, "rhs", "C vs Python")
        assert rhs_agrees(c_xdot, M, F, xdot, n), (seed, "rhs", "C vs SymPy")


# -- physics ---------------------------------------------------------------------------

def test_sphere_on_turntable_moves_on_a_circle(python_module):
    """Eq. (14.30) with Ω constant and no forces: 7ẍ + 2Ωẏ = 0, 7ÿ − 2Ωẋ = 0.

    The velocity w = ẋ + iẏ turns at ω = 2Ω/7: w = w₀ e^{iωt}, so the centre
    moves on the circle about z₀ + i w₀/ω of radius 7|w₀|/(2Ω).
    """
    module = python_module("sphere_on_turntable")
    omega_plane = 3.0
    p = [module.DEFAULTS[n] for n in module.PARAMETERS]
    r = [0.0] * 6 + [omega_plane, 0.0]
    z0, w0 = 0.2 - 0.1j, 0.05 + 0.08j
    x0 = [z0.real, z0.imag, w0.real, w0.imag, 1.5]
    times = np.linspace(0.0, 10.0, 201)
    sol = solve_ivp(lambda t, x: module.rhs(t, x, p, r), (0.0, 10.0), x0, method="DOP853",
                    rtol=1e-11, atol=1e-12, t_eval=times)
    assert sol.success
    omega = 2 * omega_plane / 7
    w = w0 * np.exp(1j * omega * times)
    z = z0 + w0 * (np.exp(1j * omega * times) - 1) / (1j * omega)
    np.testing.assert_allclose(sol.y[0] + 1j * sol.y[1], z, rtol=0, atol=1e-9)
    np.testing.assert_allclose(sol.y[2] + 1j * sol.y[3], w, rtol=0, atol=1e-9)
    centre, radius = z0 + 1j * w0 / omega, 7 * abs(w0) / (2 * omega_plane)
    np.testing.assert_allclose(np.abs(sol.y[0] + 1j * sol.y[1] - centre), radius, rtol=1e-8)
    np.testing.assert_allclose(sol.y[4], 1.5, rtol=1e-12)  # no torque about k: spin constant


def integrate(module, x0, t_end):
    p = [module.DEFAULTS[n] for n in module.PARAMETERS]
    sol = solve_ivp(lambda t, x: module.rhs(t, x, p), (0.0, t_end), x0, method="DOP853",
                    rtol=1e-11, atol=1e-11, dense_output=False)
    assert sol.success
    return dict(zip(module.PARAMETERS, p)), sol.y


def relative_drift(energy) -> float:
    return float(np.max(np.abs(energy - energy[0])) / abs(energy[0]))


def test_cylinder_in_cylinder_conserves_energy(python_module):
    """T = ½Mc²θ̇² + ½(½Ma²)φ̇² with aφ̇ = cθ̇, V = −Mgc cos θ."""
    module = python_module("cylinder_in_cylinder")
    par, (theta, phi, theta_dot) = integrate(module, [1.0, 0.0, 0.5], 5.0)
    M, g, a, c = par["M"], par["g"], par["a"], par["c"]
    phi_dot = c * theta_dot / a
    energy = 0.5 * M * c**2 * theta_dot**2 + 0.5 * (0.5 * M * a**2) * phi_dot**2 - M * g * c * np.cos(theta)
    assert relative_drift(energy) < 1e-8
    assert np.ptp(theta) > 1.5  # it did swing
    np.testing.assert_allclose(a * phi, c * theta - c * 1.0, atol=1e-9)  # rolling: aφ = c(θ − θ₀)


def test_spinning_top_conserves_energy(python_module):
    """Centre of mass at distance l from O; A, C about the centre of mass; u = (φ̇, θ̇, q̇), q̇ = ω₃.

    T = ½(A + m l²)(θ̇² + φ̇² sin²θ) + ½ C q̇², V = m g l cos θ.
    """
    module = python_module("spinning_top")
    par, (phi, theta, psi, phi_dot, theta_dot, q_dot) = integrate(module, [0.0, 0.5, 0.0, 1.0, 0.3, 50.0], 2.0)
    m, g, l, A, C = (par[n] for n in ("m", "g", "l", "A", "C"))
    swing = theta_dot**2 + phi_dot**2 * np.sin(theta) ** 2
    energy = 0.5 * (A + m * l**2) * swing + 0.5 * C * q_dot**2 + m * g * l * np.cos(theta)
    assert relative_drift(energy) < 1e-8
    np.testing.assert_allclose(q_dot, 50.0, rtol=1e-12)  # ω₃ is constant for a symmetric top
    assert np.ptp(theta) > 1e-3  # it nutated
