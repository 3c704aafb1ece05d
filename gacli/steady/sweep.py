"""Eigenvalues along a parameter or a speed, and the intervals where the motion is stable.

At evenly spaced values the reduced A (or the block of the states asked
for) is linearized with the equations compiled once. Its zero roots (a
family's neighbours) are the fewest eigenvalues at zero seen at any sample:
a mode that only crosses zero (the bicycle's capsize) is not one of them.
Each change of verdict between two samples is refined by Brent's method on
the largest real part of the other eigenvalues, less the tolerance (so a
conservative system, whose stable modes sit on the imaginary axis, changes
sign there too), to 1e-10 of the value swept.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from gacli.errors import SystemFileError
from gacli.mechanics.equations import Derivation
from gacli.steady.manifold import reduce_state, restricted
from gacli.steady.stability import growth

_ZERO = 1e-9
# The margin's tolerance: above the rounding of a stable mode on the imaginary axis (~1e-15),
# small enough not to move a critical value past the refinement's own tolerance.
_MARGIN = 1e-12
_XTOL = 1e-10


@dataclass(frozen=True)
class Sweep:
    """The eigenvalues at each value swept and the stable intervals with refined ends."""

    name: str
    values: np.ndarray
    state: tuple[str, ...]
    eigenvalues: np.ndarray          # one row per value, sorted by real part, then imaginary
    zero_roots: int
    stable: tuple[bool | None, ...]  # None where A cannot be evaluated
    critical: tuple[float, ...]      # where the verdict changes, refined
    intervals: tuple[tuple[float, float], ...]
    steady: bool = True              # the ends of the sweep are steady motions (the kept rows of f vanish)
    undefined: str = ""              # why A could not be had at some values (their stable entry is None)


def sweep(derivation: Derivation, name: str, start: float, stop: float, *, at: Mapping[str, float] | None = None,
          parameters: Mapping[str, float] | None = None, states: Sequence[str] | None = None,
          points: int = 101) -> Sweep:
    """Eigenvalues with ``name`` (a state, an input or a parameter) from ``start`` to ``stop``; a value
    where the equations cannot be evaluated (a top standing upright in Euler angles) is left undefined,
    and the sweep goes on past it (the first such error is raised only when no value is defined)."""
    given = dict(parameters or {})
    if name in {p.name for p in derivation.system.parameters}:  # swept: no --set needed for it
        given.setdefault(name, float(start))
    values = np.linspace(float(start), float(stop), int(points))
    matrix = _Matrix(derivation, name, dict(at or {}), given, states, values)
    matrices, failure = _matrices(matrix, values)
    defined = [i for i, A in enumerate(matrices) if A is not None]
    if not defined:
        raise failure
    nan = np.full(len(matrix.state), complex("nan"))
    eigenvalues = np.array([_sorted(np.linalg.eigvals(A)) if A is not None else nan for A in matrices])
    zero = min(int(np.sum(np.abs(eigenvalues[i]) <= _ZERO * _scale(matrices[i]))) for i in defined)
    stable = tuple(None if A is None else growth(A, zero) - _MARGIN * _scale(A) <= 0 for A in matrices)
    critical = tuple(_refine(matrix, zero, values[i], values[i + 1]) for i in range(len(values) - 1)
                     if None not in (stable[i], stable[i + 1]) and stable[i] != stable[i + 1])
    ends = (values[defined[0]], values[defined[-1]])
    return Sweep(name, values, matrix.state, eigenvalues, zero, stable, critical,
                 _intervals(values, stable, critical), all(matrix.steady(v) for v in ends),
                 str(failure.diagnostics[0].message) if failure is not None else "")


def _matrices(matrix: "_Matrix", values: np.ndarray) -> tuple[list, SystemFileError | None]:
    """A at each value, None where it cannot be evaluated; the first such error."""
    out, failure = [], None
    for v in values:
        try:
            out.append(matrix(v))
        except SystemFileError as exc:
            failure = failure or exc
            out.append(None)
    return out, failure


class _Matrix:
    """The A of the sweep as a function of the value swept."""

    def __init__(self, derivation, name, at, parameters, states, values):
        from gacli.linearize import linearizer, state_indices
        from gacli.sweep.work import resolved_parameters

        self._lin, self._name, self._at, self._given = linearizer(derivation), name, at, parameters
        self._derivation = derivation
        self._resolve = lambda given: resolved_parameters(derivation.system, given)
        self._is_parameter = name in {p.name for p in derivation.system.parameters}
        base = self._resolve(parameters)
        probe = self._probe(values)
        if not self._is_parameter and name not in probe.state + probe.inputs:
            from gacli.simulate.spec import OptionError

            known = ", ".join(probe.state + probe.inputs + tuple(base))
            raise OptionError([f"--sweep: not a state, input or parameter: {name} (they are {known})"])
        self._reduction = None if states else reduce_state(derivation, base)
        self._indices = state_indices(states, probe.state) if states else None
        self.state = tuple(states) if states else self._reduction.state

    def _probe(self, values: np.ndarray):
        """The linearization at --at, which names the state; else at the first value swept where it
        can be had (--at alone may be the singular point the sweep passes, a top upright)."""
        try:
            return self._lin(self._at, self._resolve(self._given))
        except SystemFileError as exc:
            for v in values:
                try:
                    return self._lin(*self._point(v))
                except SystemFileError:
                    continue
            raise exc

    def _point(self, value: float) -> tuple[dict, dict]:
        if self._is_parameter:
            return self._at, self._resolve({**self._given, self._name: float(value)})
        return {**self._at, self._name: float(value)}, self._resolve(self._given)

    def steady(self, value: float) -> bool:
        """Whether the point is a steady motion (always True for a block of --states: not judged)."""
        from gacli.linearize import rates_at
        from gacli.steady.stability import steady_numeric

        if self._reduction is None:
            return True
        return steady_numeric(rates_at(self._derivation, *self._point(value)), self._reduction)

    def __call__(self, value: float) -> np.ndarray:
        lin = self._lin(*self._point(value))
        if self._indices is not None:
            return lin.A[np.ix_(self._indices, self._indices)]
        return np.array(restricted(lin.A, lin.state, self._reduction), dtype=float).reshape(len(self.state), -1)


def _refine(matrix: _Matrix, zero: int, low: float, high: float) -> float:
    from scipy.optimize import brentq

    def margin(v: float) -> float:
        A = matrix(v)
        return growth(A, zero) - _MARGIN * _scale(A)

    return round(float(brentq(margin, low, high, xtol=_XTOL, rtol=4 * np.finfo(float).eps)), 9)


def _intervals(values: np.ndarray, stable: tuple[bool | None, ...], critical: tuple[float, ...]):
    """The stable stretches of [start, stop], with the refined values as their ends; a value where A is
    undefined ends a stretch at the defined value before it."""
    out = []
    for run in _defined_runs(stable):
        low, high = float(values[run[0]]), float(values[run[-1]])
        edges = [low, *(c for c in critical if low < c < high), high]
        # The verdict of each stretch is that of a sample inside it: the middle one.
        for a, b in zip(edges, edges[1:]):
            inside = [stable[i] for i in run if a <= values[i] <= b]
            if inside and inside[len(inside) // 2]:
                out.append((a, b))
    return tuple(out)


def _defined_runs(stable: tuple[bool | None, ...]) -> list[list[int]]:
    runs: list[list[int]] = []
    for i, verdict in enumerate(stable):
        if verdict is None:
            continue
        if runs and runs[-1][-1] == i - 1:
            runs[-1].append(i)
        else:
            runs.append([i])
    return runs


def _sorted(values: np.ndarray) -> np.ndarray:
    return values[np.lexsort((values.imag, values.real))]


def _scale(A: np.ndarray) -> float:
    return max(1.0, float(np.abs(A).max())) if A.size else 1.0
