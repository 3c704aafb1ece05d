"""The JSON Schema of system files: shipped, in step with the reader, and right about real files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from gacli.read import schema as reader
from gacli.cli import app
from gacli.read.file_schema import SCHEMA_FILE, build_schema, schema_text
from gacli.read.source import Mapping, Sequence, parse_source

ROOT = Path(__file__).resolve().parent.parent
SHIPPED = ROOT / "schema" / SCHEMA_FILE
SYSTEMS = sorted((ROOT / "systems").glob("*.yaml"))
SCHEMA = build_schema()
DEFS = SCHEMA["$defs"]


def plain(node):
    """A composed YAML node as JSON data, the way gacli reads it (keys stay strings: 'on' is not True)."""
    if isinstance(node, Mapping):
        return {key.text: plain(value) for key, value in node.items}
    if isinstance(node, Sequence):
        return [plain(item) for item in node.items]
    if node.kind == "null":
        return None
    if node.kind in ("int", "float"):
        number = node.text.replace("_", "")
        try:
            return int(number) if node.kind == "int" else float(number)
        except ValueError:
            return node.text
    return node.text


def data(text: str):
    return plain(parse_source(text.encode("utf-8")).root)


def test_the_shipped_schema_is_what_gacli_schema_prints():
    result = CliRunner().invoke(app, ["schema"])
    assert result.exit_code == 0, result.output
    assert result.stdout == schema_text()
    assert SHIPPED.read_text(encoding="utf-8") == result.stdout, "run: gacli schema > schema/" + SCHEMA_FILE


def test_the_schema_is_stable_json():
    assert json.loads(schema_text()) == SCHEMA
    assert schema_text() == schema_text()


# -- in step with gacli.read.schema (the reader) ---------------------------------------------------

def properties(definition: dict) -> set[str]:
    found = set(definition.get("properties", {}))
    for choice in definition.get("oneOf", []):
        found |= set(choice.get("properties", {}))
    return found


def test_top_level_keys_follow_the_reader():
    assert tuple(SCHEMA["properties"]) == reader.TOP_KEYS


@pytest.mark.parametrize("definition, keys", [
    ("body", reader.BODY_KEYS),
    ("load", reader.LOAD_KEYS),
    ("frame", reader.FRAME_KEYS),
    ("rolling", reader.ROLLING_KEYS),
    ("constraint", reader.VELOCITY_CONSTRAINT_KEYS),
    ("parameter", reader.SYMBOL_KEYS),
    ("function", reader.SYMBOL_KEYS),
    ("plain_symbol", tuple(k for k in reader.SYMBOL_KEYS if k != "value")),
    ("quasi_coordinate", reader.QUASI_KEYS),
])
def test_keys_follow_the_reader(definition, keys):
    assert properties(DEFS[definition]) == set(keys)


# -- validation (needs the jsonschema package, a test-only dependency) --------------------------------

@pytest.fixture(scope="module")
def validator():
    jsonschema = pytest.importorskip("jsonschema")
    jsonschema.Draft202012Validator.check_schema(SCHEMA)
    return jsonschema.Draft202012Validator(json.loads(SHIPPED.read_text(encoding="utf-8")))


@pytest.mark.parametrize("path", SYSTEMS, ids=lambda p: p.stem)
def test_every_shipped_system_validates(validator, path):
    errors = [f"{list(e.absolute_path)}: {e.message}" for e in validator.iter_errors(data(path.read_text()))]
    assert errors == []


SMALL = """\
gacli: 1
name: small
parameters: {m: 1, l: {value: 2, unit: m}}
coordinates: [x]
bodies:
  b: {mass: m, position: [x, 0]}
"""


def test_a_small_file_validates(validator):
    assert validator.is_valid(data(SMALL))


@pytest.mark.parametrize("change", [
    ("gacli: 1", "gacli: 2"),
    ("name: small", "name: 2small"),
    ("coordinates: [x]", "coordinates: [x]\ncoordinate: [y]"),
    ("position: [x, 0]", "position: [x, 0, 0, 0]"),
    ("position: [x, 0]", "position: [x, 0], inertia: [m, m, m]"),
    ("position: [x, 0]", "position: [\"__import__('os')\", 0]"),
    ("position: [x, 0]", "position: [x; y, 0]"),
    ("coordinates: [x]", "coordinates: [x]\nconstraints: [dx = 0 = 1]"),
    ("coordinates: [x]", "coordinates: [x]\nframes: {A: {rotations: [[w, x]]}}"),
    ("coordinates: [x]", "coordinates: [x]\nrolling: [{body: b}]"),
    ("bodies:\n  b: {mass: m, position: [x, 0]}", "bodies: {}"),
])
def test_a_broken_file_does_not_validate(validator, change):
    old, new = change
    assert old in SMALL
    assert not validator.is_valid(data(SMALL.replace(old, new)))


def test_the_editor_line_is_documented():
    text = (ROOT / "docs" / "check.md").read_text(encoding="utf-8")
    assert "# yaml-language-server: $schema=" in text
    assert SCHEMA_FILE in text
