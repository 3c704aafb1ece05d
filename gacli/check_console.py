"""How ``gacli check`` shows its report to a person (rich; UI only).

Diagnostics go to stderr as ``file:line:col: severity: ...`` lines, the
summary table to stdout. Everything that comes from a file (paths, names,
messages) is shown as plain text, never as markup, with control characters
escaped, so a hostile file cannot restyle or clear the terminal.
"""

from __future__ import annotations

from rich import box
from rich.table import Table
from rich.text import Text

from gacli import console
from gacli.check import CheckReport, FileReport
from gacli.console import printable

_STATUS_STYLE = {"ok": "green", "warning": "yellow", "error": "bold red"}


def show(report: CheckReport) -> None:
    """Diagnostics (stderr), then one table row per file and a summary line (stdout)."""
    for file in report.files:
        console.diagnostics(file.diagnostics)  # escapes and shortens what the file wrote
    out = console.stdout()
    out.print(_table(report))
    out.print(_summary(report))


def _table(report: CheckReport) -> Table:
    table = Table(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False)
    table.add_column("file", overflow="fold")
    table.add_column("result")
    table.add_column("k", justify="right")
    table.add_column("independent")
    table.add_column("constraints and quasi-coordinates")
    table.add_column("time", justify="right", no_wrap=True)
    for file in report.files:
        table.add_row(
            Text(printable(file.path)), _result(file, report.strict),
            Text("" if file.k is None else str(file.k)), Text(printable(", ".join(file.independent))),
            Text("\n".join(printable(f"{c.where}: {c.verdict}") for c in file.classifications)),
            Text(f"{file.elapsed:.1f} s"),
        )
    return table


def _result(file: FileReport, strict: bool) -> Text:
    status = file.status(strict)
    parts = []
    if file.errors:
        parts.append(_count(len(file.errors), "error"))
    if file.warnings:
        parts.append(_count(len(file.warnings), "warning"))
    style = "bold red" if file.failed(strict) else _STATUS_STYLE[status]
    return Text(", ".join(parts) or "ok", style=style)


def _count(n: int, word: str) -> str:
    return f"{n} {word}" + ("" if n == 1 else "s")


def _summary(report: CheckReport) -> Text:
    failed = len(report.failed)
    total = len(report.files)
    text = Text()
    if failed:
        text.append(f"{failed} of {_count(total, 'file')} failed", style="bold red")
    else:
        text.append(f"all {_count(total, 'file')} passed", style="bold green")
    if report.strict:
        text.append(" (--strict: warnings fail)")
    return text
