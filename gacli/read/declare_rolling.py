"""The ``rolling`` section: bodies rolling without slipping on a plane, and the bodies they place.

A contact's shape is a sphere (``radius``), a thin wheel (``radius``,
``axle``), a torus (``radius``, ``axle``, ``tube``) or an ellipsoid
(``semi_axes``); ``contact`` places the body from its contact point, so that
the body needs no ``position`` (docs/frames.md, "Rolling").
"""

from __future__ import annotations

from gacli.read.reader import Reader, did_you_mean
from gacli.read.schema import ROLLING_KEYS, BodyDecl, RollingDecl, VectorDecl
from gacli.read.source import Mapping, Scalar, Sequence


def read_rolling(reader: Reader, top: dict) -> tuple[RollingDecl, ...]:
    """The ``rolling`` list: bodies rolling without slipping on the plane z = 0 of a frame."""
    node = reader.section(top, "rolling", Sequence, "a list of rolling contacts")
    if node is None:
        return ()
    out = []
    for i, item in enumerate(node.items):
        fields = reader.mapping(item, f"rolling[{i}]", ROLLING_KEYS)
        if isinstance(item, Mapping) and _shape_keys_consistent(reader, item, fields, f"rolling[{i}]"):
            decl = _rolling(reader, i, item, fields)
            if decl is not None:
                out.append(decl)
    return tuple(out)


def _shape_keys_consistent(reader: Reader, item: Mapping, fields: dict, where: str) -> bool:
    """One shape: a radius (sphere, wheel, torus) or semi-axes (ellipsoid), and a tube only on a wheel."""
    if "body" not in fields:
        reader.error(item, where, "missing required key 'body'")
        return False
    if "radius" not in fields and "semi_axes" not in fields:
        reader.error(item, where, "missing required key 'radius'",
                     "or 'semi_axes: [a, b, c]' for an ellipsoid")
        return False
    if "semi_axes" in fields:
        extra = [k for k in ("radius", "axle", "tube") if k in fields]
        if extra:
            reader.error(fields[extra[0]][0], f"{where}.{extra[0]}",
                         f"an ellipsoid is given by its semi-axes alone: '{extra[0]}' does not go with 'semi_axes'")
            return False
    if "tube" in fields and "axle" not in fields:
        reader.error(fields["tube"][0], f"{where}.tube", "a tube is the round tyre of a wheel: it needs an 'axle'")
        return False
    return True


def _rolling(reader: Reader, i: int, item: Mapping, fields: dict) -> RollingDecl | None:
    where = f"rolling[{i}]"

    def optional(key, read):
        return read(fields[key][1], f"{where}.{key}") if key in fields else None

    body = fields["body"][1]
    radius = optional("radius", reader.expression)
    tube = optional("tube", reader.expression)
    axle = optional("axle", lambda n, w: reader.vector(n, w, (3,)))
    centre = optional("centre", lambda n, w: reader.vector(n, w, (3,)))
    contact = optional("contact", lambda n, w: reader.vector(n, w, (3,), point=True))
    semi_axes = optional("semi_axes", lambda n, w: _semi_axes(reader, n, w))
    on = fields["on"][1] if "on" in fields else None
    read = {"radius": radius, "tube": tube, "axle": axle, "centre": centre, "contact": contact,
            "semi_axes": semi_axes}
    if not reader.name(body, f"{where}.body") or any(k in fields and v is None for k, v in read.items()) \
            or (on is not None and not reader.name(on, f"{where}.on")):
        return None
    return RollingDecl(i, item, body, radius, axle, on, centre, tube, semi_axes, contact)


def _semi_axes(reader: Reader, node, where: str) -> VectorDecl | None:
    """Three expressions along the body's own axes (never components in frames)."""
    components = reader.expressions(node, where, (3,))
    return VectorDecl(node, components=components) if components else None


def check_placements(reader: Reader, top: dict, bodies: tuple[BodyDecl, ...],
                     rolling: tuple[RollingDecl, ...]) -> None:
    """Each body has a ``position`` or is placed by one rolling contact's ``contact``, not both."""
    placing: dict[str, RollingDecl] = {}
    positioned = {b.name for b in bodies if b.position is not None}
    for decl in rolling:
        if decl.contact is None:
            continue
        name, where = decl.body.text, f"rolling[{decl.index}].contact"
        if name not in {b.name for b in bodies}:
            # Said here, or the body it was meant for would only be missing its position.
            reader.error(decl.body, f"rolling[{decl.index}].body", f"'{name}' is not a body",
                         did_you_mean(name, [b.name for b in bodies]))
        elif name in placing:
            reader.error(decl.contact.node, where, f"'{name}' is placed by rolling[{placing[name].index}].contact "
                         "already: a body is placed by one contact")
        elif name in positioned:
            reader.error(decl.contact.node, where, f"'{name}' has a 'position' already: the contact places the "
                         "body, so give one of them", "leave out the body's 'position'")
        placing.setdefault(name, decl)
    claimed = _claimed(top) | set(placing)  # an entry refused above has said what is wrong with it
    for body in bodies:
        if body.position is None and body.name not in claimed:
            reader.error(body.node, f"bodies.{body.name}", "missing required key 'position'",
                         "or place the body from its contact point with a rolling contact's 'contact'")


def _claimed(top: dict) -> set[str]:
    """The bodies that rolling entries with a ``contact`` name, as written (read or refused)."""
    node = top["rolling"][1] if "rolling" in top else None
    out = set()
    for item in node.items if isinstance(node, Sequence) else ():
        if isinstance(item, Mapping):
            fields = {key.text: value for key, value in item.items}
            body = fields.get("body")
            if "contact" in fields and isinstance(body, Scalar):
                out.add(body.text)
    return out
