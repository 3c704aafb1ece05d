"""Bodies assembled in units: the frame each body's share of M and F is formed in, and composite bodies.

A rigid body's inertia is constant in its own frame, and in every frame
reached from it by constant rotations (the inertia turned with them) or by
rotations about an axis it is symmetric about (a wheel's spin: the body
turns in that frame by its spin only, σ about one axis). Bodies whose
inertias are constant in a common frame and whose centres are fixed in it
(a bicycle's frame and rear wheel; its fork and front wheel) are merged
into one *unit*: composite mass, centre and inertia, parameters only. A
unit needs one partial velocity and one partial angular velocity per
speed however many bodies it holds.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.frame_model import INERTIAL, BodyPlacement, PointLink
from gacli.loader.frames import simple_rotation
from gacli.mechanics.program.frames import FrameTree
from gacli.mechanics.program.support import Unsupported
from gacli.mechanics.program.vectors import isotropic, unit


@dataclass(frozen=True)
class Placement:
    """A body assembled in ``frame``: its inertia there (constant), the spins that turn it relative to
    the frame [(edge, sign, constant vector)], and the constant rotations [(edge, up)] that take the
    declared inertia there."""

    frame: str
    inertia: sp.Matrix
    spins: tuple
    steps: tuple


@dataclass(frozen=True)
class Wheel:
    """A member turning relative to its unit's frame about ``axis``: spin σ = Σ sign θ̇_edge, inertia λ about it."""

    axis: int
    inertia: sp.Expr
    edges: tuple[tuple[str, sp.Expr], ...]
    body: str


@dataclass(frozen=True)
class Unit:
    """One body, or bodies rigidly joined: assembled at centre ``point`` along ``frame``."""

    members: tuple[tuple[BodyPlacement, Placement | None], ...]
    point: str
    frame: str
    mass: sp.Expr
    offsets: tuple  # each member's centre from the unit's anchor, along the frame (composite only)
    wheels: tuple[Wheel, ...]

    @property
    def rigid(self) -> bool:
        return any(b.inertia is not None for b, _ in self.members)

    def holds(self, body: str) -> bool:
        return any(b.name == body for b, _ in self.members)


def _invariant(inertia: sp.Matrix, axis: int) -> bool:
    """The inertia unchanged by any rotation about the axis (symmetric about it)."""
    j, k = (axis + 1) % 3, (axis + 2) % 3
    off = [inertia[axis, j], inertia[axis, k], inertia[j, k], inertia[j, axis], inertia[k, axis], inertia[k, j]]
    return sp.expand(inertia[j, j] - inertia[k, k]) == 0 and all(x == 0 for x in off)


def placements(tree: FrameTree, body: BodyPlacement) -> dict[str, Placement]:
    """Every frame where the body's inertia is constant, reached from its own frame (see the module)."""
    start = Placement(body.frame, sp.Matrix(body.inertia), (), ())
    found, todo = {body.frame: start}, [start]
    children: dict[str, list[str]] = {}
    for e in tree.edges.values():
        children.setdefault(e.parent, []).append(e.name)
    while todo:
        here = todo.pop()
        moves = [(here.frame, tree.edges[here.frame].parent, True)] if here.frame != INERTIAL else []
        moves += [(c, c, False) for c in children.get(here.frame, [])]
        for edge, there, up in moves:
            if there in found or there == INERTIAL:
                continue
            step = _across(tree, here, edge, there, up)
            if step is not None:
                found[there] = step
                todo.append(step)
    return found


def _across(tree: FrameTree, here: Placement, edge: str, there: str, up: bool) -> Placement | None:
    """The placement one edge away: a spin about a symmetry axis, or a constant rotation."""
    axis, constant = tree.edges[edge].axis, tree.constant(edge)
    if axis < 0:  # a quaternion's turn is about no one axis, and never constant
        return None
    along = all(all(v[i] == 0 for i in range(3) if i != axis) for _, _, v in here.spins)
    if _invariant(here.inertia, axis) and along:
        spins = here.spins + (() if constant else ((edge, 1 if up else -1, unit(axis)),))
        return Placement(there, here.inertia, spins, here.steps)
    if not constant:
        return None
    rotation = simple_rotation("xyz"[axis], tree.edges[edge].angle)
    rotation = rotation if up else rotation.T  # components along ``there`` from those along ``here``
    spins = tuple((e, s, tuple(rotation * sp.Matrix(v))) for e, s, v in here.spins)
    inertia = (rotation * here.inertia * rotation.T).applyfunc(sp.expand)
    return Placement(there, inertia, spins, here.steps + ((edge, up),))


def rigid_rotation(tree: FrameTree, a: str, b: str) -> sp.Matrix | None:
    """The constant rotation taking components along a to components along b, or None if it moves."""
    ca, cb = tree.chain(a), tree.chain(b)
    common = next(f for f in ca if f in cb)
    rotation = sp.eye(3)
    for f in ca[:ca.index(common)]:
        if not tree.constant(f):
            return None
        rotation = simple_rotation("xyz"[tree.edges[f].axis], tree.edges[f].angle) * rotation
    for f in reversed(cb[:cb.index(common)]):
        if not tree.constant(f):
            return None
        rotation = simple_rotation("xyz"[tree.edges[f].axis], tree.edges[f].angle).T * rotation
    return rotation


def offset_in(tree: FrameTree, links: dict[str, PointLink], anchor: str | None, point: str | None,
              frame: str, coordinates: set) -> sp.Matrix | None:
    """The point's position from ``anchor`` (one of its ancestors) along ``frame``, when fixed there."""
    total = sp.zeros(3, 1)
    while point != anchor:
        link = links.get(point) if point is not None else None
        if link is None or any(x.free_symbols & coordinates for x in link.components):
            return None
        rotation = rigid_rotation(tree, link.frame, frame)
        if rotation is None:
            return None
        total += rotation * sp.Matrix(link.components)
        point = link.parent
    return total


def ancestors(links: dict[str, PointLink], point: str | None) -> list[str | None]:
    """The point and the points it hangs from, up to N's origin (None)."""
    out = []
    while point is not None:
        out.append(point)
        point = links[point].parent if point in links else None
    return out + [None]


def _about_one_axis(placement: Placement) -> bool:
    """Whether the placement's spins are all about one axis of its frame (none: a body at rest in it)."""
    axes = {next(i for i in range(3) if v[i] != 0) for _, _, v in placement.spins}
    return len(axes) <= 1 and all(sum(abs(x) for x in v) == 1 for _, _, v in placement.spins)


def wheels_of(body: BodyPlacement, placement: Placement) -> tuple[Wheel, ...]:
    """The body as a wheel of its unit: its spins, all about one axis of the unit's frame."""
    if not placement.spins:
        return ()
    if not _about_one_axis(placement):
        raise Unsupported(f"the spins of '{body.name}' are not about one axis of the frame it is assembled in")
    a = next(i for i in range(3) if placement.spins[0][2][i] != 0)
    edges = tuple((e, s * v[a]) for e, s, v in placement.spins)
    return (Wheel(a, placement.inertia[a, a], edges, body.name),)


def units(tree: FrameTree, links: dict[str, PointLink], bodies: tuple[BodyPlacement, ...],
          coordinates: set, partial: tuple = ()) -> list[Unit]:
    """The bodies grouped greedily, in declaration order, into units (a composite's centre becomes a
    link); ``partial``: the partial passes, which choose a lone wheel's frame (:func:`_spun`)."""
    groups: list[dict] = []
    for body in bodies:
        options = placements(tree, body) if body.inertia is not None else None
        if options is None or not any(_join(tree, links, g, body, options, coordinates) for g in groups):
            groups.append({"members": [(body, options)], "frames": set(options or ())})
    return [_unit(tree, links, g, coordinates, partial) for g in groups]


def _join(tree, links, group: dict, body: BodyPlacement, options: dict, coordinates: set) -> bool:
    """Add the body to the group if they share a frame where both are constant and their centres fixed.

    Only bodies whose masses are positive numbers are gathered: a composite's centre and
    reduced mass divide by the total, which a parameter can make zero (massless wheels set
    at run time), where the chapter's route still has a positive definite M."""
    if any(b.inertia is None or not _positive(b.mass) for b, _ in [*group["members"], (body, None)]):
        return False
    common = group["frames"] & set(options)
    own = [links[b.point].frame for b, _ in group["members"]] + [links[body.point].frame]
    for frame in sorted(common, key=lambda f: (f not in own, f)):
        members = [b for b, _ in group["members"]] + [body]
        if _offsets(tree, links, members, frame, coordinates) is not None:
            group["members"].append((body, options))
            group["frames"] = common
            return True
    return False


def _spun(tree: FrameTree, body: BodyPlacement, options: dict, partial: tuple) -> str:
    """The frame a lone body is assembled in when its centre's link frame is not one it is constant
    in: of those frames, the one whose partial ω have the fewest components that are not numbers,
    where the body turns by its spin alone (a wheel hung from a board by its steering truck: the
    truck's frame; a rotor in a shell whose speeds are its body rates: the shell's, not the
    frame above it that its spin and the shell's last Euler angle share). An isotropic body is
    constant in every frame; it stays in its own, and its rotation is formed along the frame
    where its ω is simplest (gacli.mechanics.program.assemble.rotation_frame)."""
    if not partial or isotropic(body.inertia.tolist()):
        return body.frame
    return min(options, key=lambda f: (tree.varying(f, partial), f != body.frame, f))


def _positive(mass: sp.Expr) -> bool:
    return bool(mass.is_Number and mass > 0)


def _offsets(tree, links, members: list[BodyPlacement], frame: str, coordinates: set):
    """(anchor, each centre from it along ``frame``) when all are fixed there, else None."""
    chains = [ancestors(links, b.point) for b in members]
    anchor = next((a for a in chains[0] if all(a in other for other in chains[1:])), None)
    offsets = [offset_in(tree, links, anchor, b.point, frame, coordinates) for b in members]
    return None if any(o is None for o in offsets) else (anchor, offsets)


def _unit(tree: FrameTree, links: dict[str, PointLink], group: dict, coordinates: set, partial: tuple) -> Unit:
    members = group["members"]
    if len(members) == 1:
        body, options = members[0]
        if options is None:  # a particle: assembled along its own link's frame
            return Unit(((body, None),), body.point, links[body.point].frame, body.mass, (), ())
        # Only where its spins are about one axis: a wheel on a skewed mount (turned by constants from
        # the hub its centre is placed in) spins about no one axis of the hub, and of its mount's.
        usable = {f: pl for f, pl in options.items() if _about_one_axis(pl)}
        link = links[body.point].frame
        frame = link if link in usable else _spun(tree, body, usable, partial)
        return Unit(((body, options[frame]),), body.point, frame, body.mass, (), wheels_of(body, options[frame]))
    own = [links[b.point].frame for b, _ in members]
    frame = sorted(group["frames"], key=lambda f: (f not in own, f))[0]
    anchor, offsets = _offsets(tree, links, [b for b, _ in members], frame, coordinates)
    mass = sp.Add(*(b.mass for b, _ in members))
    centre = sum((b.mass * o for (b, _), o in zip(members, offsets)), sp.zeros(3, 1)) / mass
    name = "+".join(b.name for b, _ in members)
    links[name] = PointLink(name, anchor, frame, tree.tape.vec((sp.factor_terms(x) for x in centre),
                                                               name=("r", name, frame)))
    chosen = tuple((b, options[frame]) for b, options in members)
    wheels = tuple(w for b, pl in chosen for w in wheels_of(b, pl))
    return Unit(chosen, name, frame, mass, tuple(offsets), wheels)


def unit_inertia(tree: FrameTree, u: Unit) -> list[list[sp.Expr]]:
    """The unit's inertia about its centre along its frame, as program values (parameters only)."""
    tape = tree.tape
    parts = [_turned(tree, b, pl) for b, pl in u.members if pl is not None]
    total = [[sp.Add(*(p[i][j] for p in parts)) for j in range(3)] for i in range(3)]
    if len(u.members) == 2:  # two bodies: μ (|δ|² 1 − δ δᵀ), μ = m₁m₂/(m₁+m₂), δ between their centres
        (b1, _), (b2, _) = u.members
        mu = tape.let(b1.mass * b2.mass / u.mass)
        delta = tape.vec(tuple(u.offsets[0] - u.offsets[1]))
        for i in range(3):
            for j in range(3):
                total[i][j] += (mu * sp.Add(*(delta[k] ** 2 for k in range(3) if k != i)) if i == j
                                else -mu * delta[i] * delta[j])
    elif len(u.members) > 2:  # Σ m (|ρ|² 1 − ρ ρᵀ), ρ each centre from the composite's
        centre = sum((b.mass * o for (b, _), o in zip(u.members, u.offsets)), sp.zeros(3, 1)) / u.mass
        for (b, _), o in zip(u.members, u.offsets):
            rho = tape.vec(tuple(o - centre))
            for i in range(3):
                for j in range(3):
                    total[i][j] += b.mass * ((sum(x ** 2 for x in rho) if i == j else 0) - rho[i] * rho[j])
    return [[tape.let(x, name=("I", u.point, u.frame, *_axes(total, i, j))) for j, x in enumerate(row)]
            for i, row in enumerate(total)]


def _axes(total: list[list], i: int, j: int) -> tuple:
    """(i, j) of an entry's label; of a moment equal about several axes (a bar's [0, I, I]), those
    axes as (i, i) for each: the tape names one value once, and it is the moment about each of them."""
    if i != j:
        return i, j
    same = tuple(a for a in range(3) if total[a][a] == total[i][i])
    return (same, same) if len(same) > 1 else (i, j)


def _turned(tree: FrameTree, body: BodyPlacement, pl: Placement) -> list[list[sp.Expr]]:
    """The declared inertia turned one constant rotation at a time: I' = R I Rᵀ, R applied to the
    columns of I, then to the columns of the transpose."""
    tape = tree.tape
    inertia = [[tape.let(x) for x in row] for row in body.inertia.tolist()]
    for edge, up in pl.steps:
        cols = [tree.step(edge, tuple(inertia[i][j] for i in range(3)), up) for j in range(3)]  # R I
        rows = [tree.step(edge, tuple(cols[j][i] for j in range(3)), up) for i in range(3)]  # R (R I)ᵀ
        inertia = [[rows[j][i] for j in range(3)] for i in range(3)]
    return inertia
