"""The chapter's printed results, reproduced symbolically (difference simplifies to 0).

Each expected expression is typed in from the chapter (section 14.4 and
problem 14/1) in gacli's plain symbols: ``dot(x)`` is ẋ, ``ddot(x)`` is ẍ.
"""

from __future__ import annotations

import sympy as sp

from conftest import derived


def sym(name: str) -> sp.Symbol:
    return sp.Symbol(name, real=True)


def zero(expr) -> bool:
    return sp.simplify(expr) == 0


def accelerations(d) -> sp.Matrix:
    """u̇ = M⁻¹ F, solved symbolically (small systems only)."""
    return d.mass_matrix.LUsolve(d.forcing)


def acceleration_terms(G, accs):
    """G without its acceleration-free terms (as the chapter prints it)."""
    return G - G.subs({a: 0 for a in accs})


# -- particle in a plane ------------------------------------------------------

def test_particle_gibbs_function():
    d = derived("particle_in_plane")
    m, r, dq, ddr, ddq = sym("m"), sym("r"), sym("dot(q)"), sym("ddot(r)"), sym("ddot(q)")
    printed = m / 2 * (ddr**2 - 2 / r**3 * dq**2 * ddr + ddq**2 / r**2)
    assert zero(d.gibbs - printed)


def test_particle_generalized_forces():
    d = derived("particle_in_plane")
    R, S, r = sym("R"), sym("S"), sym("r")
    assert zero(d.generalized_forces[0] - R)
    assert zero(d.generalized_forces[1] - S / r)


def test_particle_equations():
    d = derived("particle_in_plane")
    m, r, dq, R, S = sym("m"), sym("r"), sym("dot(q)"), sym("R"), sym("S")
    ddr, ddq = sym("ddot(r)"), sym("ddot(q)")
    residual = d.mass_matrix * sp.Matrix([ddr, ddq]) - d.forcing
    assert zero(residual[0] - (m * (ddr - dq**2 / r**3) - R))
    assert zero(residual[1] - (m * ddq / r**2 - S / r))


def test_particle_kinematics_theta_rate():
    d = derived("particle_in_plane")
    assert zero(dict(d.kinematic_equations)["theta"] - sym("dot(q)") / sym("r") ** 2)


# -- cylinder rolling in a cylinder ------------------------------------------

def test_cylinder_gibbs_function():
    d = derived("cylinder_in_cylinder")
    M, c, ddth = sym("M"), sym("c"), sym("ddot(theta)")
    assert zero(d.gibbs - sp.Rational(3, 4) * M * c**2 * ddth**2)


def test_cylinder_equation_is_a_pendulum():
    d = derived("cylinder_in_cylinder")
    g, c, th = sym("g"), sym("c"), sym("theta")
    (ddth,) = accelerations(d)
    assert zero(ddth + sp.Rational(2, 3) * g / c * sp.sin(th))
    assert zero(d.generalized_forces[0] + sym("M") * g * c * sp.sin(th))


# -- sphere on a turntable ----------------------------------------------------

def _sphere_symbols():
    names = "M a I Omega dot(Omega) x y dot(x) dot(y) ddot(x) ddot(y) ddot(q_z) F_x F_y M_x M_y M_z"
    return {n: sym(n) for n in names.split()}


def test_sphere_gibbs_function_14_27():
    d = derived("sphere_on_turntable")
    s = _sphere_symbols()
    M, a, I, W, dW = s["M"], s["a"], s["I"], s["Omega"], s["dot(Omega)"]
    ax, ay, az = s["ddot(x)"], s["ddot(y)"], s["ddot(q_z)"]
    printed = (M / 2 * (ax**2 + ay**2)
               + I / (2 * a**2) * (ax + W * s["dot(y)"] + dW * s["y"]) ** 2
               + I / (2 * a**2) * (-ay + W * s["dot(x)"] + dW * s["x"]) ** 2
               + I / 2 * az**2)
    assert zero(d.gibbs - acceleration_terms(printed, (ax, ay, az)))


def test_sphere_equations_14_29():
    d = derived("sphere_on_turntable")
    s = _sphere_symbols()
    M, a, I, W, dW = s["M"], s["a"], s["I"], s["Omega"], s["dot(Omega)"]
    u_dot = sp.Matrix([s["ddot(x)"], s["ddot(y)"], s["ddot(q_z)"]])
    residual = d.mass_matrix * u_dot - d.forcing
    printed = [
        M * s["ddot(x)"] + I / a**2 * (s["ddot(x)"] + W * s["dot(y)"] + dW * s["y"]) - (s["F_x"] + s["M_y"] / a),
        M * s["ddot(y)"] + I / a**2 * (s["ddot(y)"] - W * s["dot(x)"] - dW * s["x"]) - (s["F_y"] - s["M_x"] / a),
        I * s["ddot(q_z)"] - s["M_z"],
    ]
    for got, want in zip(residual, printed):
        assert zero(got - want)


def test_sphere_generalized_forces_14_28():
    d = derived("sphere_on_turntable")
    s = _sphere_symbols()
    want = [s["F_x"] + s["M_y"] / s["a"], s["F_y"] - s["M_x"] / s["a"], s["M_z"]]
    for got, w in zip(d.generalized_forces, want):
        assert zero(got - w)


def test_sphere_special_case_14_30():
    """Ω constant, I = 2/5 M a², no moment: 7ẍ + 2Ωẏ = 5F_x/M, 7ÿ − 2Ωẋ = 5F_y/M."""
    d = derived("sphere_on_turntable")
    s = _sphere_symbols()
    case = {s["dot(Omega)"]: 0, s["I"]: sp.Rational(2, 5) * s["M"] * s["a"] ** 2,
            s["M_x"]: 0, s["M_y"]: 0, s["M_z"]: 0}
    ddx, ddy, _ = accelerations(d).subs(case)
    W, M = s["Omega"], s["M"]
    assert zero(7 * ddx + 2 * W * s["dot(y)"] - 5 * s["F_x"] / M)
    assert zero(7 * ddy - 2 * W * s["dot(x)"] - 5 * s["F_y"] / M)


def test_sphere_rates_14_26():
    """a q̈_y = ẍ + Ωẏ + Ω̇y and a q̈_x = −ÿ + Ωẋ + Ω̇x, from the derived rates."""
    from gacli.mechanics.gibbs import acceleration_chain
    from gacli.algebra.symbols import time_derivative

    d = derived("sphere_on_turntable")
    s = _sphere_symbols()
    chain = acceleration_chain(d.system, d.rates)
    qy = time_derivative(d.rates.rate("q_y"), chain)
    qx = time_derivative(d.rates.rate("q_x"), chain)
    W, dW, a = s["Omega"], s["dot(Omega)"], s["a"]
    assert zero(a * qy - (s["ddot(x)"] + W * s["dot(y)"] + dW * s["y"]))
    assert zero(a * qx - (-s["ddot(y)"] + W * s["dot(x)"] + dW * s["x"]))


# -- problem 14/1: the free rigid body ------------------------------------------

def test_rigid_body_gibbs_function_problem_14_1():
    d = derived("rigid_body")
    n = {k: sym(k) for k in "m I_x I_y I_z ddot(x) ddot(y) ddot(z)".split()}
    w = [sym(f"dot(q_{i})") for i in (1, 2, 3)]
    a = [sym(f"ddot(q_{i})") for i in (1, 2, 3)]
    Ix, Iy, Iz = n["I_x"], n["I_y"], n["I_z"]
    printed = (n["m"] / 2 * (n["ddot(x)"] ** 2 + n["ddot(y)"] ** 2 + n["ddot(z)"] ** 2)
               + sp.Rational(1, 2) * (Ix * a[0] ** 2 - 2 * (Iy - Iz) * w[1] * w[2] * a[0]
                                      + Iy * a[1] ** 2 - 2 * (Iz - Ix) * w[2] * w[0] * a[1]
                                      + Iz * a[2] ** 2 - 2 * (Ix - Iy) * w[0] * w[1] * a[2]))
    assert zero(d.gibbs - printed)


def test_rigid_body_euler_equations():
    d = derived("rigid_body")
    Ix, Iy, Iz = sym("I_x"), sym("I_y"), sym("I_z")
    w = [sym(f"dot(q_{i})") for i in (1, 2, 3)]
    a = [sym(f"ddot(q_{i})") for i in (1, 2, 3)]
    Mx, My, Mz = sym("M_x"), sym("M_y"), sym("M_z")
    residual = d.mass_matrix * sp.Matrix(d.speed_rates) - d.forcing
    euler = [Ix * a[0] - (Iy - Iz) * w[1] * w[2] - Mx,
             Iy * a[1] - (Iz - Ix) * w[2] * w[0] - My,
             Iz * a[2] - (Ix - Iy) * w[0] * w[1] - Mz]
    for got, want in zip(residual[3:], euler):
        assert zero(got - want)
    m = sym("m")
    for i, F in enumerate(("F_x", "F_y", "F_z")):
        assert zero(residual[i] - (m * d.speed_rates[i] - sym(F)))
