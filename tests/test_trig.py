"""sin² + cos² = 1 applied angle by angle (gacli.algebra.trig): the value never changes, the size does."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from gacli.algebra import trig
from gacli.algebra.graph import expanded_terms

a, b, m, r, u = sp.symbols("a b m r u")
ANGLES = (a, b)
FACTORS = (sp.sin(a), sp.cos(a), sp.sin(b), sp.cos(b), m, r, u, sp.Integer(2), m + r)


def _products(draw_indices) -> sp.Expr:
    return sp.Mul(*[FACTORS[i] for i in draw_indices])


expressions = st.lists(st.lists(st.integers(0, len(FACTORS) - 1), min_size=1, max_size=5),
                       min_size=1, max_size=8).map(lambda terms: sp.Add(*[_products(t) for t in terms]))


def _values(expr: sp.Expr, seed: int) -> list[complex]:
    rng = random.Random(seed)
    out = []
    for _ in range(3):
        point = {s: sp.Float(rng.uniform(-2, 2)) for s in (a, b, m, r, u)}
        out.append(complex(expr.xreplace(point).evalf(30)))
    return out


@settings(max_examples=60, deadline=None)
@given(expressions, st.integers(0, 10_000))
def test_the_value_is_unchanged(expr, seed):
    reduced = trig.reduce(expr)
    for x, y in zip(_values(expr, seed), _values(reduced, seed)):
        assert abs(x - y) <= 1e-20 + 1e-12 * abs(x)


@settings(max_examples=60, deadline=None)
@given(expressions)
def test_no_square_pair_is_left(expr):
    """After the reduction, no angle has both sin² and cos² (one of them was replaced)."""
    reduced = sp.expand(trig.reduce(expr))
    for angle in ANGLES:
        powers = {type(p.base) for p in reduced.atoms(sp.Pow) if p.exp >= 2 and isinstance(p.base, (sp.sin, sp.cos))
                  and p.base.args[0] == angle}
        assert len(powers) < 2, reduced


def test_an_expression_free_of_an_angle_loses_it():
    # (s² + c²)² X + s² c² Y − s² c² Y: a spin angle that cancels only through the identity.
    s, c = sp.sin(a), sp.cos(a)
    expr = sp.expand((s ** 2 + c ** 2) ** 2 * m * u ** 2) + s ** 2 * c ** 2 * r - c ** 2 * s ** 2 * r
    assert trig.reduce(expr) == m * u ** 2


def test_the_rolling_disk_pair_collapses():
    s, c = sp.sin(b), sp.cos(b)
    expr = 4 * u ** 2 * m * r ** 2 * sp.sin(a) ** 5 * (s ** 4 + 2 * s ** 2 * c ** 2 + c ** 4)
    assert trig.reduce(sp.expand(expr)) == 4 * u ** 2 * m * r ** 2 * sp.sin(a) ** 5


def test_sums_of_parameters_are_not_multiplied_out():
    expr = (m + r) * sp.sin(a) ** 2 * u + (m + r) * sp.cos(a) ** 2 * u
    assert trig.reduce(expr) == (m + r) * u


def test_a_large_expansion_is_left_alone():
    expr = (sp.sin(a) + sp.cos(a) + sp.sin(b) + m + r) ** 40
    assert trig.reduce(expr) is expr


@pytest.mark.parametrize("expr, limit, expected", [
    ((a + b) ** 2, 100, 3), ((a + b + m) * (a + r), 100, 6), (a * b, 10, 1),
    ((a + b + m + r + u) ** 40, 1_000, None),
])
def test_expanded_terms_counts_without_expanding(expr, limit, expected):
    count = expanded_terms(expr, limit)
    if expected is None:
        assert count > limit
    else:
        assert count == len(sp.Add.make_args(sp.expand(expr)))


def _reduced_without_count(expr: sp.Expr) -> sp.Expr:
    """trig.reduce as it was before the count: distribute until a bound is met."""
    try:
        return trig._reduce(expr, {trig._WORK: 0})
    except trig._TooLarge:
        return expr


nested = st.lists(expressions, min_size=1, max_size=4).map(
    lambda parts: sp.Mul(*[p if i % 2 else (p + 1) ** 2 for i, p in enumerate(parts)])
    + sp.sqrt(sp.Add(*parts) ** 2 + 1))


@settings(max_examples=200, deadline=None)
@given(nested)
def test_the_count_refuses_exactly_what_distributing_would(expr):
    # The count walks instead of multiplying; it must agree with the walk that
    # multiplies on every expression, those just past the bounds included.
    assert trig.reduce(expr) == _reduced_without_count(expr)


def test_the_count_refuses_a_product_past_the_bound():
    s = sp.Add(*[sp.sin(a) * sp.cos(b) ** i for i in range(50)])
    expr = s * (s + m) + sp.sqrt(s ** 2 + 1)
    with pytest.raises(trig._TooLarge):
        trig._count(expr, {trig._WORK: 0})
    assert trig.reduce(expr) is expr


@pytest.mark.parametrize("n, refused", [(20, False), (42, False), (43, True), (60, True)])
def test_the_count_and_the_products_agree_at_the_bound(n, refused):
    # 42 terms squared stay within the work bound (MAX_WORK), 43 do not.
    s = sp.Add(*[sp.sin(a) ** (i % 3) * sp.cos(a) ** (i // 3) * m ** i for i in range(n)])
    expr = s ** 2 + sp.sqrt(s * sp.sin(a) + 1)
    assert trig.reduce(expr) == _reduced_without_count(expr)
    assert (trig.reduce(expr) is expr) == refused


def test_cancel_distributes_what_has_no_square():
    # After a turn by an angle, terms meet only once multiplied out; no square is there to prompt it.
    expr = sp.sin(a) * (m * sp.cos(a) + r) - sp.cos(a) * (m * sp.sin(a) + u)
    assert trig.reduce(expr) is expr
    assert trig.reduce(expr, cancel=True) == r * sp.sin(a) - u * sp.cos(a)


d, t = sp.symbols("delta theta_T")


def test_a_sum_beside_its_own_angles_is_written_out():
    # sin θ cos(θ + δ) − cos θ sin(θ + δ) = −sin δ: only one angle at a time, after
    # θ + δ is written out by the addition formulas.
    expr = m * (sp.sin(a) * sp.cos(a + d) - sp.cos(a) * sp.sin(a + d))
    assert trig.reduce(expr) == -m * sp.sin(d)


def test_a_difference_kept_whole_when_shorter():
    # sin²(θ − θ_T) + cos²(θ − θ_T) beside sin θ and sin θ_T: still reduced.
    expr = m * sp.cos(a - t) ** 2 + r * sp.sin(a) + u * sp.sin(t) + m * sp.sin(a - t) ** 2
    assert sp.expand(trig.reduce(expr) - (m + r * sp.sin(a) + u * sp.sin(t))) == 0
    # A hitch angle θ − θ_T beside θ and θ_T: written out by the addition formulas
    # it would be longer, so it is kept whole.
    hitch = m * sp.sin(a) * sp.cos(a - t) + r * sp.sin(a - t) * sp.cos(t)
    assert trig.reduce(hitch, cancel=True).has(sp.cos(a - t))


@settings(max_examples=40, deadline=None)
@given(st.lists(st.lists(st.integers(0, 7), min_size=1, max_size=4), min_size=1, max_size=6), st.integers(0, 10_000))
def test_sums_of_angles_keep_their_value(terms, seed):
    factors = (sp.sin(a + b), sp.cos(a + b), sp.sin(a), sp.cos(b), sp.cos(a - 2 * b), m, r, sp.Integer(3))
    expr = sp.Add(*[sp.Mul(*[factors[i] for i in term]) for term in terms])
    for x, y in zip(_values(expr, seed), _values(trig.reduce(expr), seed)):
        assert abs(x - y) <= 1e-20 + 1e-12 * abs(x)


def test_a_large_multiple_of_an_angle_is_not_written_out():
    # sin(θ + 100000 φ) by the addition formulas is a polynomial of degree 100000 in sin φ, cos φ:
    # a hostile file held a derivation for minutes. Small multiples (θ − 2ψ) are still written out.
    from gacli.algebra import angle_sums

    big = sp.sin(a + 100000 * b) + sp.sin(a) * sp.cos(b)
    assert angle_sums.expansions(big.atoms(sp.sin, sp.cos)) == {}
    assert trig.reduce(big * sp.sin(a), cancel=True).has(sp.sin(a + 100000 * b))
    assert angle_sums.expansions({sp.sin(a - 2 * b), sp.sin(b)})


@pytest.mark.parametrize("n", [2, 3, 9, 40])
def test_a_high_power_of_a_sine_is_eliminated_by_the_binomial_theorem(n):
    # One square at a time made 2**(n/2) monomials (sin(x)**40: 3.4 s); the binomial theorem makes
    # n/2 + 1, equal to the power at random angles.
    poly = {frozenset({(sp.sin(a), n), (sp.cos(b), 1)}): [m]}
    out = trig._eliminate(poly, a, sp.sin)
    assert len(out) == n // 2 + 1
    rebuilt = sp.Add(*(c[0] * sp.Mul(*(base ** e for base, e in monomial)) for monomial, c in out.items()))
    s = sp.Symbol("s")  # exactly: cos² a = 1 − sin² a (floats lose (1 − c²)^20 to cancellation)
    on_circle = rebuilt.xreplace({sp.sin(a): s, sp.cos(a): sp.sqrt(1 - s ** 2)})
    assert sp.expand(on_circle - m * s ** n * sp.cos(b)) == 0


def test_an_elimination_past_its_bound_is_not_formed():
    poly = {frozenset({(sp.sin(a), 2 * trig.ELIMINATED_TERMS),}): [m]}
    assert trig._eliminate(poly, a, sp.sin) is None
    assert trig.reduce(m * sp.sin(a) ** (2 * trig.ELIMINATED_TERMS) + m) is not None


def test_expand_is_counted_inside_functions_as_it_runs_there():
    x, y, z = sp.symbols("x y z")
    assert expanded_terms((x + y + z) ** 100, 2_000) > 2_000
    assert expanded_terms(sp.sqrt((x + y + z) ** 100 + 1), 2_000) > 2_000
    assert expanded_terms(sp.sin((x + y) ** 3) * (x + y), 2_000) == 2


def test_a_negative_power_is_kept_by_the_elimination():
    # divmod(-2, 2) is (-1, 0): a quotient's 1/sin² a was dropped (a sleigh's equations lost a term).
    poly = {frozenset({(sp.sin(a), -2)}): [m], frozenset({(sp.sin(a), 3)}): [r]}
    out = trig._eliminate(poly, a, sp.sin)
    assert out[frozenset({(sp.sin(a), -2)})] == [m]
    assert trig.reduce(m / sp.sin(a) ** 2 + r * sp.sin(a) ** 2 + r * sp.cos(a) ** 2) == m / sp.sin(a) ** 2 + r


def test_expand_is_counted_through_powers_of_products_and_below_fraction_bars():
    # (50 (x + y + z)**49)**2 counted as one term took 2.9 GB in SymPy's expand; (3 + x + y + z)**-50
    # and (x + y + z)**50.5 are multiplied out too, below the bar and under the root.
    x, y, z = sp.symbols("x y z")
    squared = sp.Pow(sp.Mul(50, (x + y + z) ** 49, evaluate=False), 2, evaluate=False)
    assert expanded_terms(squared, 2_000) > 2_000
    assert expanded_terms((3 + x + y + z) ** -50, 2_000) > 2_000
    assert expanded_terms((x + y + z) ** sp.Rational(131, 2), 2_000) > 2_000
    assert expanded_terms(1 / (x + y), 2_000) == 1 and expanded_terms((2 * (x + y)) ** 2, 2_000) == 3
