"""Which form a derivation prints in, and the named form's text (docs/printing.md).

A system prints its equations written out, tidied (:mod:`gacli.display.printed`),
while they fit in :func:`limit` characters: 25 per operation of its generated
right-hand side after common subexpressions are shared, and never less than
:data:`SMALL_PRINTOUT`. Past it, they are written through named quantities
(:mod:`gacli.display.named`), which are read off the derivation's own
record: the straight-line program generated code takes, or the shared
subexpressions of the closed forms.
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra.graph import trees_within
from gacli.algebra.readable import show
from gacli.algebra.symbols import rate_name
from gacli.display import named as N
from gacli.display.labels import legend
from gacli.display import printed

# The bound: at most this many characters per operation of the generated rhs.
CHARS_PER_OPERATION = 25
# A printout this short is taken as within the bound whatever its operations: a handful
# of operations still comes with the report's titles and its degrees of freedom (~500 characters),
# and a textbook system's equations written out (Routh's sphere: 2,161 characters, as the
# chapter's reader checks them) stay so when its generated code shrinks (87 → 69 operations).
SMALL_PRINTOUT = 2_500
# Written out, a line of more characters than this (a screenful) is named through its pieces instead.
LONGEST_LINE = 2_000


# M, F and Q of more tree nodes than this (counting stops there) are named without being tidied
# first: tidying a 6-link spatial arm's 14,608 nodes took 9 s of its text derive only to print
# past the bound; the systems that print written out have at most 6,001 (a robot with a castor).
TIDIED_NODES = 10_000


def printed_expressions(d) -> list[sp.Expr]:
    """What a printout tidies: M (r ≤ s, M being symmetric), F and Q."""
    return [*(e for (i, j), e in d.mass_matrix.todok().items() if j >= i), *d.forcing, *d.generalized_forces]


def tidy_worth_trying(d) -> bool:
    """Whether M (r ≤ s), F and Q have at most TIDIED_NODES nodes as trees together."""
    return trees_within(printed_expressions(d), TIDIED_NODES)


# Tree nodes of the closed M, F and q̇ up to which --steps prints the worked solution even where the
# results alone would print named: a student who asks for the steps wants β, the accelerations and G
# as the chapter forms them (Chaplygin's ball: 423 nodes, 6,700 characters; a satellite with three
# wheels 1,177 and 10,000; a four-bar's 6,199 would be 86,000, and is named).
STEPS_NODES = 2_000


def steps_written_out(d) -> bool:
    """Whether ``--steps`` prints the worked solution (the closed forms are there and not too large)."""
    if not d.closed:
        return False
    return trees_within([*d.mass_matrix, *d.forcing, *(e for _, e in d.kinematic_equations)], STEPS_NODES)


def limit(d) -> int:
    """The characters the equations may print in written out (see the module)."""
    return max(CHARS_PER_OPERATION * d.code.operations, SMALL_PRINTOUT)


def named_of(d, header: int = 0) -> N.Named:
    """q̇, M and F of ``d`` through named quantities: the program's, by their physical names, where
    generated code takes the program and they print within :func:`limit`; else generated code's
    own shared subexpressions (never derived again), which print in about half: the program's
    steps are more than the operations left once code's CSE has shared them (a rattleback's
    12,800 characters for 383 operations, 4,100 so). ``header``: the characters printed before
    these sections (the title, the degrees of freedom)."""
    code, taken = d.code, N.declared_names(d)
    if code.route == "program":
        from gacli.mechanics.code import program_for

        named = N.from_program(d.program if d.program is not None else program_for(d.system), taken)
        sections = parts(d, named)
        if parts_length(sections) + len(sections) + header <= limit(d):  # a blank line before each
            return named
    # Read off the program, a dependent rate is its solve inlined: tidied as the written-out
    # printout's rates section tidies it (an Ackermann car's named printout: 3,108 → 2,863 characters).
    dependent = {n: e if d.closed else printed.tidy(e) for n, e in d.dependent_rates}
    mass = [(key, e) for key, e in code.mass_matrix if key[0] <= key[1]]
    return N.from_closed(code.kinematic_equations, mass, code.forcing, dependent, taken)


def parts(d, named: N.Named) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """(title, lines) of the named form's sections."""
    return (("Named quantities, each computed once, in order (docs/printing.md)", quantity_lines(named)),
            ("Kinematic equations, eq. (14.20)", kinematic_lines(d, named)),
            (f"Gibbs-Appell equations, eq. (14.19), as M u' = F with u = ({', '.join(d.independent)})",
             equation_lines(d, named)))


def quantity_lines(named: N.Named) -> tuple[str, ...]:
    """``name = value`` in evaluation order, each vector's description once above it as ``# ...``."""
    lines = [legend(q.about for q in named.quantities)] if named.source == "program" else []
    said = None
    for q in named.quantities:
        if q.about and q.about != said:
            lines.append(f"# {q.about}")
        said = q.about
        lines.append(f"{q.symbol.name} = {show(q.value)}")
    return tuple(lines) or ("(none: M and F are short enough as they are)",)


def kinematic_lines(d, named: N.Named) -> tuple[str, ...]:
    lines = [f"{rate_name(q, 1)} = {show(e)}" for q, e in named.rates]
    above = [q.symbol.name for q in named.quantities if q.symbol.name.startswith("dot(")]
    if above:
        lines.append(f"({', '.join(above)}: named above)")
    return tuple(lines) or ("(every coordinate is independent: its rate is one of the speeds)",)


def mass_name(r: int, s: int) -> str:
    return f"M_{r + 1}_{s + 1}"


def equation_lines(d, named: N.Named) -> tuple[str, ...]:
    """M's entries r ≤ s (M is symmetric), F, then each equation through them."""
    lines = [f"{mass_name(r, s)} = {show(e)}" for (r, s), e in named.mass]
    lines += [f"F_{r + 1} = {show(e)}" for r, e in enumerate(named.forcing)]
    nonzero = {key for key, _ in named.mass}
    for s, name in enumerate(d.independent):
        terms = [f"{mass_name(min(s, r), max(s, r))}*{rate_name(u, 2)}" for r, u in enumerate(d.independent)
                 if (min(s, r), max(s, r)) in nonzero]
        lines.append(f"for {rate_name(name, 2)}: {' + '.join(terms) or '0'} = F_{s + 1}")
    return tuple(lines)


def gibbs_lines(d) -> tuple[str, ...]:
    """G named through the equations' coefficients, as ``derive`` says it for a long G."""
    return ("G = 1/2*sum(M[r,s]*ddot(u_r)*ddot(u_s)) + sum((Q_s - F_s)*ddot(u_s)) + ...",
            f"  with u = {', '.join(d.independent)} and M, F as written below: dG/d(ddot(u_s)) = Q_s is "
            "sum(M[s,r]*ddot(u_r)) = F_s (eq. 14.19)")


def printed_length(sections) -> int:
    """Characters of sections as ``gacli derive`` prints them (two spaces before each line)."""
    return parts_length((s.title, s.lines) for s in sections)


def parts_length(parts) -> int:
    """:func:`printed_length` of (title, lines) pairs."""
    return sum(len(title) + 1 + sum(len(line) + 3 for line in lines) for title, lines in parts)


def longest_line(sections) -> int:
    return max((len(line) for s in sections for line in s.lines), default=0)
