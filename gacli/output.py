"""Write generated files: where they go, and all of them or none.

Where (one rule for every format and command, docs/generated-code.md): an
``--output`` that ends in ``/`` or names an existing directory is a
directory, and each generated file goes into it under its own name (the
directory is made when missing); anything else is a file. A format that
writes several files (C's ``.c`` and ``.h``, Octave's set) takes a file name
only when it is one of them: its companions go beside it.

How: only regular files are written. A path that exists as a device, a FIFO
or a socket is refused before anything is written (``--output /dev/null``,
run as root, would otherwise replace the device). Every file is written to a
temporary file beside its target first; only when all are complete are they
renamed over their targets, and a rename that fails puts back what the earlier
ones replaced. A failure of the file system (a read-only directory, a parent
that is a file, ``/proc``, a full disk) is one :class:`OutputError` naming
the path, never a traceback, and leaves every existing file as it was.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import stat
import tempfile
from dataclasses import dataclass
from pathlib import Path

from gacli.errors import GacliError


class OutputError(GacliError):
    """The output path cannot receive the generated files."""


Text = str | bytes


def is_directory_target(output: str | Path) -> bool:
    """A trailing separator, or an existing directory (a link to one counts)."""
    text = os.fspath(output)
    if text.endswith(("/", os.sep)):
        return True
    try:
        return stat.S_ISDIR(os.stat(text).st_mode)
    except (FileNotFoundError, NotADirectoryError):
        return False
    except OSError as exc:  # a name too long, a loop of links, no permission to look
        raise _failure(Path(text), exc) from None


def targets(files: dict[str, Text], output: str | Path) -> dict[Path, Text]:
    """Where each generated file goes, by the rule in the module docstring."""
    path = Path(output)
    refuse_special(output)
    if is_directory_target(output):
        try:
            mode = path.stat().st_mode
        except (FileNotFoundError, NotADirectoryError):
            mode = None
        except OSError as exc:
            raise _failure(path, exc) from None
        if mode is not None and not stat.S_ISDIR(mode):
            raise OutputError(f"{output}: not a directory (a trailing / asks for one)")
        return {path / name: text for name, text in sorted(files.items())}
    if len(files) == 1:
        (text,) = files.values()
        return {path: text}
    if path.name in files:
        return {path.parent / name: text for name, text in sorted(files.items())}
    names = ", ".join(sorted(files))
    raise OutputError(f"{output}: this format writes {len(files)} files ({names}); give a directory "
                      f"(a trailing / makes one: {output}/) or the name of one of them")


def write_files(files: dict[str, Text], output: str | Path, source: str | Path | None = None) -> list[Path]:
    """Write every file, all or none; returns the paths written. ``source``: the system file the
    command read, which no file written may be (a folder of ``pend.c`` written by ``-f c -o ./``).

    Raises:
        OutputError: the output is not a regular file or directory, is the system file, or the file
        system failed.
    """
    planned = targets(files, output)
    for path in planned:
        if source is not None:
            refuse_input(path, source)
        _require_writable_kind(path)
    directories = sorted({path.parent for path in planned}, key=lambda p: p.parts)
    for directory in directories:
        _make_directory(directory)
    _commit(planned)
    return list(planned)


def refuse_input(output: str | Path, source: str | Path) -> None:
    """Refuse, before any work, an output that is the system file the command reads (``derive f.yaml
    --output f.yaml``): writing it would replace the file with what was derived from it."""
    if str(source) == "-" or is_directory_target(output):
        return
    try:
        same = os.path.samefile(output, source)
    except OSError:  # the output does not exist yet (or cannot be looked at: written, it says why)
        return
    if same:
        raise OutputError(f"{output}: is the system file this command reads; give the output another name")


def refuse_special(output: str | Path) -> None:
    """Refuse, before any work, an output that exists and is neither a regular file nor a directory."""
    if not is_directory_target(output):
        _require_writable_kind(Path(output))


def _require_writable_kind(path: Path) -> None:
    try:
        mode = path.stat().st_mode  # follows a link: a link to /dev/null is refused too
    except FileNotFoundError:
        return
    except NotADirectoryError:
        parent = next(p for p in reversed(path.parents) if p.exists() and not p.is_dir())
        raise OutputError(f"{path}: cannot write: {parent} is a file, not a directory") from None
    except OSError as exc:
        raise _failure(path, exc) from None
    if stat.S_ISDIR(mode):
        raise OutputError(f"{path}: is a directory, where a generated file of that name would go")
    if not stat.S_ISREG(mode):
        raise OutputError(f"{path}: not a regular file (a device, pipe or socket); gacli writes only "
                          "regular files")


def _make_directory(directory: Path) -> None:
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise _failure(directory, exc, "cannot make the directory") from None


def _failure(path: Path, exc: OSError, what: str = "cannot write") -> OutputError:
    # The target, never the temporary beside it that the system names.
    return OutputError(f"{path}: {what}: {exc.strerror or type(exc).__name__}")


# -- all or none -------------------------------------------------------------------

@dataclass
class _Staged:
    target: Path
    temporary: Path
    backup: Path | None = None     # the replaced file, kept until every rename has succeeded
    renamed: bool = False


def _commit(planned: dict[Path, Text]) -> None:
    staged: list[_Staged] = []
    current = next(iter(planned))
    try:
        for current, text in planned.items():
            staged.append(_Staged(current, _temporary(current)))
            _write(staged[-1].temporary, text, _mode_for(current))
        for item in staged:
            current = item.target
            item.backup = _backup(item.target)
            os.replace(item.temporary, item.target)
            item.renamed = True
    except OSError as exc:
        _roll_back(staged)
        changed = "" if len(planned) == 1 else " (no file was changed)"
        raise _failure(current, exc, f"cannot write{changed}") from None
    except BaseException:
        _roll_back(staged)
        raise
    for item in staged:
        if item.backup is not None:
            with contextlib.suppress(OSError):
                os.unlink(item.backup)


def _temporary(path: Path) -> Path:
    fd, name = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    return Path(name)


def _write(temporary: Path, text: Text, mode: int) -> None:
    if isinstance(text, bytes):  # a zip (the FMU): written as it is
        temporary.write_bytes(text)
    else:
        temporary.write_text(text, encoding="utf-8", newline="\n")
    os.chmod(temporary, mode)


def _backup(target: Path) -> Path | None:
    """A second name for the file about to be replaced (a hard link; a copy where links fail)."""
    if not os.path.lexists(target):  # a dangling link is put back on failure too
        return None
    backup = _temporary(target)
    os.unlink(backup)
    try:
        os.link(target, backup, follow_symlinks=False)
    except OSError:
        # A copy of the link, never of what it leads to: that is outside the output path.
        shutil.copy2(target, backup, follow_symlinks=False)
    return backup


def _roll_back(staged: list[_Staged]) -> None:
    """Put back every replaced file, remove every new one and every temporary."""
    for item in reversed(staged):
        if item.renamed:
            _quietly(os.replace, item.backup, item.target) if item.backup else _quietly(os.unlink, item.target)
        else:
            _quietly(os.unlink, item.temporary)
            if item.backup is not None:
                _quietly(os.unlink, item.backup)


def _quietly(operation, *paths: Path) -> None:
    # Rolling back after a failure: one that fails too must not hide the first.
    with contextlib.suppress(OSError):
        operation(*paths)


@contextlib.contextmanager
def atomic_path(path: Path):
    """A temporary path beside ``path`` to write; renamed over ``path`` only if the block succeeds.

    The file gets the mode an ordinary new file would (or the replaced
    file's), not mkstemp's private 0600. File-system failures become one
    OutputError naming the path.
    """
    _require_writable_kind(path)
    try:
        tmp = _temporary(path)
    except OSError as exc:
        raise _failure(path, exc) from None
    try:
        yield tmp
        os.chmod(tmp, _mode_for(path))
        os.replace(tmp, path)
    except OSError as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise _failure(path, exc) from None
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def _mode_for(path: Path) -> int:
    """The replaced file's permissions, else a new file's; never a link target's, nor set-id bits.

    The output replaces a link rather than writing through it (nothing outside
    the output path is written), so the mode of whatever the link led to,
    perhaps an executable elsewhere, is no business of the new file.
    """
    with contextlib.suppress(OSError):
        mode = os.lstat(path).st_mode
        if stat.S_ISREG(mode):
            return mode & 0o777
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask
