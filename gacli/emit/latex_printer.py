"""gacli's plain symbols in LaTeX: the printer every LaTeX output uses.

:class:`GacliLatexPrinter` prints ``x``, ``dot(x)``, ``ddot(x)``, ``d3(x)``
as :math:`x, \\dot{x}, \\ddot{x}, \\dddot{x}`, with the ``latex:`` names of
the system file, and a name TeX could not set (or a word such as ``yaw``)
upright.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import sympy as sp
from sympy.printing.latex import LatexPrinter

from gacli.algebra.readable import oriented, positive_first, toggled, turned
from gacli.algebra.symbols import RATE_NAME
from gacli.model import System
from gacli.read.texsafe import is_printable_name

_RATE = RATE_NAME
_DIFFERENTIAL = re.compile(r"^d\[(.+)\]$")
_SUBSCRIPTED = re.compile(r"^(\\?[A-Za-z]+)(_(?:[A-Za-z0-9]|\{[^{}]*\}))$")
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

    # Euler's number upright, as ISO 80000-2 sets it: an italic e is a parameter's (an ellipse's e).
    # (E's own _latex method answers before any _print_Exp1 would.)
    def _print(self, expr, **kwargs) -> str:
        return r"\mathrm{e}" if expr is sp.S.Exp1 else super()._print(expr, **kwargs)

    def _print_ExpBase(self, expr, exp=None) -> str:
        tex = r"\mathrm{e}^{%s}" % self._print(expr.args[0])
        return self._do_exponent(tex, exp)

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
            # The dots go over the letter of a latex: name, not over its subscript (\dot{\theta}_R).
            parts = _SUBSCRIPTED.match(self._names[base])
            head, tail = (parts[1], parts[2]) if parts else (self._names[base], "")
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

    # The sign order a textbook uses, as the text output has it (gacli.algebra.readable).
    def _as_ordered_terms(self, expr, order=None):
        return positive_first(super()._as_ordered_terms(expr, order=order))

    def _print_Add(self, expr, order=None) -> str:
        tex = ""
        for i, term in enumerate(self._as_ordered_terms(expr, order=order)):
            negative, magnitude = oriented(term)
            term_tex = self._print(magnitude)
            if self._needs_add_brackets(magnitude):
                term_tex = rf"\left({term_tex}\right)"
            tex += ("- " if negative else "") + term_tex if i == 0 else (" - " if negative else " + ") + term_tex
        return tex

    def _print_Mul(self, expr) -> str:
        turn = turned(expr)
        if turn is None:
            return super()._print_Mul(expr)
        return toggled(super()._print_Mul(turn[1]), turn[0])

    def _print_atan2(self, expr: sp.Expr, exp: str | None = None) -> str:
        args = ", ".join(self._print(a) for a in expr.args)
        tex = rf"\operatorname{{atan2}}\left({args}\right)"
        return f"{tex}^{{{exp}}}" if exp else tex
