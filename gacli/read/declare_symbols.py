"""The declared names and how their rates are tied: ``parameters``, ``functions``,
``inputs``, ``coordinates``, ``quasi_coordinates``, ``constraints`` and ``independent``."""

from __future__ import annotations

import keyword
import re

from gacli.read.expr.grammar import ParseError, Rate, names, walk
from gacli.read.expr.parser import parse
from gacli.read.reader import Reader, describe
from gacli.read.schema import (
    QUASI_KEYS,
    SYMBOL_KEYS,
    SYMBOL_SECTIONS,
    VELOCITY_CONSTRAINT_KEYS,
    SymbolDecl,
    VelocityConstraintDecl,
    CoincidenceDecl,
    GuideDecl,
)
from gacli.read.source import Mapping, Node, Scalar, Sequence
from gacli.read.texsafe import MAX_LENGTH as LATEX_MAX_LENGTH
from gacli.read.texsafe import check_math


_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z")


def _constant(text: str) -> bool:
    """Whether ``text`` is a number, or an expression of the grammar in numbers and pi alone (1/2,
    2*pi, exp(1)): a value, where a description would leave the symbol without one, silently."""
    if _NUMBER.match(text.strip()):
        return True
    try:
        tree = parse(text)
    except ParseError:
        return False
    return names(tree) <= {"pi"} and not any(isinstance(n, Rate) for n in walk(tree))


def read_symbols(reader: Reader, top: dict) -> tuple[SymbolDecl, ...]:
    """The sections ``parameters``, ``functions``, ``inputs``, ``coordinates``, ``quasi_coordinates``."""
    out: list[SymbolDecl] = []
    for section in SYMBOL_SECTIONS:
        if section in top:
            kind = section.rstrip("s").replace("quasi_coordinate", "quasi")
            out.extend(_symbol_section(reader, top[section][1], section, kind))
    return tuple(out)


def _symbol_section(reader: Reader, node: Node, section: str, kind: str) -> list[SymbolDecl]:
    if isinstance(node, Sequence):
        names = [(item, _written_name(reader, item, f"{section}[{i}]")) for i, item in enumerate(node.items)]
        return [SymbolDecl(kind, name, item) for item, name in names if name]
    if isinstance(node, Mapping):
        out = []
        for key, value in node.items:
            name = _written_name(reader, key, section)
            if name:
                out.append(_symbol_entry(reader, kind, key, value, f"{section}.{name}"))
        return out
    if isinstance(node, Scalar) and node.kind == "null":
        return []
    reader.error(node, section, f"expected a list of names or a mapping, found {describe(node)}")
    return []


def _written_name(reader: Reader, node: Node, where: str) -> str | None:
    """A symbol's name, refused where it is declared when no expression could write it (the grammar's
    rule): a Python keyword, or a name with '__'; else its first use was the error."""
    name = reader.name(node, where)
    if name is not None and (keyword.iskeyword(name) or "__" in name):
        why = "is a Python keyword" if keyword.iskeyword(name) else "contains '__'"
        reader.error(node, where, f"'{name}' {why}: no expression could use it", "choose another name")
        return None
    return name


def _symbol_entry(reader: Reader, kind: str, key: Scalar, value: Node, where: str) -> SymbolDecl:
    if isinstance(value, Scalar):
        if value.kind == "null":
            return SymbolDecl(kind, key.text, key)
        if kind == "quasi":
            return SymbolDecl(kind, key.text, key, differential=reader.expression(value, where))
        if kind in ("parameter", "function") and (value.kind in ("int", "float") or _constant(value.text)):
            # `m: 1`, `J: 5e6` or `r: 2*pi` means that value (no one describes a mass as "1"); text stays
            # a description.
            return SymbolDecl(kind, key.text, key, value=reader.expression(value, f"{where}.value"))
        return SymbolDecl(kind, key.text, key, description=value.text)
    allowed = QUASI_KEYS if kind == "quasi" else SYMBOL_KEYS
    if kind in ("input", "coordinate"):
        allowed = tuple(k for k in allowed if k != "value")
    fields = reader.mapping(value, where, allowed)
    get = lambda k: fields[k][1] if k in fields else None  # noqa: E731
    return SymbolDecl(
        kind, key.text, key,
        description=reader.text(get("description"), f"{where}.description") if get("description") else "",
        value=reader.expression(get("value"), f"{where}.value") if get("value") else None,
        unit=reader.text(get("unit"), f"{where}.unit") if get("unit") else "",
        latex=_latex(reader, get("latex"), f"{where}.latex"),
        differential=reader.expression(get("differential"), f"{where}.differential") if get("differential") else None,
    )


def _latex(reader: Reader, node: Node | None, where: str) -> str:
    """A ``latex:`` override, only if it is a math name TeX cannot run (see gacli.read.texsafe)."""
    if node is None:
        return ""
    text = reader.text(node, where)
    if not text or not isinstance(node, Scalar):
        return ""
    problem = check_math(text)
    if problem is None:
        return text
    reader.error(node, where, f"bad LaTeX override: {problem.message}",
                 f"a name in math TeX of at most {LATEX_MAX_LENGTH} characters: letters, digits, "
                 "^ _ { } ' , and commands such as \\alpha, \\dot, \\hat, \\mathrm",
                 offset=problem.offset)
    return ""


def read_constraints(reader: Reader, top: dict) -> tuple[Scalar, ...]:
    """The ``constraints`` list: expressions, and velocity constraints (``velocity_of`` a point ``along`` a vector)."""
    node = reader.section(top, "constraints", Sequence, "a list of constraints", null_is_empty=True)
    if node is None:
        return ()
    items = [_constraint(reader, i, item) for i, item in enumerate(node.items)]
    return tuple(item for item in items if item)


def _constraint(reader: Reader, index: int, node: Node):
    where = f"constraints[{index}]"
    if not isinstance(node, Mapping):
        return reader.expression(node, where)
    fields = reader.mapping(node, where, VELOCITY_CONSTRAINT_KEYS)
    if "coincide" in fields:
        return _coincidence(reader, index, node, fields, where)
    if "moves_along" in fields or "moves_in" in fields:
        return _guide(reader, index, node, fields, where)
    if "velocity_of" not in fields or "along" not in fields:
        reader.error(node, where, "a velocity constraint needs 'velocity_of' (a point) and 'along' (a vector)")
        return None
    point = fields["velocity_of"][1]
    along = reader.vector(fields["along"][1], f"{where}.along", (2, 3))
    if not reader.name(point, f"{where}.velocity_of") or along is None:
        return None
    return VelocityConstraintDecl(index, node, point, along)


def _coincidence(reader: Reader, index: int, node: Node, fields: dict, where: str) -> CoincidenceDecl | None:
    """``coincide: [A, B]``: two named points at one place."""
    ends = fields["coincide"][1]
    if set(fields) - {"coincide", "description"}:
        reader.error(node, where, "a coincidence is 'coincide': [A, B] alone (two points)")
        return None
    if not isinstance(ends, Sequence) or len(ends.items) != 2:
        reader.error(ends, f"{where}.coincide", f"expected two point names [A, B], found {describe(ends)}")
        return None
    if not all(reader.name(e, f"{where}.coincide") for e in ends.items):
        return None
    return CoincidenceDecl(index, node, tuple(ends.items))


GUIDES = {"moves_along": (1, "an axis of the frame (x, y or z)"),
          "moves_in": (2, "a plane of the frame named by two axes (xy, yz or zx)")}


def _guide(reader: Reader, index: int, node: Node, fields: dict, where: str) -> GuideDecl | None:
    """``moves_along: [P, F, x]`` or ``moves_in: [P, F, xy]``: a point on a line or in a plane of a frame."""
    key = "moves_along" if "moves_along" in fields else "moves_in"
    count, what = GUIDES[key]
    if set(fields) - {key, "description"}:
        reader.error(node, where, f"'{key}' stands alone: [point, frame, {'axis' if count == 1 else 'plane'}]")
        return None
    items = fields[key][1]
    place = f"{where}.{key}"
    if not isinstance(items, Sequence) or len(items.items) != 3:
        reader.error(items, place, f"expected [point, frame, {what}], found {describe(items)}")
        return None
    point, frame, axes = items.items
    if not (reader.name(point, place) and reader.name(frame, place)):
        return None
    text = axes.text if isinstance(axes, Scalar) else ""
    if len(text) != count or len(set(text)) != count or not set(text) <= set("xyz"):
        reader.error(axes, place, f"expected {what}, found {describe(axes)}")
        return None
    return GuideDecl(index, node, key, point, frame, tuple(sorted("xyz".index(c) for c in text)))


def read_independent(reader: Reader, top: dict) -> tuple[Scalar, ...] | None:
    """The names listed under ``independent``; None when the section is absent."""
    node = reader.section(top, "independent", Sequence, "a list of names")
    if node is None:
        return None
    names = [item for i, item in enumerate(node.items) if reader.name(item, f"independent[{i}]")]
    return tuple(names)
