"""The geometry bodies are placed in: the ``frames`` and ``points`` sections (``rolling``: declare_rolling)."""

from __future__ import annotations

import re

from gacli.read.reader import Reader
from gacli.read.schema import AXIS_NAMES, FRAME_KEYS, FrameDecl, PointDecl
from gacli.read.source import Mapping, Node, Scalar, Sequence


def read_frames(reader: Reader, top: dict) -> tuple[FrameDecl, ...]:
    """The ``frames`` mapping: rotations from a parent (or a ``sequence`` of angles) and an ``origin``."""
    node = reader.section(top, "frames", Mapping, "a mapping of named frames")
    if node is None:
        return ()
    frames = [_frame(reader, key, value) for key, value in node.items if reader.name(key, "frames")]
    return tuple(f for f in frames if f)


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
    if ("rotations" in fields) == ("sequence" in fields) and not (origin and "rotations" not in fields):
        reader.error(node, where, "a frame needs either 'rotations' ([[axis, angle], ...]) or 'sequence' and "
                     "'angles' (or only an 'origin': its parent's axes, moved)")
        return None
    # A frame with only an origin keeps its parent's axes: the plane of a translating surface.
    rotations = _rotations(reader, fields, where) if "rotations" in fields or "sequence" in fields else ()
    return FrameDecl(key.text, key, parent, rotations, origin) if rotations is not None else None


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

