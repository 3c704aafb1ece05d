"""The linear solve of the dependent rates (gacli.algebra.matrices.solve_linear), against SymPy's inverse."""

from __future__ import annotations

import pytest
import sympy as sp

from gacli.algebra.matrices import solve_linear


@pytest.mark.parametrize("size", [2, 3, 4, 5, 6])
def test_adjugate_solve_equals_the_inverse_on_sparse_integer_matrices(size, rng):
    for _ in range(5):
        entries = rng.integers(-3, 4, size=(size, size)) * (rng.random((size, size)) < 0.6)
        A = sp.Matrix(entries.tolist()) + sp.eye(size) * 7  # regular, with zeros off the diagonal
        B = sp.Matrix(rng.integers(-5, 6, size=(size, 2)).tolist())
        assert solve_linear(A, B) == A.inv() * B


def test_symbolic_entries_give_the_inverse_too():
    a, b, c, d, e = sp.symbols("a b c d e")
    A = sp.Matrix([[sp.cos(a), 0, b], [c, sp.sin(a), 0], [0, d, e]])
    B = sp.Matrix([[1, a], [b, 0], [0, c]])
    assert sp.simplify(solve_linear(A, B) - A.inv() * B) == sp.zeros(3, 2)


def test_blocks_are_solved_in_an_order_that_needs_only_earlier_unknowns():
    """Seven rows in a 3-block and a 4-block: each solved by its own adjugate, none by a pivot."""
    import sympy as sp
    from gacli.algebra.blocks import block_triangular
    from gacli.algebra.matrices import solve_linear

    q = sp.symbols("q0:4", real=True)
    a, b, c = sp.symbols("a b c", real=True)
    rotational = [[-q[1], q[0], q[3], -q[2]], [-q[2], -q[3], q[0], q[1]],
                  [-q[3], q[2], -q[1], q[0]], list(q)]
    # Rows 0-2 need x, y, z and q (coupled to the rotation); rows 3-6 only q.
    A = sp.zeros(7, 7)
    for i in range(3):
        A[i, i], A[i, (i + 1) % 3], A[i, 3 + i] = a, b * q[i], c
    for i, row in enumerate(rotational):
        A[3 + i, 3:] = sp.Matrix([row])
    blocks = block_triangular([[A[i, j] != 0 for j in range(7)] for i in range(7)])
    assert [len(rows) for rows, _ in blocks] == [4, 3]
    assert blocks[0] == ((3, 4, 5, 6), (3, 4, 5, 6))
    B = sp.Matrix(7, 1, sp.symbols("r0:7"))
    x = solve_linear(A, B)
    assert "1/q0" not in str(x) and all(not d.is_Symbol for d in (sp.denom(sp.together(e)) for e in x))
    point = {s: v for s, v in zip([*q, a, b, c, *B], [0.0, 0.6, 0.0, 0.8, 1.3, 0.7, -0.4, 1, 2, 3, 4, 5, 6, 7])}
    residual = (A * x - B).xreplace(point)
    assert max(abs(float(e)) for e in residual) < 1e-12


def test_a_structurally_singular_matrix_has_no_blocks():
    from gacli.algebra.blocks import block_triangular

    assert block_triangular([[True, True], [False, False]]) is None
