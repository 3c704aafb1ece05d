"""Velocities and accelerations of points by passes, and the free root the rolling carries.

A point is a chain of links (gacli.frame_model.PointLink); its velocity for
a pass of rates ρ is its parent's plus ω × p plus the rate of p's own
components (transport theorem), along the frame of its last link; its
acceleration with all accelerations zero (the velocity-product part of
eq. 14.14) is a_parent + α₀ × p + ω × (ω × p) + 2 ω × ṗ + p̈₀. Components that hold time
add ∂p/∂t to the actual velocity (a timed pass) and their time terms to p̈₀.

A *free root* is a point at N's origin whose N components are dependent
coordinates, (x, y, 0) of a vehicle on the ground, above a rolling contact:
the contact's three rows solved for those coordinates are the root's
velocity, v_P0 = −(v_C − v_P0), so that x and y never enter the rows of
the other contacts, and ẋ, ẏ cost a few products.
"""

from __future__ import annotations

import sympy as sp

from gacli.frame_model import INERTIAL, PointLink
from gacli.mechanics.program import contacts as C
from gacli.mechanics.program.frames import FrameTree, time_rate
from gacli.mechanics.program.vectors import ZV, Pass, add, cross, scale


class Motion:
    """Points and contacts over a frame tree; a builder object whose caches write each vector once per pass."""

    def __init__(self, tree: FrameTree, links: dict[str, PointLink], coordinates: dict[str, sp.Symbol],
                 contacts: list[C.Contact], root: tuple[str, C.Contact] | None) -> None:
        self.tree, self.tape, self.coordinates = tree, tree.tape, coordinates
        self.contacts = contacts
        self.root, self.root_contact = root if root is not None else (None, None)
        moving = set(coordinates.values())
        # Each link that places a body from its contact point (a body placed by ``contact``), with its contact.
        self.lifts = {name: c for c in contacts if (name := C.lift(tree, links, c, moving, self.root)) is not None}
        self.links = {**links, **{name: self._lifted(links[name], c) for name, c in self.lifts.items()}}
        self._velocity: dict = {}
        self._acceleration: dict = {}
        self._odot: dict = {}
        self._reach: dict = {}

    @staticmethod
    def _lifted(link: PointLink, c: C.Contact) -> PointLink:
        """The lift as the contact's −o along S: its rates are then −ȯ (C.o_rate, ṅ = n × ω),
        not the chain rule through the coordinates the loader wrote it in (a disc's Euler parameters
        under a square root: its x, y rates cost 213 operations, Kane's 35)."""
        return PointLink(link.name, link.parent, c.frame, tuple(-x for x in c.o))

    def frame_of(self, point: str | None) -> str:
        """The frame a point's velocity is formed along: its last link's (the root's: its contact's S)."""
        if point is None:
            return INERTIAL
        if point == self.root:
            return self.root_contact.frame
        return self.links[point].frame

    def velocity(self, point: str | None, rates: Pass, frame: str | None = None, zero_root: bool = False) -> tuple:
        """v of the point for the pass, along ``frame`` (default: :meth:`frame_of`); ``zero_root``: the
        root held still (v_C − v_P0 of the root's contact)."""
        if point is None:
            return ZV
        key = (point, rates.key, zero_root)
        if key not in self._velocity:
            self._velocity[key] = self._link_velocity(point, rates, zero_root)
        v, f = self._velocity[key]
        return v if frame is None else self.tree.express(v, f, frame, key=("v",) + key)

    def _link_velocity(self, point: str, rates: Pass, zero_root: bool) -> tuple[tuple, str]:
        link = self.links[point]
        if point == self.root:
            c = self.root_contact
            if zero_root:
                return ZV, c.frame
            if self.lifts.get(c.point) is c:  # v_P with the root still, ω × (−o) − ȯ, left unnamed: ω × o cancels
                lifted = self.links[c.point]
                v_point = add(cross(self.tree.omega(c.frame, rates), lifted.components), self._moving(lifted, rates))
                return self.tape.vec(scale(-1, C.velocity(self.tree, c, v_point, rates))), c.frame
            return self.tape.vec(scale(-1, self.contact_velocity(c, rates, zero_root=True))), c.frame
        parent = self.velocity(link.parent, rates, link.frame, zero_root)
        v = add(parent, cross(self.tree.omega(link.frame, rates), link.components), self._moving(link, rates))
        return self.tape.vec(v, name=None if zero_root else ("v", point, rates.key, link.frame)), link.frame

    def home(self, point: str | None, rates: Pass) -> str | None:
        """The highest point of ``point``'s chain whose velocity for the pass is the point's own, turned:
        the links below it add nothing for these rates (a chain's far link, for the speed of a joint
        above it). Its velocity along its own frame is the partial velocity at its simplest."""
        while point is not None and point != self.root:
            link = self.links[point]
            own = add(cross(self.tree.omega(link.frame, rates), link.components), self._moving(link, rates))
            if link.parent is None or any(c != 0 for c in own):
                break
            point = link.parent
        return point

    def _moving(self, link: PointLink, rates: Pass) -> tuple:
        """ṗ: the rate of the link's own components, Σ ∂p/∂q ρ_q (+ ∂p/∂t for a timed pass)."""
        if link.name in self.lifts:
            return scale(-1, C.o_rate(self.tree, self.lifts[link.name], rates))
        return tuple(self._rate(x, rates) for x in link.components)

    def _rate(self, x: sp.Expr, rates: Pass) -> sp.Expr:
        moved = sp.Add(*(sp.diff(x, s) * rates.rate(q) for q, s in self.coordinates.items() if x.has(s)))
        return moved + time_rate(x, self.tree.time) if rates.timed else moved

    def acceleration0(self, point: str | None, actual: Pass, frame: str | None = None,
                      zero_root: bool = False, gamma: Pass | None = None) -> tuple:
        """a of the point with all accelerations zero, along ``frame``; with ``gamma``, the rest
        acceleration with u̇ = 0 (eq. 14.14), formed level by level as α's is (FrameTree.alpha0)."""
        if point is None:
            return ZV
        key = (point, zero_root, gamma is not None)
        if key not in self._acceleration:
            self._acceleration[key] = self._link_acceleration(point, actual, zero_root, gamma)
        a, f = self._acceleration[key]
        return a if frame is None else self.tree.express(a, f, frame, key=("a",) + key)

    def _link_acceleration(self, point: str, actual: Pass, zero_root: bool, gamma: Pass | None) -> tuple[tuple, str]:
        link = self.links[point]
        if point == self.root:
            c = self.root_contact
            if zero_root:
                return ZV, c.frame
            return self.tape.vec(scale(-1, self.contact_acceleration0(c, actual, True, gamma))), c.frame
        parent = self.acceleration0(link.parent, actual, link.frame, zero_root, gamma)
        w, al = self.tree.omega(link.frame, actual), self.tree.alpha0(link.frame, actual, gamma)
        p = link.components
        moving = self.tape.vec(self._moving(link, actual))
        inner = self.tape.vec(add(cross(w, p), scale(2, moving)))
        if link.name in self.lifts:  # −ö, whose α part is the rest α's, γ's share with it
            c = self.lifts[link.name]
            odd = C.o_acceleration(self.tree, c, actual, C.relative_alpha(self.tree, c, actual, al, gamma))
            name = None if zero_root else ("a", point, "rest" if gamma else actual.key, link.frame)
            return self.tape.vec(add(parent, cross(al, p), cross(w, inner), scale(-1, odd)), name=name), link.frame
        a = add(parent, cross(al, p), cross(w, inner), self._moving2(link, actual))
        if gamma is not None:
            a = add(a, self._moving(link, gamma))
        name = None if zero_root else ("a", point, actual.key if gamma is None else "rest", link.frame)
        return self.tape.vec(a, name=name), link.frame

    def _moving2(self, link: PointLink, actual: Pass) -> tuple:
        """p̈ with all accelerations zero: Σ ∂²p/∂q∂q' q̇ q̇' (and the terms of ∂/∂t, when timed)."""
        return tuple(self._rate(self._rate(x, actual), actual) for x in link.components)

    def contact_velocity(self, c: C.Contact, rates: Pass, zero_root: bool = False) -> tuple:
        """v of the body's material point at the contact relative to the plane's, v_C − v_Q, along S."""
        v = C.velocity(self.tree, c, self.velocity(c.point, rates, c.frame, zero_root), rates)
        if c.plane == INERTIAL:
            return v
        w = self.tree.express(self.tree.omega(c.plane, rates), c.plane, c.frame)
        v_q = add(self.velocity(c.origin, rates, c.frame), cross(w, self.reach(c)))
        return self.tape.vec(add(v, scale(-1, v_q)))

    def contact_acceleration0(self, c: C.Contact, actual: Pass, zero_root: bool = False,
                              gamma: Pass | None = None) -> tuple:
        """Its derivative with all accelerations zero (with ``gamma``: with u̇ = 0), along S: on a
        frame's plane, less a_O + α_P × ρ + ω_P × ρ̇, ρ̇ = v_P − v_O + ω_S × D + Ḋ."""
        if c.body.name not in self._odot:
            self._odot[c.body.name] = C.o_rate(self.tree, c, actual)
        odot = self._odot[c.body.name]
        a_point = self.acceleration0(c.point, actual, c.frame, zero_root, gamma)
        a = C.acceleration(self.tree, c, a_point, actual, odot, gamma)
        if c.plane == INERTIAL:
            return a
        tree = self.tree
        w = tree.express(tree.omega(c.plane, actual), c.plane, c.frame)
        al = tree.express(tree.alpha0(c.plane, actual, gamma), c.plane, c.frame)
        big_d, ddot = C.lever(tree, c, actual, odot)
        rho_dot = add(self.velocity(c.point, actual, c.frame), scale(-1, self.velocity(c.origin, actual, c.frame)),
                      cross(tree.omega(c.frame, actual), big_d), ddot)
        a_q = add(self.acceleration0(c.origin, actual, c.frame, False, gamma), cross(al, self.reach(c)),
                  cross(w, self.tape.vec(rho_dot)))
        return self.tape.vec(add(a, scale(-1, a_q)))

    def reach(self, c: C.Contact) -> tuple:
        """ρ, from the plane's origin to the contact, along S."""
        if c.body.name not in self._reach:
            self._reach[c.body.name] = self.tape.vec(add(self.position(c.point, c.frame),
                                                         scale(-1, self.position(c.origin, c.frame)),
                                                         C.reach_from_point(self.tree, c)))
        return self._reach[c.body.name]

    def position(self, point: str | None, frame: str) -> tuple:
        """The point's position from N's origin, along ``frame``."""
        if point is None:
            return ZV
        link = self.links[point]
        return self.tape.vec(add(self.position(link.parent, frame),
                                 self.tree.express(link.components, link.frame, frame)))
