"""The shape of a system file: the keys each place may have, and the records they are read into.

No SymPy and no logic here: expressions stay text (a located
:class:`~gacli.read.source.Scalar`) until :mod:`gacli.loader.loading` builds them.
The records are filled by :func:`gacli.read.declarations.read_declarations`
and the ``declare_*`` modules beside it; :mod:`gacli.read.file_schema` (the
JSON Schema for editors) is held to these key lists by the tests.
"""

from __future__ import annotations

from dataclasses import dataclass

from gacli.read.source import Node, Scalar, SourceFile

FORMAT_VERSION = 1

TOP_KEYS = (
    "gacli", "name", "title", "description", "source", "parameters", "functions",
    "inputs", "coordinates", "quasi_coordinates", "constraints", "independent",
    "frames", "points", "bodies", "rolling", "loads", "work", "potential",
)
SYMBOL_KEYS = ("description", "value", "unit", "latex")
QUASI_KEYS = ("description", "differential", "unit", "latex")
BODY_KEYS = ("mass", "position", "inertia", "inertia_about", "inertia_in", "rotation", "frame", "description")
LOAD_KEYS = ("force", "at", "torque", "body", "reaction", "spring", "damper", "between", "length", "description")
FRAME_KEYS = ("parent", "origin", "rotations", "sequence", "angles", "quaternion", "rates", "description")
ROLLING_KEYS = ("body", "radius", "axle", "tube", "semi_axes", "centre", "contact", "on", "description")
VELOCITY_CONSTRAINT_KEYS = ("velocity_of", "along", "coincide", "moves_along", "moves_in", "description")
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
    or by the four Euler parameters named in ``quaternion`` (scalar first; then ``rotations`` is
    empty), with ``rates`` the quasi-coordinates its body rates are (none: the parameters' own
    rates); with its origin at a point (``origin``), or at its parent's origin when none is given."""

    name: str
    node: Scalar
    parent: Scalar | None
    rotations: tuple[tuple[Scalar, Scalar], ...]
    origin: VectorDecl | None = None
    quaternion: tuple[Scalar, ...] = ()
    rates: tuple[Scalar, ...] = ()


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
    position: VectorDecl | None  # None: placed by a rolling contact's 'contact'
    inertia: tuple[Scalar, ...] = ()
    inertia_node: Node | None = None
    rotation: tuple[Scalar, ...] = ()
    rotation_node: Node | None = None
    frame: Scalar | None = None
    description: str = ""
    # The point the inertia is given about (its mass centre when absent) and the frame whose
    # axes it is given in (the body's frame when absent): gacli shifts and turns it.
    inertia_about: Scalar | None = None
    inertia_in: Scalar | None = None

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
    # A torque's reaction: −torque on this body (a motor between two bodies).
    reaction: Scalar | None = None
    # A linear spring (stiffness) or damper (coefficient) between two points or bodies' centres;
    # a spring's free length (0 when absent).
    spring: Scalar | None = None
    damper: Scalar | None = None
    between: tuple[Scalar, Scalar] | None = None
    length: Scalar | None = None


@dataclass(frozen=True)
class RollingDecl:
    """A body rolling without slipping on the plane z = 0 of frame ``on`` (N when absent),
    its geometric centre at ``centre`` from its centre of mass (at it when absent).

    The body is a sphere (``radius``), a thin wheel (``radius``, ``axle``), a torus
    (``radius`` of the circle of tube centres, ``axle``, ``tube``) or an ellipsoid
    (``semi_axes`` along its own axes). ``contact``, when given, is the contact
    point's position on the plane, from which gacli places the body (which then
    has no ``position``)."""

    index: int
    node: Node
    body: Scalar
    radius: Scalar | None
    axle: VectorDecl | None = None
    on: Scalar | None = None
    centre: VectorDecl | None = None
    tube: Scalar | None = None
    semi_axes: VectorDecl | None = None
    contact: VectorDecl | None = None


@dataclass(frozen=True)
class GuideDecl:
    """A point kept on a line (``moves_along``: a frame's axis) or in a plane (``moves_in``: two of its
    axes) through the frame's origin: each component of its place across them is a holonomic constraint."""

    index: int
    node: Node
    key: str
    point: Scalar
    frame: Scalar
    free: tuple[int, ...]  # the frame's axes the point may move along


@dataclass(frozen=True)
class CoincidenceDecl:
    """Two points coincide (a loop closed at a joint): their N components agree, a holonomic constraint each."""

    index: int
    node: Node
    ends: tuple[Scalar, Scalar]


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
    constraints: tuple[Scalar | VelocityConstraintDecl | CoincidenceDecl | GuideDecl, ...] = ()
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
