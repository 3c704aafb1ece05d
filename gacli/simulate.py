"""Integrate the generated equations of motion and measure what a user checks first.

The generated Python module (``gacli.api.emit(derivation, "python")``, the
very code users vendor) is written to a temporary directory, imported under
a unique name and integrated with SciPy's ``solve_ivp``. Values come from the
command line (``SimulationSpec``) or from the system file:

.. code:: text

    --set       parameters     expressions in numbers and parameters; a file
                               value that names other parameters is recomputed
    --init      state          by STATE name; unspecified entries start at 0
    --function  free functions expressions in t and parameters; the rates the
                               equations need (dot(Omega), ...) are their
                               symbolic derivatives
    --input     inputs         expressions in t, parameters and the state

Every expression goes through gacli's own grammar (:mod:`gacli.expr`), never
``eval``. Along the computed path the report measures (docs/simulate.md):

* the drift of the energy E = Σ ½ m v·v + ½ ω·Iω + V when the system
  conserves it (:func:`conservation_problems` says why not otherwise);
* for each Pfaffian constraint, its residual A(q, t) ṙ + a₀ with the
  coordinate rates differentiated from the dense solution and the
  quasi-coordinate rates from β u + β₀ (eq. 14.7);
* for each finite constraint f(q, t) = 0, the drift of f.

Nothing here prints: :mod:`gacli.simulate_console` shows progress and the
summary, :mod:`gacli.simulate_plot` draws.
"""

from __future__ import annotations

import csv
import difflib
import importlib.util
import io
import math
import tempfile
import uuid
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType

import numpy as np
import sympy as sp

from gacli import symbols as S
from gacli.coerce import as_expr
from gacli.equations import Derivation
from gacli.errors import GacliError
from gacli.expr.build import BuildError, Scope, build
from gacli.expr.grammar import Name, ParseError, Rate, parse
from gacli.graph import free_symbols
from gacli.numeric.compiled import scalar, vectorized
from gacli.suggest import closest_state

METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")
DEFAULT_METHOD = "DOP853"
DEFAULT_RTOL = 1e-9
DEFAULT_ATOL = 1e-12
DEFAULT_T_END = 10.0
DEFAULT_POINTS = 1001
INSTALL = "pip install 'gacli[sim]'"

_PROGRESS_STEPS = 200        # progress reports per run, at most
_FD_FRACTION = 0.01          # finite-difference step, as a fraction of the solver's step
_MAX_FUNCTION_ORDER = 8      # rates of a free function that generated code may ask for

Assignments = tuple[tuple[str, str], ...]


class SimulationError(GacliError, ValueError):
    """Options that cannot be simulated, or an integration that failed; holds every problem."""

    def __init__(self, problems: Sequence[str]) -> None:
        self.problems = tuple(problems)
        super().__init__(str(self))

    def __str__(self) -> str:
        if len(self.problems) == 1:
            return self.problems[0]
        lines = [f"{len(self.problems)} problems with the simulation:"]
        return "\n".join(lines + [f"  {p}" for p in self.problems])


class MissingExtraError(GacliError, ImportError):
    """An optional dependency of ``gacli simulate`` is not installed."""


def require(module: str, purpose: str = "simulation") -> ModuleType:
    """Import ``module`` or say what to install (``scipy.integrate``, ``matplotlib``)."""
    try:
        return importlib.import_module(module)
    except ImportError:
        top = module.split(".")[0]
        raise MissingExtraError(f"{purpose} needs {top}, which is not installed: {INSTALL}") from None


# -- options --------------------------------------------------------------------

@dataclass(frozen=True)
class SimulationSpec:
    """What to simulate, as given on the command line (values still unparsed text)."""

    parameters: Assignments = ()
    initial: Assignments = ()
    inputs: Assignments = ()
    functions: Assignments = ()
    t_end: float = DEFAULT_T_END
    method: str = DEFAULT_METHOD
    rtol: float = DEFAULT_RTOL
    atol: float = DEFAULT_ATOL
    points: int = DEFAULT_POINTS
    show: tuple[str, ...] = ()
    phase: tuple[str, ...] = ()


def spec_from_options(*, set: Sequence[str] = (), init: Sequence[str] = (), input: Sequence[str] = (),
                      function: Sequence[str] = (), show: str | None = None, phase: str | None = None,
                      **numbers) -> SimulationSpec:
    """A spec from the raw option strings (each option may be repeated).

    >>> spec_from_options(set=["M=1,a=f(1,2)"], t_end=2.0).parameters
    (('M', '1'), ('a', 'f(1,2)'))
    """
    def joined(texts, option):
        return tuple(pair for text in texts for pair in parse_assignments(text, option))

    return SimulationSpec(
        parameters=joined(set, "--set"), initial=joined(init, "--init"),
        inputs=joined(input, "--input"), functions=joined(function, "--function"),
        show=tuple(split_top_level(show or "", "--show")), phase=tuple(split_top_level(phase or "", "--phase")),
        **numbers,
    )


def split_top_level(text: str, option: str = "") -> list[str]:
    """Split on the commas outside parentheses; empty pieces are dropped.

    >>> split_top_level("a=1, b=atan2(1, 2)")
    ['a=1', 'b=atan2(1, 2)']
    """
    pieces, depth, start = [], 0, 0
    for i, char in enumerate(text):
        depth += {"(": 1, ")": -1}.get(char, 0)
        if depth < 0:
            raise SimulationError([f"{option} '{text}': unmatched ')' at column {i + 1}".lstrip()])
        if char == "," and depth == 0:
            pieces.append(text[start:i])
            start = i + 1
    if depth:
        raise SimulationError([f"{option} '{text}': unclosed '('".lstrip()])
    pieces.append(text[start:])
    return [p.strip() for p in pieces if p.strip()]


def parse_assignments(text: str, option: str = "") -> list[tuple[str, str]]:
    """``"a=1,b=f(1,2)"`` → ``[("a", "1"), ("b", "f(1,2)")]``; commas inside parentheses stay.

    >>> parse_assignments("x=1, dot(x)=-2*a")
    [('x', '1'), ('dot(x)', '-2*a')]
    """
    out = []
    for piece in split_top_level(text, option):
        name, equals, value = piece.partition("=")
        if not equals or not name.strip() or not value.strip():
            raise SimulationError([f"{option} '{piece}': expected name=value".lstrip()])
        out.append((name.strip(), value.strip()))
    return out


# -- the result -----------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class ConstraintResidual:
    """A constraint along the path: A ṙ + a₀ (Pfaffian) or f(q, t) (finite), per sample."""

    label: str            # "constraints[0]"
    text: str             # as written in the system file
    finite: bool
    values: np.ndarray

    @property
    def initial(self) -> float:
        return float(self.values[0])

    @property
    def max_abs(self) -> float:
        """max |A ṙ + a₀| for a Pfaffian constraint, max |f − f(t₀)| for a finite one."""
        reference = self.values[0] if self.finite else 0.0
        return float(np.max(np.abs(self.values - reference)))


@dataclass(frozen=True, eq=False)
class Simulation:
    """A computed trajectory: ``states[i, j]`` is STATE[j] at ``t[i]``."""

    system: str
    t: np.ndarray
    states: np.ndarray
    state_names: tuple[str, ...]
    coordinates: tuple[str, ...]
    parameters: dict[str, float]
    method: str
    rtol: float
    atol: float
    evaluations: int
    energy: np.ndarray | None = None
    kinetic_energy: np.ndarray | None = None
    not_conservative: tuple[str, ...] = ()
    residuals: dict[str, ConstraintResidual] = field(default_factory=dict)

    def column(self, name: str) -> np.ndarray:
        return self.states[:, self.state_names.index(name)]

    @property
    def energy_drift(self) -> float | None:
        """max |E(t) − E(t₀)| along the path, or None when E is not conserved."""
        if self.energy is None:
            return None
        return float(np.max(np.abs(self.energy - self.energy[0])))

    @property
    def energy_relative_drift(self) -> float | None:
        """The drift over max(|E(t₀)|, max T): E has an arbitrary zero, T does not."""
        if self.energy is None:
            return None
        scale = max(abs(float(self.energy[0])), float(np.max(self.kinetic_energy)))
        return self.energy_drift / scale if scale > 0 else self.energy_drift


# -- the run --------------------------------------------------------------------

def simulate(derivation: Derivation, spec: SimulationSpec,
             progress: Callable[[float], None] | None = None) -> Simulation:
    """Integrate the generated equations from t = 0 to ``spec.t_end``.

    ``progress(t)`` is called as the integration advances (at most about 200
    times, t increasing). Every problem with the options is collected first
    and raised together, before any integration.

    Raises:
        MissingExtraError: SciPy is not installed.
        SimulationError: a value is missing or wrong, or the integration failed.
    """
    solve_ivp = require("scipy.integrate").solve_ivp
    module = load_generated(derivation)
    problem = _Problem.make(derivation, module, spec)
    solution = _integrate(solve_ivp, problem, spec, progress)
    t = np.linspace(0.0, spec.t_end, spec.points)
    states = solution.sol(t).T
    conservative = conservation_problems(derivation)
    energy = kinetic = None
    if not conservative:
        kinetic, potential = problem.energies(t, states)
        energy = kinetic + potential
    return Simulation(
        system=derivation.system.name, t=t, states=states, state_names=problem.state,
        coordinates=problem.coordinates, parameters=dict(zip(problem.parameter_names, problem.p)),
        method=spec.method, rtol=spec.rtol, atol=spec.atol, evaluations=int(solution.nfev),
        energy=energy, kinetic_energy=kinetic, not_conservative=tuple(conservative),
        residuals=problem.residuals(t, states, solution.sol),
    )


def load_generated(derivation: Derivation) -> ModuleType:
    """Import the generated Python module from a temporary directory, outside sys.modules."""
    from gacli.api import emit

    files = emit(derivation, "python")
    with tempfile.TemporaryDirectory(prefix="gacli-sim-") as folder:
        (filename, text), = files.items()
        path = Path(folder) / filename
        path.write_text(text, encoding="utf-8")
        name = f"_gacli_simulate_{derivation.system.name}_{uuid.uuid4().hex}"
        spec = importlib.util.spec_from_file_location(name, path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
    return module


class _EvaluationFailed(Exception):
    def __init__(self, t: float, x: np.ndarray, error: Exception) -> None:
        super().__init__(str(error))
        self.t, self.x, self.error = t, np.array(x, dtype=float), error


def _integrate(solve_ivp, problem: "_Problem", spec: SimulationSpec, progress):
    report = _throttled(progress, spec.t_end)

    def fun(t, x):
        report(t)
        try:
            return problem.module.rhs(t, x, problem.p, problem.r)
        except (ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            raise _EvaluationFailed(t, x, exc) from exc

    try:
        solution = solve_ivp(fun, (0.0, spec.t_end), problem.x0, method=spec.method,
                             rtol=spec.rtol, atol=spec.atol, dense_output=True)
    except _EvaluationFailed as exc:
        message = f"the equations cannot be evaluated at t = {exc.t:.6g}: {exc.error}"
        if isinstance(exc.error, np.linalg.LinAlgError) and exc.t > 0:
            # The usual cause in a model that was fine at t = 0: it has moved to a configuration
            # where its constraints lose rank (a wheel lying flat), not a failure of the integrator.
            message += " (the motion has reached a configuration where the model is singular)"
        where = ", ".join(f"{n} = {_g(v)}" for n, v in zip(problem.state, exc.x))
        raise SimulationError([f"{message}; the state there: {where}"]) from None
    if solution.status < 0:
        reached = solution.t[-1] if len(solution.t) else 0.0
        raise SimulationError([f"the integration stopped at t = {reached:.6g}: {solution.message}"])
    if progress is not None:
        progress(spec.t_end)
    return solution


def _throttled(progress, t_end: float) -> Callable[[float], None]:
    if progress is None:
        return lambda t: None
    step, reached = t_end / _PROGRESS_STEPS, [0.0]

    def report(t: float) -> None:
        if t >= reached[0] + step:
            reached[0] = t
            progress(min(t, t_end))

    return report


# -- values from the options ------------------------------------------------------

@dataclass(frozen=True)
class _Problem:
    """Everything the run needs, numbers resolved and functions compiled."""

    derivation: Derivation
    module: ModuleType
    state: tuple[str, ...]
    parameter_names: tuple[str, ...]
    p: tuple[float, ...]
    x0: np.ndarray
    r: object                                  # () or a callable r(t, x)
    functions: dict[sp.Symbol, sp.Expr]        # each free function's rates, as expressions in t

    @property
    def coordinates(self) -> tuple[str, ...]:
        return tuple(c.name for c in self.derivation.system.coordinates)

    @property
    def arguments(self) -> list[sp.Symbol]:
        """(t, x..., p...): the arguments of every compiled function."""
        return _arguments(self.state, self.parameter_names)

    @staticmethod
    def make(derivation: Derivation, module: ModuleType, spec: SimulationSpec) -> "_Problem":
        values = _Values(derivation, tuple(module.STATE))
        values.check_numbers(spec)
        values.check_plot_names(spec)
        p = values.parameters(spec.parameters)
        x0 = values.initial(spec.initial, p)
        functions = values.functions(spec.functions)
        inputs = values.inputs(spec.inputs)
        r_exprs = values.r_entries(tuple(module.INPUTS), inputs, functions)
        if values.problems:
            raise SimulationError(values.problems)
        r = ()
        if r_exprs:
            arguments = _arguments(values.state, values.parameter_names)
            compiled = scalar(arguments, r_exprs)
            r = lambda t, x: compiled(t, *x, *p)  # noqa: E731
        return _Problem(derivation, module, values.state, values.parameter_names, p, x0, r, functions)

    def _vectorized(self, expr: sp.Expr, extra=()) -> Callable:
        f = vectorized(self.arguments + list(extra), expr)
        return lambda t, states, *more: np.array(np.broadcast_to(
            np.asarray(f(t, *states.T, *self.p, *more), dtype=float), t.shape))

    def energies(self, t: np.ndarray, states: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        kinetic, potential = energy_expressions(self.derivation)
        return self._vectorized(kinetic)(t, states), self._vectorized(potential)(t, states)

    def residuals(self, t: np.ndarray, states: np.ndarray, dense) -> dict[str, ConstraintResidual]:
        system = self.derivation.system
        n = len(system.coordinates)
        coordinate_rates = None
        out = {}
        for i, constraint in enumerate(system.constraints):
            label, text = f"constraints[{i}]", getattr(constraint, "text", "")
            if constraint.relation is not None:
                f = self._vectorized(constraint.relation.xreplace(self.functions))
                out[label] = ConstraintResidual(label, text, True, f(t, states))
                continue
            if coordinate_rates is None:
                coordinate_rates = path_rates(dense, t, n)
            expr, fd = self._rate_form(constraint.form)
            values = self._vectorized(expr, fd)(t, states, *coordinate_rates.T)
            out[label] = ConstraintResidual(label, text, False, values)
        return out

    def _rate_form(self, form) -> tuple[sp.Expr, list[sp.Symbol]]:
        """A ṙ + a₀ with coordinate rates as fresh symbols and quasi rates from β u + β₀."""
        system, rates = self.derivation.system, self.derivation.rates
        fd = [sp.Dummy(f"fd_{c.name}") for c in system.coordinates]
        replace = {S.rate(c.name): d for c, d in zip(system.coordinates, fd)}
        replace.update({S.rate(q.name): rates.rate(q.name) for q in system.quasi_coordinates})
        expr = sum((c * S.rate(n) for n, c in form.coefficients), form.dt)
        return as_expr(expr).xreplace(replace).xreplace(self.functions), fd


def _arguments(state: Sequence[str], parameters: Sequence[str]) -> list[sp.Symbol]:
    return [S.T, *(S.value(n) for n in state), *(S.value(n) for n in parameters)]


class _Values:
    """Resolves the options to numbers and expressions, collecting every problem."""

    def __init__(self, derivation: Derivation, state: tuple[str, ...]) -> None:
        self.derivation = derivation
        self.system = derivation.system
        self.state = state
        self.parameter_names = tuple(p.name for p in self.system.parameters)
        self.problems: list[str] = []

    # -- checks of the plain options
    def check_numbers(self, spec: SimulationSpec) -> None:
        if spec.method not in METHODS:
            self.problems.append(f"--method: '{spec.method}' is not a method of solve_ivp "
                                 f"(one of: {', '.join(METHODS)})")
        for option, value in (("--t-end", spec.t_end), ("--rtol", spec.rtol), ("--atol", spec.atol)):
            if not (math.isfinite(value) and value > 0):
                self.problems.append(f"{option}: expected a positive number, found {value!r}")
        if spec.points < 2:
            self.problems.append(f"--points: expected at least 2, found {spec.points}")

    def check_plot_names(self, spec: SimulationSpec) -> None:
        for option, names in (("--show", spec.show), ("--phase", spec.phase)):
            for name in names:
                self._state_name(option, name)
        if spec.phase and len(spec.phase) != 2:
            self.problems.append(f"--phase: expected two state names (x,y), found {len(spec.phase)}")

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
        for name, text in self._unique("--init", assignments):
            entry = self._state_name("--init", name)
            expr = self._expression("--init", name, text, scope)
            if entry is None or expr is None:
                continue
            expr = expr.xreplace(numbers)
            if not expr.free_symbols:  # else a parameter without value, reported already
                x0[self.state.index(entry)] = self._number(f"--init {entry}", expr)
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
                self.problems.append(f"--function {name}: '{name}' has a value in the system file, "
                                     "already substituted in the equations")
                continue
            if not self._known("--function", name, free, "a free function of time"):
                continue
            expr = self._expression("--function", name, text, scope)
            if expr is not None:
                seen.add(name)
                out.update({S.rate(name, o): sp.diff(expr, S.T, o) for o in range(_MAX_FUNCTION_ORDER + 1)})
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
                self.problems.append(f"{option}: '{name}' is given twice")
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
        self.problems.append(f"{option} {name}: '{name}' is not {what} of {self.system.name}{hint}{listing}")
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
            self.problems.append(f"{option} '{text}': expected a state name such as x or dot(x)")
            return None
        if name in self.state:
            return name
        self.problems.append(f"{option} {name}: '{name}' is not in the state{self._why_not(node)}; "
                             f"the state is {', '.join(self.state)}")
        return None

    def _why_not(self, node) -> str:
        base = node.name if isinstance(node, Rate) else node.id
        if isinstance(node, Rate) and node.order == 1 and base in self.derivation.rates.names:
            return (": its rate follows from the constraints "
                    f"(the independent rates are {', '.join(self.derivation.independent)})")
        if isinstance(node, Name) and self._kind(base) == "a quasi-coordinate":
            return ": a quasi-coordinate has a rate but no value"
        written = S.rate_name(base, getattr(node, "order", 0))
        close = closest_state(written, self.state)
        return f" (did you mean '{close}'?)" if close else ""


# -- energy and its conservation ----------------------------------------------------

def conservation_problems(derivation: Derivation) -> list[str]:
    """Why E = T + V need not be constant along a motion; empty when it must be.

    E is conserved when nothing external works on the system and nothing
    depends on time: no inputs, no free functions, no ``work`` form and no
    torques; forces only constant ones (given a potential −F·r); and no t in
    the positions, the rotations, the constraints or the potential, with
    every velocity homogeneous in u (no β₀ terms, v = V u and ω = W u).
    """
    system = derivation.system
    out = []
    if system.inputs:
        out.append("inputs " + ", ".join(i.name for i in system.inputs))
    if system.free_functions:
        out.append("free functions " + ", ".join(f.name for f in system.free_functions))
    if system.work is not None:
        out.append("a work form (write conservative forces as a potential)")
    if system.torques:
        out.append("torques")
    if any(_free(e) - _parameter_symbols(system) for force in system.forces for e in force.vector):
        out.append("forces that are not constant")
    if S.T in _free(system.potential):
        out.append("a potential that depends on t")
    if any(c.form.dt != 0 or S.T in _free(*(e for _, e in c.form.coefficients)) for c in system.constraints):
        out.append("constraints that depend on t")
    if any(_moves_with_time(m) for m in derivation.motions):
        out.append("velocities with terms free of the independent rates (a moving support)")
    return out


def _moves_with_time(motion) -> bool:
    parts = [motion.linear] + ([motion.angular] if motion.angular is not None else [])
    return any(S.T in _free(*m.partials, *m.velocity0) or any(sp.simplify(e) != 0 for e in m.velocity0)
               for m in parts)


def _free(*exprs) -> set[sp.Symbol]:
    return free_symbols([as_expr(e) for e in exprs])


def _parameter_symbols(system) -> set[sp.Symbol]:
    return {S.value(p.name) for p in system.parameters}


def energy_expressions(derivation: Derivation) -> tuple[sp.Expr, sp.Expr]:
    """T = Σ ½ m v·v + ½ ω·Iω with v = V u + v₀, ω = W u + ω₀; and V (constant forces included)."""
    u = sp.Matrix(derivation.speeds)
    kinetic = sp.S.Zero
    for motion in derivation.motions:
        v = motion.linear.partials * u + motion.linear.velocity0
        kinetic += motion.body.mass * v.dot(v) / 2
        if motion.angular is not None:
            w = motion.angular.partials * u + motion.angular.velocity0
            kinetic += (w.T * motion.body.inertia * w)[0, 0] / 2
    potential = derivation.system.potential
    for force in derivation.system.forces:
        potential -= sp.Matrix(force.vector).dot(sp.Matrix(force.point))
    return kinetic, potential


# -- rates along the path -------------------------------------------------------------

def path_rates(dense, t: np.ndarray, n: int) -> np.ndarray:
    """d/dt of the first ``n`` states at ``t``, differentiated from the dense solution.

    Each time is differentiated inside the polynomial of its own solver step
    (``dense.interpolants``) by the five-point central difference with a step
    of 1% of that solver step, so no kink between steps enters the result.
    """
    ts = dense.ts
    segment = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, len(dense.interpolants) - 1)
    out = np.empty((len(t), n))
    for j in np.unique(segment):
        mask = segment == j
        tj, h = t[mask], _FD_FRACTION * abs(ts[j + 1] - ts[j])
        f = dense.interpolants[j]
        d = (f(tj - 2 * h) - 8 * f(tj - h) + 8 * f(tj + h) - f(tj + 2 * h)) / (12 * h)
        out[mask] = np.atleast_2d(d)[:n].T
    return out


# -- output -------------------------------------------------------------------------

def to_csv(sim: Simulation) -> str:
    """A header ``t`` then the STATE names, one row per sample, floats in shortest round-trip form."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(("t",) + sim.state_names)
    for t, row in zip(sim.t, sim.states):
        writer.writerow([repr(float(t))] + [repr(float(v)) for v in row])
    return buffer.getvalue()


def summary_lines(sim: Simulation) -> list[str]:
    """What the run did and what it measured, one fact a line (shown by gacli.simulate_console)."""
    lines = [
        f"{sim.system}: t = 0 to {_g(sim.t[-1])} with {sim.method} (rtol {_g(sim.rtol)}, atol {_g(sim.atol)}), "
        f"{sim.evaluations} evaluations of rhs, {len(sim.t)} samples",
        "parameters: " + (", ".join(f"{n} = {_g(v)}" for n, v in sim.parameters.items()) or "none"),
        "initial state: " + ", ".join(f"{n} = {_g(v)}" for n, v in zip(sim.state_names, sim.states[0])),
        "final state: " + ", ".join(f"{n} = {_g(v)}" for n, v in zip(sim.state_names, sim.states[-1])),
    ]
    if sim.energy is None:
        lines.append("energy: not reported, E need not be conserved (" + "; ".join(sim.not_conservative) + ")")
    else:
        lines.append(f"energy: E(0) = {_g(sim.energy[0])}, max |E - E(0)| = {_g(sim.energy_drift)} "
                     f"(relative {_g(sim.energy_relative_drift)})")
    for r in sim.residuals.values():
        if r.finite:
            lines.append(f"{r.label} {r.text}: f(0) = {_g(r.initial)}, max |f - f(0)| = {_g(r.max_abs)}")
        else:
            lines.append(f"{r.label} {r.text}: max |residual| = {_g(r.max_abs)}")
    return lines


def _g(value: float) -> str:
    return f"{float(value):.6g}"
