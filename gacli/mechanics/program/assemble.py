"""Each unit's share of M and F (eqs. 14.17-14.19), from its partial velocities and rest accelerations.

With a = Σ V_r u̇_r + a_rest and α = Σ Ω_r u̇_r + α_rest (eq. 14.14), a unit
of mass m and inertia I about its centre, whose wheels turn relative to its
frame by σ about an axis e_a with inertia λ about it, contributes

    M_rs += m V_r·V_s + Ω_r·H_s + Σ σ_r λ (Ω_s,a + σ_s),   H_s = I Ω_s + Σ λ σ_s e_a
    F_r  += V_r·(f − m a_rest) + Ω_r·(τ − I α_rest − ω × I ω − Σ λ (σ̇ e_a + σ ω × e_a))
            + Σ σ_r (τ_a − λ (α_rest,a + σ̇))

(f, τ its loads: resultant at the centre, moment and torques); only r ≤ s
of M is formed, M being symmetric. The partial velocities are the passes
ρ = e_r + Σ_d β_dr e_d (eq. 14.8); the rest accelerations are the pass with
all accelerations zero plus the pass ρ = γ of the dependent accelerations.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.frame_model import INERTIAL
from gacli.mechanics.program.loads import UnitLoads
from gacli.mechanics.program.motion import Motion
from gacli.mechanics.program.units import Unit, Wheel, unit_inertia
from gacli.mechanics.program.vectors import Pass, add, cross, dot, isotropic, matrix_times, scale, unit


@dataclass(frozen=True)
class Passes:
    """The rates the velocities are formed for: one partial pass per speed, the actual rates, γ."""

    partial: tuple[Pass, ...]
    actual: Pass
    gamma: Pass
    # (x, y, θ): the pair of coordinates solved along the heading θ (solve.turned_columns), whose
    # rates along it each pass holds (Pass.along); None without such a pair.
    heading: tuple | None = None


@dataclass(frozen=True)
class Sums:
    """The terms of M (r ≤ s) and F gathered from every unit and load, summed once at the end, and
    the loads' own terms of F again in Q (eq. 14.13), which the printout shows and code never reads:
    where a unit's F term holds its loads and its inertia in one dot product, Q's is a second
    expression over the same assigned symbols, never assigned itself."""

    M: list
    F: list
    Q: list

    @staticmethod
    def empty(k: int) -> "Sums":
        return Sums([[[] for _ in range(k)] for _ in range(k)], [[] for _ in range(k)], [[] for _ in range(k)])

    def load(self, r: int, term: sp.Expr) -> None:
        """A term of F that is all load: a term of Q_r too."""
        self.F[r].append(term)
        self.Q[r].append(term)


@dataclass(frozen=True)
class UnitMotion:
    """A unit's partial velocities V, Ω and spins σ (per speed), actual ω, rest accelerations a, α."""

    V: list
    W: list
    sigma: list
    omega: tuple
    a_rest: tuple
    alpha_rest: tuple
    homes: tuple  # per speed, the point whose velocity V is, turned (Motion.home)
    frame: str  # the frame V and a_rest are along (translation_frame)
    turning: str = ""  # the frame Ω, ω and α_rest are along (rotation_frame)


def _sigma(motion: Motion, wheel: Wheel, rates: Pass) -> sp.Expr:
    return sp.Add(*(s * motion.tree.rate(e, rates) for e, s in wheel.edges))


def translation_frame(motion: Motion, u: Unit) -> str:
    """The frame V_r·(f − m a_rest) is formed in: the one the unit's point is written in, where its
    velocity is formed. A free body at [x, y, z] in N under a force along N keeps both in N; in its own
    frame they were turned there and back (R Rᵀ, which the program does not know is I)."""
    return motion.frame_of(u.point) if u.point is not None else u.frame


def rotation_frame(motion: Motion, u: Unit, inertia, passes: Passes) -> str:
    """The frame a unit's Ω, ω and α are formed along: its own, or for an isotropic inertia (where
    Ω_r·I Ω_s and Ω_r·I α read alike along any axes) the frame of its chain, up through rotations
    about frame axes, where its partial ω have the fewest components that are not numbers: a ball
    turned by Euler angles' rates, along the frame between its second and third rotation, has
    ω = (θ̇, φ̇ sin θ, φ̇ cos θ + ψ̇); with body rates as speeds its own frame, where ω = u."""
    tree = motion.tree
    if inertia is None or u.wheels or not isotropic(inertia):
        return u.frame
    candidates, f = [u.frame], u.frame
    while f != INERTIAL and tree.edges[f].quaternion is None:
        f = tree.edges[f].parent
        candidates.append(f)

    return min(candidates, key=lambda top: tree.varying(u.frame, passes.partial, top))  # the lowest of equals


def unit_motion(motion: Motion, u: Unit, passes: Passes, inertia=None) -> UnitMotion:
    tape, tree = motion.tape, motion.tree
    tape.stage = "partials"
    homes = tuple(motion.home(u.point, p) for p in passes.partial)
    # From each home along the point's own frame: one merged turn, not a turn per link of the chain.
    along = translation_frame(motion, u)
    V = [motion.velocity(h, p, along) for h, p in zip(homes, passes.partial)]
    turning = rotation_frame(motion, u, inertia, passes) if u.rigid else u.frame
    W = [tree.omega_along(u.frame, turning, p) for p in passes.partial] if u.rigid else []
    sigma = [[_sigma(motion, w, p) for p in passes.partial] for w in u.wheels]
    tape.stage = "rest"
    # Components of the rest that vanish are exact zeros (a wheel's, a moment that cancels).
    a_rest = tape.vec(tape.nonzero(x) for x in motion.acceleration0(u.point, passes.actual, along,
                                                                     gamma=passes.gamma))
    omega = alpha = None
    if u.rigid:
        omega = tree.omega_along(u.frame, turning, passes.actual)
        alpha = tape.vec(tape.nonzero(x) for x in tree.alpha_along(u.frame, turning, passes.actual, passes.gamma))
    return UnitMotion(V, W, sigma, omega, a_rest, alpha, homes, along, turning)


def assemble(motion: Motion, u: Unit, loads: UnitLoads, passes: Passes, sums: Sums) -> None:
    """Add the unit's terms to ``sums`` (see the module)."""
    tape = motion.tape
    tape.stage = "body setup"
    inertia = unit_inertia(motion.tree, u) if u.rigid else None
    lam = [tape.let(w.inertia) for w in u.wheels]
    m = unit_motion(motion, u, passes, inertia)
    tape.stage = "M"
    mass = tape.let(u.mass)
    k = len(passes.partial)
    for r in range(k):
        for s in range(r, k):
            pair = (m.homes[r], passes.partial[r]), (m.homes[s], passes.partial[s])
            sums.M[r][s].append(mass * tape.let(_home_dot(motion, *pair)))
    if inertia is not None:
        _rotation_mass(motion, u, m, inertia, lam, sums)
    tape.stage = "F"
    resultant = loads.resultant(motion.tree, m.frame)
    effective = tape.vec(add(resultant, scale(-mass, m.a_rest)))
    for r in range(k):
        sums.F[r].append(tape.let(dot(m.V[r], effective)))
        sums.Q[r].append(dot(m.V[r], resultant))
    if inertia is not None:
        _rotation_forcing(motion, u, m, inertia, lam, loads, passes, sums)


def _home_dot(motion: Motion, first: tuple[str | None, Pass], second: tuple[str | None, Pass]) -> sp.Expr:
    """V_r·V_s, each partial velocity taken at its home point and the two met in the frame of
    the lower one: |V_r|² of a far link is the joint's lever squared, as Kane's vectors give it,
    not a sum of squares of turned components (cos² + sin²)."""
    (home_r, pass_r), (home_s, pass_s) = first, second
    if home_r is None or home_s is None:
        return sp.S.Zero
    return dot(motion.velocity(home_r, pass_r, motion.frame_of(home_s)), motion.velocity(home_s, pass_s))


def _rotation_mass(motion: Motion, u: Unit, m: UnitMotion, inertia, lam: list, sums: Sums) -> None:
    """Ω_r·H_s + Σ σ_r g_s, H_s = I Ω_s + Σ λ σ_s e_a, g_s = λ (Ω_s,a + σ_s)."""
    tape, k = motion.tape, len(m.V)
    H = []
    for s in range(k):
        h = matrix_times(inertia, m.W[s])
        for j, wheel in enumerate(u.wheels):
            h = add(h, scale(lam[j] * m.sigma[j][s], unit(wheel.axis)))
        H.append(tape.vec(h))
    g = [[tape.let(lam[j] * (m.W[s][w.axis] + m.sigma[j][s])) for s in range(k)] for j, w in enumerate(u.wheels)]
    for r in range(k):
        for s in range(r, k):
            sums.M[r][s].append(tape.let(dot(m.W[r], H[s])))
            sums.M[r][s].extend(m.sigma[j][r] * g[j][s] for j in range(len(u.wheels)) if m.sigma[j][r] != 0)


def _rotation_forcing(motion: Motion, u: Unit, m: UnitMotion, inertia, lam: list, loads: UnitLoads,
                      passes: Passes, sums: Sums) -> None:
    """Ω_r·(τ − I α − ω × Iω − Σ λ(σ̇ e_a + σ ω × e_a)) + Σ σ_r (τ_a − λ (α_a + σ̇))."""
    tape, k = motion.tape, len(m.V)
    h = matrix_times(inertia, m.alpha_rest)
    if not isotropic(inertia):  # a sphere's I ω is along ω: ω × I ω is zero, not a sum that cancels
        h = add(h, cross(m.omega, tape.vec(matrix_times(inertia, m.omega))))
    rates = []
    for j, wheel in enumerate(u.wheels):
        now, rest = (tape.let(_sigma(motion, wheel, p)) for p in (passes.actual, passes.gamma))
        rates.append(rest)
        h = add(h, scale(lam[j], add(scale(rest, unit(wheel.axis)), scale(now, cross(m.omega, unit(wheel.axis))))))
    applied = add(*(t for _, t in loads.torques), _moment(motion, loads.moment))
    applied = motion.tree.express(tape.vec(applied), u.frame, m.turning)
    torque = tape.vec(add(scale(-1, h), applied))
    for r in range(k):
        sums.F[r].append(tape.let(dot(m.W[r], torque)))
        sums.Q[r].append(dot(m.W[r], applied))
    for j, wheel in enumerate(u.wheels):
        own = sp.Add(*(t[wheel.axis] for body, t in loads.torques if body == wheel.body))
        spin = tape.let(own - lam[j] * (m.alpha_rest[wheel.axis] + rates[j]))
        for r in range(k):
            if m.sigma[j][r] != 0:
                sums.F[r].append(m.sigma[j][r] * spin)
                sums.Q[r].append(m.sigma[j][r] * own)


def _moment(motion: Motion, moment: tuple) -> tuple:
    """The loads' moment about the centre, or nothing where it vanishes (gravity on a composite)."""
    if all(motion.tape.vanishes(c) for c in moment):
        return (sp.S.Zero,) * 3
    return motion.tape.vec(moment)
