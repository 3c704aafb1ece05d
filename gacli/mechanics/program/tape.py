"""The tape a program is written on: scalar assignments, each named once, in evaluation order.

:class:`Tape` is a builder object, not a frozen record, because value
numbering needs one memo over the whole build: an expression already on the
tape (or its negative) is never written twice, whichever step asks for it.
Each assignment carries the stage it was written in (for reports), and may
carry a *label*, a tuple saying what physical quantity it is (``("w", frame,
pass key, component)``: a component of a frame's angular velocity along its
own axes; see gacli.display.named), which the printout names it by. The tape
also knows the value of every assignment at a few seeded generic points, so
that the builder can tell an entry that vanishes identically (a row entry,
a moment that cancels), as the loader does for its rolling rows
(gacli.numeric.zero.vanishes: three generic points, a value below 1e-12
taken as zero); the tolerance here is relative to the terms' size.
"""

from __future__ import annotations

import cmath
import random
from fractions import Fraction
from collections.abc import Iterable

import sympy as sp

ZERO = sp.S.Zero

from gacli.algebra.coerce import as_expr
from gacli.numeric import Program as Evaluator
from gacli.numeric.samples import SAMPLE_INTERVAL
from gacli.numeric.spheres import scaled_onto

# Assigned symbols are named so that no declared name can be one: the grammar's names are
# identifiers, and brackets keep these apart as they keep the differentials d[x] apart.
NAME = "_p[{}]"
_SEEDS = (1, 2, 3)
_TOLERANCE = 1e-11


def _trivial(e: sp.Expr) -> bool:
    """An atom, or minus an atom: never worth a name."""
    return e.is_Atom or (e.is_Mul and len(e.args) == 2 and e.args[0] is sp.S.NegativeOne and e.args[1].is_Atom)


class Tape:
    """Assignments (symbol, expression, stage) with value numbering and numeric values at generic points."""

    def __init__(self, spheres: tuple = ()) -> None:
        # The generic points lie on the spheres the system keeps its coordinates on
        # (gacli.numeric.spheres): a contact point's height that is zero only where e·e = 1 is zero.
        self.spheres = tuple(spheres)
        self._spheres = {x: sphere for sphere in spheres for x in sphere.symbols}
        self.assignments: list[tuple[sp.Symbol, sp.Expr, str]] = []
        self.stage = ""
        self._memo: dict[sp.Expr, sp.Symbol] = {}
        self._points: list[dict[sp.Symbol, complex]] = [{} for _ in _SEEDS]
        self._draws = [random.Random(seed) for seed in _SEEDS]
        self._evaluated = 0
        self.labels: dict[sp.Symbol, tuple] = {}
        self._assigned: set[sp.Symbol] = set()  # the symbols written: a label may still name one

    def let(self, e, name: tuple | None = None) -> sp.Expr:
        """A symbol for ``e`` (its own, or the one already written for e or −e); atoms stay as they are.

        ``name``: the label of the quantity ``e`` is (see the module); a value already
        written keeps the label it was first given.
        """
        e = as_expr(e)
        if _trivial(e):
            if name is not None and e in self._assigned:
                # Already written (a vector turned into this frame): this is what it is, too.
                self.labels.setdefault(e, name)
            return e
        hit = self._memo.get(e)
        if hit is not None:
            if name is not None:
                self.labels.setdefault(hit, name)
            return hit
        # −e of a sum is a new sum of every term negated: an eighth of a bicycle's build, and
        # no sum of the repository's systems comes back negated; a product's −e is cheap.
        hit = None if e.is_Add else self._memo.get(-e)
        if hit is not None:
            return -hit
        scaled = self._scaled(e)
        if scaled is not None:
            e = scaled
            hit = self._memo.get(e)
            if hit is not None:
                if name is not None:
                    self.labels.setdefault(hit, name)
                return hit
        if e.is_Add and self._cancels(e):
            return ZERO
        label, name = name, sp.Symbol(NAME.format(len(self.assignments)), real=True)
        self.assignments.append((name, e, self.stage))
        self._memo[e] = name
        self._assigned.add(name)
        if label is not None:
            self.labels[name] = label
        return name

    def _scaled(self, e: sp.Expr) -> sp.Expr | None:
        """c·x when ``e`` is a number c ≠ ±1 times a product x (or −x) already on the tape: a
        centre's lever l/2 sin θ when the rows have l sin θ. None otherwise."""
        if not e.is_Mul or not e.args[0].is_Rational or e.args[0] in (1, -1):
            return None
        c, rest = e.as_coeff_Mul()
        hit = self._memo.get(rest)
        if hit is None:
            hit = self._memo.get(-rest)
            c = -c if hit is not None else c
        return None if hit is None else c * hit

    def closed_within(self, e: sp.Expr, names: int) -> sp.Expr | None:
        """:meth:`closed`, or None when ``e`` reads more than ``names`` assignments: the walk is
        bounded before any tree is formed (a bicycle's row entries read hundreds)."""
        index = {name: i for i, (name, _, _) in enumerate(self.assignments)}
        seen: set[sp.Symbol] = set()
        todo = [s for s in as_expr(e).free_symbols if s in index]
        while todo:
            s = todo.pop()
            if s in seen:
                continue
            seen.add(s)
            if len(seen) > names:
                return None
            todo += [x for x in self.assignments[index[s]][1].free_symbols if x in index]
        return self.closed(e)

    def closed(self, e: sp.Expr) -> sp.Expr:
        """``e`` with the assignments it reads written out, down to the state and the parameters
        (for small values only: a tree of every step)."""
        values = {name: value for name, value, _ in self.assignments}
        memo: dict[sp.Symbol, sp.Expr] = {}

        def out(x: sp.Expr) -> sp.Expr:
            names = [s for s in x.free_symbols if s in values]
            for s in names:
                if s not in memo:
                    memo[s] = out(values[s])
            return x.xreplace({s: memo[s] for s in names}) if names else x

        return out(as_expr(e))

    def vec(self, v: Iterable, name: tuple | None = None) -> tuple:
        """Each component let; ``name`` labels component i as ``(*name, i)``."""
        return tuple(self.let(c, None if name is None else (*name, i)) for i, c in enumerate(v))

    def values(self, e: sp.Expr) -> list[complex]:
        """``e`` (over state symbols and assigned ones) at each generic point."""
        return [v[0] for v in self._values([as_expr(e)])]

    def number(self, e) -> sp.Rational | None:
        """The small rational ``e`` equals at every generic point (a frame's partial angular velocity
        that is a unit vector, read through Euler angles' rates), or None."""
        e = as_expr(e)
        if e.is_Rational:
            return e
        values = self.values(e)
        first = values[0]
        if abs(first.imag) > _TOLERANCE or any(abs(v - first) > _TOLERANCE * max(1.0, abs(first)) for v in values):
            return None
        guess = Fraction(first.real).limit_denominator(12)
        return sp.Rational(guess.numerator, guess.denominator) if abs(float(guess) - first.real) < _TOLERANCE else None

    def nonzero(self, e, name: tuple | None = None) -> sp.Expr:
        """``e`` on the tape (:meth:`let`), or an exact zero where it vanishes at the generic points:
        so the sums and solves after it see the zero (a row entry, a moment, a rest that cancels)."""
        return ZERO if self.vanishes(e) else self.let(e, name=name)

    def vanishes(self, e) -> bool:
        """``e`` is zero at every generic point (relative to the size of its terms): taken as identically zero."""
        e = as_expr(e)
        if e == 0:
            return True
        terms = list(sp.Add.make_args(e))
        for values in self._values([e, *terms]):
            if not all(cmath.isfinite(v) for v in values):  # NaN compares false: never a zero
                return False
            if abs(values[0]) > _TOLERANCE * max([1.0] + [abs(v) for v in values[1:]]):
                return False
        return True

    def _cancels(self, e: sp.Expr) -> bool:
        """A sum whose terms cancel at every generic point, relative to the largest term alone (a
        vector turned into a frame and back, e sin φ − (e sin φ − r) − r): the sum is zero. Stricter
        than :meth:`vanishes`, with no absolute floor, so that a sum of terms that are small in
        themselves (a tiny parameter of the file) is never taken for zero."""
        terms = sp.Add.make_args(e)
        for values in self._values([e, *terms]):
            if not all(cmath.isfinite(v) for v in values):  # NaN compares false: never a zero
                return False
            largest = max(abs(v) for v in values[1:])
            if abs(values[0]) > 1e-12 * largest or largest == 0 and values[0] != 0:
                return False
        return True

    def _values(self, exprs: list[sp.Expr]) -> list[list[complex]]:
        """The expressions' values at each point (one compiled evaluation per point)."""
        self._catch_up()
        evaluate = Evaluator(exprs)
        return [evaluate(self._with(point, draw, evaluate.symbols)) for point, draw in zip(self._points, self._draws)]

    def _catch_up(self) -> None:
        """Evaluate the assignments written since the last question, in order, at every point."""
        for name, e, _ in self.assignments[self._evaluated:]:
            evaluate = Evaluator([e])
            for point, draw in zip(self._points, self._draws):
                point[name] = evaluate(self._with(point, draw, evaluate.symbols))[0]
        self._evaluated = len(self.assignments)

    def _with(self, point: dict, draw: random.Random, symbols) -> dict:
        """The point, with a generic value drawn for each state symbol seen for the first time
        (``symbols`` comes sorted by name, so the draws do not depend on hashing); a sphere's
        coordinates all at once, scaled onto it."""
        for s in symbols:
            if s not in point:
                sphere = self._spheres.get(s)
                if sphere is None:
                    point[s] = complex(draw.uniform(*SAMPLE_INTERVAL))
                else:
                    self._on_sphere(point, draw, sphere)
        return point

    def _on_sphere(self, point: dict, draw: random.Random, sphere) -> None:
        radius = sorted(sphere.radius2.free_symbols, key=lambda x: x.name)
        self._with(point, draw, radius)
        drawn = {x: draw.uniform(*SAMPLE_INTERVAL) for x in sphere.symbols}
        scaled = scaled_onto({**drawn, **{x: point[x].real for x in radius}}, (sphere,))
        point.update({x: complex(scaled[x]) for x in drawn})
