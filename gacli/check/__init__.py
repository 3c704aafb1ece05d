"""``gacli check``: validate system files the way a CI gate needs.

For each file (:mod:`~gacli.check.run`): read it (within the size, depth and
alias limits of :mod:`gacli.read.source`), load it (every expression parsed by the
restricted grammar), derive the equations, classify each constraint and
quasi-coordinate (:mod:`~gacli.check.integrability`, with the exterior
calculus of :mod:`~gacli.check.exterior`) and check that M is symmetric, has
no undefined entries and is positive definite at a few seeded sample states
when every parameter has a value (:mod:`~gacli.check.mass`). Unused
parameters and coordinates are warnings; an input that no load uses is a
note, which never fails (:mod:`~gacli.check.declarations`, docs/check.md).

Every problem becomes a :class:`~gacli.errors.Diagnostic`; nothing a file
contains can make this package raise. The report and its pure renderers are
in :mod:`~gacli.check.report`; the rich table in :mod:`~gacli.check.console`.
"""

from gacli.budget import STEP_LOAD, STEP_READ
from gacli.check.declarations import unused_declarations
from gacli.check.paths import SUFFIXES, Found, expand_paths, find
from gacli.check.report import (
    JSON_VERSION, CheckReport, capped, FileReport, MassMatrixCheck, PathsError, Skipped, to_github, to_json,
)
from gacli.check.run import (
    DEFAULT_TIMEOUT,
    MAX_DIAGNOSTICS,
    STEP_CLASSIFY,
    STEP_MASS,
    STEP_VERIFY,
    check_file,
    check_paths,
)

__all__ = [
    "DEFAULT_TIMEOUT", "JSON_VERSION", "capped", "MAX_DIAGNOSTICS", "STEP_CLASSIFY", "STEP_LOAD", "STEP_MASS", "STEP_READ",
    "STEP_VERIFY", "SUFFIXES", "CheckReport", "FileReport", "Found", "MassMatrixCheck", "PathsError", "Skipped",
    "check_file", "check_paths", "expand_paths", "find", "to_github", "to_json", "unused_declarations",
]
