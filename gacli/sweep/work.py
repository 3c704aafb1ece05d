"""One point of a sweep: ``simulate`` or ``linearize`` at the swept values, as a row of numbers.

A :class:`Job` is what every worker receives once: the derivation (derived
once, by the command) and the :class:`Task`. A worker keeps what it builds
from a job (the generated module a simulation imports) under the job's key,
so a process or a Dask worker compiles once however many chunks it runs.

A point that fails (the integration stops, the operating point is singular)
is a row like any other, with NaN for its numbers and the reason in
``error``: one bad corner of a grid does not lose the others.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from types import ModuleType

from gacli.algebra import symbols as S
from gacli.errors import GacliError
from gacli.mechanics.equations import Derivation

MODES = ("linearize", "simulate")
STABLE_MARGIN = 1e-9    # "stable": every real part below -1e-9 times max(1, the largest |eigenvalue|)

Value = float | bool | str


@dataclass(frozen=True)
class Task:
    """What to run at each point; numbers for linearize, the options' text for simulate."""

    mode: str
    names: tuple[str, ...]                 # the swept names, in the table's order
    kinds: tuple[str, ...]                 # "parameter", "state" or "input", per name
    state: tuple[str, ...]                 # the generated code's STATE
    parameters: tuple[tuple[str, float], ...] = ()   # linearize: --set, evaluated
    at: tuple[tuple[str, float], ...] = ()           # linearize: --at, evaluated
    states: tuple[str, ...] = ()           # linearize: the block of A whose eigenvalues count
    spec: object = None                    # simulate: the SimulationSpec of the fixed options


@dataclass(frozen=True)
class Job:
    """A sweep's derivation and task, sent to each worker once; ``key`` names the sweep."""

    key: str
    derivation: Derivation
    task: Task


def columns(task: Task) -> tuple[str, ...]:
    """The table's header: the swept names, the results, then ``error``."""
    if task.mode == "linearize":
        count = len(task.states or task.state)
        eigen = [f"eig{i}_{part}" for i in range(1, count + 1) for part in ("re", "im")]
        return (*task.names, "max_real", "stable", *eigen, "error")
    return (*task.names, *(f"final_{n}" for n in task.state), "energy_drift", "max_residual", "error")


def run_chunk(job: Job, chunk: Sequence[tuple[int, tuple[float, ...]]]) -> list[tuple[int, tuple[Value, ...]]]:
    """The rows of ``(index, point)`` pairs, each row's failure caught into its ``error``."""
    return [(index, run_point(job, point, strict=False)) for index, point in chunk]


def run_point(job: Job, point: Sequence[float], strict: bool = True) -> tuple[Value, ...]:
    """The results at one point (without the swept values); ``strict``: a failure raises."""
    task = job.task
    try:
        if task.mode == "linearize":
            return _linearize(job, point)
        return _simulate(job, point)
    except GacliError as exc:
        if strict:
            raise
        size = len(columns(task)) - len(task.names) - 1
        return (*([math.nan] * size), " ".join(str(exc).split()))


def _linearize(job: Job, point: Sequence[float]) -> tuple[Value, ...]:
    from gacli.linearize import linearize

    task = job.task
    given = {**dict(task.parameters), **{n: v for n, v, k in zip(task.names, point, task.kinds) if k == "parameter"}}
    at = {**dict(task.at), **{n: v for n, v, k in zip(task.names, point, task.kinds) if k != "parameter"}}
    result = linearize(job.derivation, at, resolved_parameters(job.derivation.system, given))
    eigenvalues = result.eigenvalues(list(task.states) or None)
    largest = float(max(eigenvalues.real))
    pairs = [float(v) for value in eigenvalues for v in (value.real, value.imag)]
    # A real part within rounding of zero (a conservative system's) is not a decay: only a clear one counts.
    margin = STABLE_MARGIN * max(1.0, float(max(abs(eigenvalues))))
    return (largest, bool(largest < -margin), *pairs, "")


def resolved_parameters(system, given: Mapping[str, float]) -> dict[str, float]:
    """Every parameter's value: ``given`` ones as given, the file's others in its order.

    A file value written in other parameters is computed again from theirs,
    as ``gacli simulate --set`` does: sweeping a wheel base moves what the
    file computes from it.
    """
    from gacli.numeric.guarded import UndefinedValue, evaluate

    values: dict = {}
    out: dict[str, float] = {}
    for parameter in system.parameters:
        if parameter.name in given:
            number = float(given[parameter.name])
        elif parameter.value is None:
            continue
        else:
            try:
                number = float(evaluate(parameter.value, values)[0].real)
            except (UndefinedValue, ArithmeticError, ValueError, TypeError):
                continue
        values[S.value(parameter.name)] = number
        out[parameter.name] = number
    return out


def _simulate(job: Job, point: Sequence[float]) -> tuple[Value, ...]:
    from gacli.simulate import simulate

    task, spec = job.task, job.task.spec
    swept = set(task.names)
    parameters = [(n, v) for n, v in spec.parameters if n not in swept]
    initial = [(n, v) for n, v in spec.initial if n not in swept]
    for name, value, kind in zip(task.names, point, task.kinds):
        (parameters if kind == "parameter" else initial).append((name, repr(float(value))))
    run = replace(spec, parameters=tuple(parameters), initial=tuple(initial))
    result = simulate(job.derivation, run, module=_module(job))
    drift = result.energy_relative_drift
    residual = max((r.max_abs for r in result.residuals.values()), default=math.nan)
    return (*(float(v) for v in result.states[-1]), math.nan if drift is None else float(drift), float(residual), "")


_MODULES: dict[str, ModuleType] = {}
_LOCK = threading.Lock()
_KEPT = 4   # sweeps whose modules a long-lived worker keeps


def _module(job: Job) -> ModuleType:
    """The generated module of the job's derivation, imported once per process (and per sweep)."""
    from gacli.simulate import load_generated

    with _LOCK:
        if job.key not in _MODULES:
            while len(_MODULES) >= _KEPT:
                _MODULES.pop(next(iter(_MODULES)))
            _MODULES[job.key] = load_generated(job.derivation)
        return _MODULES[job.key]
