"""The worked solution (``--steps``) in LaTeX: one subsection a step, sentences with their mathematics
in math mode, equations in align*, one tag for a block of equations that the chapter numbers alike."""

from __future__ import annotations

import sympy as sp

from gacli.algebra import symbols as S
from gacli.display.steps import Equation, Formula, Load, Names, Sentence, variation, worked_solution
from gacli.emit.latex_layout import LINE_WIDTH, Section, expression_rows, grouped, rows, typeset_width
from gacli.emit.latex_printer import GacliLatexPrinter, latex_names, printer_for
from gacli.emit.latex_text import tex_text
from gacli.mechanics.equations import Derivation


def step_sections(derivation: Derivation) -> list[Section]:
    """The worked solution: one subsection a step, sentences as text and mathematics, equations in align*."""
    printer = printer_for(derivation.system, {"fold_func_brackets": True, "symbol_names": _step_symbols(derivation)})
    sections = []
    for step in worked_solution(derivation):
        sections += _step_blocks(step, printer)
    return sections


def _step_blocks(step, printer: GacliLatexPrinter) -> list[Section]:
    """Consecutive equations of one number share one align* and its tag; a sentence opens a block."""
    blocks: list[Section] = []
    title, note, groups, tag = tex_text(step.title), "", [], ""
    loads = 0

    def close():
        nonlocal title, note, groups, tag
        if groups or note:
            # Equations of several lines each are set apart, as a book spaces them.
            gap = "[1ex]" if any(len(group) > 1 for group in groups) and len(groups) > 1 else ""
            blocks.append(Section(title, note, groups, gap=gap, tag=tag))
            title, note, groups, tag = "", "", [], ""

    for item in step.items:
        if isinstance(item, Equation):
            if groups and item.label != tag:
                close()
            groups.append(_step_rows(item, printer))
            tag = item.label
            continue
        close()
        if isinstance(item, Load):
            loads += 1
            note, groups = _load(item, loads, printer)
        else:
            note = sentence(item, printer)
    close()
    return blocks


def sentence(item: str | Sentence, printer: GacliLatexPrinter) -> str:
    """Prose as text, its mathematics in ``$…$``."""
    if isinstance(item, str):
        return tex_text(item)
    return "".join(_fragment(part, printer) for part in item.parts)


def _fragment(part, printer: GacliLatexPrinter) -> str:
    if isinstance(part, str):
        # Free text loses its outer spaces (one_line); those between prose and mathematics are kept.
        lead = " " if part[:1].isspace() else ""
        return lead + tex_text(part) + (" " if part[-1:].isspace() and part.strip() else "")
    if isinstance(part, Formula):
        return f"${part.tex}$"
    if isinstance(part, Names):
        if not part.names:
            return "none"
        return "$" + ", ".join(printer.doprint(sp.Symbol(n)) for n in part.names) + "$"
    return f"${printer.doprint(part)}$"


def _step_rows(item: Equation, printer: GacliLatexPrinter) -> list[str]:
    if item.head is not None:  # ∂G/∂u̇_s = Q_s, its left side written out
        label = rf"\frac{{\partial G}}{{\partial {printer.doprint(item.head)}}}"
        return rows(label, grouped(item.lhs), printer, grouped(item.rhs))
    if not isinstance(item.lhs, sp.Symbol):  # a relation: its left side is a sum too
        return rows("", grouped(item.lhs), printer, grouped(item.rhs))
    label = printer.doprint(item.lhs)
    if isinstance(item.rhs, sp.MatrixBase):
        return vector_rows(label, item.rhs, printer)
    return expression_rows(label, item.rhs, printer)


def column(vector: sp.MatrixBase, printer: GacliLatexPrinter) -> str:
    """A column; fractions in it set at the size of the equations around it, not of an index."""
    entries = [printer.doprint(e) for e in vector]
    if any(r"\frac" in e for e in entries):
        return r"\begin{bmatrix} " + r" \\[1ex] ".join(rf"\displaystyle {e}" for e in entries) + r" \end{bmatrix}"
    return r"\begin{bmatrix} " + r" \\ ".join(entries) + r" \end{bmatrix}"


def vector_rows(label: str, vector: sp.MatrixBase, printer: GacliLatexPrinter, frame: str = "") -> list[str]:
    """``label = [column]``, or one row a component when a column would not fit the line."""
    tex = column(vector, printer) + (f"_{{{frame}}}" if frame else "")
    if typeset_width(label) + max(typeset_width(printer.doprint(e)) for e in vector) + 4 <= LINE_WIDTH:
        return [f"{label} &= {tex}"]
    rows = []
    for i, e in enumerate(vector, start=1):
        rows += expression_rows(rf"\left({label}\right)_{{{i}}}", e, printer)
    return rows


def _load(load: Load, number: int, printer: GacliLatexPrinter) -> tuple[str, list[list[str]]]:
    """A sentence that names the load's point or body and frames, and the load as columns."""
    symbol = rf"\mathbf{{{'M' if load.torque else 'F'}}}_{{{number}}}"
    frames = ", ".join(rf"$\mathrm{{{tex_text(frame)}}}$" for frame, _ in load.terms)
    where = rf"\textit{{{tex_text(load.where)}}}" if load.where else "the point at $\\mathbf{r}$"
    kind = "A torque on" if load.torque else ("A force at the point" if load.where else "A force at")
    note = f"{kind} {where}, its components along the axes of {'frame' if len(load.terms) == 1 else 'frames'} {frames}:"
    rows = []
    for i, (frame, vector) in enumerate(load.terms):
        name = rf"\mathrm{{{tex_text(frame)}}}"
        if i == 0:
            rows += vector_rows(symbol, vector, printer, name)
        else:  # a load written as a sum of vectors in several frames
            rows.append(rf"&\quad + {column(vector, printer)}_{{{name}}}")
    groups = [rows]
    if load.position is not None:
        groups.append(vector_rows(r"\mathbf{r}", load.position, printer, r"\mathrm{N}"))
    return note, groups


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
