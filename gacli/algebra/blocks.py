"""A square sparse matrix's block-triangular form: which unknowns can be solved for first.

More than six dependent rates are too many for the adjugate solve (its
minors grow as 2^n), and SymPy's LU picks as pivot the first entry that is
not identically zero: a free body in Euler parameters whose translation is
also given by body-axis rates then divides by λ₀, a coordinate that is zero
at an ordinary half-turn. Such a matrix falls apart into small square blocks
(the body's three translational rows, its four rotational ones) that are
solved in turn, each by the adjugate, whose only division is its own
determinant: the Dulmage-Mendelsohn order, a perfect matching of rows to
columns and the strongly connected components of the graph it leaves.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from sympy.utilities.iterables import strongly_connected_components

Block = tuple[tuple[int, ...], tuple[int, ...]]  # (rows, columns)


def block_triangular(pattern: Sequence[Sequence[bool]]) -> list[Block] | None:
    """Square blocks in the order they can be solved, or None when no row-to-column matching is perfect.

    ``pattern[i][j]``: whether entry (i, j) is not identically zero. Solving
    the blocks in the order returned, each needs only unknowns of earlier blocks.
    """
    n = len(pattern)
    match = _perfect_matching(pattern)
    if match is None:
        return None
    column_of = match  # row i is matched to column match[i]
    row_of = {c: r for r, c in enumerate(column_of)}
    # Row i needs the unknown of column j, which row_of[j] determines: an edge i → row_of[j].
    edges = [(i, row_of[j]) for i in range(n) for j in range(n) if pattern[i][j] and row_of[j] != i]
    # SymPy returns the components in reverse topological order: what a row needs comes first.
    components = strongly_connected_components((list(range(n)), edges))
    return [(tuple(sorted(rows)), tuple(sorted(column_of[r] for r in rows))) for rows in components]


def _perfect_matching(pattern: Sequence[Sequence[bool]]) -> list[int] | None:
    """Each row's column in a perfect matching (Kuhn's augmenting paths), or None."""
    n = len(pattern)
    owner: dict[int, int] = {}  # column → row

    def augment(row: int, seen: set[int]) -> bool:
        for col in range(n):
            if pattern[row][col] and col not in seen:
                seen.add(col)
                if col not in owner or augment(owner[col], seen):
                    owner[col] = row
                    return True
        return False

    for row in range(n):
        if not augment(row, set()):
            return None
    column_of = [0] * n
    for col, row in owner.items():
        column_of[row] = col
    return column_of


def solve_by_blocks(blocks: Sequence[Block], entry: Callable[[int, int], object], rhs: list[list],
                    solve_block: Callable[[list[list], list[list]], list[list]]) -> list[list]:
    """x with A x = rhs, block after block; ``solve_block(A_block, b_block)`` solves one square block.

    ``rhs`` is a list of rows (one list of columns each); the answer is too, by column index.
    """
    n = len(rhs)
    x: list[list | None] = [None] * n
    for rows, cols in blocks:
        block = [[entry(r, c) for c in cols] for r in rows]
        known = [
            [rhs[r][k] - sum((entry(r, c) * x[c][k] for c in range(n) if x[c] is not None and entry(r, c) != 0), 0)
             for k in range(len(rhs[r]))]
            for r in rows
        ]
        for c, value in zip(cols, solve_block(block, known)):
            x[c] = value
    return x  # type: ignore[return-value]
