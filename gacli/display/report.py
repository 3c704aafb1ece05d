"""The chapter's steps as readable text: what ``gacli derive`` prints.

Expressions are written in the system file's own grammar (``dot(x)``,
``ddot(q_z)``, ``**``), so a line of output can be pasted back into a file.
Simplification here is for reading only, bounded by expression size, and
never changes what the code emitters see.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.mechanics.equations import Derivation
from gacli.algebra import symbols as S
from gacli.algebra.readable import TOO_LARGE, Tidy, displayable, show
from gacli.algebra.symbols import rate_name


@dataclass(frozen=True)
class Section:
    title: str
    lines: tuple[str, ...]


def dependent_rows(d: Derivation) -> tuple[str, ...]:
    """The constraint rows left out of l: rolling rows that say again what the others say.

    ``gacli check`` lists every row it classifies; this is what lets it and
    ``gacli derive`` agree on why l is smaller than the number of rows.
    """
    if d.rates.constraints_used == len(d.system.constraints):
        return ()
    from gacli.mechanics.rates import relation_rows

    kept = {where for where, _, _ in relation_rows(d.system)[0]}
    return tuple(w for w in (f"constraints[{i}]" for i in range(len(d.system.constraints))) if w not in kept)


def rank_note(rows: int, dependent: tuple[str, ...]) -> str:
    """``4 rows, rank 3: constraints[3] repeats the others``, said alike by derive and check."""
    verb = "repeats" if len(dependent) == 1 else "repeat"
    return f"{rows} rows, rank {rows - len(dependent)}: {', '.join(dependent)} {verb} the others"


def freedom(d: Derivation) -> Section:
    s = d.system
    n, p = len(s.coordinates), len(s.quasi_coordinates)
    dq = sum(1 for q in s.quasi_coordinates if q.differential is not None)
    ell = d.rates.constraints_used
    how = "chosen automatically" if d.rates.chosen_automatically else "as given in the file"
    dependent = dependent_rows(d)
    why = f" (the rolling contacts give {rank_note(len(s.constraints), dependent)})" if dependent else ""
    return Section("Degrees of freedom", (
        f"k = n + p - d - l = {n} + {p} - {dq} - {ell} = {d.k}",
        f"n = {n} coordinates, p = {p} quasi-coordinates (d = {dq} defined by a differential), "
        f"l = {ell} constraints{why}",
        f"independent: {', '.join(d.independent)} ({how})",
    ))


def rates(d: Derivation, tidy: Tidy) -> Section:
    lines = [f"{rate_name(n, 1)} = {show(tidy(d.rates.rate(n)))}"
             for n in d.rates.names if n not in d.independent]
    return Section("Rates in terms of the independent rates, eq. (14.7)", tuple(lines) or ("(all rates are independent)",))


def gibbs(d: Derivation, tidy: Tidy) -> Section:
    from gacli.display.steps import gibbs_polynomial

    return Section("Gibbs function, acceleration terms (eqs. 14.17, 14.21)",
                   (f"G = {show(gibbs_polynomial(d, tidy))} + ...",))


def forces(d: Derivation, tidy: Tidy) -> Section:
    lines = [f"Q_{name} = {show(tidy(q))}" for name, q in zip(d.independent, d.generalized_forces)]
    return Section("Generalized forces, eq. (14.13)", tuple(lines))


def equations(d: Derivation, tidy: Tidy) -> Section:
    from gacli.display.steps import equation_of_motion

    lines = []
    for s, name in enumerate(d.independent):
        eq = equation_of_motion(d, s, tidy)
        lines.append(f"dG/d({rate_name(name, 2)}): {show(eq.lhs)} = {show(eq.rhs)}")
    return Section("Gibbs-Appell equations, eq. (14.19)", tuple(lines))


def kinematic(d: Derivation, tidy: Tidy) -> Section:
    # q̇ = q̇ for an independent coordinate says nothing, and is not printed.
    lines = [f"{rate_name(n, 1)} = {show(tidy(e))}" for n, e in d.kinematic_equations if e != S.rate(n)]
    return Section("Kinematic equations, eq. (14.20)",
                   tuple(lines) or ("(every coordinate is independent: its rate is one of the speeds)",))


def too_large() -> Section:
    return Section("Equations", (TOO_LARGE,))


def derivation_report(d: Derivation) -> tuple[Section, ...]:
    """The results of the chapter's solution procedure (section 14.3)."""
    if not displayable(d):
        return (freedom(d), too_large())
    return (freedom(d), rates(d, Tidy()), gibbs(d, Tidy()), forces(d, Tidy()), equations(d, Tidy()), kinematic(d, Tidy()))


def gibbs_report(d: Derivation) -> tuple[Section, ...]:
    if not displayable(d):
        return (too_large(),)
    return (gibbs(d, Tidy()),)


def steps_report(d: Derivation) -> tuple[Section, ...]:
    """The worked solution (:mod:`gacli.display.steps`) as text sections."""
    from gacli.display.steps import Equation, worked_solution

    if not displayable(d):
        return (freedom(d), too_large())
    def line(item) -> str:
        if isinstance(item, Equation):
            return f"{_side(item.lhs)} = {_side(item.rhs)}"
        return item

    return tuple(Section(step.title, tuple(line(i) for i in step.items)) for step in worked_solution(d))


def _side(expr) -> str:
    if isinstance(expr, sp.MatrixBase):
        return "[" + ", ".join(show(e) for e in expr) + "]"
    return show(expr)


def reactions_report(d: Derivation) -> tuple[Section, ...]:
    """The constraint forces λ (gacli.verify), one per constraint, in the state."""
    from gacli.reactions import constraint_forces

    title = "Constraint forces (multipliers of eq. 14.1, see docs/verify.md)"
    if not displayable(d):
        return (Section(title, ("Not written out for a system this large: in closed form they would be "
                                "millions of terms. The generated code computes them numerically: "
                                "--format python or --format c with --reactions.",)),)
    tidy = Tidy()
    forces = constraint_forces(d)
    lines = [f"lambda_{i} = {show(tidy(value))}    ({c.text})"
             for i, (value, c) in enumerate(zip(forces, d.system.constraints))]
    return (Section(title, tuple(lines) or ("(no constraints)",)),)
