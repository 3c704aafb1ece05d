"""Sums of products of sines and cosines reduced by sin² + cos² = 1, one angle at a time.

Kinematics carried through direction-cosine matrices leave terms such as
c·sin(ψ)²·X + c·cos(ψ)²·X, and for a body symmetric about an axis, powers of
its spin angle that cancel only through the identity. Taken as a polynomial
in s = sin θ and c = cos θ (other factors are its coefficients), an
expression has one normal form modulo s² + c² − 1 in which s appears at most
to the first power, and another in which c does; both are canonical, so an
expression that does not depend on θ loses θ altogether. Of the two, the one
with fewer terms is kept, angle by angle.

Only sums and products are distributed, and only where a factor holds a sine
or cosine; sums of parameters stay whole, so that factored masses such as
(m₁ + m₂) are not multiplied out. The work is bounded: an expression whose
distribution would exceed :data:`MAX_TERMS` terms is returned unchanged.
"""

from __future__ import annotations

from collections.abc import Iterable

import sympy as sp

from gacli.graph import postorder

# Terms of the distributed polynomial past which the reduction is not tried:
# it stays well below a second, and the equations it is meant for (a few
# bodies through a frame tree) need a few hundred.
MAX_TERMS = 4_000
# A coefficient is multiplied out to see whether it cancels only below this many terms.
COEFFICIENT_TERMS = 400
# Distinct subexpressions past which an expression is not even looked at.
MAX_NODES = 20_000

Monomial = frozenset  # of (sin(θ) or cos(θ), exponent) pairs
Poly = dict[Monomial, list[sp.Expr]]  # monomial → the coefficient as a list of terms


class _TooLarge(Exception):
    pass


def reduce(expr: sp.Expr) -> sp.Expr:
    """``expr`` with sin² + cos² = 1 applied, or ``expr`` itself when that would not be cheap."""
    if not isinstance(expr, sp.Expr) or not _may_square(expr):
        return expr
    try:
        poly = _distribute(expr)
    except _TooLarge:
        return expr
    angles = _angles(poly)
    if not angles:
        return expr
    for angle in angles:
        poly = min((_eliminate(poly, angle, sp.cos), _eliminate(poly, angle, sp.sin)), key=_size)
    return _rebuild(poly)


def reduce_all(exprs: Iterable[sp.Expr]) -> list[sp.Expr]:
    return [reduce(e) for e in exprs]


# -- to a polynomial in the sines and cosines ---------------------------------

def _may_square(expr: sp.Expr) -> bool:
    """Whether multiplying out could give a square of a sine or cosine (else there is nothing to reduce).

    One walk over the distinct subexpressions: a power of a sine or cosine, a
    power of a sum that holds one, or a product of two factors that hold the
    same sine (or the same cosine); sin θ · cos θ is no square. A chain of
    pendulums has none in most entries, and skipping them keeps the
    reduction nearly free there.
    """
    held: dict[sp.Basic, frozenset] = {}
    for count, node in enumerate(postorder([expr])):
        if count > MAX_NODES:
            return False  # too large to distribute anyway
        if isinstance(node, (sp.sin, sp.cos)):
            held[node] = frozenset((node,))
            continue
        inside = [held.get(a, frozenset()) for a in node.args]
        if node.is_Pow and inside[0] and node.exp.is_Integer and node.exp >= 2:
            return True
        if node.is_Mul:
            seen: set = set()
            for part in inside:
                if seen & part:
                    return True
                seen |= part
        held[node] = frozenset().union(*inside) if inside else frozenset()
    return False


def _is_trig(expr: sp.Expr) -> bool:
    return isinstance(expr, (sp.sin, sp.cos))


def _distribute(expr: sp.Expr) -> Poly:
    if expr.is_Add:
        out: Poly = {}
        for term in expr.args:
            _merge(out, _distribute(term))
        return _bounded(out)
    if expr.is_Mul:
        out = {frozenset(): [sp.S.One]}
        plain = []
        for factor in expr.args:
            if factor.has(sp.sin, sp.cos):
                out = _times(out, _distribute(factor))
            else:
                plain.append(factor)
        if plain:
            scale = sp.Mul(*plain)
            out = {m: [scale * c for c in cs] for m, cs in out.items()}
        return out
    if expr.is_Pow and expr.exp.is_Integer:
        n = int(expr.exp)
        if _is_trig(expr.base):
            return {frozenset(((expr.base, n),)): [sp.S.One]}
        if n > 0 and expr.base.is_Add:
            out = {frozenset(): [sp.S.One]}
            base = _distribute(expr.base)
            for _ in range(n):
                out = _times(out, base)
            return out
    if _is_trig(expr):
        return {frozenset(((expr, 1),)): [sp.S.One]}
    if expr.args and not expr.is_Atom:
        # Not a polynomial in the sines and cosines (a quotient, a root): reduce inside it.
        expr = expr.func(*[reduce(a) if isinstance(a, sp.Expr) else a for a in expr.args])
    return {frozenset(): [expr]}


def _merge(into: Poly, other: Poly) -> None:
    for monomial, coefficient in other.items():
        into.setdefault(monomial, []).extend(coefficient)


def _times(a: Poly, b: Poly) -> Poly:
    out: Poly = {}
    for ma, ca in a.items():
        for mb, cb in b.items():
            terms = out.setdefault(_multiply(ma, mb), [])
            terms.extend(x * y for x in ca for y in cb)
    return _bounded(out)


def _bounded(poly: Poly) -> Poly:
    if sum(len(c) for c in poly.values()) > MAX_TERMS:
        raise _TooLarge
    return poly


def _multiply(a: Monomial, b: Monomial) -> Monomial:
    powers = dict(a)
    for base, exp in b:
        powers[base] = powers.get(base, 0) + exp
    return _monomial(powers)


def _monomial(powers: dict[sp.Expr, int]) -> Monomial:
    return frozenset((b, e) for b, e in powers.items() if e != 0)


# -- the reduction --------------------------------------------------------------

def _angles(poly: Poly) -> list[sp.Expr]:
    """The angles whose sine or cosine appears squared or higher: the only places the identity acts."""
    found = {base.args[0] for monomial in poly for base, exp in monomial if exp >= 2}
    return sorted(found, key=sp.default_sort_key)


def _eliminate(poly: Poly, angle: sp.Expr, kind: type) -> Poly:
    """Powers of ``kind``(angle) above the first replaced: f² → 1 − g² (f, g = sin, cos in some order)."""
    f, g = kind(angle), (sp.cos if kind is sp.sin else sp.sin)(angle)
    out: Poly = {}
    work = [(dict(m), c) for m, c in poly.items()]
    while work:
        powers, coefficient = work.pop()
        if powers.get(f, 0) < 2:
            _merge(out, {_monomial(powers): coefficient})
            continue
        lower = dict(powers)
        lower[f] -= 2
        other = dict(lower)
        other[g] = other.get(g, 0) + 2
        work.append((lower, coefficient))
        work.append((other, [-c for c in coefficient]))
    return _summed(out)


def _summed(poly: Poly, multiply_out: bool = False) -> Poly:
    """Each coefficient summed once (and multiplied out where shorter); vanishing ones dropped."""
    out: Poly = {}
    for monomial, terms in poly.items():
        total = sp.Add(*terms)
        if multiply_out:
            total = _coefficient(total)
        if total != 0:
            out[monomial] = [total]
    return out


def _coefficient(total: sp.Expr) -> sp.Expr:
    """A coefficient multiplied out where that is shorter: sums of rates that cancel only so.

    Parameters' sums such as (m₁ + m₂) stay whole where multiplying them out
    would lengthen the coefficient.
    """
    if not total.is_Add or expanded_terms(total, COEFFICIENT_TERMS) > COEFFICIENT_TERMS:
        return total
    expanded = sp.expand(total)
    return expanded if len(sp.Add.make_args(expanded)) < len(total.args) else total


def _size(poly: Poly) -> tuple[int, int]:
    terms = sum(len(sp.Add.make_args(c[0])) for c in poly.values())
    degree = sum(abs(e) for m in poly for _, e in m)
    return terms, degree


def _rebuild(poly: Poly) -> sp.Expr:
    terms = []
    for monomial, coefficient in _summed(poly, multiply_out=True).items():
        trig = sp.Mul(*[b ** e for b, e in monomial])
        terms.append(coefficient[0] * trig)
    return sp.Add(*terms)


def expanded_terms(expr: sp.Expr, limit: int) -> int:
    """How many terms ``expand(expr)`` would have, counted without expanding (stops past ``limit``)."""
    if expr.is_Add:
        total = 0
        for term in expr.args:
            total += expanded_terms(term, limit)
            if total > limit:
                break
        return total
    if expr.is_Mul:
        total = 1
        for factor in expr.args:
            total *= expanded_terms(factor, limit)
            if total > limit:
                break
        return total
    if expr.is_Pow and expr.exp.is_Integer and expr.exp > 0 and expr.base.is_Add:
        k = expanded_terms(expr.base, limit)
        n = int(expr.exp)
        # The multinomial count C(n + k − 1, k − 1), stopped as soon as it passes the limit.
        total = 1
        for i in range(1, min(n, k - 1) + 1):
            total = total * (max(n, k - 1) + i) // i
            if total > limit:
                break
        return total
    return 1
