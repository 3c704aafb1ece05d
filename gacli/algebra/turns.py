"""Sines and cosines of whole multiples of angles as a sum of turns, Σ c_m e^(i m·q).

cos φ = (e^(iφ) + e^(−iφ))/2 and sin φ = (e^(iφ) − e^(−iφ))/(2i), so an
expression polynomial in the sines and cosines of whole combinations m·q of
some angles q is one sum Σ c_m e^(i m·q), whatever way it was written: a
chain's cos(q₁ + q₂) and its cos q₁ cos q₂ − sin q₁ sin q₂ are the same two
terms. The sum is a normal form (Fourier's, in several angles), which
gives a planar position's vectors along the frames it turns by
(gacli.mechanics.program.planar) and a potential written with products of
sines and cosines folded back into sines and cosines of sums, which cost
less to differentiate.
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra.graph import expands_within, trees_within
from gacli.algebra.turn_products import PRODUCTS_NODES, TRIG_FACTORS, NotTurned, products

# Tree nodes of what SymPy's expand rewrites, at most (trig factors in one product: TRIG_FACTORS, as
# turn_products reads them): the terms of a product of k sums of two double each time.
TURNED_NODES = 2_000
# Terms of that expansion, at most.
TURNED_TERMS = 2_000


def turns(expr: sp.Expr, angles: list[sp.Symbol]) -> dict[tuple, sp.Expr] | None:
    """{m: c_m} with expr = Σ c_m e^(i m·q) (q = ``angles``, in order; c_m free of them), or None."""
    if trees_within([expr], PRODUCTS_NODES):
        try:
            return products(expr, angles)
        except NotTurned:
            pass
    if not trees_within([expr], TURNED_NODES):
        return None
    return _expanded(expr, angles)


def _expanded(expr: sp.Expr, angles: list[sp.Symbol]) -> dict[tuple, sp.Expr] | None:
    """:func:`turns` by SymPy's expand of the exponentials (any offset in the angles)."""
    w = [sp.Symbol(f"_w_{q}") for q in angles]
    try:
        exponentials = _exponentials(sp.S(expr), angles, w)
    except NotTurned:
        return None
    # Counted before SymPy's expand forms them: (x + y + z)**100 is a tree of six nodes and 5,151
    # terms, and its expansion took minutes and gigabytes.
    if not expands_within(exponentials, TURNED_TERMS):
        return None
    written = sp.expand(exponentials)
    out: dict[tuple, sp.Expr] = {}
    for term in sp.Add.make_args(written):
        powers = term.as_powers_dict()
        m = tuple(sp.S(powers.get(wj, 0)) for wj in w)
        if not all(k.is_Integer for k in m):
            return None
        c = term / sp.Mul(*(wj ** k for wj, k in zip(w, m)))
        if c.free_symbols & set(w):
            return None
        out[m] = out.get(m, sp.S.Zero) + c
    return {m: c for m, c in ((m, sp.expand(c)) for m, c in out.items()) if c != 0}


def angle(m: tuple, angles: list[sp.Symbol]) -> sp.Expr:
    """m·q."""
    return sp.Add(*(k * q for k, q in zip(m, angles)))


def real_imaginary(c: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(a, b) of an expanded c = a + i b whose symbols are real."""
    b = sp.expand(c).coeff(sp.I)
    return sp.expand(c - sp.I * b), b


def folded(expr: sp.Expr, angles: list[sp.Symbol]) -> sp.Expr | None:
    """A real ``expr`` as c₀ + Σ 2 (a_m cos m·q − b_m sin m·q) over one of each pair ±m (c_m = a_m + i b_m);
    None where it is not such a sum."""
    parts = turns(expr, angles)
    if parts is None:
        return None
    out = [real_imaginary(parts.pop(tuple(sp.S.Zero for _ in angles), sp.S.Zero))[0]]
    for m in sorted(parts, key=sp.default_sort_key):
        if tuple(-k for k in m) in parts and next(k for k in m if k != 0) < 0:
            continue  # its pair, +m, is written
        a, b = real_imaginary(parts[m])
        phi = angle(m, angles)
        out.append(2 * (a * sp.cos(phi) - b * sp.sin(phi)))
    return sp.Add(*out)


def _exponentials(expr: sp.Expr, angles: list, w: list) -> sp.Expr:
    """``expr`` with each cos(φ), sin(φ) of the angles written through e^(iφ) (w_j = e^(i q_j))."""
    def rewritten(f: sp.Expr) -> sp.Expr:
        m = [sp.diff(f.args[0], q) for q in angles]
        offset = sp.expand(f.args[0] - angle(m, angles))
        if not all(k.is_Integer for k in m) or offset.free_symbols & set(angles):
            raise NotTurned
        W = sp.Mul(*(wj ** k for wj, k in zip(w, m)))
        turn, back = sp.cos(offset) + sp.I * sp.sin(offset), sp.cos(offset) - sp.I * sp.sin(offset)
        return (W * turn + back / W) / 2 if isinstance(f, sp.cos) else (W * turn - back / W) / (2 * sp.I)

    moving = set(angles)
    for term in sp.preorder_traversal(expr):
        if term.is_Mul and sum(isinstance(f, (sp.cos, sp.sin)) for f in term.args) > TRIG_FACTORS:
            raise NotTurned
        # Refused before anything is rebuilt: SymPy re-evaluates each function around a rewritten
        # argument, and sin(sin(...(x))) sixty deep took minutes in its assumptions.
        if isinstance(term, sp.Function) and term.free_symbols & moving and (
                not isinstance(term, (sp.cos, sp.sin)) or term.args[0].has(sp.Function)):
            raise NotTurned
    out = expr.replace(lambda e: isinstance(e, (sp.cos, sp.sin)) and bool(e.free_symbols & moving), rewritten)
    if any(isinstance(f, sp.Function) and f.free_symbols & moving for f in sp.preorder_traversal(out)):
        raise NotTurned
    return out
