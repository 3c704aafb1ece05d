"""Bodies, forces and torques of a file written without frames (format 1), as the program takes them.

A body is its mass centre's position p(q, t) in N and, when rigid, its
angular velocity in body axes as three forms ω_i = Σ_s W_is ṙ_s + W_it.
For the pass ρ_r of speed r its partial velocities are V_r = Σ_q ∂p/∂q ρ_r(q)
and Ω_r,i = Σ_s W_is ρ_r(s) (eq. 14.8); the accelerations' rest (eq. 14.14)
is the pass ρ = γ plus the derivative of the velocity with all
accelerations zero, a_rest = Σ_q ∂p/∂q γ_q + d/dt(Σ_q ∂p/∂q ṙ_q + ∂p/∂t)|r̈=0.
Each body then adds, as a unit of the frame route does (program.assemble),

    M_rs += m V_r·V_s + Ω_r·I Ω_s
    F_r  += −m V_r·a_rest + Ω_r·(−I α_rest − ω × I ω)

and a force f at a point P adds f·∂P/∂u_r, a torque τ (body axes) τ·Ω_r
(eq. 14.13). The positions and forms are the file's closed forms, small;
the rates in them are program values.
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.algebra.fastdiff import jacobian_rows
from gacli.mechanics.program.assemble import Passes, Sums
from gacli.mechanics.program.despun import Despin, despin
from gacli.mechanics.program.forms import time_derivative
from gacli.mechanics.program import heading
from gacli.mechanics.program.gram import Gram, add_translation, add_work
from gacli.mechanics.program.support import Unsupported
from gacli.mechanics.program.tape import Tape
from gacli.mechanics.program.vectors import ZERO, Pass, add, cross, dot, isotropic, matrix_times, scale
from gacli.model import Form, System


class FormMotion:
    """Partial, actual and rest vectors of closed-form positions and rotation forms, on one tape."""

    def __init__(self, tape: Tape, system: System, passes: Passes, substitution: dict, gram: bool = False) -> None:
        self.tape, self.system, self.passes = tape, system, passes
        self.gram = gram  # points through their dot products (gacli.mechanics.program.gram) where they may be
        self.coordinates = [c.name for c in system.coordinates]
        self.names = list(system.rate_names)
        self.substitution = substitution  # dependent rate symbols → their program values
        self.D = time_derivative(system, passes.actual, tape)
        self.time = S.time_chain(f.name for f in system.free_functions)  # t and each free function: their rates
        self._points: dict[tuple, tuple] = {}  # a force at a body's centre asks for the body's motion again

    def point(self, position) -> tuple[list[tuple], tuple]:
        """(V_r for each speed, a_rest) of a point at ``position`` in N."""
        key = tuple(as_expr(x) for x in position)
        if key not in self._points:
            self._points[key] = self._point(key)
        return self._points[key]

    def turned(self, position) -> bool:
        """Whether the point is formed along the heading the rows were solved along (heading.takes)."""
        return heading.takes(self, tuple(as_expr(x) for x in position))

    def _point(self, position: tuple) -> tuple[list[tuple], tuple]:
        if heading.takes(self, position):
            return heading.point(self, position)
        tape, actual = self.tape, self.passes.actual
        symbols = [S.value(q) for q in self.coordinates]
        J = jacobian_rows(list(position), symbols)  # 3 × n: ∂p/∂q
        columns = {q: tape.vec(J[i][j] for i in range(3)) for j, q in enumerate(self.coordinates)}
        V = [self._along(columns, p) for p in self.passes.partial]
        # d/dt of the closed forms ∂p/∂q, not of their names on the tape: q̈ itself is in V and γ; and of
        # the rest of the velocity, ∂p/∂t and ∂p/∂f ḟ of each free function f (a rod turned by f(t)).
        change = [sp.Add(*(self.D(J[i][j]) * actual.rate(q) for j, q in enumerate(self.coordinates)
                           if J[i][j] != 0), self.D(self._moved(x))) for i, x in enumerate(position)]
        rest = add(self._along(columns, self.passes.gamma), tuple(change))
        return V, tape.vec(rest)

    def _moved(self, x: sp.Expr) -> sp.Expr:
        """The rate of ``x`` with the coordinates held: through t and the free functions of time."""
        return sp.Add(*(sp.diff(x, s) * rate for s, rate in self.time.items() if x.has(s)))

    def _along(self, columns: dict, p: Pass) -> tuple:
        return self.tape.vec(add(*(scale(p.rate(q), columns[q]) for q in self.coordinates if p.rate(q) != 0)))

    def rotation(self, forms: tuple[Form, Form, Form], turn: Despin | None = None) -> tuple[list[tuple], tuple, tuple]:
        """(Ω_r for each speed, ω, α_rest) in body axes from the rotation forms; with ``turn``, along
        the axes that do not spin with the body (gacli.mechanics.program.despun)."""
        if turn is not None:
            W, omega, alpha = self.rotation(turn.forms(forms))
            # α along D: the rate of D's components plus σ φ̇ e × ω (D turns as the body, less its spin).
            i, k = turn.transverse
            spin = turn.sense * self.passes.actual.rate(turn.coordinate)
            extra = [ZERO] * 3
            extra[i], extra[k] = -spin * omega[k], spin * omega[i]
            return W, omega, self.tape.vec(self.tape.nonzero(x) for x in add(alpha, extra))
        tape, actual = self.tape, self.passes.actual
        rows = [{q: tape.let(f.coefficient(q)) for q in self.names if f.coefficient(q) != 0} for f in forms]
        W = [tape.vec(sp.Add(*(c * p.rate(q) for q, c in row.items())) for row in rows)
             for p in self.passes.partial]
        omega = tape.vec(sp.Add(*(c * actual.rate(q) for q, c in row.items()), f.dt) for row, f in zip(rows, forms))
        gamma = self.passes.gamma
        alpha = []
        for f in forms:
            change = sp.Add(*(self.D(c) * actual.rate(q) for q, c in f.coefficients), self.D(f.dt))
            alpha.append(sp.Add(*(c * gamma.rate(q) for q, c in f.coefficients), change))
        # Components of the rest that vanish are exact zeros (body rates as speeds: α = u̇).
        return W, omega, tape.vec(tape.nonzero(x) for x in alpha)

    def loaded(self, e: sp.Expr) -> sp.Expr:
        """A load's component with the dependent rates replaced by their values (eq. 14.7)."""
        return self.tape.let(e.xreplace(self.substitution))


def assemble_bodies(motion: FormMotion, sums: Sums) -> None:
    """Every body's share of M and F, then every force's and torque's (see the module)."""
    tape, system = motion.tape, motion.system
    rotations = {}
    for body in system.bodies:
        tape.stage = "partials"
        mass = tape.let(body.mass)
        if motion.gram and Gram.takes(motion, body.position):
            add_translation(motion, mass, body.position, sums)
        else:
            _add_translation(tape, mass, *motion.point(body.position), sums)
        if body.is_rigid:
            turn = despin(body.inertia.tolist(), body.rotation, motion.coordinates)
            rotations[body.name] = (*motion.rotation(body.rotation, turn), turn)
            _add_rotation(tape, body.inertia.tolist(), *rotations[body.name][:3], sums)
    tape.stage = "F"
    for force in system.forces:
        f = tuple(motion.loaded(c) for c in force.vector)
        if motion.gram and Gram.takes(motion, force.point):
            add_work(motion, force.point, f, sums)
            continue
        V, _ = motion.point(force.point)
        f = heading.force(motion, f) if motion.turned(force.point) else f
        for r, v in enumerate(V):
            sums.load(r, tape.let(dot(v, f)))
    for torque in system.torques:
        if torque.body not in rotations:
            raise Unsupported(f"the torque on '{torque.body}' acts on a body without rotation forms")
        W, _, _, turn = rotations[torque.body]
        tau = tuple(motion.loaded(c) for c in (torque.vector if turn is None else turn.vector(torque.vector)))
        for r, w in enumerate(W):
            sums.load(r, tape.let(dot(w, tau)))


def _add_translation(tape: Tape, mass, V: list, a_rest: tuple, sums: Sums) -> None:
    k = len(V)
    for r in range(k):
        for s in range(r, k):
            sums.M[r][s].append(mass * tape.let(dot(V[r], V[s])))
        inertial = dot(V[r], a_rest)
        if not tape.vanishes(inertial):  # a crank's centripetal acceleration, normal to its V
            sums.F[r].append(-mass * tape.let(inertial))


def _add_rotation(tape: Tape, inertia, W: list, omega: tuple, alpha: tuple, sums: Sums) -> None:
    k = len(W)
    H = [tape.vec(matrix_times(inertia, w)) for w in W]
    h = matrix_times(inertia, alpha)
    if not isotropic(inertia):  # ω × I ω of a sphere is zero, not a sum that cancels
        h = add(h, cross(omega, tape.vec(matrix_times(inertia, omega))))
    torque = tape.vec(scale(-1, h))
    for r in range(k):
        for s in range(r, k):
            sums.M[r][s].append(tape.let(dot(W[r], H[s])))
        sums.F[r].append(tape.let(dot(W[r], torque)))
