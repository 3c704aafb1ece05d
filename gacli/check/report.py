"""What ``gacli check`` found, per file and for the run, and its renderers for machines.

:func:`to_json` and :func:`to_github` are pure; the rich table lives in
:mod:`gacli.check.console`.
"""

from __future__ import annotations

import json
from dataclasses import dataclass

from gacli.check.integrability import Classification
from gacli.errors import Diagnostic
from gacli.read.textsafe import printable, shortened

JSON_VERSION = 1
MAX_DIAGNOSTICS = 100  # per file; a file can hold thousands of errors (aliases)
_RANK = {"error": 0, "warning": 1, "note": 2}


def capped(diagnostics, limit: int = MAX_DIAGNOSTICS) -> tuple[Diagnostic, ...]:
    """The first ``limit`` problems in order, then one located line for the rest.

    The line stands at the first problem left out and carries the most severe
    severity among them, so a CI parser that wants every line located reads
    it, and a file whose errors all fall past the limit still fails; its text
    counts the rest by severity (docs/check.md, "Output and exit codes").
    """
    diagnostics = tuple(diagnostics)
    if len(diagnostics) <= limit:
        return diagnostics
    rest = diagnostics[limit:]
    worst = min((d.severity for d in rest), key=lambda s: _RANK.get(s, 0))
    counts = ", ".join(f"{n} {s}{'s' if n != 1 else ''}" for s in ("error", "warning", "note")
                       if (n := sum(d.severity == s for d in rest)))
    summary = Diagnostic(rest[0].location, f"{len(rest)} more problems not shown ({counts})", severity=worst)
    return diagnostics[:limit] + (summary,)


class PathsError(ValueError):
    """Some command-line paths match no file (a usage error, exit code 2)."""


@dataclass(frozen=True)
class MassMatrixCheck:
    """What is known about M: ``positive_definite`` is None when not checked (see ``note``)."""

    symmetric: bool | None
    positive_definite: bool | None
    samples: int
    note: str = ""


@dataclass(frozen=True)
class FileReport:
    """The outcome of checking one file."""

    path: str
    diagnostics: tuple[Diagnostic, ...] = ()
    classifications: tuple[Classification, ...] = ()
    k: int | None = None
    independent: tuple[str, ...] = ()
    mass_matrix: MassMatrixCheck | None = None
    elapsed: float = 0.0
    # Rolling rows that repeat the others: classified, but left out of the derivation's l.
    dependent: tuple[str, ...] = ()

    @property
    def errors(self) -> tuple[Diagnostic, ...]:
        return tuple(d for d in self.diagnostics if d.severity == "error")

    @property
    def warnings(self) -> tuple[Diagnostic, ...]:
        return tuple(d for d in self.diagnostics if d.severity == "warning")

    @property
    def notes(self) -> tuple[Diagnostic, ...]:
        """Shown, never failing, not even with ``strict``."""
        return tuple(d for d in self.diagnostics if d.severity == "note")

    def failed(self, strict: bool = False) -> bool:
        return bool(self.errors or (strict and self.warnings))

    def status(self, strict: bool = False) -> str:
        """"error", "warning" (fails only under ``strict``) or "ok"."""
        if self.errors:
            return "error"
        return "warning" if self.warnings else "ok"


@dataclass(frozen=True)
class Skipped:
    """A file found in a folder or glob and left out: not gacli YAML, or a link that leaves or loops."""

    path: str
    reason: str

    @property
    def kind(self) -> str:
        """The reason in a few words, for the count in the summary."""
        for start, kind in _KINDS:
            if self.reason.startswith(start):
                return kind
        return self.reason


_KINDS = (("not a gacli file", "not a gacli file"), ("a symbolic link that leads out", "a link out of its folder"),
          ("a symbolic link loop", "a link loop"), ("a symbolic link to a file that does not", "a dangling link"),
          ("not a regular file", "not a regular file"))


@dataclass(frozen=True)
class CheckReport:
    files: tuple[FileReport, ...]
    strict: bool = False
    skipped: tuple[Skipped, ...] = ()

    @property
    def failed(self) -> tuple[FileReport, ...]:
        return tuple(f for f in self.files if f.failed(self.strict))

    @property
    def exit_code(self) -> int:
        """0 when every file passes, 1 otherwise (black's Report.return_code)."""
        return 1 if self.failed else 0


# -- renderers -------------------------------------------------------------------

def to_json(report: CheckReport) -> str:
    """The report as JSON (sorted keys, stable layout), for machines."""
    files = [_file_json(f, report.strict) for f in report.files]
    summary = {
        "files": len(report.files), "failed": len(report.failed),
        "errors": sum(len(f.errors) for f in report.files),
        "warnings": sum(len(f.warnings) for f in report.files),
        "notes": sum(len(f.notes) for f in report.files), "skipped": len(report.skipped),
    }
    data = {"version": JSON_VERSION, "strict": report.strict, "exit_code": report.exit_code,
            "summary": summary, "files": files,
            "skipped": [{"path": s.path, "reason": s.reason} for s in report.skipped]}
    return json.dumps(_strict_text(data), sort_keys=True, indent=2) + "\n"


def _strict_text(value):
    """Every string as valid Unicode: a file name that is not UTF-8 reaches Python as lone
    surrogates (os.fsdecode), which json.dumps writes as ``\\udc80``, an escape strict readers
    (jq) refuse. Such a character is written as the text ``\\udc80`` instead, as printable() shows it."""
    if isinstance(value, str):
        return value.encode("utf-8", "backslashreplace").decode("utf-8")
    if isinstance(value, dict):
        return {_strict_text(k): _strict_text(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_strict_text(v) for v in value]
    return value


def _file_json(report: FileReport, strict: bool) -> dict:
    mass = report.mass_matrix
    return {
        "path": report.path, "status": report.status(strict), "failed": report.failed(strict),
        "k": report.k, "independent": list(report.independent), "elapsed": round(report.elapsed, 3),
        "dependent": list(report.dependent),
        "diagnostics": [_diagnostic_json(d) for d in report.diagnostics],
        "classifications": [
            {"kind": c.kind, "where": c.where, "text": c.text, "line": c.location.line,
             "column": c.location.column, "integrable": c.integrable, "verdict": c.verdict, "method": c.method,
             "test": c.test, "note": c.note}
            for c in report.classifications
        ],
        "mass_matrix": None if mass is None else {
            "symmetric": mass.symmetric, "positive_definite": mass.positive_definite,
            "samples": mass.samples, "note": mass.note,
        },
    }


def _diagnostic_json(d: Diagnostic) -> dict:
    # Quotes of file text kept short here too: a 900 kB scalar must not become one JSON string.
    return {"path": d.location.path, "line": d.location.line, "column": d.location.column,
            "severity": d.severity, "where": shortened(d.where), "message": shortened(d.message),
            "hint": shortened(d.hint)}


def to_github(report: CheckReport) -> str:
    """GitHub Actions workflow commands: one ``::error`` / ``::warning`` / ``::notice`` line per diagnostic.

    Escaped as GitHub's runner unescapes them (actions/toolkit, command.ts): in the
    message ``%``, CR and LF; in a property also ``:`` and ``,``, so that a file
    name cannot end its own ``file=`` or start another command.
    """
    lines = []
    for file in report.files:
        for d in file.diagnostics:
            level = {"error": "error", "note": "notice"}.get(d.severity, "warning")
            properties = f"file={_gh_property(d.location.path)},line={d.location.line},col={d.location.column}"
            where = f"{d.where}: " if d.where else ""
            hint = f" ({d.hint})" if d.hint else ""
            lines.append(f"::{level} {properties},title=gacli check::{_gh_data(where + d.message + hint)}")
    if report.skipped:
        lines.append(f"::notice title=gacli check::{_gh_data(skipped_summary(report.skipped))}")
    return "".join(line + "\n" for line in lines)


def skipped_summary(skipped: tuple[Skipped, ...]) -> str:
    """``skipped 3 files (not a gacli file: 2, a link out of its folder: 1)``."""
    kinds: dict[str, int] = {}
    for s in skipped:
        kinds[s.kind] = kinds.get(s.kind, 0) + 1
    count = len(skipped)
    return f"skipped {count} file{'' if count == 1 else 's'} (" + ", ".join(
        f"{kind}: {n}" for kind, n in sorted(kinds.items())) + ")"


def _escape(text: str) -> str:
    # GitHub's escapes first (a line break in a message is one in the annotation), then
    # every other control character shown as an escape, as in the terminal.
    return printable(text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A"))


def _gh_data(text: str) -> str:
    return _escape(shortened(text))


def _gh_property(text: str) -> str:
    # Never shortened: the file property is the annotation's location, whole or not at all.
    return _escape(_strict_text(text)).replace(":", "%3A").replace(",", "%2C")
