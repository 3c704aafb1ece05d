"""Common factors drawn out of sums, as SymPy's ``factor_terms`` draws them, each subtree once.

The display's simplifier (:mod:`gacli.algebra.readable`) and the choice of
generated code (:mod:`gacli.mechanics.code`) call ``factor_terms`` on sums
whose pieces they factored a moment before: a coefficient, then the sum of
coefficients times sines, then the whole. SymPy walks each of those trees
again from the leaves; most of a mid-sized robot's text derive went there
(4.9 of 11.4 s for a unicycle with a rider). This is SymPy's own walk, with
the same steps and so the same result, remembering what each subtree
became, so a piece factored once is not factored again.
"""

from __future__ import annotations

import sympy as sp
from sympy.core.exprtools import gcd_terms
from sympy.core.mul import _keep_coeff

from gacli.algebra.coerce import as_expr

# Subtrees remembered at most; past it the memory starts again (a 6-link arm's display holds ~40,000).
REMEMBERED = 200_000

_SEEN: dict[sp.Basic, sp.Basic] = {}


def factor_terms(expr: sp.Expr) -> sp.Expr:
    """``sympy.factor_terms(expr)`` with its default options (no radicals, numbers not cleared, signs kept)."""
    if len(_SEEN) > REMEMBERED:
        _SEEN.clear()
    return _do(as_expr(expr))


def _do(expr):
    if not isinstance(expr, sp.Basic) or expr.is_Atom:
        return expr
    hit = _SEEN.get(expr)
    if hit is None:
        hit = _SEEN[expr] = _step(expr)
    return hit


def _step(expr):
    """One level of SymPy's ``factor_terms.do``; sums and integrals, which it treats apart, are left to it."""
    if isinstance(expr, (sp.Sum, sp.Integral)):
        return sp.factor_terms(expr)
    if expr.is_Pow or expr.is_Function or not hasattr(expr, "args_cnc"):
        args = expr.args
        new = tuple(_do(a) for a in args)
        return expr if new == args else expr.func(*new)
    cont, p = expr.as_content_primitive(radical=False, clear=False)
    if p.is_Add:
        parts = [_do(a) for a in sp.Add.make_args(p)]
        # A common minus sign, which gcd_terms leaves in.
        if not any(a.as_coeff_Mul()[0].extract_multiplicatively(-1) is None for a in parts):
            cont, parts = -cont, [-a for a in parts]
        special = {}  # exp(-(x + 2)) kept from becoming exp(-x - 2), as SymPy keeps it
        for i, a in enumerate(parts):
            _, e = a.as_base_exp()
            if e.is_Mul and e != sp.Mul(*e.args):
                parts[i] = sp.Dummy()
                special[parts[i]] = a
        p = gcd_terms(sp.Add._from_args(parts), isprimitive=True, clear=False, fraction=False).xreplace(special)
    elif p.args:
        p = p.func(*[_do(a) for a in p.args])
    return _keep_coeff(cont, p, clear=False, sign=True)
