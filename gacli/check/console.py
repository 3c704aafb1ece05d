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

from gacli.display import console
from gacli.check.report import CheckReport, FileReport, skipped_summary
from gacli.display.console import printable
from gacli.display.report import rank_note

_STATUS_STYLE = {"ok": "green", "warning": "yellow", "error": "bold red"}


def show(report: CheckReport) -> None:
    """Diagnostics (stderr), then one table row per file and a summary line (stdout)."""
    for file in report.files:
        console.diagnostics(file.diagnostics)  # escapes and shortens what the file wrote
    for skipped in report.skipped:
        if skipped.kind != "not a gacli file":  # a link a pull request added is worth a line of its own
            # Located as a problem of the whole file is (1:1), so that every stderr line parses alike.
            console.note(f"{skipped.path}:1:1: note: skipped, {skipped.reason}")
    out = console.stdout()
    table = _table(report, out.width)
    needed = sum(c.width for c in table.columns) + 2 * (len(table.columns) - 1)  # as _fit lays them out
    # Laid out to the width, not run on; wider only where the unbreakable columns need it (a CI log's long
    # paths at 80 columns), so that a path or a time is never cut.
    wide = out if needed <= out.width else console.stdout(needed)
    wide.print(table, soft_wrap=False, crop=False)
    out.print(_summary(report))


def _table(report: CheckReport, width: int) -> Table:
    # At 80 columns a file name must stay whole (it is what one copies), so
    # the file column never wraps and the others are made of short words that
    # fold between them: verdicts counted, not one line per constraint. k is
    # not a column: it is the length of the independent set beside it.
    table = Table(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False, padding=(0, 1, 0, 0))
    table.add_column("file", no_wrap=True)
    table.add_column("result")
    table.add_column("independent")
    table.add_column("constraints")
    table.add_column("time", justify="right", no_wrap=True)
    for file in report.files:
        table.add_row(
            Text(printable(file.path)), _result(file, report.strict),
            Text(printable(", ".join(file.independent))),
            Text("\n".join(map(printable, _classified(file)))), Text(f"{file.elapsed:.1f}s"),
        )
    _fit(table, width)
    return table


def _fit(table: Table, width: int) -> None:
    """Narrow the widest wrapping columns first, never below their longest word.

    Rich shares a shortage out in proportion, which cuts words (and headers)
    it could have wrapped; here only whole words move to the next line.
    """
    cells = [[str(c) for c in (column.header, *column.cells)] for column in table.columns]
    natural = [max(len(line) for cell in column for line in cell.splitlines() or [""]) for column in cells]
    floor = [n if column.no_wrap else max((len(w) for cell in cells[i] for w in cell.split()), default=1)
             for i, (column, n) in enumerate(zip(table.columns, natural))]
    widths = list(natural)
    excess = sum(widths) + 2 * (len(widths) - 1) - width  # a divider and a pad between columns
    while excess > 0:
        i = max(range(len(widths)), key=lambda j: (widths[j] - floor[j], widths[j]))
        if widths[i] <= floor[i]:
            break
        widths[i] -= 1
        excess -= 1
    for column, w in zip(table.columns, widths):
        column.width = w


def _classified(file: FileReport) -> list[str]:
    """``4 non-holonomic (4 rows, rank 3: ...)``, then ``s: not a coordinate`` per quasi-coordinate."""
    verdicts: dict[str, int] = {}
    for c in file.classifications:
        if c.kind == "constraint":
            verdicts[c.verdict] = verdicts.get(c.verdict, 0) + 1
    lines = [", ".join(f"{n} {verdict}" for verdict, n in verdicts.items())] if verdicts else []
    if file.dependent and lines:  # no verdicts when the check stopped before classifying
        lines[0] += f" ({rank_note(sum(verdicts.values()), file.dependent)})"
    lines += [f"{c.where.rsplit('.', 1)[-1]}: {c.verdict}" for c in file.classifications if c.kind != "constraint"]
    return lines


def _result(file: FileReport, strict: bool) -> Text:
    status = file.status(strict)
    parts = []
    if file.errors:
        parts.append(_count(len(file.errors), "error"))
    if file.warnings:
        parts.append(_count(len(file.warnings), "warning"))
    if file.notes:
        parts.append(_count(len(file.notes), "note"))
    style = "bold red" if file.failed(strict) else _STATUS_STYLE[status]
    return Text(", ".join(parts if file.errors or file.warnings else ["ok", *parts]), style=style)


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
    if report.skipped:
        text.append(f"; {skipped_summary(report.skipped)}")
    return text
