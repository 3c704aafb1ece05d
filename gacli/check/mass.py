"""The checks of M: defined, real, symmetric, and positive definite at seeded sample states."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import sympy as sp

from gacli.check.report import MassMatrixCheck
from gacli.mechanics.equations import Derivation
from gacli.errors import Diagnostic, Location, SystemFileError
from gacli.algebra.graph import free_symbols, postorder
from gacli.mechanics.program.record import inline
from gacli.model import System
from gacli.numeric import UndefinedValue, evaluate, parameter_values, sample_points
from gacli.numeric.definite import diagonally_scaled
from gacli.numeric.samples import SAMPLE_INTERVAL
from gacli.numeric.spheres import on_spheres
from gacli.numeric.zero import decide_zero

PD_SAMPLES = 3


_UNDEFINED = (sp.zoo, sp.nan, sp.oo, -sp.oo)


def check_mass_matrix(derivation: Derivation, findings) -> MassMatrixCheck:
    """What is known about M; each fault is ``findings.error(...)`` (a Diagnostic of the file)."""
    M, F, kinematic = _equations(derivation)
    system = derivation.system
    where = system.location
    nodes = set(postorder([*M, *F, *(e for _, e in kinematic)]))
    if any(node in nodes for node in _UNDEFINED):
        findings.error("the equations contain an undefined value (zoo or nan: a division by zero or a "
                       "logarithm of zero somewhere in the file)", "equations", location=where)
    if sp.I in nodes:  # the loader refuses an imaginary expression; this is the last guard
        findings.error("the equations contain the imaginary unit I: M, F and the kinematic equations must be real",
                       "equations", location=where)
    symmetric = _symmetric(M, findings, where)
    _zero_rows(derivation, M, findings)
    values, missing = parameter_values(system)
    if missing:
        note = f"not checked: no value for {', '.join(missing)}"
        return MassMatrixCheck(symmetric, None, 0, note)
    return _positive_definite(system, M, values, symmetric, findings, where)


def require_regular(derivation: Derivation) -> None:
    """For a command that solves M u̇ = F (simulate, verify, --reactions, linearize --symbolic): a row
    of M that is zero at every state is one located error, as check reports it, not a solver's
    traceback (NonInvertibleMatrixError) partway through."""
    found: list[Diagnostic] = []
    collected = SimpleNamespace(error=lambda message, where="", hint="", location=None: found.append(
        Diagnostic(location or derivation.system.location, message, where, hint)))
    _zero_rows(derivation, _equations(derivation)[0], collected)
    if found:
        raise SystemFileError(found)


def _equations(derivation: Derivation):
    """M, F and q̇: the closed forms or those read off the program, or for a derivation by the program
    alone its outputs inlined (expression graphs: walked by gacli.algebra.graph and evaluated
    numerically, never printed). Not generated code's choice among the program's forms: they
    have the same values, and weighing them is most of a small system's check."""
    if derivation.printable:
        return derivation.mass_matrix, derivation.forcing, derivation.kinematic_equations
    program = derivation.program
    rates, M, F = inline(program)
    kinematic = tuple((name, e) for (name, _), e in zip(program.rates, rates))
    return sp.ImmutableMatrix(program.k, program.k, M), sp.ImmutableMatrix(F), kinematic


def _zero_rows(derivation: Derivation, M, findings) -> None:
    """A row of M that is zero at every state: whatever the parameters, M is singular there and the
    rate's equation reads 0 = 0 (a coordinate that turns only a particle, say), so nothing can be solved."""
    system = derivation.system
    coordinates = {c.name: c.location for c in system.coordinates}
    for i, name in enumerate(derivation.independent):
        if all(M[i, j] == 0 for j in range(M.cols)):
            rate = f"dot({name})"
            findings.error(f"M is singular at every state: its row for {rate} is zero, so the equation of "
                           f"{rate} reads 0 = 0 (no body's kinetic energy depends on {rate})", "mass_matrix",
                           "give the body that this rate turns an inertia, or remove the coordinate",
                           location=coordinates.get(name, system.location))


def _symmetric(M: sp.ImmutableMatrix, findings, where: Location) -> bool | None:
    answer: bool | None = True
    for i in range(M.rows):
        for j in range(i + 1, M.cols):
            decision = decide_zero(M[i, j] - M[j, i])
            if decision.zero is False:
                findings.error(f"M is not symmetric: M[{i}, {j}] != M[{j}, {i}]", "mass_matrix", location=where)
                return False
            if decision.zero is None:
                answer = None
    return answer


def _positive_definite(system: System, M, values, symmetric, findings,
                       where: Location) -> MassMatrixCheck:
    others = sorted(free_symbols(M) - set(values), key=lambda s: s.name)
    # Symbols only in positions get values too, from their own stream: M's samples stay as they were.
    placed = free_symbols([c for body in system.bodies for c in body.position]) - set(values) - set(others)
    evaluated = 0
    for i, (point, more) in enumerate(_samples(others, placed)):
        if i >= PD_SAMPLES and evaluated:
            break
        # Euler parameters on their unit sphere, where the file keeps them: generated code's M is
        # positive definite there, not necessarily off it (a chain of quaternion links).
        state = on_spheres({**values, **more, **point}, system)
        try:
            _require_real_positions(system, state)
            numeric = np.array([[float(evaluate(M[i, j], state)[0]) for j in range(M.cols)] for i in range(M.rows)])
        except UndefinedValue:
            continue
        evaluated += 1
        if not _definite(numeric):
            smallest = float(np.linalg.eigvalsh((numeric + numeric.T) / 2).min())
            shown = ", ".join(f"{s.name}={float(state[s]):.4g}" for s in point)
            at = f"at the sample state {shown}" if shown else "at every state (M is constant)"
            findings.error(f"M is not positive definite {at} "
                           f"(smallest eigenvalue {smallest:.3g})", "mass_matrix",
                           "check the masses and inertias, and that every independent rate moves some body",
                           location=where)
            return MassMatrixCheck(symmetric, False, evaluated)
    if evaluated == 0:
        note = "not checked: M has no real value at the sample states"
        findings.diagnostics.append(Diagnostic(where, f"M's definiteness was {note} (a position is not real "
                                               "at any of them)", "mass_matrix", severity="note"))
        return MassMatrixCheck(symmetric, None, 0, note)
    return MassMatrixCheck(symmetric, True, evaluated)


def _definite(numeric: np.ndarray) -> bool:
    """Whether ``numeric`` is positive definite beyond rounding, whatever the units of its rates
    (gacli.numeric.definite)."""
    if not numeric.size:
        return True
    scaled = diagonally_scaled(numeric, len(numeric))
    return scaled is not None and float(np.linalg.eigvalsh(np.array(scaled, dtype=float)).min()) > 1e-12


# Where no sample of [0.3, 1.7] gives every position a real value (a pendulum of length 0.25 placed by
# sqrt(L**2 - x**2)), the same count of samples ten times smaller.
SMALL_INTERVAL = (0.03, 0.17)


def _samples(others, placed) -> list[tuple[dict, dict]]:
    """Sample states for M (``others``) and for the symbols only in positions (``placed``)."""
    out = []
    for interval in (SAMPLE_INTERVAL, SMALL_INTERVAL):
        out += zip(sample_points(others, PD_SAMPLES, interval=interval),
                   sample_points(placed, PD_SAMPLES, seed=11, interval=interval))
    return out


def _require_real_positions(system: System, state) -> None:
    """UndefinedValue when a position is not real at the state: M there says nothing of the file.

    ``sqrt(1 - x**2)`` is a position only for |x| <= 1; beyond, M is real but meaningless.
    """
    for body in system.bodies:
        for coordinate in body.position:
            evaluate(coordinate, state)
