"""The layout of equations in ``align*``: signed terms, filled into lines of about LINE_WIDTH.

A :class:`Section` is a titled block of equations; each equation is a list
of rows ``label &= ...`` broken where the typeset width (estimated by
:func:`typeset_width`) passes LINE_WIDTH, and a term too wide for a line is
written expanded so that it can break.
"""

from __future__ import annotations

import functools
import re
import sys
from typing import NamedTuple

import sympy as sp

from gacli.emit.latex_printer import GacliLatexPrinter
from gacli.algebra.readable import Tidy

# Rough printed width (in characters of typeset maths) before a sum is broken.
LINE_WIDTH = 44
# A single term wider than this is written expanded, term by term (a line cannot break inside it).
WIDE = LINE_WIDTH + 8


class Section(NamedTuple):
    """A titled block: a note (text) and equations, set in one align*."""

    title: str
    note: str
    groups: list[list[str]]  # the align* rows of each equation
    gap: str = ""  # extra space between equations, e.g. "[1ex]"
    shown: bool = False  # in a fragment, the note as text too, not only as a comment


def align(section: Section) -> list[str]:
    rows = (" \\\\\n".join(group) for group in section.groups)
    return [r"\begin{align*}", f" \\\\{section.gap}\n".join(rows), r"\end{align*}"]


Term = tuple[bool, str]  # (negative, LaTeX of the magnitude)
ZERO: list[Term] = [(False, "0")]


@functools.lru_cache(maxsize=1024)  # G and the equations read the same coefficients
def tidy(expr: sp.Expr) -> sp.Expr:
    """The display simplifier that text uses too (:func:`gacli.algebra.readable.readable`), within its size bounds."""
    return Tidy(budget=sys.maxsize)(expr)


def signed_terms(expr: sp.Expr, printer: GacliLatexPrinter, wide: int = WIDE) -> list[Term]:
    """The terms of a sum in the printer's order, each with its sign pulled out; [] for 0.
    A term wider than ``wide`` is written expanded."""
    if expr == 0:
        return []
    terms = printer._as_ordered_terms(expr, order=None) if expr.is_Add else [expr]
    out = []
    for term in terms:
        negative = term.could_extract_minus_sign()
        tex = printer._print(-term if negative else term)
        if typeset_width(tex) > wide and (spread := sp.expand(term)).is_Add:
            # A factored term wider than a line cannot break; its expansion can.
            out += signed_terms(spread, printer, wide)
        else:
            out.append((negative, tex))
    return out


def product_term(coefficient: sp.Expr, monomial: sp.Expr, printer: GacliLatexPrinter) -> Term | None:
    """coefficient · monomial, the coefficient first and bracketed when it is a sum; None if zero."""
    if coefficient == 0:
        return None
    negative = coefficient.could_extract_minus_sign()
    if negative:
        coefficient = -coefficient
    tail = printer._print(monomial)
    if coefficient == 1:
        return negative, tail
    head = printer._print(coefficient)
    if coefficient.is_Add:
        head = rf"\left({head}\right)"
    return negative, f"{head} {tail}" if coefficient.is_Number else f"{head} \\, {tail}"


def half_term(coefficient: sp.Expr, monomial: sp.Expr, printer: GacliLatexPrinter) -> Term | None:
    """½ · coefficient · monomial: ½ folded into a product, written in front of a sum."""
    if not coefficient.is_Add:
        return product_term(coefficient / 2, monomial, printer)
    term = product_term(coefficient, monomial, printer)
    return term and (term[0], r"\frac{1}{2} " + term[1])


def sum_rows(label: str, terms: list[Term], rhs: list[Term] | None = None) -> list[str]:
    """align* rows for ``label = terms [= rhs]``, broken after about LINE_WIDTH."""
    lines = _fill(terms)
    if rhs is not None:
        right = _fill(rhs)
        if len(lines) == 1 and len(right) == 1 and typeset_width(lines[0] + right[0]) <= LINE_WIDTH:
            lines[0] += " = " + right[0]
        else:
            lines += ["= " + right[0]] + right[1:]
            return _rows(label, lines, equals_at=len(lines) - len(right))
    return _rows(label, lines)


def _rows(label: str, lines: list[str], equals_at: int | None = None) -> list[str]:
    rows = [f"{label} &= {lines[0]}"]
    for i, line in enumerate(lines[1:], start=1):
        rows.append(f"&{line}" if i == equals_at else rf"&\quad {line}")
    return rows


def _fill(terms: list[Term]) -> list[str]:
    """Join signed terms into lines; a new line starts with its sign."""
    lines: list[str] = []
    current, width = "", 0
    for negative, tex in terms:
        w = typeset_width(tex)
        if current and width + w > LINE_WIDTH:
            lines.append(current)
            current, width = "", 0
        sign = "-" if negative else "+"
        if current:
            current += f" {sign} {tex}"
        else:
            current = f"{sign} {tex}" if (lines or negative) else tex
        width += w + 2
    lines.append(current)
    return lines


_ZERO_WIDTH = re.compile(r"\\(left|right|dot|ddot|dddot|ddddot|bar|hat|tilde|vec|mathrm|operatorname)\b")
_COMMAND = re.compile(r"\\[A-Za-z]+")
_FRAC = r"\frac{"


def typeset_width(tex: str) -> int:
    """A rough typeset width: one per symbol, nothing for braces and accents; a fraction is its wider part."""
    start = tex.find(_FRAC)
    if start >= 0:
        numerator, middle = _group(tex, start + len(_FRAC) - 1)
        denominator, end = _group(tex, middle)
        return typeset_width(tex[:start]) + max(typeset_width(numerator), typeset_width(denominator)) + typeset_width(tex[end:])
    tex = _ZERO_WIDTH.sub("", tex)
    tex = _COMMAND.sub(lambda m: "xxx" if m[0] in (r"\sin", r"\cos", r"\tan", r"\log") else "x", tex)
    return len(re.sub(r"[\s{}_^]", "", tex))


def _group(tex: str, start: int) -> tuple[str, int]:
    """The braced group opening at tex[start] (its inside) and the index after it."""
    depth = 0
    for i in range(start, len(tex)):
        depth += {"{": 1, "}": -1}.get(tex[i], 0)
        if depth == 0:
            return tex[start + 1:i], i + 1
    return tex[start + 1:], len(tex)
