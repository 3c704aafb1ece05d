"""First integrals: the energy, the momenta the constraints allow, and a user's candidates.

A function G(q, u) is an integral when its rate along the equations,

.. code:: text

    Ġ = ∇_q G · q̇ + ∇_u G · u̇,   q̇ = β u + β₀ (eq. 14.20),  M u̇ = F (eq. 14.19)

vanishes identically. Multiplied by det M it is free of fractions:
det(M) ∇_q G · q̇ + ∇_u Gᵀ adj(M) F; that is decided zero by
:func:`gacli.numeric.zero.decide_zero`, by SymPy's simplify when small
("symbolic") and otherwise at seeded random points ("numeric"), and each
integral says which.

The energy T + V is offered when nothing works on the system (the
conditions of :func:`gacli.simulate.energy.conservation_problems`). For each
ignorable coordinate c the momentum offered is ∂T/∂q̇_c: with T written in
the coordinates' rates when there are no constraints (u = β⁻¹ q̇, so the
top's p_φ is A sin²θ φ̇ + C ω₃ cos θ and not ∂T/∂φ̇ at fixed ω₃), and
∂T/∂u_c otherwise. Every one is claimed only after its rate is found zero;
where it is not, the result says the constraints break it (the sleigh's
heading, the rolling disk's yaw). A coordinate whose rate the constraints
fix (x, y of a rolling body) has no momentum of its own.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.mechanics.equations import Derivation

# Beyond this many operations the expansion costs more than the seeded points' verdict is worth.
_EXPAND_MAX_OPS = 1500
_EXPAND_SECONDS = 1.5


@dataclass(frozen=True)
class Integral:
    """G and how its rate along the equations was found zero (or not)."""

    name: str
    expression: sp.Expr
    conserved: bool | None
    method: str          # "symbolic", "numeric" or "undecided"


@dataclass(frozen=True)
class Integrals:
    """What a system provably keeps, what it does not, and the candidates checked."""

    found: tuple[Integral, ...]
    broken: tuple[tuple[str, str], ...]          # (what, why it is not an integral)
    candidates: tuple[Integral, ...]


def integrals(derivation: Derivation, candidates: Sequence[sp.Expr] = (), search: bool = True) -> Integrals:
    """The energy and the momenta that hold, the statements where they do not, and the candidates
    (only the candidates with ``search=False``)."""
    from gacli.simulate.energy import MOVING_SUPPORT, conservation_problems, energy_expressions
    from gacli.steady import require_small

    require_small(derivation, "integrals")
    found, broken = [], []
    checked = tuple(Integral(f"candidate {i + 1}", *_checked(derivation, c, tidy=False)) for i, c in enumerate(candidates))
    if not search:
        return Integrals((), (), checked)
    problems = conservation_problems(derivation)
    T, V = energy_expressions(derivation)
    if not problems:
        _sort(Integral("energy T + V", *_checked(derivation, T + V)), found, broken)
    elif problems == [MOVING_SUPPORT]:  # the only work a moving support's: Jacobi's integral
        broken.append(("energy", "work is done on the system: " + problems[0]))
        _sort(Integral("Jacobi's integral T2 - T0 + V", *_checked(derivation, _jacobi(derivation, T, V))),
              found, broken, "the support's motion is not steady: its rate along the equations is not zero")
    else:
        broken.append(("energy", "work is done on the system: " + "; ".join(problems)))
    for name, momentum, why in _momenta(derivation):
        if momentum is None:
            broken.append((f"momentum of {name}", why))
        else:
            _sort(Integral(f"momentum of {name}", *_checked(derivation, momentum)), found, broken,
                  f"{_breakers(derivation)} break it: its rate along the equations is not zero")
    return Integrals(tuple(found), tuple(broken), checked)


def _breakers(derivation: Derivation) -> str:
    """What can make a momentum's rate nonzero: loads and the potential always, constraints if any
    (a particle's p_y under gravity was said to be broken by constraints it did not have)."""
    return "the constraints or the loads" if derivation.system.constraints else "the loads or the potential"


def _jacobi(derivation: Derivation, T: sp.Expr, V: sp.Expr) -> sp.Expr:
    """T₂ − T₀ + V, with T = T₂ + T₁ + T₀ split by degree in the independent rates."""
    scale = sp.Dummy("scale")
    parts = sp.Poly(sp.expand(T.xreplace({u: scale * u for u in derivation.speeds})), scale)
    return parts.coeff_monomial(scale**2) - parts.coeff_monomial(1) + V


def _sort(integral: Integral, found: list, broken: list, why: str = "its rate along the equations is not zero"):
    if integral.conserved:
        found.append(integral)
    else:
        broken.append((integral.name, why if integral.conserved is False else "undecided at every point tried"))


def _checked(derivation: Derivation, G: sp.Expr, tidy: bool = True) -> tuple[sp.Expr, bool | None, str]:
    from gacli.numeric.zero import decide_zero

    G = _readable(G) if tidy else G
    rate = rate_along(derivation, G)
    if _expands_to_zero(rate):
        return G, True, "symbolic"
    decision = decide_zero(rate, place=_on_the_motion(derivation))
    return G, decision.zero, decision.method


def _on_the_motion(derivation: Derivation):
    """Points moved onto the spheres the motion keeps to (Euler parameters' e·e = 1), or None: a
    candidate conserved there only was judged at points off it, and called broken."""
    from gacli.numeric.spheres import scaled_onto, spheres

    kept = spheres(derivation.system)
    if not kept:
        return None

    def place(point: dict) -> dict:
        point = dict(point)
        for sphere in kept:  # a sphere's coordinates the rate does not hold still count in its norm
            for i, y in enumerate(sphere.symbols):
                point.setdefault(y, 0.4 + 0.1 * i)
        return scaled_onto(point, kept, digits=50)  # the zero test compares to 1e-25 of the terms

    return place


def _expands_to_zero(expr: sp.Expr) -> bool:
    """Zero after expansion with cos² = 1 − sin² for every angle: a proof, tried where it is cheap."""
    from gacli.numeric.zero import time_limit

    if sp.count_ops(expr) > _EXPAND_MAX_OPS:
        return False
    try:
        with time_limit(_EXPAND_SECONDS, _TooSlow):
            expanded = sp.expand(expr)
            angles = {c.args[0] for c in expanded.atoms(sp.cos)}
            squares = {sp.cos(a)**2: 1 - sp.sin(a)**2 for a in angles}
            return expanded == 0 or sp.expand(expanded.subs(squares)) == 0
    except _TooSlow:
        return False     # the seeded points decide instead, and say so


class _TooSlow(Exception):
    pass


def _readable(G: sp.Expr) -> sp.Expr:
    """G with sin² + cos² folded for the reader, when SymPy does it quickly; else as formed."""
    from gacli.numeric.zero import time_limit

    if sp.count_ops(G) >= 400:
        return G
    try:
        with time_limit(_EXPAND_SECONDS, _TooSlow):
            return sp.factor(sp.trigsimp(G))
    except _TooSlow:
        return G


def rate_along(derivation: Derivation, G: sp.Expr) -> sp.Expr:
    """det(M) · dG/dt along the equations (see the module's text); rates of non-speeds put in first."""
    kinematic = {S.value(c): e for c, e in derivation.kinematic_equations}
    speeds = list(derivation.speeds)
    G = G.xreplace({S.rate(c.name): e for c, e in kinematic.items() if S.rate(c.name) not in speeds})
    M, F = sp.Matrix(derivation.mass_matrix), sp.Matrix(derivation.forcing)
    along_q = sum((sp.diff(G, q) * e for q, e in kinematic.items()), sp.S.Zero)
    grad_u = sp.Matrix([[sp.diff(G, u) for u in speeds]])
    # An integral may hold t (Jacobi's, with a support turning steadily) and the free functions of time:
    # their rates are free symbols, so what is proved holds whatever the functions do (a ring turned at
    # Ω(t): p = m R² (Ω + φ̇) is conserved, and its rate had missed m R² Ω̇ where a load cancels it).
    timed = S.time_chain(f.name for f in derivation.system.free_functions)
    along_q += sp.Add(*(sp.diff(G, s) * rate for s, rate in timed.items() if G.has(s)))
    det, adjugate_F = _det_and_adjugate_times(M, F)
    return det * along_q + sum((g * a for g, a in zip(grad_u, adjugate_F)), sp.S.Zero)


def _det_and_adjugate_times(M: sp.Matrix, F: sp.Matrix) -> tuple[sp.Expr, list[sp.Expr]]:
    """det(M) and adj(M)·F, one diagonal block of M at a time.

    SymPy's adjugate takes k² cofactors of size k − 1 whatever M holds: a chain
    of 60 particles, M the identity, did not finish in 40 s. M's blocks are
    the connected parts of its pattern of nonzero entries; for M =
    diag(B_1, ..., B_n), det M = Π det B_j and adj(M) = diag(adj(B_i) Π_{j≠i} det B_j).
    """
    from sympy.matrices.utilities import dotprodsimp

    blocks = _blocks(M)
    # SymPy expands every product of a small det or adjugate (its intermediate "dotprodsimp"): M of a
    # body in Euler parameters holds (q0² + q1² + q2² + q3²)², and the expansions took 5 minutes for
    # one 3×3 block. The products as formed are what the zero test needs.
    with dotprodsimp(False):
        dets = [M.extract(b, b).det(method="berkowitz") for b in blocks]
        out: list[sp.Expr] = [sp.S.Zero] * M.rows
        for i, block in enumerate(blocks):
            others = sp.Mul(*(d for j, d in enumerate(dets) if j != i))
            part = M.extract(block, block).adjugate(method="berkowitz") * F.extract(block, [0])
            for row, value in zip(block, part):
                out[row] = others * value
    return sp.Mul(*dets), out


def _blocks(M: sp.Matrix) -> list[list[int]]:
    """The indices of M's diagonal blocks: connected through nonzero entries (M is symmetric), in order."""
    parent = list(range(M.rows))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for (i, j), value in M.todok().items():
        if value != 0:
            parent[root(i)] = root(j)
    groups: dict[int, list[int]] = {}
    for i in range(M.rows):
        groups.setdefault(root(i), []).append(i)
    return sorted(groups.values())


def _momenta(derivation: Derivation):
    """(coordinate, ∂T/∂q̇_c or None, why none) for each ignorable coordinate."""
    from gacli.emit.naming import parameter_defaults
    from gacli.simulate.energy import energy_expressions
    from gacli.steady.manifold import reduce_state

    reduction = reduce_state(derivation, parameter_defaults(derivation.system.parameters))
    T, _ = energy_expressions(derivation)
    speeds = list(derivation.speeds)
    names = [c.name for c, _ in ((c, None) for c in derivation.system.coordinates)]
    inverse = _rate_inverse(derivation) if len(names) == len(speeds) else None
    grad = [sp.diff(T, u) for u in speeds]
    for c in reduction.ignorable:
        if inverse is not None:
            yield c, sum((grad[s] * inverse[s, names.index(c)] for s in range(len(speeds))), sp.S.Zero), ""
        elif S.rate(c) in speeds:
            yield c, grad[speeds.index(S.rate(c))], ""
        else:
            yield c, None, "its rate is fixed by the constraints (not an independent rate): no momentum of its own"


def _rate_inverse(derivation: Derivation) -> sp.Matrix | None:
    """∂u/∂q̇ when the coordinates' rates and u are one-to-one (no constraints), else None."""
    rows = sp.Matrix([e for _, e in derivation.kinematic_equations])
    beta = rows.jacobian(list(derivation.speeds))
    if beta.free_symbols & set(derivation.speeds):
        return None
    try:
        return beta.inv(method="LU").applyfunc(sp.simplify)
    except (ValueError, ZeroDivisionError):
        return None


def parse_candidate(derivation: Derivation, text: str) -> sp.Expr:
    """A candidate read by gacli's own grammar (never eval): coordinates, their rates, parameters."""
    from gacli.read.expr.build import BuildError, Scope, build
    from gacli.read.expr.grammar import ParseError
    from gacli.read.expr.parser import parse
    from gacli.simulate.spec import OptionError

    system = derivation.system
    coordinates = [c.name for c in system.coordinates]
    names = coordinates + list(derivation.independent)
    functions = [f.name for f in system.free_functions]  # a ring's mark turned at Ω(t): m R² (Ω + φ̇)
    values = {n: S.value(n) for n in [p.name for p in system.parameters] + coordinates + functions}
    rates = {(n, 1): S.rate(n) for n in names + functions}
    try:
        expr = build(parse(text), Scope(values=values, rates=rates, declared=frozenset(names),
                                        rate_note="a candidate holds coordinates, their rates, parameters and functions of time"))
    except (ParseError, BuildError) as exc:
        raise OptionError([f"--candidate {text}: {exc.message}"]) from None
    # sqrt(-1) or 3 was 'conserved (proved symbolically)': true of any constant, and says nothing.
    if expr.has(sp.I, sp.zoo, sp.nan, sp.oo, -sp.oo):
        raise OptionError([f"--candidate {text}: is not a real expression"])
    if not expr.free_symbols & {*(values[n] for n in coordinates + functions), *rates.values()}:
        raise OptionError([f"--candidate {text}: holds no coordinate or rate (every constant is conserved)"])
    return expr
