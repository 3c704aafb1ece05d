"""``gacli check``: validate system files the way a CI gate needs.

For each file: read it (within the size, depth and alias limits of
:mod:`gacli.source`), load it (every expression parsed by the restricted
grammar), derive the equations, classify each constraint and quasi-coordinate
(:mod:`gacli.integrability`) and check that M is symmetric, has no undefined
entries and is positive definite at a few seeded sample states (when every
parameter has a value). Unused parameters and coordinates are warnings; an
input that no load uses is a note, which never fails (see docs/check.md).

Every problem becomes a :class:`~gacli.errors.Diagnostic`; nothing a file
contains can make this module raise. A wall-clock budget per file (SIGALRM,
main thread only) turns a runaway step into an error that names the step.
The renderers :func:`to_json` and :func:`to_github` are pure; the rich table
lives in :mod:`gacli.check_console`.
"""

from __future__ import annotations

import glob
import json
import os
import stat
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
import sympy as sp

from gacli import symbols as S
from gacli.budget import STEP_LOAD, STEP_READ, forget_frames  # one name for each step, shared with every command
from gacli.equations import Derivation, derive
from gacli.errors import (
    DerivationError,
    Diagnostic,
    GacliError,
    Location,
    SystemFileError,
)
from gacli.integrability import Classification, classify, decide_zero, time_limit
from gacli.loading import load_source
from gacli.model import System
from gacli.numeric import UndefinedValue, evaluate, parameter_values, sample_points
from gacli.report import dependent_rows
from gacli.graph import free_symbols, postorder
from gacli.source import read_source
from gacli.textsafe import printable, shortened

DEFAULT_TIMEOUT = 60.0
SUFFIXES = (".yaml", ".yml")
MAX_DIAGNOSTICS = 100  # per file; a file can hold thousands of errors (aliases)
PD_SAMPLES = 3
JSON_VERSION = 1

STEP_CLASSIFY = "classifying constraints and quasi-coordinates (Frobenius)"
STEP_MASS = "checking M (symmetric, positive definite)"


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
class CheckReport:
    files: tuple[FileReport, ...]
    strict: bool = False

    @property
    def failed(self) -> tuple[FileReport, ...]:
        return tuple(f for f in self.files if f.failed(self.strict))

    @property
    def exit_code(self) -> int:
        """0 when every file passes, 1 otherwise (black's Report.return_code)."""
        return 1 if self.failed else 0


# -- which files -------------------------------------------------------------

def expand_paths(patterns: Iterable[str | Path]) -> list[Path]:
    """Files named, found in directories (``*.yaml``, ``*.yml``, sorted) or matched by globs.

    Hidden files and directories are skipped inside directories. Raises
    PathsError naming every pattern that matches nothing.
    """
    found: list[Path] = []
    missing: list[str] = []
    empty: list[str] = []
    for pattern in patterns:
        matches = _expand_one(str(pattern))
        if not matches:
            (empty if Path(pattern).is_dir() else missing).append(str(pattern))
        found.extend(matches)
    problems = []
    if missing:
        problems.append(f"no such file, directory or match: {', '.join(missing)}")
    if empty:
        problems.append(f"no system files (*.yaml, *.yml) in {', '.join(empty)}")
    if problems:
        raise PathsError("; ".join(problems))
    return list(dict.fromkeys(found))


def _expand_one(pattern: str) -> list[Path]:
    path = Path(pattern)
    if path.is_dir():
        return _system_files(path)
    if path.exists() or path.is_symlink():
        return [path]
    if not glob.has_magic(pattern):
        return []
    out: list[Path] = []
    for match in sorted(glob.glob(pattern, recursive=True)):
        p = Path(match)
        out.extend(_system_files(p) if p.is_dir() else [p] if p.name.endswith(SUFFIXES) else [])
    return out


def _system_files(directory: Path) -> list[Path]:
    """System files under ``directory``; a symlink leading out of it is not followed."""
    top = directory.resolve()
    out = []
    for root, dirs, files in os.walk(directory):  # does not enter symlinked directories
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        candidates = (Path(root, f) for f in files if f.endswith(SUFFIXES) and not f.startswith("."))
        out.extend(p for p in candidates if not p.is_symlink() or p.resolve().is_relative_to(top))
    return sorted(out, key=lambda p: p.parts)


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
    source = read_source(path)
    findings(STEP_LOAD)
    system = load_source(source)
    findings.diagnostics.extend(unused_declarations(system))
    derivation = derive(system, progress=findings)
    findings.k, findings.independent = derivation.k, derivation.independent
    findings.dependent = dependent_rows(derivation)
    findings(STEP_CLASSIFY)
    findings.classifications = classify(system)
    findings.diagnostics.extend(_undecided_notes(findings.classifications))
    findings(STEP_MASS)
    findings.mass_matrix = _check_mass_matrix(derivation, findings)
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
    ordered = sorted(located, key=lambda d: (d.location, d.severity != "error"))
    if len(ordered) <= MAX_DIAGNOSTICS:
        return tuple(ordered)
    rest = len(ordered) - MAX_DIAGNOSTICS
    more = Diagnostic(ordered[MAX_DIAGNOSTICS].location, f"{rest} more problems not shown")
    return tuple(ordered[:MAX_DIAGNOSTICS]) + (more,)


# -- the time budget -----------------------------------------------------------

def _timeout_message(step: str, seconds: float | None) -> str:
    return f"ran out of time in the step '{step}' (the budget is {seconds:g} s per file; raise it with --timeout)"


def _expiry(findings: _Findings, seconds: float | None) -> Callable[[], DerivationError]:
    """The error the time budget raises: it names the step that was running."""
    def error() -> DerivationError:
        findings.expired = True
        return DerivationError(_timeout_message(findings.step, seconds))
    return error


# -- warnings ------------------------------------------------------------------

def unused_declarations(system: System) -> list[Diagnostic]:
    """Warnings (unused parameters, coordinates no body depends on) and notes (unused inputs).

    An input is the generated code's interface as much as the model's: a file
    may declare a whole force vector (F_x, F_y, F_z) of which a constraint
    makes one component do no work, and ``--strict`` in CI must not fail it
    for that. So an unused input is a note: shown, but never failing.
    """
    used = _symbols_used(system)
    loads = [e for f in system.forces for e in f.vector] + [e for t in system.torques for e in t.vector]
    loaded = _form_symbols(system.work) | free_symbols(loads)
    bodies = _body_dependencies(system)
    out = []
    for p in system.parameters:
        if S.value(p.name) not in used:
            out.append(_warning(p.location, f"parameters.{p.name}", f"parameter '{p.name}' is not used"))
    for i in system.inputs:
        if S.value(i.name) not in loaded:
            out.append(Diagnostic(i.location, f"input '{i.name}' is declared but no load uses it "
                                  "(it stays an input of the generated code, with no effect)",
                                  f"inputs.{i.name}", severity="note"))
    for c in system.coordinates:
        if c.name not in bodies:
            out.append(_warning(c.location, f"coordinates.{c.name}",
                                f"no body depends on coordinate '{c.name}' (it is in no position or rotation)"))
    return out


def _warning(location: Location, where: str, message: str) -> Diagnostic:
    return Diagnostic(location, message, where, severity="warning")


def _form_symbols(form) -> set:
    if form is None:
        return set()
    return free_symbols([form.dt, *(c for _, c in form.coefficients)])


def _symbols_used(system: System) -> set:
    """Every symbol in an expression of the system, parameter and function values included."""
    exprs: list = [p.value for p in system.parameters] + [f.value for f in system.functions]
    for body in system.bodies:
        exprs += [body.mass, *body.position]
        exprs += list(body.inertia) if body.inertia is not None else []
    exprs += [e for f in system.forces for e in (*f.vector, *f.point)]
    exprs += [e for t in system.torques for e in t.vector] + [system.potential]
    exprs += [c.relation for c in system.constraints]
    used = free_symbols([e for e in exprs if e is not None])
    forms = [c.form for c in system.constraints] + [q.differential for q in system.quasi_coordinates]
    forms += [f for b in system.bodies if b.rotation for f in b.rotation] + [system.work]
    return used.union(*(_form_symbols(f) for f in forms))


def _body_dependencies(system: System) -> set[str]:
    """Names of the coordinates in a position or in a rotation (as a value or a differential)."""
    names: set[str] = set()
    coordinates = {S.value(c.name): c.name for c in system.coordinates}
    for body in system.bodies:
        symbols = free_symbols(body.position)
        for form in body.rotation or ():
            symbols |= _form_symbols(form)
            names.update(form.names)
        names.update(coordinates[s] for s in symbols if s in coordinates)
    return names


# -- M -----------------------------------------------------------------------

_UNDEFINED = (sp.zoo, sp.nan, sp.oo, -sp.oo)


def _check_mass_matrix(derivation: Derivation, findings: _Findings) -> MassMatrixCheck:
    M, F = derivation.mass_matrix, derivation.forcing
    system = derivation.system
    where = system.location
    nodes = set(postorder([*M, *F, *(e for _, e in derivation.kinematic_equations)]))
    if any(node in nodes for node in _UNDEFINED):
        findings.error("the equations contain an undefined value (zoo or nan: a division by zero or a "
                       "logarithm of zero somewhere in the file)", "equations", location=where)
    if sp.I in nodes:  # the loader refuses an imaginary expression; this is the last guard
        findings.error("the equations contain the imaginary unit I: M, F and the kinematic equations must be real",
                       "equations", location=where)
    symmetric = _symmetric(M, findings, where)
    values, missing = parameter_values(system)
    if missing:
        note = f"not checked: no value for {', '.join(missing)}"
        return MassMatrixCheck(symmetric, None, 0, note)
    return _positive_definite(system, M, values, symmetric, findings, where)


def _symmetric(M: sp.ImmutableMatrix, findings: _Findings, where: Location) -> bool | None:
    answer: bool | None = True
    for i in range(M.rows):
        for j in range(i + 1, M.cols):
            decision = decide_zero(M[i, j] - M[j, i])
            if decision.zero is False:
                findings.error(f"M is not symmetric: M[{i}, {j}] != M[{j}, {i}]", "mass_matrix", location=where)
                return False
            if decision.zero is None:
                answer = None
    return answer


def _positive_definite(system: System, M, values, symmetric, findings: _Findings,
                       where: Location) -> MassMatrixCheck:
    others = sorted(free_symbols(M) - set(values), key=lambda s: s.name)
    # Symbols only in positions get values too, from their own stream: M's samples stay as they were.
    placed = free_symbols([c for body in system.bodies for c in body.position]) - set(values) - set(others)
    evaluated = 0
    for point, more in zip(sample_points(others, PD_SAMPLES), sample_points(placed, PD_SAMPLES, seed=11)):
        state = {**values, **more, **point}
        try:
            _require_real_positions(system, state)
            numeric = np.array([[float(evaluate(M[i, j], state)[0]) for j in range(M.cols)] for i in range(M.rows)])
        except UndefinedValue:
            continue
        evaluated += 1
        smallest = float(np.linalg.eigvalsh((numeric + numeric.T) / 2).min()) if M.rows else 1.0
        if smallest <= 1e-12 * max(1.0, float(np.abs(numeric).max())):
            shown = ", ".join(f"{s.name}={v:.4g}" for s, v in point.items())
            at = f"at the sample state {shown}" if shown else "at every state (M is constant)"
            findings.error(f"M is not positive definite {at} "
                           f"(smallest eigenvalue {smallest:.3g})", "mass_matrix",
                           "check the masses and inertias, and that every independent rate moves some body",
                           location=where)
            return MassMatrixCheck(symmetric, False, evaluated)
    if evaluated == 0:
        return MassMatrixCheck(symmetric, None, 0, "not checked: M has no real value at the sample states")
    return MassMatrixCheck(symmetric, True, evaluated)


def _require_real_positions(system: System, state) -> None:
    """UndefinedValue when a position is not real at the state: M there says nothing of the file.

    ``sqrt(1 - x**2)`` is a position only for |x| <= 1; beyond, M is real but meaningless.
    """
    for body in system.bodies:
        for coordinate in body.position:
            evaluate(coordinate, state)


# -- many files ----------------------------------------------------------------

def check_paths(
    patterns: Iterable[str | Path], *, timeout: float | None = DEFAULT_TIMEOUT, strict: bool = False,
    verify: bool = False,
    on_file: Callable[[Path], None] | None = None,
) -> CheckReport:
    """Expand the patterns (PathsError if one matches nothing) and check every file."""
    reports = []
    for path in expand_paths(patterns):
        if on_file is not None:
            on_file(path)
        reports.append(check_file(path, timeout=timeout, verify=verify))
    return CheckReport(tuple(reports), strict)


# -- renderers -------------------------------------------------------------------

def to_json(report: CheckReport) -> str:
    """The report as JSON (sorted keys, stable layout), for machines."""
    files = [_file_json(f, report.strict) for f in report.files]
    summary = {
        "files": len(report.files), "failed": len(report.failed),
        "errors": sum(len(f.errors) for f in report.files),
        "warnings": sum(len(f.warnings) for f in report.files),
        "notes": sum(len(f.notes) for f in report.files),
    }
    data = {"version": JSON_VERSION, "strict": report.strict, "exit_code": report.exit_code,
            "summary": summary, "files": files}
    return json.dumps(data, sort_keys=True, indent=2) + "\n"


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
    """GitHub Actions workflow commands: one ``::error`` / ``::warning`` / ``::notice`` line per diagnostic."""
    lines = []
    for file in report.files:
        for d in file.diagnostics:
            level = {"error": "error", "note": "notice"}.get(d.severity, "warning")
            properties = f"file={_gh_property(d.location.path)},line={d.location.line},col={d.location.column}"
            where = f"{d.where}: " if d.where else ""
            hint = f" ({d.hint})" if d.hint else ""
            lines.append(f"::{level} {properties},title=gacli check::{_gh_data(where + d.message + hint)}")
    return "".join(line + "\n" for line in lines)


def _gh_data(text: str) -> str:
    return printable(shortened(text).replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A"))


def _gh_property(text: str) -> str:
    return _gh_data(text).replace(":", "%3A").replace(",", "%2C")
