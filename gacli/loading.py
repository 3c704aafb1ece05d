"""Load a system file: source → declarations → parsed expressions → System.

Each expression is parsed by our own grammar and built under the scope of
the place it stands in, so a mass cannot name a coordinate and a position
cannot name an input. All problems are collected and raised together as one
:class:`~gacli.errors.SystemFileError`.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp

from gacli import frames as F
from gacli import nonlinear as NL
from gacli.contact import RollingContacts
from gacli import symbols as S
from gacli import trig
from gacli.errors import Diagnostic, Location, SystemFileError
from gacli.read.expr.build import BuildError, Scope, build
from gacli.read.expr.grammar import FUNCTIONS, ParseError
from gacli.read.expr.parser import parse
from gacli.fastdiff import jacobian_rows
from gacli.graph import is_small
from gacli.read.imaginary import imaginary_problem
from gacli.zero import vanishes
from gacli.numeric import Program
from gacli.model import (
    Body,
    Constraint,
    Coordinate,
    Force,
    Form,
    Function,
    Input,
    Parameter,
    QuasiCoordinate,
    System,
    Torque,
)
from gacli.read.schema import (
    BodyDecl,
    FrameDecl,
    LoadDecl,
    SymbolDecl,
    SystemDecl,
    VectorDecl,
    VelocityConstraintDecl,
)
from gacli.read.declarations import read_declarations
from gacli.read.reader import did_you_mean
from gacli.read.source import Scalar, SourceFile, parse_source, read_source

RESERVED = {"t": "time", "pi": "the constant π", "dot": "the rate operator", "ddot": "the rate operator"}
MAX_SYMBOLS = 500

_KIND_WORDS = {
    "parameter": "a parameter", "function": "a function", "input": "an input",
    "coordinate": "a coordinate", "quasi": "a quasi-coordinate",
}


def load(path: str | Path) -> System:
    """Read, parse and validate a system file.

    Raises:
        SystemFileError: with every problem found, each located in the file.
    """
    return load_source(read_source(path))


def loads(text: str, path: str = "<string>") -> System:
    """Like :func:`load`, from text in memory."""
    return load_source(parse_source(text.encode("utf-8"), path))


def load_source(source: SourceFile) -> System:
    decl, diagnostics = read_declarations(source)
    if diagnostics or decl is None:
        raise SystemFileError(diagnostics)
    builder = _Builder(decl)
    system = builder.system()
    if builder.diagnostics:
        raise SystemFileError(sorted(builder.diagnostics, key=lambda d: d.location))
    return system


@dataclass
class _Builder(RollingContacts):
    decl: SystemDecl
    diagnostics: list[Diagnostic] = field(default_factory=list)
    known: dict[sp.Symbol, float] = field(default_factory=dict)  # parameters' numeric values, as read

    # -- reporting ---------------------------------------------------------
    @property
    def source(self) -> SourceFile:
        return self.decl.source

    def error(self, node, where: str, message: str, hint: str = "", offset: int | None = None) -> None:
        location = self.source.location(node, offset)
        self.diagnostics.append(Diagnostic(location, message, where, hint))

    def where_of(self, node) -> Location:
        return self.source.location(node)

    # -- expressions -------------------------------------------------------
    def expression(self, text: Scalar | None, where: str, scope: Scope, start: int = 0, stop: int | None = None):
        """Parse and build text[start:stop]; None (and a diagnostic) on error."""
        if text is None:
            return None
        piece = text.text[start:stop]
        try:
            expr = build(parse(piece), scope)
        except ParseError as exc:
            self.error(text, where, exc.message, offset=start + exc.pos)
        except BuildError as exc:
            self.error(text, where, exc.message, exc.hint, offset=start + exc.pos)
        else:
            if not (problem := imaginary_problem(expr, self.known)):
                return expr
            self.error(text, where, problem, offset=start)
        return None

    # -- the whole system --------------------------------------------------
    def system(self) -> System:
        self._check_names()
        parameters = self._parameters()
        functions = self._functions(parameters)
        self.scopes = _Scopes.make(self.decl, parameters, functions)
        coordinates = tuple(
            Coordinate(s.name, self.where_of(s.node), s.description, s.unit, s.latex)
            for s in self.decl.of_kind("coordinate")
        )
        inputs = tuple(Input(s.name, self.where_of(s.node), s.description, s.unit, s.latex) for s in self.decl.of_kind("input"))
        quasi = tuple(self._quasi(s) for s in self.decl.of_kind("quasi"))
        self.frames = self._frames()
        self._failed_points: set[str] = set()
        self.points = self._points()
        self._frame_origins()
        bodies = tuple(b for b in (self._body(b) for b in self.decl.bodies) if b)
        self.body_frames = {b.name: b.frame for b in self.decl.bodies if b.frame is not None}
        forces, torques = self._loads(bodies)
        work = self._form(self.decl.work, "work", self.scopes.work) if self.decl.work else None
        if work is not None and work.dt != 0:
            self.error(self.decl.work, "work", "virtual work has no dt term (δt = 0 in a virtual displacement)")
        potential = self.expression(self.decl.potential, "potential", self.scopes.config) if self.decl.potential else None
        constraints = tuple(c for c in (self._constraint(i, c) for i, c in enumerate(self.decl.constraints)) if c)
        constraints += self._rolling_constraints(bodies)
        independent = self._independent()
        return System(
            name=self.decl.name, path=self.source.path, sha256=self.source.sha256,
            location=Location(self.source.path, 1, 1),
            title=self.decl.title, description=self.decl.description, reference=self.decl.reference,
            parameters=parameters, functions=functions, inputs=inputs,
            coordinates=coordinates, quasi_coordinates=quasi, constraints=constraints,
            independent=independent,
            independent_location=self.where_of(self.decl.independent_node) if self.decl.independent_node else Location(self.source.path, 1, 1),
            bodies=bodies, forces=forces, torques=torques, work=work,
            potential=potential if potential is not None else sp.S.Zero,
            uses_frames=bool(self.decl.frames or self.decl.points or self.decl.rolling),
        )

    def _check_names(self) -> None:
        seen: dict[str, SymbolDecl] = {}
        if len(self.decl.symbols) > MAX_SYMBOLS:
            self.error(self.decl.symbols[MAX_SYMBOLS].node, "", f"too many declared names (the limit is {MAX_SYMBOLS})")
        rated = {s.name for s in self.decl.symbols if s.kind in ("coordinate", "quasi")}
        for sym in self.decl.symbols:
            where = f"{_section(sym.kind)}.{sym.name}"
            if sym.name in seen:
                first = seen[sym.name]
                self.error(sym.node, where, f"'{sym.name}' is already declared as {_KIND_WORDS[first.kind]} (line {first.node.line})")
                continue
            seen[sym.name] = sym
            if sym.name in RESERVED:
                self.error(sym.node, where, f"'{sym.name}' is reserved for {RESERVED[sym.name]}")
            elif sym.name in FUNCTIONS:
                self.error(sym.node, where, f"'{sym.name}' is the name of a function and cannot be declared")
            elif sym.name.startswith("d") and sym.name[1:] in rated:
                self.error(sym.node, where, f"'{sym.name}' would be the differential of '{sym.name[1:]}'",
                           "rename it; 'd' + a coordinate name is its differential")

    def _parameters(self) -> tuple[Parameter, ...]:
        out: list[Parameter] = []
        # The scopes grow by one name per parameter; made afresh each time
        # (symbols and all), they cost quadratic time in a file of many parameters.
        earlier: dict[str, sp.Symbol] = {}
        declared = self._all_names()
        refused = {s.name: "a parameter's value may name only earlier parameters" for s in self.decl.symbols}
        counts = Counter(s.name for s in self.decl.symbols)
        for sym in self.decl.of_kind("parameter"):
            value = None
            if sym.value is not None:
                refusals = dict(refused)
                if counts[sym.name] == 1:  # a duplicate's twin stays refused
                    del refusals[sym.name]
                scope = Scope(values=dict(earlier), declared=declared, refusals=refusals)
                value = self.expression(sym.value, f"parameters.{sym.name}.value", scope)
            out.append(Parameter(sym.name, self.where_of(sym.node), sym.description, sym.unit, sym.latex, value))
            earlier[sym.name] = S.value(sym.name)
            self._remember(earlier[sym.name], value)
        return tuple(out)

    def _remember(self, symbol: sp.Symbol, value: sp.Expr | None) -> None:
        """The parameter's number, for telling later expressions that are never real."""
        if value is None or not value.free_symbols <= set(self.known):
            return
        try:  # Program, not evalf: evalf of exp(exp(exp(100))) would take hours
            number = Program([value])(self.known)[0]
        except (TypeError, ValueError, ArithmeticError):
            return
        if number.imag == 0:
            self.known[symbol] = number.real

    def _functions(self, parameters: tuple[Parameter, ...]) -> tuple[Function, ...]:
        values = {p.name: S.value(p.name) for p in parameters}
        values["t"] = S.T
        scope = Scope(values=values, declared=self._all_names(),
                      refusals={n: "a function's value depends on t and parameters only" for n in self._all_names()})
        out = []
        for sym in self.decl.of_kind("function"):
            value = self.expression(sym.value, f"functions.{sym.name}.value", scope)
            out.append(Function(sym.name, self.where_of(sym.node), sym.description, sym.unit, sym.latex, value))
        return tuple(out)

    def _all_names(self) -> frozenset[str]:
        return frozenset(s.name for s in self.decl.symbols)

    # -- differential forms ------------------------------------------------
    def _form(self, text: Scalar, where: str, scope: Scope, start: int = 0, stop: int | None = None) -> Form | None:
        expr = self.expression(text, where, scope, start, stop)
        if expr is None:
            return None
        return self._as_form(expr, text, where, start)

    def _as_form(self, expr: sp.Expr, text: Scalar, where: str, start: int = 0) -> Form | None:
        try:
            return self._linear_form(expr, text, where, start)
        except (ArithmeticError, ValueError, TypeError, RecursionError):
            # SymPy evaluates numbers as it goes; an extreme one (cosh(cosh(1e300))) overflows.
            self.error(text, where, "this form cannot be evaluated: a number in it is too large", offset=start)
            return None

    def _linear_form(self, expr: sp.Expr, text: Scalar, where: str, start: int) -> Form | None:
        names = self.scopes.rate_names
        free = expr.free_symbols
        present = [d for d in [S.differential(n) for n in names] + [S.DT] if d in free]
        # One memoised pass for all the coefficients (sp.diff walks the form once per differential).
        partials = dict(zip(present, jacobian_rows([expr], present)[0])) if present else {}
        problem = _linearity_problem(expr, partials)
        if problem:
            self.error(text, where, problem, offset=start)
            return None
        coefficients = ((n, partials.get(S.differential(n), sp.S.Zero)) for n in names)
        return Form(tuple((n, c) for n, c in coefficients if c != 0), partials.get(S.DT, sp.S.Zero))

    def _quasi(self, sym: SymbolDecl) -> QuasiCoordinate:
        form = None
        if sym.differential is not None:
            form = self._form(sym.differential, f"quasi_coordinates.{sym.name}", self.scopes.form)
            if form is not None and not form.coefficients and form.dt == 0:
                self.error(sym.differential, f"quasi_coordinates.{sym.name}", "the differential is zero")
        return QuasiCoordinate(sym.name, self.where_of(sym.node), sym.description, sym.unit, sym.latex, form)

    def _constraint(self, index: int, text) -> Constraint | None:
        where = f"constraints[{index}]"
        if isinstance(text, VelocityConstraintDecl):
            return self._velocity_constraint(text, where)
        sides = _split_equation(text.text)
        if isinstance(sides, int):
            self.error(text, where, "a constraint has at most one '=' (write lhs = rhs)", offset=sides)
            return None
        parts = [self.expression(text, where, self.scopes.constraint, a, b) for a, b in sides]
        if any(p is None for p in parts):
            return None
        expr = parts[0] - parts[1] if len(parts) == 2 else parts[0]
        diffs = {S.differential(n) for n in self.scopes.rate_names} | {S.DT}
        rates = {S.rate(n) for n in self.scopes.rate_names}
        try:
            nonlinear = bool(expr.free_symbols & rates) or bool(expr.free_symbols & diffs) and not _is_linear_form(expr, diffs)
        except (ArithmeticError, ValueError, TypeError, RecursionError):
            # SymPy evaluates numbers as it goes; an extreme one (cosh(cosh(1e300))) overflows.
            self.error(text, where, "this form cannot be evaluated: a number in it is too large")
            return None
        if nonlinear:
            try:
                return self._rate_constraint(expr, parts[0] if len(parts) == 2 else None, text, where)
            except (ArithmeticError, ValueError, TypeError, RecursionError):
                self.error(text, where, "this relation cannot be evaluated: a number in it is too large")
                return None
        if expr.free_symbols & diffs:
            form = self._as_form(expr, text, where)
            return Constraint(form, self.where_of(text), text.text) if form else None
        return self._finite_constraint(expr, text, where)

    def _rate_constraint(self, expr: sp.Expr, lhs: sp.Expr | None, text: Scalar, where: str) -> Constraint | None:
        """A constraint nonlinear in the rates (docs/nonlinear.md): solved for the rate it determines."""
        names = self.scopes.rate_names
        g, kind = NL.rate_form(expr, names)
        if g is None and kind == "homogeneous":
            present = expr.free_symbols & ({S.differential(n) for n in names} | {S.DT})
            self.error(text, where, f"the form is not linear in the differentials: {_offending_term(expr, present)}, "
                       "nor homogeneous of degree one in them (as a velocity relation such as "
                       "dz = -c*sqrt(dx**2 + dy**2) is)")
            return None
        if g is None:
            self.error(text, where, kind)
            return None
        preferred = next((n for n in names if lhs in (S.rate(n), S.differential(n))), None)
        independent = self.decl.independent
        solved = NL.solve_for_rate(g, names, preferred, [s.text for s in independent] if independent else None)
        if isinstance(solved, str):
            self.error(text, where, solved)
            return None
        coefficients, rest = NL.linearized_row(g, names)
        return Constraint(Form(coefficients, rest), self.where_of(text), text.text, rates=solved)

    def _finite_constraint(self, expr: sp.Expr, text: Scalar, where: str) -> Constraint | None:
        """f(q, t) = 0 is used through df = 0."""
        if expr == 0:
            self.error(text, where, "the constraint is identically satisfied")
            return None
        coordinates = [s.name for s in self.decl.of_kind("coordinate")]
        gradient = tuple((n, sp.diff(expr, S.value(n))) for n in coordinates)
        dt = S.time_derivative(expr, self.scopes.function_chain)
        return Constraint(Form(tuple((n, c) for n, c in gradient if c != 0), dt), self.where_of(text), text.text, expr)

    # -- bodies and loads --------------------------------------------------
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
                    self.error(frame, where, f"'{frame.text}' is not a frame", did_you_mean(frame.text, self.frames))
                    return None
                values = self._vector(items, f"{where}.{frame.text}", scope)
                if values is None:
                    return None
                terms[frame.text] = values
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

    # -- frames and points -------------------------------------------------
    def differential(self, expr: sp.Expr) -> sp.Matrix:
        """d(expr) as a row over the differentials of the rate names, then dt."""
        coordinates = {s.name for s in self.decl.of_kind("coordinate")}
        row = [sp.diff(expr, S.value(n)) if n in coordinates else sp.S.Zero for n in self.scopes.rate_names]
        return sp.Matrix([row + [S.time_derivative(expr, self.scopes.function_chain)]])

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
            self.error(decl.parent, f"{where}.parent", f"'{parent}' is not a frame declared before '{decl.name}'",
                       did_you_mean(parent, frames))
            return None
        rotations = []
        for i, (axis, text) in enumerate(decl.rotations):
            angle = self.expression(text, f"{where}.rotations[{i}]", self.scopes.config)
            if angle is None:
                return None
            rotations.append((axis.text.lower(), angle))
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

    # -- bodies and loads --------------------------------------------------
    def _body(self, decl: BodyDecl) -> Body | None:
        where = f"bodies.{decl.name}"
        mass = self.expression(decl.mass, f"{where}.mass", self.scopes.constant)
        position = self._in_frames(decl.position, f"{where}.position", self.scopes.config)
        inertia = rotation = None
        if decl.is_rigid:
            inertia = self._inertia(decl, where)
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
            self.error(decl.frame, f"{where}.frame", f"'{decl.frame.text}' is not a frame",
                       did_you_mean(decl.frame.text, self.frames))
            return None
        return tuple(self._row_form(frame.omega[i, :]) for i in range(3))

    def _row_form(self, row: sp.Matrix) -> Form:
        names = self.scopes.rate_names
        coefficients = tuple((n, row[j]) for j, n in enumerate(names) if row[j] != 0)
        return Form(coefficients, row[len(names)])

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
        forms = [self._form(item, f"{where}.rotation[{i}]", self.scopes.form) for i, item in enumerate(decl.rotation)]
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
            else:
                torque = self._torque(load, by_name)
                torques += [torque] if torque else []
        return tuple(forces), tuple(torques)

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
            return (sp.S.Zero, sp.S.Zero, values[0]) if len(values) == 1 else tuple(values)
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

    # -- constraints from geometry -----------------------------------------
    def _velocity_form(self, position) -> sp.Matrix:
        """d r of a point (inertial components), as a form vector."""
        return sp.Matrix.vstack(*(self.differential(c) for c in position))

    def _velocity_constraint(self, decl: VelocityConstraintDecl, where: str) -> Constraint | None:
        point = self._point_named(decl.point, f"{where}.velocity_of")
        along = self._in_frames(decl.along, f"{where}.along", self.scopes.config)
        if point is None or along is None:
            return None
        row = sp.Matrix([along]) * self._velocity_form(point)
        return Constraint(self._row_form(row), self.where_of(decl.node), f"velocity of {decl.point.text} along {list(along)}")

    def _independent(self) -> tuple[str, ...] | None:
        if self.decl.independent is None:
            return None
        rated = {s.name: s for s in self.decl.symbols if s.kind in ("coordinate", "quasi")}
        names: list[str] = []
        for i, node in enumerate(self.decl.independent):
            where = f"independent[{i}]"
            if node.text in names:
                self.error(node, where, f"'{node.text}' is listed twice")
            elif node.text not in rated:
                    self.error(node, where, f"'{node.text}' is not a coordinate or quasi-coordinate",
                           did_you_mean(node.text, rated))
            else:
                names.append(node.text)
        return tuple(names)


def _section(kind: str) -> str:
    return {"quasi": "quasi_coordinates"}.get(kind, kind + "s")


def _split_equation(text: str) -> list[tuple[int, int | None]] | int:
    """Spans of the sides of 'lhs = rhs', or the offset of a second '='."""
    first = text.find("=")
    if first < 0:
        return [(0, None)]
    second = text.find("=", first + 1)
    if second >= 0:
        return second
    return [(0, first), (first + 1, None)]


def _is_linear_form(expr: sp.Expr, diffs: set[sp.Symbol]) -> bool:
    """Whether no differential's coefficient holds a differential (cheap: degree two is enough to refuse)."""
    present = expr.free_symbols & diffs
    return all(not (sp.diff(expr, d).free_symbols & present) for d in present)


def _linearity_problem(expr: sp.Expr, partials: dict[sp.Symbol, sp.Expr]) -> str:
    """Why ``expr`` is not a linear form in the differentials it has ('' when it is).

    ``partials`` maps each differential present in ``expr`` to ∂expr/∂d.
    """
    present = set(partials)
    if not present:
        return "expected a differential form (a combination of differentials such as dx and dt), found no differential"
    for d in sorted(present, key=sp.default_sort_key):
        if partials[d].free_symbols & present:
            return f"the form is not linear in the differentials: {_offending_term(expr, present)}"
    rest = expr.xreplace({d: 0 for d in present})
    if not vanishes(rest):
        return f"every term of a differential form needs a differential; '{_plain(rest)}' has none"
    return ""


def _offending_term(expr: sp.Expr, present: set) -> str:
    # A small tree may still multiply out to millions of terms ((dx + x + ... )**100).
    if not is_small(expr, 400) or trig.expanded_terms(expr, 2_000) > 2_000:
        return "a differential appears inside a power or a function"
    for term in sp.Add.make_args(sp.expand(expr)):
        degree = sum(sp.degree(term, d) for d in present if d in term.free_symbols) if term.is_polynomial(*present) else 2
        if degree > 1:
            return f"term '{_plain(term)}' is not linear"
    return "a differential appears inside a function"


def _plain(expr: sp.Expr) -> str:
    """An expression written in the file's grammar (differentials as dx)."""
    text = sp.sstr(expr)
    return text.replace("d[", "d").replace("]", "")


@dataclass(frozen=True)
class _Scopes:
    """The scopes of each kind of place in a system file."""

    constant: Scope
    config: Scope
    form: Scope
    constraint: Scope  # a form's scope, and the rates too: a constraint may be nonlinear in them
    load: Scope
    work: Scope
    rate_names: tuple[str, ...]
    function_chain: dict

    @staticmethod
    def make(decl: SystemDecl, parameters, functions) -> "_Scopes":
        declared = frozenset(s.name for s in decl.symbols)
        kinds = {s.name: s.kind for s in decl.symbols}
        coordinates = [s.name for s in decl.of_kind("coordinate")]
        rated = coordinates + [s.name for s in decl.of_kind("quasi")]
        params = {p.name: S.value(p.name) for p in parameters}
        fvalues, frates = _function_values(functions)
        config_values = {**params, **fvalues, **{c: S.value(c) for c in coordinates}, "t": S.T}
        refusals = _refusals(kinds, "config")
        config = Scope(config_values, frates, {}, refusals, declared, _CONFIG_NOTE)
        constant = Scope(params, {}, {}, _refusals(kinds, "constant"), declared)
        diffs = {f"d{n}": S.differential(n) for n in rated}
        diffs["dt"] = S.DT
        form = Scope(config_values, frates, diffs, refusals, declared, _CONFIG_NOTE)
        load_rates = {**frates, **{(n, 1): S.rate(n) for n in rated}}
        constraint = Scope(config_values, load_rates, diffs, refusals, declared, _CONFIG_NOTE)
        load_values = {**config_values, **{s.name: S.value(s.name) for s in decl.of_kind("input")}}
        load = Scope(load_values, load_rates, {}, _refusals(kinds, "load"), declared, _LOAD_NOTE)
        work = Scope(load_values, load_rates, diffs, _refusals(kinds, "load"), declared, _LOAD_NOTE)
        chain = {S.rate(f.name, o): S.rate(f.name, o + 1) for f in functions if f.value is None for o in range(4)}
        return _Scopes(constant, config, form, constraint, load, work, tuple(rated), chain)


def _function_values(functions) -> tuple[dict, dict]:
    """Names and rates of functions: a value substitutes, a free function stays a symbol."""
    values, rates = {}, {}
    for f in functions:
        if f.value is None:
            values[f.name] = S.value(f.name)
            rates.update({(f.name, o): S.rate(f.name, o) for o in (1, 2)})
        else:
            values[f.name] = f.value
            rates.update({(f.name, o): sp.diff(f.value, S.T, o) for o in (1, 2)})
    return values, rates


_CONFIG_NOTE = "this depends on the configuration only (coordinates, parameters, functions and t), not on rates"
_LOAD_NOTE = "loads may depend on first rates dot(x), not on accelerations"

_WHY = {
    ("quasi", "config"): "'{n}' is a quasi-coordinate: it has a rate dot({n}) and a differential d{n}, but no value",
    ("quasi", "load"): "'{n}' is a quasi-coordinate: it has a rate dot({n}) and a differential d{n}, but no value",
    ("quasi", "constant"): "'{n}' is a quasi-coordinate; only parameters may appear here",
    ("input", "config"): "'{n}' is an input; inputs may appear only in loads and work",
    ("input", "constant"): "'{n}' is an input; only parameters may appear here",
    ("coordinate", "constant"): "'{n}' is a coordinate; only parameters may appear here (masses and inertias are constant)",
    ("function", "constant"): "'{n}' is a function of time; only parameters may appear here",
}


def _refusals(kinds: dict[str, str], place: str) -> dict[str, str]:
    out = {}
    for name, kind in kinds.items():
        why = _WHY.get((kind, place))
        if why:
            out[name] = why.format(n=name)
    return out
