"""Draw a simulation with matplotlib (an optional extra: ``pip install 'gacli[sim]'``).

matplotlib is imported on first use, and only through its object API
(``matplotlib.figure.Figure``), so no pyplot state and no GUI backend is
touched: the file is rendered by Agg (PNG) or by the SVG backend. The file is
written to a temporary name beside the target and renamed, like every file
gacli writes.

.. code:: text

    left panel   the states in ``show`` against t (default: the coordinates)
    right panel  ``phase[1]`` against ``phase[0]``, when ``phase`` is given
"""

from __future__ import annotations

from collections.abc import Sequence
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


def plot(sim: Simulation, path: Path, show: Sequence[str] = (), phase: Sequence[str] = ()) -> Path:
    """Draw ``sim`` into ``path`` (.png or .svg); returns the path written."""
    check(path)
    from matplotlib.figure import Figure

    path = Path(path)
    names = list(show) or ([] if phase else list(sim.coordinates))
    panels = int(bool(names)) + int(bool(phase))
    figure = Figure(figsize=(6.4 * panels, 4.8), layout="constrained")
    axes = figure.subplots(1, panels, squeeze=False)[0]
    if names:
        _against_time(axes[0], sim, names)
    if phase:
        _phase(axes[-1], sim, phase)
    figure.suptitle(sim.system)
    _save(figure, path)
    return path


def _against_time(ax, sim: Simulation, names: Sequence[str]) -> None:
    for name in names:
        ax.plot(sim.t, sim.column(name), label=name)
    ax.set_xlabel("t")
    ax.legend()
    ax.grid(True, alpha=0.3)


def _phase(ax, sim: Simulation, phase: Sequence[str]) -> None:
    x, y = phase
    ax.plot(sim.column(x), sim.column(y))
    ax.plot(sim.column(x)[:1], sim.column(y)[:1], "o", label="t = 0")
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    if x in sim.coordinates and y in sim.coordinates:
        ax.set_aspect("equal", adjustable="datalim")
    ax.legend()
    ax.grid(True, alpha=0.3)


def _save(figure, path: Path) -> None:
    from gacli.output import atomic_path

    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path) as tmp:
        figure.savefig(tmp, format=path.suffix.lower().lstrip("."))
