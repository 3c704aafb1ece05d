"""Sums of products of sines and cosines reduced by sin² + cos² = 1, one angle at a time.

Direction cosines leave terms such as c·sin(ψ)²·X + c·cos(ψ)²·X. As a polynomial in s = sin θ and
c = cos θ (other factors its coefficients), an expression has one normal form modulo s² + c² − 1
with s at most to the first power, and one with c; both are canonical, so an expression free of θ
loses θ altogether. The one with fewer terms is kept, angle by angle. Only sums and products are
distributed, where a factor holds a sine or cosine (a factored mass (m₁ + m₂) stays whole), and the
work is bounded: past :data:`MAX_TERMS` terms an expression is returned unchanged. A sine or cosine
of a sum (θ + δ) beside one of its angles alone is first written out (:mod:`gacli.algebra.angle_sums`).
"""

from __future__ import annotations

import math

import sympy as sp

from gacli.algebra import angle_sums
from gacli.algebra.coefficients import multiplied_out
from gacli.algebra.graph import postorder, substitute


# Terms of the distributed polynomial past which the reduction is not tried:
# it stays well below a second, and the equations it is meant for (a few
# bodies through a frame tree) need a few hundred.
MAX_TERMS = 2_000
# Terms formed in all the products of one reduction, past which it stops:
# a large entry that would end unchanged must not cost much to find so.
MAX_WORK = 2_000
# Terms formed by one elimination of an angle's squares, past which it stops.
ELIMINATED_TERMS = 4 * MAX_TERMS
_WORK = object()  # the memo's key for the work done so far
# Distinct subexpressions past which an expression is not even looked at.
MAX_NODES = 20_000

Monomial = frozenset  # of (sin(θ) or cos(θ), exponent) pairs
Poly = dict[Monomial, list[sp.Expr]]  # monomial → the coefficient as a list of terms


class _TooLarge(Exception):
    """An expression past MAX_NODES, MAX_TERMS or MAX_WORK: left as it is."""

def reduce(expr: sp.Expr, cancel: bool = False) -> sp.Expr:
    """``expr`` with sin² + cos² = 1 applied, or ``expr`` itself when that would not be cheap.

    With ``cancel``, also an expression without squares is distributed, so that
    terms equal but for the order of their factors cancel (X sin φ cos φ −
    X cos φ sin φ after a turn by φ).
    """
    if not isinstance(expr, sp.Expr) or not (cancel and _holds_trig(expr) or _may_square(expr)):
        return expr
    memo = {_WORK: 0}
    # Counted first: an entry too large to distribute (a bicycle's solved rates)
    # is refused at the cost of a walk, not of the products formed before the
    # bound is met, which were half of the bicycle's derivation.
    plain = _reduced_or_none(expr, cancel, memo)
    # θ + δ beside θ alone: written out, every angle is one angle again and the
    # reduction a normal form (a steered wheel's rows). Kept only when shorter: a
    # hitch angle θ − θ_T beside θ and θ_T is the shorter angle to keep whole.
    sums = angle_sums.expansions(memo)
    # Substituted over the graph: SymPy's xreplace walks every path of a tree
    # whose subexpressions are shared (a bicycle's dependent accelerations:
    # 7.6 million calls for 74 entries, a derivation that never ended).
    written_out = _reduced_or_none(substitute([expr], sums)[0], cancel, {_WORK: 0}) if sums else None
    candidates = [e for e in (plain, written_out) if e is not None]
    return min(candidates, key=_nodes) if candidates else expr


def _reduced_or_none(expr: sp.Expr, cancel: bool, memo: dict) -> sp.Expr | None:
    """The reduction of ``expr``, or None when it is too large to distribute (``memo`` holds what the count saw)."""
    try:
        _count(expr, memo)
        return _reduce(expr, {_WORK: 0}, cancel)
    except _TooLarge:
        return None


def _nodes(expr: sp.Expr) -> int:
    return sum(1 for _ in postorder([expr]))


def _reduce(expr: sp.Expr, memo: dict, cancel: bool = False) -> sp.Expr:
    if not isinstance(expr, sp.Expr) or not (cancel or _may_square(expr)):
        return expr
    poly = _distribute(expr, memo)
    angles = _angles(poly)
    if not angles and not cancel:
        # Squares inside a root alone (a spring's length, √(l² sin² θ + l² cos² θ + …)), reduced there.
        inside = _rebuild(poly)
        return inside if _nodes(inside) < _nodes(expr) else expr
    for angle in angles:
        eliminated = [p for p in (_eliminate(poly, angle, sp.cos), _eliminate(poly, angle, sp.sin)) if p is not None]
        if not eliminated:
            raise _TooLarge
        poly = min(eliminated, key=_size)
    return _rebuild(poly)


# -- to a polynomial in the sines and cosines ---------------------------------

def monomial_may_square(powers: dict) -> bool:
    """:func:`_may_square` for a product given as {base: exponent}, as gacli.mechanics.equations groups terms."""
    for base, exp in powers.items():
        if _is_trig(base):
            if not exp.is_Integer or exp >= 2 or exp < 0:
                return True
        elif not (base.is_Symbol or base.is_Number):
            return True  # a sum or function: only the full walk can tell
    return False


def _may_square(expr: sp.Expr) -> bool:
    """Whether multiplying out could give a square of a sine or cosine (else there is nothing to reduce).

    One walk over the distinct subexpressions: a power of a sine or cosine, a
    power of a sum that holds one, or a product of two factors that hold the
    same sine (or the same cosine); sin θ · cos θ is no square. A chain of
    pendulums has none in most entries, and skipping them keeps the
    reduction nearly free there. An expression of more than MAX_NODES
    distinct subexpressions counts as none: it is too large to distribute.
    """
    try:
        return bool(angle_sums.expansions(_held(expr, {})))  # sin(θ + δ) beside sin θ, to write out
    except _Square:
        return True
    except (_TooLarge, RecursionError):
        return False


def _holds_trig(expr: sp.Expr) -> bool:
    """Whether a sine or cosine is inside ``expr``: one walk over its distinct
    subexpressions, none past MAX_NODES (``has`` walks the tree, which for a
    bicycle's equations is millions of nodes)."""
    try:
        return bool(_held(expr, {}))
    except _Square:
        return True
    except (_TooLarge, RecursionError):
        return False


class _Square(Exception):
    """A square of a sine or cosine may form: the reduction is worth trying."""


_NONE: frozenset = frozenset()


def _held(node: sp.Basic, memo: dict) -> frozenset:
    """The sines and cosines inside ``node``; raises _Square where a product or power could square one."""
    if node.is_Atom:
        return _NONE
    known = memo.get(node)
    if known is not None:
        return known
    if len(memo) > MAX_NODES:
        raise _TooLarge
    if isinstance(node, (sp.sin, sp.cos)):
        known = frozenset((node,))
    else:
        parts = [p for p in (_held(a, memo) for a in node.args) if p]
        if node.is_Pow and parts and node.exp.is_Integer and node.exp >= 2:
            raise _Square
        if node.is_Mul and len(parts) > 1 and sum(map(len, parts)) > len(frozenset().union(*parts)):
            raise _Square
        known = parts[0] if len(parts) == 1 else frozenset().union(*parts) if parts else _NONE
    memo[node] = known
    return known


def _is_trig(expr: sp.Expr) -> bool:
    return isinstance(expr, (sp.sin, sp.cos))


def _distribute(expr: sp.Expr, memo: dict) -> Poly:
    """The polynomial of ``expr``; ``memo`` holds those of subexpressions met before (a graph, not a tree)."""
    return _walk(expr, memo, _POLYNOMIALS)


def _count(expr: sp.Expr, memo: dict) -> int:
    """The terms :func:`_distribute` would form for ``expr``, raising _TooLarge where it would.

    The same walk (:func:`_walk`) over integers: the same memo of distinct
    subexpressions, the same work added at each product, the same bounds, and
    the reductions inside quotients and roots counted as they would be made.
    """
    return _walk(expr, memo, _COUNTS)


def _walk(expr: sp.Expr, memo: dict, algebra) -> object:
    known = memo.get(expr)
    if known is None:
        known = memo[expr] = _walk_new(expr, memo, algebra)
    return known


def _walk_new(expr: sp.Expr, memo: dict, algebra) -> object:
    """``expr`` as a polynomial in its sines and cosines, in ``algebra`` (polynomials or their sizes)."""
    if expr.is_Add:
        return algebra.bounded(algebra.sum([_walk(term, memo, algebra) for term in expr.args]))
    if expr.is_Mul:
        out, plain = algebra.one(), []
        for factor in expr.args:
            if factor.has(sp.sin, sp.cos):
                out = algebra.times(out, _walk(factor, memo, algebra), memo)
            else:
                plain.append(factor)
        return algebra.scaled(out, plain)
    if expr.is_Pow and expr.exp.is_Integer:
        n = int(expr.exp)
        if _is_trig(expr.base):
            return algebra.trig(expr.base, n)
        if n > 0 and expr.base.is_Add:
            out, base = algebra.one(), _walk(expr.base, memo, algebra)
            for _ in range(n):
                out = algebra.times(out, base, memo)
            return out
    if _is_trig(expr):
        return algebra.trig(expr, 1)
    if expr.args and not expr.is_Atom:
        # Not a polynomial in the sines and cosines (a quotient, a root): reduced inside.
        return algebra.opaque(expr, memo)
    return algebra.leaf(expr)


class _Polynomials:
    """The walk's algebra that forms the polynomial."""

    one = staticmethod(lambda: {frozenset(): [sp.S.One]})
    trig = staticmethod(lambda base, n: {frozenset(((base, n),)): [sp.S.One]})
    leaf = staticmethod(lambda expr: {frozenset(): [expr]})
    bounded = staticmethod(lambda poly: _bounded(poly))
    times = staticmethod(lambda a, b, memo: _times(a, b, memo))

    @staticmethod
    def sum(parts: list[Poly]) -> Poly:
        out: Poly = {}
        for part in parts:
            _merge(out, part)
        return out

    @staticmethod
    def scaled(poly: Poly, plain: list[sp.Expr]) -> Poly:
        if not plain:
            return poly
        scale = sp.Mul(*plain)
        return {m: [scale * c for c in cs] for m, cs in poly.items()}

    @staticmethod
    def opaque(expr: sp.Expr, memo: dict) -> Poly:
        return {frozenset(): [expr.func(*[_reduce(a, memo) if isinstance(a, sp.Expr) else a for a in expr.args])]}


class _Counts:
    """The walk's algebra that only counts the terms the polynomial would have."""

    one = staticmethod(lambda: 1)
    sum = staticmethod(lambda parts: sum(parts))
    scaled = staticmethod(lambda count, plain: count)
    trig = staticmethod(lambda base, n: 1)
    leaf = staticmethod(lambda expr: 1)

    @staticmethod
    def bounded(terms: int) -> int:
        if terms > MAX_TERMS:
            raise _TooLarge
        return terms

    @staticmethod
    def times(a: int, b: int, memo: dict) -> int:
        size = a * b
        memo[_WORK] += size
        if size > MAX_TERMS or memo[_WORK] > MAX_WORK:
            raise _TooLarge
        return _Counts.bounded(size)

    @staticmethod
    def opaque(expr: sp.Expr, memo: dict) -> int:
        for a in expr.args:  # as _reduce would: only what may hold a square is distributed
            if isinstance(a, sp.Expr) and _may_square(a):
                _walk(a, memo, _COUNTS)
        return 1


_POLYNOMIALS, _COUNTS = _Polynomials(), _Counts()


def _merge(into: Poly, other: Poly) -> None:
    for monomial, coefficient in other.items():
        into.setdefault(monomial, []).extend(coefficient)


def _times(a: Poly, b: Poly, memo: dict) -> Poly:
    # Refused before it is formed: a product of two large sums is where the work would go.
    size = _terms(a) * _terms(b)
    memo[_WORK] += size
    if size > MAX_TERMS or memo[_WORK] > MAX_WORK:
        raise _TooLarge
    out: Poly = {}
    for ma, ca in a.items():
        for mb, cb in b.items():
            terms = out.setdefault(_multiply(ma, mb), [])
            terms.extend(x * y for x in ca for y in cb)
    return _bounded(out)


def _bounded(poly: Poly) -> Poly:
    if _terms(poly) > MAX_TERMS:
        raise _TooLarge
    return poly


def _terms(poly: Poly) -> int:
    return sum(len(c) for c in poly.values())


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


def _eliminate(poly: Poly, angle: sp.Expr, kind: type) -> Poly | None:
    """Powers of ``kind``(angle) above the first replaced: f^(2k+r) → (1 − g²)^k f^r (f, g = sin, cos in
    some order), by the binomial theorem: k + 1 monomials. (One f² at a time made 2^k: sin⁴⁰ θ alone
    took 3.4 s.) None past ELIMINATED_TERMS terms formed."""
    f, g = kind(angle), (sp.cos if kind is sp.sin else sp.sin)(angle)
    out: Poly = {}
    formed = 0
    for monomial, coefficient in poly.items():
        powers = dict(monomial)
        k, r = divmod(powers.get(f, 0), 2)
        if k <= 0:  # f or 1/f² (a quotient's power) as it is
            _merge(out, {monomial: coefficient})
            continue
        formed += (k + 1) * len(coefficient)
        if formed > ELIMINATED_TERMS:
            return None
        powers[f], held = r, powers.get(g, 0)
        for j in range(k + 1):
            powers[g] = held + 2 * j
            scale = math.comb(k, j) * (-1) ** j
            _merge(out, {_monomial(powers): [scale * c for c in coefficient]})
    return _summed(out)


def _summed(poly: Poly, multiply_out: bool = False) -> Poly:
    """Each coefficient summed once (and multiplied out where shorter); vanishing ones dropped."""
    out: Poly = {}
    for monomial, terms in poly.items():
        total = sp.Add(*terms)
        if multiply_out:
            total = multiplied_out(total)
        if total != 0:
            out[monomial] = [total]
    return out


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
