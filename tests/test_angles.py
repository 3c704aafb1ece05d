"""Pairs of angles written through their difference (gacli.algebra.angles)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from gacli.algebra.angles import relative

a, b, c, k, m = sp.symbols("theta theta_T delta k m", real=True)


def _value(expr, point):
    return complex(expr.xreplace(point).evalf(30))


def _agree(x, y, rng, names):
    for _ in range(5):
        point = {s: sp.Float(rng.uniform(-3, 3), 30) for s in names}
        assert abs(_value(x, point) - _value(y, point)) < 1e-20


def test_a_product_of_two_headings_becomes_the_cosine_of_their_difference():
    expr = k * (sp.sin(a) * sp.sin(b) + sp.cos(a) * sp.cos(b))
    assert sp.simplify(relative(expr) - k * sp.cos(a - b)) == 0
    assert relative(expr).atoms(sp.cos) == {sp.cos(a - b)}


def test_a_turned_vector_loses_the_heading_it_was_turned_by():
    # The trailer's velocity along its own heading: the tractor's (v cos θ, v sin θ) turned by θ_T.
    v = m * sp.cos(a), m * sp.sin(a)
    forward = sp.cos(b) * v[0] + sp.sin(b) * v[1]
    sideways = -sp.sin(b) * v[0] + sp.cos(b) * v[1]
    assert sp.simplify(relative(forward) - m * sp.cos(a - b)) == 0
    assert sp.simplify(relative(sideways) - m * sp.sin(a - b)) == 0
    for e in (relative(forward), relative(sideways)):
        assert {s.args[0] for s in e.atoms(sp.sin, sp.cos)} == {a - b}


def test_an_expression_of_both_angles_apart_keeps_its_value(rng):
    # sin θ + sin θ_T depends on each angle, not only on the difference: it may
    # change form, but never value.
    for expr in (sp.sin(a) + sp.sin(b),
                 k * sp.sin(a) * sp.cos(b) + m * sp.cos(a) * sp.sin(b) + sp.cos(c) * sp.sin(a) * sp.sin(b),
                 (sp.sin(a) * sp.cos(b) - sp.cos(a) * sp.sin(b)) ** 2 * k + sp.cos(c) * sp.sin(b)):
        out = relative(expr)
        _agree(out, expr, rng, [a, b, c, k, m])
        assert sp.count_ops(out) <= sp.count_ops(expr)


@pytest.mark.parametrize("seed", range(5))
def test_random_sums_of_products_keep_their_value(seed):
    rng = np.random.default_rng(seed)
    atoms = [sp.sin(a), sp.cos(a), sp.sin(b), sp.cos(b), sp.sin(c), sp.cos(c), k, m]
    terms = []
    for _ in range(6):
        picks = rng.choice(len(atoms), size=3)
        terms.append(int(rng.integers(-3, 4)) * sp.Mul(*[atoms[i] for i in picks]))
    expr = sp.Add(*terms)
    _agree(relative(expr), expr, rng, [a, b, c, k, m])


def test_one_angle_or_none_is_left_alone():
    for expr in (k * sp.sin(a) ** 2 + sp.cos(a), k + m, sp.Integer(3)):
        assert relative(expr) == expr


def test_a_pair_that_would_stay_beside_its_difference_is_left_alone():
    # A snakeboard's yaw rate: sin(φ_F) − sin(φ_B) cos(φ_F)/cos(φ_B) is sin(φ_F − φ_B)/cos(φ_B),
    # shorter, but φ_B stays on its own beside the difference, and products of
    # the two forms would no longer cancel.
    for expr in (sp.sin(b) - sp.sin(a) * sp.cos(b) / sp.cos(a), sp.cos(a - b) + sp.sin(b)):
        assert relative(expr) == expr


@pytest.mark.parametrize("seed", range(5))
def test_random_functions_of_the_difference_written_out_come_back_shorter(seed):
    # Built from sin(θ − θ_T), cos(θ − θ_T) and multiplied out: the pair combines again.
    rng = np.random.default_rng(seed)
    atoms = [sp.sin(a - b), sp.cos(a - b), sp.cos(c), k, m]
    terms = [int(rng.integers(1, 4)) * sp.Mul(*[atoms[i] for i in rng.choice(len(atoms), size=3)])
             for _ in range(4)]
    written_out = sp.expand(sp.expand_trig(sp.Add(*terms)))
    out = relative(written_out)
    _agree(out, written_out, rng, [a, b, c, k, m])
    assert sp.count_ops(out) < sp.count_ops(written_out)


def test_a_pair_the_denominator_holds_is_left_alone():
    numerator = sp.sin(b) * sp.cos(a) - sp.sin(a) * sp.cos(b)
    assert relative(numerator, beside=sp.cos(a)) == numerator
    assert relative(numerator, beside=k) != numerator


def test_the_trailer_rates_are_functions_of_the_hitch_angle():
    # A robot towing a trailer, both headings absolute: the trailer's rates depend on
    # the two only through the hitch angle θ − θ_T, and are written so.
    from pathlib import Path

    from gacli.loader.loading import load
    from gacli.mechanics.rates import solve_rates

    rates = solve_rates(load(Path(__file__).parent / "twins" / "robot_trailer.yaml"))
    theta, theta_T = sp.Symbol("theta", real=True), sp.Symbol("theta_T", real=True)
    for name in ("theta_T", "psi_L", "psi_R"):
        rate = rates.rate(name)
        assert {f.args[0] for f in rate.atoms(sp.sin, sp.cos)} == {theta - theta_T}, (name, rate)


def test_a_pair_through_their_sum_is_written_so_for_display():
    # A bead at s on a hoop spinning by φ: the display writes sin(s + φ), as by hand.
    s_, phi = sp.symbols("s phi", real=True)
    expr = k * (sp.sin(s_) * sp.cos(phi) + sp.cos(s_) * sp.sin(phi)) + m * (sp.cos(s_) * sp.cos(phi) - sp.sin(s_) * sp.sin(phi))
    shown = relative(expr, sums=True)
    assert shown.atoms(sp.sin, sp.cos) == {sp.sin(s_ + phi), sp.cos(s_ + phi)}
    assert sp.simplify(shown - expr) == 0
    # The derivation keeps sums out (its products cancel less so).
    assert relative(expr) == expr


def test_a_pair_that_does_not_combine_is_not_tried(monkeypatch):
    # sin θ + sin θ_T changes when θ and θ_T move with their difference fixed: no reduction is spent on it.
    import gacli.algebra.angles as angles

    calls = []
    monkeypatch.setattr(angles, "_through", lambda *args: calls.append(args) or args[0])
    relative(k * sp.sin(a) * sp.cos(b) + m * sp.sin(b), sums=True)
    assert calls == []
