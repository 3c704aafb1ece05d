"""The layout of equations in ``align*``: terms grouped and broken as a typesetter breaks them.

An equation's side is a list of :class:`Part` (a coefficient and the monomial
it multiplies): the terms of a sum grouped by the products of accelerations
they multiply, then by the products of rates (:func:`grouped`), each printed
coefficient first. Parts are filled into lines of about LINE_WIDTH (the typeset
width estimated by :func:`typeset_width`); a part too wide for a line is broken
inside its widest sum, which is set in ``\\Bigl( … \\Bigr)`` over several lines,
its other factors in front. Nothing is multiplied out to find a break: the
printed form is the form given (docs/latex.md).
"""

from __future__ import annotations

import re
from typing import NamedTuple

import sympy as sp

from gacli.algebra.readable import oriented, positive_first
from gacli.algebra.terms import factor_terms
from gacli.emit.latex_printer import GacliLatexPrinter, split_rate

# Typeset width of a row (in characters of typeset maths: about 6.5 pt each in 10 pt
# Computer Modern, so 50 fill the 345 pt of an article's line with room for a tag).
LINE_WIDTH = 50
# What a nested line gives up to the \quad that marks it as a continuation.
INDENT = 2


class Section(NamedTuple):
    """A titled block: a note (text) and equations, set in one align* with one tag at most."""

    title: str
    note: str
    groups: list[list[str]]  # the align* rows of each equation
    gap: str = ""  # extra space between equations, e.g. "[1ex]"
    shown: bool = False  # in a fragment, the note as text too, not only as a comment
    tag: str = ""  # the chapter's number for the whole block, e.g. "14.19"


def align(section: Section) -> list[str]:
    groups = [list(group) for group in section.groups]
    if section.tag and groups:
        groups[-1][-1] += rf" \tag*{{({section.tag})}}"
    rows = (" \\\\\n".join(group) for group in groups)
    return [r"\begin{align*}", f" \\\\{section.gap}\n".join(rows), r"\end{align*}"]


class Part(NamedTuple):
    """coefficient · monomial, printed in that order; the monomial is 1 for a term not grouped."""

    coefficient: sp.Expr
    monomial: sp.Expr = sp.S.One


def _order(symbol: sp.Symbol) -> int:
    """2 for an acceleration; 1 for a rate or a virtual displacement δq (δW is grouped by them); else 0."""
    if not isinstance(symbol, sp.Symbol):
        return 0
    if symbol.name.startswith("δ"):
        return 1
    return split_rate(symbol.name)[0]


def _is_monomial_in(expr: sp.Expr, symbols: set) -> bool:
    for factor in sp.Mul.make_args(expr):
        base, exp = factor.as_base_exp()
        if base not in symbols or not (exp.is_Integer and exp > 0):
            return False
    return True


def grouped(expr: sp.Expr) -> list[Part]:
    """The terms of ``expr`` grouped by the products of accelerations they multiply, then the
    rest by the products of rates, as a textbook groups them: quadratic before linear, the
    declared order within a degree, the part free of both last. Terms whose accelerations or
    rates are not a plain monomial (a square of a sum) stand alone, as given."""
    if expr == 0:
        return []
    symbols = sorted(expr.free_symbols, key=sp.default_sort_key)
    accelerations = {s for s in symbols if _order(s) == 2}
    rates = {s for s in symbols if _order(s) == 1}
    groups: dict[tuple, list[sp.Expr]] = {}
    for term in sp.Add.make_args(expr):
        key, coefficient = _key(term, accelerations, rates)
        groups.setdefault(key, []).append(coefficient)
    parts, kinds = [], []
    for key in sorted(groups, key=lambda k: k[:2]):
        coefficients = groups[key]
        if key[0] >= 2:
            parts += [Part(term) for term in coefficients]
            kinds += [key[0]] * len(coefficients)
            continue
        coefficient = sp.Add(*coefficients)
        if len(coefficients) > 1:
            coefficient = factor_terms(coefficient)
        if coefficient != 0:
            parts.append(Part(coefficient, key[2]))
            kinds.append(key[0])
    return _positive_first(parts, kinds)


def _positive_first(parts: list[Part], kinds: list[int]) -> list[Part]:
    """A positive group of the leading kind moved to the front, as a sum is begun by hand."""
    if not parts or not signed(parts[0])[0]:
        return parts
    for i, (part, kind) in enumerate(zip(parts, kinds)):
        if kind != kinds[0]:
            break
        if not signed(part)[0]:
            return [part] + parts[:i] + parts[i + 1:]
    return parts


def _key(term: sp.Expr, accelerations: set, rates: set) -> tuple[tuple, sp.Expr]:
    """((kind, rank, monomial), coefficient): kind 0 accelerations, 1 rates, 2 neither, 3 not a monomial."""
    for kind, symbols in ((0, accelerations), (1, rates)):
        if not symbols:
            continue
        coefficient, monomial = term.as_independent(*symbols, as_Add=False)
        if monomial == 1:
            continue
        if not _is_monomial_in(monomial, symbols):
            return (3, (), term), term
        return (kind, _rank(monomial), monomial), coefficient
    return (2, (), sp.S.One), term


def _rank(monomial: sp.Expr) -> tuple:
    """Higher degree first, then by the symbols' names (ẍ² before ẍÿ before ẍ)."""
    powers = monomial.as_powers_dict()
    degree = sum(int(e) for e in powers.values())
    return (-degree, tuple((sp.default_sort_key(s), -int(e)) for s, e in sorted(powers.items(), key=lambda p: sp.default_sort_key(p[0]))))


# -- printing a part -------------------------------------------------------------

def signed(part: Part) -> tuple[bool, Part]:
    """The part with its sign pulled out of the coefficient (and differences oriented)."""
    negative, coefficient = oriented(part.coefficient)
    if negative and part.monomial == 1 and coefficient.is_Add:
        # A sum standing alone is printed unbracketed (part_tex): its minus pulled out before it would
        # apply to its first term only (−(g m + k z) printed as − g m + k z). It keeps its own signs.
        return False, Part(-coefficient, 1)
    return negative, Part(coefficient, part.monomial)


def part_tex(part: Part, printer: GacliLatexPrinter) -> str:
    """coefficient · monomial, the coefficient bracketed when it is a sum."""
    coefficient, monomial = part
    if monomial == 1:
        return printer.doprint(coefficient)
    tail = printer.doprint(monomial)
    if coefficient == 1:
        return tail
    head = printer.doprint(coefficient)
    if coefficient.is_Add:
        head = rf"\left({head}\right)"
    return f"{head} {tail}" if coefficient.is_Number else f"{head} \\, {tail}"


def rows(label: str, parts: list[Part], printer: GacliLatexPrinter, rhs: list[Part] | None = None,
         width: int = LINE_WIDTH) -> list[str]:
    """align* rows of ``label = parts [= rhs]``, filled into lines of ``width`` and broken where they must be."""
    room = max(width - typeset_width(label) - 2, width // 2)
    lines = fill(parts, printer, room - INDENT, room) if parts else ["0"]
    if rhs is None:
        return _rows(label, lines)
    right = fill(rhs, printer, room - INDENT, room) if rhs else ["0"]
    if len(lines) == 1 and len(right) == 1 and typeset_width(lines[0] + right[0]) + 2 <= room:
        if not label:
            return [f"&{lines[0]} = {right[0]}"]
        return _rows(label, [lines[0] + " = " + right[0]])
    if len(right) == 1 and typeset_width(lines[-1] + right[0]) + 2 <= room - INDENT:
        return _rows(label, lines[:-1] + [f"{lines[-1]} = {right[0]}"])  # a short right side ends the last line
    return _rows(label, lines + ["= " + right[0]] + right[1:], equals_at=len(lines))


def expression_rows(label: str, expr: sp.Expr, printer: GacliLatexPrinter, width: int = LINE_WIDTH) -> list[str]:
    """``label = expr``, grouped by accelerations and rates (:func:`grouped`)."""
    return rows(label, grouped(expr), printer, width=width)


def _rows(label: str, lines: list[str], equals_at: int | None = None) -> list[str]:
    if not label:  # a relation, lhs = rhs, set flush left, so that a broken one aligns with the others
        out = [f"&{lines[0]}"]
        for i, line in enumerate(lines[1:], start=1):
            if i == equals_at and typeset_width(out[-1] + line) <= LINE_WIDTH:
                out[-1] += f" {line}"
            else:
                out.append(f"&{line}" if i == equals_at else rf"&\quad {line}")
        return out
    out = [f"{label} &= {lines[0]}"]
    for i, line in enumerate(lines[1:], start=1):
        out.append(f"&{line}" if i == equals_at else rf"&\quad {line}")
    return out


def fill(parts: list[Part], printer: GacliLatexPrinter, room: int, first_room: int | None = None) -> list[str]:
    """Signed parts joined into lines of at most ``room``; a part wider than a line is broken."""
    lines: list[str] = []
    current, used = "", 0
    limit = room if first_room is None else first_room
    for part in parts:
        negative, part = signed(part)
        sign = "-" if negative else "+"
        tex = part_tex(part, printer)
        w = typeset_width(tex) + 2
        if current and used + w > limit:
            lines.append(current)
            current, used, limit = "", 0, room
        if w <= limit or not (pieces := broken(part, printer, limit - 2)):
            current = _joined(current, sign, tex, lead=not lines and not current)
            used += w
            continue
        head = _joined(current, sign, pieces[0], lead=not lines and not current)
        lines += [head] + pieces[1:-1]
        current, used, limit = pieces[-1], typeset_width(pieces[-1]), room
    lines.append(current)
    return lines


def _joined(current: str, sign: str, tex: str, lead: bool) -> str:
    if current:
        return f"{current} {sign} {tex}"
    return tex if lead and sign == "+" else f"{sign} {tex}"


def broken(part: Part, printer: GacliLatexPrinter, room: int) -> list[str] | None:
    """The part over several lines: its plain factors in front, then each sum factor in brackets, a sum
    too wide for the line broken inside them; None when it has no sum to break."""
    coefficient, monomial = part
    factors = list(sp.Mul.make_args(coefficient))
    # A sum in a denominator is broken only when it is too wide to stand under a fraction bar.
    sums = [f for f in factors if _sum_of(f) is not None
            and (_sum_of(f)[1] > 0 or typeset_width(printer.doprint(_sum_of(f)[0])) > room // 2)]
    if not sums:
        return None
    plain = sp.Mul(*[f for f in factors if f not in sums])
    lines = ["" if plain == 1 else printer.doprint(plain)]
    for factor in sums:
        base, exponent = _sum_of(factor)
        power = "" if exponent == 1 else f"^{{{printer.doprint(exponent)}}}"
        tex = rf"\left({printer.doprint(base)}\right){power}"
        free = room - typeset_width(lines[-1]) - 1
        if typeset_width(tex) <= free:
            lines[-1] = f"{lines[-1]} {tex}".lstrip()
            continue
        if typeset_width(tex) <= room - INDENT:
            lines.append(rf"\quad \times {tex}")
            continue
        if free < room // 3:  # too little left on this line to open the bracket here
            lines.append(r"\quad \times")
            free = room - INDENT - 4
        inner = fill(ordered_parts(base, printer), printer, room - INDENT, first_room=free - 2)
        lines[-1] = f"{lines[-1]} \\{_size(inner)}l( {inner[0]}".lstrip()
        lines += [rf"\quad {line}" for line in inner[1:]]
        lines[-1] += rf" \{_size(inner)}r){power}"
    if monomial != 1:
        tail = printer.doprint(monomial)
        if typeset_width(lines[-1]) + typeset_width(tail) + 1 <= room:
            lines[-1] += " \\, " + tail
        else:
            lines.append(rf"\quad \times {tail}")
    return lines


def _size(lines: list[str]) -> str:
    """The size of brackets around these lines: above the brackets and fractions inside them."""
    if any(r"\Bigl" in line or r"\biggl" in line for line in lines):
        return "bigg"
    if any(r"\frac" in line or r"\bigl" in line or r"\left" in line for line in lines):
        return "Big"
    return "big"


def _sum_of(factor: sp.Expr) -> tuple[sp.Expr, sp.Expr] | None:
    """(the sum, its integer power) of a factor that is a sum or a power of one (a negative one: a denominator)."""
    if factor.is_Add:
        return factor, sp.S.One
    base, exponent = factor.as_base_exp()
    if base.is_Add and exponent.is_Integer and exponent != 0:
        return base, exponent
    return None


def ordered_parts(expr: sp.Expr, printer: GacliLatexPrinter) -> list[Part]:
    """The terms of a sum inside brackets, in the printer's order with a positive term first."""
    return [Part(t) for t in positive_first(printer._as_ordered_terms(expr, order=None))]


# -- typeset width ---------------------------------------------------------------

_ZERO_WIDTH = re.compile(r"\\(left|right|dot|ddot|dddot|ddddot|bar|hat|tilde|vec|mathrm|mathbf|boldsymbol|operatorname"
                         r"|[Bb]igg?l|[Bb]igg?r|quad|qquad|tag\*?)\b")
_COMMAND = re.compile(r"\\[A-Za-z]+")
_WIDE_COMMANDS = frozenset((r"\sin", r"\cos", r"\tan", r"\log", r"\operatorname"))
_FRAC = r"\frac{"


def typeset_width(tex: str) -> int:
    """A rough typeset width: one per symbol, nothing for braces and accents; a fraction is its wider part."""
    start = tex.find(_FRAC)
    if start >= 0:
        numerator, middle = _group(tex, start + len(_FRAC) - 1)
        denominator, end = _group(tex, middle)
        return typeset_width(tex[:start]) + max(typeset_width(numerator), typeset_width(denominator)) + typeset_width(tex[end:])
    # An upright word is as wide as its letters; a thin space is a third of a letter.
    tex = tex.replace(r"\,", "").replace(r"\!", "")
    tex = _ZERO_WIDTH.sub("", tex)
    tex = _COMMAND.sub(lambda m: "xxx" if m[0] in _WIDE_COMMANDS else "x", tex)
    return len(re.sub(r"[\s{}_^&]", "", tex))


def _group(tex: str, start: int) -> tuple[str, int]:
    """The braced group opening at tex[start] (its inside) and the index after it."""
    depth = 0
    for i in range(start, len(tex)):
        depth += {"{": 1, "}": -1}.get(tex[i], 0)
        if depth == 0:
            return tex[start + 1:i], i + 1
    return tex[start + 1:], len(tex)
