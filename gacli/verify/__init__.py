"""``gacli verify``: check a derivation by an independent route. See docs/verify.md.

The Gibbs-Appell route (:mod:`gacli.mechanics.equations`) eliminates the dependent
rates first (eq. 14.7) and never sees a constraint force. This package
derives the motion a second way that shares none of that code
(:mod:`~gacli.verify.fundamental`): the fundamental equation (eq. 14.10)
over ALL n + p rates ṙ (coordinates and quasi-coordinates), with one
Lagrange multiplier per constraint (eq. 14.1) and per quasi-coordinate
definition (eq. 14.2),

.. code:: text

    Σ_bodies [ m a·∂v/∂ṙ_j + (Iα + ω×Iω)·∂ω/∂ṙ_j ] − Q̃_j = Σ_i λ_i A_ij    (j = 1..n+p)
    A r̈ + (d/dt A) ṙ + d/dt a₀ = 0                                         (the relations, differentiated)

where A ṙ + a₀ = 0 holds the constraints, then θ̇ − C q̇ − C₀ = 0 for each
quasi-coordinate with a differential, and Q̃_j is the generalized force on
the unreduced rate j. At random admissible states this linear system is
solved numerically (30 significant digits) for r̈ and λ, and compared with
the derivation (:mod:`~gacli.verify.run`): u̇ = M⁻¹F, the kinematic
equations (14.20), every row of ṙ = β u + β₀ (14.7), the displayed G
(∂G/∂u̇_s = Q_s, eq. 14.19), and M symmetric positive definite. The
multipliers themselves, the constraint forces, are :mod:`gacli.reactions`.

API (all pure; nothing is printed)::

    report = verify(system, derivation, samples=20, tol=1e-9, seed=DEFAULT_SEED, gibbs=True)
    report.passed              # bool
    report.failures            # tuple of one-line messages naming the equation
    format_report(report)      # list of lines for the CLI

Imports: none of the derivation's modules (kinematics, forces, equations,
gibbs; a test checks it), only symbols, model and helpers (errors, graph,
numeric, readable); the derivation is read through the ``Derivation`` it is given.
"""

from gacli.verify.fundamental import DEFAULT_SEED, FundamentalEquations, fundamental_equations, redundant_relations
from gacli.verify.report import Difference, VerifyReport, format_report
from gacli.verify.run import DEFAULT_SAMPLES, DEFAULT_TOL, verify

__all__ = [
    "DEFAULT_SAMPLES", "DEFAULT_SEED", "DEFAULT_TOL", "Difference", "FundamentalEquations", "VerifyReport",
    "format_report", "fundamental_equations", "redundant_relations", "verify",
]
