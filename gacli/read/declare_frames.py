"""The geometry bodies are placed in: the ``frames`` and ``points`` sections (``rolling``: declare_rolling)."""

from __future__ import annotations

import re

from gacli.read.reader import IDENTIFIER, Reader, describe
from gacli.read.schema import AXIS_NAMES, FRAME_KEYS, FrameDecl, PointDecl
from gacli.read.source import Mapping, Node, Scalar, Sequence


def read_frames(reader: Reader, top: dict) -> tuple[FrameDecl, ...]:
    """The ``frames`` mapping: rotations from a parent (or a ``sequence`` of angles) and an ``origin``."""
    node = reader.section(top, "frames", Mapping, "a mapping of named frames")
    if node is None:
        return ()
    frames = [_frame(reader, key, value) for key, value in node.items if reader.name(key, "frames")]
    return parents_first(tuple(f for f in frames if f))


def parents_first(frames: tuple[FrameDecl, ...]) -> tuple[FrameDecl, ...]:
    """The frames each after its parent, otherwise in the file's order: a file may declare them in
    any order, as it may its points. Those in a circle, or under a name no frame has, stay last,
    in order, for the loader to report."""
    names = {f.name for f in frames}
    placed, ordered, pending = set(), [], list(frames)
    while True:
        ready = [f for f in pending if f.parent is None or f.parent.text in placed or f.parent.text not in names]
        if not ready:
            return tuple(ordered + pending)
        for f in ready:
            ordered.append(f)
            placed.add(f.name)
        pending = [f for f in pending if f.name not in placed]


def _frame(reader: Reader, key: Scalar, node: Node) -> FrameDecl | None:
    where = f"frames.{key.text}"
    fields = reader.mapping(node, where, FRAME_KEYS)
    if not isinstance(node, Mapping):
        return None
    parent = fields["parent"][1] if "parent" in fields else None
    if parent is not None and not reader.name(parent, f"{where}.parent"):
        return None
    origin = reader.vector(fields["origin"][1], f"{where}.origin", (3,), point=True) if "origin" in fields else None
    if "origin" in fields and origin is None:
        return None
    if "quaternion" in fields or "rates" in fields:
        return _quaternion_frame(reader, key, node, fields, parent, origin)
    if ("rotations" in fields) == ("sequence" in fields) and not (origin and "rotations" not in fields):
        reader.error(node, where, "a frame needs either 'rotations' ([[axis, angle], ...]), 'sequence' and "
                     "'angles', or 'quaternion' ([e0, e1, e2, e3]) (or only an 'origin': its parent's axes, moved)")
        return None
    # A frame with only an origin keeps its parent's axes: the plane of a translating surface.
    rotations = _rotations(reader, fields, where) if "rotations" in fields or "sequence" in fields else ()
    return FrameDecl(key.text, key, parent, rotations, origin) if rotations is not None else None


def _quaternion_frame(reader: Reader, key: Scalar, node: Mapping, fields: dict, parent, origin) -> FrameDecl | None:
    """A frame oriented by four Euler parameters (coordinates, scalar first), its body rates optionally
    named as quasi-coordinates (docs/frames.md, "Quaternions")."""
    where = f"frames.{key.text}"
    if "quaternion" not in fields:
        reader.error(fields["rates"][0], where, "'rates' names the body rates of a frame oriented by a "
                     "'quaternion'; this frame has none")
        return None
    clash = next((k for k in ("rotations", "sequence", "angles") if k in fields), None)
    if clash is not None:
        reader.error(fields[clash][0], where, f"a frame is oriented either by 'quaternion' or by '{clash}', "
                     "not both")
        return None
    quaternion = _names(reader, fields["quaternion"][1], f"{where}.quaternion", 4,
                        "the four Euler parameters, scalar first, as [e0, e1, e2, e3]")
    rates = (_names(reader, fields["rates"][1], f"{where}.rates", 3,
                    "three quasi-coordinates, the body rates along the frame's x, y and z axes")
             if "rates" in fields else ())
    if quaternion is None or rates is None:
        return None
    return FrameDecl(key.text, key, parent, (), origin, quaternion, rates)


def _names(reader: Reader, node: Node, where: str, count: int, what: str) -> tuple[Scalar, ...] | None:
    """Exactly ``count`` distinct names; None (and a located error) otherwise."""
    if not isinstance(node, Sequence) or len(node.items) != count:
        found = f"{len(node.items)} entries" if isinstance(node, Sequence) else describe(node)
        reader.error(node, where, f"expected a list of {count} names, found {found}", f"give {what}")
        return None
    seen: dict[str, int] = {}
    for i, item in enumerate(node.items):
        if not isinstance(item, Scalar) or not IDENTIFIER.match(item.text):
            # A constant or scaled entry would not stay on the unit sphere: only names of the file's own.
            reader.error(item, f"{where}[{i}]", f"expected a name, found {describe(item)}", f"give {what}")
            return None
        if item.text in seen:
            reader.error(item, f"{where}[{i}]", f"'{item.text}' is named twice (also entry {seen[item.text]})",
                         f"give {what}")
            return None
        seen[item.text] = i
    return tuple(node.items)


def _rotations(reader: Reader, fields: dict, where: str):
    if "rotations" in fields:
        node = fields["rotations"][1]
        if not isinstance(node, Sequence) or not node.items:
            reader.error(node, f"{where}.rotations", "expected a list of [axis, angle] pairs")
            return None
        pairs = []
        for i, item in enumerate(node.items):
            if not (isinstance(item, Sequence) and len(item.items) == 2 and isinstance(item.items[0], Scalar)):
                reader.error(item, f"{where}.rotations[{i}]", "expected [axis, angle], as [z, psi]")
                return None
            axis, angle = item.items
            if not _axis_ok(reader, axis, f"{where}.rotations[{i}]"):
                return None
            angle = reader.expression(angle, f"{where}.rotations[{i}]")
            if angle is None:
                return None
            pairs.append((axis, angle))
        return tuple(pairs)
    return _sequence(reader, fields, where)


def _sequence(reader: Reader, fields: dict, where: str):
    sequence = fields["sequence"][1]
    if "angles" not in fields:
        reader.error(sequence, where, "a 'sequence' needs 'angles'")
        return None
    angles = fields["angles"][1]
    text = sequence.text if isinstance(sequence, Scalar) else ""
    if not re.fullmatch(r"[XYZxyz]{1,3}", text):
        reader.error(sequence, f"{where}.sequence", "expected body-axis rotations such as ZXZ or ZXY")
        return None
    values = reader.expressions(angles, f"{where}.angles", (len(text),))
    if not values:
        return None
    return tuple((Scalar(axis.lower(), "str", sequence.line, sequence.column, None), angle)
                 for axis, angle in zip(text, values))


def _axis_ok(reader: Reader, axis: Scalar, where: str) -> bool:
    if axis.text.lower() in AXIS_NAMES:
        return True
    reader.error(axis, where, f"'{axis.text}' is not an axis; expected x, y or z")
    return False


def read_points(reader: Reader, top: dict) -> tuple[PointDecl, ...]:
    """The ``points`` mapping: named positions."""
    node = reader.section(top, "points", Mapping, "a mapping of named points")
    if node is None:
        return ()
    out = []
    for key, value in node.items:
        if reader.name(key, "points"):
            vector = reader.vector(value, f"points.{key.text}", (2, 3))
            if vector:
                out.append(PointDecl(key.text, key, vector))
    return tuple(out)

