"""Reading YAML: libyaml, when PyYAML has it, must give exactly the nodes and places PyYAML's own loader gives."""

from __future__ import annotations

import pytest

from conftest import ROOT
from gacli.read import source
from gacli.errors import SystemFileError

YAML_FILES = sorted(
    p for d in ("systems", "tests/invalid", "tests/hostile", "tests/cases", "benchmarks/cases")
    for p in (ROOT / d).glob("*.yaml")
)

needs_libyaml = pytest.mark.skipif(source.CParser is None, reason="PyYAML without libyaml")


def python_only(monkeypatch, data: bytes, path: str = "<string>"):
    """parse_source as without libyaml (the reference), or its error's diagnostics."""
    monkeypatch.setattr(source, "CParser", None)
    try:
        return source.parse_source(data, path).root
    except SystemFileError as exc:
        return [str(d) for d in exc.diagnostics]
    finally:
        monkeypatch.undo()


def either(data: bytes, path: str = "<string>"):
    try:
        return source.parse_source(data, path).root
    except SystemFileError as exc:
        return [str(d) for d in exc.diagnostics]


@needs_libyaml
@pytest.mark.parametrize("path", YAML_FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_libyaml_gives_the_nodes_and_places_of_pyyaml(path, monkeypatch):
    data = path.read_bytes()
    assert either(data, str(path)) == python_only(monkeypatch, data, str(path))


@needs_libyaml
def test_the_shipped_systems_are_read_by_libyaml():
    """The fast path is taken for ordinary files (else this speed-up silently vanishes)."""
    for path in sorted((ROOT / "systems").glob("*.yaml")):
        text = source._decode(path.read_bytes(), str(path))
        assert source._compose_fast(text) is not None, path


@needs_libyaml
@pytest.mark.parametrize("text", [
    "a: {b: , c: 1}\n",           # an empty value: libyaml places it at the ','
    "a: [x, {b: }]\n",
    "a: b\tc\n",                  # a tab in a plain scalar: libyaml accepts it
    "a: {p: {m: 1, pos?tion: 2}}\n",  # '?' inside a flow plain scalar: libyaml accepts it
    "a: |#\n  x\n",               # a comment right after '|': libyaml accepts it
    "a: 'it''s'\nb: \"x\\ty\"\nc: \"héllo\"\n",  # quoted text: offsets from the marks' index
    "a: 1\nb: [1, 2\n",           # a syntax error: PyYAML's message and place
    "a: 1\na: 2\n",               # a duplicate key
    "- &A [1]\n- *B\n",           # an undefined alias
    "name\ufeff: target\n",        # a byte-order mark mid-line: libyaml counts it as a column
    "a: !!python/object:os.system x\nb: {c: !y, d: 1}\n",  # a refused tag before a syntax error
    "a: !&!str x\n",               # a tag libyaml accepts and PyYAML refuses
])
def test_libyaml_and_pyyaml_agree_where_they_differ(text, monkeypatch):
    data = text.encode("utf-8")
    assert either(data) == python_only(monkeypatch, data)


def _error_of(text: str):
    with pytest.raises(SystemFileError) as info:
        source.parse_source(text.encode("utf-8"), "f.yaml")
    (diagnostic,) = info.value.diagnostics
    return diagnostic


@pytest.mark.parametrize("char", ["\x07", "\x1b", "\x7f", "\x08"])
def test_a_control_character_is_located_at_its_line(char):
    text = "gacli: 1\nname: c\ntitle: fine\ncoordinates: [x]\nbodies:\n  b: {mass: m" + char + ", position: [x, 0]}\n"
    d = _error_of(text)
    assert (d.location.line, d.location.column) == (6, 14)
    assert f"U+{ord(char):04X}" in d.message


@pytest.mark.parametrize(("text", "line", "column"), [
    ("gacli: 1\nparameters:\n  m: {value: 1}\n   k: {value: 2}\n", 4, 4),
    ("gacli: 1\nparameters:\n    m: {value: 1}\n  k: {value: 2}\n", 4, 3),
    ("bodies:\n  - a\n  - b\n - c\n", 4, 2),
])
def test_an_indentation_mistake_is_said_in_the_files_terms(text, line, column):
    d = _error_of(text)
    assert (d.location.line, d.location.column) == (line, column)
    assert "does not line up" in d.message and "<block" not in d.message


def test_a_key_indented_under_a_value_is_explained():
    d = _error_of("bodies:\n  b:\n    mass: m\n      position: [x, 0]\n")
    assert d.location.line == 4
    assert "indented deeper than the key above it" in d.message


def test_a_key_past_yamls_length_for_a_key_is_named():
    # PyYAML reads a plain key of at most 1024 characters; past it the ':' was 'inside a value'.
    d = _error_of("gacli: 1\nparameters:\n  " + "k" * 1100 + ": {value: 1}\n")
    assert (d.location.line, d.location.column) == (3, 3)
    assert "a key longer than 1024 characters" in d.message and "inside a value" not in d.message


def test_a_tab_is_named():
    d = _error_of("gacli: 1\nparameters:\n\tm: {value: 1}\n")
    assert d.location.line == 3 and "tab" in d.message
