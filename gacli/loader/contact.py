"""Rolling contact on a plane given by a frame: its rows as Pfaffian constraints, eq. (14.1).

The plane is the xy-plane of a frame (N when a contact names none), through
the frame's origin, moving with the frame: tilted, translating or turning
about any axis, as functions of time or of coordinates. A sphere or wheel of
radius r has its geometric centre C at an offset from its centre of mass G
(none by default); it touches the plane at P = C − r n for a sphere (n the
plane's normal, the frame's z axis), or P = C − r (n − (n·a)a)/|n − (n·a)a|
for a wheel with axle a. Rolling without slipping says that the body's
material point at P has the velocity of the surface point there:

    dG + (ω dt) × (P − G) = dO + (Ω dt) × (P − O),

O the plane's origin and Ω its angular velocity. For a horizontal plane the
rows are formed along N's axes, as they always were; for any other they are
formed along the plane's axes from the motion relative to the plane, where
the contact geometry has the same simple form as on z = 0 and the plane's
own motion cancels wherever it can.

:class:`RollingContacts` is a part of the loader's builder (gacli.loader.loading):
it reads frames, points, bodies and expressions through it.
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from gacli.loader import frames as F
from gacli.algebra import trig
from gacli.algebra.graph import is_small
from gacli.model import Body, Constraint, Form
from gacli.loader.rolling_geometry import axle_problem, radius_problem
from gacli.read.reader import did_you_mean
from gacli.read.schema import RollingDecl
from gacli.numeric.zero import vanishes

# Rolling rows: along a wheel (frames.in_wheel_heading), or a plane's axes for a sphere.
_WHEEL_ROWS = ("forward", "sideways", "normal")
_EXPAND_OPS = 60  # row entries up to this size are expanded so that the offset's terms cancel
_REDUCED_NODES = 600  # larger row entries are kept as formed (a steered wheel's: nested products)


class RollingContacts:
    """Frames' origins and rolling contacts, for the loader's builder."""

    def _frame_origins(self) -> None:
        """Each frame's origin: its declared point, else its parent's (N's origin for N)."""
        done = {F.INERTIAL}
        for decl in self.decl.frames:
            if decl.name in done or decl.name not in self.frames:
                continue  # a repeated or refused frame: its error is reported already
            done.add(decl.name)
            parent = decl.parent.text if decl.parent is not None else F.INERTIAL
            origin = self.frames[parent].origin
            if decl.origin is not None:
                origin = self._in_frames(decl.origin, f"frames.{decl.name}.origin", self.scopes.config)
            self.frames[decl.name] = replace(self.frames[decl.name], origin=origin)

    def _rolling_constraints(self, bodies: tuple[Body, ...]) -> tuple[Constraint, ...]:
        by_name = {b.name: b for b in bodies}
        out: list[Constraint] = []
        for decl in self.decl.rolling:
            out += self._rolling(decl, by_name)
        return tuple(out)

    def _rolling(self, decl: RollingDecl, bodies: dict[str, Body]) -> list[Constraint]:
        """The material point at the contact has the surface's velocity: up to three rows."""
        where = f"rolling[{decl.index}]"
        body = self._body_named(decl.body, f"{where}.body", bodies)
        radius = self.expression(decl.radius, f"{where}.radius", self.scopes.constant)
        frame = self._rolling_frame(decl, body, where) if body is not None else None
        surface = self._surface(decl, where)
        if radius is not None and (problem := radius_problem(radius, self.known)):
            self.error(decl.radius, f"{where}.radius", problem)
            return []
        if body is None or radius is None or frame is None or surface is None:
            return []
        plane = plane_axes(surface)
        axle = self._axle(decl, frame, plane, where) if decl.axle is not None else None
        centre = self._geometric_centre(decl, body, frame, where)
        if axle is False or centre is None:
            return []
        self.parsed[id(decl)] = radius
        if not self.rolling_rows:
            return []
        rows = self._contact_rows(body, frame, surface, plane, centre, radius, axle)
        names = _WHEEL_ROWS if axle is not None else _axis_names(surface, plane)
        return [Constraint(self._row_form(rows[i, :]), self.where_of(decl.node),
                           f"rolling of {body.name} ({names[i]})", derived=True)
                for i in range(3) if not _vanishes(rows[i, :])]

    def _contact_rows(self, body: Body, frame: F.Frame, surface: F.Frame, plane: sp.Matrix | None,
                      centre: sp.Matrix, radius: sp.Expr, axle: sp.Matrix | None) -> sp.Matrix:
        """v_P dt − v_surface dt at the contact, along the plane's axes (N's for a horizontal plane)."""
        # The contact geometry is that of the plane z = 0 in the plane's own axes.
        below = F.contact_point(sp.zeros(3, 1), radius, axle)
        if plane is not None:
            return F.in_wheel_heading(self._relative_rows(body, frame, surface, plane, centre, below), axle)
        contact = centre + below
        origin = surface.origin
        spin = sp.Matrix(surface.dcm) * sp.Matrix(surface.omega)
        moving = F.cross_form(spin, contact if origin is None else contact - sp.Matrix(origin))
        if origin is not None:
            moving = self._velocity_form(origin) + moving
        position = sp.Matrix(body.position)
        rows = F.rolling_rows(self._velocity_form(body.position), sp.Matrix(frame.dcm) * sp.Matrix(frame.omega),
                              contact - position, moving)
        return F.in_wheel_heading(rows, axle).applyfunc(_shorter)

    def _relative_rows(self, body: Body, frame: F.Frame, surface: F.Frame, plane: sp.Matrix,
                       centre: sp.Matrix, below: sp.Matrix) -> sp.Matrix:
        """The rows along the plane's axes, from the motion relative to the plane.

        v_P − v_surface(P) = (v_G − v_O − Ω × (G − O)) + (ω − Ω) × (P − G), and the
        bracket is the rate of G's components g along the plane's axes: the rows
        are dg + ((ω − Ω) dt) × (P − G), all along those axes. Formed so, they hold
        no products of the plane's turning with itself that sin² + cos² must undo.
        """
        def along(vector):
            return (plane.T * vector).applyfunc(trig.reduce)

        origin = sp.Matrix(surface.origin) if surface.origin is not None else sp.zeros(3, 1)
        g = along(sp.Matrix(body.position) - origin)
        spin = along(sp.Matrix(frame.dcm) * sp.Matrix(frame.omega)) - sp.Matrix(surface.omega)
        rows = self._velocity_form(tuple(g)) + F.cross_form(spin, along(centre - sp.Matrix(body.position)) + below)
        return rows.applyfunc(_cancelled)

    def _axle(self, decl: RollingDecl, frame: F.Frame, plane: sp.Matrix | None, where: str):
        """The unit axle along the plane's axes (N's for a horizontal plane); False on error."""
        local = self._vector(decl.axle.components, f"{where}.axle", self.scopes.constant) if decl.axle.components else None
        if local is None:
            self.error(decl.axle.node, f"{where}.axle", "the axle is a list of three components in the body's axes")
            return False
        self.parsed[id(decl.axle)] = local
        local = sp.Matrix(local)
        dcm = sp.Matrix(frame.dcm) if plane is None else plane.T * sp.Matrix(frame.dcm)
        if problem := axle_problem(local, dcm, self.known):  # else the contact divides by zero: rows lost
            self.error(decl.axle.node, f"{where}.axle", problem)
            return False
        if not self.rolling_rows:
            return local  # checked; the unit axle along N's axes is for the rows alone
        axle = dcm * (local / sp.sqrt(local.dot(local)))
        return axle if plane is None else axle.applyfunc(trig.reduce)

    def _geometric_centre(self, decl: RollingDecl, body: Body, frame: F.Frame, where: str) -> sp.Matrix | None:
        """The body's geometric centre: its centre of mass plus the declared offset (N components)."""
        position = sp.Matrix(body.position)
        offset = decl.centre
        if offset is None:
            return position
        where = f"{where}.centre"
        if offset.origin is not None or offset.point is not None:
            self.error(offset.node, where, "the centre is an offset from the centre of mass: a list in the "
                       "body's axes or components in frames, without 'from'")
            return None
        if not offset.components:
            value = self._in_frames(offset, where, self.scopes.config)
            return None if value is None else position + sp.Matrix(value)
        if body.name not in self.body_frames:
            self.error(offset.node, where, f"an offset in the body's axes needs a body with a 'frame'; "
                       f"'{body.name}' has none", "or give it in frames, as {N: [0, 0, e]}")
            return None
        local = self._vector(offset.components, where, self.scopes.constant)
        self.parsed[id(offset)] = {None: local}  # None: the body's own axes
        return None if local is None else position + sp.Matrix(frame.dcm) * sp.Matrix(local)

    def _rolling_frame(self, decl: RollingDecl, body: Body, where: str) -> F.Frame | None:
        if body.is_rigid and body.name in self.body_frames:
            return self.frames.get(self.body_frames[body.name].text)
        if body.is_rigid and decl.axle is None:
            # A sphere given by format-1 forms: its rotation components are taken as inertial ones.
            omega = sp.Matrix.vstack(*(self._form_row(f) for f in body.rotation))
            return F.Frame(body.name, sp.ImmutableMatrix(sp.eye(3)), sp.ImmutableMatrix(omega))
        self.error(decl.body, f"{where}.body", f"'{body.name}' needs a 'frame' to roll with an axle")
        return None

    def _form_row(self, form: Form) -> sp.Matrix:
        return sp.Matrix([[form.coefficient(n) for n in self.scopes.rate_names] + [form.dt]])

    def _surface(self, decl: RollingDecl, where: str) -> F.Frame | None:
        name = decl.on.text if decl.on is not None else F.INERTIAL
        if name not in self.frames:
            self.error(decl.on, f"{where}.on", f"'{name}' is not a frame", did_you_mean(name, self.frames))
            return None
        return self.frames[name]


def plane_axes(surface: F.Frame) -> sp.Matrix | None:
    """The plane's axes (frame → N) when its normal is not N's z; None for a horizontal plane,
    whose rows stay along N's axes (a frame turning about the vertical changes nothing)."""
    dcm = sp.Matrix(surface.dcm)
    normal = [trig.reduce(e) for e in dcm[:, 2]]
    return None if normal == [0, 0, 1] else dcm


def _cancelled(entry: sp.Expr) -> sp.Expr:
    """A row entry with the offset's terms cancelled ((e cos θ − r) sin φ − e sin φ cos θ = −r sin φ):
    expanded when small, then reduced by sin² + cos² = 1."""
    if sp.count_ops(entry) <= _EXPAND_OPS:
        entry = sp.expand(entry)
    return trig.reduce(entry)


def _shorter(entry: sp.Expr) -> sp.Expr:
    """:func:`_cancelled` where that shortens the entry (an unbalanced sphere's rows lose
    sin² + cos² of the spin), else the entry as formed: a steered wheel's rows, multiplied
    out, are longer than their nested products."""
    if not is_small(entry, _REDUCED_NODES):
        return entry
    cancelled = _cancelled(entry)
    return cancelled if sp.count_ops(cancelled) < sp.count_ops(entry) else entry


def _axis_names(surface: F.Frame, plane: sp.Matrix | None) -> tuple[str, str, str]:
    if plane is None:
        return ("x", "y", "z")
    return tuple(f"{axis} of {surface.name}" for axis in ("x", "y", "z"))


def _vanishes(row: sp.Matrix) -> bool:
    """Every entry identically zero (a rolling row that geometry already satisfies)."""
    return all(vanishes(e, simplify=False) for e in row)
