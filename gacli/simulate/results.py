"""What a run found: the path, the energy and the constraint residuals; as CSV and as lines."""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field

import numpy as np

# -- the result -----------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class ConstraintResidual:
    """A constraint along the path: A ṙ + a₀ (Pfaffian) or f(q, t) (finite), per sample."""

    label: str            # "constraints[0]"
    text: str             # as written in the system file
    finite: bool
    values: np.ndarray

    @property
    def initial(self) -> float:
        return float(self.values[0])

    @property
    def max_abs(self) -> float:
        """max |A ṙ + a₀| for a Pfaffian constraint, max |f − f(t₀)| for a finite one."""
        reference = self.values[0] if self.finite else 0.0
        return float(np.max(np.abs(self.values - reference)))


@dataclass(frozen=True, eq=False)
class Simulation:
    """A computed trajectory: ``states[i, j]`` is STATE[j] at ``t[i]``."""

    system: str
    t: np.ndarray
    states: np.ndarray
    state_names: tuple[str, ...]
    coordinates: tuple[str, ...]
    parameters: dict[str, float]
    method: str
    rtol: float
    atol: float
    evaluations: int
    energy: np.ndarray | None = None
    kinetic_energy: np.ndarray | None = None
    not_conservative: tuple[str, ...] = ()
    residuals: dict[str, ConstraintResidual] = field(default_factory=dict)
    # Each first integral besides E (gacli.steady.integrals) along the path, by name.
    integrals: dict[str, np.ndarray] = field(default_factory=dict)

    def integral_drift(self, name: str) -> float:
        """max |I(t) − I(t₀)| of a first integral along the path."""
        values = self.integrals[name]
        return float(np.max(np.abs(values - values[0])))

    def column(self, name: str) -> np.ndarray:
        return self.states[:, self.state_names.index(name)]

    @property
    def energy_drift(self) -> float | None:
        """max |E(t) − E(t₀)| along the path, or None when E is not conserved."""
        if self.energy is None:
            return None
        return float(np.max(np.abs(self.energy - self.energy[0])))

    @property
    def energy_relative_drift(self) -> float | None:
        """The drift over max(|E(t₀)|, max T): E has an arbitrary zero, T does not."""
        if self.energy is None:
            return None
        scale = max(abs(float(self.energy[0])), float(np.max(self.kinetic_energy)))
        return self.energy_drift / scale if scale > 0 else self.energy_drift


# -- output -------------------------------------------------------------------------

def to_csv(sim: Simulation) -> str:
    """A header ``t`` then the STATE names, one row per sample, floats in shortest round-trip form."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(("t",) + sim.state_names)
    for t, row in zip(sim.t, sim.states):
        writer.writerow([repr(float(t))] + [repr(float(v)) for v in row])
    return buffer.getvalue()


def summary_lines(sim: Simulation) -> list[str]:
    """What the run did and what it measured, one fact a line (shown by gacli.simulate.console)."""
    lines = [
        f"{sim.system}: t = 0 to {short(sim.t[-1])} with {sim.method} "
        f"(rtol {short(sim.rtol)}, atol {short(sim.atol)}), "
        f"{sim.evaluations} evaluations of rhs, {len(sim.t)} samples",
        "parameters: " + (", ".join(f"{n} = {short(v)}" for n, v in sim.parameters.items()) or "none"),
        "initial state: " + ", ".join(f"{n} = {short(v)}" for n, v in zip(sim.state_names, sim.states[0])),
        "final state: " + ", ".join(f"{n} = {short(v)}" for n, v in zip(sim.state_names, sim.states[-1])),
    ]
    if sim.energy is None:
        lines.append("energy: not reported, E need not be conserved (" + "; ".join(sim.not_conservative) + ")")
    else:
        lines.append(f"energy: E(0) = {short(sim.energy[0])}, max |E - E(0)| = {short(sim.energy_drift)} "
                     f"(relative {short(sim.energy_relative_drift)})")
    for name, values in sim.integrals.items():
        lines.append(f"{name}: I(0) = {short(values[0])}, max |I - I(0)| = {short(sim.integral_drift(name))}")
    for r in sim.residuals.values():
        if r.finite:
            lines.append(f"{r.label} {r.text}: f(0) = {short(r.initial)}, max |f - f(0)| = {short(r.max_abs)}")
        else:
            lines.append(f"{r.label} {r.text}: max |residual| = {short(r.max_abs)}")
    return lines


def short(value: float) -> str:
    return f"{float(value):.6g}"
