"""A point of a file without frames along the heading its rows were solved along.

Where the stated rows turn with an angle θ on the rates of a pair (x, y)
(gacli.mechanics.program.solve.turned_columns: a vehicle's cos θ ẋ +
sin θ ẏ − w θ̇ = r φ̇), each pass holds that pair's rates turned back by θ
(Pass.along), the velocity along the heading. A point at p = (x + f, y + g, h)
is then formed along the heading too, its components turned back by θ:

    V_r = Σ_q ρ_r(q) R(−θ) ∂p/∂q + (ρ_r along x, ρ_r along y, 0)     (q ≠ x, y)
    a_rest = Σ_q γ_q R(−θ) ∂p/∂q + (γ along x, γ along y, 0) + R(−θ) Σ_q,l ∂²p/∂q∂l q̇ l̇

each R(−θ) ∂p/∂q reduced in closed form: a hitch at (x + d cos θ, y + d sin θ)
has (0, d, 0) for θ, where its N components carry d sin θ and d cos θ into
every product with the pair's rates, which multiplied out never cancel. M's
m V_r·V_s is the same along any axes; a force given along N is turned back
as the point was (eq. 14.13).
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra import angles
from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.algebra.fastdiff import jacobian_rows
from gacli.mechanics.program.forms import closed_time_derivative
from gacli.mechanics.program.vectors import ZERO, add, scale, turned

_X, _Y = (sp.S.One, ZERO, ZERO), (ZERO, sp.S.One, ZERO)


def takes(motion, position: tuple) -> bool:
    """Whether the point is x + f, y + g, h of the heading's pair, with no time in it."""
    heading = motion.passes.heading
    if heading is None:
        return False
    timed = set(S.time_chain(f.name for f in motion.system.free_functions)) | {S.T}
    if any(as_expr(x).free_symbols & timed for x in position):
        return False
    x, y = (S.value(q) for q in heading[:2])
    J = jacobian_rows(list(position), [x, y])
    return tuple(J[i][0] for i in range(3)) == _X and tuple(J[i][1] for i in range(3)) == _Y


def turned_back(v, angle: sp.Symbol) -> tuple:
    """v's components along axes turned by ``angle`` about z, as closed forms (unreduced)."""
    return turned(v, 2, sp.cos(angle), -sp.sin(angle))


def point(motion, position: tuple) -> tuple[list[tuple], tuple]:
    """(V_r for each speed, a_rest) along the heading (see the module)."""
    tape, passes = motion.tape, motion.passes
    pair, angle = passes.heading[:2], passes.heading[2]
    others = [q for q in motion.coordinates if q not in pair]
    J = jacobian_rows(list(position), [S.value(q) for q in others])
    columns = {q: tape.vec(angles.reduced(e) for e in turned_back([J[i][j] for i in range(3)], angle))
               for j, q in enumerate(others) if any(J[i][j] != 0 for i in range(3))}

    def along(p) -> tuple:
        own = (p.rate_along(pair[0]), p.rate_along(pair[1]), ZERO)
        return tape.vec(add(own, *(scale(p.rate(q), v) for q, v in columns.items() if p.rate(q) != 0)))

    derivative, rates = closed_time_derivative(motion.system)
    change = [sp.Add(*(derivative(J[i][j]) * S.rate(q) for j, q in enumerate(others))) for i in range(3)]
    actual = {S.rate(q): passes.actual.rate(q) for q in motion.coordinates}
    change = [tape.let(angles.reduced_by(e, rates).xreplace(actual)) for e in turned_back(change, angle)]
    return [along(p) for p in passes.partial], tape.vec(add(along(passes.gamma), change))


def force(motion, f: tuple) -> tuple:
    """A force given along N, along the heading (its components are program values)."""
    c, s = (motion.tape.let(g(motion.passes.heading[2])) for g in (sp.cos, sp.sin))
    return motion.tape.vec(turned(f, 2, c, -s))
