"""The C99 header and source of a derivation (interface 1 of the generated-code spec).

:func:`emit_c` returns ``{"<name>.h": header, "<name>.c": source}``:

.. code:: text

    <NAME>_NX, _NU, _NP, _NR          sizes of x, u, p and r
    <NAME>_X_*, _P_*, _R_*            index of each entry (see naming.py)
    void <name>_mass_matrix(t, x, p, r, M)    M: k*k, row-major
    void <name>_forcing(t, x, p, r, F)        F: k
    int  <name>_rhs(t, x, p, r, xdot)         xdot: [q', u']; 0, a pivot number, or -1 (undefined)
    int  <name>_default_parameters(p)         p: the file's values; returns how many it lacks

The code is C99 with no allocation, no globals and nothing beyond
``<math.h>``, and compiles cleanly with ``-std=c99 -Wall -Wextra -Werror
-pedantic``: unused arguments are cast to void, π is a literal (``M_PI`` is
not C99). Each function shares its common subexpressions; ``rhs`` fills a
local ``double M[k*k]`` (zero-filled first when M has zero entries: only the
nonzero ones are computed) and solves M u' = F in place by a Cholesky
factorization written as loops for the fixed size k.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from string import Template

import sympy as sp

from gacli.emit.assembly import Assembly, assemble, live_block, reaction_equations, reaction_solve
from gacli.emit.c_solvers import LU_SOLVE, SOLVERS
from gacli.emit.defaults import defaults, missing
from gacli.emit.naming import Entry, Layout, header_lines, layout
from gacli.emit.printers import GacliCPrinter, print_block
from gacli.mechanics.equations import Derivation
from gacli.errors import EmitError
from gacli.algebra.readable import displayable

INDENT = "    "

HEADER = Template('''\
$comment
#ifndef $guard
#define $guard

#ifdef __cplusplus
extern "C" {
#endif

/* Sizes: state x = (q, u), independent rates u, parameters p, arguments r. */
$sizes

/* x: the coordinates q, then the independent rates u. */
$state

/* p: the parameters. */
$parameters

/* Fills p with the values the system file gives, in the file's order (a value
   written as an expression in earlier parameters is evaluated, exactly, when
   the code is generated). Returns the number of parameters the file gives no
   value; their entries are set to NaN, so that a forgotten one shows. */
$default_parameters;

/* r: the inputs, then each free function of time and its rates. */
$r

/* The mass matrix M, NU*NU entries, row-major, symmetric positive definite. */
$mass_matrix;

/* The forcing F of M u' = F, NU entries. */
$forcing;

/* xdot = [q', u'], NX entries, with M u' = F solved by Cholesky.
   Returns 0; or n > 0 when pivot n (counting from 1) of M is not positive
   (M is not positive definite); or -1 when a number it computes is not
   finite (a function outside its domain, a division by zero, an overflow,
   NaN or infinity given). On a nonzero return every entry of xdot is NaN. */
$rhs;
$reactions
#ifdef __cplusplus
}
#endif

#endif /* $guard */
''')

SOURCE = Template('''\
$comment
#include <math.h>

#include "$name.h"
$solvers$functions''')

FUNCTION = Template('''
$signature
{
$body
}
''')


def emit_c(derivation: Derivation, *, reactions: bool = False) -> dict[str, str]:
    """The C header and source of a derivation.

    ``reactions`` adds ``NAME_reactions``, the constraint forces.

    Raises:
        EmitError: when an expression has no C rendering.
    """
    lay = layout(derivation)
    comment = _comment(header_lines(derivation, "c"))
    header = HEADER.substitute(
        comment=comment, guard=f"{lay.prefix}_H", sizes=_sizes(lay),
        state=_indices(lay.state_entries), parameters=_indices(lay.parameter_entries) or "/* (none) */",
        r=_indices(lay.r_entries) or "/* (none: r may be NULL) */",
        default_parameters=_defaults_signature(lay), mass_matrix=_signature(lay, "mass_matrix"), forcing=_signature(lay, "forcing"), rhs=_signature(lay, "rhs"),
        reactions=_reactions_declaration(derivation, lay) if reactions else "",
    )
    functions = [_default_parameters(derivation, lay), _mass_matrix(derivation, lay), _forcing(derivation, lay),
                 _rhs(derivation, lay)]
    if reactions:
        functions.append(_reactions(derivation, lay))
    solvers = SOLVERS.substitute(name=lay.system, prefix=lay.prefix)
    source = SOURCE.substitute(comment=comment, name=lay.system, solvers=solvers, functions="".join(functions))
    return {f"{lay.system}.h": header, f"{lay.system}.c": source}


# -- header pieces ---------------------------------------------------------------

def _comment(lines: Sequence[str]) -> str:
    safe = [comment_text(line) for line in lines]
    return "\n".join(["/* " + safe[0], *(" * " + line for line in safe[1:]), " */"])


# '/*' inside a comment fails -Werror=comment and '*/' ends it early; a trigraph
# (C99 has them) such as '??/' is a backslash, and a backslash at a line's end
# splices the next line of the comment into it.
_SLASH_STAR = re.compile(r"/(?=\*)|\*(?=/)")
_TRIGRAPH = re.compile(r"\?(?=\?[=(/)'<!>-])")


def comment_text(text: str) -> str:
    """Free text (a title, a file name) made inert inside a C block comment, on one line."""
    text = _SLASH_STAR.sub(lambda m: m.group() + " ", text)
    text = _TRIGRAPH.sub("? ", text)
    return text.rstrip("\\ ")


def _sizes(lay: Layout) -> str:
    sizes = [("NX", len(lay.state)), ("NU", lay.k), ("NP", len(lay.parameters)), ("NR", len(lay.r))]
    return _defines([(f"{lay.prefix}_{name}", str(size), "") for name, size in sizes])


def _indices(entries: Sequence[Entry]) -> str:
    return _defines([(e.macro, str(e.index), e.name) for e in entries])


def _defines(rows: Sequence[tuple[str, str, str]]) -> str:
    width = max((len(macro) for macro, _, _ in rows), default=0)
    lines = []
    for macro, value, note in rows:
        line = f"#define {macro.ljust(width)} {value}"
        lines.append(f"{line.ljust(width + 12)} /* {note} */" if note else line)
    return "\n".join(lines)


_RETURNS = {"mass_matrix": ("void", "M"), "forcing": ("void", "F"), "rhs": ("int", "xdot"),
            "reactions": ("void", "lambda")}


def _signature(lay: Layout, function: str) -> str:
    kind, out = _RETURNS[function]
    opening = f"{kind} {lay.function(function)}("
    return (f"{opening}double t, const double *x, const double *p,\n"
            f"{' ' * len(opening)}const double *r, double *{out})")


def _defaults_signature(lay: Layout) -> str:
    return f"int {lay.function('default_parameters')}(double *p)"


# -- the functions ------------------------------------------------------------------

def _default_parameters(derivation: Derivation, lay: Layout) -> str:
    """p's defaults as literals (gacli.emit.defaults): C computes nothing."""
    rows = defaults(derivation, lay)
    lines = [] if rows else ["(void)p;"]
    for row in rows:
        note = row.formula if row.value is not None else (
            f"{row.formula}: not a number" if row.given else "no value in the system file")
        value = f"{lay.system}_nan()" if row.value is None else repr(row.value)
        lines.append(f"p[{row.entry.macro}] = {value};" + (f" /* {comment_text(note)} */" if note else ""))
    lines.append(f"return {missing(rows)};")
    return FUNCTION.substitute(signature=_defaults_signature(lay), body="\n".join(INDENT + line for line in lines))


def _mass_matrix(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("M",))
    # Only M's nonzero entries are set: a wide system's M is k² entries, nearly all zero.
    fill = [] if code.dense("M") else [f"for (int _i = 0; _i < {lay.prefix}_NU*{lay.prefix}_NU; ++_i) M[_i] = 0.0;"]
    return _function(lay, "mass_matrix", fill, code, _assign_matrix(code.slots["M"], lay.k))


def _forcing(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("F",))
    return _function(lay, "forcing", [], code, _assign_vector("F", code.slots["F"]))


def _rhs(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("qdot", "M_lower", "F"))
    size = f"{lay.prefix}_NU*{lay.prefix}_NU"
    locals_ = [
        f"double M[{size}]; /* only the lower triangle is set and read */" if code.dense("M_lower") else
        f"double M[{size}] = {{0.0}}; /* only the lower triangle's nonzero entries are set */",
        f"double *F = xdot + ({lay.prefix}_NX - {lay.prefix}_NU);",
    ]
    assignments = [
        *_assign_vector("xdot", code.slots["qdot"]),
        *_assign_matrix(code.slots["M_lower"], lay.k),
        *_assign_vector("F", code.slots["F"]),
        f"return {lay.function('solved')}(M, xdot);",
    ]
    return _function(lay, "rhs", locals_, code, assignments)


def _reactions_declaration(derivation: Derivation, lay: Layout) -> str:
    count = len(derivation.system.constraints)
    numeric = ("" if displayable(derivation) else
               "\n   Found by solving the fundamental equations numerically; all NaN when they are singular.")
    size = _defines([(f"{lay.prefix}_NLAMBDA", str(count), "entries of lambda")])
    return (f"\n{size}\n\n/* The constraint forces: {count} multipliers, one per constraint in the file's order\n"
            f"   (docs/verify.md gives their sign and units).{numeric} */\n{_signature(lay, 'reactions')};\n")


def _reactions(derivation: Derivation, lay: Layout) -> str:
    solve = reaction_solve(derivation)
    if solve is None:
        code = _block(lay, reaction_equations(derivation))
        # No constraint, no multiplier: the output array is never written, and -Wextra says so.
        none = [] if code.block.results else ["(void)lambda;"]
        return _function(lay, "reactions", none, code, _assign("lambda", code.block.results))
    if solve.redundant:
        raise EmitError(
            f"{derivation.system.path}: the constraint forces of a system this large with repeated constraint "
            "rows (the reaction shared among them is statically indeterminate) are generated for Python only, "
            "as the minimum-norm solution; leave out --reactions for C")
    code = _block(lay, solve.equations)
    entries, rhs = code.block.results[:len(solve.nonzero)], code.block.results[len(solve.nonzero):]
    n = solve.size
    locals_ = [
        "/* The fundamental equations in all the rates and multipliers (docs/verify.md), solved",
        "   numerically: closed-form multipliers of a system this large would be millions of terms. */",
        f"double _K[{n * n}] = {{0.0}};",
        f"double _b[{n}];",
        "int _i;",
    ]
    assignments = [
        *(f"_K[{i * n + j}] = {code};" for (i, j), code in zip(solve.nonzero, entries)),
        *_assign("_b", rhs),
        f"if ({lay.function('lu_solve')}({n}, _K, _b) != 0) {{",
        f"{INDENT}for (_i = 0; _i < {solve.count}; ++_i) {{",
        f"{INDENT * 2}lambda[_i] = {lay.system}_nan();",
        f"{INDENT}}}",
        f"{INDENT}return;",
        "}",
        f"for (_i = 0; _i < {solve.count}; ++_i) {{",
        f"{INDENT}lambda[_i] = _b[{solve.first} + _i];",
        "}",
    ]
    return LU_SOLVE.substitute(name=lay.system) + _function(lay, "reactions", locals_, code, assignments)



def _assemble(derivation: Derivation, lay: Layout, parts: Sequence[str]) -> Assembly:
    code, printer = assemble(derivation, lay.identifiers, GacliCPrinter, parts)
    printer.includes()  # raises if the code would need more than <math.h>
    return code


def _block(lay: Layout, equations: list[tuple[str, sp.Expr]]) -> Assembly:
    block, printer = print_block(GacliCPrinter, lay.identifiers, equations)
    printer.includes()
    return Assembly(live_block(block, lay.identifiers), {}, lay.k)  # the reactions' route too


def _function(lay: Layout, function: str, locals_: list[str], code: Assembly, assignments: list[str]) -> str:
    """Unused arguments, unpacked entries, temporaries, then the assignments."""
    body = [
        *(f"(void){arg};" for arg in code.unused(lay)),
        *locals_,
        *(f"const double {e.identifier} = {vector}[{e.macro}];"
          for vector in ("x", "p", "r") for e in code.read_entries(lay, vector)),
        *(f"const double {name} = {value};" for name, value in code.block.temporaries),
        *assignments,
    ]
    return FUNCTION.substitute(signature=_signature(lay, function), body="\n".join(INDENT + line for line in body))


def _assign(array: str, codes: Sequence[str]) -> list[str]:
    return [f"{array}[{i}] = {code};" for i, code in enumerate(codes)]


def _assign_vector(array: str, slots: Sequence[tuple[int, str]]) -> list[str]:
    return [f"{array}[{i}] = {code};" for i, code in slots]


def _assign_matrix(slots: Sequence[tuple[tuple[int, int], str]], k: int) -> list[str]:
    return [f"M[{i * k + j}] = {code};" for (i, j), code in slots]
