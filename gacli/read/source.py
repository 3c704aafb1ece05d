"""Read a system file into YAML nodes that remember where they came from.

The YAML is *composed*, never *constructed*: PyYAML's composer with the safe
loader builds a node graph and no Python object is made from a tag, so a
``!!python/object`` tag is just an unknown tag that we report. Scalars keep
their source text, so ``0.1`` stays the exact decimal the user wrote and a key
``on`` stays the string ``on`` (YAML 1.1 would make it ``True``).

Scanning and parsing in pure Python is most of the time of reading a file,
so when PyYAML has libyaml, libyaml does them and the same Python composer
builds the nodes. Whatever libyaml refuses, or might read otherwise than
PyYAML, is read again by the pure-Python loader, whose nodes and messages
are the reference.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Union

import yaml
from yaml.composer import Composer
from yaml.reader import Reader
from yaml.resolver import Resolver

try:
    from yaml._yaml import CParser
except ImportError:  # PyYAML built without libyaml
    CParser = None

from gacli.errors import Diagnostic, Location, SystemFileError

MAX_FILE_BYTES = 1_000_000
MAX_DEPTH = 32
MAX_NODES = 100_000
# Characters of scalar text once every alias is expanded. Loading costs time
# in proportion to this, not to the file's size: 30,000 aliases of one 2 KB
# expression are a 150 kB file that reads as 60 MB of expressions. Twice the
# largest file leaves room for anchors used as intended.
MAX_EXPANDED_CHARS = 2 * MAX_FILE_BYTES

# Tags of plain data; any other tag (``!!python/...``, ``!custom``) is refused.
_SCALAR_TAGS = {
    "tag:yaml.org,2002:str": "str",
    "tag:yaml.org,2002:int": "int",
    "tag:yaml.org,2002:float": "float",
    "tag:yaml.org,2002:bool": "bool",
    "tag:yaml.org,2002:null": "null",
}
_MAP_TAG = "tag:yaml.org,2002:map"
_SEQ_TAG = "tag:yaml.org,2002:seq"


@dataclass(frozen=True)
class Scalar:
    """A YAML scalar: its text as written, its resolved kind and its place.

    ``offset_base`` is the column (0-based) of the text's first character when
    the scalar sits on one line, so that a column inside an expression can be
    mapped back to the file; ``None`` when it cannot (block or folded text).
    """

    text: str
    kind: str
    line: int
    column: int
    offset_base: int | None

    def column_of(self, offset: int) -> tuple[int, int]:
        """(line, column), 1-based, of character ``offset`` of the text."""
        if self.offset_base is None:
            return self.line, self.column
        return self.line, self.offset_base + offset + 1


@dataclass(frozen=True)
class Mapping:
    items: tuple[tuple[Scalar, "Node"], ...]
    line: int
    column: int


@dataclass(frozen=True)
class Sequence:
    items: tuple["Node", ...]
    line: int
    column: int


Node = Union[Scalar, Mapping, Sequence]


@dataclass(frozen=True)
class SourceFile:
    """The text of a system file, its SHA-256 and its root node."""

    path: str
    text: str
    sha256: str
    root: Node

    def location(self, node: Node, offset: int | None = None) -> Location:
        if isinstance(node, Scalar) and offset is not None:
            line, col = node.column_of(offset)
            return Location(self.path, line, col)
        return Location(self.path, node.line, node.column)


def _fail(path: str, message: str, line: int = 1, column: int = 1) -> SystemFileError:
    return SystemFileError([Diagnostic(Location(path, line, column), message)])


def read_source(path: str | Path) -> SourceFile:
    """Read and compose a system file; every failure is a located SystemFileError."""
    name = str(path)
    try:
        if not Path(path).exists():
            raise _fail(name, "no such file")
        if not Path(path).is_file():
            raise _fail(name, "not a regular file")
        # Read one byte past the limit rather than trusting the size: the
        # path may be a FIFO or a link to /dev/zero.
        with open(path, "rb") as handle:
            data = handle.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise _fail(name, f"cannot read the file: {exc.strerror or exc}") from None
    if len(data) > MAX_FILE_BYTES:
        raise _fail(name, f"file is too large (more than {MAX_FILE_BYTES} bytes)")
    return parse_source(data, name)


def parse_source(data: bytes, path: str = "<string>") -> SourceFile:
    """Compose YAML from bytes (UTF-8) into located nodes."""
    if len(data) > MAX_FILE_BYTES:
        raise _fail(path, f"file is too large ({len(data)} bytes; the limit is {MAX_FILE_BYTES})")
    text = _decode(data, path)
    digest = hashlib.sha256(data).hexdigest()
    root = _compose_fast(text)
    if root is not None:
        _check_expansion(root, path, text)
        try:
            return SourceFile(path, text, digest, _Converter(path, text, libyaml=True).convert(root, 0))
        except (_NotLikePyYAML, SystemFileError):
            # An error found on libyaml's nodes may hide one PyYAML reports
            # earlier in the text: errors always come from the reference path.
            pass
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as exc:
        raise _fail(path, *_marked_problem(exc)) from None
    except yaml.reader.ReaderError as exc:
        raise _fail(path, *_reader_problem(exc, text)) from None
    except yaml.YAMLError as exc:
        raise _fail(path, f"invalid YAML: {exc}".splitlines()[0]) from None
    except RecursionError:
        raise _fail(path, f"YAML is nested too deeply (the limit is {MAX_DEPTH} levels)") from None
    if root is None:
        raise _fail(path, "the file is empty; a system file is a YAML mapping", 1, 1)
    _check_expansion(root, path, text)
    return SourceFile(path, text, digest, _Converter(path, text).convert(root, 0))


def _check_expansion(root: yaml.Node, path: str, text: str) -> None:
    """Refuse a node graph whose expansion passes the limits, before anything walks the expansion.

    Aliases share nodes, so the sizes are summed over the graph with each
    distinct node counted once (a walk of the graph, not of its expansion):
    a billion laughs is refused in the time it takes to read it.
    """
    sizes: dict[int, tuple[int, int]] = {}
    open_nodes: set[int] = set()  # entered, children not yet done: meeting one again is a cycle
    stack: list[tuple[yaml.Node, bool]] = [(root, False)]
    while stack:
        node, children_done = stack.pop()
        if id(node) in sizes:
            continue
        children = _children(node)
        if not children_done:
            if id(node) in open_nodes:
                mark = node.start_mark
                raise _fail(path, "the YAML contains itself (an alias inside the node it names)",
                            mark.line + 1, mark.column + 1)
            open_nodes.add(id(node))
            stack.append((node, True))
            stack.extend((child, False) for child in children if id(child) not in sizes)
            continue
        open_nodes.discard(id(node))
        nodes = 1 + sum(sizes[id(c)][0] for c in children)
        chars = (len(node.value) if isinstance(node, yaml.ScalarNode) else 0) + sum(sizes[id(c)][1] for c in children)
        sizes[id(node)] = (nodes, chars)
        if nodes > MAX_NODES or chars > MAX_EXPANDED_CHARS:
            what = f"{MAX_NODES} nodes" if nodes > MAX_NODES else f"{MAX_EXPANDED_CHARS} characters of text"
            mark = node.start_mark
            # Without an anchor (&) nothing can be repeated: the file itself is that large.
            why = "aliases repeat this part; " if "&" in text else ""
            raise _fail(path, f"the YAML expands to more than {what} ({why}the file has {len(text)} characters)",
                        mark.line + 1, mark.column + 1)


def _children(node: yaml.Node) -> list[yaml.Node]:
    if isinstance(node, yaml.SequenceNode):
        return list(node.value)
    if isinstance(node, yaml.MappingNode):
        return [n for pair in node.value for n in pair]
    return []


# Text that libyaml reads where PyYAML's scanner refuses it (found by
# comparing the two on mutated system files).
# A byte-order mark inside the text: libyaml counts it as a column, PyYAML not.
_LIBYAML_DIFFERS = re.compile(r"[\t?\ufeff]|[|>][-+0-9]*#")

if CParser is not None:

    class _LibyamlComposer(Composer, Resolver, CParser):
        """libyaml's events, composed and resolved by PyYAML's own Python classes.

        Only the event source differs from ``yaml.SafeLoader``: the nodes,
        tags and marks are the same (the plain style is ``''``, not None), and
        no constructor is present, so nothing can build a Python object.
        """

        def __init__(self, text: str) -> None:
            CParser.__init__(self, text)
            Composer.__init__(self)
            Resolver.__init__(self)


def _compose_fast(text: str) -> yaml.Node | None:
    """The root node through libyaml; None when it is missing, finds a problem or an empty file.

    On a problem the caller composes again with the pure-Python loader, so
    that errors (and the few inputs libyaml and PyYAML judge differently)
    behave exactly as without libyaml. libyaml accepts some text that PyYAML
    refuses (characters its reader rejects, a tab or a '?' inside a plain
    scalar, ``|#``), so such text goes to the Python loader directly.
    """
    if CParser is None or _LIBYAML_DIFFERS.search(text) or Reader.NON_PRINTABLE.search(text):
        return None
    loader = _LibyamlComposer(text)
    try:
        return loader.get_single_node()
    except (yaml.YAMLError, RecursionError):
        return None
    finally:
        loader.dispose()


_YAML_KEY_LIMIT = 1024


def _indent(mark) -> int:
    """Where the marked line's text starts (0-based), where PyYAML kept the text; else 0."""
    buffer, pointer = getattr(mark, "buffer", None), getattr(mark, "pointer", None)
    if not isinstance(buffer, str) or pointer is None:
        return 0
    start = buffer.rfind("\n", 0, pointer) + 1
    return len(buffer[start:pointer]) - len(buffer[start:pointer].lstrip(" "))


def _marked_problem(exc: yaml.MarkedYAMLError) -> tuple[str, int, int]:
    """PyYAML's complaint in the file's terms, where PyYAML's own words are parser jargon."""
    mark = exc.problem_mark or exc.context_mark
    line, col = (mark.line + 1, mark.column + 1) if mark else (1, 1)
    problem = exc.problem or exc.context or "invalid YAML"
    context = exc.context_mark
    if problem.startswith("expected <block end>") and context is not None:
        # The scanner closed the mapping or list that began at the context mark,
        # then met more content: a line indented unlike its siblings.
        return (f"invalid YAML: this line is indented to column {col}, which does not line up with the "
                f"entries it follows (the block at line {context.line + 1} starts at column "
                f"{context.column + 1}); entries of one mapping or list must start in the same column",
                line, col)
    if problem == "mapping values are not allowed here" and col > _YAML_KEY_LIMIT:
        # PyYAML ends a plain key at 1024 characters and then finds this ':' inside a value.
        return (f"invalid YAML: a key longer than {_YAML_KEY_LIMIT} characters, the most YAML reads as "
                "a key; shorten it", line, 1 + _indent(mark))
    if problem == "mapping values are not allowed here":
        return ("invalid YAML: a ':' inside a value: this line is indented deeper than the key above it, so it "
                "reads as part of that key's value; start it in the same column as its siblings, or quote "
                "the value if the ':' belongs to it", line, col)
    if "'\\t'" in problem:  # PyYAML names the character by its repr
        return "invalid YAML: a tab character; YAML indents with spaces only", line, col
    return f"invalid YAML: {problem}", line, col


def _reader_problem(exc: yaml.reader.ReaderError, text: str) -> tuple[str, int, int]:
    """A character PyYAML refuses, located at its line rather than at the top of the file."""
    position = max(0, min(exc.position, len(text)))
    line = text.count("\n", 0, position) + 1
    col = position - (text.rfind("\n", 0, position) + 1) + 1
    char = exc.character if isinstance(exc.character, int) else ord(str(exc.character)[:1] or "?")
    return f"invalid YAML: control character U+{char:04X} is not allowed in a YAML file", line, col


def _decode(data: bytes, path: str) -> str:
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise _fail(path, f"the file is not UTF-8 text (byte 0x{data[exc.start]:02x} at offset {exc.start})", line, 1) from None
    if "\x00" in text:
        line = text[: text.index("\x00")].count("\n") + 1
        raise _fail(path, "the file contains a NUL byte; it is not a text file", line, 1)
    return text


class _NotLikePyYAML(Exception):
    """libyaml's nodes may differ from PyYAML's here: compose with PyYAML instead."""


class _Converter:
    """Walks the composed node graph once, bounding depth and total size.

    Aliases make the graph a DAG whose tree expansion can be exponential
    ("billion laughs"), so the walk counts every node it visits and the
    characters of every scalar it visits: what later steps read is the
    expansion, so that is what is bounded.
    """

    def __init__(self, path: str, text: str, libyaml: bool = False) -> None:
        self.path = path
        self.text = text
        self.libyaml = libyaml
        self.count = 0
        self.chars = 0

    def convert(self, node: yaml.Node, depth: int) -> Node:
        self.count += 1
        line, col = node.start_mark.line + 1, node.start_mark.column + 1
        if self.count > MAX_NODES:
            raise _fail(self.path, f"the YAML expands to more than {MAX_NODES} nodes (aliases?)", line, col)
        if depth > MAX_DEPTH:
            raise _fail(self.path, f"YAML is nested too deeply (the limit is {MAX_DEPTH} levels)", line, col)
        if isinstance(node, yaml.ScalarNode):
            return self._scalar(node)
        if isinstance(node, yaml.SequenceNode) and node.tag == _SEQ_TAG:
            return Sequence(tuple(self.convert(n, depth + 1) for n in node.value), line, col)
        if isinstance(node, yaml.MappingNode) and node.tag == _MAP_TAG:
            return self._mapping(node, depth, line, col)
        raise _fail(self.path, f"YAML tag '{node.tag}' is not allowed in a system file", line, col)

    def _scalar(self, node: yaml.ScalarNode) -> Scalar:
        if self.libyaml and not node.value and not node.style:
            # An empty value (``{a: , b: 1}``) is placed by libyaml at the
            # next token, by PyYAML after the ':'; only PyYAML's place is known.
            raise _NotLikePyYAML
        line, col = node.start_mark.line + 1, node.start_mark.column + 1
        self.chars += len(node.value)
        if self.chars > MAX_EXPANDED_CHARS:
            why = f"aliases repeat {len(node.value)} characters here; " if "&" in self.text else ""
            raise _fail(self.path, f"the YAML expands to more than {MAX_EXPANDED_CHARS} characters of text "
                        f"({why}the file has {len(self.text)})", line, col)
        kind = _SCALAR_TAGS.get(node.tag)
        if kind is None:
            raise _fail(self.path, f"YAML tag '{node.tag}' is not allowed in a system file", line, col)
        return Scalar(node.value, kind, line, col, _offset_base(node, self.text))

    def _mapping(self, node: yaml.MappingNode, depth: int, line: int, col: int) -> Mapping:
        items = []
        seen: dict[str, Scalar] = {}
        for key_node, value_node in node.value:
            key = self.convert(key_node, depth + 1)
            if not isinstance(key, Scalar):
                raise _fail(self.path, "a mapping key must be a plain name", key.line, key.column)
            if key.text in seen:
                first = seen[key.text]
                raise _fail(self.path, f"duplicate key '{key.text}' (first at line {first.line})", key.line, key.column)
            seen[key.text] = key
            items.append((key, self.convert(value_node, depth + 1)))
        return Mapping(tuple(items), line, col)


def _offset_base(node: yaml.ScalarNode, text: str) -> int | None:
    """Column (0-based) of the first character of a one-line scalar's text."""
    start, end = node.start_mark, node.end_mark
    if start.line != end.line:
        return None
    if node.style in ("'", '"'):
        # Escapes would shift offsets; only trust quoted text without them.
        # Both loaders count a mark's index in characters of ``text``
        # (libyaml's marks carry no buffer).
        raw = text[start.index + 1 : end.index - 1]
        return start.column + 1 if raw == node.value else None
    if not node.style:  # plain: None from PyYAML, '' from libyaml
        return start.column
    return None
