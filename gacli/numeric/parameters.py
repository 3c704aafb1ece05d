"""Parameters as numbers: the file's values, and physical random samples of the others.

Every tool that needs numbers for the parameters takes them here: ``gacli
check`` (:func:`parameter_values`), ``gacli verify`` and the reactions
(:func:`sample_parameters`, :func:`precise_parameter_values`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.numeric.evaluator import Program
from gacli.numeric.guarded import UndefinedValue, evaluate


def parameter_values(system) -> tuple[dict[sp.Symbol, float], list[str]]:
    """Numeric values of the parameters (values may name earlier ones) and the names without one.

    By the guarded evaluator: a value too large to be a number is no value.
    """
    values: dict[sp.Symbol, float] = {}
    missing = []
    for p in system.parameters:
        if p.value is None:
            missing.append(p.name)
            continue
        try:
            values[S.value(p.name)] = float(evaluate(p.value, values)[0])
        except UndefinedValue:
            missing.append(p.name)
    return values, missing


def precise_parameter_values(system, sample: "ParameterSample", digits: int) -> dict[sp.Symbol, mpmath.mpf]:
    """The file's values at ``digits`` digits (expressions in earlier parameters), the sample's elsewhere."""
    values: dict[sp.Symbol, mpmath.mpf] = {}
    for p in system.parameters:
        if p.value is None:
            values[S.value(p.name)] = mpmath.mpf(sample.values[S.value(p.name)])
        else:
            exact = {s: sp.Float(str(v), digits) for s, v in values.items()}
            values[S.value(p.name)] = mpmath.mpf(str(sp.N(p.value.xreplace(exact), digits)))
    return values


# -- physical samples of the parameters -------------------------------------------
# gacli verify gives every parameter without a value a random number. Each one
# drawn alone in [0.5, 2] makes masses and lengths positive, but an inertia
# matrix of symbolic moments and products is then indefinite about half the
# time, and M with it: verify would blame the derivation for the sample.

PARAMETER_RANGE = (0.5, 2.0)   # masses, lengths, moments: positive, of order one
PRODUCT_RANGE = (-0.3, 0.3)    # a product of inertia alone in an entry: either sign, small
TRIES = 100


@dataclass(frozen=True)
class ParameterSample:
    """Float values of every parameter that has one; ``problem`` is "" when every body is physical."""

    values: dict[sp.Symbol, float]
    problem: str


def sample_parameters(system, rng) -> ParameterSample:
    """Parameters without a value drawn at random so that every body is physical.

    The first draw is one ``rng.uniform(0.5, 2)`` per such parameter in
    declaration order (the draw verify always made, so its samples of
    physical systems do not change); while a mass is not positive or an
    inertia matrix is not positive semidefinite with principal moments
    obeying the triangle inequalities, the parameters of masses and inertias
    are drawn again. ``problem`` says what is still wrong after ``TRIES``.
    """
    drawn = [S.value(p.name) for p in system.parameters if p.value is None]
    chosen = {s: rng.uniform(*PARAMETER_RANGE) for s in drawn}
    values = _parameter_floats(system, chosen)
    problem = unphysical(system, values)
    inertial, products = _inertial_parameters(system, set(drawn))
    for _ in range(TRIES if inertial else 0):
        if not problem:
            break
        chosen.update({s: rng.uniform(*(PRODUCT_RANGE if s in products else PARAMETER_RANGE)) for s in inertial})
        values = _parameter_floats(system, chosen)
        problem = unphysical(system, values)
    return ParameterSample(values, problem)


def _parameter_floats(system, chosen: Mapping[sp.Symbol, float]) -> dict[sp.Symbol, float]:
    """The chosen values, and the file's values (expressions in earlier parameters) as floats."""
    values: dict[sp.Symbol, float] = {}
    for p in system.parameters:
        symbol = S.value(p.name)
        number = chosen.get(symbol) if p.value is None else _float(p.value, values)
        if number is not None:
            values[symbol] = number
    return values


def _inertial_parameters(system, drawn: set) -> tuple[list[sp.Symbol], set[sp.Symbol]]:
    """Drawn parameters in masses and inertias (sorted), and those only in products of inertia."""
    diagonal, off = set(), set()
    for body in system.bodies:
        diagonal |= body.mass.free_symbols
        if body.inertia is not None:
            for i in range(3):
                for j in range(3):
                    (diagonal if i == j else off).update(body.inertia[i, j].free_symbols)
    inertial = sorted((diagonal | off) & drawn, key=lambda s: s.name)
    return inertial, (off - diagonal) & drawn


def unphysical(system, values: Mapping[sp.Symbol, float]) -> str:
    """What makes a body unphysical at these parameter values ("" when nothing does, or unknown)."""
    return next((problem for body in system.bodies if (problem := body_problem(body, values))), "")


def body_problem(body, values: Mapping[sp.Symbol, float], massless: bool = False) -> str:
    """What makes one body unphysical at these values: a mass not positive (0 allowed, and then
    nothing else judged, with ``massless``), an inertia not positive or breaking the triangle
    inequality; "" when nothing does, or unknown."""
    mass = _float(body.mass, values)
    if mass is not None and not mass > 0:
        return "" if massless and mass == 0 else f"the mass of {body.name} is {mass:.3g}"
    if body.inertia is None:
        return ""
    entries = [_float(body.inertia[i, j], values) for i in range(3) for j in range(3)]
    if None in entries:
        return ""
    moments = sorted(float(v) for v in np.linalg.eigvalsh(np.array(entries).reshape(3, 3)))
    slack = 1e-9 * max(abs(moments[-1]), 1e-300)
    shown = ", ".join(f"{v:.3g}" for v in moments)
    if moments[0] < -slack:
        return f"the inertia of {body.name} is not positive definite (principal moments {shown})"
    # A plane body gives only the moment about its axis: diag(0, 0, I) is no real body, but no fault.
    planar = moments[1] <= slack
    if not planar and moments[2] > moments[0] + moments[1] + slack:
        return f"the inertia of {body.name} breaks the triangle inequality (principal moments {shown})"
    return ""


def _float(expr: sp.Expr, values: Mapping[sp.Symbol, float]) -> float | None:
    """The real value of ``expr`` at ``values``; None when it has none there."""
    if not expr.free_symbols <= set(values):
        return None
    try:
        value = Program([expr])(values)[0]
    except (ArithmeticError, ValueError, TypeError):
        return None
    return value.real if value.imag == 0 else None
