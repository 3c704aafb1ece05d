"""The top level of a system file, read into a :class:`~gacli.read.schema.SystemDecl`.

Each section is read by its own module (``declare_symbols``,
``declare_bodies``, ``declare_frames``); every problem is collected as a
:class:`~gacli.errors.Diagnostic`, so one run reports them all.
"""

from __future__ import annotations

from gacli.errors import Diagnostic
from gacli.read.declare_bodies import read_bodies, read_loads
from gacli.read.declare_frames import read_frames, read_points
from gacli.read.declare_rolling import check_placements, read_rolling
from gacli.read.declare_symbols import read_constraints, read_independent, read_symbols
from gacli.read.reader import Reader, describe
from gacli.read.schema import FORMAT_VERSION, TOP_KEYS, SystemDecl
from gacli.read.source import Mapping, Scalar, SourceFile
from gacli.read.system_name import name_problem


def read_declarations(source: SourceFile) -> tuple[SystemDecl | None, list[Diagnostic]]:
    """Read the top level of a system file into a :class:`SystemDecl`."""
    reader = Reader(source)
    top = reader.mapping(source.root, "", TOP_KEYS)
    if not isinstance(source.root, Mapping):
        return None, reader.diagnostics
    _check_required(reader, source.root, top)
    _check_version(reader, top)
    name = _system_name(reader, top)
    decl = SystemDecl(
        source=source,
        name=name or "system",
        title=_optional_text(reader, top, "title"),
        description=_optional_text(reader, top, "description"),
        reference=_optional_text(reader, top, "source"),
        symbols=read_symbols(reader, top),
        constraints=read_constraints(reader, top),
        independent=read_independent(reader, top),
        independent_node=top["independent"][1] if "independent" in top else None,
        frames=read_frames(reader, top),
        points=read_points(reader, top),
        bodies=read_bodies(reader, top),
        rolling=read_rolling(reader, top),
        loads=read_loads(reader, top),
        work=_optional_expression(reader, top, "work"),
        potential=_optional_expression(reader, top, "potential"),
    )
    check_placements(reader, top, decl.bodies, decl.rolling)
    return decl, reader.diagnostics


def _check_required(reader: Reader, root: Mapping, top: dict) -> None:
    for key in ("gacli", "name", "coordinates", "bodies"):
        if key not in top:
            reader.error(root, "", f"missing required key '{key}'")


def _check_version(reader: Reader, top: dict) -> None:
    if "gacli" in top:
        node = top["gacli"][1]
        if not (isinstance(node, Scalar) and node.text == str(FORMAT_VERSION)):
            reader.error(node, "gacli", f"unsupported format version {describe(node)}",
                         f"this gacli reads format {FORMAT_VERSION}")


def _system_name(reader: Reader, top: dict) -> str | None:
    """The name, if it can name files, a Python module and C identifiers (see gacli.read.system_name)."""
    if "name" not in top or not reader.name(top["name"][1], "name"):
        return None
    node = top["name"][1]
    problem = name_problem(node.text)
    if problem:
        reader.error(node, "name", problem, "the name becomes <name>.py, <name>.c, <name>.h and C identifiers")
        return None
    return node.text


def _optional_text(reader: Reader, top: dict, key: str) -> str:
    return reader.text(top[key][1], key) if key in top else ""


def _optional_expression(reader: Reader, top: dict, key: str) -> Scalar | None:
    return reader.expression(top[key][1], key) if key in top else None
