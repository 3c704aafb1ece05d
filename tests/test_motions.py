"""Each body's motion in the axes where it is simplest (gacli.mechanics.motions): same equations, fewer terms.

The turned motions are checked against what they must agree with: the
Gibbs function's own route (accelerations differentiated afresh, through
the transport theorem of the turning axes) and the dependent accelerations
of the differentiated constraints.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp

from gacli.algebra import symbols as S
from gacli.loader.loading import load
from gacli.mechanics import motions
from gacli.mechanics.equations import derive
from gacli.mechanics.gibbs import gibbs_coefficients
from gacli.mechanics.rates import solve_rates

TESTS = Path(__file__).resolve().parent
SYSTEMS = TESTS.parent / "systems"
TURNED = [SYSTEMS / "rolling_disk.yaml", SYSTEMS / "differential_drive.yaml", TESTS / "frames" / "car.yaml",
          TESTS / "frames" / "self_balancing.yaml", TESTS / "frames" / "unbalanced.yaml",
          TESTS / "twins" / "diff_drive_castor.yaml"]


def _value(expr: sp.Expr, point: dict) -> complex:
    return complex(expr.xreplace({s: point[s] for s in expr.free_symbols}).evalf(25))


def _point(exprs, rng) -> dict:
    symbols = set().union(*(e.free_symbols for e in exprs))
    return {s: sp.Float(rng.uniform(0.3, 1.2), 30) for s in symbols}


@pytest.mark.parametrize("path", TURNED, ids=lambda p: p.stem)
def test_the_gibbs_function_gives_the_same_m_and_f(path, rng):
    # G's accelerations come from the turned velocities by the transport theorem;
    # M and F from the turned partials: ∂G/∂u̇ = M u̇ + (Q − F) must hold.
    d = derive(load(path))
    H, g = gibbs_coefficients(d.gibbs, d.rates)
    pairs = [(h, m) for h, m in zip(H, d.mass_matrix)]
    pairs += [(gi, q - f) for gi, q, f in zip(g, d.generalized_forces, d.forcing)]
    point = _point([e for pair in pairs for e in pair], rng)
    for ours, theirs in pairs:
        x, y = _value(ours, point), _value(theirs, point)
        assert abs(x - y) <= 1e-9 * (1 + abs(y)), (path.stem, ours, theirs)


def test_a_vehicle_is_carried_in_its_heading_and_a_wheel_without_its_spin():
    d = derive(load(SYSTEMS / "rolling_disk.yaml"))
    (disk,) = d.motions
    assert disk.heading == S.value("yaw") and disk.spin == ("y", S.value("spin"))
    held = set().union(*(e.free_symbols for e in (*disk.linear.partials.values(), *disk.angular.partials.values())))
    assert not held & {S.value("yaw"), S.value("spin")}


def test_a_robots_equations_are_free_of_its_heading():
    d = derive(load(TESTS / "twins" / "diff_drive_castor.yaml"))
    held = set().union(*(e.free_symbols for e in (*d.mass_matrix, *d.forcing)))
    assert S.value("theta") not in held and S.value("x") not in held


def test_a_format1_file_keeps_its_axes():
    d = derive(load(TESTS / "cases" / "rolling_disk_format1.yaml"))
    assert all(m.heading == 0 and m.spin is None for m in d.motions)


@pytest.mark.parametrize("path", [TESTS / "frames" / "car.yaml", TESTS / "twins" / "tricycle_front_drive.yaml"],
                         ids=lambda p: p.stem)
def test_the_differentiated_rates_are_the_differentiated_constraints(path, rng, monkeypatch):
    system = load(path)
    rates = solve_rates(system)
    short = motions.dependent_acceleration_rest(system, rates)
    monkeypatch.setattr(motions, "_SMALL_RATE", -1)  # every rate "large": the constraints' route
    solved = motions.dependent_acceleration_rest(system, rates)
    assert any(e != 0 for e in short.values())
    point = _point([*short.values(), *solved.values()], rng)
    for name in short:
        x, y = _value(short[name], point), _value(solved[name], point)
        assert abs(x - y) <= 1e-9 * (1 + abs(y)), name
