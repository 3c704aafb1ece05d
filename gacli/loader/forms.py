"""Differential forms and constraints of a system file, for the loader's builder.

Constraints (eq. 14.1) and quasi-coordinate definitions (eq. 14.2) are read as
forms linear in the differentials; a constraint nonlinear in the rates is solved
for the rate it determines (docs/nonlinear.md), a finite one is differentiated.
:class:`Forms` is a part of :class:`gacli.loader.loading._Builder`: it reads expressions
and reports through it.
"""

from __future__ import annotations

import sympy as sp

from gacli.loader import nonlinear as NL
from gacli.algebra import symbols as S
from gacli.read.expr.build import Scope
from gacli.algebra.fastdiff import jacobian_rows
from gacli.algebra.graph import expands_within, is_small
from gacli.algebra.coerce import as_expr
from gacli.numeric.zero import decide_zero, vanishes
from gacli.model import Constraint, Form, QuasiCoordinate
from gacli.read.schema import CoincidenceDecl, GuideDecl, SymbolDecl, VelocityConstraintDecl
from gacli.read.source import Scalar


class Forms:
    """Forms, quasi-coordinates and constraints, for the loader's builder."""

    def _form(self, text: Scalar, where: str, scope: Scope, start: int = 0, stop: int | None = None,
              zero: bool = False) -> Form | None:
        """The form ``text`` writes; ``zero``: 0 (or any expression that vanishes) is the zero form, as
        a rotation component about which a body does not turn (``rotation: [0, 0, dq1]``)."""
        expr = self.expression(text, where, scope, start, stop)
        if expr is None:
            return None
        return self._as_form(expr, text, where, start, zero)

    def _as_form(self, expr: sp.Expr, text: Scalar, where: str, start: int = 0, zero: bool = False) -> Form | None:
        try:
            if zero and vanishes(expr):
                return Form(())
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

    def _constraints_of(self, index: int, decl) -> tuple[Constraint, ...]:
        """The constraints one entry of ``constraints`` gives: one, or a coincidence's up to three."""
        if isinstance(decl, CoincidenceDecl):
            return self._coincidence(decl, f"constraints[{index}]")
        if isinstance(decl, GuideDecl):
            return self._guide(decl, f"constraints[{index}]")
        constraint = self._constraint(index, decl)
        return (constraint,) if constraint else ()

    def _coincidence(self, decl: CoincidenceDecl, where: str) -> tuple[Constraint, ...]:
        """B − A = 0 along N's axes, each component that is not identically zero a holonomic
        constraint f(q, t) = 0, used through its differential (eq. 14.1)."""
        ends = [self._point_named(e, f"{where}.coincide") for e in decl.ends]
        if any(e is None for e in ends):
            return ()
        a, b = ends
        names = " and ".join(e.text for e in decl.ends)
        gaps = {f"{names} coincide along N's {axis} axis": as_expr(y) - as_expr(x) for axis, x, y in zip("xyz", a, b)}
        return self._holonomic_rows(gaps, decl.node, where, f"{names} are the same point wherever the system is: "
                                                           "their coincidence constrains nothing")

    def _guide(self, decl: GuideDecl, where: str) -> tuple[Constraint, ...]:
        """The point's place from the frame's origin, along each of the frame's axes it may not move
        along, is zero: a holonomic constraint each (eq. 14.1), as for a coincidence."""
        place = f"{where}.{decl.key}"
        point = self._point_named(decl.point, place)
        frame = self.frames.get(decl.frame.text)
        if frame is None:
            self.not_a_frame(decl.frame, place)
        if point is None or frame is None:
            return ()
        origin = frame.origin or (sp.S.Zero,) * 3
        gap = [as_expr(p) - as_expr(o) for p, o in zip(point, origin)]
        said = f"{decl.point.text} {decl.key.replace('_', ' ')} {decl.frame.text}"
        gaps = {f"{said} (none along its {'xyz'[axis]} axis)": sp.Add(*(frame.dcm[row, axis] * g for row, g in enumerate(gap)))
                for axis in range(3) if axis not in decl.free}
        return self._holonomic_rows(gaps, decl.node, where, f"{decl.point.text} is on that "
                                    f"{'line' if len(decl.free) == 1 else 'plane'} wherever the system is: "
                                    "the constraint constrains nothing")

    def _holonomic_rows(self, gaps: dict[str, sp.Expr], node, where: str, idle: str) -> tuple[Constraint, ...]:
        """A holonomic constraint for each gap that is not identically zero (a coincidence's or a guide's
        components); ``idle`` is the error when none is left."""
        out = tuple(self._holonomic(gap, self.where_of(node), text)
                    for text, gap in gaps.items() if not decide_zero(gap).zero)
        if not out:
            self.error(node, where, idle)
        return out

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
            expr = _rates_as_differentials(expr, self.scopes.rate_names, diffs)
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
        return self._holonomic(expr, self.where_of(text), text.text)

    def _holonomic(self, expr: sp.Expr, location, text: str) -> Constraint:
        """f(q, t) = 0 as the row df = Σ ∂f/∂q dq + ∂f/∂t dt."""
        coordinates = [s.name for s in self.decl.of_kind("coordinate")]
        gradient = tuple((n, sp.diff(expr, S.value(n))) for n in coordinates)
        dt = S.time_derivative(expr, self.scopes.function_chain)
        return Constraint(Form(tuple((n, c) for n, c in gradient if c != 0), dt), location, text, expr)

    def differential(self, expr: sp.Expr) -> sp.Matrix:
        """d(expr) as a row over the differentials of the rate names, then dt."""
        coordinates = {s.name for s in self.decl.of_kind("coordinate")}
        row = [sp.diff(expr, S.value(n)) if n in coordinates else sp.S.Zero for n in self.scopes.rate_names]
        return sp.Matrix([row + [S.time_derivative(expr, self.scopes.function_chain)]])

    def _velocity_form(self, position) -> sp.Matrix:
        """d r of a point (inertial components), as a form vector."""
        # One memoised walk per coordinate for the three components: they share
        # most of their terms (a wheel's hub through a chain of frames).
        names = self.scopes.rate_names
        coordinates = {s.name for s in self.decl.of_kind("coordinate")}
        moving = [n for n in names if n in coordinates]
        partials = jacobian_rows(position, [S.value(n) for n in moving])
        rows = []
        for c, row in zip(position, partials):
            by_name = dict(zip(moving, row))
            rows.append([by_name.get(n, sp.S.Zero) for n in names]
                        + [S.time_derivative(c, self.scopes.function_chain)])
        return sp.Matrix(rows)

    def _velocity_constraint(self, decl: VelocityConstraintDecl, where: str) -> Constraint | None:
        point = self._point_named(decl.point, f"{where}.velocity_of")
        along = self._in_frames(decl.along, f"{where}.along", self.scopes.config)
        if point is None or along is None:
            return None
        row = sp.Matrix([along]) * self._velocity_form(point)
        return Constraint(self._row_form(row), self.where_of(decl.node), f"velocity of {decl.point.text} along {list(along)}")

    def _row_form(self, row: sp.Matrix) -> Form:
        names = self.scopes.rate_names
        coefficients = tuple((n, row[j]) for j, n in enumerate(names) if row[j] != 0)
        return Form(coefficients, row[len(names)])


def _split_equation(text: str) -> list[tuple[int, int | None]] | int:
    """Spans of the sides of 'lhs = rhs', or the offset of a second '='."""
    first = text.find("=")
    if first < 0:
        return [(0, None)]
    second = text.find("=", first + 1)
    if second >= 0:
        return second
    return [(0, first), (first + 1, None)]


def _rates_as_differentials(expr: sp.Expr, names, diffs: set[sp.Symbol]) -> sp.Expr:
    """A relation written with rates but linear in them, Σ c ṙ + c₀ = 0 (dot(x) = r*dot(phi)), as the
    form Σ c dr + c₀ dt = 0 it is: classified, tested for integrability and solved as any Pfaffian row,
    not as a relation nonlinear in the rates (docs/nonlinear.md). Anything else is returned as it is."""
    differential = {S.rate(n): S.differential(n) for n in names}
    present = sorted(expr.free_symbols & differential.keys(), key=lambda r: r.name)
    if not present or expr.free_symbols & diffs:
        return expr
    partials = [sp.diff(expr, r) for r in present]
    if any(p.free_symbols & set(present) for p in partials):
        return expr
    rest = expr.xreplace({r: sp.S.Zero for r in present})
    return sp.Add(*(c * differential[r] for c, r in zip(partials, present))) + rest * S.DT


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
    if not is_small(expr, 400) or not expands_within(expr, 2_000):
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

