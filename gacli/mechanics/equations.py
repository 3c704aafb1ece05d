"""The Gibbs-Appell equations ∂G/∂u̇_s = Q_s (eq. 14.19) and the kinematic equations (14.20).

∂G/∂u̇_s is formed directly: for each body,
Σ M a·∂a/∂u̇_s + (Iα + ω × Iω)·∂α/∂u̇_s, and ∂a/∂u̇_s is the partial
velocity V_s. With a = V u̇ + a_rest and α = Ω u̇ + α_rest this gives

.. code:: text

    M(q, t) u̇ = F(q, u, t)
    M = Σ m VᵀV + Σ ΩᵀIΩ                                    (k × k, symmetric)
    F = Q − Σ m Vᵀa_rest − Σ Ωᵀ(I α_rest + ω × Iω)          (k × 1)
    q̇ = β u + β₀   for the coordinates                     (eq. 14.20)

so G is never expanded to find the equations.
"""

from __future__ import annotations

from collections.abc import Callable

import sympy as sp

from gacli.algebra.canonical import product as canonical_product
from gacli.errors import DerivationError
from gacli.mechanics.forces import generalized_forces
from gacli.algebra.matrices import product
from gacli.mechanics.axes import turned
from gacli.mechanics.code import program_for
from gacli.mechanics.derivation import Derivation
from gacli.mechanics.motions import BodyMotion, body_motions, motion_context, motion_velocity
from gacli.mechanics.rates import Rates, solve_rates
from gacli.algebra import trig
from gacli.model import System


def derive_for_code(system: System) -> Derivation | None:
    """The equations generated code computes, by the program alone (:mod:`gacli.mechanics.code`):
    the closed forms are not formed. None where the builder does not take the system or would
    choose other independent rates than the chapter's route; the caller then derives the
    closed forms as usual (docs/program.md)."""
    program = program_for(system) if _same_choice(system) else None
    # No independent rate: the chapter's route says so, located, for every command alike (k = 0).
    return None if program is None or not program.independent else Derivation(system, program=program)


def _same_choice(system: System) -> bool:
    """Whether the program's independent rates are the chapter's: given in the file, or chosen
    from the same rows. Both routes take the earliest declared rates the rows leave free
    (gacli.mechanics.rates); a rolling contact's rows are formed apart by each route, and the
    two sets need not pick alike where the choice is numerically close."""
    if system.independent is not None:
        return True
    return system.frames is None or not system.frames.rolling


def derive(system: System, *, progress: Callable[[str], None] | None = None) -> Derivation:
    """Derive the Gibbs-Appell equations of a loaded system (section 14.3).

    >>> import gacli
    >>> d = gacli.derive(gacli.loads('''
    ... gacli: 1
    ... name: falling
    ... parameters: [m, g]
    ... coordinates: [z]
    ... bodies: {ball: {mass: m, position: [0, 0, z]}}
    ... potential: m*g*z
    ... '''))
    >>> d.mass_matrix, d.forcing
    (Matrix([[m]]), Matrix([[-g*m]]))
    """
    current = ["start"]

    def step(name: str) -> None:
        current[0] = name
        if progress is not None:
            progress(name)

    try:
        return _derive(system, step)
    except (OverflowError, RecursionError) as exc:
        # Extreme numbers (cosh(cosh(1e300))) overflow inside SymPy's evaluation.
        raise DerivationError(f"{system.path}: the derivation failed at '{current[0]}': "
                              f"a number is too large to evaluate ({type(exc).__name__})") from None


def _derive(system: System, step: Callable[[str], None]) -> Derivation:
    if not system.rolling_rows:
        raise DerivationError(f"{system.path}: loaded without its rolling rows, for generated code alone; "
                              "load it again with rolling_rows=True to derive it")
    step("rates in terms of the independent rates (14.7)")
    rates = solve_rates(system)
    step("velocities and accelerations (14.14)")
    context = motion_context(system, rates)
    motions = turned(system, body_motions(system, rates, context))
    step("generalized forces (14.13)")
    Q = generalized_forces(system, rates, motions)
    step("Gibbs-Appell equations (14.19)")
    M, F = _mass_matrix_and_forcing(motions, rates, Q, system.uses_frames)
    kinematic = tuple((c.name, rates.rate(c.name)) for c in system.coordinates)
    return Derivation(
        system=system, rates=rates, motions=motions, mass_matrix=M, forcing=F,
        generalized_forces=Q, kinematic_equations=kinematic,
        dependent_accelerations=_dependent_accelerations(rates, context.gamma),
        dependent_rates=rates.dependent(),
    )


def _dependent_accelerations(rates: Rates, gamma: dict[str, sp.Expr]) -> tuple[tuple[str, sp.Expr], ...]:
    """r̈ = β u̇ + γ for each dependent rate: the rate's row of β times u̇, plus γ."""
    out = []
    for i, name in enumerate(rates.names):
        if name in rates.independent:
            continue
        row = [b * a for b, a in zip(rates.beta.row(i), rates.speed_rates) if b != 0]
        out.append((name, sp.Add(*row, gamma[name])))
    return tuple(out)


def _mass_matrix_and_forcing(motions: tuple[BodyMotion, ...], rates: Rates, Q: sp.ImmutableMatrix,
                             frames: bool = True) -> tuple[sp.ImmutableMatrix, sp.ImmutableMatrix]:
    """M and F = Q − (the u̇-free part of ∂G/∂u̇) (eq. 14.19 without expanding G).

    Each entry is collected as a list of terms and summed once: adding whole
    matrices body by body re-flattens ever longer sums. Terms that differ only
    in their mass (or inertia) factor share one sum of masses, so a chain of n
    bodies gives entries with O(n) terms rather than O(n²).
    """
    k = rates.k
    symmetric = all(m.angular is None or _is_symmetric(m.body.inertia) for m in motions)
    terms = _Terms()
    mass_terms: dict[tuple[int, int], dict] = {}
    rest_terms: list[dict] = [{} for _ in range(k)]
    for motion in motions:
        V, m = motion.linear.partials, motion.body.mass
        terms.add_quadratic(mass_terms, V, [[m if a == b else 0 for b in range(V.rows)] for a in range(V.rows)],
                            symmetric)
        terms.add_linear(rest_terms, V, [m * a for a in motion.linear.acceleration_rest])
        if motion.angular is not None:
            W, I = motion.angular.partials, motion.body.inertia
            # From W's nonzero entries: SymPy's matrix product multiplies out the zero
            # entries of W and builds each sum pairwise.
            w = sp.Matrix(motion_velocity(motion.angular, rates.speeds))
            terms.add_quadratic(mass_terms, W, I, symmetric)
            # Kept whole: the angular terms of different bodies rarely coincide, and splitting
            # I α + ω × Iω would undo the factoring that keeps it small.
            terms.add_linear(rest_terms, W, product(I, motion.angular.acceleration_rest) + w.cross(product(I, w)),
                             split=False)
    M = [[sp.S.Zero] * k for _ in range(k)]  # lists: setting matrix entries one by one is slow
    for (i, j), groups in mass_terms.items():
        M[i][j] = _reduced(_sum_grouped(groups), groups, frames)
        if symmetric:
            M[j][i] = M[i][j]
    # A format-1 file's F stays as its author's positions give it (the display reduces it):
    # reducing it there lengthened the generated code of a chain of bodies after CSE.
    F = [_reduced(sp.Add(Q[s], _sum_grouped(groups, -1)), groups, True) if frames else sp.Add(Q[s], _sum_grouped(groups, -1))
         for s, groups in enumerate(rest_terms)]
    return sp.ImmutableMatrix(k, k, [e for row in M for e in row]), sp.ImmutableMatrix(k, 1, F)


def _is_symmetric(I: sp.Matrix) -> bool:
    return all(I[a, b] == I[b, a] for a in range(I.rows) for b in range(a))


class _Terms:
    """Products of expressions as monomials (a rational coefficient and powers of bases), grouped by monomial.

    The products P_ai P_bj of eq. (14.19) are mostly formed once to be taken
    apart again as keys; adding exponents in a dict costs far less than
    SymPy's Mul, which is called once per group in :func:`_sum_grouped`.
    A factor Mul would treat beyond adding exponents (a number's root, exp,
    a non-commutative symbol) sends the product through Mul instead.
    """

    def __init__(self) -> None:
        self._memo: dict[sp.Expr, tuple | None] = {}

    def monomial(self, expr: sp.Expr) -> tuple[sp.Expr, dict[sp.Expr, sp.Expr]] | None:
        """(coefficient, {base: exponent}), or None when only Mul can say what the product is."""
        try:
            return self._memo[expr]
        except KeyError:
            pass
        coefficient, rest = expr.as_coeff_Mul()
        powers: dict[sp.Expr, sp.Expr] = {}
        result = (coefficient, powers)
        for f in () if rest is sp.S.One else sp.Mul.make_args(rest):  # a number: no powers at all
            base, exp = f.args if f.is_Pow else (f, sp.S.One)
            if base.is_Number or isinstance(base, sp.exp) or base is sp.E or not f.is_commutative:
                result = None
                break
            powers[base] = powers[base] + exp if base in powers else exp
        self._memo[expr] = result
        return result

    def add(self, groups: dict, a: sp.Expr, b: sp.Expr, factor: sp.Expr) -> None:
        """Record factor·a·b under the monomial of a·b (its coefficient goes to the factor)."""
        ma, mb = self.monomial(a), self.monomial(b)
        if ma is None or mb is None:
            coefficient, key = (a * b).as_coeff_Mul()
            powers = None
        else:
            coefficient = ma[0] * mb[0]
            powers = dict(ma[1])
            for base, exp in mb[1].items():
                powers[base] = powers[base] + exp if base in powers else exp
            powers = {base: exp for base, exp in powers.items() if exp != 0}
            key = frozenset(powers.items())
        entry = groups.get(key)
        if entry is None:
            entry = groups[key] = (powers, [])
        entry[1].append(factor if coefficient is sp.S.One else coefficient * factor)

    def add_quadratic(self, entries, P: sp.Matrix, C, lower_only: bool) -> None:
        """Add the terms P_ai C_ab P_bj of (Pᵀ C P)_ij, grouped by the geometric factor P_ai P_bj.

        With a symmetric C (every mass matrix m·1 and inertia matrix), Pᵀ C P is
        symmetric: only i ≥ j is formed and the caller mirrors it.
        """
        C = C.tolist() if isinstance(C, sp.MatrixBase) else C
        # Only the columns this body moves, read from the nonzero entries: a particle
        # of a wide system moves one of k, and a scan of every entry would cost k per body.
        nonzero: dict[int, list[tuple[int, sp.Expr]]] = {}
        for (a, i), p_ai in sorted(P.todok().items()):
            nonzero.setdefault(i, []).append((a, p_ai))
        moved = sorted(nonzero)
        for i in moved:
            for j in moved:
                if lower_only and j > i:
                    break
                groups = entries.setdefault((i, j), {})
                for a, p_ai in nonzero[i]:
                    for b, p_bj in nonzero[j]:
                        if C[a][b] != 0:
                            self.add(groups, p_ai, p_bj, C[a][b])

    def add_linear(self, entries, P: sp.Matrix, g, split: bool = True) -> None:
        """Add the terms of (Pᵀ g)_s, g split into its terms so that equal products share their factors."""
        rows: dict[int, list[tuple[int, sp.Expr]]] = {}
        for (a, s), p_as in sorted(P.todok().items()):
            rows.setdefault(a, []).append((s, p_as))
        for a, g_a in enumerate(g):
            if g_a == 0:
                continue
            terms = sp.Add.make_args(g_a) if split else (g_a,)
            for s, p_as in rows.get(a, ()):
                for term in terms:
                    self.add(entries[s], p_as, term, sp.S.One)


def _sum_grouped(groups: dict, sign: int = 1) -> sp.Expr:
    """± Σ (Σ factors)·monomial, each product formed once and the whole by one Add."""
    coefficient = sp.S.One if sign == 1 else sp.S.NegativeOne
    out = []
    for key, (powers, factors) in groups.items():
        rest = [key] if powers is None else [base if exp is sp.S.One else sp.Pow(base, exp)
                                             for base, exp in powers.items()]
        total = sp.Add(*factors)
        out.append(canonical_product(coefficient, rest if total is sp.S.One else [total, *rest]))
    return sp.Add(*out)


def _reduced(entry: sp.Expr, groups: dict, cancel: bool = False) -> sp.Expr:
    """``entry`` reduced by sin² + cos² = 1 where its monomials hold a square (see :mod:`gacli.algebra.trig`).

    With ``cancel`` (a system written with frames) it is distributed whenever it
    holds a sine or cosine: its bodies' motions are along turned axes
    (:mod:`gacli.mechanics.axes`), where the terms that cancel
    need no identity, only to meet.

    The monomials are at hand as dicts of exponents: reading them costs far
    less than the reduction's own walk of the entry, and a chain of
    pendulums has no square in most entries. Q, added to F, is reduced
    already (:mod:`gacli.mechanics.forces`): with no square among the other terms, the
    sum is in normal form too.
    """
    if cancel:
        return trig.reduce(entry, cancel=True)
    for key, (powers, _) in groups.items():
        if powers is None or trig.monomial_may_square(powers):
            return trig.reduce(entry)
    return entry

