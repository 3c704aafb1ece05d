"""The worked solution (``--steps``) in LaTeX: one subsection a step, prose as text, equations in align*."""

from __future__ import annotations

import sympy as sp

from gacli.algebra import symbols as S
from gacli.emit.latex_layout import ZERO, Section, signed_terms, sum_rows
from gacli.emit.latex_printer import GacliLatexPrinter, latex_names, printer_for
from gacli.emit.latex_text import tex_text
from gacli.mechanics.equations import Derivation
from gacli.display.steps import variation, worked_solution


def step_sections(derivation: Derivation) -> list[Section]:
    """The worked solution: one subsection a step, prose as text, equations in align*."""
    printer = printer_for(derivation.system, {"fold_func_brackets": True, "symbol_names": _step_symbols(derivation)})
    sections = []
    for step in worked_solution(derivation):
        sections += _step_blocks(step, printer)
    return sections


def _step_blocks(step, printer: GacliLatexPrinter) -> list[Section]:
    """Consecutive equations share one align*; each prose line opens a block."""
    blocks: list[Section] = []
    title, note, groups = tex_text(step.title), "", []
    for item in step.items:
        if isinstance(item, str):
            if groups or note:
                blocks.append(Section(title, note, groups))
                title, groups = "", []
            note = tex_text(item)
        else:
            groups.append(_step_rows(item, printer))
    blocks.append(Section(title, note, groups))
    return blocks


def _step_rows(item, printer: GacliLatexPrinter) -> list[str]:
    label = printer.doprint(item.lhs)
    if isinstance(item.rhs, sp.MatrixBase):
        rows = [f"{label} &= {printer.doprint(item.rhs)}"]
    else:
        rows = sum_rows(label, signed_terms(item.rhs, printer) or ZERO)
    if item.label:
        rows[-1] += rf" \tag*{{({item.label})}}"
    return rows


def _step_symbols(derivation: Derivation) -> dict[sp.Symbol, str]:
    """LaTeX of the worked solution's own symbols: δq, Q_s, body accelerations, δW."""
    base = GacliLatexPrinter(latex_names(derivation.system))
    names: dict[sp.Symbol, str] = {sp.Symbol("δW"): r"\delta W", sp.Symbol("δW_work"): r"\delta W"}
    for name in derivation.rates.names:
        tex = base.doprint(S.value(name))
        names[variation(name)] = rf"\delta {tex}"
        names[sp.Symbol(f"Q_{name}")] = rf"Q_{{{tex}}}"
    for motion in derivation.motions:
        label = rf"\mathrm{{{tex_text(motion.body.name)}}}"
        names[sp.Symbol(f"a_{motion.body.name}")] = rf"\mathbf{{a}}_{{{label}}}"
        names[sp.Symbol(f"alpha_{motion.body.name}")] = rf"\boldsymbol{{\alpha}}_{{{label}}}"
    return names
