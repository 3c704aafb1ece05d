"""A planar file without frames read as a tree of frames, one per angle its positions turn by.

A chain written out by hand puts its third bar's centre at
(l₁ cos q₁ + l₂ cos(q₁ + q₂) + ½ l₃ cos(q₁ + q₂ + q₃), l₁ sin q₁ + …): the
sum of one vector along each of three frames, each turned from the one
before by one coordinate. Read so, the frame-tree program forms its
velocities as the same chain written with frames does (each link's ω × r
in its own frame), where the positions' partial derivatives cost a product
of angle sums per pair of bars (a four-link chain: 347 operations against
231 with frames, Kane 295). The builder builds this reading beside the
plain one and keeps the cheaper (gacli.mechanics.program.build).

Read so only when every body moves in the plane z = const and turns about
z by a sum of coordinates (its rotation form integrable with constant
coefficients: only I_zz then enters eq. (14.17)), and each position holds
the coordinates only in sines and cosines of whole combinations of them
(x + i y is then a sum of turns, gacli.algebra.turns: one vector along
the frame each combination turns, however the file wrote the sums).
"""

from __future__ import annotations

import itertools

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra import turns as T
from gacli.frame_model import INERTIAL, BodyPlacement, FrameEdge, FrameModel, FrameVector, Load, PointLink
from gacli.model import Form, System

Z = 2  # the axis every frame turns about


def planar_frames(system: System) -> FrameModel | None:
    """The frame tree of a planar file without frames (see the module), or None."""
    if system.frames is not None or not system.bodies:
        return None
    coordinates = {S.value(c.name): c.name for c in system.coordinates}
    builder = _Builder(coordinates)
    for body in system.bodies:  # a body's frame is named after it, whatever needs it first
        turn = builder.angle(body.rotation) if body.rotation is not None else None
        if turn is not None:
            builder.names.setdefault(turn, body.name)
    bodies = []
    for body in system.bodies:
        frame = builder.turned_by(body.rotation) if body.rotation is not None else None
        point = builder.point(body.position, f"{body.name}@")
        if point is None or (body.rotation is not None and frame is None):
            return None
        bodies.append(BodyPlacement(body.name, body.mass, point, frame, body.inertia if frame else None))
    loads = _loads(system, builder, {b.name: b.frame for b in bodies})
    if loads is None or len(builder.edges) < 2:
        return None
    return FrameModel(tuple(builder.edges), (), tuple(builder.links), tuple(bodies), (), loads)


def _loads(system: System, builder: "_Builder", frames: dict) -> tuple[Load, ...] | None:
    out = []
    for i, force in enumerate(system.forces):
        point = builder.point(force.point, f"forces[{i}]@")
        if point is None:
            return None
        out.append(Load(FrameVector(((INERTIAL, force.vector),)), False, point=point))
    for torque in system.torques:
        if frames.get(torque.body) is None:
            return None
        out.append(Load(FrameVector(((frames[torque.body], torque.vector),)), True, body=torque.body))
    return tuple(out)


class _Builder:
    """Frames per angle and point links per prefix of terms, each made once and shared."""

    def __init__(self, coordinates: dict) -> None:
        self.coordinates = coordinates
        self.frames: dict = {sp.S.Zero: INERTIAL}
        self.edges: list[FrameEdge] = []
        self.links: list[PointLink] = []
        self.names: dict = {}  # angle → the name of its frame, a body's own
        self._prefixes: dict = {}

    def angle(self, rotation: tuple[Form, Form, Form]) -> sp.Expr | None:
        """Σ c_s q_s of a body whose rotation forms are (0, 0, Σ c_s dq_s), c_s numbers; or None."""
        x, y, z = rotation
        if x.coefficients or y.coefficients or x.dt != 0 or y.dt != 0 or z.dt != 0:
            return None
        names = set(self.coordinates.values())
        if not all(n in names and c.is_number for n, c in z.coefficients):
            return None
        return sp.Add(*(c * S.value(n) for n, c in z.coefficients))

    def turned_by(self, rotation: tuple[Form, Form, Form]) -> str | None:
        """The frame of a body turned by :meth:`angle`; or None."""
        angle = self.angle(rotation)
        return self.frame(angle) if angle is not None else None

    def frame(self, angle: sp.Expr) -> str:
        """The frame turned by ``angle`` from N, hung from the frame whose angle differs least from it."""
        if angle in self.frames:
            return self.frames[angle]
        parent = min(self.frames, key=lambda a: (len(sp.Add.make_args(angle - a)), -len(sp.Add.make_args(a))))
        name = self.names.get(angle) or next(f"frame{i}" for i in itertools.count(len(self.edges) + 1)
                                             if f"frame{i}" not in self.names.values())
        self.edges.append(FrameEdge(name, self.frames[parent], Z, angle - parent))
        self.frames[angle] = name
        return name

    def point(self, position, name: str) -> str | None:
        """The point link at ``position`` (N components), its terms along their frames, the last link
        ``name`` unless another position ran through it first; or None."""
        terms = _terms(position, set(self.coordinates))
        if terms is None:
            return None
        parent, prefix = None, ()
        for i, (angle, components) in enumerate(terms):
            prefix += ((angle, components),)
            if prefix not in self._prefixes:
                link = name if i == len(terms) - 1 else f"joint{len(self.links) + 1}"
                frame = self.frame(angle) if angle != 0 else INERTIAL
                self.links.append(PointLink(link, parent, frame, components))
                self._prefixes[prefix] = link
            parent = self._prefixes[prefix]
        return parent


def _terms(position, coordinates: set) -> list[tuple[sp.Expr, tuple]] | None:
    """[(angle, components along the frame turned by it)], N's part first (angle 0), then by angle;
    None when the position is not planar, too large, or turns by other than whole multiples of the
    coordinates. x + i y is a sum of turns Σ c_m e^(i m·q) (gacli.algebra.turns): each is the vector
    (Re c_m, Im c_m) along the frame turned by m·q, whether the file wrote cos(q1 + q2) or
    cos q1 cos q2 − sin q1 sin q2, and the part with m = 0 lies along N."""
    x, y, z = (sp.S(c) for c in position)
    if z.free_symbols & coordinates:
        return None
    order = sorted(coordinates, key=str)
    parts = T.turns(x + sp.I * y, order)
    if parts is None or len(parts) > _MOST_TURNS_PER_SINE * _sines(x, y) + 1:
        return None
    offsets = _offsets([x, y], order)
    out = []
    for m in sorted(parts, key=lambda m: (sum(k != 0 for k in m), [abs(k) for k in m], m)):
        alpha = offsets.get(m, sp.S.Zero)  # a frame turned by q1 + π/6 when the file writes so
        u, v = T.real_imaginary(sp.expand(parts[m] * (sp.cos(alpha) - sp.I * sp.sin(alpha))))
        if u.has(sp.I):
            return None
        phi = T.angle(m, order) + alpha
        out.append((phi, (u, v, z if phi == 0 else sp.S.Zero)))
    if z != 0 and not any(phi == 0 for phi, _ in out):
        out.insert(0, (sp.S.Zero, (sp.S.Zero, sp.S.Zero, z)))
    return out or [(sp.S.Zero, (sp.S.Zero, sp.S.Zero, sp.S.Zero))]


# A chain's written-out position has a turn per link, a product cos q1 cos q2 two, cos³ q four: a
# position with many more turns than sines and cosines (a power, (sin x + cos y)**20: 441 turns, one
# frame each) is not a chain, and reading it as one costs what its expansion costs, not the system.
_MOST_TURNS_PER_SINE = 4


def _sines(*components) -> int:
    """The sines and cosines written in ``components`` (a tree count, as the file wrote them)."""
    return sum(isinstance(f, (sp.sin, sp.cos)) for c in components for f in sp.preorder_traversal(c))


def _offsets(components: list, order: list) -> dict[tuple, sp.Expr]:
    """{m: α} where the sines and cosines of the components turn by m·q + α with one constant α ≠ 0."""
    found: dict[tuple, set] = {}
    for f in (f for c in components for f in sp.preorder_traversal(c) if isinstance(f, (sp.cos, sp.sin))):
        m = tuple(sp.diff(f.args[0], q) for q in order)
        if any(k != 0 for k in m):
            found.setdefault(m, set()).add(sp.expand(f.args[0] - T.angle(m, order)))
    return {m: alpha.pop() for m, alpha in found.items() if len(alpha) == 1 and next(iter(alpha)) != 0}
