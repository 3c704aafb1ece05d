"""The run: the generated module imported, the problem compiled, solve_ivp, the measurements."""

from __future__ import annotations

import dataclasses
import importlib.util
import tempfile
import uuid
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.mechanics.equations import Derivation
from gacli.mechanics.rates import solve_rates
from gacli.mechanics.read_off import dependent_rates
from gacli.numeric.compiled import scalar, vectorized
from gacli.simulate.energy import conservation_problems, kinetic_energy, path_rates, potential_energy
from gacli.simulate.results import ConstraintResidual, Simulation, short
from gacli.simulate.spec import OptionError, SimulationError, SimulationSpec, require
from gacli.simulate.values import OptionValues

_PROGRESS_STEPS = 200        # progress reports per run, at most


# -- the run --------------------------------------------------------------------

def simulate(derivation: Derivation, spec: SimulationSpec,
             progress: Callable[[float], None] | None = None, module: ModuleType | None = None) -> Simulation:
    """Integrate the generated equations from t = 0 to ``spec.t_end``.

    ``progress(t)`` is called as the integration advances (at most about 200
    times, t increasing). ``module``: the generated module, when the caller
    already imported it (:func:`load_generated`). Every problem with the options is collected first
    and raised together, before any integration.

    Raises:
        MissingExtraError: SciPy is not installed.
        SimulationError: a value is missing or wrong, or the integration failed.
    """
    solve_ivp = require("scipy.integrate").solve_ivp
    spec = _within_floor(spec)
    module = load_generated(derivation) if module is None else module  # gacli sweep imports it once
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
        integrals={name: problem._vectorized(expr)(t, states) for name, expr in integrals_of(derivation)},
    )


_FOUND: dict[int, tuple[Derivation, tuple]] = {}


def integrals_of(derivation: Derivation) -> tuple[tuple[str, sp.Expr], ...]:
    """The first integrals besides the energy (gacli.steady.integrals), once per derivation (a sweep
    simulates one derivation many times); none searched for a system too large to print, whose
    closed forms were not formed (gacli.pipeline's STEPS)."""
    from gacli.algebra.readable import displayable
    from gacli.steady.integrals import integrals

    held = _FOUND.get(id(derivation))
    if held is not None and held[0] is derivation:
        return held[1]
    if not derivation.closed or not displayable(derivation) or derivation.system.free_functions:
        found = ()
    else:
        found = tuple((i.name, i.expression) for i in integrals(derivation).found if i.name != "energy T + V")
    if len(_FOUND) > 16:
        _FOUND.clear()
    _FOUND[id(derivation)] = (derivation, found)
    return found


def load_generated(derivation: Derivation) -> ModuleType:
    """Import the generated Python module from a temporary directory, outside sys.modules."""
    from gacli.emit import emit

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


# SciPy's solvers take no rtol below 100 machine epsilons: they raise it, and the run says the one used.
RTOL_FLOOR = 100 * float(np.finfo(float).eps)


class ToleranceNote(UserWarning):
    """A tolerance raised to what the integrator can use (a note on the command line)."""


def _within_floor(spec: SimulationSpec) -> SimulationSpec:
    if not 0 < spec.rtol < RTOL_FLOOR:  # a tolerance that is no positive number is the options' error
        return spec
    warnings.warn(f"--rtol {short(spec.rtol)} is below what double precision resolves; the integration uses "
                  f"{short(RTOL_FLOOR)} (100 machine epsilons, SciPy's floor)", ToleranceNote, stacklevel=2)
    return dataclasses.replace(spec, rtol=RTOL_FLOOR)


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
        where = ", ".join(f"{n} = {short(v)}" for n, v in zip(problem.state, exc.x))
        raise SimulationError([f"{message}; the state there: {where}"]) from None
    if solution.status < 0:
        reached = solution.t[-1] if len(solution.t) else 0.0
        message = f"the integration stopped at t = {reached:.6g}: {solution.message}"
        if len(solution.t) and reached > 0 and (why := _singular(problem, reached, solution.y[:, -1])):
            where = ", ".join(f"{n} = {short(v)}" for n, v in zip(problem.state, solution.y[:, -1]))
            message += f" ({why}); the state there: {where}"
        raise SimulationError([message])
    if progress is not None:
        progress(spec.t_end)
    return solution


# M's condition number past which an integrator that gave up is said to have met a singular
# configuration: its steps shrink as the accelerations grow without bound there.
SINGULAR_CONDITION = 1e8


def _singular(problem: "_Problem", t: float, x: np.ndarray) -> str:
    """Why the integrator gave up, when the configuration it reached is singular; "" otherwise.

    Near a bicycle lying flat its rolling constraints lose rank: M, solved for the dependent
    rates numerically, grows ill-conditioned without ceasing to be positive definite."""
    try:
        M = np.asarray(problem.module.mass_matrix(t, x, problem.p, problem.r), dtype=float)
        condition = np.linalg.cond(M)
    except (ArithmeticError, ValueError, np.linalg.LinAlgError):
        return "the motion has reached a configuration where the model is singular"
    if not np.isfinite(condition) or condition > SINGULAR_CONDITION:
        return (f"the motion has reached a configuration where the model is singular: "
                f"M's condition number there is {short(condition)}")
    return ""


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
        values = OptionValues(derivation, tuple(module.STATE))
        values.check_numbers(spec)
        values.check_plot_names(spec)
        p = values.parameters(spec.parameters)
        x0 = values.initial(spec.initial, p)
        functions = values.functions(spec.functions)
        inputs = values.inputs(spec.inputs)
        r_exprs = values.r_entries(tuple(module.INPUTS), inputs, functions)
        if values.problems:
            raise (OptionError if values.usage else SimulationError)(values.problems)
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
        """T from generated code's M and V from the file, for a system that conserves E."""
        mass_matrix = lambda ti, x: self.module.mass_matrix(ti, x, self.p, self.r)  # noqa: E731
        kinetic = kinetic_energy(mass_matrix, t, states, self.derivation.k)
        return kinetic, self._vectorized(potential_energy(self.derivation.system))(t, states)

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
        """A ṙ + a₀ with coordinate rates as fresh symbols, an independent quasi-coordinate's rate from
        the state and a dependent one's from its differential (eq. 14.2)."""
        system, independent = self.derivation.system, self.derivation.independent
        fd = [sp.Dummy(f"fd_{c.name}") for c in system.coordinates]
        coordinate_rates = {c.name: d for c, d in zip(system.coordinates, fd)}
        rates = dependent_rates(system, independent, coordinate_rates)
        if rates is None:  # a dependent quasi-coordinate without a differential: its rate is β u + β₀
            rates = tuple((q.name, (self.derivation.rates or solve_rates(system)).rate(q.name))
                          for q in system.quasi_coordinates)
        replace = {S.rate(n): e for n, e in [*coordinate_rates.items(), *rates]}
        expr = sum((c * S.rate(n) for n, c in form.coefficients), form.dt)
        return as_expr(expr).xreplace(replace).xreplace(self.functions), fd


def _arguments(state: Sequence[str], parameters: Sequence[str]) -> list[sp.Symbol]:
    return [S.T, *(S.value(n) for n in state), *(S.value(n) for n in parameters)]
