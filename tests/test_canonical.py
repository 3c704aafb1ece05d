"""gacli.algebra.canonical.product builds exactly what sympy.Mul builds, or defers to it."""

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from gacli.algebra.canonical import _only_sorting_needed, mul, product

x, y, z = sp.symbols("x y z")
a, b = sp.symbols("a b", positive=True)
f = sp.Function("f")
A, B = sp.symbols("A B", commutative=False)

ATOMS = [x, y, z, a, b, sp.sin(x), sp.cos(x), sp.cos(y), f(z), sp.exp(x), sp.exp(y), x + y, a + 1, x * y,
         sp.sqrt(2), sp.Rational(1, 2), sp.I, sp.pi, sp.E, sp.oo, sp.zoo, sp.nan, A, B, sp.S.Zero,
         sp.Piecewise((x, y > 0), (1, True)), sp.Abs(x), sp.atan2(x, y), sp.Integer(-3)]
EXPONENTS = [sp.S.One, sp.Integer(2), sp.Integer(-1), sp.Rational(1, 2), sp.Rational(-3, 2), y, x + 1,
             sp.factor(2 * a + 2 * b), sp.Symbol("zr", zero=True), sp.Float(2.0)]
COEFFICIENTS = [sp.S.One, sp.S.NegativeOne, sp.Integer(2), sp.Rational(-3, 4), sp.S.Zero]


def _power(base, exp):
    return base if exp is sp.S.One else sp.Pow(base, exp)


factor = st.builds(_power, st.sampled_from(ATOMS), st.sampled_from(EXPONENTS))


@settings(max_examples=3000, deadline=None)
@given(st.sampled_from(COEFFICIENTS), st.lists(factor, min_size=1, max_size=6))
def test_product_is_sympy_mul_argument_for_argument(coefficient, factors):
    expected = sp.Mul(coefficient, *factors)
    got = product(coefficient, factors)
    assert got == expected
    assert type(got) is type(expected) and got.args == expected.args


def test_the_fast_path_is_taken_for_the_terms_of_a_mass_matrix():
    m1, m2, l1, l2, q1, q2 = sp.symbols("m1 m2 l1 l2 q1 q2")
    factors = [m1 + m2, l1, l2, sp.cos(q1), sp.cos(q2)]
    assert _only_sorting_needed(sp.S.One, factors)
    assert _only_sorting_needed(sp.S.NegativeOne, [l1, m1, sp.sin(q1) + q2 ** 2, sp.cos(q1) ** 2])


def test_mul_is_left_what_only_it_does():
    # merging exponents, exp(x)·exp(y), distributing a number over a sum, numbers, non-commuting factors
    assert not _only_sorting_needed(sp.S.One, [x, x ** 2])
    assert not _only_sorting_needed(sp.S.One, [sp.exp(x), sp.exp(y)])
    assert not _only_sorting_needed(sp.Integer(2), [x + y])
    assert not _only_sorting_needed(sp.S.One, [sp.sqrt(2), x])
    assert not _only_sorting_needed(sp.S.One, [A, x])
    assert not _only_sorting_needed(sp.S.Zero, [x])


BENIGN = [x, y, z, a, b, sp.sin(x), sp.cos(x), sp.cos(y), f(z), x + y, a + 1, x - z ** 2,
          sp.Abs(x), sp.atan2(x, y), sp.sin(x) + sp.cos(y), sp.Symbol("m10"), sp.Symbol("m2")]


@settings(max_examples=1500, deadline=None)
@given(st.sampled_from(COEFFICIENTS[:-1]),
       st.lists(st.tuples(st.sampled_from(BENIGN), st.sampled_from(EXPONENTS)), min_size=1, max_size=7,
                unique_by=lambda pair: pair[0]))
def test_sorting_only_products_take_the_fast_path_and_equal_mul(coefficient, pairs):
    factors = [_power(base, exp) for base, exp in pairs]
    expected = sp.Mul(coefficient, *factors)
    rational = all(exp.is_Rational for _, exp in pairs)  # Mul rebuilds symbolic exponents
    if rational and not (len(factors) == 1 and factors[0].is_Add and coefficient is not sp.S.One):
        assert _only_sorting_needed(coefficient, factors) or any(
            fa.as_base_exp()[0] == fb.as_base_exp()[0] for i, fa in enumerate(factors) for fb in factors[:i])
    got = product(coefficient, factors)
    assert type(got) is type(expected) and got.args == expected.args


MUL_ARGS = [*BENIGN, sp.Integer(2), sp.Rational(-1, 3), sp.S.One, sp.S.NegativeOne, sp.Float(1.5), sp.S.Zero,
            sp.Float(0.1), sp.Float(0.3) * x, x + sp.oo, sp.Function("f", real=True)(z), x ** sp.Float(2.0),
            sp.Mul(2, x + y, evaluate=False), -x * sp.sin(y), 3 * a * b, x ** 2, sp.sqrt(2) * z, sp.exp(x), sp.I]


@settings(max_examples=3000, deadline=None)
@given(st.lists(st.sampled_from(MUL_ARGS), min_size=0, max_size=6))
def test_mul_is_sympy_mul_argument_for_argument(args):
    expected = sp.Mul(*args)
    got = mul(*args)
    assert type(got) is type(expected) and got.args == expected.args and got == expected


ZERO = sp.Symbol("zr", zero=True)
TIE = sp.Function("f", real=True)(z)  # unequal to f(z), yet Basic.compare ranks them equal


@pytest.mark.parametrize("coefficient, factors", [
    (sp.S.One, [x ** sp.factor(2 * a + 2 * b), y]),               # Mul rebuilds the exponent 2*(a + b)
    (sp.S.One, [sp.Pow(x, sp.Mul(-1, a + b, evaluate=False)), y]),
    (sp.S.One, [x ** ZERO, y]),                                   # an exponent known to be zero
    (sp.Integer(2), [x ** ZERO, y + z]),
    (sp.S.One, [f(z) * y, TIE]),
])
def test_products_that_mul_rebuilds(coefficient, factors):
    expected = sp.Mul(coefficient, *factors)
    got = product(coefficient, factors)
    assert type(got) is type(expected) and got.args == expected.args


@pytest.mark.parametrize("args", [
    (sp.Float(0.1) * x, sp.Float(0.2), sp.Float(0.3)),              # Float products depend on the order
    (y, x + sp.oo, sp.Rational(1, 2), sp.S.Zero),                  # so does 0·∞
    (f(z) * y, TIE), (TIE * y, f(z), x),                           # ties of the sort keep Mul's order
])
def test_mul_keeps_what_depends_on_mul_order(args):
    expected = sp.Mul(*args)
    got = mul(*args)
    assert type(got) is type(expected) and got.args == expected.args


def test_nothing_is_shortened_inside_evaluate_false():
    with sp.evaluate(False):
        assert product(sp.S.One, [y, x]).args == sp.Mul(1, y, x).args
        assert mul(y, x * z, x).args == sp.Mul(y, x * z, x).args
