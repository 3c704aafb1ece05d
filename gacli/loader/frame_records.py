"""The frame model (gacli.frame_model) of a file written with frames, from what the loader parsed.

The loader's builder parses every expression once and keeps the parsed
pieces it reads on the way (``parsed``, keyed by the declaration they come
from: a frame's rotations, a vector's components per frame, a rolling
contact's radius and axle); this module only arranges them into records.
No geometry is done here: the cost is a walk of the declarations.
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from gacli.frame_model import (INERTIAL, BodyPlacement, FrameEdge, FrameModel, FrameVector, KnifeEdge, Line,
                               Load, PointLink, RollingContact)
from gacli.model import Body
from gacli.read.schema import SystemDecl, VectorDecl, VelocityConstraintDecl

_AXES = {"x": 0, "y": 1, "z": 2}
_ZERO3 = (sp.S.Zero, sp.S.Zero, sp.S.Zero)


def frame_model(decl: SystemDecl, parsed: dict, bodies: tuple[Body, ...], owners: dict[str, str] | None = None,
                lines: tuple[Line, ...] = (), potential: sp.Expr = sp.S.Zero, work=None) -> FrameModel:
    """The records of ``decl``'s frames, points, bodies, rolling contacts and loads (a loaded file: no
    errors); ``lines``: the springs and dampers between their ends' names, and ``potential`` and
    ``work`` the file's own, without them."""
    links: list[PointLink] = []
    edges, origins = _edges(decl, parsed, links)
    for point in decl.points:
        _point(point.name, point.position, parsed, links)
    frames_of = {b.name: (b.frame.text if b.frame is not None else None) for b in decl.bodies}
    placements = tuple(
        BodyPlacement(b.name, b.mass, _point(f"{b.name}@", d.position, parsed, links) if d.position is not None
                      else _placed(b.name, parsed, links), frames_of[b.name], b.inertia)
        for b, d in zip(bodies, decl.bodies))
    centres = {b.name: b.point for b in placements}
    rolling = tuple(_rolling(r, parsed, frames_of) for r in decl.rolling)
    loads = tuple(_load(ld, parsed, links, frames_of, centres, owners or {}) for ld in decl.loads
                  if ld.force or ld.torque)
    loads += tuple(_reaction(ld, loads[i]) for i, ld in enumerate(l for l in decl.loads if l.force or l.torque)
                   if ld.reaction is not None)
    knives = tuple(KnifeEdge(c.point.text, _vector(c.along, parsed, INERTIAL)) for c in decl.constraints
                   if isinstance(c, VelocityConstraintDecl))
    between = tuple(replace(line, ends=tuple(centres.get(e, e) for e in line.ends)) for line in lines)
    return FrameModel(tuple(edges), tuple(origins), tuple(links), placements, rolling, loads, knives,
                      between, potential, work)


def _edges(decl: SystemDecl, parsed: dict, links: list[PointLink]) -> tuple[list[FrameEdge], list]:
    """Each frame as a chain of simple rotations (its inner links named frame#0 ...), and its origin."""
    edges, origins = [], []
    for frame in decl.frames:
        parent = frame.parent.text if frame.parent is not None else INERTIAL
        if frame.quaternion:
            e, rates = parsed[id(frame)]
            edges.append(FrameEdge(frame.name, parent, -1, sp.S.Zero, e, rates))
            if frame.origin is not None:
                origins.append((frame.name, _point(f"{frame.name}@origin", frame.origin, parsed, links)))
            continue
        rotations = parsed.get(id(frame), ()) or (("z", sp.S.Zero),)  # only an origin: the parent's axes
        for i, (axis, angle) in enumerate(rotations):
            name = frame.name if i == len(rotations) - 1 else f"{frame.name}#{i}"
            edges.append(FrameEdge(name, parent, _AXES[axis], angle))
            parent = name
        if frame.origin is not None:
            origins.append((frame.name, _point(f"{frame.name}@origin", frame.origin, parsed, links)))
    return edges, origins


def _point(name: str, vector: VectorDecl, parsed: dict, links: list[PointLink]) -> str:
    """Links for a position (one per frame term, from its ``from`` point); the name of the last."""
    if vector.point is not None:
        return vector.point.text
    parent = vector.origin.text if vector.origin is not None else None
    terms = list(parsed[id(vector)].items()) or [(INERTIAL, _ZERO3)]
    for i, (frame, components) in enumerate(terms):
        label = name if i == len(terms) - 1 else f"{name}#{i}"
        links.append(PointLink(label, parent, frame, tuple(components)))
        parent = label
    return parent


def _placed(body: str, parsed: dict, links: list[PointLink]) -> str:
    """A body placed by its rolling contact: the contact's links, then C − P and G − C along frames."""
    contact, terms = parsed[("placed", body)]
    parent = _point(f"{body}@contact", contact, parsed, links)
    for i, (frame, components) in enumerate(terms):
        label = f"{body}@" if i == len(terms) - 1 else f"{body}@#{i}"
        links.append(PointLink(label, parent, frame, tuple(components)))
        parent = label
    return parent


def _vector(vector: VectorDecl, parsed: dict, own: str | None) -> FrameVector:
    """A vector's terms; a list given in a body's own axes is along ``own`` (None: the body has no frame)."""
    if vector.point is not None:
        return FrameVector((), vector.point.text)
    terms = tuple((own if frame is None else frame, tuple(components))
                  for frame, components in parsed[id(vector)].items())
    return FrameVector(terms, vector.origin.text if vector.origin is not None else None)


def _rolling(decl, parsed: dict, frames_of: dict) -> RollingContact:
    own = frames_of.get(decl.body.text)
    axle = tuple(parsed[id(decl.axle)]) if decl.axle is not None else None
    centre = _vector(decl.centre, parsed, own) if decl.centre is not None else FrameVector(())
    shape = parsed[id(decl)]  # gacli.loader.rolling_geometry.Shape
    return RollingContact(decl.body.text, shape.radius, axle, centre, decl.on.text if decl.on is not None else None,
                          shape.tube, shape.semi_axes)


def _reaction(decl, load: Load) -> Load:
    """The torque's reaction: the same vector, negated, on the body it is mounted on (springs and
    dampers are the potential and work the loader forms, gacli.loader.lines)."""
    terms = tuple((frame, tuple(-c for c in components)) for frame, components in load.vector.terms)
    return Load(FrameVector(terms, load.vector.origin), True, body=decl.reaction.text)


def _load(decl, parsed: dict, links: list[PointLink], frames_of: dict, centres: dict, owners: dict) -> Load:
    if decl.torque is not None:
        if decl.body.text in owners:  # a torque on a frame fixed in a body: a list is along that frame
            return Load(_vector(decl.torque, parsed, decl.body.text), True, body=owners[decl.body.text])
        own = frames_of.get(decl.body.text)
        return Load(_vector(decl.torque, parsed, own), True, body=decl.body.text)
    if decl.at_name is not None:
        point = centres.get(decl.at_name.text, decl.at_name.text)  # a body's centre, or a named point
    else:
        point = _point(f"loads[{decl.index}]@", decl.at_position, parsed, links)
    return Load(_vector(decl.force, parsed, INERTIAL), False, point=point)
