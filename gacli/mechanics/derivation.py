"""The one record a derivation gives: the equations, in closed form when they were formed, and for code.

Every command and every emitter reads a :class:`Derivation`. It holds the
chapter's closed forms (β, the motions, Q, M and F of eq. 14.19, the
kinematic equations 14.20) when :func:`gacli.mechanics.equations.derive`
formed them; for generated code alone
(:func:`gacli.mechanics.equations.derive_for_code`) it holds the
straight-line program instead, and the closed forms are left unformed
(``closed`` is False); for a printout, the program and q̇, M, F and Q read
off it (:func:`gacli.mechanics.read_off.read_off`: ``printable``, not
``closed``). What generated code computes is :attr:`Derivation.code`
either way: the program's equations wherever the builder takes the system
(gacli.mechanics.code).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.mechanics.code import CodeEquations, StateNames, from_closed, from_program, program_for
from gacli.mechanics.gibbs import gibbs_function
from gacli.mechanics.motions import BodyMotion
from gacli.mechanics.program import Program
from gacli.mechanics.rates import Rates
from gacli.model import System


@dataclass(frozen=True)
class Derivation(StateNames):
    """Everything derived from a system; SymPy expressions in plain symbols.

    Symbols: a coordinate ``x`` is ``Symbol('x')``, its rate ``Symbol('dot(x)')``
    and its acceleration ``Symbol('ddot(x)')``; ``speeds`` are the independent
    rates u and ``speed_rates`` their derivatives u̇. A derivation for code
    alone has ``rates`` None and the closed-form fields empty (see the module).
    """

    system: System
    rates: Rates | None = None
    motions: tuple[BodyMotion, ...] = ()
    mass_matrix: sp.ImmutableMatrix | None = None
    forcing: sp.ImmutableMatrix | None = None
    generalized_forces: sp.ImmutableMatrix | None = None
    kinematic_equations: tuple[tuple[str, sp.Expr], ...] = ()
    # r̈ = β u̇ + γ for each dependent rate (eq. 14.14), as the motions used them.
    dependent_accelerations: tuple[tuple[str, sp.Expr], ...] = ()
    # The straight-line program, for a derivation for generated code or read off it.
    program: Program | None = None
    # Each rate that is not a speed, in the speeds (eq. 14.7): β u + β₀ of the closed route, or
    # read off the program (gacli.mechanics.read_off); none for a derivation for code alone.
    dependent_rates: tuple[tuple[str, sp.Expr], ...] = ()

    def __repr__(self) -> str:
        # One line: the dataclass repr would print every matrix. The notebook's typeset face
        # (_repr_latex_) is given by gacli.notebook, which this stage must not import.
        s, k = self.system, self.k
        if not self.printable:
            return f"<Derivation of {s.name!r} for code: k = {k}, {self.code.operations:,} operations>"
        return (f"<Derivation of {s.name!r}: k = {k}, coordinates {', '.join(c.name for c in s.coordinates)}; "
                f"speeds {', '.join(str(u) for u in self.speeds)}; M {k}x{k}, F {k}x1>")

    @property
    def closed(self) -> bool:
        """Whether the chapter's closed route formed β, the motions and G (False: a derivation for
        generated code alone, or read off the program)."""
        return self.rates is not None

    @property
    def printable(self) -> bool:
        """Whether q̇, M, F and Q are here as expressions, formed by the closed route or read off the program."""
        return self.mass_matrix is not None

    @functools.cached_property
    def code(self) -> CodeEquations:
        """q̇, M and F as generated code computes them (:mod:`gacli.mechanics.code`): the
        straight-line program's, or these closed forms where there is no program in the same speeds."""
        names = tuple(c.name for c in self.system.coordinates)
        if not self.closed:  # the program's, or read off it
            return from_program(self.program, names)
        program = program_for(self.system)
        if program is not None and program.independent != self.independent:
            program = None  # M and F in other speeds: not the same equations
        if program is None:
            return from_closed(self.kinematic_equations, self.mass_matrix, self.forcing)
        return from_program(program, names)

    @functools.cached_property
    def gibbs(self) -> sp.Expr:
        """G with its acceleration-free terms dropped (eqs. 14.17, 14.21); built on first use."""
        return gibbs_function(self.system, self.rates, self.motions)

    @property
    def k(self) -> int:
        return len(self.independent)

    @property
    def independent(self) -> tuple[str, ...]:
        return self.rates.independent if self.closed else self.program.independent

    @property
    def beta(self) -> sp.ImmutableMatrix:
        return self.rates.beta

    @property
    def beta0(self) -> sp.ImmutableMatrix:
        return self.rates.beta0

    @property
    def speeds(self) -> tuple[sp.Symbol, ...]:
        return tuple(S.rate(n) for n in self.independent)

    @property
    def speed_rates(self) -> tuple[sp.Symbol, ...]:
        return tuple(S.rate(n, 2) for n in self.independent)

    @property
    def equations(self) -> tuple[sp.Eq, ...]:
        """∂G/∂u̇_s = Q_s written as M u̇ + (Q − F) = Q (eq. 14.19)."""
        lhs = self.mass_matrix * sp.Matrix(self.speed_rates) + (self.generalized_forces - self.forcing)
        return tuple(sp.Eq(lhs[s], self.generalized_forces[s], evaluate=False) for s in range(self.k))

    @property
    def mass_matrix_full(self) -> sp.ImmutableMatrix:
        """Block diagonal [I_n, M] for the state (q, u)."""
        n = len(self.system.coordinates)
        return sp.ImmutableMatrix(sp.diag(sp.eye(n), self.mass_matrix))

    @property
    def forcing_full(self) -> sp.ImmutableMatrix:
        """[q̇; F] so that mass_matrix_full · d(state)/dt = forcing_full."""
        qdot = sp.Matrix([e for _, e in self.kinematic_equations])
        return sp.ImmutableMatrix(qdot.col_join(sp.Matrix(self.forcing)))
