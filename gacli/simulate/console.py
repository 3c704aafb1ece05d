"""What ``gacli simulate`` shows a person: a progress bar and the summary (rich).

The progress bar goes to stderr and appears only on a terminal: piped or
redirected runs stay quiet. The summary (:func:`gacli.simulate.summary_lines`)
is the command's result and goes to stdout.
"""

from __future__ import annotations

import contextlib
import warnings
from collections.abc import Callable, Iterator

from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn
from rich.text import Text

from gacli.display.console import printable, stderr, stdout
from gacli.simulate.results import Simulation, summary_lines


@contextlib.contextmanager
def progress(t_end: float) -> Iterator[Callable[[float], None] | None]:
    """Yields ``advance(t)`` for :func:`gacli.simulate.simulate`, or None when not on a terminal."""
    console = stderr()
    if not console.is_terminal:
        yield None
        return
    columns = (
        TextColumn("simulating"), BarColumn(),
        TextColumn("t = {task.completed:.4g} / {task.total:.4g}"), TimeElapsedColumn(),
    )
    with Progress(*columns, console=console, transient=True) as bar:
        task = bar.add_task("simulate", total=t_end)
        yield lambda t: bar.update(task, completed=t)


MAX_WARNING_NOTES = 5  # distinct warnings shown; a run can warn at every step


@contextlib.contextmanager
def notes_from_warnings() -> Iterator[None]:
    """SciPy's, NumPy's and Matplotlib's warnings as gacli notes on stderr: one line each,
    each distinct warning once, at most MAX_WARNING_NOTES, then how many more
    (docs/simulate.md). Shown when the block ends, also when it fails."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            yield
        finally:
            for line in warning_notes(caught):
                stderr().print(Text(printable(line), style="dim"))


def warning_notes(caught) -> list[str]:
    """``note: <library>: <message>`` per distinct warning, capped."""
    distinct = list(dict.fromkeys((_library(w), " ".join(str(w.message).split())) for w in caught))
    lines = [f"note: {library}: {message}" for library, message in distinct[:MAX_WARNING_NOTES]]
    if len(distinct) > MAX_WARNING_NOTES:
        lines.append(f"note: {len(distinct) - MAX_WARNING_NOTES} more warnings not shown")
    return lines


def _library(w: warnings.WarningMessage) -> str:
    if w.category.__name__ == "InitialStateNote":
        return "initial state"
    if w.category.__name__ == "ToleranceNote":
        return "tolerance"
    parts = str(w.filename).replace("\\", "/").split("/")
    known = [p for p in ("scipy", "numpy", "matplotlib", "sympy") if p in parts]
    return f"{known[0]} {w.category.__name__}" if known else w.category.__name__


def summary(sim: Simulation) -> None:
    """The run and what it measured, one fact a line, to stdout."""
    console = stdout()
    lines = summary_lines(sim)
    console.print(Text(printable(lines[0]), style="bold"))  # the first line names the system
    for line in lines[1:]:
        console.print(Text(f"  {printable(line)}"))


def wrote(path) -> None:
    stderr().print(Text(printable(f"wrote {path}"), style="dim"))
