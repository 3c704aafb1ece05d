"""Load a system file: source → declarations → parsed expressions → System.

Each expression is parsed by our own grammar and built under the scope of
the place it stands in, so a mass cannot name a coordinate and a position
cannot name an input. All problems are collected and raised together as one
:class:`~gacli.errors.SystemFileError`.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path

import sympy as sp

from gacli.loader.contact import RollingContacts
from gacli.loader.bodies import Geometry
from gacli.loader import kinks
from gacli.loader.inertia import MovedInertia
from gacli.loader.kinks import kink
from gacli.loader.lines import Lines
from gacli.loader.forms import Forms
from gacli.loader.frame_records import frame_model
from gacli.loader.quaternions import Quaternions
from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.errors import Diagnostic, Location, SystemFileError
from gacli.read.expr.build import BuildError, Scope, build
from gacli.read.expr.grammar import FUNCTIONS, ParseError
from gacli.read.expr.parser import parse
from gacli.read.imaginary import imaginary_problem
from gacli.numeric import Program
from gacli.model import Coordinate, Function, Input, Parameter, System
from gacli.read.declarations import read_declarations
from gacli.read.reader import did_you_mean
from gacli.read.schema import SymbolDecl, SystemDecl
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


def load_source(source: SourceFile, *, rolling_rows: bool = True) -> System:
    """The System of a source. ``rolling_rows=False`` leaves out the rolling rows in N, 80 %
    of a bicycle's loading: the straight-line program (gacli.mechanics.program) forms its
    own from the frame model, and every declaration is still read and checked. Such a
    System has ``rolling_rows`` False, and the chapter's steps refuse it."""
    system, complete = load_in_stages(source)
    return complete() if rolling_rows else system


def load_in_stages(source: SourceFile) -> tuple[System, Callable[[], System]]:
    """The System without its rolling rows, and a function that adds them to it.

    The file is read and every declaration checked once, in the first stage;
    the second forms only the rolling rows, from the same builder, so that a
    command that may not need them (generated code by the program) loads the
    file once either way. Both stages raise located SystemFileErrors.
    """
    decl, diagnostics = read_declarations(source)
    if diagnostics or decl is None:
        raise SystemFileError(diagnostics)
    builder = _Builder(decl, rolling_rows=False)
    system = _guarded(source, builder.system)
    done: list[System] = []

    def complete() -> System:
        if not done:
            done.append(_guarded(source, lambda: builder.with_rolling_rows(system)))
        return done[0]

    return system, complete


def _guarded(source: SourceFile, stage: Callable[[], System]) -> System:
    try:
        system = stage()
    except (RecursionError, OverflowError) as exc:
        # A frame turned by 1e300*delta made SymPy recurse without end in a rolling row:
        # one located message, as every other problem of the file, not a traceback.
        why = "an expression nests too deeply" if isinstance(exc, RecursionError) else "a number is too large"
        raise SystemFileError([Diagnostic(Location(source.path, 1, 1),
                                          f"the file cannot be loaded: {why} to evaluate ({type(exc).__name__})")])
    return system


@dataclass
class _Builder(Forms, Geometry, RollingContacts, Lines, MovedInertia, Quaternions):
    decl: SystemDecl
    diagnostics: list[Diagnostic] = field(default_factory=list)
    known: dict[sp.Symbol, float] = field(default_factory=dict)  # parameters' numeric values, as read
    # Parsed pieces of frames, vectors and rolling contacts by id of their declaration, for the frame model.
    parsed: dict[int, object] = field(default_factory=dict)
    rolling_rows: bool = True  # form the rolling contacts' rows in N (see load_source)

    @property
    def source(self) -> SourceFile:
        return self.decl.source

    def error(self, node, where: str, message: str, hint: str = "", offset: int | None = None) -> None:
        location = self.source.location(node, offset)
        self.diagnostics.append(Diagnostic(location, message, where, hint))

    def where_of(self, node) -> Location:
        return self.source.location(node)

    def expression(self, text: Scalar | None, where: str, scope: Scope, start: int = 0, stop: int | None = None,
                   times: int | None = None):
        """Parse and build text[start:stop]; None (and a diagnostic) on error. ``times``: how often the
        equations differentiate it (gacli.loader.kinks); by default, what the scope's places are."""
        if text is None:
            return None
        piece = text.text[start:stop]
        try:
            tree = parse(piece)
            expr = build(tree, scope)
        except ParseError as exc:
            self.error(text, where, exc.message, offset=start + exc.pos)
        except BuildError as exc:
            self.error(text, where, exc.message, exc.hint, offset=start + exc.pos)
        else:
            times = self._differentiated(scope, expr) if times is None else times
            moves = lambda e: bool(e.free_symbols - self._constants)  # noqa: E731
            if call := kink(tree, times, lambda node: moves(build(node, scope))):
                self.error(text, where, kinks.message(call.func, times), kinks.hint(call.func, times),
                           offset=start + call.pos)
            elif written := kinks.built_kink(expr, times, moves):  # sqrt(x**2) is Abs(x) once built
                self.error(text, where, kinks.message(written, times), kinks.hint(written, times), offset=start)
            elif not (problem := imaginary_problem(expr, self.known)):
                return expr
            else:
                self.error(text, where, problem, offset=start)
        return None

    def _differentiated(self, scope: Scope, expr: sp.Expr) -> int:
        """How often the equations differentiate an expression of ``scope``'s places: positions, angles,
        points and a constraint's finite relation (no differential, no rate) twice; forms and Pfaffian
        or rate constraints once; constants, loads and work never."""
        scopes = getattr(self, "scopes", None)
        if scopes is None:
            return 0
        if scope is scopes.constraint:
            rated = set(scope.differentials.values()) | {r for r in scope.rates.values() if r.is_Symbol}
            return 1 if expr.free_symbols & rated else 2
        return 2 if scope is scopes.config else 1 if scope is scopes.form else 0

    @property
    def _constants(self) -> set:
        return {S.value(p.name) for p in self.decl.of_kind("parameter")}

    def system(self) -> System:
        system = self._system()
        if self.diagnostics:
            raise SystemFileError(sorted(self.diagnostics, key=lambda d: d.location))
        return system

    def with_rolling_rows(self, system: System) -> System:
        """``system`` (this builder's, loaded without them) with its rolling rows, as one load forms them."""
        if system.rolling_rows:
            return system
        self.rolling_rows = True
        rolling = self._rolling_constraints(system.bodies)
        if self.diagnostics:
            raise SystemFileError(sorted(self.diagnostics, key=lambda d: d.location))
        return replace(system, constraints=system.constraints + rolling, rolling_rows=True)

    def _system(self) -> System:
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
        self.quaternion_frames = []
        self.frames = self._frames()
        quasi = self._frame_rates(quasi)
        self._failed_points: set[str] = set()
        self.points = self._points()
        self._frame_origins()
        bodies = tuple(b for b in (self._body(b) for b in self.decl.bodies) if b)
        self.body_frames = {b.name: b.frame for b in self.decl.bodies if b.frame is not None}
        self.torque_owners: dict[str, str] = {}  # a frame a torque acts on → the body it is fixed in
        forces, torques = self._loads(bodies)
        work = self._form(self.decl.work, "work", self.scopes.work) if self.decl.work else None
        if work is not None and work.dt != 0:
            self.error(self.decl.work, "work", "virtual work has no dt term (δt = 0 in a virtual displacement)")
        potential = self.expression(self.decl.potential, "potential", self.scopes.config, times=1) if self.decl.potential else None
        springs, dampers, lines = self._line_loads(bodies)
        own = {"potential": as_expr(potential if potential is not None else 0), "work": work}
        potential = springs + (potential if potential is not None else 0)
        work = dampers if work is None else (work if dampers is None else work + dampers)
        constraints = tuple(c for i, d in enumerate(self.decl.constraints) for c in self._constraints_of(i, d))
        constraints += self._unit_norms() + self._rolling_constraints(bodies)
        independent = self._independent()
        uses_frames = bool(self.decl.frames or self.decl.points or self.decl.rolling)
        frames = (frame_model(self.decl, self.parsed, bodies, self.torque_owners, lines, **own)
                  if uses_frames and not self.diagnostics else None)
        return System(
            name=self.decl.name, path=self.source.path, sha256=self.source.sha256,
            location=Location(self.source.path, 1, 1),
            title=self.decl.title, description=self.decl.description, reference=self.decl.reference,
            parameters=parameters, functions=functions, inputs=inputs,
            coordinates=coordinates, quasi_coordinates=quasi, constraints=constraints,
            independent=independent,
            independent_location=self.where_of(self.decl.independent_node) if self.decl.independent_node else Location(self.source.path, 1, 1),
            bodies=bodies, forces=forces, torques=torques, work=work,
            potential=as_expr(potential),
            uses_frames=uses_frames, frames=frames, rolling_rows=self.rolling_rows or not self.decl.rolling,
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
                    refusals[sym.name] = f"'{sym.name}' cannot be its own value: a value is a number or an " \
                                         "expression in parameters declared before it"
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
            value = self.expression(sym.value, f"functions.{sym.name}.value", scope, times=2)
            out.append(Function(sym.name, self.where_of(sym.node), sym.description, sym.unit, sym.latex, value))
        return tuple(out)

    def _all_names(self) -> frozenset[str]:
        return frozenset(s.name for s in self.decl.symbols)

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
        chain = S.function_chain(f.name for f in functions if f.value is None)
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

