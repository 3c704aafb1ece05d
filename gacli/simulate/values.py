"""The command line's values resolved to numbers and expressions, every problem collected."""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping, Sequence

import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.mechanics.equations import Derivation
from gacli.read.expr.build import BuildError, Scope, build
from gacli.read.expr.grammar import Name, ParseError, Rate
from gacli.read.expr.parser import parse
from gacli.simulate.initial import constrained
from gacli.simulate.spec import MAX_FUNCTION_ORDER, MAX_VALUES, METHODS, Assignments, SimulationSpec
from gacli.simulate.suggest import closest_state


class OptionValues:
    """Resolves the options to numbers and expressions, collecting every problem."""

    def __init__(self, derivation: Derivation, state: tuple[str, ...]) -> None:
        self.derivation = derivation
        self.system = derivation.system
        self.state = state
        self.parameter_names = tuple(p.name for p in self.system.parameters)
        self.problems: list[str] = []
        self.usage: list[str] = []  # those that make it a usage error (exit 2): a name unknown, twice, a conflict

    def _refuse(self, problem: str) -> None:
        self.problems.append(problem)
        self.usage.append(problem)

    # -- checks of the plain options
    def check_numbers(self, spec: SimulationSpec) -> None:
        if spec.method not in METHODS:
            self._refuse(f"--method: '{spec.method}' is not a method of solve_ivp "
                                 f"(one of: {', '.join(METHODS)})")
        for option, value in (("--t-end", spec.t_end), ("--rtol", spec.rtol), ("--atol", spec.atol)):
            if not (math.isfinite(value) and value > 0):
                self._refuse(f"{option}: expected a positive number, found {float(value)!r}")  # not np.float64(...)
        if spec.points < 2:
            self._refuse(f"--points: expected at least 2, found {spec.points}")
        elif spec.points * len(self.state) > MAX_VALUES:
            self._refuse(f"--points: {spec.points:,} samples of {len(self.state)} state entries exceed "
                         f"{MAX_VALUES:,} values; at most {MAX_VALUES // len(self.state):,} samples for this system")

    def check_plot_names(self, spec: SimulationSpec) -> None:
        for option, names in (("--show", spec.show), ("--phase", spec.phase)):
            for name in names:
                self._state_name(option, name)
        if spec.phase and len(spec.phase) != 2:
            self._refuse(f"--phase: expected two state names (x,y), found {len(spec.phase)}")

    # -- parameters
    def parameters(self, assignments: Assignments) -> tuple[float, ...]:
        exprs = {p.name: p.value for p in self.system.parameters if p.value is not None}
        symbols = {n: S.value(n) for n in self.parameter_names}
        scope = self._scope("--set", symbols, "numbers and parameters")
        for name, text in self._unique("--set", assignments):
            if self._known("--set", name, self.parameter_names, "a parameter"):
                expr = self._expression("--set", name, text, scope)
                exprs[name] = expr if expr is not None else exprs.get(name, sp.nan)
        missing = [n for n in self.parameter_names if n not in exprs]
        if missing:
            self._missing("parameter", missing, "--set", "numbers, or expressions in parameters")
        numbers = self._resolve(exprs)
        return tuple(numbers.get(n, math.nan) for n in self.parameter_names)

    def _resolve(self, exprs: dict[str, sp.Expr]) -> dict[str, float]:
        """Values that name other parameters, in dependency order; cycles are reported."""
        known: dict[sp.Symbol, sp.Expr] = {}
        numbers: dict[str, float] = {}
        pending = dict(exprs)
        while pending:
            ready = [n for n, e in pending.items() if not (e.free_symbols - set(known))]
            if not ready:
                break
            for name in ready:
                number = self._number(f"parameter '{name}'", pending.pop(name).xreplace(known))
                numbers[name] = number
                known[S.value(name)] = sp.Float(number) if math.isfinite(number) else sp.nan
        stuck = sorted(n for n, e in pending.items() if {s.name for s in e.free_symbols} <= set(exprs))
        if stuck:
            self.problems.append(f"--set: the values of {', '.join(stuck)} refer to each other")
        return numbers

    def _number(self, what: str, expr: sp.Expr) -> float:
        if expr.has(sp.nan):  # a value it names is wrong, and reported already
            return math.nan
        value = complex(sp.N(expr))
        if value.imag != 0 or not math.isfinite(value.real):
            self.problems.append(f"{what}: the value {sp.sstr(expr)} is not a finite real number")
            return math.nan
        return value.real

    # -- initial state
    def initial(self, assignments: Assignments, p: Sequence[float]) -> np.ndarray:
        x0 = np.zeros(len(self.state))
        numbers = {S.value(n): sp.Float(v) for n, v in zip(self.parameter_names, p) if math.isfinite(v)}
        scope = self._scope("--init", {n: S.value(n) for n in self.parameter_names}, "numbers and parameters")
        given = set()
        for name, text in self._unique("--init", assignments):
            entry = self._state_name("--init", name)
            expr = self._expression("--init", name, text, scope)
            if entry is None or expr is None:
                continue
            given.add(entry)
            expr = expr.xreplace(numbers)
            if not expr.free_symbols:  # else a parameter without value, reported already
                x0[self.state.index(entry)] = self._number(f"--init {entry}", expr)
        if not self.problems and len(numbers) == len(self.parameter_names):
            self.problems += constrained(self.system, x0, self.state, numbers, given)
        return x0

    # -- free functions and inputs
    def functions(self, assignments: Assignments) -> dict[sp.Symbol, sp.Expr]:
        free = [f.name for f in self.system.free_functions]
        given = [f.name for f in self.system.functions if f.value is not None]
        values = {**{n: S.value(n) for n in self.parameter_names}, "t": S.T}
        scope = self._scope("--function", values, "t and parameters")
        out: dict[sp.Symbol, sp.Expr] = {}
        seen = set()
        for name, text in self._unique("--function", assignments):
            if name in given:
                self._refuse(f"--function {name}: '{name}' has a value in the system file, "
                                     "already substituted in the equations")
                continue
            if not self._known("--function", name, free, "a free function of time"):
                continue
            expr = self._expression("--function", name, text, scope)
            if expr is not None:
                seen.add(name)
                out.update({S.rate(name, o): sp.diff(expr, S.T, o) for o in range(MAX_FUNCTION_ORDER + 1)})
        missing = [n for n in free if n not in seen and not self._mentioned(assignments, n)]
        if missing:
            self._missing("free function", missing, "--function", "expressions in t and parameters")
        return out

    def inputs(self, assignments: Assignments) -> dict[str, sp.Expr]:
        names = [i.name for i in self.system.inputs]
        values = {**{n: S.value(n) for n in self.parameter_names}, "t": S.T,
                  **{c.name: S.value(c.name) for c in self.system.coordinates}}
        rates = {(n, 1): S.rate(n) for n in self.derivation.independent}
        scope = self._scope("--input", values, "t, parameters and the state", rates)
        out = {}
        for name, text in self._unique("--input", assignments):
            if self._known("--input", name, names, "an input"):
                expr = self._expression("--input", name, text, scope)
                if expr is not None:
                    out[name] = expr
        missing = [n for n in names if n not in out and not self._mentioned(assignments, n)]
        if missing:
            self._missing("input", missing, "--input", "expressions in t, parameters and the state")
        return out

    def r_entries(self, r_names: tuple[str, ...], inputs: dict, functions: dict) -> tuple[sp.Expr, ...]:
        by_name = {**inputs, **{s.name: e for s, e in functions.items()}}
        return tuple(by_name.get(n, sp.S.Zero) for n in r_names)

    # -- helpers
    def _scope(self, option: str, values: Mapping[str, sp.Expr], allowed: str, rates=None) -> Scope:
        declared = frozenset(self._declared_names())
        refusals = {n: f"'{n}' is {self._kind(n)}; {option} values may use {allowed}"
                    for n in declared if n not in values}
        if "t" not in values:
            refusals["t"] = f"'t' is time; {option} values may use {allowed}"
        note = f"{option} values may use {allowed}"
        return Scope(values=dict(values), rates=rates or {}, refusals=refusals, declared=declared, rate_note=note)

    def _declared_names(self) -> list[str]:
        s = self.system
        return [d.name for group in (s.parameters, s.functions, s.inputs, s.coordinates, s.quasi_coordinates)
                for d in group]

    def _kind(self, name: str) -> str:
        from gacli import model

        kinds = {model.Parameter: "a parameter", model.Function: "a function", model.Input: "an input",
                 model.Coordinate: "a coordinate", model.QuasiCoordinate: "a quasi-coordinate"}
        return kinds.get(type(self.system.declared(name)), "declared")

    def _expression(self, option: str, name: str, text: str, scope: Scope) -> sp.Expr | None:
        try:
            return build(parse(text), scope)
        except (ParseError, BuildError) as exc:
            hint = f" ({exc.hint})" if getattr(exc, "hint", "") else ""
            self.problems.append(f"{option} {name}={text}: {exc.message}{hint} (column {exc.pos + 1})")
            return None

    def _unique(self, option: str, assignments: Assignments) -> list[tuple[str, str]]:
        seen: set[str] = set()
        out = []
        for name, text in assignments:
            if name in seen:
                self._refuse(f"{option}: '{name}' is given twice")
                continue
            seen.add(name)
            out.append((name, text))
        return out

    @staticmethod
    def _mentioned(assignments: Assignments, name: str) -> bool:
        """Given, but with an error already reported: not 'missing' as well."""
        return any(n == name for n, _ in assignments)

    def _known(self, option: str, name: str, allowed: Sequence[str], what: str) -> bool:
        if name in allowed:
            return True
        close = [a for a in allowed if a.lower() == name.lower()]
        close = close or difflib.get_close_matches(name, list(allowed), n=1, cutoff=0.6)
        hint = f" (did you mean '{close[0]}'?)" if close else ""
        listing = f"; the system has: {', '.join(allowed)}" if allowed and not close else ""
        self._refuse(f"{option} {name}: '{name}' is not {what} of {self.system.name}{hint}{listing}")
        return False

    def _missing(self, kind: str, names: list[str], option: str, what: str) -> None:
        several = len(names) > 1
        listed = ", ".join(f"'{n}'" for n in names)
        example = ",".join(f"{n}=..." for n in names)
        verb = "have no values: give them" if several else "has no value: give it"
        self.problems.append(f"{kind}{'s' if several else ''} {listed} {verb} with {option} \"{example}\" ({what})")

    def _state_name(self, option: str, text: str) -> str | None:
        """The STATE entry that ``text`` names (``dot( x )`` → ``dot(x)``), or None and a problem."""
        try:
            node = parse(text)
        except ParseError:
            node = None
        name = S.rate_name(node.name, node.order) if isinstance(node, Rate) else getattr(node, "id", None)
        if not isinstance(node, (Name, Rate)):
            self._refuse(f"{option} '{text}': expected a state name such as x or dot(x)")
            return None
        if name in self.state:
            return name
        self._refuse(f"{option} {name}: '{name}' is not in the state{self._why_not(node)}; "
                             f"the state is {', '.join(self.state)}")
        return None

    def _why_not(self, node) -> str:
        base = node.name if isinstance(node, Rate) else node.id
        if isinstance(node, Rate) and node.order == 1 and base in self.system.rate_names:
            return (": its rate follows from the constraints "
                    f"(the independent rates are {', '.join(self.derivation.independent)})")
        if isinstance(node, Name) and self._kind(base) == "a quasi-coordinate":
            return ": a quasi-coordinate has a rate but no value"
        written = S.rate_name(base, getattr(node, "order", 0))
        close = closest_state(written, self.state)
        return f" (did you mean '{close}'?)" if close else ""
