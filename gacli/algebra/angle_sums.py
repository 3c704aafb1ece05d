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

For reading, the other way (:func:`angle_sums_compacted`): a pair such as
sin x cos y − sin y cos x in a small sum printed as sin(x − y).
"""

from __future__ import annotations

from collections.abc import Iterable

import sympy as sp

from gacli.algebra.graph import postorder


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


# A sum is searched for sin x cos y ± cos x sin y only up to this many terms (the search is by pairs).
COMPACT_TERMS = 8


def angle_sums_compacted(expr: sp.Expr) -> sp.Expr:
    """sin x cos y − sin y cos x as sin(x − y), cos x cos y + sin x sin y as cos(x − y), and the
    same for sums, wherever such a pair stands in a small sum: as a difference that the whole
    expression holds (:func:`gacli.algebra.angles.relative`) is written, so is one it holds
    beside other uses of its angles (a trailer's b (sin θ cos θ_T − sin θ_T cos θ) θ̇).

    Each distinct sum is compacted once, from the innermost out, with the sums below its terms
    hidden: SymPy's TR10i walks everything below the sum it is given, and given every sum in turn
    it walked the inner ones again for each sum above them (a five-bar's F: 121 walks, 1.5 s)."""
    if not (expr.has(sp.sin) and expr.has(sp.cos)):
        return expr
    done: dict[sp.Expr, sp.Expr] = {}
    for node in postorder([expr]):
        args = [done.get(a, a) for a in node.args]
        new = node.func(*args) if any(a is not b for a, b in zip(args, node.args)) else node
        if new.is_Add and len(new.args) <= COMPACT_TERMS and new.has(sp.sin) and new.has(sp.cos):
            new = _compacted_sum(new)
        if new is not node:
            done[node] = new
    return done.get(expr, expr)


def _compacted_sum(add: sp.Expr) -> sp.Expr:
    """TR10i on the sum's own terms: a factor that is a sum (or a power of one) stands for a symbol."""
    from sympy.simplify.fu import TR10i

    hidden: dict[sp.Expr, sp.Dummy] = {}

    def hide(factor: sp.Expr) -> sp.Expr:
        base = factor.base if factor.is_Pow else factor
        if base.is_Add:
            return hidden.setdefault(factor, sp.Dummy())
        return factor

    terms = [sp.Mul(*(hide(f) for f in sp.Mul.make_args(t))) for t in add.args]
    out = TR10i(sp.Add(*terms))
    return out.xreplace({d: f for f, d in hidden.items()}) if hidden else out


