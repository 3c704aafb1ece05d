"""A format-1 wheel's rotation read in the axes that do not spin with it.

A body whose inertia is symmetric about one of its axes e (a wheel, a disc:
diag(A, C, A)) and whose rotation forms turn with a coordinate φ about that
axis (ω_x = −sin φ θ̇, ω_z = cos φ θ̇: a wheel spinning by φ on a chassis
turning by θ) has the same rotation terms in the axes D turned back by φ:
I is the same there, and Ω_r·I Ω_s, Ω_r·τ are dot products. Along D the
transverse components are the forms at φ = 0 (ω = (0, φ̇, θ̇)), so the sines
and cosines of φ, which the program would multiply out and never cancel, are
not there at all. α along D is the rate of D's components plus ω_D × ω,
ω_D = ω − φ̇ e, which is −φ̇ e × ω; with I symmetric about e,
I α + ω × I ω along D is then Euler's dH/dt (docs/program.md). A torque on
the body, given along its own axes, is turned into D the same way.

The frame route gets the same from its frames (gacli.mechanics.program.units,
``_spun``); this is what lets a file written without frames cost what the
same system costs with them.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.mechanics.program.vectors import turned
from gacli.model import Form


@dataclass(frozen=True)
class Despin:
    """The body's symmetry axis, the coordinate it spins by there, and the turn's sense (±1)."""

    axis: int
    coordinate: str
    sense: int

    @property
    def transverse(self) -> tuple[int, int]:
        return (self.axis + 1) % 3, (self.axis + 2) % 3

    def forms(self, forms: tuple[Form, Form, Form]) -> tuple[Form, Form, Form]:
        """The rotation forms along D: the transverse ones at φ = 0."""
        at_zero = {S.value(self.coordinate): sp.S.Zero}
        return tuple(f if n == self.axis else f.xreplace(at_zero) for n, f in enumerate(forms))

    def vector(self, v: tuple) -> tuple:
        """A vector given along the body's axes, along D (a torque on the wheel)."""
        i, k = self.transverse
        phi = S.value(self.coordinate)
        if all(_turns(v[i], v[k], phi, self.sense)):
            return tuple(as_expr(x).xreplace({phi: 0}) for x in v)
        return turned(v, self.axis, sp.cos(phi), -self.sense * sp.sin(phi))


def despin(inertia, forms: tuple[Form, Form, Form], coordinates: list[str]) -> Despin | None:
    """How the body's axes spin about its symmetry axis, or None (not symmetric, or no such φ)."""
    axis = _symmetry_axis(inertia)
    if axis is None:
        return None
    i, k = (axis + 1) % 3, (axis + 2) % 3
    columns = _columns(forms[i], forms[k])
    used = set().union(*(a.free_symbols | b.free_symbols for a, b in columns))
    for name in coordinates:
        phi = S.value(name)
        if phi not in used:
            continue
        for sense in (1, -1):
            if all(all(_turns(a, b, phi, sense)) for a, b in columns):
                return Despin(axis, name, sense)
    return None


def _symmetry_axis(inertia) -> int | None:
    """The axis e of a diagonal inertia whose two other moments are equal, not all three equal."""
    if any(inertia[r][c] != 0 for r in range(3) for c in range(3) if r != c):
        return None
    d = [inertia[n][n] for n in range(3)]
    if d[0] == d[1] == d[2]:
        return None
    return next((a for a in range(3) if d[(a + 1) % 3] == d[(a + 2) % 3]), None)


def _columns(fi: Form, fk: Form) -> list[tuple[sp.Expr, sp.Expr]]:
    """The two transverse forms' coefficients, rate by rate, and their dt parts."""
    names = dict.fromkeys(fi.names + fk.names)
    return [(fi.coefficient(n), fk.coefficient(n)) for n in names] + [(fi.dt, fk.dt)]


def _turns(a: sp.Expr, b: sp.Expr, phi: sp.Symbol, sense: int) -> tuple[bool, bool]:
    """Whether (a, b) is a φ-free pair turned by sense·φ about the axis: ∂a/∂φ = −σ b, ∂b/∂φ = σ a."""
    a, b = as_expr(a), as_expr(b)
    return (sp.expand(sp.diff(a, phi) + sense * b) == 0, sp.expand(sp.diff(b, phi) - sense * a) == 0)
