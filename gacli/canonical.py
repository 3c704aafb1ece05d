"""SymPy's canonical product, built directly when sorting is all it takes.

``sympy.Mul(*factors)`` goes through the cache, sympifies its arguments and
runs ``Mul.flatten``, which collects coefficients, merges powers of equal
bases, combines numeric radicals, distributes a number over a sum... and
finally sorts the factors. For the terms of the Gibbs-Appell equations
(a sum of masses times powers of lengths, sines and cosines, eq. 14.19)
none of that applies but the sort, and the rest costs three times as much
as the sort. :func:`product` builds the same object as ``Mul`` when it can
tell the factors need nothing else, and calls ``Mul`` otherwise.
"""

from __future__ import annotations

from collections.abc import Sequence

import sympy as sp
from sympy.core.mul import _args_sortkey


def mul(*args: sp.Expr) -> sp.Expr:
    """``sp.Mul(*args)``, equal to it argument for argument; products among ``args`` are flattened."""
    args = [a for a in args if a is not sp.S.One]
    if len(args) < 2:
        return args[0] if args else sp.S.One
    if len(args) == 2 and (args[0].is_Rational or args[1].is_Rational):
        return sp.Mul(*args)  # Mul's two-argument rules (e.g. 3·(2·(x + y)) stays unexpanded)
    coefficient, factors = sp.S.One, []
    for a in args:
        for f in (a.args if a.is_Mul else (a,)):
            if f.is_Number:
                coefficient *= f
            else:
                factors.append(f)
    return product(coefficient, factors)


def product(coefficient: sp.Rational, factors: Sequence[sp.Expr]) -> sp.Expr:
    """``sp.Mul(coefficient, *factors)``, equal to it argument for argument."""
    if _only_sorting_needed(coefficient, factors):
        if len(factors) == 1 and coefficient is sp.S.One:
            return factors[0]
        ordered = sorted(factors, key=_args_sortkey)  # the order Mul.flatten gives
        if coefficient is not sp.S.One:
            ordered.insert(0, coefficient)
        return sp.Mul._from_args(ordered, is_commutative=True)
    return sp.Mul(coefficient, *factors)


def _only_sorting_needed(coefficient: sp.Expr, factors: Sequence[sp.Expr]) -> bool:
    """Whether Mul.flatten would only sort ``factors`` and put a nonzero rational coefficient first.

    The factors must be commutative symbols, function values, sums, or powers
    with a symbolic base that is none of these, no two of them with the same
    base (Mul would merge their exponents); and a number times a single sum
    is left to Mul, which distributes it.
    """
    if not factors or not coefficient.is_Rational or coefficient.is_zero:
        return False
    if len(factors) == 1 and coefficient is not sp.S.One and factors[0].is_Add:
        return False
    bases = set()
    for f in factors:
        if not (f.is_Symbol or f.is_Function or f.is_Add or f.is_Pow) or not f.is_commutative:
            return False
        base = f.as_base_exp()[0]  # exp(x) has the base E: Mul merges exp(x)·exp(y)
        if base.is_number or base.is_Mul or base.is_Pow or base in bases:
            return False
        bases.add(base)
    return True
