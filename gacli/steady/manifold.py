"""The reduced state of a steady motion: what the constraint manifold leaves free.

The linearization's state (every coordinate, then the independent rates u)
has directions that say nothing about stability. A coordinate that neither
M u̇ = F (eq. 14.19) nor the kinematic rows (eq. 14.20) of the coordinates
kept contain is *ignorable*: x, y, heading and the wheels' angles of a
vehicle; it moves with the steady motion and its perturbation changes
nothing. A coordinate that is contained but whose rate is not among u is
taken as *held* by a holonomic constraint on the coordinates kept,
p = h(q); its rate row q̇_p = Σ β_pj u_j then gives the gradient of h
(u_j = q̇_j), so a perturbation along the manifold moves it by
δp = Σ β_pj δq_j and a perturbation off it is not a direction at all
(the bicycle's pitch, fixed by the front wheel's contact).

Which coordinates enter is decided at seeded random points from the
complex-step Jacobian (exact to rounding), not from the printed trees:
the top's M and F hold φ and ψ in terms that cancel.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.mechanics.equations import Derivation

_SEED = 20261126
_SAMPLES = 2
# Far above the complex step's rounding (~1e-16 relative), far below any real dependence.
_ZERO = 1e-9


@dataclass(frozen=True)
class Reduction:
    """The coordinates kept, those ignored and those held, and the map from the reduced state."""

    coordinates: tuple[str, ...]
    speeds: tuple[str, ...]
    ignorable: tuple[str, ...]
    held: tuple[str, ...]

    @property
    def state(self) -> tuple[str, ...]:
        return self.coordinates + self.speeds


def reduce_state(derivation: Derivation, parameters: Mapping[str, float]) -> Reduction:
    """Which coordinates a perturbation of a steady motion may move (see the module's text)."""
    from gacli.emit.naming import layout
    from gacli.linearize import linearizer

    linearize = linearizer(derivation)
    names = tuple(c.name for c in derivation.system.coordinates)
    speeds = tuple(str(u) for u in derivation.speeds)
    # Inputs and functions of time at generic values too: at 0, a rod turned at Ω(t) left r out of
    # Ω² r, and r was taken for ignorable (a bead flung out along the rod called stable).
    driving = tuple(layout(derivation).r)
    depends = np.zeros((len(names) + len(speeds), len(names)), dtype=bool)
    rng = np.random.default_rng(_SEED)
    # Which symbols enter does not hang on the values: a parameter the file leaves open gets a generic one.
    parameters = {**{p.name: float(rng.uniform(0.5, 1.5)) for p in derivation.system.parameters}, **parameters}
    for _ in range(_SAMPLES):
        state = names + speeds + driving
        at = {n: float(v) for n, v in zip(state, rng.uniform(-0.4, 0.4, len(state)))}
        A = linearize(at, parameters).A
        scale = max(1.0, float(np.abs(A).max()))
        depends |= np.abs(A[:, :len(names)]) > _ZERO * scale
    for j in _kinked(derivation, names):
        depends[len(names):, j] = True
    ignorable = _ignorable(names, depends)
    rates = {c: S.rate_name(c, 1) for c in names}
    held = tuple(c for c in names if c not in ignorable and rates[c] not in speeds)
    kept = tuple(c for c in names if c not in ignorable and c not in held)
    return Reduction(kept, speeds, ignorable, held)


def _kinked(derivation: Derivation, names: tuple[str, ...]) -> list[int]:
    """The coordinates inside a sign() or abs() of the equations: the Jacobian is zero on either side
    of the kink, so k|x| in a potential (a force −k sign(x)) left x 'ignorable' and its family wrong."""
    from gacli.algebra.graph import postorder

    code = derivation.code
    exprs = [*(e for _, e in code.kinematic_equations), *(e for _, e in code.mass_matrix), *code.forcing]
    held = set()
    for node in postorder(exprs):
        if isinstance(node, (sp.sign, sp.Abs, sp.Heaviside)):
            held |= {s.name for s in node.args[0].free_symbols}
    return [j for j, c in enumerate(names) if c in held]


def _ignorable(names: tuple[str, ...], depends: np.ndarray) -> tuple[str, ...]:
    """The coordinates neither u̇ nor the rows of the coordinates that stay contain (a fixed point)."""
    n = len(names)
    out = {j for j in range(n) if not depends[n:, j].any()}
    while True:
        contained = {j for j in out if any(depends[i, j] for i in range(n) if i not in out)}
        if not contained:
            return tuple(names[j] for j in sorted(out))
        out -= contained


def restricted(A, state: tuple[str, ...], reduction: Reduction):
    """A on the reduced state: rows of the kept states, times the map δx = P δz from the reduced.

    Works on numpy arrays and SymPy matrices alike (only products and sums).
    """
    z = reduction.state
    rows = [state.index(n) for n in z]
    P = [[0] * len(z) for _ in state]
    for j, name in enumerate(z):
        P[state.index(name)][j] = 1
    for p in reduction.held:
        for j, q in enumerate(reduction.coordinates):
            rate = S.rate_name(q, 1)
            if rate in state:
                P[state.index(p)][j] = A[state.index(p), state.index(rate)]
    return [[sum(A[r, i] * P[i][j] for i in range(len(state)) if P[i][j] != 0)
             for j in range(len(z))] for r in rows]
