"""u/|u| read as sign(u), for display: a spring's force along its line, as written by hand.

A spring between a wall and a cart at x does work −k(|x + 1| − L₀) d|x + 1|,
whose coefficient the derivation forms as k(|x + 1| − L₀)(x + 1)/|x + 1|, or,
multiplied out, as k(w + x − L₀w/|w + x| − L₀x/|w + x|). A reader writes
k(|x + 1| − L₀) sign(x + 1). Where u = 0 the quotient is undefined and
sign(u) is 0; the spring's direction is undefined there either way, so the
two say the same. Only the display reads this: generated code keeps the
quotient, which every target prints without a sign function.
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra.graph import is_small

_FACTORED = 200  # tree nodes of a sum's numerator past which it is not factored


def with_signs(expr: sp.Expr) -> sp.Expr:
    """``expr`` with each u·|u|⁻¹ written sign(u), where that prints shorter; else ``expr``."""
    if not isinstance(expr, sp.Expr) or not expr.has(sp.Abs):
        return expr
    signed = _rebuilt(expr)
    return signed if len(str(signed)) < len(str(expr)) else expr


def _rebuilt(e: sp.Expr) -> sp.Expr:
    if not e.args or not e.has(sp.Abs):
        return e
    e = e.func(*(_rebuilt(a) for a in e.args))
    if e.is_Add and any(_denominator(t) is not None for t in e.args):
        return min((_over_common(e), _grouped(e)), key=lambda c: len(str(c)))
    return _signed_product(e) if e.is_Mul else e


def _denominator(term: sp.Expr) -> sp.Expr | None:
    """u of a term over |u| (the first such factor), or None."""
    for factor in sp.Mul.make_args(term):
        base, exp = factor.as_base_exp()
        if exp == -1 and (u := _abs_of(base)) is not None:
            return u
    return None


def _grouped(e: sp.Add) -> sp.Expr:
    """The terms over each |u| gathered, A/|u|, and written B sign(u) where A = B u: a spring's
    k L₀ (x + 1)/|x + 1| among the other terms of a generalized force (its k (x + 1) among them)."""
    groups: dict[sp.Expr, list] = {}
    rest = []
    for term in e.args:
        u = _denominator(term)
        (groups.setdefault(u, []) if u is not None else rest).append(term)
    for u, terms in groups.items():
        A = sp.Add(*terms) * sp.Abs(u)
        B = sp.cancel(A / u) if is_small(A, _FACTORED) else None
        signed = B is not None and not sp.fraction(B)[1].has(*u.free_symbols)
        rest += [B * sp.sign(u)] if signed else terms
    return sp.Add(*rest)


def _over_common(e: sp.Add) -> sp.Expr:
    """A sum with terms over |u|, over one denominator with its numerator factored (when small)."""
    numerator, denominator = sp.fraction(sp.together(e))
    if not is_small(numerator, _FACTORED):
        return e
    return _signed_product(sp.factor(numerator) / denominator)


def _abs_of(base: sp.Expr) -> sp.Expr | None:
    return base.args[0] if isinstance(base, sp.Abs) else None


def _signed_product(e: sp.Expr) -> sp.Expr:
    """In a product, each u·|u|⁻¹ (or −u·|u|⁻¹) as ±sign(u)."""
    if not e.is_Mul:
        return e
    powers: dict[sp.Expr, sp.Expr] = {}
    for factor in e.args:
        base, exp = factor.as_base_exp()
        powers[base] = powers.get(base, sp.S.Zero) + exp
    sign = sp.S.One
    for base, exp in list(powers.items()):
        u = _abs_of(base)
        if u is None or exp != -1:
            continue
        for candidate, s in ((u, sp.S.One), (-u, sp.S.NegativeOne)):
            if powers.get(candidate, sp.S.Zero).is_positive:
                powers[candidate] -= 1
                powers[base] = sp.S.Zero
                sign *= s * sp.sign(u)
                break
    if sign == 1:
        return e
    return sign * sp.Mul(*(b ** x for b, x in powers.items() if x != 0))
