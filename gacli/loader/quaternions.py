"""Frames oriented by Euler parameters, for the loader's builder (docs/frames.md, "Quaternions").

A frame ``{quaternion: [e0, e1, e2, e3]}`` is turned from its parent by the
unit quaternion of four coordinates. gacli adds what a format-1 file states
by hand: the unit norm e·e = 1 as a holonomic constraint (its differential
e·de = 0 a Pfaffian row, eq. 14.1), and, when the frame names ``rates``, the
three quasi-coordinates whose differentials are the components of ω dt along
the frame's axes relative to its parent, dw = 2 G(e) de (eq. 14.2). The
frame's own ω dt is then [dw1, dw2, dw3] on top of its parent's, so that a
body's angular velocity is its rates, not a quotient of the parameters'.
:class:`Quaternions` is a part of :class:`gacli.loader.loading._Builder`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from gacli.algebra import symbols as S
from gacli.loader import frames as F
from gacli.model import Constraint, Form, QuasiCoordinate
from gacli.read.reader import did_you_mean
from gacli.read.schema import FrameDecl

_KINDS = {"parameter": "a parameter", "function": "a function of time", "input": "an input",
          "quasi": "a quasi-coordinate"}


@dataclass(frozen=True)
class QuaternionFrame:
    """A frame turned by Euler parameters: its declaration, the parameters and its rates' names."""

    decl: FrameDecl
    parameters: tuple[str, str, str, str]
    rates: tuple[str, ...]


class Quaternions:
    """Quaternion frames, their unit norms and the quasi-coordinates of their rates."""

    def _quaternion_frame(self, decl: FrameDecl, parent: F.Frame) -> F.Frame | None:
        """The frame, or None (and located errors) when a name is not what it must be."""
        where = f"frames.{decl.name}"
        parameters = self._quaternion_names(decl, where)
        rates = self._rate_names(decl, where)
        if parameters is None or rates is None:
            return None
        e = [S.value(n) for n in parameters]
        self.quaternion_frames.append(QuaternionFrame(decl, parameters, rates))
        self.parsed[id(decl)] = (tuple(e), rates)  # kept for the frame model (gacli.loader.frame_records)
        width = len(self.scopes.rate_names) + 1
        if rates:
            relative = sp.zeros(3, width)
            for i, name in enumerate(rates):
                relative[i, self.scopes.rate_names.index(name)] = 1
        else:
            relative = 2 * F.quaternion_rates(e) * sp.Matrix.vstack(*(self.differential(x) for x in e))
        return F.quaternion_oriented(decl.name, parent, e, relative)

    def _quaternion_names(self, decl: FrameDecl, where: str) -> tuple[str, ...] | None:
        """The four Euler parameters: coordinates, each turning one frame only."""
        kinds = {s.name: s.kind for s in self.decl.symbols}
        taken = {n: q.decl.name for q in self.quaternion_frames for n in q.parameters}
        for i, node in enumerate(decl.quaternion):
            name, place = node.text, f"{where}.quaternion[{i}]"
            if kinds.get(name) != "coordinate":
                why = (f"'{name}' is {_KINDS[kinds[name]]}" if name in kinds
                       else f"'{name}' is not declared")
                self.error(node, place, f"{why}; a quaternion's Euler parameters are coordinates, which gacli "
                           "keeps on the unit sphere e0² + e1² + e2² + e3² = 1",
                           did_you_mean(name, [n for n, k in kinds.items() if k == "coordinate"]))
                return None
            if name in taken:
                self.error(node, place, f"'{name}' is already an Euler parameter of frame '{taken[name]}'")
                return None
        return tuple(n.text for n in decl.quaternion)

    def _rate_names(self, decl: FrameDecl, where: str) -> tuple[str, ...] | None:
        """The body rates: quasi-coordinates declared without a differential, each a rate of one frame."""
        kinds = {s.name: s for s in self.decl.symbols}
        taken = {n: q.decl.name for q in self.quaternion_frames for n in q.rates}
        for i, node in enumerate(decl.rates):
            name, place = node.text, f"{where}.rates[{i}]"
            symbol = kinds.get(name)
            if symbol is None or symbol.kind != "quasi":
                why = f"'{name}' is {_KINDS.get(symbol.kind, 'a coordinate')}" if symbol else f"'{name}' is not declared"
                self.error(node, place, f"{why}; a frame's rates are quasi-coordinates",
                           "declare it under quasi_coordinates without a differential: the frame gives it one")
                return None
            if symbol.differential is not None:
                self.error(node, place, f"the quasi-coordinate '{name}' has a differential of its own; "
                           "as a frame's rate its differential is the frame's ω dt",
                           f"leave out 'differential' of quasi_coordinates.{name}")
                return None
            if name in taken:
                self.error(node, place, f"'{name}' is already a rate of frame '{taken[name]}'")
                return None
        return tuple(n.text for n in decl.rates)

    def _unit_norms(self) -> tuple[Constraint, ...]:
        """e·e − 1 = 0 for every quaternion frame, a holonomic constraint used through e·de = 0."""
        out = []
        for q in self.quaternion_frames:
            e = [S.value(n) for n in q.parameters]
            text = f"{' + '.join(f'{n}**2' for n in q.parameters)} = 1 (unit quaternion of frame {q.decl.name})"
            out.append(self._holonomic(sp.Add(*(x * x for x in e)) - 1, self.where_of(q.decl.node), text))
        return tuple(out)

    def _frame_rates(self, quasi: tuple[QuasiCoordinate, ...]) -> tuple[QuasiCoordinate, ...]:
        """The quasi-coordinates with the differentials their frames give them: dw = 2 G(e) de (eq. 14.2)."""
        definitions = {}
        for q in self.quaternion_frames:
            G = 2 * F.quaternion_rates([S.value(n) for n in q.parameters])
            for i, name in enumerate(q.rates):
                definitions[name] = Form(tuple((n, G[i, j]) for j, n in enumerate(q.parameters)))
        return tuple(replace(w, differential=definitions[w.name]) if w.name in definitions else w for w in quasi)
