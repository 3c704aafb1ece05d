"""Print the rattleback's no-slip rows as Pfaffian rows in the system-file grammar.

The rows of rattleback.yaml and rattleback_rates.yaml were written by this
script, once: the contact point P of the ellipsoid x²/a² + y²/b² + z²/c² = 1
(centre O, body frame R turned from N by yaw about z, lean about x, pitch
about y) is P − O = −E² μ / ε with μ the R components of N's z axis,
E = diag(a, b, c) and ε = |E μ| (Kane and Levinson 1982, as PyDy's
examples/rattleback/ellipsoid_no_slip.py writes it). Rolling without slip
with (x, y) the contact point in N: dx = (dᴿ(P − O))·N.x, dy = (dᴿ(P − O))·N.y,
where dᴿ differentiates the R components (the material point of the
ellipsoid at P is at rest). The vertical row vanishes on the ellipsoid.

    python benchmarks/kane_set/make_rattleback.py
"""

import sympy as sp

yaw, lean, pitch, a, b, c = sp.symbols("yaw lean pitch a b c")
mu = sp.Matrix([-sp.sin(pitch) * sp.cos(lean), sp.sin(lean), sp.cos(lean) * sp.cos(pitch)])
eps = sp.Symbol("eps")
p_minus_o = sp.Matrix([-a**2 * mu[0], -b**2 * mu[1], -c**2 * mu[2]]) / eps
eps_value = sp.sqrt(a**2 * mu[0]**2 + b**2 * mu[1]**2 + c**2 * mu[2]**2)
# N's x and y axes in R: rows of the direction cosines (R from N by z, x, y).
Rz = sp.Matrix([[sp.cos(yaw), -sp.sin(yaw), 0], [sp.sin(yaw), sp.cos(yaw), 0], [0, 0, 1]])
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(lean), -sp.sin(lean)], [0, sp.sin(lean), sp.cos(lean)]])
Ry = sp.Matrix([[sp.cos(pitch), 0, sp.sin(pitch)], [0, 1, 0], [-sp.sin(pitch), 0, sp.cos(pitch)]])
C = Rz * Rx * Ry  # columns: R's axes in N; rows: N's axes in R
assert sp.simplify(C.T * sp.Matrix([0, 0, 1]) - mu) == sp.zeros(3, 1)


def row(axis: int) -> str:
    terms = []
    for angle in (lean, pitch):
        full = p_minus_o.subs(eps, eps_value).diff(angle)
        coefficient = sum((C[axis, i] * full[i] for i in range(3)), sp.S.Zero)
        coefficient = sp.factor_terms(sp.trigsimp(sp.together(coefficient)))
        terms.append(f"({coefficient})*d{angle}")
    return f"d{'xy'[axis]} = " + " + ".join(terms)


if __name__ == "__main__":
    for axis in (0, 1):
        text = row(axis)
        print(f"  - {text}\n")
        print(len(text))
