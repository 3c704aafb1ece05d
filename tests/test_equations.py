"""The derived equations against independent computations at random states."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from conftest import LARGE, SYSTEMS, derived, evaluate
from gacli.mechanics.gibbs import gibbs_coefficients
from gacli.algebra.graph import free_symbols

ALL = sorted(p.stem for p in SYSTEMS.glob("*.yaml"))


def random_values(symbols, rng) -> dict:
    return {s: sp.Float(rng.uniform(0.3, 1.7), 30) for s in sorted(symbols, key=lambda s: s.name)}


def numeric(expr, values) -> np.ndarray:
    return np.array(sp.Matrix(expr).xreplace(values).evalf(30).tolist(), dtype=float)


@pytest.mark.parametrize("name", [n for n in ALL if n not in LARGE])
def test_gibbs_function_yields_the_equations(name, rng):
    """∂G/∂u̇_s of the displayed G equals M u̇ + (Q − F) from the direct route."""
    d = derived(name)
    H, g = gibbs_coefficients(d.gibbs, d.rates)
    u_dot = sp.Matrix(d.speed_rates)
    from_gibbs = H * u_dot + g
    direct = d.mass_matrix * u_dot + d.generalized_forces - d.forcing
    free = set().union(*(e.free_symbols for e in list(from_gibbs) + list(direct)))
    for _ in range(5):
        values = random_values(free, rng)
        a, b = numeric(from_gibbs, values), numeric(direct, values)
        assert np.linalg.norm(a - b) <= 1e-12 * max(1.0, np.linalg.norm(b))


@pytest.mark.parametrize("name", ALL)
def test_mass_matrix_symmetric_positive_definite(name, rng):
    d = derived(name)
    M = d.mass_matrix
    if name not in LARGE:
        assert sp.simplify(M - M.T) == sp.zeros(*M.shape)
    for _ in range(5):
        values = random_values(free_symbols(M), rng)
        at = evaluate(M, values).reshape(M.shape)
        assert np.allclose(at, at.T, rtol=1e-13, atol=0)
        assert np.all(np.linalg.eigvalsh(at) > 0)


def _top_lagrangian_accelerations():
    """φ̈, θ̈, ψ̈ of the heavy symmetric top from Lagrange's equations, derived here."""
    t = sp.Symbol("t")
    m, g, l, A, C = sp.symbols("m g l A C", positive=True)
    phi, theta, psi = (sp.Function(n)(t) for n in ("phi", "theta", "psi"))
    w1 = phi.diff(t) * sp.sin(theta) * sp.sin(psi) + theta.diff(t) * sp.cos(psi)
    w2 = phi.diff(t) * sp.sin(theta) * sp.cos(psi) - theta.diff(t) * sp.sin(psi)
    w3 = psi.diff(t) + phi.diff(t) * sp.cos(theta)
    # Kinetic energy about the fixed point: transverse moment A + m l² (parallel axes).
    T = sp.Rational(1, 2) * ((A + m * l**2) * (w1**2 + w2**2) + C * w3**2)
    L = T - m * g * l * sp.cos(theta)
    qs = [phi, theta, psi]
    eqs = [sp.diff(L.diff(q.diff(t)), t) - L.diff(q) for q in qs]
    dd = [q.diff(t, 2) for q in qs]
    sol = sp.solve(eqs, dd, dict=True)[0]
    plain = {}
    for name, q in zip(("phi", "theta", "psi"), qs):
        plain[q.diff(t)] = sp.Symbol(f"d_{name}")
        plain[q] = sp.Symbol(name)
    ordered = sorted(plain.items(), key=lambda kv: -sp.count_ops(kv[0]))  # derivatives first
    out = [sol[x] for x in dd]
    for old, new in ordered:
        out = [e.subs(old, new) for e in out]
    args = [sp.Symbol(s) for s in ("phi", "theta", "psi", "d_phi", "d_theta", "d_psi")] + [m, g, l, A, C]
    return sp.lambdify(args, out, "math")


def test_spinning_top_against_lagrange(rng):
    """The generated Python rhs of the top at 20 random states, against Lagrange in Euler angles."""
    from gacli.simulate import load_generated

    module = load_generated(derived("spinning_top"))
    assert module.STATE == ("phi", "theta", "psi", "dot(phi)", "dot(theta)", "dot(q)")
    assert module.PARAMETERS == ("m", "g", "l", "A", "C")
    lagrange = _top_lagrangian_accelerations()
    for _ in range(20):
        phi, theta, psi = rng.uniform(-3, 3), rng.uniform(0.2, 2.9), rng.uniform(-3, 3)
        dphi, dtheta, dq = rng.uniform(-2, 2, size=3)
        p = rng.uniform(0.5, 2.0, size=5)
        got = np.asarray(module.rhs(0.0, [phi, theta, psi, dphi, dtheta, dq], p))[3:]
        dpsi = dq - np.cos(theta) * dphi
        ddphi, ddtheta, ddpsi = lagrange(phi, theta, psi, dphi, dtheta, dpsi, *p)
        ddq = ddpsi - np.sin(theta) * dtheta * dphi + np.cos(theta) * ddphi
        want = np.array([ddphi, ddtheta, ddq])
        assert np.linalg.norm(got - want) <= 1e-10 * max(1.0, np.linalg.norm(want))


def test_terms_that_differ_only_in_mass_share_one_sum_of_masses():
    # A unit partial velocity (a slider) and l·cos(q) reach the same product l·cos(q) in M[q, x]
    # from two bodies; it must be one term with the sum of their masses, and equal the kinetic
    # energy's Hessian (T = ½ Σ m v², computed here independently).
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import loads

    d = derive(loads("gacli: 1\nname: mixed\nparameters: [m1, m2, l]\ncoordinates: [x, q]\n"
                     "bodies:\n  a: {mass: m1, position: [x + l*sin(q), 0]}\n"
                     "  b: {mass: m2, position: [l*x + sin(q), 0]}\n"))
    from gacli.algebra import symbols as S

    m1, m2, l, q = (S.value(n) for n in ("m1", "m2", "l", "q"))
    dx, dq = S.rate("x"), S.rate("q")
    T = (m1 * (dx + l * sp.cos(q) * dq) ** 2 + m2 * (l * dx + sp.cos(q) * dq) ** 2) / 2
    hessian = sp.hessian(T, (dx, dq))
    assert sp.simplify(d.mass_matrix - hessian) == sp.zeros(2, 2)
    assert len(sp.Add.make_args(d.mass_matrix[1, 0])) == 1
