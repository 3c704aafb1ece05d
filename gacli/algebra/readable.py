"""The one simplifier for reading, within a budget of operations per step.

Everything printed for people (text, LaTeX, ``--steps``) goes through
:class:`Tidy`; generated code never does, so display choices cannot change
what a simulator computes.

It does what a careful person does by hand, and nothing that can grow an
expression: sin² + cos² = 1 angle by angle (:mod:`gacli.algebra.trig`, bounded by
the number of terms it would distribute), common factors taken out of sums
(``factor_terms``, which never expands), and, for a quotient that is small,
cancellation of common factors. SymPy's ``simplify`` is not used on
equations: its time is unbounded in the size of what it tries, and it
rewrites ``abs`` and ``sign`` into ``Piecewise`` that a reader did not write.
The one exception is :func:`solved_tidy`, for quotients that come out of a
symbolic solve (the constraint forces), where it runs only on expressions of
at most 150 operations.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy as sp
from sympy.printing.str import StrPrinter

from gacli.algebra import trig
from gacli.algebra.angle_sums import angle_sums_compacted
from gacli.algebra.angles import relative
from gacli.algebra.coefficients import small_or_whole
from gacli.algebra.signs import with_signs
from gacli.algebra.symbols import RATE_NAME
from gacli.algebra.terms import factor_terms
from gacli.algebra.graph import LARGE_TREE, expands_within, is_large, is_small, postorder

# A quotient is cancelled (which expands numerator and denominator) only up
# to this many operations.
SIMPLIFY_OPS = 600
# Common factors are taken out of sums (a walk that never expands) up to this
# many nodes.
FACTOR_NODES = 5_000
# An expression in the rates is multiplied out and collected on their products
# only while it would have at most this many terms.
COLLECT_TERMS = 2_000
# Any other expression is multiplied out (or cancelled) only while it would have at most this many.
EXPANDED_TERMS = 2_000
# The budget of one step, counted in operations handed to simplify rather
# than in seconds, so that the output is the same on a slow machine.
STEP_BUDGET_OPS = 5_000
# An equation of motion too large to walk as a tree is not written out for people
# either: it is printed through named quantities (gacli.display.named, docs/printing.md).
DISPLAY_NODES = LARGE_TREE


@dataclass
class Tidy:
    """Simplify expressions until ``budget`` operations have been simplified, then show them as derived."""

    budget: int = STEP_BUDGET_OPS
    spent: int = 0

    def __call__(self, expr: sp.Expr) -> sp.Expr:
        # The identity first, whatever the size: it bounds its own work, and a
        # large expression is where sin² + cos² costs the reader most.
        expr = trig.reduce(expr)
        if not is_small(expr, FACTOR_NODES) or self.spent >= self.budget:
            # Past the budget, shown as derived: taking out common factors and collecting on the
            # rates cost a 6-link chain's printout 20 s past it, for a few characters.
            return expr
        # A pair of angles the expression holds only through their sum or difference
        # (a bead at s on a spinning hoop: s + φ) is written so, as by hand.
        expr = relative(expr, sums=True)
        expr = angle_sums_compacted(expr)
        candidates = [c for c in (self._readable(expr), self._by_rates(expr), self._over_common(expr))
                      if c is not None]
        # The shortest for a reader, unless another has symbols cancelled out of it
        # (Q − F of an equation: the loads meet only multiplied out, and a shorter
        # form that still shows them would say the equation holds them twice).
        fewest = [c for c in candidates if not any(o.free_symbols < c.free_symbols for o in candidates)]
        # The first of equals: the plain reading; then a spring's u/|u| read as sign(u).
        return with_signs(min(fewest, key=lambda c: len(str(c))))

    def _readable(self, expr: sp.Expr) -> sp.Expr:
        ops = sp.count_ops(expr)
        if self.spent + ops > self.budget:
            return factor_terms(expr)
        self.spent += ops
        return readable(expr)

    def _by_rates(self, expr: sp.Expr) -> sp.Expr | None:
        """A polynomial in the rates, collected on their products, each coefficient read.

        As derived, the rest of an equation of motion holds the same product
        of rates in many terms, under different factors (a wheel's and the
        chassis' shares of V·a): only multiplied out do they meet, and only
        then do their coefficients cancel. Done when the multiplied-out form
        is small (counted first); the caller keeps it when it prints shorter.
        """
        rates = sorted((s for s in expr.free_symbols if RATE_NAME.match(s.name)), key=sp.default_sort_key)
        if not rates or not expands_within(expr, COLLECT_TERMS) or not small_or_whole(expr):
            return None
        groups: dict[sp.Expr, list[sp.Expr]] = {}
        for term in sp.Add.make_args(sp.expand(expr)):
            coefficient, monomial = term.as_independent(*rates, as_Add=False)
            groups.setdefault(monomial, []).append(coefficient)
        terms = []
        for monomial in sorted(groups, key=sp.default_sort_key):
            coefficient = trig.reduce(sp.Add(*groups[monomial]), cancel=True)
            if coefficient != 0:
                terms.append(self._readable(coefficient) * monomial)
        return sp.Add(*terms)

    def _over_common(self, expr: sp.Expr) -> sp.Expr | None:
        """``expr`` over the common denominator of its sums (:func:`over_common_denominator`).

        Bounded, as :meth:`_by_rates` is, by the terms it would multiply out, not by the budget.
        """
        return over_common_denominator(expr) if _has_denominator(expr) else None

    def collected(self, expr: sp.Expr, accelerations) -> sp.Expr:
        """Collected on the accelerations, each coefficient tidied."""
        expanded = sp.expand(expr) if is_small(expr, 2 * SIMPLIFY_OPS) and expands_within(expr, EXPANDED_TERMS) else expr
        parts = sp.collect(expanded, list(accelerations), evaluate=False)
        total = sp.S.Zero
        for key in sorted(parts, key=sp.default_sort_key):
            total += self(parts[key]) * key
        return total


def readable(expr: sp.Expr) -> sp.Expr:
    """sin² + cos² = 1, common factors out, a small quotient cancelled; never larger work than that.

    When it multiplies out small, the expression collected on its sines and cosines
    (each coefficient factored) is read too, and the shorter kept.
    """
    expr = trig.reduce(expr)  # a second time costs little: nothing is left to distribute
    if _is_quotient(expr) and is_small(expr, SIMPLIFY_OPS) and expands_within(expr, EXPANDED_TERMS):
        cancelled = trig.reduce(sp.cancel(expr))  # cancel multiplies out, and may rebuild sin² + cos²
        if sp.count_ops(cancelled) < sp.count_ops(expr):
            expr = cancelled
    plain = factor_terms(expr)
    if not expr.has(sp.sin, sp.cos) or not expands_within(expr, COLLECT_TERMS // 4):
        return plain
    by_angles = collected(sp.expand(expr))
    return by_angles if len(str(by_angles)) < len(str(plain)) else plain


def over_common_denominator(expr: sp.Expr) -> sp.Expr | None:
    """N/D as a careful person writes a quotient: D the product of the sums and functions in the
    denominators (L − c cos δ of a steered wheel, a loop's sin(θ₂ − θ₃)), N collected (:func:`collected`); None when there is no such
    sum or N would multiply out to more than COLLECT_TERMS terms.

    As derived, the terms of an entry keep their own denominators, 1/D and 1/D², each
    beside its own part of the numerator, and a coefficient such as m_c L² c² repeats
    under both. Monomial denominators (the r² of C_w/r²) stay in the coefficients.
    """
    if not expands_within(expr, COLLECT_TERMS) or len(_sum_denominators(expr)) > MAX_DENOMINATORS:
        return None
    numerator, denominator = sp.fraction(sp.together(expr))
    if not expands_within(numerator, COLLECT_TERMS) or not is_small(denominator, SIMPLIFY_OPS):
        return None
    sums, monomials = [], []
    # A sine in the denominator is brought over only in a small quotient (a loop's dependent rate):
    # over a rolling robot's cos θ every entry was multiplied out for nothing (2 s of a derive).
    over_sines = is_small(expr, SINE_DENOMINATOR_NODES)
    for factor in sp.Mul.make_args(factor_terms(denominator)):
        base = factor.base if factor.is_Pow else factor
        (sums if base.is_Add or (over_sines and isinstance(base, sp.Function)) else monomials).append(factor)
    if not sums:
        return None
    # Over a sine the numerator may be one too: a loop's dependent rate, (sin(θ₁ − θ₂) cos(θ₂ − θ₃)
    # + cos(θ₁ − θ₂) sin(θ₂ − θ₃))/sin(θ₂ − θ₃), is sin(θ₁ − θ₃)/sin(θ₂ − θ₃).
    numerator = angle_sums_compacted(trig.reduce(sp.expand(numerator), cancel=True))
    return collected(sp.expand(numerator), sp.Mul(*monomials)) / sp.Mul(*sums)


# Tree nodes of a quotient up to which a sine or cosine in its denominator is brought over too.
SINE_DENOMINATOR_NODES = 150

# Distinct sums in denominators past which no common denominator is formed: ``together``
# multiplies them all, in time quadratic in their number (400 of them took 6 s).
MAX_DENOMINATORS = 8


def _sum_denominators(expr: sp.Expr) -> set[sp.Expr]:
    return {node.base for node in postorder([expr]) if node.is_Pow and node.exp.is_negative and node.base.is_Add}


def collected(expanded: sp.Expr, below: sp.Expr = sp.S.One) -> sp.Expr:
    """A sum collected on its products of rates, each coefficient on its products of sines
    and cosines, and each coefficient of those (divided by ``below``) factored while small.

    m_k (b² − w²)/w², not −A_k b²/(c² w²) + A_k/c² + ... : the parameters of a term group
    as a careful person groups them.
    """
    terms = sp.Add.make_args(expanded)
    rates = sorted({s for s in expanded.free_symbols if RATE_NAME.match(s.name)}, key=sp.default_sort_key)
    angles = sorted(expanded.atoms(sp.sin, sp.cos), key=sp.default_sort_key)
    groups: dict[sp.Expr, dict[sp.Expr, list[sp.Expr]]] = {}
    for term in terms:
        rest, by_rates = term.as_independent(*rates, as_Add=False) if rates else (term, sp.S.One)
        coefficient, by_angles = rest.as_independent(*angles, as_Add=False) if angles else (rest, sp.S.One)
        groups.setdefault(by_rates, {}).setdefault(by_angles, []).append(coefficient)
    out = []
    for r in sorted(groups, key=sp.default_sort_key):
        inner = groups[r]
        out.append(factor_terms(sp.Add(*[_factored(sp.Add(*inner[a]) / below) * a
                                            for a in sorted(inner, key=sp.default_sort_key)])) * r)
    return factor_terms(sp.Add(*out))


# A coefficient of parameters alone is factored (a polynomial factorization) only
# up to this many operations and this degree in any one symbol.
FACTOR_OPS = 120
FACTOR_DEGREE = 6


def _factored(coefficient: sp.Expr) -> sp.Expr:
    """The coefficient's common factors out, or its factorization where that prints shorter."""
    plain = factor_terms(coefficient)
    if len(sp.Add.make_args(sp.expand(plain))) < 3 or not _factorable(coefficient):
        return plain  # two terms factor into something no shorter ((b − w)(b + w))
    factored = _factor(coefficient)
    return factored if len(str(factored)) < len(str(plain)) else plain


@functools.lru_cache(maxsize=4096)  # the same coefficient recurs in every entry of M and F
def _factor(coefficient: sp.Expr) -> sp.Expr:
    return sp.factor(coefficient)


def _factorable(expr: sp.Expr) -> bool:
    """Small, of parameters alone, and of low degree: where polynomial factoring is cheap."""
    if not is_small(expr, FACTOR_OPS) or expr.has(sp.Function):
        return False
    return all(p.exp.is_Integer and abs(p.exp) <= FACTOR_DEGREE for p in expr.atoms(sp.Pow))


def _has_denominator(expr: sp.Expr) -> bool:
    """Whether a symbolic denominator stands anywhere in ``expr``, not only in its top-level terms."""
    return any(node.is_Pow and node.exp.is_negative and not node.base.is_Number for node in postorder([expr]))


def _is_quotient(expr: sp.Expr) -> bool:
    """Whether some term has a symbolic denominator (where cancel can help)."""
    return any(not sp.fraction(term)[1].is_Number for term in sp.Add.make_args(expr))


# A symbolically solved quotient (the constraint forces, M⁻¹F put in) is
# cancelled up to this size, then simplified while it is this small: operations, not seconds.
SOLVED_CANCEL_OPS = 3000
SOLVED_SIMPLIFY_OPS = 150
SOLVED_CANCEL_SINES_OPS = 300


def solved_tidy(expr: sp.Expr) -> sp.Expr:
    """A quotient from a symbolic solve for reading: cancelled, then simplified when small.

    The constraint forces of ``--reactions`` are such quotients; bounded by
    their size in operations, ``simplify`` cannot run away on them.
    """
    ops = sp.count_ops(expr)
    if ops > SOLVED_CANCEL_OPS:
        return expr
    if ops > SOLVED_CANCEL_SINES_OPS and expr.has(sp.sin, sp.cos):
        # cancel's gcd of polynomials in sines and cosines as generators can run away: Routh's
        # sphere's λ, 432 operations, did not finish in 15 minutes; read as readable reads any
        # expression it grew threefold, and Chaplygin's ball's ran as long in trig.reduce's expand.
        return expr
    expr = sp.cancel(expr)
    return sp.simplify(expr) if sp.count_ops(expr) <= SOLVED_SIMPLIFY_OPS else expr


def displayable(d) -> bool:
    """Whether the derivation's M and F are small enough to print as formulas."""
    # The nonzero entries only: a wide system's M is k² entries, nearly all zero.
    return not any(is_large(e) for e in (*d.mass_matrix.todok().values(), *d.forcing))


class _FilePrinter(StrPrinter):
    """SymPy's str printer with the functions named as the file's grammar names them."""

    def _print_Abs(self, expr) -> str:
        return f"abs({self._print(expr.args[0])})"

    def _print_Exp1(self, expr) -> str:
        # Not SymPy's 'E': the grammar has no such constant, and a parameter may be named E.
        return "exp(1)"

    # The sign order a textbook uses (:func:`positive_first`, :func:`oriented`), as LaTeX has it too.
    def _as_ordered_terms(self, expr, order=None):
        return positive_first(super()._as_ordered_terms(expr, order=order))

    def _print_Mul(self, expr) -> str:
        turn = turned(expr)
        if turn is None:
            return super()._print_Mul(expr)
        return toggled(super()._print_Mul(turn[1]), turn[0])


_PRINTER = _FilePrinter({"order": "lex"})


def pythagorean(value: sp.Expr) -> sp.Expr:
    """A small expression with sin² + cos² = 1 applied where that shortens it: a named quantity
    may be z cos² ψ + z sin² ψ (a toroidal bicycle's), which a reader should see as z."""
    if not value.has(sp.sin, sp.cos) or not is_small(value, 200):
        return value
    reduced = trig.reduce(value)
    return reduced if sp.count_ops(reduced) < sp.count_ops(value) else value


def show(expr) -> str:
    """An expression in the system file's grammar (``dot(x)``, ``**``, ``abs``)."""
    return _PRINTER.doprint(expr)


# -- sign order for printing -------------------------------------------------------

def positive_first(terms: list) -> list:
    """The terms of a sum with the first positive one moved to the front: ``I_z - I_y``, not ``-I_y + I_z``."""
    if not terms or not oriented(terms[0])[0]:
        return list(terms)
    for i, term in enumerate(terms):
        if not oriented(term)[0]:
            return [term] + list(terms[:i]) + list(terms[i + 1:])
    return list(terms)


def _parameter(term: sp.Expr) -> sp.Symbol | None:
    """The symbol of ±c·s (c a positive number, s a symbol that is not a rate), else None."""
    coefficient, rest = term.as_coeff_Mul()
    if isinstance(rest, sp.Symbol) and not RATE_NAME.match(rest.name) and coefficient.is_nonzero:
        return rest
    return None


def _reversed_difference(factor: sp.Expr) -> bool:
    """Whether ``factor`` is a difference of two parameters with the later-sorted one subtracted:
    ``A - B`` is written ``-(B - A)``, so that a difference reads the same wherever it stands."""
    if not factor.is_Add or len(factor.args) != 2:
        return False
    a, b = factor.args
    sa, sb = _parameter(a), _parameter(b)
    if sa is None or sb is None or sa == sb or a.could_extract_minus_sign() == b.could_extract_minus_sign():
        return False
    positive, negative = (sa, sb) if b.could_extract_minus_sign() else (sb, sa)
    return sp.default_sort_key(positive) < sp.default_sort_key(negative)


def turned(product: sp.Expr) -> tuple[bool, sp.Expr] | None:
    """(whether the sign changed, the product) with each difference of parameters in it written with
    the later-sorted parameter first (``I_z - I_y``); None when there is none to turn."""
    if not product.is_Mul:
        return None
    factors = list(product.args)
    flips = [i for i, f in enumerate(factors) if _reversed_difference(f)]
    if not flips:
        return None
    for i in flips:
        factors[i] = -factors[i]
    # Unevaluated: a number times a sum would be multiplied out again.
    return len(flips) % 2 == 1, sp.Mul(*factors, evaluate=False)


def toggled(text: str, change: bool) -> str:
    """A printed product with its sign changed when ``change`` (``- x`` → ``x``, ``x`` → ``-x``)."""
    if not change:
        return text
    if text.startswith("-"):
        return text[1:].lstrip()
    return "-" + text


def oriented(expr: sp.Expr) -> tuple[bool, sp.Expr]:
    """(negative, magnitude) of ``expr``, its differences of parameters turned (:func:`turned`):
    ``expr == -magnitude if negative else magnitude``."""
    from sympy.core.function import _coeff_isneg

    # A sum is negative only when all its terms are: I_z - I_y is not -(I_y - I_z).
    negative = all(_coeff_isneg(t) for t in expr.args) if expr.is_Add else expr.could_extract_minus_sign()
    magnitude = -expr if negative else expr
    turn = turned(magnitude)
    if turn is None:
        return negative, magnitude
    return negative != turn[0], turn[1]
