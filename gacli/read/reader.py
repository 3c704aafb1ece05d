"""Reading one place of a system file as the shape it must have, collecting every problem.

:class:`Reader` holds the diagnostics of one file; its methods read a
mapping with known keys, text, an expression, a list of expressions and a
vector, and report (in the file's terms, with the place) what they found
instead. The ``declare_*`` modules read the sections with it.
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass, field

from gacli.errors import Diagnostic
from gacli.read.schema import VectorDecl
from gacli.read.source import Mapping, Node, Scalar, Sequence, SourceFile

IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


@dataclass
class Reader:
    """Collects diagnostics while the declarations are read."""

    source: SourceFile
    diagnostics: list[Diagnostic] = field(default_factory=list)

    def error(self, node: Node, where: str, message: str, hint: str = "", offset: int | None = None) -> None:
        self.diagnostics.append(Diagnostic(self.source.location(node, offset), message, where, hint))

    def section(self, top: dict, key: str, kind: type, expected: str, null_is_empty: bool = False) -> Node | None:
        """A top-level section's node when it is a ``kind``; None when it is absent (or null, when that
        means empty) or of another shape, which is reported as "expected ``expected``"."""
        if key not in top:
            return None
        node = top[key][1]
        if null_is_empty and isinstance(node, Scalar) and node.kind == "null":
            return None
        if not isinstance(node, kind):
            self.error(node, key, f"expected {expected}, found {describe(node)}")
            return None
        return node

    def mapping(self, node: Node, where: str, allowed: tuple[str, ...]) -> dict[str, tuple[Scalar, Node]]:
        if not isinstance(node, Mapping):
            self.error(node, where, f"expected a mapping, found {describe(node)}")
            return {}
        out = {}
        for key, value in node.items:
            if key.text not in allowed:
                hint = did_you_mean(key.text, allowed) or _split(key, value)
                self.error(key, where, f"unknown key '{key.text}'", hint)
                continue
            out[key.text] = (key, value)
        return out

    def text(self, node: Node, where: str) -> str:
        if isinstance(node, Scalar):
            return node.text
        self.error(node, where, f"expected text, found {describe(node)}")
        return ""

    def expression(self, node: Node, where: str) -> Scalar | None:
        if isinstance(node, Scalar) and node.kind != "null" and node.text.strip():
            return node
        self.error(node, where, f"expected an expression, found {describe(node)}")
        return None

    def expressions(self, node: Node, where: str, sizes: tuple[int, ...]) -> tuple[Scalar, ...]:
        """A list of expressions of one of the given lengths (0 in sizes: a lone scalar is allowed)."""
        if isinstance(node, Scalar) and 1 in sizes and 0 in sizes:
            one = self.expression(node, where)
            return (one,) if one else ()
        if not isinstance(node, Sequence):
            self.error(node, where, f"expected a list of {_sizes(sizes)} expressions, found {describe(node)}")
            return ()
        if len(node.items) not in sizes:
            self.error(node, where, f"expected {_sizes(sizes)} components, found {len(node.items)}")
            return ()
        items = [self.expression(item, f"{where}[{i}]") for i, item in enumerate(node.items)]
        return tuple(items) if all(items) else ()

    def vector(self, node: Node, where: str, sizes: tuple[int, ...], point: bool = False) -> VectorDecl | None:
        """A vector: list, {frame: components, from: point} mapping, or (``point``) a point name."""
        if point and isinstance(node, Scalar):
            return VectorDecl(node, point=node) if self.name(node, where) else None
        if not isinstance(node, Mapping):
            components = self.expressions(node, where, sizes)
            return VectorDecl(node, components=components) if components else None
        terms, origin = [], None
        for key, value in node.items:
            if key.text == "from":
                origin = value if self.name(value, f"{where}.from") else None
                continue
            if self.name(key, where):
                components = self.expressions(value, f"{where}.{key.text}", (3,))
                if not components:
                    return None
                terms.append((key, components))
        if not terms and origin is None:
            self.error(node, where, "expected components in one or more frames, as {N: [x, y, z]}")
            return None
        return VectorDecl(node, terms=tuple(terms), origin=origin)

    def name(self, node: Node, where: str) -> str | None:
        if not isinstance(node, Scalar):
            self.error(node, where, f"expected a name, found {describe(node)}")
            return None
        if not IDENTIFIER.match(node.text):
            self.error(node, where, f"'{node.text}' is not a valid name", _name_hint(node.text))
            return None
        return node.text


def _name_hint(text: str) -> str:
    rule = "a name is an ASCII letter or '_' followed by ASCII letters, digits and '_'"
    if any(ord(ch) > 127 for ch in text):
        # θ is a letter to a reader and to Python, not to the grammar: expressions are ASCII.
        return rule + "; spell it out in ASCII (theta for \u03b8, phi for \u03c6); a symbol's `latex:` key sets how it prints"
    return rule


def _split(key: Scalar, value: Node) -> str:
    """A hint for words with no value in a mapping: a comma in {..} ends an entry, and split a text."""
    if " " in key.text and isinstance(value, Scalar) and value.kind == "null":
        return "a comma inside {...} starts a new entry; quote a text that holds one: description: \"a, b\""
    return ""


def did_you_mean(word: str, choices) -> str:
    """A hint naming the closest of ``choices``, or "" when none is close."""
    close = difflib.get_close_matches(word, sorted(choices), n=1, cutoff=0.6)
    return f"did you mean '{close[0]}'?" if close else ""


def _sizes(sizes: tuple[int, ...]) -> str:
    shown = [str(s) for s in sorted(sizes) if s]
    return " or ".join(shown)


def describe(node: Node) -> str:
    """What a node is, as a message says it: 'a mapping', 'a list', 'nothing' or its text quoted."""
    if isinstance(node, Mapping):
        return "a mapping"
    if isinstance(node, Sequence):
        return "a list"
    if node.kind == "null" or not node.text.strip():
        return "nothing"
    return f"'{node.text}'"
