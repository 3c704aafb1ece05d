"""Conditions on the parameters for every root of a characteristic polynomial to be stable.

After the roots at zero are divided out (the neighbouring steady motions of
a family: a change of spin or of speed), two cases:

* p(λ) even in λ, as for every conservative system and for the rolling
  disk and the top, whose linear equations have no first-order terms: the
  roots come in pairs ±λ and the motion is (neutrally) stable iff every
  root μ of p(√μ) is real and negative. For degree 1 in μ: a₀/a₁ > 0; for
  degree 2: a₁/a₂ > 0, a₀/a₂ > 0 and the discriminant a₁² − 4a₂a₀ > 0.
* otherwise Routh-Hurwitz (asymptotic stability): with p normalized to a
  positive leading coefficient, every leading principal minor of the
  Hurwitz matrix is positive.

Each condition is reduced by the signs the parameters have in the file
(a mass, a length, g: positive), factor by factor, so the disk's reads
3 r ω² − g > 0 and not a quotient with m and r in it.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

# Beyond degree 2 in μ the even case has no short closed test; the numbers decide.
_EVEN_DEGREE_LIMIT = 2


def zero_roots(coefficients: list[sp.Expr]) -> int:
    """How many of the lowest coefficients (a₀, a₁, …) vanish identically."""
    count = 0
    for c in coefficients:
        if sp.simplify(c) != 0:
            break
        count += 1
    return count


def conditions(coefficients: list[sp.Expr], signs: Mapping[sp.Symbol, sp.Symbol]) -> tuple[str, list[sp.Expr]] | None:
    """("even" or "hurwitz", [c, …] each to be > 0) for p = Σ aᵢ λⁱ; None when no closed test applies.

    ``coefficients`` from a₀ up, the zero roots divided out; ``signs`` maps a
    parameter to a symbol of its sign (positive or negative) for the reduction.
    """
    a = [sp.factor(sp.cancel(c)) for c in coefficients]
    if all(sp.simplify(c) == 0 for c in a[1::2]):
        mu = a[0::2]
        if len(mu) - 1 > _EVEN_DEGREE_LIMIT:
            return None
        return "even", _reduced(_even(mu), signs)
    return "hurwitz", _reduced(_hurwitz(a), signs)


def _even(mu: list[sp.Expr]) -> list[sp.Expr]:
    if len(mu) == 2:
        return [mu[0] * mu[1]]
    if len(mu) == 3:
        a0, a1, a2 = mu
        return [a1 * a2, a0 * a2, a1**2 - 4 * a2 * a0]
    return []


def _hurwitz(a: list[sp.Expr]) -> list[sp.Expr]:
    n = len(a) - 1
    lead = a[n]
    b = [c * lead for c in a]     # times the leading coefficient: a positive one, its sign made plain
    H = sp.Matrix(n, n, lambda i, j: _entry(b, n, 2 * j - i + 1))
    return [H[:k, :k].det(method="berkowitz") for k in range(1, n + 1)]


def _entry(b: list[sp.Expr], n: int, index: int) -> sp.Expr:
    # Row i, column j of the Hurwitz matrix holds a_{n-(2j-i+1)} (zero outside 0..n).
    k = n - index
    return b[k] if 0 <= k <= n else sp.S.Zero


def _reduced(exprs: list[sp.Expr], signs: Mapping[sp.Symbol, sp.Symbol]) -> list[sp.Expr]:
    back = {v: k for k, v in signs.items()}
    out: list[sp.Expr] = []
    for e in exprs:
        reduced = _drop_signed_factors(sp.factor(sp.cancel(e.xreplace(dict(signs)))))
        if reduced is True:
            continue
        reduced = sp.expand(reduced.xreplace(back)).as_content_primitive()[1]   # a positive content out
        if reduced not in out:
            out.append(reduced)
    return out


def _drop_signed_factors(e: sp.Expr):
    """e > 0 as a product of the factors whose sign the assumptions leave open; True if none."""
    numerator, denominator = sp.fraction(e)
    sign, kept = 1, []
    for factor in sp.Mul.make_args(numerator) + sp.Mul.make_args(denominator):
        base, power = factor.as_base_exp()
        if factor.is_positive:
            continue
        if factor.is_negative:
            sign = -sign
        elif power.is_even and base.is_real:
            continue     # a square: positive unless zero, where the strict test fails anyway
        else:
            kept.append(factor)
    if not kept:
        return True if sign > 0 else sp.S.Zero  # 0 > 0: never
    return sign * sp.Mul(*kept)
