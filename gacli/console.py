"""Everything gacli shows a person: diagnostics, reports, progress (rich).

Only the CLI imports this module; the domain modules never print. Results go
to stdout, diagnostics and progress to stderr, so ``gacli derive f.yaml
--format c > f.c`` stays clean. Styling appears only on a terminal.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterable, Iterator

from rich.console import Console
from rich.text import Text

from gacli.errors import Diagnostic


def _width() -> int | None:
    # Tests and CI pin the width so wrapped output is reproducible.
    value = os.environ.get("GACLI_WIDTH")
    return int(value) if value and value.isdigit() else None


def stdout() -> Console:
    return Console(highlight=False, width=_width(), soft_wrap=True)


def stderr() -> Console:
    return Console(stderr=True, highlight=False, width=_width(), soft_wrap=True)


def printable(text: str) -> str:
    """Control characters quoted from a file, shown escaped: a file must not drive the terminal."""
    return "".join(c if c.isprintable() or c == " " else repr(c)[1:-1] for c in text)


def diagnostics(items: Iterable[Diagnostic]) -> None:
    console = stderr()
    for d in items:
        line = Text()
        line.append(printable(str(d.location)), style="bold")
        line.append(": ")
        line.append(f"{d.severity}:", style="bold red" if d.severity == "error" else "bold yellow")
        line.append(f" {printable(d.where)}: " if d.where else " ")
        line.append(printable(d.message))
        if d.hint:
            line.append(f" ({printable(d.hint)})", style="cyan")
        console.print(line)


def error(message: str) -> None:
    text = Text()
    text.append("error:", style="bold red")
    text.append(f" {printable(message)}")
    stderr().print(text)


def sections(title: str, items) -> None:
    """Print report sections (gacli.report.Section) to stdout."""
    console = stdout()
    if title:
        console.print(Text(title, style="bold"))
    for section in items:
        console.print(Text(f"\n{section.title}", style="bold cyan"))
        for line in section.lines:
            console.print(Text(f"  {line}"))


def raw(text: str) -> None:
    """Generated source to stdout, byte for byte (no wrapping, no markup)."""
    import sys

    sys.stdout.write(text)
    if not text.endswith("\n"):
        sys.stdout.write("\n")


def note(message: str) -> None:
    stderr().print(Text(message, style="dim"))


@contextlib.contextmanager
def progress(label: str) -> Iterator:
    """A spinner naming the current step, on a terminal only; yields a step callback."""
    console = stderr()
    if not console.is_terminal:
        yield lambda step: None
        return
    with console.status(f"{label}…") as status:
        yield lambda step: status.update(f"{label}: {step}…")
