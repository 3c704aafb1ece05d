"""The rolling rows A ṙ = 0 over the coordinates' rates (eq. 14.1), and which rates are independent.

A contact's rows are v_C = 0 along its row directions (contacts.row_vectors);
a column is the contact's velocity for the pass of one coordinate rate.
Entries that vanish identically (the numeric test of the tape) are exact
zeros, so that the solve sees the sparsity; rows that vanish or repeat the
rows before them (two wheels on one axle) are left out, as gacli does
(mechanics.rates.relation_rows: a derived row that does not raise the rank).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from gacli.algebra.matrices import rank
from gacli.frame_model import INERTIAL, PointLink
from gacli.mechanics.program import contacts as C
from gacli.mechanics.program.motion import Motion
from gacli.mechanics.program.vectors import ONE, Pass, dot


@dataclass(frozen=True)
class Rows:
    """The kept rows: (contact, direction along its S) and, per coordinate, its column of entries."""

    directions: tuple[tuple[C.Contact, tuple], ...]
    columns: dict[str, list[sp.Expr]]

    def numbers(self, motion: Motion, names: list[str]) -> np.ndarray:
        """The rows at the tape's first generic point, over ``names``."""
        return numbers(motion.tape, self.columns, names)


def numbers(tape, columns: dict[str, list[sp.Expr]], names: list[str]) -> np.ndarray:
    """Rows given by their columns, at the tape's first generic point, over ``names``."""
    out = np.zeros((len(columns[names[0]]) if names else 0, len(names)), dtype=complex)
    for j, q in enumerate(names):
        for i, x in enumerate(columns[q]):
            out[i, j] = tape.values(x)[0] if x != 0 else 0
    return out


def free_root(links: dict[str, PointLink], contacts: list[C.Contact], coordinates: dict[str, sp.Symbol],
              independent: tuple[str, ...], level: frozenset = frozenset({INERTIAL})) -> tuple[str, C.Contact] | None:
    """A point at N's origin whose N components are dependent coordinates (or constants), with the
    contact nearest below it on a plane of ``level`` (N's, or a frame's fixed plane that is N's z = 0,
    as a z-down ground turned by π about x): (point, contact), or None."""
    symbols = {s: q for q, s in coordinates.items()}
    for root in (link for link in links.values() if link.parent is None and link.frame == INERTIAL):
        own = [symbols[x] for x in root.components if x in symbols]
        rest = [x for x in root.components if x not in symbols]
        if not own or any(x.free_symbols & symbols.keys() for x in rest) or set(own) & set(independent):
            continue
        best = None
        for c in (c for c in contacts if c.plane in level):  # another frame's plane moves under the root
            depth, point = 0, c.body.point
            while point is not None and point != root.name:
                point, depth = links[point].parent, depth + 1
            if point == root.name and (best is None or depth < best[0]):
                best = (depth, c)
        if best is not None:
            return root.name, best[1]
    return None


def root_coordinates(links: dict[str, PointLink], root: str | None, coordinates: dict[str, sp.Symbol]):
    """{coordinate: the index of the root's N component it is}."""
    if root is None:
        return {}
    symbols = {s: q for q, s in coordinates.items()}
    return {symbols[x]: i for i, x in enumerate(links[root].components) if x in symbols}


def rows(motion: Motion, contacts: list[C.Contact], reduced: list[str]) -> Rows:
    """The rows of ``contacts`` over the rates of ``reduced``, vanishing entries zero, repeated rows left out."""
    tape = motion.tape
    tape.stage = "rows"
    directions = [(c, e) for c in contacts for e in C.row_vectors(motion.tree, c)]
    columns = {q: _column(motion, directions, Pass(f"e_{q}", {q: ONE})) for q in reduced}
    every = Rows(tuple(directions), columns)
    numeric = every.numbers(motion, reduced)
    kept: list[int] = []
    for i in range(len(directions)):
        if rank(numeric[kept + [i]]) > len(kept):
            kept.append(i)
    return Rows(tuple(directions[i] for i in kept), {q: [col[i] for i in kept] for q, col in columns.items()})


def time_column(motion: Motion, kept: Rows) -> list[sp.Expr]:
    """a₀ of the kept rows: v_C − v_Q with every rate zero and ṫ = 1 (a plane moved or turned with
    time), vanishing entries zero."""
    return _column(motion, kept.directions, Pass("time", {}, timed=True))


def _column(motion: Motion, directions, rates: Pass) -> list[sp.Expr]:
    """Each row's v_C − v_Q along its direction for the pass, vanishing entries zero."""
    velocities = {}
    for c, _ in directions:
        if c.body.name not in velocities:
            velocities[c.body.name] = motion.contact_velocity(c, rates)
    return [motion.tape.nonzero(dot(e, velocities[c.body.name])) for c, e in directions]


def earliest_independent(numeric: np.ndarray, names: list[str]) -> tuple[str, ...]:
    """gacli's automatic choice (mechanics.rates): the dependent rates index a basis of the columns,
    taken greedily from the last, so that the earliest-declared names stay independent."""
    basis: list[int] = []
    for j in reversed(range(len(names))):
        if rank(numeric[:, basis + [j]]) > len(basis):
            basis.append(j)
    return tuple(n for j, n in enumerate(names) if j not in basis)
