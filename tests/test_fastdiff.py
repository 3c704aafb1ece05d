"""The memoised derivatives of gacli.algebra.fastdiff: the expressions SymPy's own constructors would give."""

from __future__ import annotations

import sympy as sp

from gacli.algebra import fastdiff
from gacli.algebra.fastdiff import Differentiator, jacobian

q1, q2, q3, l1, l2, t = sp.symbols("q1 q2 q3 l1 l2 t", real=True)
EXPRESSIONS = [
    l1 * sp.sin(q1) + l2 * sp.sin(q2),
    -l1 * sp.cos(q1) - l2 * sp.cos(q2) * sp.sin(q3),
    sp.atan2(q1, q2) + sp.exp(q1 * q2) + sp.sqrt(l1 + q3**2),
    q1**q2 + sp.Abs(q3) + sp.Piecewise((q1, q2 > 0), (q3, True)),
    sp.S(3), l1 * l2, sp.S.Zero,
]


def test_jacobian_is_the_derivative():
    J = jacobian(EXPRESSIONS, [q1, q2, q3])
    for i, e in enumerate(EXPRESSIONS):
        for j, s in enumerate([q1, q2, q3]):
            assert sp.simplify(J[i, j] - sp.diff(e, s)) == 0


def test_no_term_and_one_term_are_what_add_gives(monkeypatch):
    """_sum skips Add for zero or one term; the expressions must be those of Add itself."""
    seeds = {q1: sp.Symbol("u1"), q2: sp.S.One, t: sp.S.One}
    fast = [jacobian(EXPRESSIONS, [q1, q2, q3]), [Differentiator(seeds)(e) for e in EXPRESSIONS]]
    monkeypatch.setattr(fastdiff, "_sum", lambda terms: sp.Add(*terms))
    plain = [jacobian(EXPRESSIONS, [q1, q2, q3]), [Differentiator(seeds)(e) for e in EXPRESSIONS]]
    assert fast[0] == plain[0] and list(fast[1]) == list(plain[1])
    assert [sp.srepr(e) for e in fast[0]] == [sp.srepr(e) for e in plain[0]]
    assert [sp.srepr(e) for e in fast[1]] == [sp.srepr(e) for e in plain[1]]
