"""The printout's closed forms read off the program: q̇, M, F and Q inlined, never derived a second time.

``gacli derive`` (text and LaTeX) and ``gacli gibbs`` print q̇ (eq. 14.20),
the dependent rates (eq. 14.7), G, Q (eq. 14.13) and M u̇ = F (eq. 14.19).
Where the program builder takes a system, these are its program's own
outputs with the assignments written in, in SymPy's canonical form, which
the one display simplifier then tidies (issue #28): the chapter's closed
route (:func:`gacli.mechanics.equations.derive`) is not run. G needs no
more: its acceleration terms are ½ u̇ᵀ M u̇ + (Q − F)ᵀ u̇ (gacli.display.printed).
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.graph import trees_within
from gacli.mechanics.derivation import Derivation
from gacli.mechanics.program import Program
from gacli.mechanics.program.record import inline_with_forces
from gacli.model import System


def read_off(system: System, program: Program) -> Derivation | None:
    """The printout's derivation from ``program``; None where the program keeps no Q, a dependent
    rate is not one the program gives, or the inlined forms are past what SymPy's cse takes as
    trees (the pipeline then forms the closed forms, as it did for every printout before)."""
    inlined = inline_with_forces(program)
    if inlined is None or not trees_within([e for part in inlined for e in part]):
        return None
    rates, mass, forcing, forces = inlined
    kinematic = tuple((name, e) for (name, _), e in zip(program.rates, rates))
    dependent = dependent_rates(system, program.independent, dict(kinematic))
    if dependent is None:
        return None
    k = program.k
    return Derivation(system, program=program, mass_matrix=sp.ImmutableMatrix(k, k, mass),
                      forcing=sp.ImmutableMatrix(k, 1, forcing),
                      generalized_forces=sp.ImmutableMatrix(k, 1, forces),
                      kinematic_equations=kinematic, dependent_rates=dependent)


def dependent_rates(system: System, independent: tuple[str, ...],
                    coordinates: dict[str, sp.Expr]) -> tuple[tuple[str, sp.Expr], ...] | None:
    """Each rate that is not a speed, in the speeds (eq. 14.7): a coordinate's from q̇, a
    quasi-coordinate's from its differential, dθ = Σ C_s dq_s + C dt (eq. 14.2); None for a
    dependent quasi-coordinate without one (the program does not give its rate)."""
    known = {n: S.rate(n) for n in independent} | coordinates
    for q in system.quasi_coordinates:
        if q.name in known:
            continue
        form = q.differential
        if form is None or any(n not in known for n in form.names):
            return None
        known[q.name] = sp.Add(*(c * known[n] for n, c in form.coefficients), form.dt)
    return tuple((n, known[n]) for n in system.rate_names if n not in independent)
