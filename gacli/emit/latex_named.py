"""LaTeX of long equations through named quantities, as the text report prints them (docs/printing.md).

The same :class:`gacli.display.named.Named` as ``gacli derive`` prints: each
quantity set once, in order, under what it is (``\\intertext``), then q̇, M
and F written through them, then each equation. A name prints as its
letter with what it is of in a subscript (``\\omega_{\\mathrm{rolled},x}``), ``z_{12}``,
``M_{1,2}`` or ``F_{1}``.
"""

from __future__ import annotations

import re

import sympy as sp

from gacli.algebra import symbols as S
from gacli.display.named import Named
from gacli.emit.latex_layout import Section, expression_rows, grouped, rows
from gacli.emit.latex_printer import GacliLatexPrinter, printer_for
from gacli.emit.latex_text import tex_text

_NUMBERED = re.compile(r"^z(\d+)$")


def tex_name(name: str) -> str:
    """A named quantity's LaTeX (see the module)."""
    if m := _NUMBERED.match(name):
        return f"z_{{{m[1]}}}"
    if m := re.match(r"^M_(\d+)_(\d+)$", name):
        return f"M_{{{m[1]},{m[2]}}}"
    if m := re.match(r"^F_(\d+)$", name):
        return f"F_{{{m[1]}}}"
    if m := _VECTOR.match(name):
        # The quantity's letter, what it is of and for in upright script, the axis: set a third
        # narrower than the whole name upright, so that a product of two fits a line.
        return r"%s_{\mathrm{%s},%s}" % (_LETTER[m[1]], m[2].replace("_", r"\_"), m[3])
    return r"\mathrm{%s}" % name.replace("_", r"\_")


_VECTOR = re.compile(r"^(w|al|v|a|r|I)_(.+)_([xyz]{1,2}|(?:xx|yy|zz){2,3})$")
_LETTER = {"w": r"\omega", "al": r"\alpha", "v": "v", "a": "a", "r": "r", "I": "I"}


def named_printer(system, named: Named) -> GacliLatexPrinter:
    names = {q.symbol: tex_name(q.symbol.name) for q in named.quantities if not S.RATE_NAME.match(q.symbol.name)}
    return printer_for(system, {"fold_func_brackets": True, "symbol_names": names})


def named_sections(derivation, named: Named) -> list[Section]:
    printer = named_printer(derivation.system, named)
    quantities = _quantity_groups(named, printer)
    note = ("Each quantity is computed once, in order; $M$ and $F$ below are written through them."
            + (f" First: {tex_text(named.quantities[0].about)}." if named.quantities and named.quantities[0].about else ""))
    kinematic = [expression_rows(printer.doprint(S.rate(q)), e, printer) for q, e in named.rates]
    return [
        Section("Named quantities", note, quantities, shown=True),
        Section("Kinematic equations (eq. 14.20)", "" if kinematic else "Every rate is a speed or named above.",
                kinematic, tag="14.20" if kinematic else ""),
        Section("Gibbs-Appell equations (eq. 14.19)", _equations_note(derivation, printer),
                _equation_groups(derivation, named, printer), tag="14.19"),
    ]


def _quantity_groups(named: Named, printer: GacliLatexPrinter) -> list[list[str]]:
    groups, said = [], named.quantities[0].about if named.quantities else None
    for q in named.quantities:
        group = expression_rows(printer.doprint(q.symbol), q.value, printer)
        if q.about and q.about != said:
            # After the row before it (amsmath: \intertext only follows a \\), so never the first.
            group[0] = rf"\intertext{{{tex_text(q.about)}:}} " + group[0]
        said = q.about
        groups.append(group)
    return groups


def _equation_groups(derivation, named: Named, printer: GacliLatexPrinter) -> list[list[str]]:
    groups = [expression_rows(tex_name(f"M_{r + 1}_{s + 1}"), e, printer) for (r, s), e in named.mass]
    groups += [expression_rows(tex_name(f"F_{r + 1}"), e, printer) for r, e in enumerate(named.forcing)]
    nonzero = {key for key, _ in named.mass}
    for s, u in enumerate(derivation.speed_rates):
        terms = [sp.Symbol(f"M_{min(s, r) + 1}_{max(s, r) + 1}") * a for r, a in enumerate(derivation.speed_rates)
                 if (min(s, r), max(s, r)) in nonzero]
        lhs = sp.Add(*terms)
        symbols = {sp.Symbol(f"M_{a}_{b}"): tex_name(f"M_{a}_{b}") for a in range(1, derivation.k + 1)
                   for b in range(1, derivation.k + 1)}
        row_printer = printer_for(derivation.system, {"symbol_names": {**symbols, sp.Symbol("F"): f"F_{{{s + 1}}}"}})
        groups.append(rows("", grouped(lhs), row_printer, grouped(sp.Symbol("F"))))
    return groups


def _equations_note(derivation, printer: GacliLatexPrinter) -> str:
    rates = ", ".join(printer.doprint(u) for u in derivation.speeds)
    return (rf"$\partial G / \partial \dot{{u}}_s = Q_s$ for $u = ({rates})$, written $M \dot{{u}} = F$ "
            r"($M$ symmetric).")
