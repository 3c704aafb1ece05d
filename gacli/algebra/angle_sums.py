"""Sines and cosines of sums of angles, written out where the sum's angles also stand alone.

A steered wheel's rolling rows are naturally written with its heading
θ + δ (``cos(theta + delta)*dx + ...``), beside rows of the chassis in θ
alone. To the reduction by sin² + cos² = 1 (:mod:`gacli.algebra.trig`),
which works one angle at a time, θ + δ is an angle of its own: the
sin θ cos(θ + δ) − cos θ sin(θ + δ) of the solved rates never becomes
−sin δ, and a car so written printed 104,000 characters instead of 4,000.
Written out by the addition formulas, every sine and cosine is of a single
angle again, and the reduction is a normal form. Only sums whose angles
also appear elsewhere in the expression are written out: a sum that stands
alone (a hitch angle θ − θ_T throughout) is one angle, and stays whole.
"""

from __future__ import annotations

from collections.abc import Iterable

import sympy as sp


def expansions(atoms: Iterable[sp.Expr]) -> dict[sp.Expr, sp.Expr]:
    """{sin(θ + δ): sin θ cos δ + cos θ sin δ, ...} for each sine or cosine among ``atoms``
    whose argument is a sum sharing an angle with another sine or cosine among them."""
    trig = [a for a in atoms if isinstance(a, (sp.sin, sp.cos))]
    sums = [a for a in trig if _is_sum_of_angles(a.args[0])]
    if not sums:
        return {}
    out = {}
    for atom in sums:
        angles = atom.args[0].free_symbols
        if any(other.args[0] != atom.args[0] and angles & other.args[0].free_symbols for other in trig):
            out[atom] = sp.expand_trig(atom)
    return out


# The largest multiple of an angle written out: sin(kφ) by the addition formulas is a
# polynomial of degree k in sin φ and cos φ (sin(θ + 100000 φ) held a derivation for minutes).
MAX_MULTIPLE = 3


def _is_sum_of_angles(arg: sp.Expr) -> bool:
    """θ + δ, θ − 2ψ, φ + π/2: symbols with small integer multiples, and rational multiples of π."""
    if not arg.is_Add:
        return False
    for term in arg.args:
        coefficient, rest = term.as_coeff_Mul()
        if rest is sp.pi and coefficient.is_Rational:
            continue
        if not (rest.is_Symbol and coefficient.is_Integer and abs(coefficient) <= MAX_MULTIPLE):
            return False
    return True
