"""``gacli check``: validate system files the way a CI gate needs.

For each file: read it (within the size, depth and alias limits of
:mod:`gacli.read.source`), load it (every expression parsed by the restricted
grammar), derive the equations, classify each constraint and quasi-coordinate
(:mod:`gacli.check.integrability`) and check that M is symmetric, has no undefined
entries and is positive definite at a few seeded sample states (when every
parameter has a value). Unused parameters and coordinates are warnings; an
input that no load uses is a note, which never fails (see docs/check.md).

Every problem becomes a :class:`~gacli.errors.Diagnostic`; nothing a file
contains can make this module raise. A wall-clock budget per file (SIGALRM,
main thread only) turns a runaway step into an error that names the step.
The renderers :func:`to_json` and :func:`to_github` are pure; the rich table
lives in :mod:`gacli.check.console`.
"""

from __future__ import annotations

import stat
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace
from pathlib import Path

from gacli.budget import DEFAULT_TIMEOUT, STEP_READ, forget_frames  # one name for each step, shared with every command
from gacli.check.declarations import unused_declarations
from gacli.check.integrability import Classification, classify
from gacli.check.mass import check_mass_matrix
from gacli.check.paths import find
from gacli.check.report import MAX_DIAGNOSTICS, CheckReport, FileReport, MassMatrixCheck, capped
from gacli.pipeline import CLOSED, MATRICES
from gacli.pipeline import run as run_pipeline
from gacli.errors import (
    DerivationError,
    Diagnostic,
    GacliError,
    Location,
    OutOfTime,
    SystemFileError,
)
from gacli.display.report import dependent_rows
from gacli.numeric.zero import time_limit


STEP_CLASSIFY = "classifying constraints and quasi-coordinates (Frobenius)"
STEP_MASS = "checking M (symmetric, positive definite)"


# -- one file ----------------------------------------------------------------

@dataclass
class _Findings:
    """What is learned about a file so far; a late failure keeps the early findings."""

    path: str
    step: str = STEP_READ
    expired: bool = False
    diagnostics: list[Diagnostic] = field(default_factory=list)
    classifications: tuple[Classification, ...] = ()
    k: int | None = None
    independent: tuple[str, ...] = ()
    mass_matrix: MassMatrixCheck | None = None
    dependent: tuple[str, ...] = ()

    def __call__(self, step: str) -> None:  # derive's progress callback
        self.step = step

    def error(self, message: str, where: str = "", hint: str = "", location: Location | None = None) -> None:
        self.diagnostics.append(Diagnostic(location or Location(self.path, 1, 1), message, where, hint))


def check_file(path: str | Path, *, timeout: float | None = DEFAULT_TIMEOUT, verify: bool = False) -> FileReport:
    """Check one system file; every problem is a Diagnostic in the report, never an exception.

    ``timeout`` is the wall-clock budget in seconds (None or 0: none); it is
    enforced only in the main thread.
    """
    start = time.perf_counter()
    findings = _Findings(str(path))
    try:
        with time_limit(timeout or 0, _expiry(findings, timeout)):
            _check(Path(path), findings, verify)
    except SystemFileError as exc:
        findings.diagnostics.extend(exc.diagnostics)
        forget_frames(exc)  # a folder of runaway files must not keep each one's half-built expressions
    except GacliError as exc:
        findings.error(str(exc))
        forget_frames(exc)
    except Exception as exc:  # noqa: BLE001 - one broken file must not stop the gate
        _crashed(findings, exc, timeout)
        forget_frames(exc)
    return FileReport(
        path=str(path), diagnostics=_tidy(findings.diagnostics, str(path)),
        classifications=findings.classifications, k=findings.k, independent=findings.independent,
        mass_matrix=findings.mass_matrix, elapsed=time.perf_counter() - start, dependent=findings.dependent,
    )


def _crashed(findings: _Findings, exc: Exception, timeout: float | None) -> None:
    """A bug in gacli (or the budget's error, rewrapped by a library) as one diagnostic."""
    if findings.expired:
        findings.error(_timeout_message(findings.step, timeout))
        return
    detail = str(exc) if len(str(exc)) <= 200 else str(exc)[:200] + "..."
    findings.error(f"internal error in the step '{findings.step}': {type(exc).__name__}: {detail}".rstrip(": "),
                   hint="this is a bug in gacli; please report it")


STEP_VERIFY = "verifying by the independent route (eq. 14.10)"


def _check(path: Path, findings: _Findings, verify: bool = False) -> None:
    findings(STEP_READ)
    _require_regular_file(path)
    # Without verify, check reads M, F and q̇ alone, as generated code computes them (the closed forms
    # only where the program builder does not take the system): what CI runs and what users integrate.
    run = run_pipeline(path, needs=CLOSED if verify else MATRICES, progress=findings,
                       loaded=lambda system: findings.diagnostics.extend(unused_declarations(system)))
    system, derivation = run.system, run.derivation
    findings.k, findings.independent = derivation.k, derivation.independent
    findings.dependent = dependent_rows(derivation)
    findings(STEP_CLASSIFY)
    findings.classifications = classify(system)
    findings.diagnostics.extend(_undecided_notes(findings.classifications))
    findings(STEP_MASS)
    findings.mass_matrix = check_mass_matrix(derivation, findings)
    if verify:
        findings(STEP_VERIFY)
        _verify(system, derivation, findings)


def _undecided_notes(classifications: Iterable[Classification]) -> list[Diagnostic]:
    """Why a verdict is undecided, at the constraint: a note, since an honest 'undecided' is no fault."""
    return [Diagnostic(c.location, f"{c.verdict}: {c.note}", c.where, severity="note")
            for c in classifications if c.integrable is None and c.note]


def _verify(system, derivation, findings: _Findings) -> None:
    """gacli verify's check as diagnostics: each failing equation is one error."""
    from gacli.verify import verify

    report = verify(system, derivation)
    for failure in report.failures:
        findings.error(f"verify: {failure}")


def _require_regular_file(path: Path) -> None:
    """A FIFO or a device (a symlink to /dev/zero) would be read forever."""
    try:
        mode = path.stat().st_mode
    except OSError as exc:
        raise _file_error(path, f"cannot read the file: {exc.strerror or exc}") from None
    if stat.S_ISDIR(mode):
        raise _file_error(path, "this is a directory, not a system file")
    if not stat.S_ISREG(mode):
        raise _file_error(path, "not a regular file (a device, socket or pipe)")


def _file_error(path: Path, message: str) -> SystemFileError:
    return SystemFileError([Diagnostic(Location(str(path), 1, 1), message)])


def _tidy(diagnostics: list[Diagnostic], path: str) -> tuple[Diagnostic, ...]:
    """Locate file-level problems at 1:1, sort by place, and cap the count."""
    located = [d if d.location.line > 0 else replace(d, location=Location(d.location.path or path, 1, 1))
               for d in diagnostics]
    return capped(sorted(located, key=lambda d: (d.location, d.severity != "error")))


# -- the time budget -----------------------------------------------------------

def _timeout_message(step: str, seconds: float | None) -> str:
    return f"ran out of time in the step '{step}' (the budget is {seconds:g} s per file; raise it with --timeout)"


def _expiry(findings: _Findings, seconds: float | None) -> Callable[[], DerivationError]:
    """The error the time budget raises: it names the step that was running."""
    def error() -> DerivationError:
        findings.expired = True
        return OutOfTime(_timeout_message(findings.step, seconds))
    return error


# -- many files ----------------------------------------------------------------

def check_paths(
    patterns: Iterable[str | Path], *, timeout: float | None = DEFAULT_TIMEOUT, strict: bool = False,
    verify: bool = False,
    on_file: Callable[[Path], None] | None = None,
    skip_other_yaml: bool = False,
) -> CheckReport:
    """Expand the patterns (PathsError if one matches nothing) and check every file.

    A named file that is not to be read (a link out of its boundary,
    gacli.check.paths) is an error in its report, never opened; what a folder
    or glob turned up and was left out is listed in ``skipped``.
    """
    found = find(patterns, skip_other_yaml=skip_other_yaml)
    refused = dict(found.refused)
    reports = []
    for path in found.files:
        if on_file is not None:
            on_file(path)
        if path in refused:
            reports.append(FileReport(str(path), (Diagnostic(Location(str(path), 1, 1), refused[path]),)))
        else:
            reports.append(check_file(path, timeout=timeout, verify=verify))
    return CheckReport(tuple(reports), strict, found.skipped)
