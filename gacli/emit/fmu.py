"""``--format fmu``: an FMI 2.0 Model Exchange FMU, built from the generated C.

:func:`emit_fmu` returns ``{"<name>.fmu": bytes}``, a zip holding

.. code:: text

    modelDescription.xml           the variables, named as in the system file (fmu_xml.py)
    sources/<name>.h, <name>.c     the generated C of --format c, unchanged
    sources/<name>_fmu.c           the FMI 2.0 functions over <name>_rhs (fmu_c.py)
    binaries/<platform>/<name>.so  built with the local C compiler, when there is one

The equations exist once, in ``<name>.c``: the FMU's derivatives are its
``rhs``. The zip is the same bytes on every run for the same system file
(fixed order, timestamps and permissions) except for the binary, which is
whatever the compiler makes of the same sources; ``binary=False`` leaves it
out, making a source FMU, which FMI 2.0 allows (modelDescription always
lists the sources in SourceFiles).
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import platform
import shlex
import shutil
import struct
import subprocess
import tempfile
import zipfile
from collections.abc import Callable
from dataclasses import asdict
from pathlib import Path

from gacli.emit.c import emit_c
from gacli.emit.fmu_c import wrapper
from gacli.emit.fmu_xml import guid_from, model_description, variables
from gacli.emit.naming import header_lines, layout
from gacli.mechanics.equations import Derivation
from gacli.errors import EmitError

# The flags the brief of the FMU names: a position-independent shared library of C99.
FLAGS = ("-shared", "-fPIC", "-O2", "-std=c99")
COMPILERS = ("cc", "gcc", "clang")
# 1980-01-01 is the earliest time a zip can hold: no clock leaks into the file.
ZIP_TIME = (1980, 1, 1, 0, 0, 0)


def emit_fmu(derivation: Derivation, *, binary: bool = True,
             note: Callable[[str], None] | None = None) -> dict[str, bytes]:
    """The FMU of a derivation, as ``{"<name>.fmu": zip bytes}``.

    ``binary`` builds ``binaries/<platform>/<name>.<so|dylib|dll>`` with the
    compiler in ``$CC`` or else the first of cc, gcc, clang on PATH; with
    none, the FMU carries sources only and ``note`` is told why.

    Raises:
        EmitError: when an expression has no C rendering, or the compiler
            fails (or ``$CC`` names no program).
    """
    from gacli.version import __version__

    lay = layout(derivation)
    sources = emit_c(derivation)
    table = variables(derivation, lay)
    digest = hashlib.sha256(json.dumps([sorted(sources.items()), [asdict(v) for v in table]]).encode())
    guid = guid_from(digest.hexdigest())
    sources[f"{lay.system}_fmu.c"] = wrapper(
        name=lay.system, prefix=lay.prefix, guid=guid, defaults=[lay.defaults.get(p, 0.0) for p in lay.parameters],
        comment_lines=header_lines(derivation, f"fmu --output {lay.system}.fmu"))  # an FMU is never printed
    xml = model_description(derivation, lay, table, guid=guid, tool=f"gacli {__version__}",
                            sources=[f"{lay.system}_fmu.c", f"{lay.system}.c"])
    members = [("modelDescription.xml", xml)]
    members += [(f"sources/{name}", text.encode("utf-8")) for name, text in sorted(sources.items())]
    if binary:
        members += _binary(lay.system, sources, note)
    return {f"{lay.system}.fmu": zip_bytes(members)}


def _binary(name: str, sources: dict[str, str], note: Callable[[str], None] | None) -> list[tuple[str, bytes]]:
    """The one binary member, or none (with a note) when there is no compiler or no FMI platform."""
    target = platform_folder()
    compiler = find_compiler()
    why = ("no C compiler found (set CC, or put cc, gcc or clang on PATH)" if compiler is None else
           f"FMI 2.0 names no binary folder for {platform.system()}" if target is None else None)
    if why is not None:
        if note is not None:
            note(f"{why}: {name}.fmu carries its C sources only")
        return []
    folder, suffix = target
    return [(f"binaries/{folder}/{name}{suffix}", build(name, sources, compiler, suffix))]


def platform_folder() -> tuple[str, str] | None:
    """FMI 2.0's folder under binaries/ for this machine and its library suffix, or None."""
    bits = struct.calcsize("P") * 8
    return {"Linux": (f"linux{bits}", ".so"), "Darwin": (f"darwin{bits}", ".dylib"),
            "Windows": (f"win{bits}", ".dll")}.get(platform.system())


def find_compiler() -> list[str] | None:
    """The compiler command: ``$CC`` (split like a shell word list) or the first of cc, gcc, clang on PATH."""
    chosen = os.environ.get("CC", "").strip()
    if chosen:
        try:
            command = shlex.split(chosen)
        except ValueError as exc:
            raise EmitError(f"CC={chosen}: {exc} (CC is read as shell words)") from None
        if not command or shutil.which(command[0]) is None:
            raise EmitError(f"CC={chosen}: no such program, so the FMU's binary cannot be built")
        return command
    for name in COMPILERS:
        path = shutil.which(name)
        if path is not None:
            return [path]
    return None


def build(name: str, sources: dict[str, str], compiler: list[str], suffix: str) -> bytes:
    """The shared library of the FMU's sources, built in a temporary directory."""
    with tempfile.TemporaryDirectory(prefix="gacli-fmu-") as tmp:
        for file, text in sources.items():
            Path(tmp, file).write_text(text, encoding="utf-8", newline="\n")
        # Relative paths, so that no temporary directory's name can reach the binary.
        command = [*compiler, *FLAGS, "-o", f"{name}{suffix}", f"{name}_fmu.c", f"{name}.c", "-lm"]
        try:
            result = subprocess.run(command, cwd=tmp, capture_output=True, text=True)
        except OSError as exc:
            raise EmitError(f"{compiler[0]} could not be run to build the FMU's binary: {exc.strerror}") from None
        if result.returncode != 0:
            raise EmitError(f"the C compiler failed to build the FMU's binary ({shlex.join(command)}): "
                            f"{_first_errors(result)}")
        return Path(tmp, f"{name}{suffix}").read_bytes()


def _first_errors(result: subprocess.CompletedProcess) -> str:
    """The compiler's first error lines, on one line (an error message is one line)."""
    lines = [line.strip() for line in (result.stderr or result.stdout).splitlines() if line.strip()]
    errors = [line for line in lines if "error" in line.lower()] or lines
    return " | ".join(errors[:3]) if errors else f"exit status {result.returncode}, no message"


def zip_bytes(members: list[tuple[str, bytes]]) -> bytes:
    """A zip of the members in the order given, with fixed times and Unix permissions."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:
        for name, data in members:
            info = zipfile.ZipInfo(name, date_time=ZIP_TIME)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.create_system = 3  # Unix, so that the permission bits below are read
            info.external_attr = (0o100755 if name.startswith("binaries/") else 0o100644) << 16
            archive.writestr(info, data, compresslevel=9)
    return buffer.getvalue()
