"""The axes each body's motion is carried in: where its components are shortest.

A vehicle's heading θ is in every inertial component of its velocity
(ẋ = v cos θ), and a wheel's spin φ in every body-axis component of its ω;
only sin² + cos² removes them from a·a, V·V and ω·Iω, and once those
products are too large to reduce, nothing does. Dot products do not change
under a rotation, so M, F and G are formed as well in axes turned by θ
about N's z (a body's linear motion), or turned back by φ about a wheel's
axle (its angular motion, where the inertia is symmetric about the axle):
the heading frame and the non-spinning frame of a hand derivation
(docs/readable.md). Only systems written with frames are turned.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import sympy as sp

from gacli.algebra import trig
from gacli.algebra.angles import relative
from gacli.algebra.graph import postorder
from gacli.loader.frames import simple_rotation
from gacli.mechanics.motions import BodyMotion, Motion, make_motion
from gacli.model import System


def turned(system: System, motions: tuple[BodyMotion, ...]) -> tuple[BodyMotion, ...]:
    """Each body's motions along the axes where they are shortest (a format-1 file's: as they are)."""
    if not system.uses_frames:
        return motions
    out = []
    for m in motions:
        linear, heading = headed(m.linear, m.body.position)
        angular, spin = unspun(m.angular, m.body.inertia) if m.angular is not None else (None, None)
        out.append(replace(m, linear=linear, angular=angular, heading=heading, spin=spin))
    return tuple(out)


def unspun(angular: Motion, inertia) -> tuple[Motion, tuple[str, sp.Expr] | None]:
    """ω and α along axes that do not spin with the body, where its inertia allows.

    A wheel's body axes turn with its spin φ, and every component of its ω
    and α holds sin φ and cos φ, which only sin² + cos² removes from ω·Iω
    (too late, once the products are too large to reduce). When the inertia
    is symmetric about a body axis, a turn about that axis changes none of
    αᵀIα, α·(ω × Iω) or T·Ω, so they are formed along the axes turned back
    by φ: the wheel's non-spinning frame of a hand derivation.
    """
    best, best_size = (angular, None), _size(angular)
    if best_size > _TURNED_NODES:
        return best
    candidates = _angles([*angular.partials.values(), *angular.velocity0])
    if len(candidates) > _MAX_ANGLES:
        return best
    for axis in "xyz":
        if not candidates or not _symmetric_about(sp.Matrix(inertia), axis):
            continue
        for angle in candidates:
            turned = _rotated(angular, lambda v: spin_back(v, (axis, angle)))
            size = _size(turned)
            if size < best_size:
                best, best_size = (turned, (axis, angle)), size
    return best


def spin_back(vector: Sequence[sp.Expr], spin: tuple[str, sp.Expr] | None) -> list[sp.Expr]:
    """Body-axis components → components along the axes turned back by the spin (R v)."""
    if spin is None:
        return list(vector)
    axis, angle = spin
    R = simple_rotation(axis, angle).tolist()  # v_parent = R v_body, as the frames' own
    return [trig.reduce(sp.Add(*[R[i][j] * vector[j] for j in range(3) if R[i][j] != 0 and vector[j] != 0]),
                        cancel=True) for i in range(3)]


def _symmetric_about(inertia: sp.Matrix, axis: str) -> bool:
    """Whether Rᵀ I R = I for every turn R about the body axis: I = diag with the two
    other moments equal, or a multiple of it."""
    i = "xyz".index(axis)
    j, k = (i + 1) % 3, (i + 2) % 3
    off = [inertia[a, b] for a in range(3) for b in range(3) if a != b]
    return all(e == 0 for e in off) and sp.expand(inertia[j, j] - inertia[k, k]) == 0


# Motions of more distinct subexpressions are kept in their axes: a turn of them
# would be too large to reduce (a bicycle's), and trying costs seconds.
_TURNED_NODES = 600
# A body turned through more angles than this is the end of a chain, where no one
# turn shortens much and trying each costs a reduction per angle and component.
_MAX_ANGLES = 4


def headed(linear: Motion, position) -> tuple[Motion, sp.Expr]:
    """The linear motion along the axes, turned about N's z, where its components are shortest.

    A vehicle's heading θ enters every inertial component of its velocity
    (ẋ = v cos θ), and only sin² θ + cos² θ removes it from a·a, V·V and
    V·a: products too large to reduce keep it, and a four-wheeled robot's
    equations held θ thousands of times. Dot products do not change under a
    rotation, so M, F and G are formed as well in the axes turned by θ,
    where each component, small enough to reduce, is free of θ (the
    body-fixed heading axes a hand derivation uses). The angles tried are
    those whose sine or cosine the horizontal position holds; N's own axes
    are kept unless a turn shortens the components.
    """
    best, best_cost = (linear, sp.S.Zero), _cost(linear)
    if best_cost[1] > _TURNED_NODES:
        return best
    candidates = _angles(position[:2])
    if len(candidates) > _MAX_ANGLES:
        return best
    for angle in candidates:
        turned = _turned(linear, angle)
        cost = _cost(turned)
        if cost < best_cost:
            best, best_cost = (turned, angle), cost
    return best


def turn(vector: Sequence[sp.Expr], angle: sp.Expr) -> list[sp.Expr]:
    """A vector's N components → its components along N's axes turned by ``angle`` about z."""
    if angle == 0:
        return list(vector)
    c, s = sp.cos(angle), sp.sin(angle)
    x, y, z = vector
    return [relative(trig.reduce(c * x + s * y, cancel=True)), relative(trig.reduce(-s * x + c * y, cancel=True)), z]


def _turned(linear: Motion, angle: sp.Expr) -> Motion:
    return _rotated(linear, lambda v: turn(v, angle))


def _rotated(motion: Motion, rotate) -> Motion:
    partials = motion.partials
    columns = [rotate(list(partials.col(j))) for j in range(partials.cols)]
    rows = [[columns[j][i] for j in range(partials.cols)] for i in range(3)]
    return make_motion(rows, rotate(list(motion.velocity0)), rotate(list(motion.acceleration_rest)))


def _angles(exprs) -> list[sp.Expr]:
    """The symbols whose sine or cosine ``exprs`` hold, in a fixed order."""
    found = {node.args[0] for node in postorder(exprs) if isinstance(node, (sp.sin, sp.cos)) and node.args[0].is_Symbol}
    return sorted(found, key=sp.default_sort_key)


def _cost(motion: Motion) -> tuple[int, int]:
    """The angles a motion's components hold, then their size: a trailer wheel's motion
    along the trailer's heading holds only the hitch angle θ − θ_T, and in N's axes
    θ and θ_T besides, whose products then cancel only through sin² + cos², though
    the factored form in N has fewer distinct subexpressions."""
    exprs = [*motion.partials.values(), *motion.velocity0, *motion.acceleration_rest]
    angles = {node.args[0] for node in postorder(exprs) if isinstance(node, (sp.sin, sp.cos))}
    return len(angles), _size(motion)


def _size(motion: Motion) -> int:
    """Distinct subexpressions of the motion: a tree count (count_ops) of a bicycle's
    motions walks millions of nodes."""
    return sum(1 for _ in postorder([*motion.partials.values(), *motion.velocity0, *motion.acceleration_rest]))

