"""Frames, points, bodies and loads of a system file, for the loader's builder.

Vectors given in frames are turned into inertial components (docs/frames.md);
a body's rotation forms come from its frame or are given as format-1 forms.
:class:`Geometry` is a part of :class:`gacli.loader.loading._Builder`.
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra import symbols as S
from gacli.loader import frames as F
from gacli.read.expr.build import Scope
from gacli.model import Body, Force, Form, Torque
from gacli.read.reader import did_you_mean
from gacli.read.schema import BodyDecl, FrameDecl, LoadDecl, VectorDecl
from gacli.read.source import Scalar


class Geometry:
    """Frames, points, bodies and loads, for the loader's builder."""

    def _vector(self, items: tuple[Scalar, ...], where: str, scope: Scope):
        values = [self.expression(item, f"{where}[{i}]", scope) for i, item in enumerate(items)]
        if any(v is None for v in values):
            return None
        return tuple(values) + (sp.S.Zero,) * (3 - len(values))

    def _in_frames(self, vector: VectorDecl, where: str, scope: Scope, default: str = F.INERTIAL):
        """A vector's N components (a list is in ``default``'s axes); None on error."""
        if vector.point is not None:
            return self._point_named(vector.point, where)
        if vector.components:
            values = self._vector(vector.components, where, scope)
            if values is None:
                return None
            terms = {default: values}
        else:
            terms = {}
            for frame, items in vector.terms:
                if frame.text not in self.frames:
                    self.not_a_frame(frame, where)
                    return None
                values = self._vector(items, f"{where}.{frame.text}", scope)
                if values is None:
                    return None
                terms[frame.text] = values
        self.parsed[id(vector)] = terms  # kept for the frame model (gacli.loader.frame_records)
        total = F.in_inertial(terms, self.frames) if terms else (sp.S.Zero,) * 3
        if vector.origin is not None:
            origin = self._point_named(vector.origin, f"{where}.from")
            if origin is None:
                return None
            total = F.add_vectors(total, origin)
        return total

    def _point_named(self, node: Scalar, where: str):
        if node.text in self.points:
            return self.points[node.text]
        if node.text in self._resolving:
            circle = " → ".join(self._resolving[self._resolving.index(node.text):] + [node.text])
            self.error(node, where, f"the points {circle} are each defined from the next, in a circle; "
                       "give one of them from a frame's components alone")
            return None
        if node.text in self._point_decls:  # declared later: resolved now; its own errors are reported there
            return self._resolve_point(self._point_decls[node.text])
        bodies = {b.name for b in self.decl.bodies}
        if node.text in bodies:  # its name is not its centre's: say so rather than suggest itself
            self.error(node, where, f"'{node.text}' is a body, not a point",
                       "declare a point under 'points' and give it as the body's position")
            return None
        self.error(node, where, f"'{node.text}' is not a point", did_you_mean(node.text, set(self.points) | bodies))
        return None

    def not_a_frame(self, node: Scalar, where: str) -> None:
        """'X' is not a frame, unless X is declared and reported where it stands (an error in its
        rotations, a circle): one message, not one more for each point or body given in it."""
        if all(d.name != node.text for d in self.decl.frames):
            self.error(node, where, f"'{node.text}' is not a frame", did_you_mean(node.text, self.frames))

    def _frames(self) -> dict[str, F.Frame]:
        width = len(self.scopes.rate_names) + 1
        frames = {F.INERTIAL: F.inertial_frame(width)}
        for decl in self.decl.frames:
            frame = self._frame(decl, frames)
            if frame is not None:
                frames[decl.name] = frame
        return frames

    def _frame(self, decl: FrameDecl, frames: dict) -> F.Frame | None:
        where = f"frames.{decl.name}"
        if decl.name in frames:
            self.error(decl.node, where, f"'{decl.name}' is already a frame" + (" (N is the inertial frame)" if decl.name == F.INERTIAL else ""))
            return None
        parent = decl.parent.text if decl.parent is not None else F.INERTIAL
        if parent not in frames:
            declared = {d.name: d.parent.text if d.parent is not None else F.INERTIAL for d in self.decl.frames}
            if parent in declared:  # read_frames put every other parent first: a circle, or a parent in error
                chain = [decl.name]
                while chain[-1] in declared and declared[chain[-1]] not in chain:
                    chain.append(declared[chain[-1]])
                if chain[-1] in declared:  # its own error, if any, is reported where it stands
                    self.error(decl.parent, f"{where}.parent", "the frames " + " → ".join([*chain, declared[chain[-1]]])
                               + " are each turned from the next, in a circle", "give one of them N as its parent")
            else:
                self.error(decl.parent, f"{where}.parent", f"'{parent}' is not a frame", did_you_mean(parent, frames))
            return None
        if decl.quaternion:
            return self._quaternion_frame(decl, frames[parent])
        rotations = []
        for i, (axis, text) in enumerate(decl.rotations):
            angle = self.expression(text, f"{where}.rotations[{i}]", self.scopes.config)
            if angle is None:
                return None
            rotations.append((axis.text.lower(), angle))
        self.parsed[id(decl)] = tuple(rotations)
        return F.oriented(decl.name, frames[parent], rotations, self.differential)

    def _points(self) -> dict[str, tuple]:
        """The named points, each resolved when first needed: a point may be given from a later one."""
        self.points, self._point_decls, self._resolving = {}, {}, []
        for decl in self.decl.points:
            if decl.name in self._point_decls:
                self.error(decl.node, f"points.{decl.name}", f"'{decl.name}' is already a point")
                continue
            self._point_decls[decl.name] = decl
        for decl in self._point_decls.values():
            self._resolve_point(decl)
        return self.points

    def _resolve_point(self, decl):
        if decl.name in self.points:
            return self.points[decl.name]
        if decl.name in self._failed_points:
            return None
        self._resolving.append(decl.name)
        value = self._in_frames(decl.position, f"points.{decl.name}", self.scopes.config)
        self._resolving.pop()
        if value is None:
            self._failed_points.add(decl.name)
        else:
            self.points[decl.name] = value
        return value

    def _body(self, decl: BodyDecl) -> Body | None:
        where = f"bodies.{decl.name}"
        mass = self.expression(decl.mass, f"{where}.mass", self.scopes.constant)
        position = self._in_frames(decl.position, f"{where}.position", self.scopes.config) \
            if decl.position is not None else self._placed_position(decl)  # placed by its contact
        inertia = rotation = None
        if decl.is_rigid:
            inertia = self._inertia(decl, where)
            if inertia is not None and mass is not None and position is not None and (decl.inertia_about or decl.inertia_in):
                inertia = self._moved_inertia(decl, where, inertia, mass, position)
            rotation = self._frame_rotation(decl, where) if decl.frame is not None else self._rotation(decl, where)
            if inertia is None or rotation is None:
                return None
        if mass is None or position is None:
            return None
        return Body(decl.name, self.where_of(decl.node), mass, position, inertia, rotation, decl.description)

    def _frame_rotation(self, decl: BodyDecl, where: str) -> tuple[Form, Form, Form] | None:
        """The body-axis rotation forms of the body's frame (its ω dt, derived)."""
        frame = self.frames.get(decl.frame.text)
        if frame is None:
            self.not_a_frame(decl.frame, f"{where}.frame")
            return None
        return tuple(self._row_form(frame.omega[i, :]) for i in range(3))

    def _inertia(self, decl: BodyDecl, where: str) -> sp.ImmutableMatrix | None:
        values = [self.expression(item, f"{where}.inertia", self.scopes.constant) for item in decl.inertia]
        if not values or any(v is None for v in values):
            return None
        if len(values) == 1:
            return sp.ImmutableMatrix(sp.diag(0, 0, values[0]))
        if len(values) == 3:
            return sp.ImmutableMatrix(sp.diag(*values))
        matrix = sp.ImmutableMatrix(3, 3, values)
        if any(sp.expand(matrix[i, j] - matrix[j, i]) != 0 for i in range(3) for j in range(i)):
            self.error(decl.inertia_node, f"{where}.inertia", "the inertia matrix is not symmetric")
            return None
        return matrix

    def _rotation(self, decl: BodyDecl, where: str) -> tuple[Form, Form, Form] | None:
        forms = [self._form(item, f"{where}.rotation[{i}]", self.scopes.form, zero=True)
                 for i, item in enumerate(decl.rotation)]
        if not forms or any(f is None for f in forms):
            return None
        if len(forms) == 1:
            return (Form(()), Form(()), forms[0])
        return tuple(forms)

    def _loads(self, bodies: tuple[Body, ...]) -> tuple[tuple[Force, ...], tuple[Torque, ...]]:
        by_name = {b.name: b for b in bodies}
        forces, torques = [], []
        for load in self.decl.loads:
            if load.force:
                force = self._force(load, by_name)
                forces += [force] if force else []
            elif load.torque:
                torque = self._torque(load, by_name)
                torques += [torque] if torque else []
                if torque and load.reaction is not None:
                    reaction = self._reaction(load, torque, by_name)
                    torques += [reaction] if reaction else []
        return tuple(forces), tuple(torques)

    def _frame_torque(self, load: LoadDecl, bodies: dict[str, Body], where: str) -> Torque | None:
        """A torque on a frame fixed in a body (a motor's stator frame): it acts on that body; a list is
        along the frame's axes."""
        frame = self.frames[load.body.text]
        owner = next((b for b in bodies.values() if b.is_rigid and self._fixed_in(frame, b.name)), None)
        if owner is None:
            self.error(load.body, f"{where}.body", f"the frame '{frame.name}' is fixed in no rigid body: a torque "
                                                   "acts on a body, or on a frame fixed in one")
            return None
        self.torque_owners[load.body.text] = owner.name
        if load.torque.components:
            values = [self.expression(item, f"{where}.torque", self.scopes.load) for item in load.torque.components]
            if any(v is None for v in values):
                return None
            along = (sp.S.Zero, sp.S.Zero, values[0]) if len(values) == 1 else tuple(values)
            self.parsed[id(load.torque)] = {frame.name: along}
            inertial = sp.Matrix(frame.dcm) * sp.Matrix(along)
        else:
            inertial = self._in_frames(load.torque, f"{where}.torque", self.scopes.load)
            if inertial is None:
                return None
        body_frame = self.frames[self.body_frames[owner.name].text]
        return Torque(tuple(sp.Matrix(body_frame.dcm).T * sp.Matrix(inertial)), owner.name, self.where_of(load.node))

    def _fixed_in(self, frame, body: str) -> bool:
        """Whether ``frame`` keeps its orientation in the body's frame."""
        own = self.body_frames.get(body)
        if own is None or own.text not in self.frames:
            return False
        return self._fixed_turn(self.frames[own.text], frame) is not None

    def _reaction(self, load: LoadDecl, torque: Torque, bodies: dict[str, Body]) -> Torque | None:
        """−torque on the body the motor is mounted on, turned from the acting body's axes into its own."""
        where = f"loads[{load.index}].reaction"
        body = self._body_named(load.reaction, where, bodies)
        if body is None:
            return None
        if not body.is_rigid:
            self.error(load.reaction, where, f"'{body.name}' is a particle; a torque acts on a rigid body")
            return None
        if body.name == torque.body:
            self.error(load.reaction, where, "a torque's reaction acts on another body than the torque")
            return None
        frames = [self.body_frames.get(name) for name in (torque.body, body.name)]
        if any(f is None or f.text not in self.frames for f in frames):
            self.error(load.reaction, where, "a torque with a reaction needs both bodies written with a 'frame'")
            return None
        acting, mounted = (sp.Matrix(self.frames[f.text].dcm) for f in frames)
        vector = mounted.T * acting * sp.Matrix(torque.vector)
        return Torque(tuple(-x for x in vector), body.name, self.where_of(load.node))

    def _force(self, load: LoadDecl, bodies: dict[str, Body]) -> Force | None:
        where = f"loads[{load.index}]"
        vector = self._in_frames(load.force, f"{where}.force", self.scopes.load)
        if load.at_name is not None:
            point = self._place_named(load.at_name, f"{where}.at", bodies)
        else:
            point = self._in_frames(load.at_position, f"{where}.at", self.scopes.config)
        if vector is None or point is None:
            return None
        return Force(vector, point, self.where_of(load.node))

    def _place_named(self, node: Scalar, where: str, bodies: dict[str, Body]):
        """A body's centre of mass or a named point."""
        if node.text in bodies:
            return bodies[node.text].position
        if node.text in self.points:
            return self.points[node.text]
        declared = {b.name for b in self.decl.bodies}
        if node.text not in declared and node.text not in self._point_decls:  # a declared point's errors are its own
            self.error(node, where, f"'{node.text}' is not a body or a point",
                       did_you_mean(node.text, declared | set(self.points)))
        return None

    def _torque(self, load: LoadDecl, bodies: dict[str, Body]) -> Torque | None:
        where = f"loads[{load.index}]"
        if load.body.text not in bodies and load.body.text in self.frames:
            return self._frame_torque(load, bodies, where)
        body = self._body_named(load.body, f"{where}.body", bodies)
        if body is None:
            return None
        if not body.is_rigid:
            self.error(load.body, f"{where}.body", f"'{body.name}' is a particle; a torque acts on a rigid body")
            return None
        vector = self._body_axes_torque(load.torque, body, f"{where}.torque")
        return Torque(vector, body.name, self.where_of(load.node)) if vector is not None else None

    def _body_axes_torque(self, torque: VectorDecl, body: Body, where: str):
        """A list is in body axes (a scalar: about z); a mapping in frames is turned into body axes."""
        if torque.components:
            values = [self.expression(item, where, self.scopes.load) for item in torque.components]
            if any(v is None for v in values):
                return None
            vector = (sp.S.Zero, sp.S.Zero, values[0]) if len(values) == 1 else tuple(values)
            self.parsed[id(torque)] = {None: vector}  # None: the body's own axes
            return vector
        frame = self.body_frames.get(body.name)
        if frame is None or frame.text not in self.frames:
            self.error(torque.node, where, f"a torque in frames needs a body with a 'frame'; '{body.name}' has none")
            return None
        inertial = self._in_frames(torque, where, self.scopes.load)
        if inertial is None:
            return None
        return tuple(sp.Matrix(self.frames[frame.text].dcm).T * sp.Matrix(inertial))

    def _body_named(self, node: Scalar, where: str, bodies: dict[str, Body]) -> Body | None:
        if node.text in bodies:
            return bodies[node.text]
        declared = {b.name for b in self.decl.bodies}
        if node.text not in declared and node.text not in self._point_decls:  # a declared point's errors are its own
            self.error(node, where, f"'{node.text}' is not a body", did_you_mean(node.text, declared))
        return None
