"""The JSON Schema (draft 2020-12) of the system file format, for editors.

Editors that run the YAML language server validate a file as it is typed
once it starts with ``# yaml-language-server: $schema=<path or URL>``. The
schema checks shape only (keys, lists, names, which strings may be
expressions); gacli itself checks everything else. It follows the reader in
:mod:`gacli.read.schema` (the tests hold its key lists to that module's, so the
two cannot drift apart), and the shipped copy
``schema/gacli-system-1.schema.json`` is tested to equal :func:`schema_text`.
No SymPy is imported here.
"""

from __future__ import annotations

import json

from gacli.read.expr.grammar import MAX_LENGTH
from gacli.read.schema import FORMAT_VERSION
from gacli.read.system_name import MAX_LENGTH as NAME_MAX_LENGTH
from gacli.read.texsafe import MAX_LENGTH as LATEX_MAX_LENGTH

SCHEMA_FILE = f"gacli-system-{FORMAT_VERSION}.schema.json"
DIALECT = "https://json-schema.org/draft/2020-12/schema"

NAME_PATTERN = "^[A-Za-z_][A-Za-z0-9_]*$"
# The characters of the expression grammar, and at least one operand.
_CHARACTERS = r"\sA-Za-z0-9_.+\-*/(),"
EXPRESSION_PATTERN = rf"^[{_CHARACTERS}]*[A-Za-z0-9_.)][{_CHARACTERS}]*$"
CONSTRAINT_PATTERN = rf"^[{_CHARACTERS}]*(=[{_CHARACTERS}]*)?$"
AXES = ["x", "y", "z", "X", "Y", "Z"]
# The characters of a latex: override (gacli.read.texsafe checks the commands and braces).
LATEX_PATTERN = r"^[A-Za-z0-9\\^_{}', ]*$"


def _ref(name: str) -> dict:
    return {"$ref": f"#/$defs/{name}"}


def _text() -> dict:
    return {"type": "string"}


def _closed(properties: dict, required: tuple[str, ...] = (), **extra) -> dict:
    """An object with exactly these keys."""
    out: dict = {"type": "object", "properties": properties, "additionalProperties": False}
    if required:
        out["required"] = list(required)
    out.update(extra)
    return out


def _list(sizes: tuple[int, ...], item: dict | None = None) -> dict:
    """A list of one of these lengths (the reader's ``sizes``)."""
    if list(sizes) != list(range(min(sizes), max(sizes) + 1)):
        return {"oneOf": [_list((n,), item) for n in sizes]}
    return {"type": "array", "items": item or _ref("expression"), "minItems": min(sizes), "maxItems": max(sizes)}


def _either(*choices: dict, description: str = "") -> dict:
    out: dict = {"description": description} if description else {}
    out["oneOf"] = list(choices)
    return out


def _symbol_section(entry: str, description: str) -> dict:
    """A list of names, or a mapping from name to an entry (or nothing)."""
    return _either({"type": "null"}, {"type": "array", "items": _ref("name"), "uniqueItems": True},
                   {"type": "object", "propertyNames": _ref("name"), "additionalProperties": _ref(entry)},
                   description=description)


def _latex() -> dict:
    return {"type": "string", "maxLength": LATEX_MAX_LENGTH, "pattern": LATEX_PATTERN,
            "description": "math TeX: letters, digits, ^ _ { } ' , and commands such as \\alpha, \\dot, \\mathrm"}


def _symbol_entry(with_value: bool) -> dict:
    properties = {"description": _text(), "unit": _text(), "latex": _latex()}
    if with_value:
        properties["value"] = _ref("expression")
    return _either({"type": "null"}, {"type": ["string", "number"], "description": "a description"},
                   _closed(properties))


def _vector(sizes: tuple[int, ...]) -> dict:
    return _either(_list(sizes), _ref("vector_in_frames"))


def _definitions() -> dict:
    return {
        "name": {"type": "string", "pattern": NAME_PATTERN, "description": "an identifier"},
        "expression": _either(
            {"type": "number"},
            {"type": "string", "maxLength": MAX_LENGTH, "pattern": EXPRESSION_PATTERN},
            description="an expression: numbers, declared names, t, pi, + - * / **, sin cos tan asin acos "
                        "atan atan2 sinh cosh tanh exp log sqrt abs sign, dot(x), ddot(x), differentials dx, dt"),
        "constraint": _constraint(),
        "vector_in_frames": {
            "type": "object", "minProperties": 1, "propertyNames": _ref("name"),
            "properties": {"from": _ref("name")}, "additionalProperties": _list((3,)),
            "description": "components in one or more frames, summed ({N: [x, y, z], B: [...]}), "
                           "plus the position of the point 'from'"},
        "parameter": _symbol_entry(True),
        "function": _symbol_entry(True),
        "plain_symbol": _symbol_entry(False),
        "quasi_coordinate": _either(
            {"type": "null"}, _ref("expression"),
            _closed({"description": _text(), "differential": _ref("expression"), "unit": _text(),
                     "latex": _latex()}),
            description="its differential (a string), or a mapping; nothing: a primitive quasi-coordinate"),
        "frame": _frame(),
        "body": _body(),
        "rolling": _closed({"body": _ref("name"), "radius": _ref("expression"), "axle": _vector((3,)),
                            "tube": {**_ref("expression"), "description": "a wheel's round tyre: its tube's radius"},
                            "semi_axes": {**_list((3,)), "description": "an ellipsoid's, along the body's axes"},
                            "centre": _vector((3,)), "on": _ref("name"),
                            "contact": _either(_ref("name"), _vector((3,)),
                                               description="the contact point, which places the body"),
                            "description": _text()},
                           ("body",), oneOf=[{"required": ["radius"]},
                                             {"required": ["semi_axes"], "not": {"anyOf": [
                                                 {"required": ["axle"]}, {"required": ["tube"]}]}}],
                           dependentSchemas={"tube": {"required": ["axle"]}}),
        "load": _load(),
    }


def _constraint() -> dict:
    """A constraint: a Pfaffian form, or one of the holonomic and knife-edge mappings."""
    return _either(
        {"type": "number"},
        {"type": "string", "maxLength": MAX_LENGTH, "pattern": CONSTRAINT_PATTERN},
        _closed({"velocity_of": _ref("name"), "along": _vector((2, 3)), "description": _text()},
                ("velocity_of", "along"), description="a knife edge: the point's velocity has no "
                                                      "component along the vector"),
        _closed({"coincide": {"type": "array", "items": _ref("name"), "minItems": 2, "maxItems": 2},
                 "description": _text()}, ("coincide",),
                description="a loop closed at a joint: the two points are at one place"),
        _closed({"moves_along": {"type": "array", "minItems": 3, "maxItems": 3,
                                 "prefixItems": [_ref("name"), _ref("name"), {"enum": ["x", "y", "z"]}]},
                 "description": _text()}, ("moves_along",),
                description="a point on a frame's axis through its origin: [point, frame, axis]"),
        _closed({"moves_in": {"type": "array", "minItems": 3, "maxItems": 3,
                              "prefixItems": [_ref("name"), _ref("name"),
                                              {"enum": ["xy", "yx", "yz", "zy", "zx", "xz"]}]},
                 "description": _text()}, ("moves_in",),
                description="a point in a frame's plane through its origin: [point, frame, plane]"),
        description="a Pfaffian constraint 'lhs = rhs' (or one expression, meaning '= 0')")


def _frame() -> dict:
    pair = {"type": "array", "prefixItems": [{"enum": AXES}, _ref("expression")], "items": False,
            "minItems": 2, "description": "[axis, angle], as [z, psi]"}
    properties = {
        "parent": _ref("name"),
        "origin": _either(_ref("name"), _vector((3,)), description="a point's name, or a position"),
        "rotations": {"type": "array", "items": pair, "minItems": 1},
        "sequence": {"type": "string", "pattern": "^[XYZxyz]{1,3}$", "description": "as ZXZ"},
        "angles": _list((1, 2, 3)),
        "quaternion": {"type": "array", "items": _ref("name"), "minItems": 4, "maxItems": 4,
                       "description": "Euler parameters, scalar first: [e0, e1, e2, e3]"},
        "rates": {"type": "array", "items": _ref("name"), "minItems": 3, "maxItems": 3,
                  "description": "quasi-coordinates: the body rates along the frame's axes"},
        "description": _text(),
    }
    # Rotations, a sequence with angles, a quaternion, or none with an origin (the parent's axes, moved).
    neither = {"not": {"anyOf": [{"required": ["rotations"]}, {"required": ["sequence"]},
                                 {"required": ["quaternion"]}]}, "required": ["origin"]}
    return _closed(properties, oneOf=[{"required": ["rotations"]}, {"required": ["sequence", "angles"]},
                                      {"required": ["quaternion"]}, neither])


def _body() -> dict:
    matrix = {"type": "array", "items": _list((3,)), "minItems": 3, "maxItems": 3}
    properties = {
        "mass": _ref("expression"),
        "position": _either(_ref("name"), _vector((2, 3)), description="a point's name, or a vector"),
        "inertia": _either(_ref("expression"), _list((1, 3)), matrix,
                           description="[Ix, Iy, Iz], a symmetric 3x3 matrix, or a scalar for plane motion"),
        "rotation": _either(_ref("expression"), _list((1, 3)),
                            description="the body-axis components of the rotation as differential forms "
                                        "(one form for plane motion)"),
        "frame": _ref("name"),
        "inertia_about": {**_ref("name"), "description": "the point the inertia is given about (its centre when absent)"},
        "inertia_in": {**_ref("name"), "description": "the frame whose axes the inertia is given in (the body's frame when absent)"},
        "description": _text(),
    }
    rigid = {
        "inertia": {"anyOf": [{"required": ["rotation"]}, {"required": ["frame"]}]},
        "rotation": {"required": ["inertia"], "not": {"required": ["frame"]}},
        "frame": {"required": ["inertia"]},
        "inertia_about": {"required": ["frame"]},
        "inertia_in": {"required": ["frame"]},
    }
    # Without a position, a rolling contact's 'contact' places the body (checked by the reader).
    return _closed(properties, ("mass",), dependentSchemas=rigid)


def _load() -> dict:
    force = _closed({"force": _vector((2, 3)), "at": _either(_ref("name"), _vector((2, 3))),
                     "description": _text()}, ("force", "at"))
    torque = _closed({"torque": _either(_ref("expression"), _vector((1, 3))), "body": _ref("name"),
                      "reaction": _ref("name"), "description": _text()}, ("torque", "body"))
    ends = {"type": "array", "items": _ref("name"), "minItems": 2, "maxItems": 2,
            "description": "the two points (or bodies' centres) it acts between"}
    spring = _closed({"spring": _ref("expression"), "between": ends, "length": _ref("expression"),
                      "description": _text()}, ("spring", "between"))
    damper = _closed({"damper": _ref("expression"), "between": ends, "description": _text()},
                     ("damper", "between"))
    return {"oneOf": [force, torque, spring, damper]}


def _top_level() -> dict:
    return {
        "gacli": {"const": FORMAT_VERSION, "description": "the format version"},
        "name": {"allOf": [_ref("name"), {"maxLength": NAME_MAX_LENGTH}],
                 "description": "the system's name: file names, the Python module, the C prefix; "
                                "not a keyword, a C standard header or a Python module"},
        "title": _text(),
        "description": _text(),
        "source": {"type": "string", "description": "where the system comes from (a book, a paper)"},
        "parameters": _symbol_section("parameter", "constant symbols"),
        "functions": _symbol_section("function", "prescribed functions of time"),
        "inputs": _symbol_section("plain_symbol", "external loads or controls (functions of time)"),
        "coordinates": _symbol_section("plain_symbol", "generalized coordinates"),
        "quasi_coordinates": _symbol_section("quasi_coordinate", "quasi-coordinates, by their differentials"),
        "constraints": {"oneOf": [{"type": "null"}, {"type": "array", "items": _ref("constraint")}]},
        "independent": {"type": "array", "items": _ref("name"), "uniqueItems": True},
        "frames": {"type": "object", "propertyNames": _ref("name"), "additionalProperties": _ref("frame")},
        "points": {"type": "object", "propertyNames": _ref("name"), "additionalProperties": _vector((2, 3))},
        "bodies": {"type": "object", "minProperties": 1, "propertyNames": _ref("name"),
                   "additionalProperties": _ref("body")},
        "rolling": {"type": "array", "items": _ref("rolling")},
        "loads": {"oneOf": [{"type": "null"}, {"type": "array", "items": _ref("load")}]},
        "work": _ref("expression"),
        "potential": _ref("expression"),
    }


def build_schema() -> dict:
    """The schema as a dict (keys in the order of the format's documentation)."""
    return {
        "$schema": DIALECT,
        "title": f"gacli system file (format {FORMAT_VERSION})",
        "description": "A mechanical system for gacli, which derives its equations of motion by the "
                       "Gibbs-Appell method. Generated by 'gacli schema'.",
        "type": "object",
        "required": ["gacli", "name", "coordinates", "bodies"],
        "additionalProperties": False,
        "properties": _top_level(),
        "$defs": _definitions(),
    }


def schema_text() -> str:
    """The schema as ``gacli schema`` prints it (and as the repository ships it)."""
    return json.dumps(build_schema(), indent=2, ensure_ascii=True) + "\n"
