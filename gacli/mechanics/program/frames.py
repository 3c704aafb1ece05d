"""The frames as a tree of simple rotations: vectors carried between frames, ω and α of each frame.

A vector lives in one frame and is carried to another one rotation at a
time (4 products and 2 sums each); successive rotations about one axis are
merged into one, by the sum of their angles (a bicycle's head tube turned
by pitch + head angle). ω of a frame comes from its parent's by the
transport theorem, ω_F = Rᵀ ω_G + Σ θ̇ e, for any pass of rates (see
:class:`~gacli.mechanics.program.vectors.Pass`); α with all accelerations
zero, the velocity-product part of eq. (14.14), is α_F = Rᵀ α_G + (Σ θ̇) ω_F × e, plus
(Σ θ̈ with q̈ = 0) e where an angle holds time (a turntable driven at a prescribed angle) or is
not linear in the coordinates.

A frame turned by a quaternion (an edge with ``quaternion``) is one general
rotation: its nine direction cosines named once, ω_F = Rᵀ ω_G + ω_rel with
ω_rel its rates (or 2 G(e) ė), and α_F = Rᵀ α_G + ω_F × ω_rel, since
G(ė) ė = 0 leaves ω̇_rel no velocity-product part.
"""

from __future__ import annotations

import sympy as sp

from gacli.frame_model import INERTIAL, FrameEdge
from gacli.loader.frames import quaternion_rates, quaternion_rotation
from gacli.mechanics.program.tape import Tape
from gacli.mechanics.program.vectors import ONE, ZERO, ZV, Pass, add, cross, scale, turned, unit


class FrameTree:
    """The frame tree on a tape; a builder object whose caches write each ω, α, N.z once per frame and pass."""

    def __init__(self, tape: Tape, edges: tuple[FrameEdge, ...], coordinates: dict[str, sp.Symbol],
                 time: dict[sp.Symbol, sp.Expr] | None = None) -> None:
        self.tape = tape
        self.edges = {e.name: e for e in edges}
        # θ̇ of each edge as Σ (∂θ/∂q) q̇ + θ_t; θ̈ adds what held_acceleration says.
        self.grad = {e.name: {q: sp.diff(e.angle, s) for q, s in coordinates.items() if e.angle.has(s)} for e in edges}
        self.time = time or {}
        self._timed = {e.name: time_rate(e.angle, self.time) for e in edges}
        # The partial passes and their speeds, once known, where the actual rates are Σ β u alone
        # (build.py): a component of ω that is a number for every partial pass is Σ c u.
        self.speeds: list[tuple[Pass, sp.Expr]] = []
        self.names = {s: q for q, s in coordinates.items()}
        self._rotation: dict = {}
        self._omega: dict = {}
        self._alpha: dict = {}
        self._nz: dict = {INERTIAL: (ZERO, ZERO, ONE)}
        self._carried: dict = {}

    def chain(self, frame: str) -> list[str]:
        """The frame and its ancestors up to N."""
        out = [frame]
        while frame != INERTIAL:
            frame = self.edges[frame].parent
            out.append(frame)
        return out

    def path(self, src: str, dst: str) -> list[tuple[int, object]]:
        """The rotations (axis, angle) taking components along src to components along dst,
        consecutive ones about one axis merged; a quaternion's is (-1, (edge, up))."""
        a, b = self.chain(src), self.chain(dst)
        common = next(f for f in a if f in b)
        steps = [self._along(f, True) for f in a[:a.index(common)]]
        steps += [self._along(f, False) for f in reversed(b[:b.index(common)])]
        merged: list[tuple[int, object]] = []
        for axis, angle in steps:
            if merged and axis >= 0 and merged[-1][0] == axis:
                merged[-1] = (axis, merged[-1][1] + angle)
            else:
                merged.append((axis, angle))
        return [(axis, angle) for axis, angle in merged if axis < 0 or angle != 0]

    def _along(self, edge: str, up: bool) -> tuple[int, object]:
        e = self.edges[edge]
        if e.quaternion is not None:
            return -1, (edge, up)
        return e.axis, e.angle if up else -e.angle

    def rotation(self, edge: str) -> list[list[sp.Expr]]:
        """A quaternion edge's direction cosines (v_parent = R v_child), each entry named once."""
        if edge not in self._rotation:
            R = quaternion_rotation(self.edges[edge].quaternion)
            self._rotation[edge] = [[self.tape.let(R[i, j]) for j in range(3)] for i in range(3)]
        return self._rotation[edge]

    def rotate(self, edge: str, v, up: bool) -> tuple:
        """v carried across a quaternion edge: R v to the parent (``up``), Rᵀ v back."""
        R = self.rotation(edge)
        rows = R if up else [list(column) for column in zip(*R)]
        return self.tape.vec(sp.Add(*(x * y for x, y in zip(row, v) if x != 0 and y != 0)) for row in rows)

    def relative(self, edge: str, rates: Pass) -> tuple:
        """ω of a quaternion edge's frame relative to its parent, along its axes: its rates, or 2 G(e) ė."""
        e = self.edges[edge]
        if e.rates:
            return tuple(rates.rate(w) for w in e.rates)
        G = quaternion_rates(e.quaternion)
        edot = [rates.rate(self.names[x]) for x in e.quaternion]
        return tuple(2 * sp.Add(*(G[i, j] * edot[j] for j in range(4))) for i in range(3))

    def turn(self, axis: int, angle: sp.Expr, v) -> tuple:
        """R(angle) v about a frame axis (v_parent = R v_child); cos and sin of the angle named once."""
        c, s = self.tape.let(sp.cos(angle)), sp.sin(angle)
        s = -self.tape.let(-s) if s.could_extract_minus_sign() else self.tape.let(s)
        return self.tape.vec(turned(v, axis, c, s))

    def express(self, v, src: str, dst: str, key=None) -> tuple:
        """v's components along dst, from its components along src (``key``: remember the result)."""
        if src == dst:
            return tuple(v)
        if key is not None and (key, dst) in self._carried:
            return self._carried[(key, dst)]
        out = tuple(v)
        for axis, angle in self.path(src, dst):
            out = self.turn(axis, angle, out) if axis >= 0 else self.rotate(angle[0], out, angle[1])
        if key is not None:
            self._carried[(key, dst)] = out
        return out

    def group(self, frame: str) -> tuple[str, int, list[str]]:
        """The frame's nearest ancestor G not reached from it by rotations about its own last axis:
        (G, the axis, the edges between)."""
        e = self.edges[frame]
        if e.quaternion is not None:
            return e.parent, -1, [frame]
        edges, top = [frame], e.parent
        while top != INERTIAL and self.edges[top].axis == e.axis:
            edges.append(top)
            top = self.edges[top].parent
        return top, e.axis, edges

    def turning_group(self, frame: str) -> tuple[str, int, list[str]]:
        """:meth:`group`, or the frame's parent alone when that parent's ω is a number for every
        partial pass (its speeds are its body rates): a rotor turned by ρ from a shell whose ω is
        u takes the shell's ω turned by ρ, not its Euler angles' ψ + ρ."""
        top, axis, edges = self.group(frame)
        parent = self.edges[frame].parent
        if len(edges) > 1 and self.speeds and all(x.is_Rational for p, _ in self.speeds for x in self.omega(parent, p)):
            return parent, axis, [frame]
        return top, axis, edges

    def rate(self, edge: str, rates: Pass) -> sp.Expr:
        """θ̇ of one edge for the pass's coordinate rates (and θ_t for a timed pass)."""
        rate = sp.Add(*(k * rates.rate(q) for q, k in self.grad[edge].items()))
        return rate + self.tape.let(self._timed[edge]) if rates.timed and self._timed[edge] != 0 else rate

    def timed(self, edge: str) -> bool:
        """The edge's angle holds time."""
        return self._timed[edge] != 0

    def held_acceleration(self, edges: list[str], actual: Pass) -> sp.Expr:
        """Σ θ̈ of the edges with every q̈ zero: θ̇'s d/dt with the rates held, Σ ∂²θ/∂q∂q' q̇ q̇'
        + 2 Σ ∂²θ/∂q∂t q̇ + θ_tt; zero for an angle linear in the coordinates and not in time."""
        total = []
        for e in edges:
            rate = sp.Add(*(k * actual.rate(q) for q, k in self.grad[e].items()), self._timed[e])
            moved = sp.Add(*(sp.diff(rate, s) * actual.rate(q) for s, q in self.names.items() if rate.has(s)))
            total.append(moved + time_rate(rate, self.time))
        return self.tape.let(sp.Add(*total))

    def omega(self, frame: str, rates: Pass) -> tuple:
        """ω of the frame along its own axes for the pass: ω_F = Rᵀ ω_G + Σ θ̇ e."""
        if frame == INERTIAL:
            return ZV
        key = (frame, rates.key)
        if key not in self._omega:
            top, axis, edges = self.turning_group(frame)
            w = list(self.express(self.omega(top, rates), top, frame))
            if axis < 0:
                w = add(w, self.relative(frame, rates))
            else:
                w[axis] = w[axis] + sp.Add(*(self.rate(e, rates) for e in edges))
            self._omega[key] = self.tape.vec(self._simplest(frame, rates, w), name=("w", frame, rates.key))
        return self._omega[key]

    def _simplest(self, frame: str, rates: Pass, w: list) -> list:
        """ω's components as numbers where a partial pass's are (a frame whose rates are stated as
        its body rates: ω = u through Euler angles' rates), and the actual ω then Σ c u."""
        partial = [p for p, _ in self.speeds]
        if any(rates is p for p in partial):
            return [x if (n := self.tape.number(x)) is None else n for x in w]
        if rates.key != "actual" or not self.speeds:
            return w
        columns, spoken = [self.omega(frame, p) for p in partial], self._spoken(frame)
        return [sp.Add(*(c[i] * u for c, (_, u) in zip(columns, self.speeds)))
                if i in spoken else x for i, x in enumerate(w)]

    def alpha0(self, frame: str, actual: Pass, gamma: Pass | None = None) -> tuple:
        """α of the frame with all accelerations zero: α_F = Rᵀ α_G + (Σ θ̇) ω_F × e (+ θ̈ held) e.

        With ``gamma`` (the dependent accelerations of u̇ = 0, eq. 14.14), the rest α with u̇ = 0
        instead: each level adds its θ̇ for γ, and a component of ω that is Σ c u with constant c
        (:meth:`_simplest`) has no rest at all, since ω's components along F change as α's do. A
        body whose speeds are its body rates so has α = u̇ with no term to cancel (Routh's sphere
        read through its Euler angles: α₀ and γ's part, each long, summed to zero)."""
        if frame == INERTIAL:
            return ZV
        key = (frame, gamma is not None)
        if key not in self._alpha:
            top, axis, edges = self.turning_group(frame)
            a = self.express(self.alpha0(top, actual, gamma), top, frame)
            rate = sp.Add(*(self.rate(e, actual) for e in edges))
            if axis < 0:
                a = add(a, cross(self.omega(frame, actual), self.relative(frame, actual)))
                a = a if gamma is None else add(a, self.relative(frame, gamma))
            else:
                if rate != 0:
                    a = add(a, scale(rate, cross(self.omega(frame, actual), unit(axis))))
                held = self.held_acceleration(edges, actual)
                if gamma is not None:
                    held = held + sp.Add(*(self.rate(e, gamma) for e in edges))
                if held != 0:
                    a = add(a, scale(held, unit(axis)))
            if gamma is not None:
                a = [ZERO if i in self._spoken(frame) else x for i, x in enumerate(a)]
            self._alpha[key] = self.tape.vec(a, name=("alpha", frame, actual.key if gamma is None else "rest"))
        return self._alpha[key]

    def _spoken(self, frame: str) -> set[int]:
        """The components of ω along the frame that are Σ c u with constant c (see :meth:`_simplest`)."""
        if not self.speeds:
            return set()
        columns = [self.omega(frame, p) for p, _ in self.speeds]
        return {i for i in range(3) if all(c[i].is_Rational for c in columns)}

    def varying(self, frame: str, partial, top: str | None = None) -> int:
        """How many components of the frame's partial ω (along ``top``, else its own axes) are not
        numbers: the frame where a body's rotation is simplest has the fewest."""
        return sum(1 for p in partial for x in self.omega_along(frame, top or frame, p)
                   if x != 0 and self.tape.number(x) is None)

    def over(self, frame: str, top: str, rates: Pass) -> tuple:
        """ω of ``frame`` relative to its ancestor ``top``, along top's axes: Σ θ̇ of the edges
        between, each along its axis turned into top (an Euler-angle body's ω along N is
        φ̇ z + θ̇ (cos φ, sin φ, 0) + ψ̇ ..., not its body components turned up three times)."""
        key = ("over", frame, top, rates.key)
        if key not in self._omega:
            out, f = ZV, frame
            while f != top:
                out = add(out, self._relative_along(f, top, rates) if self.edges[f].axis < 0
                          else scale(self.rate(f, rates), self._axis(f, top)))
                f = self.edges[f].parent
            self._omega[key] = self.tape.vec(out)
        return self._omega[key]

    def alpha_over(self, frame: str, top: str, actual: Pass, gamma: Pass | None = None) -> tuple:
        """The rate of :meth:`over`'s components along top with all accelerations zero (with
        ``gamma``: with u̇ = 0): each edge's held θ̈ (and θ̇ for γ) along its axis, and its θ̇
        times the turning of that axis, ω of its parent relative to top × the axis."""
        out, f = ZV, frame
        while f != top:
            parent = self.edges[f].parent
            if self.edges[f].axis < 0:  # a quaternion's ω relative to its parent: held, its components
                # do not change (body rates, or 2 G(e) ė with G(ė) ė = 0); only their turning into top
                turned = self._relative_along(f, top, actual)
                out = add(out, cross(self.over(parent, top, actual), turned))
                if gamma is not None:
                    out = add(out, self._relative_along(f, top, gamma))
            else:
                axis = self._axis(f, top)
                rest = self.held_acceleration([f], actual) + (self.rate(f, gamma) if gamma is not None else ZERO)
                out = add(out, scale(rest, axis), scale(self.rate(f, actual), cross(self.over(parent, top, actual), axis)))
            f = parent
        return self.tape.vec(out)

    def _relative_along(self, edge: str, top: str, rates: Pass) -> tuple:
        """A quaternion edge's ω relative to its parent (:meth:`relative`) along its ancestor ``top``."""
        return self.express(self.relative(edge, rates), edge, top)

    def omega_along(self, frame: str, top: str, rates: Pass) -> tuple:
        """ω of ``frame`` along its ancestor ``top``: ω_top + :meth:`over`."""
        if frame == top:
            return self.omega(frame, rates)
        return self.tape.vec(add(self.omega(top, rates), self.over(frame, top, rates)))

    def alpha_along(self, frame: str, top: str, actual: Pass, gamma: Pass | None = None) -> tuple:
        """α of ``frame`` along its ancestor ``top`` with all accelerations zero (with ``gamma``:
        u̇ = 0): α_top + ω_top × ω_rel + the rate of ω_rel along top (:meth:`alpha_over`)."""
        if frame == top:
            return self.alpha0(frame, actual, gamma)
        relative = self.over(frame, top, actual)
        return self.tape.vec(add(self.alpha0(top, actual, gamma), cross(self.omega(top, actual), relative),
                                 self.alpha_over(frame, top, actual, gamma)))

    def common(self, a: str, b: str) -> str:
        """The nearest frame both ``a`` and ``b`` hang from (N at the latest)."""
        chain = self.chain(b)
        return next(f for f in self.chain(a) if f in chain)

    def _axis(self, edge: str, top: str) -> tuple:
        """The axis an edge turns about, along its ancestor ``top``."""
        e = self.edges[edge]
        return self.express(unit(e.axis), e.parent, top, key=("axis", edge))

    def above(self, frame: str, top: str) -> list[str] | None:
        """The edges from ``frame`` up to its ancestor ``top`` (about a frame axis, or a quaternion's);
        None when top is not an ancestor."""
        chain = self.chain(frame)
        if top not in chain:
            return None
        return chain[:chain.index(top)]

    def nz(self, frame: str) -> tuple:
        """N's z axis along the frame's axes (a turn about it changes nothing: from the group's top)."""
        if frame not in self._nz:
            top = self.group(frame)[0]
            self._nz[frame] = self.express(self.nz(top), top, frame)
        return self._nz[frame]

    def step(self, edge: str, v, up: bool) -> tuple:
        """v carried across one edge: from the edge's frame to its parent (``up``) or back."""
        e = self.edges[edge]
        if e.quaternion is not None:
            return self.rotate(edge, v, up)
        return self.turn(e.axis, e.angle if up else -e.angle, v)

    def constant(self, edge: str) -> bool:
        """The edge's angle depends on no coordinate and not on time (a quaternion's always moves)."""
        return not self.grad[edge] and self._timed[edge] == 0 and self.edges[edge].quaternion is None


def time_rate(e: sp.Expr, time: dict[sp.Symbol, sp.Expr]) -> sp.Expr:
    """∂e/∂t along the time chain (t → 1, a free function → its rate), the coordinates held still."""
    return sp.Add(*(sp.diff(e, x) * dx for x, dx in time.items() if e.has(x)))
