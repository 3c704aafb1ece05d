"""Write generated files atomically: a temporary file beside the target, then rename.

An existing file is replaced only when its new text is complete, so an error
(or a crash) never leaves a half-written file.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

from gacli.errors import GacliError


class OutputError(GacliError):
    """The output path cannot receive the generated files."""


def targets(files: dict[str, str | bytes], output: Path) -> dict[Path, str | bytes]:
    """Where each generated file goes: into ``output`` when it is a directory
    (or several files are generated), else ``output`` itself."""
    if output.is_dir() or len(files) > 1:
        if output.exists() and not output.is_dir():
            raise OutputError(f"{output}: expected a directory for {len(files)} files ({', '.join(sorted(files))})")
        return {output / name: text for name, text in sorted(files.items())}
    (text,) = files.values()
    return {output: text}


def write_files(files: dict[str, str | bytes], output: Path) -> list[Path]:
    """Write every file atomically; returns the paths written."""
    planned = targets(files, output)
    for path in planned:
        if not path.parent.exists():
            path.parent.mkdir(parents=True, exist_ok=True)
    for path, text in planned.items():
        _write_atomic(path, text)
    return list(planned)


def _write_atomic(path: Path, text: str | bytes) -> None:
    with atomic_path(path) as tmp:
        if isinstance(text, bytes):  # a zip (the FMU): written as it is
            tmp.write_bytes(text)
        else:
            tmp.write_text(text, encoding="utf-8", newline="\n")


@contextlib.contextmanager
def atomic_path(path: Path):
    """A temporary path beside ``path`` to write; renamed over ``path`` only if the block succeeds.

    The file gets the mode an ordinary new file would (or the replaced
    file's), not mkstemp's private 0600.
    """
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=path.suffix or ".tmp", dir=path.parent)
    os.close(fd)
    try:
        yield Path(tmp)
        os.chmod(tmp, _mode_for(path))
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def _mode_for(path: Path) -> int:
    if path.exists():
        return path.stat().st_mode & 0o7777
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask
