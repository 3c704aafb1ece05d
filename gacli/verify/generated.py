"""verify's check of what generated code computes: its q̇ and u̇ = M⁻¹F at verify's own states.

``Derivation.code`` is the straight-line program's q̇, M and F wherever the
program builder takes the system, not the closed forms the other groups
check: the equations users integrate come from it. At each admissible
state of :mod:`gacli.verify.run` (the dependent rates solved from the
relations), its q̇ is compared with those rates and its u̇ = M⁻¹F with r̈ of
the fundamental equation with multipliers (eq. 14.10), as the closed forms'
are. Nothing of gacli.mechanics is imported: the derivation computes its code.
"""

from __future__ import annotations

import mpmath
import sympy as sp

from gacli.algebra import symbols as S
from gacli.numeric.compiled import Compiled
from gacli.verify.fundamental import column
from gacli.verify.report import Worst, group_floor


class GeneratedCheck:
    """Generated code's equations compiled once, and the running maxima of their differences."""

    def __init__(self, derivation, independent: tuple[str, ...]) -> None:
        code = derivation.code
        kinematic = [e for _, e in code.kinematic_equations]
        self.coordinates = [n for n, _ in code.kinematic_equations]
        self.independent = independent
        self.compiled = Compiled({
            "M": code.dense_mass_matrix(), "F": sp.Matrix(code.forcing),
            "kin": sp.Matrix(kinematic) if kinematic else sp.zeros(0, 1),
        })
        self.worst = Worst([S.rate_name(n, 2) for n in independent] + [S.rate_name(n, 1) for n in self.coordinates])

    @property
    def symbols(self) -> tuple[sp.Symbol, ...]:
        return self.compiled.symbols

    def compare(self, values: dict, rdd: list, undetermined: set[str]) -> str:
        """Both groups at one state: ``rdd`` is r̈ of the independent names (eq. 14.10). A note
        when the code cannot be evaluated or solved there, else ""."""
        try:
            got = self.compiled(values)
            if not all(mpmath.isfinite(e) for e in (*(got["M"] or ()), *(got["F"] or ()))):
                raise ArithmeticError("M or F is infinite or not a number there")
        except (ZeroDivisionError, ArithmeticError) as exc:
            self.worst.fail_all()
            return f"generated code could not be evaluated at some samples ({exc})"
        actual = [values[S.rate(n)] for n in self.coordinates]
        kin = column(got["kin"], len(self.coordinates))
        floor = group_floor(actual, kin)
        for n, a, b in zip(self.coordinates, kin, actual):
            self.worst.add(S.rate_name(n, 1), a, b, floor)
        return self._accelerations(got, rdd, undetermined)

    def _accelerations(self, got: dict, rdd: list, undetermined: set[str]) -> str:
        k = len(self.independent)
        if not k:
            return ""
        try:
            udot = column(mpmath.lu_solve(got["M"], got["F"]), k)
        except (ZeroDivisionError, ArithmeticError, ValueError, TypeError):  # TypeError: mpmath on a NaN pivot
            for n in self.independent:
                self.worst.add(S.rate_name(n, 2), mpmath.inf, 0, 1)
            return "generated code's M is singular at some samples"
        floor = group_floor(udot, rdd)
        for n, a, b in zip(self.independent, udot, rdd):
            name = S.rate_name(n, 2)
            if name in undetermined:
                self.worst.undetermined.add(name)
            else:
                self.worst.add(name, a, b, floor)
        return ""
