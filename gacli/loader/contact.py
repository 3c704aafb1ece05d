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
from gacli.loader.rolling_geometry import (Shape, axle_problem, ellipsoid_contact, ellipsoid_lift, radius_problem, size_problem,
                                          tube_problem)
from gacli.read.schema import BodyDecl, RollingDecl
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
        if decl.contact is not None and decl.body.text not in bodies:
            return []  # the placement failed, and said why (_placed_position)
        body = self._body_named(decl.body, f"{where}.body", bodies)
        frame = self._rolling_frame(decl, body, where) if body is not None else None
        shape = self._shape(decl, where)
        surface = self._surface(decl, where)
        if body is None or shape is None or frame is None or surface is None:
            return []
        plane = plane_axes(surface)
        axle = self._axle(decl, shape, frame, plane, where) if shape.axle is not None else None
        offset = self._centre_offset(decl, body.name, frame, where)
        if axle is False or offset is None:
            return []
        self.parsed[id(decl)] = shape
        if not self.rolling_rows:
            return []
        below = self._below(shape, frame, plane, axle)
        rows = self._contact_rows(body, frame, surface, plane, sp.Matrix(body.position) + offset, below, axle)
        names = _WHEEL_ROWS if axle is not None else _axis_names(surface, plane)
        return [Constraint(self._row_form(rows[i, :]), self.where_of(decl.node),
                           f"rolling of {body.name} ({names[i]})", derived=True)
                for i in range(3) if not _vanishes(rows[i, :])]

    def _below(self, shape: Shape, frame: F.Frame, plane: sp.Matrix | None, axle: sp.Matrix | None) -> sp.Matrix:
        """The contact from the geometric centre along the plane's axes (N's for a horizontal plane),
        where the geometry is that of the plane z = 0."""
        if shape.semi_axes is not None:
            return ellipsoid_contact(_body_in_plane(frame, plane), shape.semi_axes)
        return F.contact_point(sp.zeros(3, 1), shape.radius, axle, shape.tube)

    def _contact_rows(self, body: Body, frame: F.Frame, surface: F.Frame, plane: sp.Matrix | None,
                      centre: sp.Matrix, below: sp.Matrix, axle: sp.Matrix | None) -> sp.Matrix:
        """v_P dt − v_surface dt at the contact, along the plane's axes (N's for a horizontal plane)."""
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

    def _shape(self, decl: RollingDecl, where: str) -> Shape | None:
        """The contact's shape, its sizes checked; parsed once (a placed body's contact is read twice)."""
        memo = self.__dict__.setdefault("_shapes", {})
        if id(decl) not in memo:
            memo[id(decl)] = self._read_shape(decl, where)
        return memo[id(decl)]

    def _read_shape(self, decl: RollingDecl, where: str) -> Shape | None:
        constant = self.scopes.constant
        if decl.semi_axes is not None:
            axes = self._vector(decl.semi_axes.components, f"{where}.semi_axes", constant)
            if axes is None:
                return None
            for i, value in enumerate(axes):
                if problem := size_problem(value, f"the semi-axis {'abc'[i]}", self.known):
                    self.error(decl.semi_axes.components[i], f"{where}.semi_axes[{i}]", problem)
                    return None
            return Shape(None, semi_axes=tuple(axes))
        radius = self.expression(decl.radius, f"{where}.radius", constant)
        tube = self.expression(decl.tube, f"{where}.tube", constant) if decl.tube is not None else sp.S.Zero
        axle = self._axle_components(decl, where) if decl.axle is not None else None
        if radius is None or tube is None or axle is False:
            return None
        if problem := radius_problem(radius, self.known):
            self.error(decl.radius, f"{where}.radius", problem)
            return None
        if decl.tube is not None and (problem := tube_problem(tube, radius, self.known)):
            self.error(decl.tube, f"{where}.tube", problem)
            return None
        return Shape(radius, axle, tube)

    def _axle_components(self, decl: RollingDecl, where: str):
        """The axle as written, in the body's axes; False on error."""
        local = self._vector(decl.axle.components, f"{where}.axle", self.scopes.constant) if decl.axle.components else None
        if local is None:
            self.error(decl.axle.node, f"{where}.axle", "the axle is a list of three components in the body's axes")
            return False
        self.parsed[id(decl.axle)] = local
        return sp.ImmutableMatrix(local)

    def _axle(self, decl: RollingDecl, shape: Shape, frame: F.Frame, plane: sp.Matrix | None, where: str,
              always: bool = False):
        """The unit axle along the plane's axes (N's for a horizontal plane); False on error."""
        local = sp.Matrix(shape.axle)
        dcm = sp.Matrix(frame.dcm) if plane is None else plane.T * sp.Matrix(frame.dcm)
        if problem := axle_problem(local, dcm, self.known):  # else the contact divides by zero: rows lost
            self.error(decl.axle.node, f"{where}.axle", problem)
            return False
        if not (self.rolling_rows or always):
            return local  # checked; the unit axle along N's axes is for the rows alone
        axle = dcm * (local / sp.sqrt(local.dot(local)))
        return axle if plane is None else axle.applyfunc(trig.reduce)

    def _centre_offset(self, decl: RollingDecl, body: str, frame: F.Frame | None, where: str) -> sp.Matrix | None:
        """The geometric centre from the centre of mass (N components): the declared offset, or zero."""
        offset = decl.centre
        if offset is None:
            return sp.zeros(3, 1)
        where = f"{where}.centre"
        if offset.origin is not None or offset.point is not None:
            self.error(offset.node, where, "the centre is an offset from the centre of mass: a list in the "
                       "body's axes or components in frames, without 'from'")
            return None
        if not offset.components:
            value = self._in_frames(offset, where, self.scopes.config)
            return None if value is None else sp.Matrix(value)
        if frame is None or not any(b.name == body and b.frame is not None for b in self.decl.bodies):
            self.error(offset.node, where, f"an offset in the body's axes needs a body with a 'frame'; "
                       f"'{body}' has none", "or give it in frames, as {N: [0, 0, e]}")
            return None
        local = self._vector(offset.components, where, self.scopes.constant)
        self.parsed[id(offset)] = {None: local}  # None: the body's own axes
        return None if local is None else sp.Matrix(frame.dcm) * sp.Matrix(local)

    def _rolling_frame(self, decl: RollingDecl, body: Body, where: str) -> F.Frame | None:
        if body.is_rigid and body.name in self.body_frames:
            return self.frames.get(self.body_frames[body.name].text)
        if body.is_rigid and decl.axle is None and decl.semi_axes is None:
            # A sphere given by format-1 forms: its rotation components are taken as inertial ones.
            omega = sp.Matrix.vstack(*(self._form_row(f) for f in body.rotation))
            return F.Frame(body.name, sp.ImmutableMatrix(sp.eye(3)), sp.ImmutableMatrix(omega))
        self.error(decl.body, f"{where}.body", f"'{body.name}' needs a 'frame' to roll "
                   + ("as an ellipsoid" if decl.semi_axes is not None else "with an axle"))
        return None

    def _placed_position(self, body: BodyDecl):
        """The centre of mass of a body placed by its contact: P + (C − P) − (C − G), N components.

        C − P is the shape's height over the plane at the contact: r n for a sphere,
        R (n − (n·a)a)/|n − (n·a)a| + ρ n for a wheel or torus, R E n_b/√(n_bᵀ E n_b) for an
        ellipsoid (R its axes in N, n_b the normal along them). Its terms along frames are kept
        for the frame model. None (and a located message) on error.
        """
        decl = next(r for r in self.decl.rolling if r.contact is not None and r.body.text == body.name)
        where = f"rolling[{decl.index}]"
        contact = self._in_frames(decl.contact, f"{where}.contact", self.scopes.config)
        shape, surface = self._shape(decl, where), self._surface(decl, where)
        frame = self.frames.get(body.frame.text) if body.frame is not None else None
        if frame is None and shape is not None and (shape.axle is not None or shape.semi_axes is not None):
            if body.frame is None:  # a frame that is not one is reported with the body
                self.error(decl.body, f"{where}.body", f"'{body.name}' needs a 'frame' to roll "
                           + ("as an ellipsoid" if shape.semi_axes is not None else "with an axle"))
            return None
        if contact is None or shape is None or surface is None:
            return None
        offset = self._centre_offset(decl, body.name, frame, where)
        lift = self._lift(decl, shape, frame, surface, where)
        if offset is None or lift is None:
            return None
        terms = [*lift, *_negated_offset(self.parsed.get(id(decl.centre)) if decl.centre is not None else None, body)]
        self.parsed[("placed", body.name)] = (decl.contact, tuple(terms))
        total = sp.Matrix(contact) - offset
        for name, components in lift:
            total += sp.Matrix(self.frames[name].dcm) * sp.Matrix(components)
        return tuple(total)

    def _lift(self, decl: RollingDecl, shape: Shape, frame: F.Frame | None, surface: F.Frame, where: str):
        """C − P as (frame, components) terms; None on error."""
        if shape.semi_axes is not None:
            normal = _body_in_plane(frame, plane_axes(surface))[2, :]
            return [(frame.name, tuple(ellipsoid_lift(list(normal), shape.semi_axes)))]
        if shape.axle is None:
            return [(surface.name, (sp.S.Zero, sp.S.Zero, shape.radius))]
        plane = plane_axes(surface)
        axle = self._axle(decl, shape, frame, plane, where, always=True)
        if axle is False:
            return None
        below = F.contact_point(sp.zeros(3, 1), shape.radius, axle, shape.tube)
        return [(surface.name if plane is not None else F.INERTIAL, tuple(-below))]

    def _form_row(self, form: Form) -> sp.Matrix:
        return sp.Matrix([[form.coefficient(n) for n in self.scopes.rate_names] + [form.dt]])

    def _surface(self, decl: RollingDecl, where: str) -> F.Frame | None:
        name = decl.on.text if decl.on is not None else F.INERTIAL
        if name not in self.frames:
            self.not_a_frame(decl.on, f"{where}.on")
            return None
        return self.frames[name]


def plane_axes(surface: F.Frame) -> sp.Matrix | None:
    """The plane's axes (frame → N) when its normal is not N's z; None for a horizontal plane,
    whose rows stay along N's axes (a frame turning about the vertical changes nothing)."""
    dcm = sp.Matrix(surface.dcm)
    normal = [trig.reduce(e) for e in dcm[:, 2]]
    return None if normal == [0, 0, 1] else dcm


def _body_in_plane(frame: F.Frame, plane: sp.Matrix | None) -> sp.Matrix:
    """The body's axes along the plane's (N's for a horizontal plane)."""
    dcm = sp.Matrix(frame.dcm)
    return dcm if plane is None else (plane.T * dcm).applyfunc(trig.reduce)


def _negated_offset(terms: dict | None, body: BodyDecl) -> list:
    """G − C as frame terms, from the centre's parsed terms (None as a frame: the body's own axes)."""
    if not terms:
        return []
    return [(body.frame.text if name is None else name, tuple(-c for c in components))
            for name, components in terms.items()]


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
