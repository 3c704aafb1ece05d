"""First integrals against the literature: written here from the textbooks, checked by gacli.

The heavy top's two momenta and energy (Goldstein 5.7), Chaplygin's ball's
energy and angular momentum about the contact (Chaplygin 1903; Borisov and
Mamaev 2002), Jellett's and Routh's integrals of Routh's sphere (Routh,
Advanced Rigid Dynamics, arts. 222-225), and no momentum claimed where a
constraint breaks it (the sleigh's heading, the rolling disk's yaw).
"""

from __future__ import annotations

import functools

import pytest
import sympy as sp
from typer.testing import CliRunner

from conftest import derived
from gacli.cli import app
from gacli.steady.integrals import integrals


def _s(name: str) -> sp.Symbol:
    return sp.Symbol(name, real=True)


phi, theta, psi = _s("phi"), _s("theta"), _s("psi")
dphi, dtheta, dpsi = _s("dot(phi)"), _s("dot(theta)"), _s("dot(psi)")


def _zxz_body_rates():
    """ω in the body's axes for ZXZ Euler angles (Goldstein eq. 4.87), and the vertical in them."""
    w = sp.Matrix([dphi * sp.sin(theta) * sp.sin(psi) + dtheta * sp.cos(psi),
                   dphi * sp.sin(theta) * sp.cos(psi) - dtheta * sp.sin(psi),
                   dphi * sp.cos(theta) + dpsi])
    up = sp.Matrix([sp.sin(theta) * sp.sin(psi), sp.sin(theta) * sp.cos(psi), sp.cos(theta)])
    return w, up


def _same(a: sp.Expr, b: sp.Expr) -> bool:
    """Equal up to a constant factor (an integral times a number is one), at seeded random points."""
    import random

    rng = random.Random(20261126)
    symbols = sorted(a.free_symbols | b.free_symbols, key=str)
    ratios = []
    for _ in range(6):
        point = {s: rng.uniform(0.2, 1.3) for s in symbols}
        ratios.append(float(a.xreplace(point) / b.xreplace(point)))
    return ratios[0] != 0 and all(abs(r - ratios[0]) <= 1e-10 * abs(ratios[0]) for r in ratios)


@functools.lru_cache(maxsize=None)
def found(name: str):
    return integrals(derived(name))


def test_heavy_top_keeps_two_momenta_and_the_energy():
    m, g, l, A, C, q = (_s(n) for n in ("m", "g", "l", "A", "C", "dot(q)"))
    A_O = A + m * l**2                      # about the fixed point; the file's A is about the centre of mass
    p_phi = A_O * sp.sin(theta)**2 * dphi + C * q * sp.cos(theta)
    p_psi = C * q
    energy = (A_O * (dtheta**2 + sp.sin(theta)**2 * dphi**2) + C * q**2) / 2 + m * g * l * sp.cos(theta)
    result = {i.name: i.expression for i in found("spinning_top").found}
    assert set(result) == {"energy T + V", "momentum of phi", "momentum of psi"}
    assert _same(result["momentum of phi"], p_phi)
    assert _same(result["momentum of psi"], p_psi)
    assert _same(result["energy T + V"], energy)


def test_chaplygin_ball_keeps_energy_and_the_contact_momentum():
    m, r, A, B, C = (_s(n) for n in ("m", "r", "A", "B", "C"))
    w, up = _zxz_body_rates()
    I = sp.diag(A, B, C)
    K = I * w + m * r**2 * (w - w.dot(up) * up)    # about the contact: Iω + m ρ × (ω × ρ), ρ = r·up
    names = {i.name for i in found("chaplygin_ball").found}
    assert "energy T + V" in names
    vertical = next(i.expression for i in found("chaplygin_ball").found if i.name == "momentum of phi")
    assert _same(vertical, K.dot(up))
    checked = integrals(derived("chaplygin_ball"), candidates=[K.dot(K), K.dot(up)], search=False).candidates
    assert all(c.conserved for c in checked), checked


def test_routh_sphere_keeps_jellett_and_routh_integrals_as_candidates():
    m, r, e, A, C = (_s(n) for n in ("m", "r", "e", "A", "C"))
    w, up = _zxz_body_rates()
    rho = sp.Matrix([0, 0, e]) - r * up              # centre of mass → contact, in the body's axes
    jellett = (sp.diag(A, A, C) * w).dot(rho)
    # Borisov and Mamaev (2002), eq. for Routh's sphere: ω₃ √(I₁I₃ + m I₁ ⟨r, r⟩ + m (I₃ − I₁) r₃²).
    routh = w[2] * sp.sqrt(A * C + m * A * rho.dot(rho) + m * (C - A) * rho[2]**2)
    result = integrals(derived("routh_sphere"), candidates=[jellett, routh, w[2]], search=False)
    held = [c.conserved for c in result.candidates]
    assert held == [True, True, False]     # ω₃ alone is no integral: the check can say no
    assert "energy T + V" in {i.name for i in found("routh_sphere").found}


def test_no_momentum_for_the_sleighs_heading_or_the_disks_yaw():
    sleigh = found("chaplygin_sleigh")
    assert not [i for i in sleigh.found if i.name.startswith("momentum")]
    assert any(what == "momentum of theta" and "constraints or the loads break it" in why for what, why in sleigh.broken)
    disk = found("rolling_disk")
    assert [i.name for i in disk.found] == ["energy T + V"]
    assert any(what == "momentum of yaw" and "constraints or the loads break it" in why for what, why in disk.broken)


def test_bead_on_a_turning_hoop_keeps_jacobis_integral_not_its_energy():
    """Goldstein 8.2: with the hoop turned at a constant W, h = ½mR²θ̇² − ½mR²W² sin²θ − m g R cos θ."""
    from gacli import derive, load
    from conftest import SYSTEMS

    m, R, W, g, th, dth = (_s(n) for n in ("m", "R", "W", "g", "theta", "dot(theta)"))
    result = integrals(derive(load(SYSTEMS / "bead_on_rotating_hoop.yaml")))
    jacobi = m * R**2 * dth**2 / 2 - m * R**2 * W**2 * sp.sin(th)**2 / 2 - m * g * R * sp.cos(th)
    assert [i.name for i in result.found] == ["Jacobi's integral T2 - T0 + V"]
    assert sp.simplify(result.found[0].expression - jacobi) == 0
    assert any(what == "energy" for what, _ in result.broken)


def test_a_momentum_broken_without_constraints_is_blamed_on_the_loads():
    # A particle under gravity: its p_y was said to be broken by 'the constraints' it does not have.
    from gacli.loader.loading import loads
    from gacli.mechanics.equations import derive
    from gacli.steady.integrals import integrals

    system = loads("gacli: 1\nname: p\nparameters: {m: {value: 1}, g: {value: 9.81}}\ncoordinates: [x, y]\n"
                   "bodies: {b: {mass: m, position: [x, y, 0]}}\npotential: m*g*y\n")
    broken = dict(integrals(derive(system)).broken)
    assert broken["momentum of y"].startswith("the loads or the potential break it")


RING = """
gacli: 1
name: ring
parameters:
  m: {value: 1}
  R: {value: 0.5}
functions:
  Omega: rate at which the ring turns
coordinates: [phi, theta]
constraints:
  - dtheta = Omega*dt
independent: [phi]
bodies:
  bead: {mass: m, position: [R*cos(theta + phi), R*sin(theta + phi)]}
"""


def test_an_integral_through_a_function_of_time_is_judged_with_its_rate():
    # A bead on a frictionless ring turned at Ω(t): φ'' = −Ω', so p = m R² (Ω + φ') is conserved;
    # driven along the ring by m R² Ω' dφ, φ'' = 0 and p is not. dG/dt had left out Ω' ∂G/∂Ω, and
    # the two verdicts were the other way round.
    from gacli.loader.loading import loads
    from gacli.mechanics.equations import derive

    p = _s("R") ** 2 * _s("m") * (_s("Omega") + sp.Symbol("dot(phi)", real=True))
    free = integrals(derive(loads(RING)), candidates=[p], search=False).candidates
    driven = integrals(derive(loads(RING + "work: m*R**2*dot(Omega)*dphi\n")), candidates=[p], search=False).candidates
    assert [c.conserved for c in free] == [True] and [c.conserved for c in driven] == [False]


_FREE_QUATERNION_BODY = """\
gacli: 1
name: free_body
parameters: {A: 1, B: 2, C: 3}
coordinates: [e0, e1, e2, e3]
quasi_coordinates:
  w1: 2*(-e1*de0 + e0*de1 + e3*de2 - e2*de3)
  w2: 2*(-e2*de0 - e3*de1 + e0*de2 + e1*de3)
  w3: 2*(-e3*de0 + e2*de1 - e1*de2 + e0*de3)
constraints:
  - e0**2 + e1**2 + e2**2 + e3**2 = 1
independent: [w1, w2, w3]
bodies:
  b: {mass: 1, position: [0, 0, 0], inertia: [A, B, C], rotation: [dw1, dw2, dw3]}
"""


@pytest.mark.parametrize("first_row", ["e0**2 + e1**2 - e2**2 - e3**2", "1 - 2*e2**2 - 2*e3**2"])
def test_a_candidate_conserved_on_the_unit_sphere_only_is_conserved(tmp_path, first_row):
    """A free body's angular momentum along N's x, R₁·(I ω), is an integral; R written with e·e = 1
    applied (1 − 2 e₂² − 2 e₃²) is it on the sphere only, and both were 'not conserved': judged at
    points off e·e = 1, and on it to 20 digits against a test at 1e-25."""
    path = tmp_path / "free_body.yaml"
    path.write_text(_FREE_QUATERNION_BODY, encoding="utf-8")
    momentum = f"A*dot(w1)*({first_row}) + 2*B*dot(w2)*(e1*e2 - e0*e3) + 2*C*dot(w3)*(e1*e3 + e0*e2)"
    kept = CliRunner().invoke(app, ["integrals", str(path), "--candidate", momentum])
    assert kept.exit_code == 0, kept.output
    last = kept.output.splitlines()[-1]
    assert last.startswith("candidate 1:") and ": conserved" in last
    broken = CliRunner().invoke(app, ["integrals", str(path), "--candidate", "A*dot(w1)*e0"])
    assert broken.exit_code == 1 and "not conserved" in broken.output.splitlines()[-1]
