"""What ``gacli sweep`` shows a person: a progress bar over the points, and where the table went.

The bar goes to stderr and appears only on a terminal: piped or redirected
runs stay quiet, and the table (when no ``--output`` is given) is the only
thing on stdout.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator

from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn
from rich.text import Text

from gacli.display.console import printable, stderr


@contextlib.contextmanager
def progress(mode: str, total: int) -> Iterator[Callable[[int], None] | None]:
    """Yields ``advance(n)`` (n more points done), or None when stderr is not a terminal."""
    console = stderr()
    if not console.is_terminal:
        yield None
        return
    columns = (TextColumn(f"{mode}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TimeRemainingColumn())
    with Progress(*columns, console=console, transient=True) as bar:
        task = bar.add_task(mode, total=total)
        yield lambda n: bar.advance(task, n)


def summary(points: int, failed: int, where: str) -> None:
    """One line on stderr: how many points ran where, and how many failed (their rows say why)."""
    text = f"{points} points {where}" + (f"; {failed} failed (see the error column)" if failed else "")
    stderr().print(Text(printable(text), style="dim"))


def wrote(path) -> None:
    stderr().print(Text(printable(f"wrote {path}"), style="dim"))
