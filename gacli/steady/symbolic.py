"""A as expressions at an operating point of expressions, for the states asked for.

The rows of the accelerations are M₀⁻¹ (∂F/∂x − ∂M/∂x u̇₀) with M₀, F₀
and u̇₀ = M₀⁻¹F₀ taken at the point first (eq. 14.19 differentiated), so only
a k × k matrix of the point's values is inverted, never M(q) itself; at a
steady motion u̇₀ = 0 and the second term drops. Each entry is simplified
once, at the point.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy as sp

from gacli.algebra import symbols as S
from gacli.mechanics.equations import Derivation


def jacobian(derivation: Derivation, point: Mapping[sp.Symbol, sp.Expr],
             rows: Sequence[str], columns: Sequence[str]) -> sp.Matrix:
    """∂f_row/∂x_column at ``point`` (every state symbol mapped), f = (q̇, u̇); simplified."""
    kinematic = dict(derivation.kinematic_equations)
    speeds = [str(u) for u in derivation.speeds]
    wrt = [_symbol(derivation, n) for n in columns]
    accelerations = _acceleration_rows(derivation, point, wrt) if any(r in speeds for r in rows) else None
    out = []
    for name in rows:
        if name in speeds:
            out.append(list(accelerations[speeds.index(name), :]))
        else:
            expr = kinematic[name]
            out.append([sp.diff(expr, s).xreplace(point) for s in wrt])
    return sp.Matrix(out).applyfunc(_tidy)


def _acceleration_rows(derivation: Derivation, point, wrt) -> sp.Matrix:
    M, F = sp.Matrix(derivation.mass_matrix), sp.Matrix(derivation.forcing)
    M0 = M.xreplace(point).applyfunc(_tidy)
    F0 = F.xreplace(point).applyfunc(_tidy)
    u_dot = M0.LUsolve(F0).applyfunc(_tidy)
    columns = []
    for s in wrt:
        dF = F.diff(s).xreplace(point)
        if any(e != 0 for e in u_dot):
            dF -= M.diff(s).xreplace(point) * u_dot
        columns.append(dF.applyfunc(_tidy))
    return M0.LUsolve(sp.Matrix.hstack(*columns)) if columns else sp.zeros(len(F), 0)


def residual(derivation: Derivation, point, rows: Sequence[str]) -> sp.Matrix:
    """f at the point for the named rows (a steady motion makes them zero)."""
    kinematic = dict(derivation.kinematic_equations)
    speeds = [str(u) for u in derivation.speeds]
    M0 = sp.Matrix(derivation.mass_matrix).xreplace(point).applyfunc(_tidy)
    u_dot = M0.LUsolve(sp.Matrix(derivation.forcing).xreplace(point)).applyfunc(_tidy)
    return sp.Matrix([u_dot[speeds.index(n)] if n in speeds else _tidy(kinematic[n].xreplace(point))
                      for n in rows])


def _symbol(derivation: Derivation, name: str) -> sp.Symbol:
    return S.value(name) if "(" not in name else sp.Symbol(name, real=True)


def _tidy(e: sp.Expr) -> sp.Expr:
    return sp.factor(sp.cancel(sp.trigsimp(e))) if e.free_symbols else e
