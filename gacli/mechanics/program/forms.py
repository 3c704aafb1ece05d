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

import functools
import itertools
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import angles, turns
from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.algebra.fastdiff import jacobian_rows
from gacli.algebra.graph import is_small, postorder, shared_subexpressions
from gacli.numeric.zero import vanishes
from gacli.mechanics.program.tape import Tape
from gacli.mechanics.program.vectors import ZERO, Pass
from gacli.model import Form, RateRelation, System


@dataclass(frozen=True)
class FormRows:
    """The rows as forms, in order: every constraint not derived from rolling, then each quasi definition."""

    forms: tuple[Form, ...]
    # The combinations that made ``forms`` (i, j, φ_i, φ_j: _best_turns), in order, and the rows
    # as stated before them.
    turns: tuple[tuple[int, int, sp.Expr, sp.Expr], ...] = ()
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
        """The rows with pairs combined while that leaves fewer nonzero entries in the dependent
        rates' columns (see the module, :func:`_best_turns`): one set for each of the first
        :data:`TURNINGS` first combinations, each completed greedily; none when none clears an entry."""
        return list(_turnings(self, tuple(dependent)))

    def _completed(self, turn: tuple, dependent: list[str]) -> "FormRows":
        forms, turns = list(self.forms), []
        while turn is not None:
            i, j, phases, a, b = turn
            forms[i], forms[j] = a, b
            turns.append((i, j, *phases))
            following = _best_turns(forms, dependent)
            turn = following[0] if following else None
        return FormRows(tuple(forms), tuple(turns), self.forms)


@functools.lru_cache(maxsize=8)
def _turnings(rows: FormRows, dependent: tuple[str, ...]) -> tuple[FormRows, ...]:
    """FormRows.turnings, found once for the rows of a load (the program is built once for each)."""
    if len(rows.forms) > TURNED_ROWS or not all(_small(f) for f in rows.forms):
        return ()
    first = _best_turns(list(rows.forms), list(dependent))
    return tuple(rows._completed(turn, list(dependent)) for turn in first[:TURNINGS])


def _best_turns(forms: list[Form], dependent: list[str]) -> list[tuple]:
    """(i, j, (φ_i, φ_j), new row i, new row j) of the combinations that leave fewer nonzero entries
    in the dependent columns than now; the fewest first, then by the rows' operations, then i, j.

    A combination writes row i as cos φ_i r_i + sin φ_i r_j and row j as cos φ_j r_i + sin φ_j r_j:
    a turn about θ (φ_i = θ, φ_j = θ + π/2), or, where two dependent columns of the pair are each
    one link's lever turning with its angle (a loop's l_a ė_a, l_b ė_b), the row along each link:
    each then holds the other link alone, divided by l sin(θ_a − θ_b), the loop's own dead point.
    """
    trials = []
    for i, j in itertools.combinations(range(len(forms)), 2):
        phases = [(angle, angle + sp.pi / 2) for angle in _angles(forms[i], forms[j])
                  if _clears(forms[i], forms[j], angle, dependent)]
        phases += _along_links(forms[i], forms[j], dependent)
        trials += [(i, j, p, *_combined(forms[i], forms[j], *p)) for p in phases]
    scored = [(_score([*forms[:i], a, *forms[i + 1:j], b, *forms[j + 1:]], dependent), (i, j, p, a, b))
              for i, j, p, a, b in trials]
    now = _score(forms, dependent)[0]
    kept = sorted((x for x in scored if x[0][0] < now), key=lambda x: (*x[0], x[1][0], x[1][1], str(x[1][2])))
    return [turn for _, turn in kept]


def _along_links(a: Form, b: Form, dependent: list[str]) -> list[tuple[sp.Expr, sp.Expr]]:
    """(φ_i, φ_j) that each clear a different dependent column whose entries are a lever of fixed
    length turning with one angle (x² + y² holds no angle): the pair's rows along those links.
    Only for a pair whose dependent entries are those two columns alone: the pair's block is then
    theirs, of determinant l_a l_b sin(θ_a − θ_b), and each new pivot vanishes only where it does."""
    if sum(1 for q in dependent if a.coefficient(q) != 0 or b.coefficient(q) != 0) != 2:
        return []
    clearing = []
    for q in dependent:
        x, y = a.coefficient(q), b.coefficient(q)
        turning = _angles(Form((("", x),)), Form((("", y),)))
        if x == 0 or y == 0 or any(not _zero(_moved(x * x + y * y, angle)) for angle in turning):
            continue
        for angle in turning:
            clearing += [(q, phase) for phase in (angle, angle + sp.pi / 2)
                         if _zero(sp.cos(phase) * x + sp.sin(phase) * y)]
    return [(p, r) for (q, p), (s, r) in itertools.combinations(clearing, 2)
            if q != s and not _zero(sp.sin(r - p))]


# Rows past which no pair is turned: each pair is tried about each of its angles.
TURNED_ROWS = 6
TURNINGS = 3  # first turns tried, each built into a program (build.program_of keeps the cheapest)
_SMALL = 200  # tree nodes of a coefficient past which the rows are taken as they are


def _small(form: Form) -> bool:
    return all(is_small(c, _SMALL) for c in (*(c for _, c in form.coefficients), form.dt))


def closed_time_derivative(system: System):
    """d/dt of a small closed form in the coordinates, t and the free functions, in the rates'
    symbols (dot(q)), and those symbols sorted by name: :func:`time_derivative` without a tape."""
    chain = {S.value(c.name): S.rate(c.name) for c in system.coordinates}
    chain.update(S.time_chain(f.name for f in system.free_functions))

    def derivative(e: sp.Expr) -> sp.Expr:
        return sp.Add(*(sp.diff(e, x) * dx for x, dx in chain.items() if e.has(x)))

    return derivative, sorted(set(chain.values()) - {sp.S.One}, key=lambda x: x.name)


def _turned_rest(rows: FormRows, system: System) -> list[sp.Expr]:
    """b₀ of the stated rows in closed form, in the rates' symbols, turned as the rows were."""
    derivative, rates = closed_time_derivative(system)
    out = [sp.Add(*(derivative(c) * S.rate(q) for q, c in f.coefficients), derivative(f.dt)) for f in rows.stated]
    for i, j, first, second in rows.turns:
        out[i], out[j] = (angles.reduced_by(sp.cos(p) * out[i] + sp.sin(p) * out[j], rates, _shortest)
                              for p in (first, second))
    return out


def _clears(a: Form, b: Form, angle: sp.Symbol, dependent: list[str]) -> bool:
    """Whether turning the pair about ``angle`` makes an entry of a dependent column vanish (at a
    generic point: only then is the turn formed and reduced)."""
    c, s = sp.cos(angle), sp.sin(angle)
    for q in dependent:
        x, y = a.coefficient(q), b.coefficient(q)
        if x == 0 or y == 0:
            continue
        if any(_zero(e) for e in (c * x + s * y, c * y - s * x)):
            return True
    return False


def _zero(e: sp.Expr) -> bool:
    """``e`` is zero identically: expanded when small, else at generic points (the loader's test)."""
    return vanishes(e, simplify=False)


def _moved(e: sp.Expr, angle: sp.Expr) -> sp.Expr:
    """e at ``angle`` + 0.37 less e (the angle's first coordinate moved, the others held): zero when e
    does not depend on the angle."""
    first = min(angle.free_symbols, key=lambda s: s.name)
    return e.xreplace({first: first + sp.Rational(37, 100) / angle.coeff(first)}) - e


def _angles(a: Form, b: Form) -> list[sp.Expr]:
    """The angles whose sine or cosine the two rows' coefficients hold, sorted by name: coordinates,
    and sums of them where a coefficient is a sum of turns (a link turned by q₃ + q₄ written out as
    sin q₃ cos q₄ + cos q₃ sin q₄, gacli.algebra.turns)."""
    exprs = [c for f in (a, b) for _, c in f.coefficients]
    found = {n.args[0] for n in postorder(exprs) if isinstance(n, (sp.sin, sp.cos)) and n.args[0].is_Symbol}
    for e in map(_folded, exprs):
        found |= {n.args[0] for n in sp.preorder_traversal(e) if isinstance(n, (sp.sin, sp.cos))
                  and _whole(n.args[0])}
    return sorted(found, key=sp.default_sort_key)


def _whole(angle: sp.Expr) -> bool:
    """A coordinate, or a sum of coordinates with whole coefficients."""
    return angle.is_Symbol or (angle.is_Add and all(t.is_Symbol or (t.is_Mul and len(t.args) == 2
                               and t.args[0].is_Integer and t.args[1].is_Symbol) for t in angle.args))


# Tree nodes of a row's coefficient up to which it is folded into a sum of turns: a link's lever
# l (sin q₃ cos q₄ + cos q₃ sin q₄) has 15; a rattleback's hand-derived rows, of about 200, took 9 s
# to write through e^(iq) for nothing.
FOLDED_NODES = 80


@functools.lru_cache(maxsize=1024)  # the same coefficients recur in each turning and each build
def _folded(e: sp.Expr) -> sp.Expr:
    """``e`` as one sum of turns in the angles it holds (gacli.algebra.turns), or as it is."""
    if not is_small(e, FOLDED_NODES):
        return e
    held = sorted({s for n in sp.preorder_traversal(e) if isinstance(n, (sp.sin, sp.cos))
                   for s in n.free_symbols}, key=lambda s: s.name)
    out = turns.folded(e, held) if held else None
    return e if out is None else out


def _combined(a: Form, b: Form, first: sp.Expr, second: sp.Expr) -> tuple[Form, Form]:
    """(cos φ₁ a + sin φ₁ b, cos φ₂ a + sin φ₂ b), each coefficient reduced."""
    names = tuple(dict.fromkeys(a.names + b.names))

    def combined(phase: sp.Expr) -> Form:
        x, y = sp.cos(phase), sp.sin(phase)
        pairs = ((n, _shortest(x * a.coefficient(n) + y * b.coefficient(n))) for n in names)
        return Form(tuple((n, e) for n, e in pairs if e != 0), _shortest(x * a.dt + y * b.dt))

    return combined(first), combined(second)


@functools.lru_cache(maxsize=1024)
def _shortest(e: sp.Expr) -> sp.Expr:
    """``e`` reduced (gacli.algebra.angles) or folded into a sum of turns, whichever is shorter."""
    return min((angles.reduced(e), _folded(e)), key=lambda x: (sp.count_ops(x), sp.default_sort_key(x)))


def _score(forms: list[Form], dependent: list[str]) -> tuple[int, int]:
    """(nonzero entries in the dependent columns, operations of every coefficient)."""
    nonzero = sum(1 for f in forms for q in dependent if f.coefficient(q) != 0)
    return nonzero, sum(sp.count_ops(c) for f in forms for c in (*(c for _, c in f.coefficients), f.dt))


def _entry(tape: Tape, e: sp.Expr) -> sp.Expr:
    return ZERO if e == 0 else tape.let(e)


def form_rows(system: System) -> FormRows:
    """The system's rows stated as forms (see the module)."""
    forms = []
    for c in system.constraints:
        if c.derived:
            continue
        forms.append(c.form if c.rates is None else _solved(c.form, c.rates))
    forms += [q.definition for q in system.quasi_coordinates if q.definition is not None]
    return FormRows(tuple(forms))


def _solved(form: Form, relation: RateRelation) -> Form:
    """A relation g(q, ṙ, t) = 0 nonlinear in the rates as its linearization A ṙ + a₀ = g (A = ∂g/∂ṙ,
    gacli.loader.nonlinear), the dependent rate in A and a₀ replaced by its solution. Solved by the
    rows, the dependent rate is then f exactly, the partial velocities Chetaev's ∂f/∂u, and
    b₀ = Σ ∂g/∂q q̇ + ∂g/∂t, the coefficients' d/dt with the rates held (forms.rest): a term that
    the solution's own rate of change adds is Σ_s ∂A_s/∂ṙ_d ṙ_s + ∂a₀/∂ṙ_d, which vanishes since
    g = A ṙ + a₀ for every ṙ. The rows' other rates must be independent (build.py checks)."""
    solution = {S.rate(relation.dependent): relation.solution}
    return form.xreplace(solution)


def rates_held(forms: FormRows, dependent) -> list[str]:
    """The dependent rates the rows' entries hold (a relation nonlinear in the rates written with two
    of them): the rows would then not be linear in the dependent rates."""
    entries = [c for f in forms.forms for c in (*(c for _, c in f.coefficients), f.dt)]
    return [q for q in dependent if any(c.has(S.rate(q)) for c in entries)]


def time_derivative(system: System, actual: Pass, tape: Tape):
    """d/dt of an expression in the coordinates, t and the free functions, along the actual rates.

    Each partial derivative is written on the tape before it is multiplied by
    its rate: the derivative of one row entry is often another entry (the
    loop of a linkage: ∂(−l sin θ)/∂θ = −(l cos θ)), which the tape then
    names once.
    """
    chain = {S.value(c.name): actual.rate(c.name) for c in system.coordinates}
    chain.update(S.time_chain(f.name for f in system.free_functions))
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
