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
coefficients: only I_zz then enters eq. (14.17)), and each position is a
part in N plus terms c cos φ, c sin φ with φ linear in the coordinates,
paired as the components of one vector along the frame turned by φ.
"""

from __future__ import annotations

import itertools

import sympy as sp

from gacli.algebra import symbols as S
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
        angle = builder.angle(body.rotation) if body.rotation is not None else None
        if angle is not None:
            builder.names.setdefault(angle, body.name)
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
    None when a term is not c cos φ or c sin φ paired as one vector's components."""
    x, y, z = (sp.expand(c) for c in position)
    if z.free_symbols & coordinates:
        return None
    rest, parts = [sp.S.Zero, sp.S.Zero], {}
    for i, component in enumerate((x, y)):
        for term in sp.Add.make_args(component):
            split = _turned(term, coordinates)
            if split is None:
                return None
            if split[0] is None:
                rest[i] += term
                continue
            angle, kind, c = split
            parts.setdefault(angle, {}).setdefault((i, kind), []).append(c)
    out = [(sp.S.Zero, (rest[0], rest[1], z))] if (rest[0] != 0 or rest[1] != 0 or z != 0) else []
    for angle in sorted(parts, key=lambda a: (len(sp.Add.make_args(a)), sp.default_sort_key(a))):
        vector = _along(parts[angle])
        if vector is None:
            return None
        out.append((angle, vector))
    return out or [(sp.S.Zero, (sp.S.Zero, sp.S.Zero, sp.S.Zero))]


def _turned(term: sp.Expr, coordinates: set):
    """(angle, 'cos' or 'sin', coefficient) of c·cos φ or c·sin φ; (None,) for a term with no
    turn in it; None for any other term that holds the coordinates in a function."""
    trig = [f for f in sp.Mul.make_args(term) if isinstance(f, (sp.cos, sp.sin)) and f.free_symbols & coordinates]
    if not trig:
        if any(isinstance(f, sp.Function) or (f.is_Pow and not f.exp.is_Integer)
               for f in sp.preorder_traversal(term) if f.free_symbols & coordinates and f is not term):
            return None
        return (None,)
    if len(trig) != 1:
        return None
    f = trig[0]
    angle = f.args[0]
    c = term / f
    if not angle.is_polynomial(*coordinates) or sp.Poly(angle, *sorted(coordinates, key=str)).total_degree() != 1:
        return None
    if not all(sp.diff(angle, q).is_number for q in angle.free_symbols & coordinates):
        return None
    if angle.free_symbols - coordinates or (c.free_symbols & coordinates and not c.is_polynomial(*coordinates)):
        return None
    return angle, "cos" if isinstance(f, sp.cos) else "sin", c


def _along(part: dict) -> tuple | None:
    """(u, v, 0) along the frame turned by φ from x = u cos φ − v sin φ, y = u sin φ + v cos φ."""
    xc, xs, yc, ys = (sp.Add(*part.get(key, [])) for key in ((0, "cos"), (0, "sin"), (1, "cos"), (1, "sin")))
    if sp.expand(xc - ys) != 0 or sp.expand(yc + xs) != 0:
        return None
    return (xc, yc, sp.S.Zero)
