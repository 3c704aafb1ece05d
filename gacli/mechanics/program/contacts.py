"""Rolling contacts on a plane: where the body touches, and the velocity of its material point there.

A wheel (axle a along a frame axis) touches at o = −r (n − (n·a)a)/|n − (n·a)a|
from its geometric centre, n = N.z, the wheel above the plane (as
gacli.loader.frames.contact_point); a torus a further −ρ n; a sphere at
o = −r n; an ellipsoid at o = −E n/√(nᵀ E n) along its own axes (its S is
the body's frame, gacli.loader.rolling_geometry.ellipsoid_contact). Everything is
formed in the wheel's *non-spinning frame* S: the highest frame reached
from the body's by rotations about the axle, where o depends on the
lean only. The material point at the contact moves with

    v_C = v_P + ω_S × (d + c + o) + s a × (c + o),

P the point the centre hangs from (d its offset along S), c the geometric
centre's offset from the centre of mass (turned into S) and s the spin
rate about the axle. Rolling without slipping on N's ground is v_C = 0
(eq. 14.1). On the plane z = 0 of a frame P (a turntable, a tilted or
moving plane), n is P's z axis, o turns with S relative to P, and the rows
are v_C − v_Q = 0, v_Q = v_O + ω_P × ρ the velocity of P's material point
at the contact (O P's origin, ρ from O to the contact; gacli.mechanics.program.motion).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.frame_model import INERTIAL, BodyPlacement, RollingContact
from gacli.mechanics.program.frames import FrameTree
from gacli.mechanics.program.vectors import ZERO, ZV, Pass, add, cross, dot, scale, unit


@dataclass(frozen=True)
class Contact:
    """A rolling contact's frames, points and geometry in its non-spinning frame ``frame`` (S)."""

    body: BodyPlacement
    radius: sp.Expr
    frame: str
    axis: int | None  # the axle's axis of S; None for a sphere
    spin_edges: tuple[str, ...]  # the edges between the body's frame and S (a wheel's: all about the axle)
    point: str | None  # P
    offset: tuple  # d, along S
    centre: tuple  # c along the body's axes
    o: tuple  # the contact from the geometric centre, along S
    perp: tuple | None  # n − (n·a)a along S where it is not a constant direction (an ellipsoid's: E n)
    inverse: sp.Expr | None  # 1/|n − (n·a)a| (an ellipsoid's: 1/√(nᵀ E n))
    tube: sp.Expr = sp.S.Zero  # a torus's: o is a wheel's − ρ n
    semi_axes: tuple | None = None  # an ellipsoid's (S is the body's frame)
    plane: str = INERTIAL  # the frame whose plane z = 0 the body rolls on
    origin: str | None = None  # the point at that frame's origin (None: N's)


def contact(tree: FrameTree, links: dict, body: BodyPlacement, rolling: RollingContact,
            coordinates: set, origins: dict[str, str], above: bool = False) -> Contact:
    """The contact of ``rolling``, its geometry written on the tree's tape; ``origins``: the point at
    a frame's origin, for the frames given one (a frame without one shares its parent's).

    ``above``: a sphere's S is the nearest frame above both its own and the plane's (the plane's
    own frame when it is an ancestor), reached from the sphere through rotations about frame
    axes: its rows are then along that frame, where a centre at (x, y, r) moves along the
    coordinates' own axes, and its ω is summed there from the angles' rates (FrameTree.over)."""
    frame, spins, axis = body.frame, [], None
    plane = rolling.on or INERTIAL
    if rolling.axle is not None:
        axis = next(i for i, c in enumerate(rolling.axle) if c != 0)
        while frame != INERTIAL and tree.edges[frame].axis == axis:
            spins.append(frame)
            frame = tree.edges[frame].parent
    elif above and rolling.semi_axes is None and (edges := tree.above(frame, tree.common(frame, plane))):
        spins, frame = edges, tree.common(frame, plane)
    link = links[body.point]
    fixed = not any(c.free_symbols & coordinates for c in link.components)
    centre = rolling.centre.terms[0][1] if rolling.centre.terms else ZV
    if link.frame == frame and fixed:
        point, offset = link.parent, link.components
    elif link.frame == body.frame and fixed and link.parent is not None:
        # A mass centre placed from the geometric centre along the body's own axes (a ball's e
        # below it): both offsets turn with the body, so they are one, and a ball's c = −link
        # leaves the contact read from the centre, where nothing of e is formed to cancel.
        point, offset, centre = link.parent, ZV, tuple(sp.Add(a, b) for a, b in zip(link.components, centre))
    else:
        point, offset = body.point, ZV
    n = normal(tree, frame, plane)
    if rolling.semi_axes is not None:
        o, perp, inverse = _ellipsoid_below(tree, n, rolling.semi_axes)
    else:
        o, perp, inverse = _below(tree, n, axis, rolling.radius)
        if rolling.tube != 0:
            o = tree.tape.vec(add(o, scale(-rolling.tube, n)))
    origin = next((origins[f] for f in tree.chain(plane) if f in origins), None)
    return Contact(body, rolling.radius, frame, axis, tuple(spins), point, tuple(offset), tuple(centre),
                   o, perp, inverse, rolling.tube, rolling.semi_axes, plane, origin)


def normal(tree: FrameTree, frame: str, plane: str) -> tuple:
    """The plane's normal (its frame's z axis) along ``frame``."""
    if plane == INERTIAL:
        return tree.nz(frame)
    return tree.express((ZERO, ZERO, sp.S.One), plane, frame, key=("normal", plane))


def relative_omega(tree: FrameTree, c: Contact, rates: Pass) -> tuple:
    """ω of S relative to the plane's frame, along S: the turning the contact's geometry sees."""
    w = tree.omega(c.frame, rates)
    if c.plane == INERTIAL:
        return w
    return tree.tape.vec(add(w, scale(-1, tree.express(tree.omega(c.plane, rates), c.plane, c.frame))))


def _ellipsoid_below(tree: FrameTree, n: tuple, semi_axes: tuple):
    """(o, E n, 1/√(nᵀ E n)) along the body's axes, E = diag(a², b², c²): o = −E n/√(nᵀ E n)."""
    en = tree.tape.vec([s ** 2 * x for s, x in zip(semi_axes, n)])
    inverse = tree.tape.let(1 / sp.sqrt(dot(en, n)))
    return tree.tape.vec(scale(-inverse, en)), en, inverse


def _below(tree: FrameTree, n: tuple, axis: int | None, radius: sp.Expr):
    """(o, n − (n·a)a, 1/|n − (n·a)a|) along S; a constant direction needs no root."""
    if axis is None:
        return tree.tape.vec(scale(-radius, n)), None, None
    perp = tuple(ZERO if i == axis else n[i] for i in range(3))
    live = [i for i in range(3) if perp[i] != 0]
    if len(live) == 1:  # the wheel's plane holds the normal: o = −r e, e = ±S's axis along the normal
        # (its sign the entry's: a z-down ground, N turned by π, has n = −N.z, the wheel above it at −z)
        r = radius if tree.tape.closed(perp[live[0]]).could_extract_minus_sign() else -radius
        return tuple(r if i == live[0] else ZERO for i in range(3)), None, None
    inverse = tree.tape.let(1 / sp.sqrt(sp.Add(*(x ** 2 for x in perp))))
    return tree.tape.vec([-radius * x * inverse for x in perp]), perp, inverse


def spin(tree: FrameTree, c: Contact, rates: Pass) -> sp.Expr:
    return sp.Add(*(tree.rate(e, rates) for e in c.spin_edges))


def turning(tree: FrameTree, c: Contact, rates: Pass) -> tuple:
    """ω of the body relative to S, along S: a wheel's spin s a, a sphere's ω when S is its plane's frame."""
    if c.axis is not None:
        return scale(spin(tree, c, rates), unit(c.axis))
    return tree.over(c.body.frame, c.frame, rates) if c.spin_edges else ZV


def centre_in_s(tree: FrameTree, c: Contact) -> tuple:
    """The centre's offset c along S (it turns with the spin)."""
    if c.centre == ZV:
        return ZV
    return tree.express(c.centre, c.body.frame, c.frame, key=("centre", c.body.name))


def o_rate(tree: FrameTree, c: Contact, actual: Pass) -> tuple:
    """The rate of o's components along S: the normal is fixed in the plane's frame, so its
    components turn as ṅ = n × ω, ω of S relative to that frame."""
    tape, n = tree.tape, normal(tree, c.frame, c.plane)
    w = relative_omega(tree, c, actual)
    if c.semi_axes is not None:
        # o = −E n h⁻¹, h² = nᵀ E n: ȯ = h⁻³ (nᵀ E ṅ) E n − h⁻¹ E ṅ.
        edot = tape.vec([s ** 2 * x for s, x in zip(c.semi_axes, cross(n, w))])
        along = tape.let(c.inverse ** 3 * dot(n, edot))
        return tape.vec([along * e - c.inverse * d for e, d in zip(c.perp, edot)])
    if c.tube != 0:
        wheel = _wheel_o_rate(tree, c, n, w)
        return tape.vec(add(wheel, scale(-c.tube, cross(n, w))))
    return _wheel_o_rate(tree, c, n, w)


def _wheel_o_rate(tree: FrameTree, c: Contact, n: tuple, w: tuple) -> tuple:
    """The sphere's or thin wheel's part of :func:`o_rate` (n the normal, w the relative ω)."""
    tape = tree.tape
    if c.axis is None:
        return tape.vec(scale(-c.radius, cross(n, w)))
    if c.perp is None:
        return ZV
    ndot = tape.vec(cross(n, w))
    ndot = [ZERO if i == c.axis else ndot[i] for i in range(3)]
    dinv = tape.let(-c.inverse ** 3 * dot(c.perp, ndot))
    return tape.vec([-c.radius * (nd * c.inverse + x * dinv) for x, nd in zip(c.perp, ndot)])


def lift(tree: FrameTree, links: dict, c: Contact, coordinates: set, root: str | None) -> str | None:
    """The link that places ``c``'s body from its contact point (a body placed by ``contact``): on the
    chain above the contact's P, written with the coordinates, and −o at the tape's generic points.
    Not an ellipsoid's, whose ö :func:`o_acceleration` does not form."""
    if c.semi_axes is not None or c.point is None:
        return None
    point = c.point
    while point is not None and point != root and point in links:
        link = links[point]
        if any(x.free_symbols & coordinates for x in link.components):
            o = tree.express(c.o, c.frame, link.frame)
            if all(tree.tape.vanishes(x + y) for x, y in zip(link.components, o)):
                return point
        point = link.parent
    return None


def relative_alpha(tree: FrameTree, c: Contact, actual: Pass, alpha: tuple, gamma: Pass | None) -> tuple:
    """The rate of the components along S of ω relative to the plane's frame P, α_S − α_P + ω_S × ω_P
    (``alpha``: S's rest α)."""
    if c.plane == INERTIAL:
        return alpha
    w_p = tree.express(tree.omega(c.plane, actual), c.plane, c.frame)
    a_p = tree.express(tree.alpha0(c.plane, actual, gamma), c.plane, c.frame)
    return tree.tape.vec(add(alpha, scale(-1, a_p), cross(tree.omega(c.frame, actual), w_p)))


def o_acceleration(tree: FrameTree, c: Contact, actual: Pass, alpha: tuple) -> tuple:
    """ö along S with the speeds' rates held (``alpha``: :func:`relative_alpha`): n̈ = ṅ × ω + n × α,
    ω relative to the plane, and o of n as in :func:`o_rate`; for a wheel, d²/dt² of 1/|n − (n·a)a|
    by the chain rule."""
    tape, n = tree.tape, normal(tree, c.frame, c.plane)
    w = relative_omega(tree, c, actual)
    ndot = tape.vec(cross(n, w))
    nddot = tape.vec(add(cross(ndot, w), cross(n, alpha)))
    if c.axis is None:
        return tape.vec(scale(-c.radius, nddot))
    tube = scale(-c.tube, nddot)  # a torus's o is a wheel's − ρ n
    if c.perp is None:  # the wheel's plane holds the normal: the wheel's o = −r e, constant along S
        return tape.vec(tube)
    pd = [ZERO if i == c.axis else ndot[i] for i in range(3)]
    pdd = [ZERO if i == c.axis else nddot[i] for i in range(3)]
    s = tape.let(dot(c.perp, pd))
    dinv = tape.let(-c.inverse ** 3 * s)
    ddinv = tape.let(-3 * c.inverse ** 2 * dinv * s - c.inverse ** 3 * (dot(pd, pd) + dot(c.perp, pdd)))
    wheel = [-c.radius * (c.inverse * a + 2 * dinv * b + ddinv * x) for a, b, x in zip(pdd, pd, c.perp)]
    return tape.vec(add(wheel, tube))


def velocity(tree: FrameTree, c: Contact, v_point: tuple, rates: Pass) -> tuple:
    """v_C along S for the pass: v_P + ω_S × (d + c + o) + ω_r × (c + o), ω_r = :func:`turning`."""
    cs = centre_in_s(tree, c)
    out = add(v_point, cross(tree.omega(c.frame, rates), add(c.offset, cs, c.o)))
    if c.axis is not None:
        s = spin(tree, c, rates)
        return add(out, scale(s, cross(unit(c.axis), add(cs, c.o)))) if s != 0 else out
    return add(out, cross(turning(tree, c, rates), add(cs, c.o))) if c.spin_edges else out


def acceleration(tree: FrameTree, c: Contact, a_point: tuple, actual: Pass, odot: tuple,
                 gamma: Pass | None = None) -> tuple:
    """d/dt of v_C with all accelerations zero (the rows' velocity-product term), along S:
    a_P + α × D + ω × (Ḋ + ω × D) + ω_r × Ḋ + ω × (ω_r × (c + o)) + α_r × (c + o), D = d + c + o,
    Ḋ = ω_r × c + ȯ, ω_r = s a for a wheel; with ``gamma`` (u̇ = 0), α, α_r and a_P are the rests."""
    cs = centre_in_s(tree, c)
    w, al = tree.omega(c.frame, actual), tree.alpha0(c.frame, actual, gamma)
    rel = turning(tree, c, actual)
    big_d, ddot = reach_from_point(tree, c), _lever_rate(tree, c, rel, odot)
    out = add(a_point, cross(al, big_d), cross(w, tree.tape.vec(add(ddot, cross(w, big_d)))))
    if any(x != 0 for x in rel):
        out = add(out, cross(rel, ddot), cross(w, cross(rel, add(cs, c.o))))
    if c.spin_edges:
        out = add(out, cross(tree.alpha_over(c.body.frame, c.frame, actual, gamma), add(cs, c.o)))
    return out


def lever(tree: FrameTree, c: Contact, actual: Pass, odot: tuple) -> tuple[tuple, tuple]:
    """D = d + c + o, from P to the contact along S, and the rate of its components, Ḋ = ω_r × c + ȯ."""
    return reach_from_point(tree, c), _lever_rate(tree, c, turning(tree, c, actual), odot)


def _lever_rate(tree: FrameTree, c: Contact, rel: tuple, odot: tuple) -> tuple:
    """Ḋ = ω_r × c + ȯ, ω_r the body's turning relative to S (:func:`turning`)."""
    cs = centre_in_s(tree, c)
    ddot = add(cross(rel, cs), odot) if any(x != 0 for x in rel) and cs != ZV else odot
    return tree.tape.vec(ddot)


def reach_from_point(tree: FrameTree, c: Contact) -> tuple:
    """D = d + c + o, from P to the contact along S."""
    return add(c.offset, centre_in_s(tree, c), c.o)


def row_vectors(tree: FrameTree, c: Contact) -> list[tuple]:
    """The directions v_C = 0 is taken along, in S: for a wheel forward (a × o), along the axle and
    vertical (N.z): the spin moves the contact forward only, a turn about N.z horizontally only,
    so the rows are as sparse as the geometry allows. A sphere's (an ellipsoid's) along S's axes where
    S's z axis is the plane's normal, else along the plane's axes, its normal last: along the plane the
    centre's rates have pivots 1 (or a turntable's cos, sin), where along S's own axes the two rows
    kept for them divide by S's z·n, zero whenever S's z axis lies in the plane (a ball in a
    quaternion frame on a turntable: 1/(e0² − e1² − e2² + e3²))."""
    n = normal(tree, c.frame, c.plane)
    if c.axis is not None:
        return [tree.tape.vec(cross(unit(c.axis), c.o)), unit(c.axis), n]
    if tuple(n) == (0, 0, 1):  # S turns about n alone: its axes do
        return [unit(0), unit(1), unit(2)]
    return [tree.express(unit(i), c.plane, c.frame, key=("plane axis", c.plane, i)) for i in (0, 1)] + [n]
