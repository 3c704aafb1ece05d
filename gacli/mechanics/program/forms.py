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

Two rows that are the components of one vector along N's axes (a linkage's
loop closed in N) are taken along a turned pair of axes where that leaves a
dependent rate out of one of them (:meth:`FormRows.turnings`): any invertible
combination of the rows is the same constraint, and a loop written along the
rocker's axes is triangular, solved by −l₃ and l₂ sin(θ₂ − θ₃) instead of a
2 × 2 determinant, as by hand.
"""

from __future__ import annotations

import itertools
import random
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import angles
from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.algebra.fastdiff import jacobian_rows
from gacli.algebra.graph import is_small, postorder, shared_subexpressions
from gacli.mechanics.program.support import Unsupported
from gacli.mechanics.program.tape import Tape
from gacli.mechanics.program.vectors import ZERO, Pass
from gacli.model import Form, System


@dataclass(frozen=True)
class FormRows:
    """The rows as forms, in order: every constraint not derived from rolling, then each quasi definition."""

    forms: tuple[Form, ...]
    # The turns that made ``forms`` (i, j, θ), in order, and the rows as stated before them.
    turns: tuple[tuple[int, int, sp.Symbol], ...] = ()
    stated: tuple[Form, ...] | None = None

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
        """b₀ of each row: d/dt of its coefficients along the actual motion, times the actual rates.

        Of turned rows, the stated rows' b₀ turned: d/dt (R A) ṙ = R Ȧ ṙ + Ṙ A ṙ, and A ṙ + a₀ = 0
        along the motion, so the turn's own rate drops out. It is formed in closed form and
        reduced, as the turned rows are: a loop's centripetal terms along N, −l cos θ θ̇², turned
        about the coupler, are l cos(θ − θ₂) θ̇², on the sines and cosines the rows already hold.
        """
        if self.turns:
            values = {S.rate(q): actual.rate(q) for q in system.rate_names}
            return [tape.let(b.xreplace(values)) for b in _turned_rest(self, system)]
        D = time_derivative(system, actual, tape)
        out = []
        for f in self.forms:
            terms = [D(c) * actual.rate(q) for q, c in f.coefficients]
            out.append(tape.let(sp.Add(*terms, D(f.dt))))
        return out

    def turnings(self, dependent: list[str]) -> list["FormRows"]:
        """The rows with pairs turned about an angle of theirs while that leaves fewer nonzero
        entries in the dependent rates' columns (see the module): one set for each first turn
        that leaves the fewest, at most :data:`TURNINGS`; none when no turn clears an entry."""
        if len(self.forms) > TURNED_ROWS or not all(_small(f) for f in self.forms):
            return []
        first = _best_turns(list(self.forms), dependent)
        return [self._completed(turn, dependent) for turn in first[:TURNINGS]]

    def _completed(self, turn: tuple, dependent: list[str]) -> "FormRows":
        forms, turns = list(self.forms), []
        while turn is not None:
            i, j, angle, a, b = turn
            forms[i], forms[j] = a, b
            turns.append((i, j, angle))
            following = _best_turns(forms, dependent)
            turn = following[0] if following else None
        return FormRows(tuple(forms), tuple(turns), self.forms)


def _best_turns(forms: list[Form], dependent: list[str]) -> list[tuple]:
    """(i, j, θ, turned row i, turned row j) of the turns that leave the fewest nonzero entries in
    the dependent columns, fewer than now; in order of the rows' operations, then of i, j, θ."""
    trials = [(i, j, angle, *_turn(forms[i], forms[j], angle))
              for i, j in itertools.combinations(range(len(forms)), 2) for angle in _angles(forms[i], forms[j])
              if _clears(forms[i], forms[j], angle, dependent)]
    scored = [(_score([*forms[:i], a, *forms[i + 1:j], b, *forms[j + 1:]], dependent), (i, j, angle, a, b))
              for i, j, angle, a, b in trials]
    now = _score(forms, dependent)[0]
    fewest = min((score[0] for score, _ in scored), default=now)
    if fewest >= now:
        return []
    kept = sorted((x for x in scored if x[0][0] == fewest), key=lambda x: (x[0][1], x[1][0], x[1][1], x[1][2].name))
    return [turn for _, turn in kept]


# Rows past which no pair is turned: each pair is tried about each of its angles.
TURNED_ROWS = 6
TURNINGS = 3  # first turns tried, each built into a program (build.program_of keeps the cheapest)
_SMALL = 200  # tree nodes of a coefficient past which the rows are taken as they are


def _small(form: Form) -> bool:
    return all(is_small(c, _SMALL) for c in (*(c for _, c in form.coefficients), form.dt))


def _turned_rest(rows: FormRows, system: System) -> list[sp.Expr]:
    """b₀ of the stated rows in closed form, in the rates' symbols, turned as the rows were."""
    chain = {S.value(c.name): S.rate(c.name) for c in system.coordinates}
    chain.update(S.function_chain(f.name for f in system.free_functions))
    chain[S.T] = sp.S.One

    def derivative(e: sp.Expr) -> sp.Expr:
        return sp.Add(*(sp.diff(e, x) * dx for x, dx in chain.items() if e.has(x)))

    out = [sp.Add(*(derivative(c) * S.rate(q) for q, c in f.coefficients), derivative(f.dt)) for f in rows.stated]
    rates = sorted(set(chain.values()) - {sp.S.One}, key=lambda x: x.name)
    for i, j, angle in rows.turns:
        c, s = sp.cos(angle), sp.sin(angle)
        out[i], out[j] = angles.reduced_by(c * out[i] + s * out[j], rates), angles.reduced_by(c * out[j] - s * out[i], rates)
    return out


def _clears(a: Form, b: Form, angle: sp.Symbol, dependent: list[str]) -> bool:
    """Whether turning the pair about ``angle`` makes an entry of a dependent column vanish (at a
    generic point: only then is the turn formed and reduced)."""
    c, s = sp.cos(angle), sp.sin(angle)
    for q in dependent:
        x, y = a.coefficient(q), b.coefficient(q)
        if x == 0 or y == 0:
            continue
        if any(_vanishes(e) for e in (c * x + s * y, c * y - s * x)):
            return True
    return False


def _vanishes(e: sp.Expr) -> bool:
    """``e`` is zero at two generic points (its symbols drawn by name, seeded)."""
    symbols = sorted(e.free_symbols, key=lambda x: x.name)
    for seed in (1, 2):
        rng = random.Random(seed)
        value = e.xreplace({x: sp.Float(rng.uniform(0.3, 1.7), 30) for x in symbols}).evalf(30)
        if not value.is_number or abs(complex(value)) > 1e-20:
            return False
    return True


def _angles(a: Form, b: Form) -> list[sp.Symbol]:
    """The angles whose sine or cosine the two rows' coefficients hold, sorted by name."""
    exprs = [c for f in (a, b) for _, c in f.coefficients]
    found = {n.args[0] for n in postorder(exprs) if isinstance(n, (sp.sin, sp.cos)) and n.args[0].is_Symbol}
    return sorted(found, key=lambda s: s.name)


def _turn(a: Form, b: Form, angle: sp.Symbol) -> tuple[Form, Form]:
    """(cos θ a + sin θ b, −sin θ a + cos θ b), each coefficient reduced."""
    c, s = sp.cos(angle), sp.sin(angle)
    names = tuple(dict.fromkeys(a.names + b.names))

    def combined(x: sp.Expr, y: sp.Expr) -> Form:
        pairs = ((n, angles.reduced(x * a.coefficient(n) + y * b.coefficient(n))) for n in names)
        return Form(tuple((n, e) for n, e in pairs if e != 0), angles.reduced(x * a.dt + y * b.dt))

    return combined(c, s), combined(-s, c)


def _score(forms: list[Form], dependent: list[str]) -> tuple[int, int]:
    """(nonzero entries in the dependent columns, operations of every coefficient)."""
    nonzero = sum(1 for f in forms for q in dependent if f.coefficient(q) != 0)
    return nonzero, sum(sp.count_ops(c) for f in forms for c in (*(c for _, c in f.coefficients), f.dt))


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
