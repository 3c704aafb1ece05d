"""Which files ``gacli check`` reads: names, directories (``*.yaml``, ``*.yml``) and globs.

A pull request must not make the gate read, and quote into a CI log, a file
elsewhere on the runner: a symbolic link is followed only while it stays in
its *boundary* (the directory given; for a glob, the directory before its
first wildcard, the working directory for ``**/*.yaml``; for a file named on
the command line, the working directory when the name is inside it, else the
file's own directory). A link that leaves, or that loops, is not opened.

In a directory or a glob, YAML that is not a gacli file (no top-level
``gacli:`` key: a CI workflow, a docker-compose file) is skipped and counted;
so are named files with ``skip_other_yaml`` (what the pre-commit hook hands
over is every YAML file of a repository). Nothing is opened that is not a
regular file, so a FIFO cannot hang the search.
"""

from __future__ import annotations

import errno
import glob
import os
import re
import stat
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from gacli.check.report import PathsError, Skipped
from gacli.errors import SystemFileError
from gacli.read.source import Mapping, parse_source

SUFFIXES = (".yaml", ".yml")

# A gacli file says so at the top level: `gacli: 1` (docs/system-file.md). Searched in
# the first bytes only: the key leads every file gacli writes and the spec's examples.
_GACLI_KEY = re.compile(rb"^(?:gacli|\"gacli\"|'gacli')[ \t]*:", re.MULTILINE)
_SNIFF_BYTES = 65_536

LEAVES = "a symbolic link that leads out of {boundary}; not followed"
LOOPS = "a symbolic link loop; not followed"
DANGLING = "a symbolic link to a file that does not exist; not followed"
NOT_GACLI = "not a gacli file (no top-level 'gacli:' key)"
NOT_REGULAR = "not a regular file (a device, socket or pipe); not read"


@dataclass(frozen=True)
class Found:
    """What the patterns name: the files to check, refusals of named files, and what was skipped."""

    files: tuple[Path, ...]                      # in the order found; the refused among them are not read
    refused: tuple[tuple[Path, str], ...] = ()   # named on the command line, but not to be read: an error each
    skipped: tuple[Skipped, ...] = ()            # found in a folder or glob (or not gacli YAML): counted, not errors


def expand_paths(patterns: Iterable[str | Path]) -> list[Path]:
    """The files :func:`find` would read (for callers that only want the list)."""
    found = find(patterns)
    refused = dict(found.refused)
    return [p for p in found.files if p not in refused]


def find(patterns: Iterable[str | Path], *, skip_other_yaml: bool = False) -> Found:
    """Files named, found in directories (sorted) or matched by globs, within their boundaries.

    Hidden files and directories are skipped inside directories. Raises
    PathsError naming every pattern that matches nothing.
    """
    files: dict[Path, None] = {}
    refused: dict[Path, str] = {}
    skipped: dict[Path, str] = {}
    missing, empty = [], []
    for pattern in map(str, patterns):
        named, candidates, boundary = _expand_one(pattern)
        if not candidates:
            (empty if Path(pattern).is_dir() else missing).append(pattern)
        for path in candidates:
            why = _refusal(path, boundary) or (None if named and not skip_other_yaml else _not_gacli(path))
            if why is None or (named and why != NOT_GACLI):
                files[path] = None
                if why is not None:
                    refused[path] = why
            else:
                skipped[path] = why
    _raise_for(missing, empty)
    return Found(tuple(files), tuple(refused.items()),
                 tuple(Skipped(str(p), why) for p, why in skipped.items() if p not in files))


def _raise_for(missing: list[str], empty: list[str]) -> None:
    problems = []
    if missing:
        problems.append(f"no such file, directory or match: {', '.join(missing)}")
    if empty:
        problems.append(f"no system files (*.yaml, *.yml) in {', '.join(empty)}")
    if problems:
        raise PathsError("; ".join(problems))


def _expand_one(pattern: str) -> tuple[bool, list[Path], Path]:
    """(named on the command line, the candidates, their boundary)."""
    path = Path(pattern)
    if path.is_dir():
        return False, _system_files(path), path
    if path.exists() or path.is_symlink():
        return True, [path], _named_boundary(path)
    if not glob.has_magic(pattern):
        return True, [], path
    root, rest = _split_glob(pattern)
    if not rest or not root.is_dir():
        return False, [], root
    out: list[Path] = []
    # pathlib's ** does not enter linked directories (no loop); a link a plain * meets is
    # judged by _refusal against the boundary, like any other.
    for match in sorted(root.glob(rest), key=lambda p: p.parts):
        if any(part.startswith(".") for part in match.relative_to(root).parts):
            continue
        if match.is_dir() and not match.is_symlink():
            out.extend(_system_files(match))
        elif match.name.endswith(SUFFIXES):
            out.append(match)
    return False, out, root


def _split_glob(pattern: str) -> tuple[Path, str]:
    """``models/**/*.yaml`` → (models, ``**/*.yaml``); ``*.yaml`` → (., ``*.yaml``)."""
    parts = Path(pattern).parts
    first = next(i for i, part in enumerate(parts) if glob.has_magic(part))
    root = Path(*parts[:first]) if first else Path(".")
    return root, "/".join(parts[first:])


def _named_boundary(path: Path) -> Path:
    here = Path.cwd()
    absolute = Path(os.path.abspath(path))
    return here if absolute.is_relative_to(here) else absolute.parent


def _system_files(directory: Path) -> list[Path]:
    """Candidate files under ``directory``; linked directories are not entered."""
    out = []
    for root, dirs, files in os.walk(directory):  # followlinks=False: no loop, no way out
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        out.extend(Path(root, f) for f in files if f.endswith(SUFFIXES) and not f.startswith("."))
    return sorted(out, key=lambda p: p.parts)


def _refusal(path: Path, boundary: Path) -> str | None:
    """Why ``path`` is not to be opened (it leads out of its boundary, loops, is no regular file), or None."""
    try:
        real = path.resolve(strict=True)
    except RuntimeError:  # Python 3.11 reports a loop so; later versions raise OSError(ELOOP)
        return LOOPS
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            return LOOPS
        if exc.errno == errno.ENOENT and path.is_symlink():
            # Not "no such file": the name is there, what it points to is not.
            return DANGLING
        return None  # missing or unreadable: check_file says so, located
    try:
        if not stat.S_ISREG(real.stat().st_mode):
            return NOT_REGULAR
    except OSError:
        return None
    if not real.is_relative_to(boundary.resolve()):
        return LEAVES.format(boundary=_shown(boundary))
    return None


def _shown(boundary: Path) -> str:
    return "the working directory" if os.path.abspath(boundary) == os.getcwd() else f"{boundary}"


def _not_gacli(path: Path) -> str | None:
    """NOT_GACLI when the file's first bytes hold no top-level ``gacli:`` key, as the loader reads
    keys: after a byte-order mark, in a flow mapping ({"gacli": 1, ...}), or written any other way
    YAML allows (an anchor, an escape, the whole mapping indented), which a small file is parsed for."""
    try:
        with open(path, "rb") as handle:
            head = handle.read(_SNIFF_BYTES + 1)
    except OSError:
        return None  # check_file reports it, located
    text = head.removeprefix(b"\xef\xbb\xbf")
    if _GACLI_KEY.search(text) or _FLOW_KEY.search(text):
        return None
    return None if len(head) <= _SNIFF_BYTES and _parsed_has_key(head, str(path)) else NOT_GACLI


# The key in a flow mapping, which the gate must not skip: the loader reads it.
_FLOW_KEY = re.compile(rb"[{,][ \t\r\n]*(?:gacli|\"gacli\"|'gacli')[ \t]*:")


def _parsed_has_key(data: bytes, name: str) -> bool:
    """Whether the file parses (safely, within the reader's limits) to a mapping with the key ``gacli``."""
    try:
        root = parse_source(data, name).root
    except SystemFileError:
        return False
    return isinstance(root, Mapping) and any(key.text == "gacli" for key, _ in root.items)
