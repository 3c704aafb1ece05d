"""What ``gacli steady`` and ``gacli integrals`` print: text, LaTeX or JSON (sorted keys, stable order)."""

from __future__ import annotations

import json

import sympy as sp

from gacli.steady.integrals import Integrals
from gacli.steady.motions import SteadyMotions


def motions_text(result: SteadyMotions, fmt: str, system=None) -> str:
    if fmt == "json":
        return json.dumps(_motions_data(result), indent=2, sort_keys=True)
    if fmt == "latex":
        return _motions_latex(result, _latex(system))
    show = str
    lines = []
    if result.steady_rates:
        lines.append(f"moving at constant rates along every family: {', '.join(result.steady_rates)}")
    for i, family in enumerate(result.families, 1):
        free = f" (free: {', '.join(show(u) for u in family.free)})" if family.free else ""
        lines += ["", f"family {i}{free}"]
        lines += [f"  {show(k)} = {show(v)}" for k, v in family.values]
        lines += [f"  {show(r)} = 0" for r in family.relations]
        lines += [f"  where {show(c)} ≠ 0" for c in family.conditions]
        lines += [f"  ({_UNREAL})"] if family.real is False else []
        lines += [f"  ({_DRIFTING}: {', '.join(family.drifting)})"] if family.drifting else []
    if not result.families:
        lines.append("no steady motion found")
    return "\n".join(lines).lstrip("\n")


def _motions_latex(result: SteadyMotions, show) -> str:
    """Each family as an align* block (amsmath), its free values and conditions in words around it."""
    lines = [f"% moving at constant rates along every family: {', '.join(result.steady_rates)}"]
    for i, family in enumerate(result.families, 1):
        free = ", ".join(show(u) for u in family.free)
        rows = [f"{show(k)} &= {show(v)}" for k, v in family.values] + [f"{show(r)} &= 0" for r in family.relations]
        lines += ["", f"\\paragraph{{Family {i}}}" + (f" Free: ${free}$." if free else ""),
                  "\\begin{align*}", " \\\\\n".join(rows), "\\end{align*}"]
        lines += [f"where ${show(c)} \\neq 0$" for c in family.conditions]
        lines += [f"({_UNREAL}.)"] if family.real is False else []
        lines += [f"({_DRIFTING}: {', '.join(family.drifting)}.)"] if family.drifting else []
    return "\n".join(lines)


def _motions_data(result: SteadyMotions) -> dict:
    return {"ignorable": list(result.ignorable),
            "families": [{"values": {str(k): str(v) for k, v in f.values},
                          "free": [str(u) for u in f.free],
                          "relations": [str(r) for r in f.relations],
                          "conditions_nonzero": [str(c) for c in f.conditions],
                          "real_at_file_values": f.real,
                          "not_at_constant_rates": list(f.drifting)} for f in result.families]}


_DRIFTING = "not at constant rates here, though free of the equations"
_UNREAL = "not real at the file's parameter values: a steady motion of other parameters"


def integrals_text(result: Integrals, fmt: str, system=None) -> str:
    if fmt == "json":
        return json.dumps(_integrals_data(result), indent=2, sort_keys=True)
    if fmt == "latex":
        tex = _latex(system)
        show = lambda e: f"${tex(e)}$"  # noqa: E731  (math in running text)
    else:
        show = str
    lines = [f"{i.name}: {show(i.expression)}   ({_how(i.method)})" for i in result.found]
    if not result.found:
        lines.append("no integral found")
    lines += [f"not an integral: {what}: {why}" for what, why in result.broken]
    for c in result.candidates:
        if c.conserved is False:
            lines.append(f"{c.name}: {show(c.expression)}: not conserved (its rate is not zero at a point)")
        else:
            lines.append(f"{c.name}: {show(c.expression)}: {'conserved' if c.conserved else 'undecided'} "
                         f"({_how(c.method)})")
    return "\n".join(lines)


def _how(method: str) -> str:
    return {"symbolic": "proved symbolically", "numeric": "numeric: checked at seeded random points, not proved",
            }.get(method, "undecided: no point could be evaluated")


def _integrals_data(result: Integrals) -> dict:
    def one(i):
        return {"name": i.name, "expression": str(i.expression), "conserved": i.conserved, "method": i.method}
    return {"integrals": [one(i) for i in result.found],
            "not_integrals": [{"name": w, "why": y} for w, y in result.broken],
            "candidates": [one(c) for c in result.candidates]}


def _latex(system):
    """LaTeX as gacli derive --format latex writes symbols: dot(phi) is \\dot{\\phi}, latex: names kept."""
    from gacli.emit.latex_printer import GacliLatexPrinter, printer_for

    printer = printer_for(system) if system is not None else GacliLatexPrinter()
    return lambda e: printer.doprint(e) if isinstance(e, sp.Basic) else str(e)
