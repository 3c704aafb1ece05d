"""Walks of SymPy expressions as graphs: each distinct subexpression visited once.

Derived expressions share their subexpressions (a solved rate appears in
every velocity of the Whipple bicycle), so as trees they can be millions of
nodes while the distinct subexpressions stay a few thousand. SymPy's
``free_symbols``, ``count_ops`` and the canonical ordering inside ``cse`` walk
the trees; the functions here walk the graph.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping, Sequence

import sympy as sp

# Above this many nodes as a tree, an expression is walked as a graph: the
# shipped systems other than the bicycle stay under 3,000, the bicycle's
# equations are millions.
LARGE_TREE = 20_000


def is_small(expr: sp.Expr, limit: int) -> bool:
    """Whether the tree of ``expr`` has at most ``limit`` nodes (stops counting early).

    ``sympy.count_ops`` walks all of a large expression, which costs more than
    most of what one would skip with it.
    """
    for count, _ in enumerate(sp.preorder_traversal(expr), start=1):
        if count > limit:
            return False
    return True


def is_large(expr: sp.Basic) -> bool:
    """Whether ``expr`` has more than LARGE_TREE nodes as a tree (counting stops there)."""
    return not is_small(expr, LARGE_TREE)


# Tree nodes, all expressions together, up to which SymPy's cse is run (about a second: a
# rattleback's 166,000 nodes take 0.5 s); a bicycle's millions are walked as a graph only.
CSE_TREES = 300_000


def trees_within(exprs: Iterable[sp.Basic], limit: int = CSE_TREES) -> bool:
    """Whether the expressions have at most ``limit`` nodes as trees together, counted over the
    graph (each distinct subexpression's tree size once: a bicycle's millions cost its thousands)."""
    return tree_nodes(exprs) <= limit


def tree_nodes(exprs: Iterable[sp.Basic]) -> int:
    """The expressions' nodes as trees together, counted over the graph (see :func:`trees_within`)."""
    exprs = list(exprs)
    size: dict[sp.Basic, int] = {}
    for node in postorder(exprs):
        size[node] = 1 + sum(size[a] for a in node.args)
    return sum(size[e] for e in exprs)


def common_subexpressions(exprs: Sequence[sp.Basic], symbols: Iterator[sp.Symbol]
                          ) -> tuple[list[tuple[sp.Symbol, sp.Expr]], list[sp.Expr]]:
    """``(replacements, reduced)`` as generated code computes them: SymPy's ``cse`` in its
    canonical order where the trees are at most :data:`CSE_TREES` nodes together, else
    :func:`shared_subexpressions`.

    SymPy's finds more than one pass over the graph (a sum's repeated part, a product's
    constant factors gathered: a three-link chain's 119 operations become 110), but it
    walks and sorts the trees, which a bicycle's millions of nodes rule out.
    """
    exprs = list(exprs)
    if trees_within(exprs):
        return _sympy_cse(exprs, symbols)
    return shared_subexpressions(exprs, symbols)


def _sympy_cse(exprs: list[sp.Basic], symbols: Iterator[sp.Symbol]):
    return sp.cse(exprs, symbols=symbols, order="canonical")


def cse_operations(exprs: Sequence[sp.Basic]) -> int:
    """Operations of what :func:`common_subexpressions` gives (``count_ops``; on large graphs,
    :func:`operations`, which is what the shared subexpressions count to)."""
    exprs = list(exprs)
    if not trees_within(exprs):
        return operations(exprs)
    replacements, reduced = _sympy_cse(exprs, sp.numbered_symbols("_c"))
    return int(sum(sp.count_ops(v) for _, v in replacements) + sum(sp.count_ops(e) for e in reduced))


def postorder(exprs: Iterable[sp.Basic]) -> Iterator[sp.Basic]:
    """Each distinct subexpression once, arguments before the expression, in argument order."""
    seen: set[sp.Basic] = set()
    for root in exprs:
        if root in seen:
            continue
        stack: list[tuple[sp.Basic, bool]] = [(root, False)]
        while stack:
            node, expanded = stack.pop()
            if expanded:
                yield node
                continue
            if node in seen:
                continue
            seen.add(node)
            stack.append((node, True))
            stack.extend((a, False) for a in reversed(node.args) if a not in seen)


def free_symbols(exprs: Sequence[sp.Basic]) -> set[sp.Symbol]:
    """The symbols in the expressions (SymPy's ``free_symbols`` recomputes per occurrence)."""
    return {node for node in postorder(exprs) if node.is_Symbol}


def shared_subexpressions(exprs: Sequence[sp.Basic], symbols: Iterator[sp.Symbol]
                          ) -> tuple[list[tuple[sp.Symbol, sp.Expr]], list[sp.Expr]]:
    """Common-subexpression elimination in one walk of the graph: ``(replacements, reduced)``.

    Every compound subexpression used more than once is named (expressions
    only: not the tuples and condition pairs inside Derivative or Piecewise), in the order
    of a post-order walk (so a name is defined before it is used, and the
    order depends only on the expressions' argument order, never on hashes).
    It is what ``sympy.cse`` finds first, without its canonical sorting of
    arguments, whose node counts walk the trees.
    """
    uses: dict[sp.Basic, int] = {}
    order = list(postorder(exprs))
    for node in order:
        for a in node.args:
            uses[a] = uses.get(a, 0) + 1
    for root in exprs:
        uses[root] = uses.get(root, 0) + 1
    rebuilt: dict[sp.Basic, sp.Basic] = {}
    # Whether a node's rebuilt form differs from it: tested by this flag, not by identity, since
    # equal subexpressions need not be one object (that depends on SymPy's cache, on what was
    # built before), and a node rebuilt for nothing would be evaluated anew.
    changed: dict[sp.Basic, bool] = {}
    replacements: list[tuple[sp.Symbol, sp.Expr]] = []
    for node in order:
        if not node.args:
            rebuilt[node], changed[node] = node, False
            continue
        moved = any(changed[a] for a in node.args)
        new = node.func(*(rebuilt[a] for a in node.args)) if moved else node
        if uses[node] > 1 and isinstance(new, sp.Expr) and not _trivial(new):
            name = next(symbols)
            replacements.append((name, new))
            new, moved = name, True
        rebuilt[node], changed[node] = new, moved
    reduced = [rebuilt[e] for e in exprs]
    return _live(replacements, reduced), reduced


def _live(replacements: list[tuple[sp.Symbol, sp.Expr]], reduced: list[sp.Expr]) -> list[tuple[sp.Symbol, sp.Expr]]:
    """The replacements the results need. A sum built unevaluated (a straight-line program
    inlined) is evaluated when rebuilt, and terms that cancel there (a moment that is zero)
    take their shared subexpressions' uses with them: such a name would be dead code."""
    needed = free_symbols(reduced)
    kept = []
    for name, value in reversed(replacements):
        if name in needed:
            kept.append((name, value))
            needed |= free_symbols([value])
    return kept[::-1]


def _trivial(expr: sp.Basic) -> bool:
    """Not worth a name: an atom, or minus an atom."""
    if not expr.args:
        return True
    return expr.is_Mul and len(expr.args) == 2 and expr.args[0] == -1 and not expr.args[1].args



def substitute(exprs: Sequence[sp.Basic], mapping: Mapping[sp.Basic, sp.Basic],
               evaluate: bool = True) -> list[sp.Basic]:
    """``xreplace`` over the graph: each distinct subexpression rebuilt once; with ``evaluate`` False,
    sums, products and powers are rebuilt unevaluated (a program inlined, gacli.mechanics.program)."""
    rebuilt: dict[sp.Basic, sp.Basic] = {}
    changed: dict[sp.Basic, bool] = {}  # by flag, not identity: see shared_subexpressions
    for node in postorder(exprs):
        if node in mapping:
            rebuilt[node], changed[node] = mapping[node], True
        elif node.args and any(changed[a] for a in node.args):
            args = [rebuilt[a] for a in node.args]
            plain = not evaluate and isinstance(node, (sp.Add, sp.Mul, sp.Pow))
            rebuilt[node], changed[node] = (node.func(*args, evaluate=False) if plain else node.func(*args)), True
        else:
            rebuilt[node], changed[node] = node, False
    return [rebuilt[e] for e in exprs]


def expanded_terms(expr: sp.Expr, limit: int) -> int:
    """How many terms ``expand(expr)`` would have, counted without expanding (stops past ``limit``).

    SymPy's expand is deep: it multiplies out inside a root or a sine too, so a function whose
    argument would pass ``limit`` counts as past it (√((x + y + z)¹⁰⁰ + 1) is one term, and its
    expansion took minutes). Each distinct subexpression is counted once."""
    return _expanded_terms(expr, limit, {})


def expands_within(expr: sp.Expr, limit: int) -> bool:
    """Whether multiplying ``expr`` out stays within ``limit`` terms (:func:`expanded_terms`): asked
    before SymPy's expand runs, whose cost a small tree does not bound."""
    return expanded_terms(expr, limit) <= limit


def _expanded_terms(expr: sp.Expr, limit: int, memo: dict) -> int:
    known = memo.get(expr)
    if known is None:
        known = memo[expr] = _expanded_terms_new(expr, limit, memo)
    return known


def _expanded_terms_new(expr: sp.Expr, limit: int, memo: dict) -> int:
    if expr.is_Add:
        total = 0
        for term in expr.args:
            total += _expanded_terms(term, limit, memo)
            if total > limit:
                break
        return total
    if expr.is_Mul:
        total = 1
        for factor in expr.args:
            total *= _expanded_terms(factor, limit, memo)
            if total > limit:
                break
        return total
    if expr.is_Pow and expr.exp.is_Rational and abs(expr.exp) >= 1:
        # (a + b)**n multinomially, (a b)**n as a**n b**n, and a denominator or a root's whole power
        # ((x + y)**-50, (x + y)**50.5) too: SymPy's expand multiplies those out as well.
        terms = _power_terms(expr.base, int(abs(expr.exp)), limit, memo)
        if expr.exp.is_Integer and expr.exp > 0:
            return terms
        return limit + 1 if terms > limit else 1  # below a fraction bar or a root: work, and one term
    inside = (_expanded_terms(a, limit, memo) for a in expr.args if isinstance(a, sp.Expr))
    return limit + 1 if any(n > limit for n in inside) else 1


def _power_terms(base: sp.Expr, n: int, limit: int, memo: dict) -> int:
    """The terms of ``base``**n multiplied out (n ≥ 1), stopped past ``limit``."""
    if base.is_Mul:
        total = 1
        for factor in base.args:
            total *= _power_terms(factor, n, limit, memo)
            if total > limit:
                return limit + 1
        return total
    if base.is_Pow and base.exp.is_Rational and abs(base.exp) >= 1:
        return _power_terms(base.base, n * int(abs(base.exp)), limit, memo)
    k = _expanded_terms(base, limit, memo)
    if k > limit:
        return k
    # The multinomial count C(n + k − 1, k − 1), stopped as soon as it passes the limit.
    total = 1
    for i in range(1, min(n, k - 1) + 1):
        total = total * (max(n, k - 1) + i) // i
        if total > limit:
            break
    return total


def operations(exprs: Iterable[sp.Basic]) -> int:
    """Arithmetic operations of the expressions with every repeated subexpression computed once.

    One walk over the distinct subexpressions, never over trees: a sum or
    product of n arguments is n − 1 operations, a power or a function one. It
    is close to ``count_ops`` after :func:`shared_subexpressions` (which walks
    every piece as a tree), and cheap enough to choose between two routes.
    """
    total = 0
    for node in postorder(exprs):
        if node.is_Add or node.is_Mul:
            total += len(node.args) - 1
        elif node.is_Pow or isinstance(node, sp.Function):
            total += 1
    return total
