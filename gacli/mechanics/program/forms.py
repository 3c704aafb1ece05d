"""The rows the file states as differential forms: constraints (eq. 14.1) and quasi-coordinates (eq. 14.2).

A constraint Σ B_s dr_s + B dt = 0 (an equation's differential, a Pfaffian
row, a knife edge's velocity row) and a quasi-coordinate's definition
dθ − Σ C_s dq_s − C dt = 0 are rows of A ṙ + a₀ = 0 whose entries are the
file's closed forms, written on the tape as they are. Their part of the
dependent accelerations (eq. 14.14) is b₀ = Σ Ḃ_s ṙ_s + Ḃ, the rows'
derivative with all accelerations zero, Ḃ from the partial derivatives
(gacli.algebra.fastdiff), each named on the tape, times the rates.
The rolling contacts' rows (gacli.mechanics.program.rows) come from the
frame model instead.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.algebra.fastdiff import jacobian_rows
from gacli.algebra.graph import shared_subexpressions
from gacli.mechanics.program.support import Unsupported
from gacli.mechanics.program.tape import Tape
from gacli.mechanics.program.vectors import ZERO, Pass
from gacli.model import Form, System


@dataclass(frozen=True)
class FormRows:
    """The rows as forms, in order: every constraint not derived from rolling, then each quasi definition."""

    forms: tuple[Form, ...]

    @property
    def names(self) -> set[str]:
        """The rates some row has a term in."""
        return {n for f in self.forms for n, c in f.coefficients if c != 0}

    def columns(self, tape: Tape, names: list[str]) -> dict[str, list[sp.Expr]]:
        """Each rate's column of entries on the tape (exact zeros where a form has no term)."""
        return {q: [_entry(tape, f.coefficient(q)) for f in self.forms] for q in names}

    def dt(self, tape: Tape) -> list[sp.Expr]:
        return [_entry(tape, f.dt) for f in self.forms]

    def rest(self, tape: Tape, system: System, actual: Pass) -> list[sp.Expr]:
        """b₀ of each row: d/dt of its coefficients along the actual motion, times the actual rates."""
        D = time_derivative(system, actual, tape)
        out = []
        for f in self.forms:
            terms = [D(c) * actual.rate(q) for q, c in f.coefficients]
            out.append(tape.let(sp.Add(*terms, D(f.dt))))
        return out


def _entry(tape: Tape, e: sp.Expr) -> sp.Expr:
    return ZERO if e == 0 else tape.let(e)


def form_rows(system: System) -> FormRows:
    """The system's rows stated as forms (see the module); Unsupported for a constraint nonlinear in the rates."""
    forms = []
    for c in system.constraints:
        if c.derived:
            continue
        if c.rates is not None:
            raise Unsupported("a constraint nonlinear in the rates is not supported")
        forms.append(c.form)
    forms += [q.definition for q in system.quasi_coordinates if q.definition is not None]
    return FormRows(tuple(forms))


def time_derivative(system: System, actual: Pass, tape: Tape):
    """d/dt of an expression in the coordinates, t and the free functions, along the actual rates.

    Each partial derivative is written on the tape before it is multiplied by
    its rate: the derivative of one row entry is often another entry (the
    loop of a linkage: ∂(−l sin θ)/∂θ = −(l cos θ)), which the tape then
    names once.
    """
    chain = {S.value(c.name): actual.rate(c.name) for c in system.coordinates}
    chain.update(S.function_chain(f.name for f in system.free_functions))
    chain[S.T] = sp.S.One
    symbols = sorted(chain, key=lambda s: s.name)

    def derivative(e: sp.Expr) -> sp.Expr:
        e = as_expr(e)
        if e.is_number:
            return ZERO
        (row,) = jacobian_rows([e], symbols)
        present = [(s, d) for s, d in zip(symbols, row) if d != 0]
        named = shared_lets(tape, [d for _, d in present])
        return sp.Add(*(d * chain[s] for (s, _), d in zip(present, named)))

    return derivative


def shared_lets(tape: Tape, exprs: list[sp.Expr]) -> list[sp.Expr]:
    """Each expression on the tape, its repeated subexpressions first, each once: the partial
    derivatives of a long closed form (a rattleback's rows) repeat its denominators."""
    fresh = (sp.Dummy() for _ in iter(int, 1))
    replacements, reduced = shared_subexpressions(exprs, fresh)
    names: dict[sp.Symbol, sp.Expr] = {}
    for symbol, value in replacements:
        names[symbol] = tape.let(value.xreplace(names))
    return [tape.let(e.xreplace(names)) for e in reduced]
