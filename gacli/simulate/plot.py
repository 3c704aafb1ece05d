"""Draw a simulation with matplotlib (an optional extra: ``pip install 'gacli[sim]'``).

matplotlib is imported on first use, and only through its object API
(``matplotlib.figure.Figure``), so no pyplot state and no GUI backend is
touched: the file is rendered by Agg (PNG) or by the SVG backend. The file is
written to a temporary name beside the target and renamed, like every file
gacli writes.

.. code:: text

    left panel   the states in ``show`` against t (default: the coordinates),
                 always, as docs/simulate.md promises
    right panel  ``phase[1]`` against ``phase[0]``, when ``phase`` is given

Axes carry the units the system file gives (``unit:`` of a coordinate or
quasi-coordinate; its rate's is that per second), time in seconds; a state
without a unit is labelled by its name alone.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from pathlib import Path

from gacli.simulate.results import Simulation
from gacli.simulate.spec import SimulationError, require

FORMATS = (".png", ".svg")


def check(path: Path) -> None:
    """Fail early, before integrating, when ``path`` cannot be drawn.

    Raises:
        SimulationError: the suffix is not .png or .svg.
        MissingExtraError: matplotlib is not installed.
    """
    if Path(path).suffix.lower() not in FORMATS:
        raise SimulationError([f"--plot {path}: the file must end in .png or .svg"])
    require("matplotlib", "plotting")


def plot(sim: Simulation, path: Path, show: Sequence[str] = (), phase: Sequence[str] = (),
         units: Mapping[str, str] | None = None) -> Path:
    """Draw ``sim`` into ``path`` (.png or .svg); returns the path written.

    ``units``: state name → unit (:func:`state_units`), for the axes.
    """
    check(path)
    path = Path(path)
    _save(figure(sim, show, phase, units or {}), path)
    return path


def figure(sim: Simulation, show: Sequence[str] = (), phase: Sequence[str] = (),
           units: Mapping[str, str] | None = None):
    """The matplotlib Figure of :func:`plot`, not yet saved."""
    from matplotlib.figure import Figure

    units = units or {}
    names = list(show) or list(sim.coordinates)
    panels = 1 + int(bool(phase))
    drawing = Figure(figsize=(6.4 * panels, 4.8), layout="constrained")
    axes = drawing.subplots(1, panels, squeeze=False)[0]
    _against_time(axes[0], sim, names, units)
    if phase:
        _phase(axes[-1], sim, phase, units)
    drawing.suptitle(_mathtext_safe(sim.system))
    return drawing


def state_units(system) -> dict[str, str]:
    """The unit of each state the file gives one: a coordinate's, and per second for its rate."""
    units = {}
    for declared in (*system.coordinates, *system.quasi_coordinates):
        if declared.unit:
            units[declared.name] = declared.unit
            units[f"dot({declared.name})"] = per_second(declared.unit)
    return units


def per_second(unit: str) -> str:
    """``m`` → ``m/s``; a compound unit is bracketed first: ``m/s`` → ``(m/s)/s``."""
    return f"{unit}/s" if re.fullmatch(r"[A-Za-z]+(\^?-?\d+)?", unit) else f"({unit})/s"


def label(name: str, units: Mapping[str, str]) -> str:
    unit = units.get(name)
    return _mathtext_safe(f"{name} [{unit}]" if unit else name)


def _mathtext_safe(text: str) -> str:
    # File text in a label: '$' would start matplotlib's math mode (and can fail to parse).
    from gacli.read.textsafe import one_line

    return one_line(text).replace("$", r"\$")


def _against_time(ax, sim: Simulation, names: Sequence[str], units: Mapping[str, str]) -> None:
    for name in names:
        ax.plot(sim.t, sim.column(name), label=label(name, units))
    ax.set_xlabel("t [s]")
    shared = {units.get(name, "") for name in names}
    if len(shared) == 1 and "" not in shared:
        ax.set_ylabel(_mathtext_safe(shared.pop()))
    ax.legend()
    ax.grid(True, alpha=0.3)


def _phase(ax, sim: Simulation, phase: Sequence[str], units: Mapping[str, str]) -> None:
    x, y = phase
    ax.plot(sim.column(x), sim.column(y))
    ax.plot(sim.column(x)[:1], sim.column(y)[:1], "o", label="t = 0")
    ax.set_xlabel(label(x, units))
    ax.set_ylabel(label(y, units))
    if x in sim.coordinates and y in sim.coordinates:
        ax.set_aspect("equal", adjustable="datalim")
    ax.legend()
    ax.grid(True, alpha=0.3)


def _save(figure, path: Path) -> None:
    from gacli.output import atomic_path

    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path) as tmp:
        figure.savefig(tmp, format=path.suffix.lower().lstrip("."))
