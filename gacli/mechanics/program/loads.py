"""Forces and torques handed to the units, as the virtual work of eq. (14.13) needs them.

A force f at a point P of a unit (its centre G, or a point fixed in its
frame) does work V_P·δ = (V_G + Ω × r)·f with r = P − G, so it joins the
unit's resultant force and adds r × f to its moment: a unit needs no
partial velocity of P. Forces proportional to their bodies' masses along
one direction (gravity on a composite body) leave a moment that vanishes;
the numeric test drops it. A force at a point of no unit keeps its own
partial velocities. A torque acts on its body's unit, and on a wheel's spin
σ through its component along the axle.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from gacli.frame_model import INERTIAL, FrameVector, Load, PointLink
from gacli.mechanics.program.frames import FrameTree
from gacli.mechanics.program.units import Unit, ancestors, offset_in
from gacli.mechanics.program.vectors import ZV, add, cross, scale


@dataclass
class UnitLoads:
    """What acts on one unit: the forces' components summed per frame they are given in (one
    resultant at its centre: the weights of a composite body are one product), the moment about
    the centre and each torque with the body it acts on (for a wheel's spin), along the unit's
    frame. Filled load by load."""

    forces: dict[str, tuple] = field(default_factory=dict)
    moment: tuple = ZV
    torques: list[tuple[str, tuple]] = field(default_factory=list)

    def resultant(self, tree: FrameTree, frame: str) -> tuple:
        return along(tree, FrameVector(tuple(self.forces.items())), frame, {})


def along(tree: FrameTree, vector: FrameVector, frame: str, rates: dict) -> tuple:
    """A load's components along ``frame``: a vertical force in N is written along N.z as the frame sees it;
    a dependent rate in it is replaced by its value on the tape (eq. 14.7)."""
    total = ZV
    for source, components in vector.terms:
        v = tree.tape.vec(c.xreplace(rates) for c in components)
        if source == INERTIAL and v[0] == 0 and v[1] == 0:
            total = add(total, scale(v[2], tree.nz(frame)))
        else:
            total = add(total, tree.express(v, source, frame))
    return total


def distribute(tree: FrameTree, links: dict[str, PointLink], units: list[Unit], loads: tuple[Load, ...],
               rates: dict, coordinates: set, lines: tuple[Load, ...] = ()
               ) -> tuple[list[UnitLoads], list[tuple[str, tuple, str]]]:
    """Each unit's loads, and the forces at points of no unit [(point, components, the frame they are
    along)]. The forces of ``lines`` (one frame each) stay at their points unless at a unit's centre:
    their work is f·V_P, as Kane takes it, where the resultant and moment read f twice, (V_G + Ω × r)·f
    (a spring at a rocker's tip: l f_y/2 each time)."""
    shares = [UnitLoads() for _ in units]
    loose = []
    for load in (_spelled_out(load, links) for load in loads):
        if load.torque:
            i = next(i for i, u in enumerate(units) if u.holds(load.body))
            shares[i].torques.append((load.body, along(tree, load.vector, units[i].frame, rates)))
            continue
        i, lever = _carrier(tree, links, units, load.point, coordinates)
        if i is None:
            frame = links[load.point].frame if load.point in links else INERTIAL
            loose.append((load.point, along(tree, load.vector, frame, rates), frame))
            continue
        for source, components in load.vector.terms:
            components = tuple(c.xreplace(rates) for c in components)
            shares[i].forces[source] = add(shares[i].forces.get(source, ZV), components)
        if lever is not None:
            f = along(tree, load.vector, units[i].frame, rates)
            shares[i].moment = add(shares[i].moment, cross(tuple(lever), f))
    for load in lines:
        (frame, f), = load.vector.terms
        i, lever = _carrier(tree, links, units, load.point, coordinates)
        if i is not None and lever is None:
            shares[i].forces[frame] = add(shares[i].forces.get(frame, ZV), f)
        else:
            loose.append((load.point, f, frame))
    return shares, loose


def _spelled_out(load: Load, links: dict[str, PointLink]) -> Load:
    """A load written with ``from`` (or as a point's name): that point's position is the sum of its
    chain's offsets, each along its own frame, so its terms join the load's."""
    if load.vector.origin is None:
        return load
    terms, point = list(load.vector.terms), load.vector.origin
    while point is not None:
        terms.append((links[point].frame, links[point].components))
        point = links[point].parent
    return replace(load, vector=FrameVector(tuple(terms)))


def _carrier(tree, links, units: list[Unit], point: str, coordinates: set):
    """(the unit a force at ``point`` joins, the lever from its centre or None), or (None, None):
    the unit of a body centred there first, then any rigid unit the point is fixed in."""
    order = sorted(range(len(units)), key=lambda i: not any(b.point == point for b, _ in units[i].members))
    for i in order:
        if units[i].point == point:
            return i, None
        lever = _lever(tree, links, units[i], point, coordinates) if units[i].rigid else None
        if lever is not None:
            return i, lever
    return None, None


def _lever(tree, links, u: Unit, point: str, coordinates: set):
    """P − G along the unit's frame, when fixed there."""
    mine = ancestors(links, u.point)
    anchor = next((a for a in ancestors(links, point) if a in mine), None)
    a = offset_in(tree, links, anchor, point, u.frame, coordinates)
    b = offset_in(tree, links, anchor, u.point, u.frame, coordinates)
    return None if a is None or b is None else a - b
