"""Which files ``gacli check`` reads: names, directories (``*.yaml``, ``*.yml``) and globs."""

from __future__ import annotations

import glob
import os
from collections.abc import Iterable
from pathlib import Path

from gacli.check.report import PathsError

SUFFIXES = (".yaml", ".yml")


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
