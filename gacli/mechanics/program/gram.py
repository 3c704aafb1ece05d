"""A point of a file without frames through the dot products of its position's partial derivatives.

With J_q = ∂p/∂q for the coordinates q the position p(q) holds, the partial
velocities are V_r = Σ_q ρ_r(q) J_q (eq. 14.8) and the acceleration's rest
a_rest = Σ_q γ_q J_q + Σ_q,l (∂J_q/∂q_l) ṙ_l ṙ_q (eq. 14.14). The body's
share of M and F (eq. 14.19) and a force's virtual work (eq. 14.13) then
need only the dot products

    G_ql = J_q·J_l,   c_q = J_q·Σ_l,m (∂J_l/∂q_m) ṙ_m ṙ_l,   J_q·f,

formed in closed form and reduced (gacli.algebra.angles.reduced): a crank's
|J|² is l², where its N components square to l² sin² θ + l² cos² θ; a
coupler's J₁·J₂ is l₁ l₂ cos(θ₁ − θ₂), as Kane's vectors give it; the
crank's centripetal term c drops out. The components route
(gacli.mechanics.program.formbodies) stays the choice where the position
holds many coordinates (G has one entry per pair): build.program_of builds
both and keeps the cheaper.
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra import angles
from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.algebra.fastdiff import jacobian_rows
from gacli.mechanics.program.assemble import Sums
from gacli.mechanics.program.forms import closed_time_derivative

# Coordinates a position may hold for its dot products to be taken: G has one entry per pair.
GRAM_COORDINATES = 4


class Gram:
    """The dot products of one position's partial derivatives, each on the tape once."""

    def __init__(self, motion, position) -> None:
        self.motion, self.tape = motion, motion.tape
        position = [as_expr(x) for x in position]
        symbols = [S.value(q) for q in motion.coordinates]
        J = jacobian_rows(position, symbols)
        self.held = [q for j, q in enumerate(motion.coordinates) if any(J[i][j] != 0 for i in range(3))]
        self.J = {q: [J[i][motion.coordinates.index(q)] for i in range(3)] for q in self.held}
        self._G: dict[tuple[str, str], sp.Expr] = {}

    @staticmethod
    def takes(motion, position) -> bool:
        """Whether the position holds at most GRAM_COORDINATES coordinates, and neither t nor a
        function of time (whose derivatives the rest above leaves out)."""
        held = set().union(*(as_expr(x).free_symbols for x in position))
        timed = set(S.time_chain(f.name for f in motion.system.free_functions))
        coordinates = {S.value(q) for q in motion.coordinates}
        return not held & timed and len(held & coordinates) <= GRAM_COORDINATES

    def G(self, q: str, l: str) -> sp.Expr:
        key = (q, l) if self.held.index(q) <= self.held.index(l) else (l, q)
        if key not in self._G:
            a, b = self.J[key[0]], self.J[key[1]]
            self._G[key] = self.tape.let(angles.reduced(sum((x * y for x, y in zip(a, b)), sp.S.Zero)))
        return self._G[key]

    def along(self, vector) -> dict[str, sp.Expr]:
        """J_q·v for each coordinate held, reduced (v's components are program values)."""
        return {q: self.tape.let(angles.reduced(sum((x * y for x, y in zip(self.J[q], vector)), sp.S.Zero)))
                for q in self.held}

    def rest(self) -> dict[str, sp.Expr]:
        """J_q·a_rest for each coordinate held: Σ_l G_ql γ_l + c_q (see the module)."""
        motion, tape = self.motion, self.tape
        derivative, rates = closed_time_derivative(motion.system)
        change = [sp.Add(*(derivative(self.J[l][i]) * S.rate(l) for l in self.held)) for i in range(3)]
        actual = {S.rate(q): motion.passes.actual.rate(q) for q in motion.coordinates}
        gamma = motion.passes.gamma
        out = {}
        for q in self.held:
            c = angles.reduced_by(sum((x * y for x, y in zip(self.J[q], change)), sp.S.Zero), rates)
            out[q] = tape.let(sp.Add(c.xreplace(actual), *(self.G(q, l) * gamma.rate(l) for l in self.held
                                                          if gamma.rate(l) != 0)))
        return out


def add_translation(motion, mass, position, sums: Sums) -> None:
    """The body's m V_r·V_s and −m V_r·a_rest (see the module)."""
    gram, tape, passes = Gram(motion, position), motion.tape, motion.passes.partial
    k = len(passes)
    for r in range(k):
        for s in range(r, k):
            terms = [passes[r].rate(q) * passes[s].rate(l) * gram.G(q, l) for q in gram.held for l in gram.held
                     if passes[r].rate(q) != 0 and passes[s].rate(l) != 0]
            sums.M[r][s].append(mass * tape.let(sp.Add(*terms)))
    rest = gram.rest()
    for r, p in enumerate(passes):
        inertial = sp.Add(*(p.rate(q) * rest[q] for q in gram.held if p.rate(q) != 0))
        if not tape.vanishes(inertial):
            sums.F[r].append(-mass * tape.let(inertial))


def add_work(motion, position, force, sums: Sums) -> None:
    """A force's f·V_r = Σ_q ρ_r(q) J_q·f (eq. 14.13)."""
    along, tape = Gram(motion, position).along(force), motion.tape
    for r, p in enumerate(motion.passes.partial):
        sums.load(r, tape.let(sp.Add(*(p.rate(q) * x for q, x in along.items() if p.rate(q) != 0))))
