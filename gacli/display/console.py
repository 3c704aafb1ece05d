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
from gacli.read.textsafe import printable, quoted  # noqa: F401  (printable is re-exported)


def _width() -> int | None:
    # Tests and CI pin the width so wrapped output is reproducible.
    value = os.environ.get("GACLI_WIDTH")
    return int(value) if value and value.isdigit() else None


def stdout(width: int | None = None) -> Console:
    """Standard output; ``width`` past the pinned or detected one for what must not be cut."""
    return Console(highlight=False, width=width or _width(), soft_wrap=True)


def stderr() -> Console:
    return Console(stderr=True, highlight=False, width=_width(), soft_wrap=True)




_SEVERITY_STYLE = {"error": "bold red", "warning": "bold yellow", "note": "bold cyan"}


def diagnostics(items: Iterable[Diagnostic]) -> None:
    console = stderr()
    for d in items:
        line = Text()
        line.append(quoted(str(d.location)), style="bold")
        line.append(": ")
        line.append(f"{d.severity}:", style=_SEVERITY_STYLE.get(d.severity, "bold yellow"))
        line.append(f" {quoted(d.where)}: " if d.where else " ")
        line.append(quoted(d.message))
        if d.hint:
            line.append(f" ({quoted(d.hint)})", style="cyan")
        console.print(line)


def error(message: str, details: Iterable[str] = ()) -> None:
    """``error: message``, then each detail on a line of its own, indented.

    Each part is escaped on its own: a newline inside one (quoted from a
    file) stays ``\\n``, so no text can pass itself off as another line.
    """
    text = Text()
    text.append("error:", style="bold red")
    text.append(f" {quoted(message)}")
    for line in details:
        text.append(f"\n  {quoted(line)}")
    stderr().print(text)


def sections(title: str, items) -> None:
    """Print report sections (gacli.display.report.Section) to stdout."""
    console = stdout()
    if title:
        console.print(Text(printable(title), style="bold"))
    for section in items:
        console.print(Text(f"\n{printable(section.title)}", style="bold cyan"))
        for line in section.lines:
            console.print(Text(f"  {printable(line)}"))


def raw(text: str) -> None:
    """Generated source to stdout, as is but for characters that would drive the terminal.

    No wrapping, no markup. File text inside the source (a title in a
    comment) is escaped like every other line gacli prints; newlines and tabs
    are the source's own.
    """
    import sys

    text = printable(text, keep="\n\t")
    sys.stdout.write(text)
    if not text.endswith("\n"):
        sys.stdout.write("\n")


def note(message: str) -> None:
    stderr().print(Text(printable(message), style="dim"))


@contextlib.contextmanager
def progress(label: str) -> Iterator:
    """A spinner naming the current step, on a terminal only; yields a step callback."""
    console = stderr()
    if not console.is_terminal:
        yield lambda step: None
        return
    with console.status(f"{label}…") as status:
        yield lambda step: status.update(f"{label}: {step}…")
