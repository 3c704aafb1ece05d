"""Matrix helpers of the derivation: sparse products, the adjugate solve, rank at a generic point.

They sit below the mechanics so that nothing imports the kinematics for
them (the rates, the motions, the forces and the equations all use them).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import sympy as sp

from gacli.algebra import trig
from gacli.algebra.blocks import block_triangular, solve_by_blocks

# Ranks are decided at a random configuration (gacli.numeric.samples): a
# generic rank of a matrix of functions equals its rank at almost every point.
_RANK_TOL = 1e-9

_ZERO = sp.S.Zero


def rank(matrix: np.ndarray) -> int:
    if matrix.size == 0:
        return 0
    return int(np.linalg.matrix_rank(matrix, tol=_RANK_TOL * max(1.0, np.abs(matrix).max())))


def solve_linear(A: sp.Matrix, B: sp.Matrix) -> sp.Matrix:
    """A⁻¹ B as adj(A) B / det(A), without pivots.

    Gaussian elimination divides by pivots chosen as "not identically zero";
    such a pivot (sin(yaw), say) can vanish at an ordinary configuration where
    A is regular, and the solved rates then read 0/0 there (a bicycle going
    straight north). The adjugate divides only by det A, which vanishes only
    where the rates are truly undetermined.
    """
    if A.rows == 1:
        return B / A[0, 0]
    if A.rows > _ADJUGATE_MAX:
        return _solve_large(A, B)
    minor = _minors(A)
    everything = tuple(range(A.rows))
    # Reduced by sin² + cos² = 1: a sleigh's determinant is sin(θ)² + cos(θ)², which is 1.
    det = trig.reduce(minor(everything, everything))

    def entry(i: int, c: int) -> sp.Expr:
        # (adj A)_ij = (-1)^(i+j) det(A without row j and column i)
        terms = [(-1) ** (i + j) * minor(_without(everything, j), _without(everything, i)) * B[j, c]
                 for j in range(A.rows) if B[j, c] != 0]
        return trig.reduce(sp.Add(*terms)) / det

    return sp.Matrix(A.rows, B.cols, entry)


def _solve_large(A: sp.Matrix, B: sp.Matrix) -> sp.Matrix:
    """Too many rows for one adjugate: block after block (gacli.algebra.blocks), each by its adjugate.

    SymPy's LU, the last resort for a block still too large, takes as pivot
    the first entry not identically zero, which may vanish where A is regular.
    """
    rows = A.tolist()
    blocks = block_triangular([[nonzero(e) for e in row] for row in rows])
    if blocks is None or len(blocks) == 1:
        return A.LUsolve(B)
    solved = solve_by_blocks(blocks, lambda i, j: rows[i][j], B.tolist(),
                             lambda a, b: solve_linear(sp.Matrix(a), sp.Matrix(b)).tolist())
    return sp.Matrix(solved)


def _without(indices: tuple[int, ...], i: int) -> tuple[int, ...]:
    return tuple(j for j in indices if j != i)


def _minors(A: sp.Matrix):
    """det of the submatrix on (rows, columns), by Laplace expansion along the first row.

    Memoised over the submatrices, skipping zero entries: the constraint
    matrices are sparse, and SymPy's Berkowitz determinant goes through its
    matrix product, which multiplies the zeros too (0·expr asks whether expr
    is finite, a walk of the whole tree).
    """
    memo: dict[tuple[tuple[int, ...], tuple[int, ...]], sp.Expr] = {}

    def det(rows: tuple[int, ...], columns: tuple[int, ...]) -> sp.Expr:
        if not rows:
            return sp.S.One
        known = memo.get((rows, columns))
        if known is None:
            terms = []
            for position, c in enumerate(columns):
                a = A[rows[0], c]
                if a != 0:
                    rest = det(rows[1:], columns[:position] + columns[position + 1:])
                    if rest != 0:
                        terms.append((-1) ** position * a * rest)
            known = memo[(rows, columns)] = sp.Add(*terms)
        return known

    return det


_ADJUGATE_MAX = 6


def nonzero(e) -> bool:
    # The identity test first: S.Zero is a singleton, and SymPy's == costs far more.
    return e is not _ZERO and e != 0


def dot(row: Sequence[sp.Expr], column: Sequence[sp.Expr]) -> sp.Expr:
    """Σ row_r column_r over the nonzero pairs."""
    return sp.Add(*[a * c for a, c in zip(row, column) if nonzero(a) and nonzero(c)])


def product(A: sp.Matrix, B: sp.Matrix) -> sp.Matrix:
    """A B that skips zero factors and takes a unit entry of B as a plain selection.

    β is mostly a selection: an independent coordinate's row of β is a unit
    row (eq. 14.7), so J β mostly copies columns of J; forming every J_ir β_rs
    product and sum, as the general matrix product does, costs far more.
    """
    if A.cols != B.rows:
        raise ValueError(f"cannot multiply {A.rows}x{A.cols} by {B.rows}x{B.cols}")
    # Plain lists: indexing a SymPy matrix entry by entry costs more than the products.
    entries = [e for row in product_rows(A.tolist(), B.tolist(), B.cols) for e in row]
    return sp.Matrix(A.rows, B.cols, entries)


def product_rows(rows: Sequence[Sequence[sp.Expr]], b: Sequence[Sequence[sp.Expr]],
                 columns: int) -> list[list[sp.Expr]]:
    """:func:`product` on lists of rows; B has ``columns`` columns (its rows may be none).

    Sparse on both sides: a particle's row of the Jacobian has one nonzero
    entry and each row of β a few, so the work is the nonzero products,
    not rows × columns × the length of B (cubic in the width of a system of
    n uncoupled bodies, where every body's product scanned all of β).
    """
    out = []
    sparse: dict[int, list[tuple[int, sp.Expr]]] = {}  # per call: a cache across derivations would
    for row in rows:                                   # compare equal huge expressions node by node
        terms: dict[int, list[sp.Expr]] = {}
        for r, a in enumerate(row):
            if a is _ZERO or a == 0:
                continue
            if r not in sparse:
                sparse[r] = [(j, v) for j, v in enumerate(b[r]) if v is not _ZERO and v != 0]
            for j, v in sparse[r]:
                terms.setdefault(j, []).append(a if v is sp.S.One else a * v)
        out.append([(t[0] if len(t) == 1 else sp.Add(*t)) if (t := terms.get(j)) else _ZERO
                    for j in range(columns)])
    return out

