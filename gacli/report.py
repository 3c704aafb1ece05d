"""The chapter's steps as readable text: what ``gacli derive`` prints.

Expressions are written in the system file's own grammar (``dot(x)``,
``ddot(q_z)``, ``**``), so a line of output can be pasted back into a file.
Simplification here is for reading only, bounded by expression size, and
never changes what the code emitters see.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.equations import Derivation
from gacli.gibbs import gibbs_coefficients
from gacli.symbols import rate_name

# Above this many operations sympy.simplify can take minutes; show the
# expression as derived instead.
SIMPLIFY_BUDGET = 150


@dataclass(frozen=True)
class Section:
    title: str
    lines: tuple[str, ...]


def tidy(expr: sp.Expr) -> sp.Expr:
    """A shorter equal expression, within a size budget."""
    if sp.count_ops(expr) <= SIMPLIFY_BUDGET:
        return sp.simplify(expr)
    return sp.cancel(expr)


def show(expr: sp.Expr) -> str:
    return sp.sstr(expr, order="lex")


def freedom(d: Derivation) -> Section:
    s = d.system
    n, p = len(s.coordinates), len(s.quasi_coordinates)
    dq = sum(1 for q in s.quasi_coordinates if q.differential is not None)
    ell = len(s.constraints)
    how = "chosen automatically" if d.rates.chosen_automatically else "as given in the file"
    return Section("Degrees of freedom", (
        f"k = n + p - d - l = {n} + {p} - {dq} - {ell} = {d.k}",
        f"n = {n} coordinates, p = {p} quasi-coordinates (d = {dq} defined by a differential), "
        f"l = {ell} constraints",
        f"independent: {', '.join(d.independent)} ({how})",
    ))


def rates(d: Derivation) -> Section:
    lines = [f"{rate_name(n, 1)} = {show(tidy(d.rates.rate(n)))}"
             for n in d.rates.names if n not in d.independent]
    return Section("Rates in terms of the independent rates, eq. (14.7)", tuple(lines) or ("(all rates are independent)",))


def gibbs(d: Derivation) -> Section:
    H, g = gibbs_coefficients(d.gibbs, d.rates)
    acc = d.speed_rates
    terms = []
    for i in range(d.k):
        for j in range(i, d.k):
            c = tidy(H[i, j] / 2 if i == j else H[i, j])
            if c != 0:
                terms.append(f"({show(c)})*{acc[i]}" + ("**2" if i == j else f"*{acc[j]}"))
    for i in range(d.k):
        c = tidy(g[i])
        if c != 0:
            terms.append(f"({show(c)})*{acc[i]}")
    body = " + ".join(terms) if terms else "0"
    return Section("Gibbs function, acceleration terms (eqs. 14.17, 14.21)", (f"G = {body} + ...",))


def forces(d: Derivation) -> Section:
    lines = [f"Q_{name} = {show(tidy(q))}" for name, q in zip(d.independent, d.generalized_forces)]
    return Section("Generalized forces, eq. (14.13)", tuple(lines))


def equations(d: Derivation) -> Section:
    lines = []
    for s, name in enumerate(d.independent):
        lhs = sum((tidy(d.mass_matrix[s, r]) * a for r, a in enumerate(d.speed_rates)), sp.S.Zero)
        rest = tidy(d.generalized_forces[s] - d.forcing[s])
        lines.append(f"dG/d({rate_name(name, 2)}): {_join(show(lhs), rest)} = {show(tidy(d.generalized_forces[s]))}")
    return Section("Gibbs-Appell equations, eq. (14.19)", tuple(lines))


def _join(first: str, rest: sp.Expr) -> str:
    """'first + rest' with the sign of rest folded in."""
    if rest == 0:
        return first
    text = show(rest)
    return f"{first} - {text[1:]}" if text.startswith("-") else f"{first} + {text}"


def kinematic(d: Derivation) -> Section:
    lines = [f"{rate_name(n, 1)} = {show(tidy(e))}" for n, e in d.kinematic_equations]
    return Section("Kinematic equations, eq. (14.20)", tuple(lines))


def derivation_report(d: Derivation) -> tuple[Section, ...]:
    """The chapter's solution procedure (section 14.3), step by step."""
    return (freedom(d), rates(d), gibbs(d), forces(d), equations(d), kinematic(d))


def gibbs_report(d: Derivation) -> tuple[Section, ...]:
    return (gibbs(d),)
