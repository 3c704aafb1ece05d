"""M scaled by its diagonal, D^-1/2 M D^-1/2, where check and verify judge definiteness.

Its diagonal is 1 whatever the units of the rates: a satellite's 5e6 kg m²
beside a wheel's 2e-6, or a planet's 6e24 beside a probe's 1, is as definite
as diag(1, 1), though the eigenvalues of M span tens of decades, and
generated code's Cholesky solves it. A test relative to M's largest entry
refused such systems. Works on floats and on mpmath numbers alike.
"""

from __future__ import annotations


def diagonally_scaled(M, k: int) -> list[list] | None:
    """The symmetric part of the k × k ``M`` (indexed M[i, j]) scaled by its diagonal; None when a
    diagonal entry is not positive (then M is not positive definite)."""
    symmetric = [[(M[i, j] + M[j, i]) / 2 for j in range(k)] for i in range(k)]
    roots = [symmetric[i][i] ** 0.5 if symmetric[i][i] > 0 else None for i in range(k)]
    if any(r is None for r in roots):
        return None
    return [[symmetric[i][j] / (roots[i] * roots[j]) for j in range(k)] for i in range(k)]
