"""``verify``: the derivation against the fundamental equation (eq. 14.10) at random admissible states.

Each sample draws the parameters (physical, :func:`gacli.numeric.sample_parameters`),
the coordinates, the free functions and inputs, t, the independent rates and
their accelerations; the dependent rates are solved from the relations, so
the state is admissible. Then r̈ and λ of the fundamental equation are
compared with the derivation's u̇ = M⁻¹F (14.19), its kinematic equations
(14.20), every row of ṙ = β u + β₀ (14.7), and ∂G/∂u̇_s − Q_s (14.19); and generated code's q̇ and u̇ = M⁻¹F
(``Derivation.code``, :mod:`gacli.verify.generated`).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.model import System
from gacli.numeric import precise_parameter_values, sample_parameters
from gacli.numeric.compiled import Compiled
from gacli.numeric.definite import diagonally_scaled
from gacli.numeric.spheres import scaled_onto
from gacli.algebra.readable import displayable
from gacli.verify.fundamental import (
    DEFAULT_SEED, DPS, FUNCTION_ORDERS, column, fundamental_equations, kkt, redundant_relations, solve_least_squares,
)
from gacli.verify.generated import GeneratedCheck
from gacli.verify.report import VerifyReport, Worst, group_floor

DEFAULT_SAMPLES = 20
DEFAULT_TOL = 1e-9


def verify(system: System, derivation, *, samples: int = DEFAULT_SAMPLES, tol: float = DEFAULT_TOL,
           seed: int = DEFAULT_SEED, gibbs: bool = True) -> VerifyReport:
    """Check ``derivation`` of ``system`` against the fundamental equation at random states.

    Deterministic for a given seed. Never raises for a wrong derivation: the
    report says what differs (``report.passed``, ``report.failures``).
    ``gibbs=False`` skips the check of the displayed G (building G can cost
    more than the derivation itself for large systems); the report says so.
    """
    run = _Run(system, derivation, seed, gibbs)
    rng = np.random.default_rng(seed)
    with mpmath.workdps(DPS):
        for sample in range(samples):
            run.sample(rng, sample)
    return run.report(samples, tol, seed)


class _Run:
    """The compiled equations of both routes, and the running maxima of their differences."""

    def __init__(self, system: System, derivation, seed: int, gibbs: bool) -> None:
        self.system, self.derivation = system, derivation
        fundamental = self.fundamental = fundamental_equations(system)
        self.names = names = fundamental.names
        self.N, self.m = len(names), len(fundamental.relations)
        self.independent = independent = tuple(derivation.independent)
        self.notes: list[str] = []
        self.redundant = redundant_relations(fundamental, seed)
        for i in self.redundant:
            self.notes.append(f"{fundamental.relations[i]} repeats the relations before it: no acceleration "
                              "changes, and its multiplier is not determined")
        unknown = [n for n in independent if n not in names]
        if unknown:
            raise ValueError(f"the derivation's independent rates {unknown} are not rates of {system.name}")
        self.dependent = [n for n in names if n not in independent]
        self.ind_idx = [names.index(n) for n in independent]
        self.dep_idx = [names.index(n) for n in self.dependent]
        self.k = len(independent)
        self.speed_rates = [S.rate(n, 2) for n in independent]
        self.gibbs = gibbs
        self._compile()
        self._tallies()

    def _compile(self) -> None:
        fundamental, derivation = self.fundamental, self.derivation
        self.relations = Compiled({"A": fundamental.A, "a0": fundamental.a0})
        self.ours = Compiled({
            "mass": fundamental.mass, "inertial": fundamental.inertial, "loads": fundamental.loads,
            "A": fundamental.A, "rest": fundamental.relation_rest,
        })
        kinematic = derivation.kinematic_equations
        self.theirs = Compiled({
            "M": sp.Matrix(derivation.mass_matrix), "F": sp.Matrix(derivation.forcing),
            "Q": sp.Matrix(derivation.generalized_forces),
            "kin": sp.Matrix([e for _, e in kinematic]) if kinematic else sp.zeros(0, 1),
            "rates": sp.Matrix([derivation.rates.rate(n) for n in derivation.rates.names]),
            "dG": self._gibbs_gradient(),
        })
        self.generated = GeneratedCheck(derivation, self.independent)

    def _gibbs_gradient(self) -> sp.Matrix:
        """∂G/∂u̇_s of the displayed G (eq. 14.19), evaluated at the sample's random u̇."""
        skipped = "the check of the displayed G was skipped"
        if self.gibbs and not displayable(self.derivation):
            self.gibbs, skipped = False, skipped + " (G is not displayed for a system this large)"
        if self.gibbs:
            return sp.Matrix([sp.diff(self.derivation.gibbs, a) for a in self.speed_rates])
        self.notes.append(skipped)
        return sp.zeros(self.k, 1)

    def _tallies(self) -> None:
        independent, rates = self.independent, self.derivation.rates
        self.kin_names = [S.rate_name(n, 1) for n, _ in self.derivation.kinematic_equations]
        self.worst_acc = Worst([S.rate_name(n, 2) for n in independent])
        self.worst_kin = Worst(self.kin_names)
        self.worst_rates = Worst([S.rate_name(n, 1) for n in rates.names])
        self.worst_gibbs = Worst([f"∂G/∂{S.rate_name(n, 2)}" for n in independent] if self.gibbs else [])
        self.asymmetry, self.min_eig, self.physical_eig, self.bad_sample = 0.0, math.inf, math.inf, ""
        self.undetermined: set[str] = set()

    # -- one sample
    def sample(self, rng: np.random.Generator, sample: int) -> None:
        values, unphysical = self._draw(rng)
        try:
            self._admissible(values)
            self._fill_extra(values, rng, sample)
            rdd, free = kkt(self.ours(values), self.N, self.m, force_svd=bool(self.redundant))
            self.undetermined.update(self.names[j] for j in free if j < self.N)
        except (ZeroDivisionError, ValueError, ArithmeticError) as exc:
            self.notes.append(f"the fundamental equation could not be solved at some samples ({exc})")
            self.worst_acc.fail_all()
            self.generated.worst.fail_all()
            return
        free_names = {S.rate_name(self.names[j], 2) for j in free if j < self.N}
        if note := self.generated.compare(values, [rdd[j] for j in self.ind_idx], free_names):
            self.notes.extend([note] if note not in self.notes else [])
        try:
            th = self.theirs(values)
            if not all(mpmath.isfinite(e) for e in (*th["M"], *th["F"])):
                # A number in the file overflows (exp(exp(exp(100)))): nothing can be compared.
                raise ArithmeticError("M or F is infinite or not a number there")
        except (ZeroDivisionError, ArithmeticError) as exc:
            note = f"the derivation could not be evaluated at some samples ({exc})"
            self.notes.extend([note] if note not in self.notes else [])
            for w in (self.worst_acc, self.worst_kin, self.worst_rates, self.worst_gibbs):
                w.fail_all()
            return
        self._compare_rates(values, th)
        self._compare_mass(th, unphysical)
        self._compare_accelerations(th, rdd, free)
        self._compare_gibbs(values, th)

    def _draw(self, rng: np.random.Generator) -> tuple[dict, str]:
        """Random parameters, coordinates, functions, inputs, t, independent rates and u̇ (in this order)."""
        system = self.system
        sample = sample_parameters(system, rng)
        values: dict = precise_parameter_values(system, sample, DPS + 5)
        self.bad_sample = self.bad_sample or sample.problem
        values.update({S.value(c.name): mpmath.mpf(rng.uniform(0.3, 1.7)) for c in system.coordinates})
        self._on_spheres(values)
        functions = [S.rate(f.name, o) for f in system.free_functions for o in range(FUNCTION_ORDERS + 1)]
        inputs = [S.value(i.name) for i in system.inputs]
        values.update({s: mpmath.mpf(rng.uniform(-1.5, 1.5)) for s in functions + inputs})
        values[S.T] = mpmath.mpf(rng.uniform(0.0, 2.0))
        values.update({S.rate(n): mpmath.mpf(rng.uniform(-1.5, 1.5)) for n in self.independent})
        values.update({a: mpmath.mpf(rng.uniform(-1.5, 1.5)) for a in self.speed_rates})
        return values, sample.problem

    def _on_spheres(self, values: dict) -> None:
        """Coordinates the file keeps on a sphere (Euler parameters' e·e = 1) scaled onto it, in
        place: the motion is there, and the derivation reads its rows there (a rolling row along the
        normal of a ball in a quaternion frame vanishes only on it)."""
        placed = scaled_onto(dict(values), self.fundamental.spheres, DPS + 5)
        values.update({x: mpmath.mpf(placed[x]) for x in placed if placed[x] is not values[x]})

    def _admissible(self, values: dict) -> None:
        """The dependent rates from the relations A ṙ + a₀ = 0, in place."""
        names, m = self.names, self.m
        nonlinear = any(c.rates is not None for c in self.system.constraints)
        # A row nonlinear in the rates (A = ∂g/∂ṙ) is evaluated at the rates found so far: the
        # Pfaffian rows settle in the first pass, the nonlinear ones in the next.
        for _ in range(3 if nonlinear else 1):
            part = self.relations({s: values.get(s, 0) for s in self.relations.symbols})
            if not self.dependent:
                break
            A, a0 = part["A"], part["a0"]
            rhs = mpmath.matrix([-a0[i] - sum(A[i, j] * values[S.rate(names[j])] for j in self.ind_idx)
                                 for i in range(m)])
            Adep = mpmath.matrix([[A[i, j] for j in self.dep_idx] for i in range(m)])
            solved = mpmath.lu_solve(Adep, rhs)
            values.update({S.rate(n): solved[r] for r, n in enumerate(self.dependent)})

    def _fill_extra(self, values: dict, rng: np.random.Generator, sample: int) -> None:
        known = set(self.ours.symbols) | set(self.theirs.symbols) | set(self.generated.symbols)
        extra = [s for s in known if s not in values]
        for s in sorted(extra, key=lambda s: s.name):
            values[s] = mpmath.mpf(rng.uniform(-1.5, 1.5))
            if sample == 0:
                self.notes.append(f"symbol {s.name} has no role in the system; given random values")

    # -- the comparisons
    def _compare_rates(self, values: dict, th: dict) -> None:
        """Kinematic equations (14.20) and the rows of ṙ = β u + β₀ (14.7) against the admissible rates."""
        derivation, rates = self.derivation, self.derivation.rates
        actual_kin = [values[S.rate(n)] for n, _ in derivation.kinematic_equations]
        got_kin = column(th["kin"], len(self.kin_names))
        floor = group_floor(actual_kin, got_kin)
        for name, a, b in zip(self.kin_names, got_kin, actual_kin):
            self.worst_kin.add(name, a, b, floor)
        actual_rates = [values[S.rate(n)] for n in rates.names]
        got_rates = column(th["rates"], len(rates.names))
        floor = group_floor(actual_rates, got_rates)
        for n, a, b in zip(rates.names, got_rates, actual_rates):
            self.worst_rates.add(S.rate_name(n, 1), a, b, floor)

    def _compare_mass(self, th: dict, unphysical: str) -> None:
        """M symmetric and positive definite (the smallest eigenvalue over the largest of M scaled by its
        diagonal, D^-1/2 M D^-1/2)."""
        M, k = th["M"], self.k
        if not k:
            return
        biggest = max(abs(M[i, j]) for i in range(k) for j in range(k))
        asym = max(abs(M[i, j] - M[j, i]) for i in range(k) for j in range(k))
        self.asymmetry = max(self.asymmetry, float(asym / biggest) if biggest else math.inf)
        # Judged whatever the units, as check judges it (gacli.numeric.definite): the unscaled ratio
        # of a planet's 6e24 beside a probe's 1, 1.7e-25, 'FAILED'.
        scaled = diagonally_scaled(M, k)
        symmetric = mpmath.matrix(scaled) if scaled is not None else (M + M.T) / 2
        try:
            eig = mpmath.eigsy(symmetric, eigvals_only=True)
            lo, hi = min(eig), max(abs(x) for x in eig)
            ratio = float(lo / hi) if hi else -math.inf
        except (ZeroDivisionError, ArithmeticError, ValueError):
            ratio = -math.inf
        self.min_eig = min(self.min_eig, ratio)
        self.physical_eig = self.physical_eig if unphysical else min(self.physical_eig, ratio)

    def _compare_accelerations(self, th: dict, rdd: list, free: list[int]) -> None:
        """u̇ = M⁻¹F against r̈ of the independent names."""
        M, F, k = th["M"], th["F"], self.k
        singular: list[int] = []
        try:
            udot = column(mpmath.lu_solve(M, F), k) if k else []
        except (ZeroDivisionError, ArithmeticError, ValueError):
            solution, singular = solve_least_squares(M, F)  # the M check reports it
            udot = column(solution, k)
            self.notes.append("M is singular: u̇ = M⁻¹F compared by least squares where determined")
        independent_rdd = [rdd[j] for j in self.ind_idx]
        floor = group_floor(udot, independent_rdd)
        for j, n in enumerate(self.independent):
            if self.names.index(n) in free:
                self.worst_acc.undetermined.add(S.rate_name(n, 2))
            elif j in singular:
                self.worst_acc.add(S.rate_name(n, 2), mpmath.inf, 0, floor)
            else:
                self.worst_acc.add(S.rate_name(n, 2), udot[j], independent_rdd[j], floor)

    def _compare_gibbs(self, values: dict, th: dict) -> None:
        """∂G/∂u̇_s − Q_s against M u̇ − F, at random u̇ (eq. 14.19)."""
        k = self.k
        if not (k and self.gibbs):
            return
        ud = mpmath.matrix([values[a] for a in self.speed_rates])
        a_, b_ = column(th["dG"] - th["Q"], k), column(th["M"] * ud - th["F"], k)
        floor = group_floor(a_, b_)
        for j, n in enumerate(self.independent):
            self.worst_gibbs.add(f"∂G/∂{S.rate_name(n, 2)}", a_[j], b_[j], floor)

    def report(self, samples: int, tol: float, seed: int) -> VerifyReport:
        k = self.k
        return VerifyReport(
            system=self.system.name, samples=samples, tol=tol, seed=seed,
            accelerations=self.worst_acc.result(tol), kinematics=self.worst_kin.result(tol),
            rates=self.worst_rates.result(tol), gibbs=self.worst_gibbs.result(tol),
            code=self.generated.worst.result(tol),
            mass_asymmetry=self.asymmetry, mass_min_eigenvalue=self.min_eig if k else 1.0,
            undetermined=tuple(n for n in self.names if n in self.undetermined),
            notes=tuple(dict.fromkeys(self.notes + _unphysical_note(self.bad_sample, self.min_eig))),
            unphysical=self.bad_sample, physical_min_eigenvalue=self.physical_eig if k else 1.0,
        )


def _unphysical_note(problem: str, min_eig: float) -> list[str]:
    if not problem:
        return []
    verdict = ("M is not positive definite there: the sample, not the derivation, is at fault"
               if not (math.isfinite(min_eig) and min_eig > 1e-24) else "M stayed positive definite")
    return [f"no physical parameter values were found for some samples ({problem}); {verdict}"]
