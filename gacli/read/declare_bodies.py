"""The bodies and what acts on them: the ``bodies`` and ``loads`` sections."""

from __future__ import annotations

from gacli.read.reader import Reader, describe
from gacli.read.schema import BODY_KEYS, LOAD_KEYS, BodyDecl, LoadDecl
from gacli.read.source import Mapping, Node, Scalar, Sequence


def read_bodies(reader: Reader, top: dict) -> tuple[BodyDecl, ...]:
    """The ``bodies`` mapping: particles, and rigid bodies with inertia and either rotation forms or a frame."""
    if "bodies" not in top:
        return ()
    node = top["bodies"][1]
    if not isinstance(node, Mapping) or not node.items:
        found = "an empty mapping" if isinstance(node, Mapping) else describe(node)
        reader.error(node, "bodies", f"expected a mapping of named bodies, found {found}")
        return ()
    out = []
    for key, value in node.items:
        name = reader.name(key, "bodies")
        body = _body(reader, key, value, f"bodies.{name}") if name else None
        if body:
            out.append(body)
    return tuple(out)


def _body(reader: Reader, key: Scalar, node: Node, where: str) -> BodyDecl | None:
    fields = reader.mapping(node, where, BODY_KEYS)
    if not isinstance(node, Mapping):
        return None
    if "mass" not in fields:
        reader.error(node, where, "missing required key 'mass'")
    if not _rigid_keys_consistent(reader, fields, where):
        return None
    if "mass" not in fields:
        return None
    mass = reader.expression(fields["mass"][1], f"{where}.mass")
    # Without one, a rolling contact's 'contact' places the body (declare_rolling.check_placements).
    position = reader.vector(fields["position"][1], f"{where}.position", (2, 3), point=True) \
        if "position" in fields else None
    inertia, rotation = _rigid_parts(reader, fields, where)
    frame = fields["frame"][1] if "frame" in fields else None
    if frame is not None and not reader.name(frame, f"{where}.frame"):
        return None
    description = reader.text(fields["description"][1], f"{where}.description") if "description" in fields else ""
    about, axes = (fields[k][1] if k in fields else None for k in ("inertia_about", "inertia_in"))
    for option, value in (("inertia_about", about), ("inertia_in", axes)):
        if value is not None and (frame is None or not reader.name(value, f"{where}.{option}")):
            if frame is None:
                reader.error(value, f"{where}.{option}", f"'{option}' needs a body with a 'frame' (its axes carry "
                                                        "the inertia to the centre)")
            return None
    if mass is None or ("position" in fields and position is None):
        return None
    return BodyDecl(
        name=key.text, node=key, mass=mass, position=position,
        inertia=inertia, inertia_node=fields["inertia"][1] if "inertia" in fields else None,
        rotation=rotation, rotation_node=fields["rotation"][1] if "rotation" in fields else None,
        frame=frame, description=description, inertia_about=about, inertia_in=axes,
    )


def _rigid_keys_consistent(reader: Reader, fields: dict, where: str) -> bool:
    """A rigid body has inertia and either rotation forms or a frame, not both."""
    oriented = ("rotation" in fields) or ("frame" in fields)
    if "rotation" in fields and "frame" in fields:
        reader.error(fields["frame"][0], where, "give either 'rotation' or 'frame', not both",
                     "a frame's rotation forms are derived from its orientation")
        return False
    if ("inertia" in fields) != oriented:
        have = "inertia" if "inertia" in fields else ("rotation" if "rotation" in fields else "frame")
        lack = "'rotation' (or 'frame')" if have == "inertia" else "'inertia'"
        reader.error(fields[have][0], where, f"a rigid body needs both 'inertia' and 'rotation'; {lack} is missing")
        return False
    return True


def _rigid_parts(reader: Reader, fields: dict, where: str) -> tuple[tuple[Scalar, ...], tuple[Scalar, ...]]:
    if "inertia" not in fields:
        return (), ()
    inertia_node = fields["inertia"][1]
    if isinstance(inertia_node, Sequence) and inertia_node.items and isinstance(inertia_node.items[0], Sequence):
        inertia = _matrix(reader, inertia_node, f"{where}.inertia")
    else:
        inertia = reader.expressions(inertia_node, f"{where}.inertia", (0, 1, 3))
    if "frame" in fields:
        if isinstance(inertia_node, Scalar):
            reader.error(inertia_node, f"{where}.inertia", "a body with a frame takes three moments or a 3x3 matrix")
            return (), ()
        return inertia, ()
    rotation_node = fields["rotation"][1]
    planar = isinstance(inertia_node, Scalar)
    sizes = (0, 1) if planar else (3,)
    rotation = reader.expressions(rotation_node, f"{where}.rotation", sizes)
    if not planar and isinstance(rotation_node, Scalar):
        reader.error(rotation_node, f"{where}.rotation",
                     "a scalar rotation (plane motion) goes with a scalar inertia")
        return (), ()
    return inertia, rotation


def _matrix(reader: Reader, node: Sequence, where: str) -> tuple[Scalar, ...]:
    if len(node.items) != 3 or not all(isinstance(r, Sequence) and len(r.items) == 3 for r in node.items):
        reader.error(node, where, "an inertia matrix is 3 rows of 3 expressions")
        return ()
    out = []
    for i, row in enumerate(node.items):
        out.extend(reader.expressions(row, f"{where}[{i}]", (3,)))
    return tuple(out) if len(out) == 9 else ()


def read_loads(reader: Reader, top: dict) -> tuple[LoadDecl, ...]:
    """The ``loads`` list: forces (``at`` a body, a point or a position) and torques (on a ``body``)."""
    node = reader.section(top, "loads", Sequence, "a list of loads", null_is_empty=True)
    if node is None:
        return ()
    loads = [_load(reader, i, item) for i, item in enumerate(node.items)]
    return tuple(load for load in loads if load)


def _load(reader: Reader, index: int, node: Node) -> LoadDecl | None:
    where = f"loads[{index}]"
    fields = reader.mapping(node, where, LOAD_KEYS)
    if not isinstance(node, Mapping):
        return None
    kinds = [k for k in ("force", "torque", "spring", "damper") if k in fields]
    if len(kinds) != 1:
        reader.error(node, where, "a load is one of a 'force' (with 'at'), a 'torque' (with 'body'), "
                                  "a 'spring' or a 'damper' (with 'between')")
        return None
    if "force" in fields:
        return _force(reader, index, node, fields, where)
    if "torque" in fields:
        return _torque(reader, index, node, fields, where)
    return _line(reader, index, node, fields, where, kinds[0])


def _force(reader: Reader, index: int, node: Node, fields: dict, where: str) -> LoadDecl | None:
    if "at" not in fields or _other(fields, ("force", "at")):
        reader.error(node, where, "a force needs 'at': a body, a point, or a position [x, y, z]")
        return None
    vector = reader.vector(fields["force"][1], f"{where}.force", (2, 3))
    at = fields["at"][1]
    if isinstance(at, Scalar):
        name = reader.name(at, f"{where}.at")
        return LoadDecl(index, node, force=vector, at_name=at) if name and vector else None
    position = reader.vector(at, f"{where}.at", (2, 3))
    return LoadDecl(index, node, force=vector, at_position=position) if position and vector else None


def _torque(reader: Reader, index: int, node: Node, fields: dict, where: str) -> LoadDecl | None:
    if "body" not in fields or _other(fields, ("torque", "body", "reaction")):
        reader.error(node, where, "a torque needs 'body': the body it acts on (and may have 'reaction': the "
                                  "body it is mounted on)")
        return None
    vector = reader.vector(fields["torque"][1], f"{where}.torque", (0, 1, 3))
    body = fields["body"][1]
    reaction = fields["reaction"][1] if "reaction" in fields else None
    if not reader.name(body, f"{where}.body") or not vector:
        return None
    if reaction is not None and not reader.name(reaction, f"{where}.reaction"):
        return None
    return LoadDecl(index, node, torque=vector, body=body, reaction=reaction)


def _other(fields: dict, allowed: tuple[str, ...]) -> bool:
    """A key of another kind of load (a description goes with any)."""
    return any(k not in allowed and k != "description" for k in fields)


def _line(reader: Reader, index: int, node: Node, fields: dict, where: str, kind: str) -> LoadDecl | None:
    """A spring or damper ``between: [A, B]`` (points or bodies' centres)."""
    allowed = (kind, "between", "length") if kind == "spring" else (kind, "between")
    if "between" not in fields or _other(fields, allowed):
        reader.error(node, where, f"a {kind} needs 'between': [A, B], two points or bodies"
                     + (" (and may have 'length': its free length)" if kind == "spring" else ""))
        return None
    ends = fields["between"][1]
    if not isinstance(ends, Sequence) or len(ends.items) != 2:
        reader.error(ends, f"{where}.between", f"expected two names [A, B], found {describe(ends)}")
        return None
    if not all(reader.name(e, f"{where}.between") for e in ends.items):
        return None
    value = reader.expression(fields[kind][1], f"{where}.{kind}")
    length = reader.expression(fields["length"][1], f"{where}.length") if "length" in fields else None
    if value is None or ("length" in fields and length is None):
        return None
    return LoadDecl(index, node, between=tuple(ends.items), length=length, **{kind: value})
