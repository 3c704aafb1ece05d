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
