"""The frame vocabulary of a system file, kept as written: frames, points, bodies, rolling, loads.

The loader turns a file written with frames (docs/frames.md) into positions
in N, rotation forms and rolling rows; these records keep what it read
before any of that geometry, so that a derivation can work with the frames
themselves (gacli.mechanics.program writes the right-hand side as a
straight-line program from them). They hold the parsed expressions and the
names, nothing derived: no products of rotation matrices, no reduction.

Names: a frame with several rotations is a chain of simple rotations whose
inner links are named ``frame#0``, ``frame#1`` ... (the last link is the
frame); a point written as a sum over several frames is a chain of links
named ``point#0`` ...; a body's position written in place is the point
``body@``, a force's point of application written in place ``loads[i]@``.
None of these can be a declared name (those are identifiers).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

Triple = tuple[sp.Expr, sp.Expr, sp.Expr]
INERTIAL = "N"


@dataclass(frozen=True)
class FrameEdge:
    """Frame ``name`` is ``parent`` turned by ``angle`` about their common ``axis`` (0, 1, 2: x, y, z).

    Components turn as v_parent = R v_name, R the simple rotation of
    ``gacli.loader.frames.simple_rotation``. A frame declared with only an
    origin is its parent turned by 0. A frame turned by Euler parameters has
    ``quaternion`` (e0, e1, e2, e3), R of ``gacli.loader.frames.quaternion_rotation``,
    and the names of its body rates relative to the parent in ``rates`` (none:
    ω = 2 G(e) ė); its ``axis`` is -1 and its ``angle`` 0.
    """

    name: str
    parent: str
    axis: int
    angle: sp.Expr
    quaternion: tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr] | None = None
    rates: tuple[str, ...] = ()


@dataclass(frozen=True)
class PointLink:
    """A point: ``parent``'s position (None: N's origin) plus ``components`` along ``frame``'s axes."""

    name: str
    parent: str | None
    frame: str
    components: Triple


@dataclass(frozen=True)
class FrameVector:
    """Σ of components along frames' axes (``terms``), plus the position of point ``origin`` if one is named
    (a vector written with ``from``, or as a point's name)."""

    terms: tuple[tuple[str, Triple], ...]
    origin: str | None = None


@dataclass(frozen=True)
class BodyPlacement:
    """A body's mass, the point link of its centre of mass, its frame (None: a particle, or a rigid
    body whose rotation is given by format-1 forms) and its inertia in that frame's axes."""

    name: str
    mass: sp.Expr
    point: str
    frame: str | None
    inertia: sp.ImmutableMatrix | None


@dataclass(frozen=True)
class RollingContact:
    """``body`` rolls without slipping on the plane z = 0 of frame ``on`` (None: N).

    ``axle`` is in the body's axes (None: a sphere, or an ellipsoid when
    ``semi_axes`` are given, along the body's axes); ``tube`` is a wheel's round
    tyre (0: a thin wheel); ``centre`` is the geometric centre's offset from the
    centre of mass (no terms: at it).
    """

    body: str
    radius: sp.Expr | None
    axle: Triple | None
    centre: FrameVector
    on: str | None = None
    tube: sp.Expr = sp.S.Zero
    semi_axes: Triple | None = None


@dataclass(frozen=True)
class Load:
    """A force at ``point`` (a point link: a body's centre, a named point or one written in place),
    or a torque on ``body``; a torque's list without frames is in the body's frame's axes."""

    vector: FrameVector
    torque: bool
    point: str | None = None
    body: str | None = None


@dataclass(frozen=True)
class Line:
    """A linear spring (``stiffness``, free ``length``) or damper (``damping``) between two point
    links ``ends``: a force along the line between them, of tension k (ℓ − L) + c ℓ̇."""

    ends: tuple[str, str]
    stiffness: sp.Expr | None = None
    length: sp.Expr = sp.S.Zero
    damping: sp.Expr | None = None


@dataclass(frozen=True)
class KnifeEdge:
    """The velocity of ``point`` has no component along ``along`` (a velocity constraint)."""

    point: str
    along: FrameVector


@dataclass(frozen=True)
class FrameModel:
    """The file's frames, points, bodies, rolling contacts and loads as declared (see the module)."""

    edges: tuple[FrameEdge, ...]  # parents before children
    origins: tuple[tuple[str, str], ...]  # (frame, the point link at its origin), for frames given one
    points: tuple[PointLink, ...]
    bodies: tuple[BodyPlacement, ...]
    rolling: tuple[RollingContact, ...]
    loads: tuple[Load, ...]
    knife_edges: tuple[KnifeEdge, ...] = ()
    # Springs and dampers as lines between points, with the file's own potential and work without
    # them (the System's potential and work hold the lines too, gacli.loader.lines).
    lines: tuple[Line, ...] = ()
    potential: sp.Expr = sp.S.Zero
    work: object = None  # a gacli.model.Form, or None (gacli.model imports this module)
