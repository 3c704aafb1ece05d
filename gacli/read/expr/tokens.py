"""The tokenizer of the expression grammar (:mod:`gacli.read.expr.grammar`): text to tokens.

One pass with one regular expression; every character the grammar has no
use for is refused here, with a message that says what it would have meant
(``^`` for a power, ``.inf`` from YAML, a Greek letter pasted from a paper)
and the offset where it is. Number literals are checked for size before any
``int()`` sees them.
"""

from __future__ import annotations

import keyword
import re
import unicodedata
from typing import NamedTuple

from gacli.read.expr.grammar import MAX_LITERAL_EXPONENT, MAX_MANTISSA_DIGITS, ParseError

class Token(NamedTuple):
    kind: str  # 'num', 'name', 'end', or the operator itself: '+', '**', '(' ...
    text: str
    pos: int


# Character classes are spelled out because \d and \w also match non-ASCII.
_NUMBER = r"(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
_SCANNER = re.compile(
    r"(?P<space>[ \t\r\n]+)"
    rf"|(?P<num>{_NUMBER})"
    r"|(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
    r"|(?P<bad>//|==|!=|<=|>=|:=|<<|>>)"
    r"|(?P<op>\*\*|[-+*/(),])"
)

_COMPARISON = "comparisons and assignments are not allowed in an expression"
_NOT_ALLOWED = {
    "^": "'^' is not an operator here; write ** for a power",
    ".": "attribute access ('.') is not allowed in an expression",
    "[": "'[' is not allowed in an expression (no indexing or lists)",
    "]": "']' is not allowed in an expression (no indexing or lists)",
    "'": "strings are not allowed in an expression",
    '"': "strings are not allowed in an expression",
    "=": _COMPARISON,
    "<": _COMPARISON,
    ">": _COMPARISON,
    "==": _COMPARISON,
    "!=": _COMPARISON,
    "<=": _COMPARISON,
    ">=": _COMPARISON,
    ":=": _COMPARISON,
    "//": "'//' (floor division) is not allowed in an expression; write / for division",
    "<<": "'<<' is not allowed in an expression (no bit shifts)",
    ">>": "'>>' is not allowed in an expression (no bit shifts)",
    "%": "'%' is not allowed in an expression (no remainder or formatting)",
    "@": "'@' is not allowed in an expression (no matrix products or decorators)",
    "{": "'{' is not allowed in an expression (no sets, dicts or formatting)",
    "}": "'}' is not allowed in an expression (no sets, dicts or formatting)",
    ":": "':' is not allowed in an expression (no slices, lambdas or annotations)",
    ";": "';' is not allowed in an expression (write a single expression)",
    "!": "'!' is not allowed in an expression",
    "&": "'&' is not allowed in an expression (no bitwise or logical operators)",
    "|": "'|' is not allowed in an expression (no bitwise or logical operators)",
    "~": "'~' is not allowed in an expression (no bitwise or logical operators)",
    "\\": "a backslash is not allowed in an expression",
    "#": "'#' is not allowed in an expression (no comments)",
}
# Look-alikes that people paste from papers.
_ASCII_FOR = {"\u2212": "-", "\u00d7": "*", "\u00b7": "*", "\u22c5": "*", "\u00f7": "/",
              "\u00b2": "**2", "\u00b3": "**3"}
_GREEK = re.compile(r"GREEK (SMALL|CAPITAL) LETTER ([A-Z]+)")


def tokenize(text: str) -> list[Token]:
    tokens = []
    append, match = tokens.append, _SCANNER.match
    pos, end = 0, len(text)
    while pos < end:
        found = match(text, pos)
        if found is None:
            raise _bad_character(text[pos], pos, text)
        kind = found.lastgroup
        if kind == "op":  # the commonest token needs no checks: spare it _token's call
            word = found.group()
            append(Token(word, word, pos))
        elif kind != "space":
            append(_token(found, text))
        pos = found.end()
    tokens.append(Token("end", "", len(text)))
    return tokens


def _token(match: re.Match[str], text: str) -> Token:
    kind, word, pos = match.lastgroup, match.group(), match.start()
    if kind == "bad":
        raise ParseError(_NOT_ALLOWED[word], pos)
    if kind == "num":
        _check_number(word, pos, text)
    elif kind == "name":
        _check_name(word, pos)
    else:
        kind = word
    return Token(kind, word, pos)


_PREFIXED = re.compile(r"0([xXbBoO])[0-9A-Fa-f_]+")
_BASES = {"x": "hexadecimal", "b": "binary", "o": "octal"}
_SEPARATED = re.compile(r"[0-9]+(?:_[0-9]+)+")


def _check_number(word: str, pos: int, text: str) -> None:
    after = pos + len(word)
    prefixed = _PREFIXED.match(text, pos)
    if prefixed and word == "0":
        literal = prefixed.group()
        base = _BASES[prefixed.group(1).lower()]
        value = _integer(literal, 0)
        hint = f" (write {value})" if value is not None else ""
        raise ParseError(f"{show(literal)} is a {base} literal; gacli takes only decimal numbers{hint}", pos)
    separated = _SEPARATED.match(text, pos)
    if separated and separated.end() > after:
        literal = separated.group()
        raise ParseError(f"{show(literal)}: '_' between digits is not allowed in a number "
                         f"(write {show(literal.replace('_', ''))})", pos)
    if text[after : after + 1] in ("e", "E"):  # '2e', '2e+': digits never came
        raise ParseError(
            f"malformed number {show(text[pos : after + 1])}: an exponent needs digits, "
            "as in 1.5e-3 (and a product needs '*')", after)
    mantissa, _, exponent = word.lower().partition("e")
    if len(mantissa.replace(".", "")) > MAX_MANTISSA_DIGITS:
        raise ParseError(f"number {show(word)} has more than {MAX_MANTISSA_DIGITS} digits", pos)
    # Strip before int(): a 5000-digit exponent must not reach int() at all.
    digits = exponent.lstrip("+-").lstrip("0")
    if len(digits) > len(str(MAX_LITERAL_EXPONENT)) or int(digits or "0") > MAX_LITERAL_EXPONENT:
        raise ParseError(
            f"the exponent of {show(word)} is out of range "
            f"(at most {MAX_LITERAL_EXPONENT} in absolute value)", pos)


def _integer(literal: str, base: int) -> int | None:
    """The literal's value when it is short enough to show, else None (a message, not a computation)."""
    if len(literal) > 18:
        return None
    try:
        return int(literal, base)
    except ValueError:
        return None


def _check_name(word: str, pos: int) -> None:
    if keyword.iskeyword(word):
        raise ParseError(f"'{word}' is a Python keyword, not allowed in an expression", pos)
    if "__" in word:
        raise ParseError(f"name {show(word)} contains '__': dunder names are not allowed", pos)


# YAML 1.1's spellings of the special floats: a '.' here is not attribute access.
_YAML_SPECIAL = re.compile(r"\.(?:inf|Inf|INF|nan|NaN|NAN)(?![A-Za-z0-9_])")


def _bad_character(char: str, pos: int, text: str = "") -> ParseError:
    special = _YAML_SPECIAL.match(text, pos)
    if special:
        return ParseError(f"{show(special.group())} is YAML's spelling of "
                          f"{'infinity' if special.group()[1] in 'iI' else 'not-a-number'}; "
                          "gacli takes only finite decimal numbers", pos)
    if char in _NOT_ALLOWED:
        return ParseError(_NOT_ALLOWED[char], pos)
    if char.isascii() and char.isprintable():
        return ParseError(f"'{char}' is not allowed in an expression", pos)
    if char.isascii():
        return ParseError(f"control character U+{ord(char):04X} is not allowed in an expression", pos)
    return ParseError(_non_ascii_message(char), pos)


def _non_ascii_message(char: str) -> str:
    described = f"U+{ord(char):04X} {unicodedata.name(char, '')}".rstrip()
    message = f"non-ASCII character {char!r} ({described}) is not allowed in an expression"
    greek = _GREEK.fullmatch(unicodedata.name(char, ""))
    if char in _ASCII_FOR:
        return f"{message}; write {_ASCII_FOR[char]!r}"
    if greek:
        letter = greek[2].lower() if greek[1] == "SMALL" else greek[2].capitalize()
        return f"{message}; write {letter!r}"
    return message


def show(text: str) -> str:
    """Quote text for a message, shortened: a name may be thousands of characters."""
    return f"'{text}'" if len(text) <= 24 else f"'{text[:20]}...'"


def describe(token: Token) -> str:
    return "end of text" if token.kind == "end" else show(token.text)
