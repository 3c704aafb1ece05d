"""The chapter's steps as readable text: what ``gacli derive`` prints.

Expressions are written in the system file's own grammar (``dot(x)``,
``ddot(q_z)``, ``**``), so a line of output can be pasted back into a file.
Simplification here is for reading only, bounded by expression size, and
never changes what the code emitters see.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.display import printed
from gacli.mechanics.equations import Derivation
from gacli.algebra.readable import Tidy, displayable, show
from gacli.display import long as L
from gacli.algebra.symbols import rate_name


@dataclass(frozen=True)
class Section:
    title: str
    lines: tuple[str, ...]


def rows_used(d: Derivation) -> int:
    """ℓ, the independent constraint rows: as the closed forms solved them, else k = n + p − d − ℓ
    read backwards from the program's speeds."""
    if d.closed:
        return d.rates.constraints_used
    s = d.system
    defined = sum(1 for q in s.quasi_coordinates if q.differential is not None)
    return len(s.coordinates) + len(s.quasi_coordinates) - defined - d.k


def dependent_rows(d: Derivation) -> tuple[str, ...]:
    """The constraint rows left out of l: rolling rows that say again what the others say.

    ``gacli check`` lists every row it classifies; this is what lets it and
    ``gacli derive`` agree on why l is smaller than the number of rows.
    """
    if rows_used(d) == len(d.system.constraints):
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
    ell = rows_used(d)
    how = "as given in the file" if s.independent is not None else "chosen automatically"
    dependent = dependent_rows(d)
    why = f" ({rank_note(len(s.constraints), dependent)})" if dependent else ""
    return Section("Degrees of freedom", (
        f"k = n + p - d - l = {n} + {p} - {dq} - {ell} = {d.k}",
        f"n = {n} coordinates, p = {p} quasi-coordinates (d = {dq} defined by a differential), "
        f"l = {ell} constraints{why}",
        f"independent: {', '.join(d.independent)} ({how})",
    ))


def rates(d: Derivation) -> Section:
    lines = [f"{rate_name(n, 1)} = {show(printed.tidy(e))}" for n, e in d.dependent_rates]
    return Section("Rates in terms of the independent rates, eq. (14.7)", tuple(lines) or ("(all rates are independent)",))


def gibbs(d: Derivation) -> Section:
    """G as `gacli gibbs` prints it: the acceleration terms, as every output prints them (eqs. 14.17, 14.21)."""
    return Section(GIBBS_TITLE, (f"G = {show(printed.gibbs(d))} + ...",))


GIBBS_TITLE = "Gibbs function, acceleration terms (eqs. 14.17, 14.21)"
# Why G ends in "+ ...", said once under it.
GIBBS_DOTS = "  (+ ... : the terms free of the accelerations, which do not enter eq. (14.19))"


def forces(d: Derivation) -> Section:
    c = printed.coefficients(d)
    lines = [f"Q_{name} = {show(q)}" for name, q in zip(d.independent, c.forces)]
    return Section("Generalized forces, eq. (14.13)", tuple(lines))


def equations(d: Derivation, by_name: bool = False) -> Section:
    """∂G/∂u̇_s = Q_s; ``by_name``: each Q_s by the name the section above prints it under."""
    lines = []
    for s, name in enumerate(d.independent):
        lhs, rhs = printed.equation(d, s)
        lines.append(f"dG/d({rate_name(name, 2)}): {show(lhs)} = {f'Q_{name}' if by_name and rhs != 0 else show(rhs)}")
        if lhs == 0 and rhs == 0:
            # Said, not left for a reader to find: M is singular and the motion undetermined.
            lines.append(f"  (0 = 0: G holds no {rate_name(name, 2)} and no load does work in {name}: nothing "
                         f"moves with it, M is singular and this equation does not determine {rate_name(name, 2)}; "
                         "gacli check reports it)")
    return Section("Gibbs-Appell equations, eq. (14.19)", tuple(lines))


def gibbs_of(d: Derivation) -> Section:
    """G from the equations' own coefficients: written out when short, else named through them."""
    G = show(printed.gibbs(d))
    if len(G) <= GIBBS_WRITTEN_OUT:
        return Section(GIBBS_TITLE, (f"G = {G} + ...", GIBBS_DOTS))
    return Section(GIBBS_TITLE, (
        "G = 1/2*sum(M[r,s]*ddot(u_r)*ddot(u_s)) + sum((Q_s - F_s)*ddot(u_s)) + ...",
        f"  with u = {', '.join(d.independent)}: its coefficients are those of the equations below, "
        f"dG/d(ddot(u_s)) = sum(M[s,r]*ddot(u_r)) + Q_s - F_s; `gacli gibbs` writes it out",
        GIBBS_DOTS,
    ))


# G is written out in `derive` up to this many characters; past it, it is named through
# the equations' coefficients, which it repeats (∂G/∂u̇_s = M u̇ + Q − F): written out
# again it was a third to a half of a robot's printout (docs/readable.md).
GIBBS_WRITTEN_OUT = 2_000


def kinematic(d: Derivation) -> Section:
    # q̇ = q̇ for an independent coordinate says nothing, and is not printed.
    lines = [f"{rate_name(n, 1)} = {show(e)}" for n, e in printed.kinematic(d)]
    return Section("Kinematic equations, eq. (14.20)",
                   tuple(lines) or ("(every coordinate is independent: its rate is one of the speeds)",))


def written_length(d: Derivation, header: int) -> tuple[int, int] | None:
    """(characters, longest line) of the equations written out, counted as the bound counts a
    printout: the title and degrees of freedom above (``header``), a blank line before each section
    (a sphere whose code shrank to 69 operations printed 2,152 for 2,000); None as soon as they
    are known to print past :func:`gacli.display.long.limit`, or are too large to tidy."""
    if not d.printable or not displayable(d) or not L.tidy_worth_trying(d):
        return None
    if printed.coefficients(d, L.limit(d)) is None:
        return None
    closed = written(d, header)
    return header + L.printed_length(closed) + len(closed), L.longest_line(closed)


def prints_written_out(d: Derivation) -> bool:
    """Whether ``d``'s equations print written out, within the bound and the longest line."""
    counted = written_length(d, _header(d, freedom(d)))
    return counted is not None and counted[0] <= L.limit(d) and counted[1] <= L.LONGEST_LINE


def long_form(d: Derivation):
    """The named form (:mod:`gacli.display.named`) when the equations written out would print
    past :func:`gacli.display.long.limit` or in a line past LONGEST_LINE, and it does better;
    None otherwise (docs/printing.md)."""
    header = _header(d, freedom(d))
    counted = written_length(d, header)
    if counted is None:
        return L.named_of(d, header)
    limit, (length, longest) = L.limit(d), counted
    if length <= limit and longest <= L.LONGEST_LINE:
        return None
    named = L.named_of(d, header)
    sections = named_sections(d, named)
    if length > limit:
        return named if header + L.printed_length(sections) + len(sections) < length else None
    return named if L.printed_length(sections) <= limit and L.longest_line(sections) < longest else None


def named_sections(d: Derivation, named) -> tuple[Section, ...]:
    return tuple(Section(title, lines) for title, lines in L.parts(d, named))


def derivation_report(d: Derivation) -> tuple[Section, ...]:
    """The results of the chapter's solution procedure (section 14.3); through named
    quantities when written out they would be long (:mod:`gacli.display.long`)."""
    named, free = long_form(d), freedom(d)
    if named is not None:
        return (free, *named_sections(d, named))
    return (free, *written(d, _header(d, free)))


def _header(d: Derivation, free: Section) -> int:
    """The characters printed before the equations: the title and the degrees of freedom."""
    return len(d.system.title or d.system.name) + 1 + L.printed_length([free])


def written(d: Derivation, header: int) -> tuple[Section, ...]:
    """The equations written out: each Q_s again on its equation's right-hand side, or, where that
    prints past the bound (:func:`gacli.display.long.limit`), by its name: a two-link arm with a
    spring printed each Q twice, 2,229 characters for 79 operations. ``header``: the characters
    printed before them (:func:`_header`)."""
    full = (rates(d), gibbs_of(d), forces(d), equations(d), kinematic(d))
    if header + L.printed_length(full) + len(full) <= L.limit(d):  # a blank line before each section
        return full
    return (*full[:3], equations(d, by_name=True), full[4])


def gibbs_report(d: Derivation) -> tuple[Section, ...]:
    named = long_form(d)
    if named is not None:
        return (Section(GIBBS_TITLE, L.gibbs_lines(d)), *named_sections(d, named))
    return (gibbs(d),)


def steps_report(d: Derivation) -> tuple[Section, ...]:
    """The worked solution (:mod:`gacli.display.steps`) as text sections."""
    from gacli.display.steps import worked_solution

    named = long_form(d)
    if named is not None and not L.steps_written_out(d):
        note = Section("Worked solution", (
            "The steps' closed forms are too long to read written out; the equations are written "
            "through the quantities they are built from instead (docs/printing.md).",))
        return (freedom(d), note, *named_sections(d, named))
    return tuple(Section(step.title, tuple(_line(i) for i in step.items)) for step in worked_solution(d))


def _line(item) -> str:
    from gacli.display.steps import Equation, Load, Sentence

    if isinstance(item, Equation):
        return f"{_side(item.lhs)} = {_side(item.rhs)}"
    if isinstance(item, Sentence):
        return item.text
    if isinstance(item, Load):
        vectors = " + ".join(f"{_side(v)} ({frame} axes)" for frame, v in item.terms)
        if item.torque:
            return f"a torque {vectors} on {item.where}"
        return f"a force {vectors} at " + (item.where or f"the point {_side(item.position)} (N axes)")
    return item


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
