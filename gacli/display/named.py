"""Long equations printed through named intermediate quantities, each written once.

When M and F are too long to read written out, the printout does what a
careful hand derivation and Autolev's output do: it names the quantities the
equations are built from (a frame's angular velocity along its own axes, a
mass centre's velocity, a partial velocity), prints each once in the order
it is computed, and writes q̇, M and F through them (docs/printing.md).

The quantities are read off what the derivation already has, never derived
again: for generated code from the frame tree, the program's own
assignments (:mod:`gacli.mechanics.program`) with the labels its tape gave
them; for closed forms, their shared subexpressions
(:func:`gacli.algebra.graph.shared_subexpressions`), a dependent rate named
by its rate. Every name is an identifier, so each printed line reads back
with the system file's own parser.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.display.labels import label_name
from gacli.algebra.readable import pythagorean, show
from gacli.algebra.graph import common_subexpressions, free_symbols, postorder, shared_subexpressions, substitute

RATES = "dependent rates, eq. (14.7)"


@dataclass(frozen=True)
class Quantity:
    """One named intermediate: ``symbol = value``; ``about`` says what it is (shown once per vector)."""

    symbol: sp.Symbol
    value: sp.Expr
    about: str = ""


@dataclass(frozen=True)
class Named:
    """q̇, M and F written through named quantities, which are listed in evaluation order.

    Every expression is over the state, the parameters and names defined
    earlier in ``quantities`` (or named in ``rates``): evaluated in order,
    they are the derivation's q̇, M and F.
    """

    quantities: tuple[Quantity, ...]
    rates: tuple[tuple[str, sp.Expr], ...]  # (coordinate, q̇) where q̇ is not a speed itself
    mass: tuple[tuple[tuple[int, int], sp.Expr], ...]  # nonzero entries r ≤ s, row-major
    forcing: tuple[sp.Expr, ...]
    source: str  # "program" (the frame tree's quantities) or "closed" (shared subexpressions)


def is_inline(value: sp.Expr) -> bool:
    """Worth no name: f(a), f(a ± b), atom**n, n*atom (``cos(yaw)``, ``sin(htangle + q4)``, ``r**2``, ``-z8``)."""
    if value.is_Mul and len(value.args) == 2 and value.args[0].is_Number:
        return value.args[1].is_Atom
    if value.is_Pow:  # r**2, 1/w
        return value.base.is_Atom and value.exp.is_Integer
    if not (isinstance(value, sp.Function) and len(value.args) == 1):
        return False
    (a,) = value.args
    return a.is_Atom or a.is_Add and len(a.args) == 2 and all(t.is_Atom or (-t).is_Atom for t in a.args)


# An unlabelled value used once is written in place while it has at most this many operations.
INLINE_OPS = 6


def _ops(e: sp.Expr) -> int:
    return sum(len(n.args) - 1 if (n.is_Add or n.is_Mul) else 1 for n in sp.preorder_traversal(e)
               if n.is_Add or n.is_Mul or n.is_Pow or isinstance(n, sp.Function))


class _Namer:
    """Display symbols for assigned ones: each name once, none a name the system declares."""

    def __init__(self, taken: set[str]) -> None:
        self.taken = set(taken)
        self.declared = frozenset(taken)
        self.counter = itertools.count(1)

    def fresh(self, wanted: str | None = None) -> sp.Symbol:
        name = wanted
        while name is None or name in self.taken:
            name = f"{wanted}_{next(self.counter)}" if wanted else f"z{next(self.counter)}"
        self.taken.add(name)
        return sp.Symbol(name, real=True)


def _uses(assignments, outputs) -> dict[sp.Symbol, int]:
    counts: dict[sp.Symbol, int] = {}
    for e in [*(e for _, e in assignments), *outputs]:
        for s in e.free_symbols:
            counts[s] = counts.get(s, 0) + 1
    return counts


def from_program(program, taken: set[str]) -> Named:
    """The program's assignments as named quantities: labelled ones by their label, dependent rates by
    their rate, the rest ``z1, z2, ...`` or written in place (see the module)."""
    labels = dict(program.labels)
    outputs = [e for _, e in program.rates] + list(program.mass_matrix) + list(program.forcing)
    uses, inner = _uses(program.assignments, outputs), _uses(program.assignments, [])
    rate_of = {e: q for q, e in program.rates if e.is_Symbol and e not in labels and e != S.rate(q)}
    namer = _Namer(taken)
    shown: dict[sp.Symbol, sp.Expr] = {}
    quantities: list[Quantity] = []
    outputs_of: dict[sp.Symbol, sp.Expr] = {}
    for symbol, value in program.assignments:
        value = value.xreplace(shown)
        label = labels.get(symbol)
        if label is not None and label[0] in ("M", "F"):
            if not inner.get(symbol):
                outputs_of[symbol] = value  # printed as M and F themselves
                continue
            label = None  # an entry other steps read as well (the tape gave both one value): named
        # Worth no name even when labelled (one label per value: cos(q5) printed as w_Fork_unit_q4_y)
        if symbol not in rate_of and (is_inline(value) or
                                      (label is None and uses.get(symbol, 0) <= 1 and _ops(value) <= INLINE_OPS)):
            shown[symbol] = value
            continue
        if symbol in rate_of:
            name, about = S.rate(rate_of[symbol]), RATES
            namer.taken.add(name.name)
        elif label is not None:
            wanted, _, about = label_name(label)
            name = namer.fresh(wanted)
        else:
            name, about = namer.fresh(), ""
        shown[symbol] = name
        quantities.append(Quantity(name, pythagorean(value), about))
    return short_lines(_state_pieces(_outputs(program, shown, outputs_of, tuple(quantities)), namer), namer)


def _state_pieces(named: Named, namer: _Namer) -> Named:
    """Pieces over the state alone that the quantities repeat, each named once, first: a position
    written in closed form (an ellipsoid placed by its contact, whose height √(nᵀE n) is in every
    derivative of it) is differentiated in place, so its pieces recur from one quantity to the next."""
    defined = {q.symbol for q in named.quantities}
    exprs = [*(q.value for q in named.quantities), *(e for _, e in named.rates), *(e for _, e in named.mass),
             *named.forcing]
    replacements, reduced = shared_subexpressions(exprs, iter(lambda: namer.fresh(), None))
    kept, back = [], {}
    for symbol, value in replacements:
        value = _through(value, back)
        if is_inline(value) or _ops(value) <= INLINE_OPS or free_symbols([value]) & defined:
            back[symbol] = value
        else:
            kept.append(Quantity(symbol, value))
    if not kept:
        return named
    reduced = [_through(e, back) for e in reduced]
    n, r, m = len(named.quantities), len(named.rates), len(named.mass)
    aliases: dict = {}  # a piece's second name is that piece (z3 = z1; z5 = z3 = z1: z1), in order
    for q, e in ((q, e) for q, e in zip(named.quantities, reduced) if e.is_Atom and not q.about):
        aliases[q.symbol] = aliases.get(e, e)
    reduced = [e.xreplace(aliases) for e in reduced]
    quantities = [Quantity(q.symbol, e, q.about) for q, e in zip(named.quantities, reduced) if q.symbol not in aliases]
    return Named(tuple(kept + quantities), tuple((q, e) for (q, _), e in zip(named.rates, reduced[n:n + r])),
                 tuple((key, e) for (key, _), e in zip(named.mass, reduced[n + r:n + r + m])),
                 tuple(reduced[n + r + m:]), named.source)


def _outputs(program, shown: dict, outputs_of: dict, quantities: tuple[Quantity, ...]) -> Named:
    def out(e: sp.Expr) -> sp.Expr:
        return outputs_of[e] if e in outputs_of else e.xreplace(shown)

    k = program.k
    rates = tuple((q, out(e)) for q, e in program.rates if e != S.rate(q) and out(e) != S.rate(q))
    mass = tuple(((r, s), out(program.mass_matrix[r * k + s])) for r in range(k) for s in range(r, k)
                 if program.mass_matrix[r * k + s] != 0)
    return Named(quantities, rates, mass, tuple(out(e) for e in program.forcing), "program")


def from_closed(kinematic, mass, forcing, dependent: dict[str, sp.Expr], taken: set[str]) -> Named:
    """Closed forms through their shared subexpressions (walked as graphs, never as trees); a
    dependent rate's expression, where it stands whole in them, named by its rate."""
    namer = _Namer(taken | {S.rate(n).name for n in dependent})
    by_rate = {e: S.rate(n) for n, e in dependent.items() if not e.is_Atom}
    named = [n for n, e in dependent.items() if e in by_rate]
    entries = [e for _, e in mass]
    exprs = [*(e for _, e in kinematic), *entries, *forcing]
    exprs = substitute(exprs, by_rate) if by_rate else list(exprs)
    # Each rate's value with the other rates named in it, never itself.
    rate_values = [substitute([dependent[n]], {e: r for e, r in by_rate.items() if r != S.rate(n)})[0] for n in named]
    named, rate_values = _used(named, rate_values, exprs)
    # The CSE generated code makes (SymPy's where the trees allow): the quantities are its temporaries.
    replacements, reduced = common_subexpressions([*rate_values, *exprs], iter(lambda: namer.fresh(), None))
    rate_values, exprs = reduced[:len(rate_values)], reduced[len(rate_values):]
    inline: dict[sp.Symbol, sp.Expr] = {}
    for s, v in replacements:
        if is_inline(v):
            inline[s] = _through(v, inline)  # 1/z3 with z3 = r**2 in place too: 1/r**2
    quantities = [Quantity(s, pythagorean(_through(v, inline))) for s, v in replacements if s not in inline]
    quantities += [Quantity(S.rate(n), _through(v, inline), RATES)
                   for n, v in zip(named, rate_values)]
    exprs = [_through(e, inline) for e in exprs]
    n, m = len(kinematic), len(entries)
    rates = tuple((q, e) for (q, _), e in zip(kinematic, exprs[:n]) if e != S.rate(q))
    return short_lines(Named(tuple(quantities), rates, tuple(zip((key for key, _ in mass), exprs[n:n + m])),
                             tuple(exprs[n + m:]), "closed"), namer)


def _used(named: list[str], values: list[sp.Expr], exprs: list[sp.Expr]) -> tuple[list[str], list[sp.Expr]]:
    """The dependent rates the printed expressions read, directly or through another kept rate: a
    rate that stands nowhere in them would print a second formula beside its kinematic equation
    (a quaternion frame's ė with e·e, above code's ė on the sphere)."""
    read = free_symbols(exprs)
    kept: set[str] = set()
    while True:
        more = {n for n, v in zip(named, values) if n not in kept and S.rate(n) in read}
        if not more:
            break
        kept |= more
        read = read | free_symbols([v for n, v in zip(named, values) if n in more])
    return [n for n in named if n in kept], [v for n, v in zip(named, values) if n in kept]


# A value printing longer than this is written through names for its longest pieces, each on
# its own line (a rattleback's closed forms had single lines of 5,000 characters).
LINE = 400
# Pieces shorter than this stay in place: a name for them would save nothing.
PIECE = 40


def short_lines(named: Named, namer: _Namer) -> Named:
    """``named`` with every line of at most about LINE characters (see LINE), the pieces it names
    each before their use; quantities in an order where every name is defined before it is read."""
    out: list[Quantity] = []

    def cut(e: sp.Expr) -> sp.Expr:
        return _cut(e, namer, out)  # its pieces go just before what reads them

    for q in named.quantities:
        value = cut(q.value)
        out.append(Quantity(q.symbol, value, q.about))
    rates = tuple((q, cut(e)) for q, e in named.rates)
    mass = tuple((key, cut(e)) for key, e in named.mass)
    forcing = tuple(cut(e) for e in named.forcing)
    return _renumbered(Named(_in_order(out), rates, mass, forcing, named.source), namer)


_NUMBERED = re.compile(r"^z\d+$")


def _renumbered(named: Named, namer: _Namer) -> Named:
    """The unlabelled names z1, z2, ... in the order they are printed (value numbering and
    the names written in place leave gaps)."""
    old = [q.symbol for q in named.quantities if _NUMBERED.match(q.symbol.name)]
    fresh = _Namer(namer.declared | {q.symbol.name for q in named.quantities if not _NUMBERED.match(q.symbol.name)})
    mapping = {s: fresh.fresh() for s in old}

    def ren(e: sp.Expr) -> sp.Expr:
        return e.xreplace(mapping)

    return Named(tuple(Quantity(mapping.get(q.symbol, q.symbol), ren(q.value), q.about) for q in named.quantities),
                 tuple((q, ren(e)) for q, e in named.rates), tuple((key, ren(e)) for key, e in named.mass),
                 tuple(ren(e) for e in named.forcing), named.source)


def _cut(e: sp.Expr, namer: _Namer, pieces: list[Quantity]) -> sp.Expr:
    if e.is_Atom or len(show(e)) <= LINE:
        return e
    args = []
    for a in e.args:
        if a.is_Atom or len(show(a)) < PIECE:
            args.append(a)
            continue
        symbol = namer.fresh()
        pieces.append(Quantity(symbol, _cut(a, namer, pieces)))
        args.append(symbol)
    return e.func(*args)


def _in_order(quantities: list[Quantity]) -> tuple[Quantity, ...]:
    """The quantities each after every name its value holds (a rate named after the shared pieces
    of its value, before the pieces that hold it), otherwise in the order given."""
    names = {q.symbol for q in quantities}
    needs = [{s for s in free_symbols([q.value]) if s in names and s != q.symbol} for q in quantities]
    done: set[sp.Symbol] = set()
    out: list[Quantity] = []
    waiting = list(range(len(quantities)))
    while waiting:
        i = next((i for i in waiting if needs[i] <= done), waiting[0])  # a cycle cannot occur: first
        waiting.remove(i)
        out.append(quantities[i])
        done.add(quantities[i].symbol)
    return tuple(out)


def _through(e: sp.Expr, inline: dict) -> sp.Expr:
    """``e`` with the values worth no name written in place (over the graph)."""
    if not inline:
        return e
    return substitute([e], inline)[0]


def declared_names(derivation) -> set[str]:
    """Every name the printout may not take: the system's symbols and its coordinates' rates."""
    system = derivation.system
    names = {s.name for s in _system_symbols(derivation)}
    names |= {c.name for c in system.coordinates} | {q.name for q in system.quasi_coordinates}
    return names | {"M", "F", "G", "Q"}


def _system_symbols(derivation) -> set[sp.Symbol]:
    code = derivation.code
    exprs = [*(e for _, e in code.kinematic_equations), *(e for _, e in code.mass_matrix), *code.forcing]
    return {node for node in postorder(exprs) if node.is_Symbol}
