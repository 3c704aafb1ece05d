"""From located YAML nodes to typed declarations (no SymPy here).

This stage checks the shape of a system file: the keys it may have, which are
lists and which are mappings, which are names. Expressions stay text (with
their place in the file) until :mod:`gacli.loading` builds them. Every
problem is collected as a :class:`~gacli.errors.Diagnostic`, so one run
reports them all.
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass, field

from gacli.errors import Diagnostic
from gacli.read.source import Mapping, Node, Scalar, Sequence, SourceFile
from gacli.read.system_name import name_problem
from gacli.read.texsafe import MAX_LENGTH as LATEX_MAX_LENGTH
from gacli.read.texsafe import check_math

FORMAT_VERSION = 1
IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")

TOP_KEYS = (
    "gacli", "name", "title", "description", "source", "parameters", "functions",
    "inputs", "coordinates", "quasi_coordinates", "constraints", "independent",
    "frames", "points", "bodies", "rolling", "loads", "work", "potential",
)
SYMBOL_KEYS = ("description", "value", "unit", "latex")
QUASI_KEYS = ("description", "differential", "unit", "latex")
BODY_KEYS = ("mass", "position", "inertia", "rotation", "frame", "description")
LOAD_KEYS = ("force", "at", "torque", "body", "description")
FRAME_KEYS = ("parent", "origin", "rotations", "sequence", "angles", "description")
ROLLING_KEYS = ("body", "radius", "axle", "centre", "on", "description")
VELOCITY_CONSTRAINT_KEYS = ("velocity_of", "along", "description")
AXIS_NAMES = ("x", "y", "z")
SYMBOL_SECTIONS = ("parameters", "functions", "inputs", "coordinates", "quasi_coordinates")


@dataclass(frozen=True)
class SymbolDecl:
    """A declared name: parameter, function, input, coordinate or quasi-coordinate."""

    kind: str
    name: str
    node: Scalar
    description: str = ""
    value: Scalar | None = None
    unit: str = ""
    latex: str = ""
    differential: Scalar | None = None


@dataclass(frozen=True)
class VectorDecl:
    """A vector as written: a list of components (in the place's default axes),
    a mapping ``{frame: [x, y, z], ..., from: point}`` summed over frames, or
    a bare point name (for positions)."""

    node: Node
    components: tuple[Scalar, ...] = ()
    terms: tuple[tuple[Scalar, tuple[Scalar, ...]], ...] = ()
    origin: Scalar | None = None
    point: Scalar | None = None


@dataclass(frozen=True)
class FrameDecl:
    """A frame turned from ``parent`` by successive rotations (axis, angle) about its own axes,
    with its origin at a point (``origin``), or at its parent's origin when none is given."""

    name: str
    node: Scalar
    parent: Scalar | None
    rotations: tuple[tuple[Scalar, Scalar], ...]
    origin: VectorDecl | None = None


@dataclass(frozen=True)
class PointDecl:
    name: str
    node: Scalar
    position: VectorDecl


@dataclass(frozen=True)
class BodyDecl:
    name: str
    node: Scalar
    mass: Scalar
    position: VectorDecl
    inertia: tuple[Scalar, ...] = ()
    inertia_node: Node | None = None
    rotation: tuple[Scalar, ...] = ()
    rotation_node: Node | None = None
    frame: Scalar | None = None
    description: str = ""

    @property
    def is_rigid(self) -> bool:
        return bool(self.inertia)


@dataclass(frozen=True)
class LoadDecl:
    index: int
    node: Node
    force: VectorDecl | None = None
    torque: VectorDecl | None = None
    at_name: Scalar | None = None
    at_position: VectorDecl | None = None
    body: Scalar | None = None


@dataclass(frozen=True)
class RollingDecl:
    """A body rolling without slipping on the plane z = 0 of frame ``on`` (N when absent),
    its geometric centre at ``centre`` from its centre of mass (at it when absent)."""

    index: int
    node: Node
    body: Scalar
    radius: Scalar
    axle: VectorDecl | None = None
    on: Scalar | None = None
    centre: VectorDecl | None = None


@dataclass(frozen=True)
class VelocityConstraintDecl:
    """The velocity of a point has no component along a direction (a knife edge)."""

    index: int
    node: Node
    point: Scalar
    along: VectorDecl


@dataclass(frozen=True)
class SystemDecl:
    """The shape of a system file, its expressions still unparsed."""

    source: SourceFile
    name: str
    title: str = ""
    description: str = ""
    reference: str = ""
    symbols: tuple[SymbolDecl, ...] = ()
    constraints: tuple[Scalar | VelocityConstraintDecl, ...] = ()
    independent: tuple[Scalar, ...] | None = None
    independent_node: Node | None = None
    frames: tuple[FrameDecl, ...] = ()
    points: tuple[PointDecl, ...] = ()
    bodies: tuple[BodyDecl, ...] = ()
    rolling: tuple[RollingDecl, ...] = ()
    loads: tuple[LoadDecl, ...] = ()
    work: Scalar | None = None
    potential: Scalar | None = None

    def of_kind(self, kind: str) -> tuple[SymbolDecl, ...]:
        return tuple(s for s in self.symbols if s.kind == kind)


@dataclass
class _Reader:
    """Collects diagnostics while the declarations are read."""

    source: SourceFile
    diagnostics: list[Diagnostic] = field(default_factory=list)

    def error(self, node: Node, where: str, message: str, hint: str = "", offset: int | None = None) -> None:
        self.diagnostics.append(Diagnostic(self.source.location(node, offset), message, where, hint))

    def mapping(self, node: Node, where: str, allowed: tuple[str, ...]) -> dict[str, tuple[Scalar, Node]]:
        if not isinstance(node, Mapping):
            self.error(node, where, f"expected a mapping, found {_describe(node)}")
            return {}
        out = {}
        for key, value in node.items:
            if key.text not in allowed:
                self.error(key, where, f"unknown key '{key.text}'", did_you_mean(key.text, allowed))
                continue
            out[key.text] = (key, value)
        return out

    def text(self, node: Node, where: str) -> str:
        if isinstance(node, Scalar):
            return node.text
        self.error(node, where, f"expected text, found {_describe(node)}")
        return ""

    def expression(self, node: Node, where: str) -> Scalar | None:
        if isinstance(node, Scalar) and node.kind != "null" and node.text.strip():
            return node
        self.error(node, where, f"expected an expression, found {_describe(node)}")
        return None

    def expressions(self, node: Node, where: str, sizes: tuple[int, ...]) -> tuple[Scalar, ...]:
        """A list of expressions of one of the given lengths (0 in sizes: a lone scalar is allowed)."""
        if isinstance(node, Scalar) and 1 in sizes and 0 in sizes:
            one = self.expression(node, where)
            return (one,) if one else ()
        if not isinstance(node, Sequence):
            self.error(node, where, f"expected a list of {_sizes(sizes)} expressions, found {_describe(node)}")
            return ()
        if len(node.items) not in sizes:
            self.error(node, where, f"expected {_sizes(sizes)} components, found {len(node.items)}")
            return ()
        items = [self.expression(item, f"{where}[{i}]") for i, item in enumerate(node.items)]
        return tuple(items) if all(items) else ()

    def vector(self, node: Node, where: str, sizes: tuple[int, ...], point: bool = False) -> VectorDecl | None:
        """A vector: list, {frame: components, from: point} mapping, or (``point``) a point name."""
        if point and isinstance(node, Scalar):
            return VectorDecl(node, point=node) if self.name(node, where) else None
        if not isinstance(node, Mapping):
            components = self.expressions(node, where, sizes)
            return VectorDecl(node, components=components) if components else None
        terms, origin = [], None
        for key, value in node.items:
            if key.text == "from":
                origin = value if self.name(value, f"{where}.from") else None
                continue
            if self.name(key, where):
                components = self.expressions(value, f"{where}.{key.text}", (3,))
                if not components:
                    return None
                terms.append((key, components))
        if not terms and origin is None:
            self.error(node, where, "expected components in one or more frames, as {N: [x, y, z]}")
            return None
        return VectorDecl(node, terms=tuple(terms), origin=origin)

    def name(self, node: Node, where: str) -> str | None:
        if not isinstance(node, Scalar):
            self.error(node, where, f"expected a name, found {_describe(node)}")
            return None
        if not IDENTIFIER.match(node.text):
            self.error(node, where, f"'{node.text}' is not a valid name",
                       "a name is a letter or '_' followed by letters, digits and '_'")
            return None
        return node.text


def did_you_mean(word: str, choices) -> str:
    close = difflib.get_close_matches(word, sorted(choices), n=1, cutoff=0.6)
    return f"did you mean '{close[0]}'?" if close else ""


def _sizes(sizes: tuple[int, ...]) -> str:
    shown = [str(s) for s in sorted(sizes) if s]
    return " or ".join(shown)


def _describe(node: Node) -> str:
    if isinstance(node, Mapping):
        return "a mapping"
    if isinstance(node, Sequence):
        return "a list"
    if node.kind == "null" or not node.text.strip():
        return "nothing"
    return f"'{node.text}'"


def read_declarations(source: SourceFile) -> tuple[SystemDecl | None, list[Diagnostic]]:
    """Read the top level of a system file into a :class:`SystemDecl`."""
    reader = _Reader(source)
    top = reader.mapping(source.root, "", TOP_KEYS)
    if not isinstance(source.root, Mapping):
        return None, reader.diagnostics
    _check_required(reader, source.root, top)
    _check_version(reader, top)
    name = _system_name(reader, top)
    decl = SystemDecl(
        source=source,
        name=name or "system",
        title=_optional_text(reader, top, "title"),
        description=_optional_text(reader, top, "description"),
        reference=_optional_text(reader, top, "source"),
        symbols=_symbols(reader, top),
        constraints=_constraints(reader, top),
        independent=_independent(reader, top),
        independent_node=top["independent"][1] if "independent" in top else None,
        frames=_frames(reader, top),
        points=_points(reader, top),
        bodies=_bodies(reader, top),
        rolling=_rolling(reader, top),
        loads=_loads(reader, top),
        work=_optional_expression(reader, top, "work"),
        potential=_optional_expression(reader, top, "potential"),
    )
    return decl, reader.diagnostics


def _check_required(reader: _Reader, root: Mapping, top: dict) -> None:
    for key in ("gacli", "name", "coordinates", "bodies"):
        if key not in top:
            reader.error(root, "", f"missing required key '{key}'")


def _check_version(reader: _Reader, top: dict) -> None:
    if "gacli" in top:
        node = top["gacli"][1]
        if not (isinstance(node, Scalar) and node.text == str(FORMAT_VERSION)):
            reader.error(node, "gacli", f"unsupported format version {_describe(node)}",
                         f"this gacli reads format {FORMAT_VERSION}")


def _system_name(reader: _Reader, top: dict) -> str | None:
    """The name, if it can name files, a Python module and C identifiers (see gacli.system_name)."""
    if "name" not in top or not reader.name(top["name"][1], "name"):
        return None
    node = top["name"][1]
    problem = name_problem(node.text)
    if problem:
        reader.error(node, "name", problem, "the name becomes <name>.py, <name>.c, <name>.h and C identifiers")
        return None
    return node.text


def _latex(reader: _Reader, node: Node | None, where: str) -> str:
    """A ``latex:`` override, only if it is a math name TeX cannot run (see gacli.texsafe)."""
    if node is None:
        return ""
    text = reader.text(node, where)
    if not text or not isinstance(node, Scalar):
        return ""
    problem = check_math(text)
    if problem is None:
        return text
    reader.error(node, where, f"bad LaTeX override: {problem.message}",
                 f"a name in math TeX of at most {LATEX_MAX_LENGTH} characters: letters, digits, "
                 "^ _ { } ' , and commands such as \\alpha, \\dot, \\hat, \\mathrm",
                 offset=problem.offset)
    return ""


def _optional_text(reader: _Reader, top: dict, key: str) -> str:
    return reader.text(top[key][1], key) if key in top else ""


def _optional_expression(reader: _Reader, top: dict, key: str) -> Scalar | None:
    return reader.expression(top[key][1], key) if key in top else None


def _symbols(reader: _Reader, top: dict) -> tuple[SymbolDecl, ...]:
    out: list[SymbolDecl] = []
    for section in SYMBOL_SECTIONS:
        if section in top:
            kind = section.rstrip("s").replace("quasi_coordinate", "quasi")
            out.extend(_symbol_section(reader, top[section][1], section, kind))
    return tuple(out)


def _symbol_section(reader: _Reader, node: Node, section: str, kind: str) -> list[SymbolDecl]:
    if isinstance(node, Sequence):
        names = [(item, reader.name(item, f"{section}[{i}]")) for i, item in enumerate(node.items)]
        return [SymbolDecl(kind, name, item) for item, name in names if name]
    if isinstance(node, Mapping):
        out = []
        for key, value in node.items:
            name = reader.name(key, section)
            if name:
                out.append(_symbol_entry(reader, kind, key, value, f"{section}.{name}"))
        return out
    if isinstance(node, Scalar) and node.kind == "null":
        return []
    reader.error(node, section, f"expected a list of names or a mapping, found {_describe(node)}")
    return []


def _symbol_entry(reader: _Reader, kind: str, key: Scalar, value: Node, where: str) -> SymbolDecl:
    if isinstance(value, Scalar):
        if value.kind == "null":
            return SymbolDecl(kind, key.text, key)
        if kind == "quasi":
            return SymbolDecl(kind, key.text, key, differential=reader.expression(value, where))
        return SymbolDecl(kind, key.text, key, description=value.text)
    allowed = QUASI_KEYS if kind == "quasi" else SYMBOL_KEYS
    if kind in ("input", "coordinate"):
        allowed = tuple(k for k in allowed if k != "value")
    fields = reader.mapping(value, where, allowed)
    get = lambda k: fields[k][1] if k in fields else None  # noqa: E731
    return SymbolDecl(
        kind, key.text, key,
        description=reader.text(get("description"), f"{where}.description") if get("description") else "",
        value=reader.expression(get("value"), f"{where}.value") if get("value") else None,
        unit=reader.text(get("unit"), f"{where}.unit") if get("unit") else "",
        latex=_latex(reader, get("latex"), f"{where}.latex"),
        differential=reader.expression(get("differential"), f"{where}.differential") if get("differential") else None,
    )


def _constraints(reader: _Reader, top: dict) -> tuple[Scalar, ...]:
    if "constraints" not in top:
        return ()
    node = top["constraints"][1]
    if isinstance(node, Scalar) and node.kind == "null":
        return ()
    if not isinstance(node, Sequence):
        reader.error(node, "constraints", f"expected a list of constraints, found {_describe(node)}")
        return ()
    items = [_constraint(reader, i, item) for i, item in enumerate(node.items)]
    return tuple(item for item in items if item)


def _constraint(reader: _Reader, index: int, node: Node):
    where = f"constraints[{index}]"
    if not isinstance(node, Mapping):
        return reader.expression(node, where)
    fields = reader.mapping(node, where, VELOCITY_CONSTRAINT_KEYS)
    if "velocity_of" not in fields or "along" not in fields:
        reader.error(node, where, "a velocity constraint needs 'velocity_of' (a point) and 'along' (a vector)")
        return None
    point = fields["velocity_of"][1]
    along = reader.vector(fields["along"][1], f"{where}.along", (2, 3))
    if not reader.name(point, f"{where}.velocity_of") or along is None:
        return None
    return VelocityConstraintDecl(index, node, point, along)


def _independent(reader: _Reader, top: dict) -> tuple[Scalar, ...] | None:
    if "independent" not in top:
        return None
    node = top["independent"][1]
    if not isinstance(node, Sequence):
        reader.error(node, "independent", f"expected a list of names, found {_describe(node)}")
        return None
    names = [item for i, item in enumerate(node.items) if reader.name(item, f"independent[{i}]")]
    return tuple(names)


def _bodies(reader: _Reader, top: dict) -> tuple[BodyDecl, ...]:
    if "bodies" not in top:
        return ()
    node = top["bodies"][1]
    if not isinstance(node, Mapping) or not node.items:
        reader.error(node, "bodies", f"expected a mapping of named bodies, found {_describe(node)}")
        return ()
    out = []
    for key, value in node.items:
        name = reader.name(key, "bodies")
        body = _body(reader, key, value, f"bodies.{name}") if name else None
        if body:
            out.append(body)
    return tuple(out)


def _body(reader: _Reader, key: Scalar, node: Node, where: str) -> BodyDecl | None:
    fields = reader.mapping(node, where, BODY_KEYS)
    if not isinstance(node, Mapping):
        return None
    for required in ("mass", "position"):
        if required not in fields:
            reader.error(node, where, f"missing required key '{required}'")
    if not _rigid_keys_consistent(reader, fields, where):
        return None
    if "mass" not in fields or "position" not in fields:
        return None
    mass = reader.expression(fields["mass"][1], f"{where}.mass")
    position = reader.vector(fields["position"][1], f"{where}.position", (2, 3), point=True)
    inertia, rotation = _rigid_parts(reader, fields, where)
    frame = fields["frame"][1] if "frame" in fields else None
    if frame is not None and not reader.name(frame, f"{where}.frame"):
        return None
    description = reader.text(fields["description"][1], f"{where}.description") if "description" in fields else ""
    if mass is None or position is None:
        return None
    return BodyDecl(
        name=key.text, node=key, mass=mass, position=position,
        inertia=inertia, inertia_node=fields["inertia"][1] if "inertia" in fields else None,
        rotation=rotation, rotation_node=fields["rotation"][1] if "rotation" in fields else None,
        frame=frame, description=description,
    )


def _rigid_keys_consistent(reader: _Reader, fields: dict, where: str) -> bool:
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


def _rigid_parts(reader: _Reader, fields: dict, where: str) -> tuple[tuple[Scalar, ...], tuple[Scalar, ...]]:
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


def _matrix(reader: _Reader, node: Sequence, where: str) -> tuple[Scalar, ...]:
    if len(node.items) != 3 or not all(isinstance(r, Sequence) and len(r.items) == 3 for r in node.items):
        reader.error(node, where, "an inertia matrix is 3 rows of 3 expressions")
        return ()
    out = []
    for i, row in enumerate(node.items):
        out.extend(reader.expressions(row, f"{where}[{i}]", (3,)))
    return tuple(out) if len(out) == 9 else ()


def _loads(reader: _Reader, top: dict) -> tuple[LoadDecl, ...]:
    if "loads" not in top:
        return ()
    node = top["loads"][1]
    if isinstance(node, Scalar) and node.kind == "null":
        return ()
    if not isinstance(node, Sequence):
        reader.error(node, "loads", f"expected a list of loads, found {_describe(node)}")
        return ()
    loads = [_load(reader, i, item) for i, item in enumerate(node.items)]
    return tuple(load for load in loads if load)


def _load(reader: _Reader, index: int, node: Node) -> LoadDecl | None:
    where = f"loads[{index}]"
    fields = reader.mapping(node, where, LOAD_KEYS)
    if not isinstance(node, Mapping):
        return None
    if ("force" in fields) == ("torque" in fields):
        reader.error(node, where, "a load is either a 'force' (with 'at') or a 'torque' (with 'body')")
        return None
    if "force" in fields:
        return _force(reader, index, node, fields, where)
    return _torque(reader, index, node, fields, where)


def _force(reader: _Reader, index: int, node: Node, fields: dict, where: str) -> LoadDecl | None:
    if "at" not in fields or "body" in fields:
        reader.error(node, where, "a force needs 'at': a body, a point, or a position [x, y, z]")
        return None
    vector = reader.vector(fields["force"][1], f"{where}.force", (2, 3))
    at = fields["at"][1]
    if isinstance(at, Scalar):
        name = reader.name(at, f"{where}.at")
        return LoadDecl(index, node, force=vector, at_name=at) if name and vector else None
    position = reader.vector(at, f"{where}.at", (2, 3))
    return LoadDecl(index, node, force=vector, at_position=position) if position and vector else None


def _torque(reader: _Reader, index: int, node: Node, fields: dict, where: str) -> LoadDecl | None:
    if "body" not in fields or "at" in fields:
        reader.error(node, where, "a torque needs 'body': the body it acts on")
        return None
    vector = reader.vector(fields["torque"][1], f"{where}.torque", (0, 1, 3))
    body = fields["body"][1]
    if not reader.name(body, f"{where}.body") or not vector:
        return None
    return LoadDecl(index, node, torque=vector, body=body)


def _frames(reader: _Reader, top: dict) -> tuple[FrameDecl, ...]:
    if "frames" not in top:
        return ()
    node = top["frames"][1]
    if not isinstance(node, Mapping):
        reader.error(node, "frames", f"expected a mapping of named frames, found {_describe(node)}")
        return ()
    frames = [_frame(reader, key, value) for key, value in node.items if reader.name(key, "frames")]
    return tuple(f for f in frames if f)


def _frame(reader: _Reader, key: Scalar, node: Node) -> FrameDecl | None:
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


def _rotations(reader: _Reader, fields: dict, where: str):
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


def _sequence(reader: _Reader, fields: dict, where: str):
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


def _axis_ok(reader: _Reader, axis: Scalar, where: str) -> bool:
    if axis.text.lower() in AXIS_NAMES:
        return True
    reader.error(axis, where, f"'{axis.text}' is not an axis; expected x, y or z")
    return False


def _points(reader: _Reader, top: dict) -> tuple[PointDecl, ...]:
    if "points" not in top:
        return ()
    node = top["points"][1]
    if not isinstance(node, Mapping):
        reader.error(node, "points", f"expected a mapping of named points, found {_describe(node)}")
        return ()
    out = []
    for key, value in node.items:
        if reader.name(key, "points"):
            vector = reader.vector(value, f"points.{key.text}", (2, 3))
            if vector:
                out.append(PointDecl(key.text, key, vector))
    return tuple(out)


def _rolling(reader: _Reader, top: dict) -> tuple[RollingDecl, ...]:
    if "rolling" not in top:
        return ()
    node = top["rolling"][1]
    if not isinstance(node, Sequence):
        reader.error(node, "rolling", f"expected a list of rolling contacts, found {_describe(node)}")
        return ()
    out = []
    for i, item in enumerate(node.items):
        where = f"rolling[{i}]"
        fields = reader.mapping(item, where, ROLLING_KEYS)
        if not isinstance(item, Mapping):
            continue
        missing = [k for k in ("body", "radius") if k not in fields]
        if missing:
            reader.error(item, where, f"missing required key '{missing[0]}'")
            continue
        body = fields["body"][1]
        radius = reader.expression(fields["radius"][1], f"{where}.radius")
        axle = reader.vector(fields["axle"][1], f"{where}.axle", (3,)) if "axle" in fields else None
        on = fields["on"][1] if "on" in fields else None
        centre = reader.vector(fields["centre"][1], f"{where}.centre", (3,)) if "centre" in fields else None
        if reader.name(body, f"{where}.body") and radius and ("axle" not in fields or axle) \
                and (on is None or reader.name(on, f"{where}.on")) and ("centre" not in fields or centre):
            out.append(RollingDecl(i, item, body, radius, axle, on, centre))
    return tuple(out)
