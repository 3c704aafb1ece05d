"""What ``gacli verify`` found: the largest relative difference of each equation, and M's checks."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath

from gacli.algebra import symbols as S

_SCALE_FLOOR = 1e-12      # of the largest entry of the same group, for near-zero entries


@dataclass(frozen=True)
class Difference:
    """The largest relative difference of one equation over the samples."""

    equation: str
    max_relative: float
    tol: float
    undetermined: bool = False  # the fundamental equation leaves this acceleration free

    @property
    def passed(self) -> bool:
        return not self.undetermined and math.isfinite(self.max_relative) and self.max_relative <= self.tol


@dataclass(frozen=True)
class VerifyReport:
    """What :func:`verify` found. Relative differences are |a − b| / max(|a|, |b|, floor)."""

    system: str
    samples: int
    tol: float
    seed: int
    accelerations: tuple[Difference, ...]  # u̇: Gibbs-Appell M⁻¹F vs the fundamental equation (14.10)
    kinematics: tuple[Difference, ...]     # q̇: kinematic equations (14.20) vs the relations
    rates: tuple[Difference, ...]          # every ṙ: β u + β₀ (14.7) vs the relations
    gibbs: tuple[Difference, ...]          # ∂G/∂u̇_s − Q_s vs (M u̇ − F)_s  (14.19)
    mass_asymmetry: float                  # max over samples of max|M − Mᵀ| / max|M|
    mass_min_eigenvalue: float             # min over samples of λ_min(M) / λ_max(M)
    undetermined: tuple[str, ...]          # rates whose acceleration the fundamental equation leaves free
    notes: tuple[str, ...] = ()
    unphysical: str = ""                   # what was wrong with the parameters of some samples
    physical_min_eigenvalue: float = math.inf  # the minimum over the other samples (inf: none)
    code: tuple[Difference, ...] = ()      # generated code's u̇ = M⁻¹F and q̇ vs (14.10) and the relations

    GROUPS = (
        ("accelerations", "accelerations u̇: fundamental equation (14.10) with multipliers vs M u̇ = F (14.19)"),
        ("kinematics", "kinematic equations (14.20) vs the relations (14.1, 14.2)"),
        ("rates", "every rate ṙ = β u + β₀ (14.7) vs the relations (14.1, 14.2)"),
        ("gibbs", "the displayed G: ∂G/∂u̇_s − Q_s vs (M u̇ − F)_s (14.19)"),
        ("code", "generated code: its u̇ = M⁻¹F vs (14.10), its q̇ vs the relations"),
    )

    @property
    def mass_symmetric(self) -> bool:
        return math.isfinite(self.mass_asymmetry) and self.mass_asymmetry <= self.tol

    @property
    def mass_positive_definite(self) -> bool:
        """Judged on the samples whose parameters are physical: M of a negative mass is the sample's fault."""
        if self.unphysical:
            value = self.physical_min_eigenvalue
            return value == math.inf or (math.isfinite(value) and value > 1e-24)
        return math.isfinite(self.mass_min_eigenvalue) and self.mass_min_eigenvalue > 1e-24

    @property
    def failures(self) -> tuple[str, ...]:
        out = []
        for key, title in self.GROUPS:
            for d in getattr(self, key):
                if not d.passed and not d.undetermined:
                    # inf: not evaluated at some sample (the notes say why), not a measured difference
                    found = ("could not be evaluated at some samples" if d.max_relative == math.inf
                             else f"relative difference {d.max_relative:.3g} > {self.tol:g}")
                    out.append(f"{d.equation}: {found} ({title})")
        if not self.mass_symmetric:
            out.append(f"M is not symmetric: relative asymmetry {self.mass_asymmetry:.3g}")
        if self.mass_min_eigenvalue == math.inf and not self.unphysical:
            out.append("M could not be evaluated at any sample (see the notes)")
        elif not self.mass_positive_definite:
            out.append(f"M is not positive definite: smallest eigenvalue / largest = {self.mass_min_eigenvalue:.3g}")
        for name in self.undetermined:
            out.append(f"{S.rate_name(name, 2)}: the fundamental equation leaves it undetermined "
                       f"(no body and no relation fixes the motion of {name})")
        return tuple(out)

    @property
    def passed(self) -> bool:
        return not self.failures


def format_report(report: VerifyReport) -> list[str]:
    """The report as lines of text for the command line."""
    lines = [(f"verify {report.system}: {report.samples} random admissible states (seed {report.seed}), "
              f"tolerance {report.tol:g}, largest relative difference per equation")]
    for key, title in report.GROUPS:
        diffs = getattr(report, key)
        if not diffs:
            continue
        lines.append(f"  {title}")
        width = max(len(d.equation) for d in diffs)
        for d in diffs:
            if d.undetermined:
                lines.append(f"    {d.equation:<{width}}  {'-':>9}  undetermined")
            else:
                lines.append(f"    {d.equation:<{width}}  {d.max_relative:9.2e}  {'ok' if d.passed else 'FAILED'}")
    lines.append(f"  M symmetric: relative asymmetry {report.mass_asymmetry:.2e}  "
                 f"{'ok' if report.mass_symmetric else 'FAILED'}")
    shown, which = report.mass_min_eigenvalue, ""
    if report.unphysical:  # the note says why the other samples do not count
        shown, which = report.physical_min_eigenvalue, " (over the physical samples)"
    if shown == math.inf:
        lines.append("  M positive definite: not judged (no sample had physical parameters)")
    else:
        lines.append(f"  M positive definite{which}: smallest eigenvalue / largest, scaled by its diagonal {shown:.3g}  "
                     f"{'ok' if report.mass_positive_definite else 'FAILED'}")
    for note in report.notes:
        lines.append(f"  note: {note}")
    if report.passed:
        lines.append("verify: passed")
    else:
        lines.append(f"verify: FAILED ({len(report.failures)})")
        lines.extend(f"  {f}" for f in report.failures)
    return lines


# -- running maxima over the samples ----------------------------------------------

def relative(a, b, floor) -> float:
    diff = abs(a - b)
    if diff == 0:
        return 0.0
    scale = max(abs(a), abs(b), floor)
    if not (mpmath.isfinite(diff) and mpmath.isfinite(scale)) or scale == 0:
        return math.inf
    return float(diff / scale)


def group_floor(*vectors) -> mpmath.mpf:
    biggest = max((abs(x) for v in vectors for x in v if mpmath.isfinite(x)), default=mpmath.mpf(0))
    return max(biggest * _SCALE_FLOOR, _ABSOLUTE_FLOOR)


# Below this both sides are zero at the 30 digits verify works to (a slider whose acceleration is 0 by
# the Gibbs-Appell equations and 1.6e-40 by the multipliers' solve was a relative difference of 1).
_ABSOLUTE_FLOOR = mpmath.mpf("1e-20")


class Worst:
    """Running maxima of relative differences, by equation name (in order)."""

    def __init__(self, names):
        self.values = {n: 0.0 for n in names}
        self.undetermined: set[str] = set()

    def add(self, name, a, b, floor):
        value = relative(a, b, floor)
        if math.isnan(value) or value > self.values[name]:
            self.values[name] = math.inf if math.isnan(value) else value

    def fail_all(self):
        for n in self.values:
            self.values[n] = math.inf

    def result(self, tol) -> tuple[Difference, ...]:
        return tuple(Difference(n, v, tol, n in self.undetermined) for n, v in self.values.items())
