"""GNU Octave / MATLAB function files of a derivation.

:func:`emit_octave` returns one function file per entry point:

.. code:: text

    xdot = NAME_rhs(t, x, p, r)          [q'; u'], NX-by-1, M u' = F solved by Cholesky
    M    = NAME_mass_matrix(t, x, p, r)  k-by-k, symmetric positive definite
    F    = NAME_forcing(t, x, p, r)      k-by-1
    idx  = NAME_indices()                sizes and 1-based index of each entry of x, p, r
    p    = NAME_defaults()               NP-by-1: the file's parameter values, NaN where it gives none

x, p and r are vectors (column or row), indexed from 1 in the order of
:mod:`gacli.emit.naming`; ``ode45(@(t, x) NAME_rhs(t, x, p, r), tspan, x0)``
integrates the system. The code uses only builtins that Octave and MATLAB
share (``zeros``, ``chol``, the element-wise operators), so the same files
run in both. A name that is an Octave keyword or a builtin the code calls
(``end``, ``pi``, ``i``, ``sin``) is renamed as C and Python rename theirs.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from string import Template

from gacli.emit.assembly import Assembly, assemble, refuse_reactions
from gacli.emit.defaults import defaults
from gacli.emit.naming import Layout, header_lines, layout
from gacli.emit.printers import GacliOctavePrinter
from gacli.mechanics.equations import Derivation

INDENT = "  "

# Keywords of Octave and MATLAB, and the builtins and constants that generated
# code may call: a local variable of the same name would hide the function.
OCTAVE_RESERVED = frozenset("""
    break case catch classdef continue do else elseif end end_try_catch end_unwind_protect
    endclassdef endenumeration endevents endfor endfunction endif endmethods endparfor
    endproperties endspmd endswitch endwhile enumeration events for function global if methods
    otherwise parfor persistent properties return spmd switch try until unwind_protect
    unwind_protect_cleanup while
    pi e i j I J Inf inf NaN nan NA eps true false
    sin cos tan sec csc cot asin acos atan atan2 sinh cosh tanh asinh acosh atanh exp log log2
    log10 log1p expm1 sqrt cbrt abs sign floor ceil round fix mod rem power mpower hypot gamma
    erf erfc real imag conj min max zeros ones chol struct nargin double L idx
    flag all isfinite isreal error
""".split())

FUNCTION = Template('''\
$header
function $out = $name(t, x, p, r)
$doc
$body
end
''')

DOCS = {
    "rhs": "{NAME}_RHS  d(x)/dt = [q'; u'] ({nx}-by-1), with M u' = F solved by Cholesky.",
    "mass_matrix": "{NAME}_MASS_MATRIX  The mass matrix M ({k}-by-{k}), symmetric positive definite.",
    "forcing": "{NAME}_FORCING  The forcing F of M u' = F ({k}-by-1).",
}


def emit_octave(derivation: Derivation, *, reactions: bool = False) -> dict[str, str]:
    """``{"<name>_rhs.m": ..., "<name>_mass_matrix.m": ..., "<name>_forcing.m": ..., "<name>_indices.m": ...}``.

    Raises:
        EmitError: when an expression has no Octave rendering, or for ``reactions``.
    """
    refuse_reactions(reactions)
    own = {f"{derivation.system.name}_{suffix}" for suffix in ("indices", "defaults")}
    lay = layout(derivation, reserved=OCTAVE_RESERVED | own)
    header = "\n".join(f"% {line}" for line in header_lines(derivation, "octave"))
    files = {
        "rhs": _rhs(derivation, lay), "mass_matrix": _mass_matrix(derivation, lay),
        "forcing": _forcing(derivation, lay),
    }
    texts = {f"{lay.function(name)}.m": FUNCTION.substitute(header=header, **parts) for name, parts in files.items()}
    texts[f"{lay.function('indices')}.m"] = _indices(lay, header)
    texts[f"{lay.function('defaults')}.m"] = _defaults(derivation, lay, header)
    return texts


def _rhs(derivation: Derivation, lay: Layout) -> dict[str, str]:
    code = _assemble(derivation, lay, ("qdot", "M_lower", "F"))
    lines = [
        *_mass("M_lower", code, lay.k),
        *_column("F", [c for _, c in code.slots["F"]]),
        *_column("xdot", [*(c for _, c in code.slots["qdot"]), "F"]),
        *_refuse_undefined(lay, "rhs", "[xdot; M(:)]"),
        "[L, flag] = chol(M, 'lower');  % M = L*L', reading only the lower triangle",
        "if flag ~= 0",
        f"{INDENT}error('gacli:undefined', '{lay.function('rhs')}: the mass matrix is not positive definite "
        "at t = %g (pivot %d)', t, flag);",
        "end",
        f"xdot({len(lay.state) - lay.k + 1}:end) = L' \\ (L \\ F);",
        *_refuse_undefined(lay, "rhs", "xdot"),
    ]
    return _function(lay, "rhs", "xdot", code, lines)


def _refuse_undefined(lay: Layout, name: str, values: str) -> list[str]:
    """Octave computes sqrt(-1) as a complex number and 1/0 as Inf: where the equations are
    undefined it raises gacli:undefined, as the other targets raise or return a flag."""
    return [
        f"if ~all(isfinite({values})) || ~isreal({values})",
        f"{INDENT}error('gacli:undefined', '{lay.function(name)}: undefined at t = %g: a value is not a finite "
        "real number', t);",
        "end",
    ]


def _mass_matrix(derivation: Derivation, lay: Layout) -> dict[str, str]:
    code = _assemble(derivation, lay, ("M",))
    return _function(lay, "mass_matrix", "M", code, [*_mass("M", code, lay.k), *_refuse_undefined(lay, "mass_matrix", "M(:)")])


def _forcing(derivation: Derivation, lay: Layout) -> dict[str, str]:
    code = _assemble(derivation, lay, ("F",))
    return _function(lay, "forcing", "F", code, [*_column("F", [c for _, c in code.slots["F"]]),
                                                 *_refuse_undefined(lay, "forcing", "F")])


def _assemble(derivation: Derivation, lay: Layout, parts: Sequence[str]) -> Assembly:
    code, _ = assemble(derivation, lay.identifiers, GacliOctavePrinter, parts, prefix=temporary_prefix(lay))
    return code


def temporary_prefix(lay: Layout) -> str:
    """``c_`` for the temporaries ``c_0``, ``c_1`` ..., or ``cc_``... when an entry has such a name.

    MATLAB names must start with a letter, so the other targets' ``_c0`` will not do.
    """
    prefix = "c_"
    while any(re.fullmatch(re.escape(prefix) + r"\d+", e.identifier) for e in lay.entries):
        prefix = "c" + prefix
    return prefix


def _function(lay: Layout, name: str, out: str, code: Assembly, lines: Sequence[str]) -> dict[str, str]:
    """The parts of a function file: entries read, temporaries, then the results."""
    doc = DOCS[name].format(NAME=lay.system.upper(), nx=len(lay.state), k=lay.k)
    body = [
        *(f"{e.identifier} = {vector}({e.index + 1});"
          for vector in ("x", "p", "r") for e in code.read_entries(lay, vector)),
        *(f"{temporary} = {value};" for temporary, value in code.block.temporaries),
        *lines,
    ]
    return {"out": out, "name": lay.function(name), "doc": f"{INDENT}% {doc}",
            "body": "\n".join(INDENT + line for line in body)}


def _mass(part: str, code: Assembly, k: int) -> list[str]:
    # Only M's nonzero entries are set: a wide system's M is k² entries, nearly all zero.
    return [f"M = zeros({k}, {k});", *(f"M({i + 1}, {j + 1}) = {c};" for (i, j), c in code.slots[part])]


def _column(name: str, codes: Sequence[str]) -> list[str]:
    return [f"{name} = [", *(f"{INDENT}{c};" for c in codes), "];"]


def _indices(lay: Layout, header: str) -> str:
    """The function that returns the sizes and the index of each entry of x, p and r, from 1."""
    name = lay.function("indices")
    lines = [
        f"% {name.upper()}  Sizes (nx, nu, np, nr) and the 1-based index of each entry of x, p and r,",
        "% by the names the generated functions give them: idx.x.dot_q_z, idx.p.m ...",
        f"idx.nx = {len(lay.state)};", f"idx.nu = {lay.k};",
        f"idx.np = {len(lay.parameters)};", f"idx.nr = {len(lay.r)};",
    ]
    for vector, entries in (("x", lay.state_entries), ("p", lay.parameter_entries), ("r", lay.r_entries)):
        lines.append(f"idx.{vector} = struct();")
        lines += [f"idx.{vector}.{e.identifier} = {e.index + 1};  % {e.name}" for e in entries]
    body = "\n".join(INDENT + line for line in lines)
    return f"{header}\nfunction idx = {name}()\n{body}\nend\n"


def _defaults(derivation: Derivation, lay: Layout, header: str) -> str:
    """The function that returns p as the system file gives it (gacli.emit.defaults)."""
    name = lay.function("defaults")
    lines = [
        f"% {name.upper()}  The parameters p ({len(lay.parameters)}-by-1) with the values the system file gives,",
        "% in the file's order (an expression in earlier parameters evaluated exactly); NaN where it gives none.",
        f"p = zeros({len(lay.parameters)}, 1);",
    ]
    for row in defaults(derivation, lay):
        literal = "NaN" if row.value is None else repr(row.value)
        note = f"{row.entry.name} = {row.formula}" if row.formula else row.entry.name
        lines.append(f"p({row.entry.index + 1}) = {literal};  % {note}")
    body = "\n".join(INDENT + line for line in lines)
    return f"{header}\nfunction p = {name}()\n{body}\nend\n"
