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
from sympy.core.parameters import global_parameters


def mul(*args: sp.Expr) -> sp.Expr:
    """``sp.Mul(*args)``, equal to it argument for argument; products among ``args`` are flattened.

    Numbers are multiplied first, so the shortcut is taken only when they are
    rational (exact in any order); products are expanded in the order
    ``Mul.flatten`` visits them (nested arguments after the others), so that
    factors the sort ranks equal keep Mul's order.
    """
    args = [a for a in args if a is not sp.S.One]
    if len(args) < 2:
        return args[0] if args else sp.S.One
    if len(args) == 2 and (args[0].is_Rational or args[1].is_Rational):
        return sp.Mul(*args)  # Mul's two-argument rules (e.g. 3·(2·(x + y)) stays unexpanded)
    coefficient, factors = sp.S.One, []
    seq = list(args)
    for a in seq:  # grows while it is read, as in Mul.flatten
        if a.is_Mul:
            seq.extend(a.args)
        elif a.is_Number:
            if not a.is_Rational:
                return sp.Mul(*args)
            coefficient *= a
        else:
            factors.append(a)
    if not _only_sorting_needed(coefficient, factors):
        return sp.Mul(*args)  # in Mul's own order: some of its rules (0·∞) depend on it
    return product(coefficient, factors)


def product(coefficient: sp.Rational, factors: Sequence[sp.Expr]) -> sp.Expr:
    """``sp.Mul(coefficient, *factors)``, equal to it argument for argument."""
    if _only_sorting_needed(coefficient, factors):
        if len(factors) == 1 and coefficient is sp.S.One:
            return factors[0]
        ordered = sorted(factors, key=_args_sortkey)  # the order Mul.flatten gives (a stable sort, as there)
        if coefficient is not sp.S.One:
            ordered.insert(0, coefficient)
        return sp.Mul._from_args(ordered, is_commutative=True)
    return sp.Mul(coefficient, *factors)


def _only_sorting_needed(coefficient: sp.Expr, factors: Sequence[sp.Expr]) -> bool:
    """Whether Mul.flatten would only sort ``factors`` and put a nonzero rational coefficient first.

    Each factor must be a commutative symbol, function value or sum, or a
    power of one with a nonzero rational exponent (Mul rebuilds other
    exponents); no two may have the same base (Mul would merge their
    exponents); a number times a single sum is left to Mul, which
    distributes it; and nothing is shortened inside ``sympy.evaluate(False)``.
    """
    if not factors or not coefficient.is_Rational or coefficient.is_zero:
        return False
    if len(factors) == 1 and coefficient is not sp.S.One and factors[0].is_Add:
        return False
    if not (global_parameters.evaluate and global_parameters.distribute):
        return False
    bases = set()
    for f in factors:
        if f.is_Pow:
            if not (f.exp.is_Rational and f.exp != 0):
                return False
            base = f.base
        elif f.is_Symbol or f.is_Function or f.is_Add:
            base = f.as_base_exp()[0]  # exp(x) has the base E: Mul merges exp(x)·exp(y)
        else:
            return False
        if not f.is_commutative or base.is_number or base.is_Mul or base.is_Pow or base in bases:
            return False
        bases.add(base)
    return True
