"""What ``gacli simulate`` shows a person: a progress bar and the summary (rich).

The progress bar goes to stderr and appears only on a terminal: piped or
redirected runs stay quiet. The summary (:func:`gacli.simulate.summary_lines`)
is the command's result and goes to stdout.
"""

from __future__ import annotations

import contextlib
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


def summary(sim: Simulation) -> None:
    """The run and what it measured, one fact a line, to stdout."""
    console = stdout()
    lines = summary_lines(sim)
    console.print(Text(printable(lines[0]), style="bold"))  # the first line names the system
    for line in lines[1:]:
        console.print(Text(f"  {printable(line)}"))


def wrote(path) -> None:
    stderr().print(Text(printable(f"wrote {path}"), style="dim"))
