"""LaTeX (amsmath) rendering of a derivation: G, Q, eqs. (14.19) and (14.20).

:class:`GacliLatexPrinter` prints gacli's plain symbols (``x``, ``dot(x)``,
``ddot(x)``, ``d3(x)``) as :math:`x, \\dot{x}, \\ddot{x}, \\dddot{x}`, with the
``latex:`` names of the system file. :func:`emit_latex` returns the source
text as data, ``{"<name>.tex": text}``; nothing here writes files.

Every coefficient is simplified for reading only (a copy, on a small budget);
the derivation itself is never changed.
"""

from __future__ import annotations

import os
import re
import sys
import textwrap
import unicodedata
from collections.abc import Mapping
from typing import NamedTuple

import sympy as sp
from sympy.printing.latex import LatexPrinter

from gacli import symbols as S
from gacli.equations import Derivation
from gacli.gibbs import gibbs_coefficients
from gacli.graph import is_small
from gacli.model import System
from gacli.readable import TOO_LARGE, Tidy, displayable
from gacli.read.texsafe import is_printable_name
from gacli.version import __version__

# Rough printed width (in characters of typeset maths) before a sum is broken.
LINE_WIDTH = 44
# A single term wider than this is written expanded, term by term (a line cannot break inside it).
WIDE = LINE_WIDTH + 8
_LABEL = 4  # the room a label ∂G/∂ü takes from the lines of an equation, beyond that of G
# Characters of free text (a title, a source) on one line of the .tex file.
TEXT_LINE = 240

_RATE = re.compile(r"^(dot|ddot|d(\d+))\((.+)\)$")
_DIFFERENTIAL = re.compile(r"^d\[(.+)\]$")
_DOTS = {1: r"\dot", 2: r"\ddot", 3: r"\dddot", 4: r"\ddddot"}


def split_rate(name: str) -> tuple[int, str]:
    """``'ddot(x)'`` → ``(2, 'x')``; ``'d3(x)'`` → ``(3, 'x')``; ``'x'`` → ``(0, 'x')``."""
    match = _RATE.match(name)
    if match is None:
        return 0, name
    if match[2] is not None:
        return int(match[2]), match[3]
    return (1 if match[1] == "dot" else 2), match[3]


def latex_names(system: System) -> dict[str, str]:
    """Name → LaTeX for every declared name with a ``latex:`` override."""
    groups = (system.parameters, system.functions, system.inputs, system.coordinates, system.quasi_coordinates)
    return {item.name: item.latex for group in groups for item in group if item.latex}


def upright_name(name: str) -> str:
    """A name as upright text, for names SymPy would print as something the document cannot set:
    ``beth`` (\\beth needs amssymb), ``xscr`` (\\mathscr), ``_K`` (a bare subscript), ``__x``
    (a double subscript)."""
    return r"\mathrm{%s}" % name.replace("_", r"\_")


def _is_word(head: str) -> bool:
    """A head of several plain letters (``yaw``, ``lean``), which SymPy prints as italic letters."""
    return len(head) > 1 and head.isascii() and head.isalpha()


def has_words(system: System) -> bool:
    """Whether some declared name prints as an upright word, so products need a visible separation."""
    printer = GacliLatexPrinter(latex_names(system))
    groups = (system.parameters, system.functions, system.inputs, system.coordinates, system.quasi_coordinates)
    return any(printer.doprint(sp.Symbol(item.name)).startswith(r"\mathrm{") for group in groups for item in group)


def printer_for(system: System, settings: dict | None = None) -> "GacliLatexPrinter":
    """The printer of a system's names; factors are set apart by a thin space when a name is a word."""
    settings = dict(settings or {})
    if has_words(system):
        settings.setdefault("mul_symbol", r"\,")
    return GacliLatexPrinter(latex_names(system), settings)


class GacliLatexPrinter(LatexPrinter):
    """SymPy's LaTeX printer for gacli's symbols.

    Args:
        names: LaTeX for base names (``latex:`` overrides); the others print
            as SymPy prints a plain symbol (``theta`` → ``\\theta``,
            ``q_x`` → ``q_{x}``). Rates decorate the base: ``dot(q_x)`` →
            ``\\dot{q}_{x}``.
        settings: LatexPrinter settings.

    >>> p = GacliLatexPrinter({"I": r"\\bar{I}"})
    >>> p.doprint(sp.Symbol("ddot(theta)")), p.doprint(sp.Symbol("dot(I)"))
    ('\\\\ddot{\\\\theta}', '\\\\dot{\\\\bar{I}}')
    """

    def __init__(self, names: Mapping[str, str] | None = None, settings: dict | None = None):
        super().__init__(settings)
        self._names = dict(names or {})

    def _print_Symbol(self, expr: sp.Symbol, style: str = "plain") -> str:
        if expr in self._settings["symbol_names"]:
            return self._settings["symbol_names"][expr]
        differential = _DIFFERENTIAL.match(expr.name)
        if differential:
            return r"\mathrm{d}" + self._decorated(differential[1], 0)
        order, base = split_rate(expr.name)
        return self._decorated(base, order)

    def _decorated(self, base: str, order: int) -> str:
        """The base name's LaTeX with ``order`` dots over its head, not over its subscripts."""
        if base in self._names:
            head, tail = self._names[base], ""
        else:
            head, supers, subs = self._split_super_sub(base)
            tail = ("^{%s}" % " ".join(supers) if supers else "") + ("_{%s}" % " ".join(subs) if subs else "")
            if base.startswith("_") or base.endswith("_") or not is_printable_name(head + tail):
                head, tail = upright_name(base), ""
            elif _is_word(head):
                head = r"\mathrm{%s}" % head  # yaw is one name, not y·a·w
        if order == 0:
            return head + tail
        if order in _DOTS:
            return f"{_DOTS[order]}{{{head}}}{tail}"
        return f"{{{head}}}^{{({order})}}{tail}"

    def _print_atan2(self, expr: sp.Expr, exp: str | None = None) -> str:
        args = ", ".join(self._print(a) for a in expr.args)
        tex = rf"\operatorname{{atan2}}\left({args}\right)"
        return f"{tex}^{{{exp}}}" if exp else tex


def emit_latex(derivation: Derivation, *, standalone: bool = False, steps: bool = False) -> dict[str, str]:
    r"""The derivation as amsmath source: ``{"<system name>.tex": text}``.

    Args:
        derivation: the result of :func:`gacli.equations.derive`.
        standalone: wrap the blocks in a complete ``article`` document.
        steps: the worked solution of :mod:`gacli.steps` instead of the results.

    >>> from gacli.equations import derive
    >>> from gacli.loading import loads
    >>> d = derive(loads("gacli: 1\nname: falling\nparameters: [m, g]\ncoordinates: [z]\n"
    ...                  "bodies: {ball: {mass: m, position: [0, 0, z]}}\npotential: m*g*z\n"))
    >>> text = emit_latex(d)["falling.tex"]
    >>> print(next(line for line in text.splitlines() if line.startswith(r"\frac")))
    \frac{\partial G}{\partial \ddot{z}} &= m \, \ddot{z} = - g m
    """
    system = derivation.system
    printer = printer_for(system, {"fold_func_brackets": True})
    if not displayable(derivation):
        # Shown in a fragment too: an \input of the file would otherwise show nothing at all.
        sections = [_Section("Equations", _text(TOO_LARGE), [], shown=True)]
    elif steps:
        sections = _step_sections(derivation)
    else:
        sections = [
            _Section("Gibbs function (eq. 14.21)", _GIBBS_NOTE, [_gibbs_rows(derivation, printer)]),
            _Section("Generalized forces (eq. 14.13)", "", _force_rows(derivation, printer)),
            _Section("Gibbs-Appell equations (eq. 14.19)", _equations_note(derivation, printer),
                     _equation_rows(derivation, printer), gap="[1ex]"),
            _kinematic_section(derivation, printer),
        ]
    lines = _header(system)
    lines += _document(system, sections) if standalone else _fragment(sections)
    return {f"{system.name}.tex": "\n".join(lines) + "\n"}


# -- document structure ------------------------------------------------------

def _header(system: System) -> list[str]:
    lines = [
        f"% Gibbs-Appell equations of '{system.name}', generated by gacli {__version__}.",
        f"% System file: {_one_line(os.path.basename(system.path))}",
        f"% SHA-256: {system.sha256}",
    ]
    if system.title:
        lines += _comment("Title", system.title)
    if system.reference:
        lines += _comment("Source", system.reference)
    return lines + ["% Requires the amsmath package."]


def _comment(label: str, text: str) -> list[str]:
    """``% label: text`` in lines of about TEXT_LINE characters (as _wrap, for the same reason)."""
    chunks = textwrap.wrap(_one_line(text), TEXT_LINE, break_long_words=True, break_on_hyphens=False)
    return [f"% {label}: {chunks[0]}"] + [f"%   {chunk}" for chunk in chunks[1:]] if chunks else []


def _fragment(sections) -> list[str]:
    lines: list[str] = []
    for section in sections:
        comment = section.title + (f". {section.note}" if section.note else "")
        # Free text comes in lines (see _wrap): each must stay a comment.
        lines += [""] + [f"% {line}" for line in comment.split("\n")]
        lines += [r"\noindent " + section.note] if section.shown else []
        lines += _align(section) if section.groups else []
    return lines


def _document(system: System, sections) -> list[str]:
    source = f"Source: {_text(system.reference)}.\\\\\n" if system.reference else ""
    lines = [
        r"\documentclass{article}",
        r"\usepackage{amsmath}",
        r"\begin{document}",
        "",
        r"\begin{center}",
        rf"\Large\bfseries {_text(system.title or system.name)}",
        r"\end{center}",
        r"\noindent " + source
        + rf"Derived by gacli {__version__} from \texttt{{{_text(os.path.basename(system.path))}}}.",
    ]
    for section in sections:
        lines += ["", rf"\subsection*{{{section.title}}}"] if section.title else [""]
        if section.note:
            lines.append(r"\noindent " + section.note)
        lines += _align(section) if section.groups else []
    return lines + ["", r"\end{document}"]


def _step_sections(derivation: Derivation) -> list[_Section]:
    """The worked solution: one subsection a step, prose as text, equations in align*."""
    from gacli.steps import worked_solution

    printer = printer_for(derivation.system, {"fold_func_brackets": True, "symbol_names": _step_symbols(derivation)})
    sections = []
    for step in worked_solution(derivation):
        sections += _step_blocks(step, printer)
    return sections


def _step_blocks(step, printer: GacliLatexPrinter) -> list[_Section]:
    """Consecutive equations share one align*; each prose line opens a block."""
    blocks: list[_Section] = []
    title, note, groups = _text(step.title), "", []
    for item in step.items:
        if isinstance(item, str):
            if groups or note:
                blocks.append(_Section(title, note, groups))
                title, groups = "", []
            note = _text(item)
        else:
            groups.append(_step_rows(item, printer))
    blocks.append(_Section(title, note, groups))
    return blocks


def _step_rows(item, printer: GacliLatexPrinter) -> list[str]:
    label = printer.doprint(item.lhs)
    if isinstance(item.rhs, sp.MatrixBase):
        rows = [f"{label} &= {printer.doprint(item.rhs)}"]
    else:
        rows = _sum_rows(label, _terms(item.rhs, printer) or _ZERO)
    if item.label:
        rows[-1] += rf" \tag*{{({item.label})}}"
    return rows


def _step_symbols(derivation: Derivation) -> dict[sp.Symbol, str]:
    """LaTeX of the worked solution's own symbols: δq, Q_s, body accelerations, δW."""
    from gacli.steps import variation

    base = GacliLatexPrinter(latex_names(derivation.system))
    names: dict[sp.Symbol, str] = {sp.Symbol("δW"): r"\delta W", sp.Symbol("δW_work"): r"\delta W"}
    for name in derivation.rates.names:
        tex = base.doprint(S.value(name))
        names[variation(name)] = rf"\delta {tex}"
        names[sp.Symbol(f"Q_{name}")] = rf"Q_{{{tex}}}"
    for motion in derivation.motions:
        label = rf"\mathrm{{{_text(motion.body.name)}}}"
        names[sp.Symbol(f"a_{motion.body.name}")] = rf"\mathbf{{a}}_{{{label}}}"
        names[sp.Symbol(f"alpha_{motion.body.name}")] = rf"\boldsymbol{{\alpha}}_{{{label}}}"
    return names


class _Section(NamedTuple):
    title: str
    note: str
    groups: list[list[str]]  # the align* rows of each equation
    gap: str = ""  # extra space between equations, e.g. "[1ex]"
    shown: bool = False  # in a fragment, the note as text too, not only as a comment


def _align(section: _Section) -> list[str]:
    rows = (" \\\\\n".join(group) for group in section.groups)
    return [r"\begin{align*}", f" \\\\{section.gap}\n".join(rows), r"\end{align*}"]


_GIBBS_NOTE = r"Terms free of the accelerations are dropped ($\dots$)."


def _equations_note(derivation: Derivation, printer: GacliLatexPrinter) -> str:
    rates = ", ".join(printer.doprint(u) for u in derivation.speeds)
    return rf"$\partial G / \partial \dot{{u}}_s = Q_s$ for the independent rates $u = ({rates})$."


# -- the blocks --------------------------------------------------------------

def _gibbs_rows(derivation: Derivation, printer: GacliLatexPrinter) -> list[str]:
    """G = ½ Σ H_ij ü_i ü_j + Σ g_i ü_i + … grouped by the accelerations."""
    H, g = gibbs_coefficients(derivation.gibbs, derivation.rates)
    a = derivation.speed_rates
    k = len(a)
    terms = [t for i in range(k) if (t := _half_term(tidy(H[i, i]), a[i] ** 2, printer))]
    pairs = [(H[i, j], a[i] * a[j]) for i in range(k) for j in range(i + 1, k)] + list(zip(g, a))
    for c, m in pairs:
        terms += _breakable_product(tidy(c), m, printer)
    terms.append((False, r"\dots"))
    return _sum_rows("G", terms)


def _breakable_product(coefficient: sp.Expr, monomial: sp.Expr, printer: GacliLatexPrinter) -> list[Term]:
    """coefficient · monomial as one term, or, when that is wider than a line (an unequal-moment
    ball's g_i), term by term of the expanded coefficient, each times the monomial, so that lines
    can break."""
    term = _product_term(coefficient, monomial, printer)
    if term is None or _width(term[1]) <= WIDE or not (spread := sp.expand(coefficient)).is_Add:
        return [term] if term else []
    parts = printer._as_ordered_terms(spread, order=None)
    return [t for part in parts if (t := _product_term(part, monomial, printer))]


def _force_rows(derivation: Derivation, printer: GacliLatexPrinter) -> list[list[str]]:
    return [
        _sum_rows(f"Q_{{{printer.doprint(S.value(name))}}}", _terms(tidy(Q), printer) or _ZERO)
        for name, Q in zip(derivation.independent, derivation.generalized_forces)
    ]


def _equation_rows(derivation: Derivation, printer: GacliLatexPrinter) -> list[list[str]]:
    """∂G/∂u̇_s = Σ_r M_sr u̇_r + (Q_s − F_s) = Q_s for each s."""
    M, F, Q = derivation.mass_matrix, derivation.forcing, derivation.generalized_forces
    a = derivation.speed_rates
    groups = []
    for s, u in enumerate(a):
        terms = [t for r in range(len(a)) if (t := _product_term(tidy(M[s, r]), a[r], printer))]
        terms += _terms(tidy(Q[s] - F[s]), printer, WIDE - _LABEL)
        label = rf"\frac{{\partial G}}{{\partial {printer.doprint(u)}}}"
        groups.append(_sum_rows(label, terms or _ZERO, _terms(tidy(Q[s]), printer) or _ZERO))
    return groups


def _kinematic_section(derivation: Derivation, printer: GacliLatexPrinter) -> "_Section":
    rows = _kinematic_rows(derivation, printer)
    note = "" if rows else "Every coordinate is independent: its rate is one of the speeds."
    return _Section("Kinematic equations (eq. 14.20)", note, rows)


def _kinematic_rows(derivation: Derivation, printer: GacliLatexPrinter) -> list[list[str]]:
    # An independent coordinate's q̇ = q̇ says nothing: left out, as by hand.
    return [
        _sum_rows(printer.doprint(S.rate(name)), _terms(tidy(rate), printer) or _ZERO)
        for name, rate in derivation.kinematic_equations if rate != S.rate(name)
    ]


# -- terms and lines -----------------------------------------------------------

Term = tuple[bool, str]  # (negative, LaTeX of the magnitude)
_ZERO: list[Term] = [(False, "0")]


def tidy(expr: sp.Expr) -> sp.Expr:
    """The display simplifier that text uses too (:func:`gacli.readable.readable`), within its size bounds."""
    return Tidy(budget=sys.maxsize)(expr)


def _terms(expr: sp.Expr, printer: GacliLatexPrinter, wide: int = WIDE) -> list[Term]:
    """The terms of a sum in the printer's order, each with its sign pulled out; [] for 0.
    A term wider than ``wide`` is written expanded."""
    if expr == 0:
        return []
    terms = printer._as_ordered_terms(expr, order=None) if expr.is_Add else [expr]
    out = []
    for term in terms:
        negative = term.could_extract_minus_sign()
        tex = printer._print(-term if negative else term)
        if _width(tex) > wide and (spread := sp.expand(term)).is_Add:
            # A factored term wider than a line cannot break; its expansion can.
            out += _terms(spread, printer, wide)
        else:
            out.append((negative, tex))
    return out


def _product_term(coefficient: sp.Expr, monomial: sp.Expr, printer: GacliLatexPrinter) -> Term | None:
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


def _half_term(coefficient: sp.Expr, monomial: sp.Expr, printer: GacliLatexPrinter) -> Term | None:
    """½ · coefficient · monomial: ½ folded into a product, written in front of a sum."""
    if not coefficient.is_Add:
        return _product_term(coefficient / 2, monomial, printer)
    term = _product_term(coefficient, monomial, printer)
    return term and (term[0], r"\frac{1}{2} " + term[1])


def _sum_rows(label: str, terms: list[Term], rhs: list[Term] | None = None) -> list[str]:
    """align* rows for ``label = terms [= rhs]``, broken after about LINE_WIDTH."""
    lines = _fill(terms)
    if rhs is not None:
        right = _fill(rhs)
        if len(lines) == 1 and len(right) == 1 and _width(lines[0] + right[0]) <= LINE_WIDTH:
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
        w = _width(tex)
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


def _width(tex: str) -> int:
    """A rough typeset width: one per symbol, nothing for braces and accents; a fraction is its wider part."""
    start = tex.find(_FRAC)
    if start >= 0:
        numerator, middle = _group(tex, start + len(_FRAC) - 1)
        denominator, end = _group(tex, middle)
        return _width(tex[:start]) + max(_width(numerator), _width(denominator)) + _width(tex[end:])
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


# -- text --------------------------------------------------------------------

_TEXT_SPECIALS = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
    "%": r"\%", "_": r"\_", "^": r"\^{}", "~": r"\~{}", "<": r"\textless{}", ">": r"\textgreater{}",
    "|": r"\textbar{}",
    "\u2013": "--", "\u2014": "---", "\u2018": "`", "\u2019": "'", "\u201c": "``", "\u201d": "''",
    "\u2026": r"\dots{}", "\u2202": r"$\partial$", "\u03a3": r"$\Sigma$", "\u00d7": r"$\times$", "\u00b0": r"$^\circ$", "\u00a0": "~",
}
_GREEK = re.compile(r"^GREEK (SMALL|CAPITAL) LETTER (?:FINAL )?([A-Z]+)$")
_GREEK_COMMANDS = frozenset(
    "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi pi rho sigma tau upsilon "
    "phi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega".split()
)
_ACCENTS = {"\u0307": ".", "\u0300": "`", "\u0301": "'", "\u0302": "^", "\u0303": "~", "\u0304": "=", "\u0306": "u",
            "\u0308": '"', "\u030a": "r", "\u030c": "v", "\u0327": "c"}


def _one_line(text: str) -> str:
    """One line of printable characters: a newline in a comment would start live TeX."""
    return " ".join("".join(c if c.isprintable() else " " for c in text).split())


def _text(text: str) -> str:
    """Free text from the system file as LaTeX text that pdflatex accepts (ASCII out), in lines."""
    units: list[str] = []  # the LaTeX of each character: lines break between them, never inside
    for c in unicodedata.normalize("NFC", _one_line(text)):
        if c in _ACCENTS and units:
            # A combining mark left over after NFC (u̇ has no precomposed form): accent the last letter.
            units[-1] = rf"\{_ACCENTS[c]}{{{units[-1]}}}"
        else:
            units.append(_text_char(c))
    # TeX sets -- and --- as dashes; an option such as --format must keep its two hyphens.
    units = [re.sub(r"-(?=-)", "-{}", u) for u in units]
    for i in range(len(units) - 1):
        if units[i].endswith("-") and units[i + 1].startswith("-"):
            units[i] += "{}"
    return _wrap(units)


def _wrap(units: list[str]) -> str:
    """Lines of about TEXT_LINE characters: pdflatex cannot read a line longer than its buffer.

    A line ends at the first space past TEXT_LINE; a run without spaces is cut
    at 2 * TEXT_LINE, the cut hidden from TeX by a ``%`` (every unit ends in a
    character that cannot continue a control word).
    """
    lines, line, size = [], [], 0
    for unit in units:
        if unit == " " and size >= TEXT_LINE:
            lines.append("".join(line))
            line, size = [], 0
            continue
        if size >= 2 * TEXT_LINE:
            lines.append("".join(line) + "%")
            line, size = [], 0
        line.append(unit)
        size += len(unit)
    lines.append("".join(line))
    return "\n".join(lines)


def _text_char(c: str) -> str:
    if c in _TEXT_SPECIALS:
        return _TEXT_SPECIALS[c]
    if c.isascii():
        return c
    greek = _GREEK.match(unicodedata.name(c, ""))
    if greek:
        letter = greek[2].lower().replace("lamda", "lambda")
        letter = letter.capitalize() if greek[1] == "CAPITAL" else letter
        return rf"$\{letter}$" if letter in _GREEK_COMMANDS else "?"
    base, *marks = unicodedata.normalize("NFD", c)
    if base.isascii() and marks and all(m in _ACCENTS for m in marks):
        out = _TEXT_SPECIALS.get(base, base)
        for mark in marks:
            out = rf"\{_ACCENTS[mark]}{{{out}}}"
        return out
    return "?"
