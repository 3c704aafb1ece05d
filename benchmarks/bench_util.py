"""Shared pieces of the benchmark: plain symbols, CSE operation counts, timing, evaluation.

Everything the harness compares is first rewritten in the plain symbols
``x_0, x_1, ...`` (state), ``p_0, ...`` (parameters) and ``r_0, ...``
(inputs and function values), in the order of gacli's generated code, so
that both tools' expressions are counted, lambdified and printed the same
way.
"""

from __future__ import annotations

import gc
import time
import timeit
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import sympy as sp


def plain_symbols(prefix: str, count: int) -> list[sp.Symbol]:
    return [sp.Symbol(f"{prefix}_{i}", real=True) for i in range(count)]


@dataclass(frozen=True)
class Equations:
    """q' = kinematics, M u' = F, in plain symbols; M is k x k (or o x o for Kane with constraints)."""

    kinematics: tuple[sp.Expr, ...]
    mass_matrix: sp.ImmutableMatrix
    forcing: sp.ImmutableMatrix
    x: tuple[sp.Symbol, ...]
    p: tuple[sp.Symbol, ...]
    r: tuple[sp.Symbol, ...]

    @property
    def k(self) -> int:
        return self.mass_matrix.rows

    def expressions(self) -> list[sp.Expr]:
        """Kinematics, then M row by row, then F: what a rhs evaluates."""
        return [*self.kinematics, *self.mass_matrix, *self.forcing]


# -- operation counts ----------------------------------------------------------

@dataclass(frozen=True)
class Counted:
    operations: int
    temporaries: int
    replacements: tuple
    reduced: tuple


def cse_count(expressions: Sequence[sp.Expr]) -> Counted:
    """``count_ops`` of SymPy's CSE of the expressions: replacements plus reduced expressions."""
    replacements, reduced = sp.cse(list(expressions), symbols=sp.numbered_symbols("_k"), order="canonical")
    return counted(replacements, reduced)


def counted(replacements, reduced) -> Counted:
    ops = sum(sp.count_ops(v) for _, v in replacements) + sum(sp.count_ops(e) for e in reduced)
    return Counted(int(ops), len(replacements), tuple(replacements), tuple(reduced))


# -- timing -------------------------------------------------------------------------

@dataclass(frozen=True)
class Timing:
    """Wall-clock (``time.perf_counter``) and CPU (``time.process_time``) seconds of one call."""

    wall: float
    cpu: float

    def get(self, clock: str) -> float:
        return self.cpu if clock == "cpu" else self.wall


def timed(fn: Callable[[], object]) -> tuple[Timing, object]:
    """Time one call; the garbage collector is collected before, and disabled during, the call."""
    gc.collect()
    gc.disable()
    try:
        wall, cpu = time.perf_counter(), time.process_time()
        result = fn()
        timing = Timing(time.perf_counter() - wall, time.process_time() - cpu)
    finally:
        gc.enable()
    return timing, result


BATCH_SECONDS = 0.002


def per_call(fn: Callable[[], object], min_time: float) -> float:
    """Seconds per call of a fast function: the fastest of many short batches.

    The number of calls per batch is doubled until a batch takes about 2 ms;
    then batches are timed until ``min_time`` seconds have passed (at least
    5). A batch that short is rarely interrupted by other processes, so the
    fastest one approximates an unloaded machine.
    """
    timer = timeit.Timer(fn)
    number = 1
    while timer.timeit(number) < BATCH_SECONDS and number < 10**7:
        number *= 2
    best, batches, start = float("inf"), 0, time.perf_counter()
    while batches < 5 or (time.perf_counter() - start < min_time and batches < 10_000):
        best = min(best, timer.timeit(number))
        batches += 1
    return best / number


# -- numeric evaluation -------------------------------------------------------------

def lambdify_rhs(eqs: Equations) -> Callable:
    """rhs(t, x, p, r) -> [q', u'] by ``lambdify(..., cse=True)`` and ``numpy.linalg.solve``.

    This is how a SymPy user would evaluate KanesMethod's output; it also
    serves as the reference evaluation of gacli's derivation.
    """
    t = sp.Symbol("t", real=True)
    target = (sp.Matrix(list(eqs.kinematics)), eqs.mass_matrix, eqs.forcing)
    f = sp.lambdify([t, list(eqs.x), list(eqs.p), list(eqs.r)], target, modules="numpy", cse=True)

    def rhs(t, x, p, r=()):
        qdot, M, F = f(t, x, p, r)
        return np.concatenate([np.ravel(qdot), np.linalg.solve(M, F).ravel()])

    rhs.parts = f  # (t, x, p, r) -> (q', M, F)
    return rhs


def relative_error(a: Sequence[float], b: Sequence[float]) -> float:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return float("inf")
    scale = max(float(np.max(np.abs(b))) if b.size else 0.0, 1e-300)
    return float(np.max(np.abs(a - b))) / scale if a.size else 0.0


def random_values(rng: np.random.Generator, count: int, low: float, high: float) -> list[float]:
    return [float(v) for v in rng.uniform(low, high, size=count)]
