"""An initial state on the holonomic constraints: completed where the user left coordinates out, else refused.

A simulation started off a holonomic constraint f(q, t) = 0 (a loop that
does not close, a bicycle whose rear and front wheels do not both touch the
ground, an Euler-parameter vector that is not of unit length) follows other
equations than the model's: gacli integrates only the rates, so the error
never shrinks. The coordinates given with ``--init`` are kept as given; those
left out (which start at 0) are solved for, by damped Gauss-Newton from 0,
so that every constraint holds to 1e-9. When that is impossible (nothing
was left out, or no solution is near), the state is refused with each
violated constraint and its residual (docs/simulate.md).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping, Sequence

import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.fastdiff import jacobian_rows
from gacli.model import System
from gacli.numeric import Program

TOLERANCE = 1e-9
ITERATIONS = 60
START_OFFSET = 0.1  # a fixed step off a start where the constraints' Jacobian loses rank


class InitialStateNote(UserWarning):
    """What gacli completed in the initial state (shown as a note)."""


def constrained(system: System, x0: np.ndarray, state: Sequence[str], numbers: Mapping[sp.Symbol, float],
                given: set[str]) -> list[str]:
    """Complete ``x0`` in place on the holonomic constraints; the problems (empty when it holds)."""
    relations = _relations(system, numbers)
    if not relations:
        return []
    coordinates = [c.name for c in system.coordinates]
    values = {S.value(q): x0[state.index(q)] for q in coordinates}
    values[S.T] = 0.0
    residual = _residuals(relations, values)
    if _holds(residual):
        return []
    free = [q for q in coordinates if q not in given and any(r.has(S.value(q)) for r, _ in relations)]
    if free and _solve(relations, values, free):
        _nearest_turns(relations, values, free)
        for q in free:
            x0[state.index(q)] = values[S.value(q)]
        solved = ", ".join(f"{q} = {values[S.value(q)]:.10g}" for q in free)
        warnings.warn(f"completed on the holonomic constraints: {solved}", InitialStateNote)
        return []
    out = []
    for (f, text), r in zip(relations, _residuals(relations, values)):
        if abs(r) <= TOLERANCE:
            continue
        if free:
            hint = f"no values of {', '.join(free)} near 0 satisfy it; give them with --init"
        else:
            hint = f"leave one of {', '.join(q for q in coordinates if f.has(S.value(q)))} out of --init for gacli to solve"
        out.append(f"--init: the initial state violates the constraint '{text}' (residual {r:.3g}): {hint}")
    return out


def _relations(system: System, numbers: Mapping[sp.Symbol, float]) -> list[tuple[sp.Expr, str]]:
    """The holonomic constraints with the parameters' values, those over coordinates and t alone."""
    allowed = {S.value(c.name) for c in system.coordinates} | {S.T}
    out = []
    for c in system.constraints:
        if c.relation is None:
            continue
        f = c.relation.xreplace(dict(numbers))
        if f.free_symbols <= allowed:
            out.append((f, c.text))
    return out


def _residuals(relations, values: dict) -> np.ndarray:
    return np.real(np.array(Program([f for f, _ in relations])(values), dtype=complex))


def _holds(residual: np.ndarray) -> bool:
    return bool(np.all(np.abs(residual) <= TOLERANCE))


def _nearest_turns(relations, values: dict, free: list[str]) -> None:
    """Each solved coordinate moved by whole turns to its value nearest 0, where it started, when the
    constraints still hold there: a four-bar's Gauss-Newton steps ended at q2 = −14.08, q3 = 27.50,
    the angles −1.52 and 2.36 two and four turns away."""
    for q in free:
        s = S.value(q)
        turns = round(values[s] / (2 * math.pi))
        if turns:
            trial = {**values, s: values[s] - 2 * math.pi * turns}
            if _holds(_residuals(relations, trial)):
                values.update(trial)


def _solve(relations, values: dict, free: list[str]) -> bool:
    """Damped Gauss-Newton over the free coordinates, from their values in ``values`` (updated in place)."""
    symbols = [S.value(q) for q in free]
    jacobian = Program([d for row in jacobian_rows([f for f, _ in relations], symbols) for d in row])
    shape = (len(relations), len(symbols))
    residual = _residuals(relations, values)
    for iteration in range(ITERATIONS):
        if _holds(residual):
            return True
        J = np.real(np.array(jacobian(values), dtype=complex)).reshape(shape)
        if iteration == 0 and np.linalg.matrix_rank(J) < min(shape):
            # Started where the constraints are stationary (Euler parameters all 0): step off it.
            values.update({s: values[s] + START_OFFSET for s in symbols})
            residual = _residuals(relations, values)
            J = np.real(np.array(jacobian(values), dtype=complex)).reshape(shape)
        step = np.linalg.lstsq(J, -residual, rcond=None)[0]
        for scale in (1.0, 0.5, 0.25, 0.125, 0.0625):
            trial = dict(values)
            trial.update({s: values[s] + scale * d for s, d in zip(symbols, step)})
            candidate = _residuals(relations, trial)
            if np.linalg.norm(candidate) < np.linalg.norm(residual) or scale == 0.0625:
                values.update(trial)
                residual = candidate
                break
    return _holds(residual)
