"""Walks over distinct subexpressions (gacli.algebra.graph), checked against SymPy's tree walks."""

from __future__ import annotations

import sympy as sp

from gacli.algebra.graph import free_symbols, postorder, shared_subexpressions


def _nested(depth: int) -> sp.Expr:
    """An expression whose tree doubles with each level while its graph grows by a few nodes."""
    x, y = sp.symbols("x y")
    e = sp.sin(x) + y
    for i in range(depth):
        e = sp.cos(e) * e + sp.Symbol(f"a{i}")
    return e


def test_postorder_visits_each_distinct_node_once_arguments_first():
    e = _nested(6)
    order = list(postorder([e, e]))
    assert len(order) == len(set(order))
    position = {node: i for i, node in enumerate(order)}
    assert all(position[a] < position[node] for node in order for a in node.args)
    assert set(order) == set(sp.preorder_traversal(e))


def test_free_symbols_match_sympy():
    e = _nested(5)
    assert free_symbols([e, sp.Symbol("z")]) == e.free_symbols | {sp.Symbol("z")}


def test_shared_subexpressions_rebuild_the_expressions():
    exprs = [_nested(5), _nested(3) * sp.Symbol("w")]
    replacements, reduced = shared_subexpressions(exprs, sp.numbered_symbols("_c"))
    assert replacements  # the nested cosines are shared
    names = [s for s, _ in replacements]
    for i, (_, value) in enumerate(replacements):
        # defined before use
        assert not (value.free_symbols & set(names[i:]))
    rebuilt = reduced
    for name, value in reversed(replacements):
        rebuilt = [e.xreplace({name: value}) for e in rebuilt]
    assert all(sp.expand(a - b) == 0 for a, b in zip(rebuilt, exprs))


def test_shared_subexpressions_are_deterministic():
    exprs = [_nested(6)]
    first = shared_subexpressions(exprs, sp.numbered_symbols("_c"))
    again = shared_subexpressions(exprs, sp.numbered_symbols("_c"))
    assert first == again


def test_only_expressions_are_named():
    t, x, y = sp.symbols("t x y")
    f, g = sp.Function("f"), sp.Function("g")
    exprs = [sp.Derivative(f(t), t) * sp.sin(x), sp.Derivative(g(t), t) * sp.cos(x),
             sp.Piecewise((x, y > 0), (1, True)), sp.Piecewise((x, y > 0), (2, True))]
    replacements, reduced = shared_subexpressions(exprs, sp.numbered_symbols("_c"))
    assert all(isinstance(value, sp.Expr) for _, value in replacements)
    rebuilt = reduced
    for name, value in reversed(replacements):
        rebuilt = [e.xreplace({name: value}) for e in rebuilt]
    assert rebuilt == exprs


def test_a_name_whose_uses_cancel_is_not_kept():
    # An unevaluated sum (a straight-line program inlined) is evaluated when rebuilt; a shared
    # term that cancels there must leave no dead name behind (the C compiler rejects one).
    import sympy as sp

    from gacli.algebra.graph import shared_subexpressions

    a, b, c, d = sp.symbols("a b c d")
    t = sp.Mul(c, a * b + 1)
    e = sp.Add(t, sp.Mul(-1, t, evaluate=False), d, evaluate=False)
    replacements, reduced = shared_subexpressions([e], sp.numbered_symbols("_c"))
    assert replacements == [] and reduced == [d]
