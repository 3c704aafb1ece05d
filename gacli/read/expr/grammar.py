"""The restricted grammar of expressions in system files, parsed without eval.

System files may come from untrusted pull requests, so their expressions never
reach ``eval``, ``exec``, ``sympify`` or ``parse_expr``. This module reads them
with its own tokenizer and recursive-descent parser (standard library only)
into an immutable tree; turning the tree into SymPy is a separate step.

The grammar, with Python's precedence::

    expr  := sum
    sum   := term (('+' | '-') term)*
    term  := unary (('*' | '/') unary)*
    unary := ('-' | '+') unary | power
    power := atom ('**' unary)?              right-associative
    atom  := NUMBER | NAME | NAME '(' args ')' | '(' expr ')'
    args  := expr (',' expr)*

so ``a-b-c`` is ``(a-b)-c``, ``2**3**2`` is ``2**(3**2)``, ``-x**2`` is
``-(x**2)`` and ``2**-x`` is allowed.

* NUMBER is a decimal literal (``2``, ``0.5``, ``.5``, ``5.``, ``1.5e-3``),
  never signed, kept as written; at most 40 mantissa digits and an exponent of
  at most 300 in absolute value.
* NAME is an ASCII identifier that is neither a Python keyword nor contains
  ``__``.
* Only the functions in FUNCTIONS may be called (``atan2`` with two arguments,
  the others with one), plus the rate operators ``dot(x)`` and ``ddot(x)``
  whose argument is a bare name.

Nothing else exists: no implicit multiplication, attribute access, indexing,
strings or comparisons. Hostile input costs bounded work: at most MAX_LENGTH
characters, one pass over them, and two limits checked while parsing, long
before Python's recursion limit:

* at most MAX_DEPTH levels of nesting (parentheses, calls, signs, ``**``),
  which bounds the parser's own recursion;
* a tree at most MAX_DEPTH nodes tall. A chain ``a+b+...`` is a left-leaning
  tree one node taller per operator, so a sum of more than about MAX_DEPTH
  terms is refused; in exchange, anything that recurses over a parsed tree
  (the nodes' own ``==``, ``hash`` and ``repr``, the SymPy builder) is safe.
"""

from __future__ import annotations

import difflib
import keyword
import re
import unicodedata
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import NamedTuple

MAX_LENGTH = 10_000
MAX_DEPTH = 100
MAX_MANTISSA_DIGITS = 40
MAX_LITERAL_EXPONENT = 300

FUNCTIONS: frozenset[str] = frozenset(
    "sin cos tan asin acos atan atan2 sinh cosh tanh exp log sqrt abs sign".split()
)
_RATES = {"dot": 1, "ddot": 2}
_RATE_NAMES = {order: name for name, order in _RATES.items()}
_ARITY = {"atan2": 2}
_OPERATORS = frozenset({"+", "-", "*", "/", "**"})


class ParseError(Exception):
    """An expression that does not follow the grammar.

    ``pos`` is the 0-based offset in the text where the problem is.
    """

    def __init__(self, message: str, pos: int) -> None:
        super().__init__(message)
        self.message = message
        self.pos = pos

    def __str__(self) -> str:
        return self.message

    def __reduce__(self):  # two constructor arguments, so pickle needs telling
        return (type(self), (self.message, self.pos))


# --- The tree --------------------------------------------------------------
# ``pos`` is where the node starts in the text (for BinOp: its operator). It
# is left out of equality and hashing so trees compare by structure only.


@dataclass(frozen=True, slots=True)
class Num:
    """An unsigned number literal, exactly as written (``'0.5'``, ``'1e-3'``)."""

    text: str
    pos: int = field(default=0, compare=False)


@dataclass(frozen=True, slots=True)
class Name:
    """A name to be looked up by whoever builds the expression."""

    id: str
    pos: int = field(default=0, compare=False)


@dataclass(frozen=True, slots=True)
class Rate:
    """A time derivative of a name: ``dot(x)`` has order 1, ``ddot(x)`` order 2."""

    name: str
    order: int
    pos: int = field(default=0, compare=False)

    def __post_init__(self) -> None:
        if self.order not in _RATE_NAMES:
            raise ValueError(f"a rate has order 1 or 2, not {self.order!r}")


@dataclass(frozen=True, slots=True)
class Call:
    """A call of one of FUNCTIONS."""

    func: str
    args: tuple[Node, ...]
    pos: int = field(default=0, compare=False)


@dataclass(frozen=True, slots=True)
class Neg:
    """Unary minus (unary plus leaves no trace in the tree)."""

    operand: Node
    pos: int = field(default=0, compare=False)


@dataclass(frozen=True, slots=True)
class BinOp:
    """A binary operation; ``op`` is one of ``+ - * / **``."""

    op: str
    left: Node
    right: Node
    pos: int = field(default=0, compare=False)

    def __post_init__(self) -> None:
        if self.op not in _OPERATORS:
            raise ValueError(f"unknown operator {self.op!r}")


Node = Num | Name | Rate | Call | Neg | BinOp


# --- Tokens ----------------------------------------------------------------


class _Token(NamedTuple):
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


def _tokenize(text: str) -> list[_Token]:
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
            append(_Token(word, word, pos))
        elif kind != "space":
            append(_token(found, text))
        pos = found.end()
    tokens.append(_Token("end", "", len(text)))
    return tokens


def _token(match: re.Match[str], text: str) -> _Token:
    kind, word, pos = match.lastgroup, match.group(), match.start()
    if kind == "bad":
        raise ParseError(_NOT_ALLOWED[word], pos)
    if kind == "num":
        _check_number(word, pos, text)
    elif kind == "name":
        _check_name(word, pos)
    else:
        kind = word
    return _Token(kind, word, pos)


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
        raise ParseError(f"{_show(literal)} is a {base} literal; gacli takes only decimal numbers{hint}", pos)
    separated = _SEPARATED.match(text, pos)
    if separated and separated.end() > after:
        literal = separated.group()
        raise ParseError(f"{_show(literal)}: '_' between digits is not allowed in a number "
                         f"(write {_show(literal.replace('_', ''))})", pos)
    if text[after : after + 1] in ("e", "E"):  # '2e', '2e+': digits never came
        raise ParseError(
            f"malformed number {_show(text[pos : after + 1])}: an exponent needs digits, "
            "as in 1.5e-3 (and a product needs '*')", after)
    mantissa, _, exponent = word.lower().partition("e")
    if len(mantissa.replace(".", "")) > MAX_MANTISSA_DIGITS:
        raise ParseError(f"number {_show(word)} has more than {MAX_MANTISSA_DIGITS} digits", pos)
    # Strip before int(): a 5000-digit exponent must not reach int() at all.
    digits = exponent.lstrip("+-").lstrip("0")
    if len(digits) > len(str(MAX_LITERAL_EXPONENT)) or int(digits or "0") > MAX_LITERAL_EXPONENT:
        raise ParseError(
            f"the exponent of {_show(word)} is out of range "
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
        raise ParseError(f"name {_show(word)} contains '__': dunder names are not allowed", pos)


# YAML 1.1's spellings of the special floats: a '.' here is not attribute access.
_YAML_SPECIAL = re.compile(r"\.(?:inf|Inf|INF|nan|NaN|NAN)(?![A-Za-z0-9_])")


def _bad_character(char: str, pos: int, text: str = "") -> ParseError:
    special = _YAML_SPECIAL.match(text, pos)
    if special:
        return ParseError(f"{_show(special.group())} is YAML's spelling of "
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


def _show(text: str) -> str:
    """Quote text for a message, shortened: a name may be thousands of characters."""
    return f"'{text}'" if len(text) <= 24 else f"'{text[:20]}...'"


def _describe(token: _Token) -> str:
    return "end of text" if token.kind == "end" else _show(token.text)


# --- Parser ----------------------------------------------------------------

_OPERAND_START = frozenset({"num", "name", "("})
_ADDITIVE = frozenset({"+", "-"})
_MULTIPLICATIVE = frozenset({"*", "/"})
_OPERAND_END = frozenset({"num", "name", ")"})


def parse(text: str) -> Node:
    """Parse one expression; raises ParseError with the offset of the problem."""
    if not isinstance(text, str):
        raise TypeError(f"parse() takes a str, not {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise ParseError(
            f"expression is too long ({len(text)} characters; the limit is {MAX_LENGTH})",
            MAX_LENGTH)
    tokens = _tokenize(text)
    if tokens[0].kind == "end":
        raise ParseError("empty expression", 0)
    return _Parser(text, tokens).expression()


class _Parser:
    """Recursive descent over a token list that ends with an 'end' token.

    One level of nesting costs at most six Python frames (sum, term, unary,
    atom, named, call): about 600 at MAX_DEPTH, under the default limit of 1000.
    """

    def __init__(self, text: str, tokens: list[_Token]) -> None:
        self.text = text
        # Look-ahead goes at most two tokens past the end: padding with copies
        # of 'end' spares _peek a bounds check on every token.
        self.tokens = tokens + [tokens[-1]] * 3
        self.i = 0
        self.depth = 0
        self.heights: dict[int, int] = {}  # id(node) -> height; leaves are absent (0)

    def expression(self) -> Node:
        node = self._sum()
        token = self._peek()
        if token.kind == ")":
            raise ParseError("unmatched ')'", token.pos)
        if token.kind != "end":
            raise self._unexpected("an operator or the end of the expression")
        return node

    # Token access.

    def _peek(self, ahead: int = 0) -> _Token:
        return self.tokens[self.i + ahead]

    def _advance(self) -> _Token:
        token = self.tokens[self.i]
        self.i += 1
        return token

    def _grow(self, node: Node, token: _Token) -> Node:
        """Record the height of a new inner node, refusing trees taller than MAX_DEPTH."""
        # Keys by id() are safe: every node made here stays alive in the tree.
        heights = self.heights
        if isinstance(node, BinOp):
            height = 1 + max(heights.get(id(node.left), 0), heights.get(id(node.right), 0))
        else:
            height = 1 + max((heights.get(id(child), 0) for child in _children(node)), default=0)
        if height > MAX_DEPTH:
            raise ParseError(f"expression is nested too deeply (more than {MAX_DEPTH} levels; "
                             "each operator of a long sum or product is a level)", token.pos)
        self.heights[id(node)] = height
        return node

    def _descend(self, token: _Token) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ParseError(
                f"expression is nested too deeply (more than {MAX_DEPTH} levels)", token.pos)

    # Grammar rules.

    def _sum(self) -> Node:
        node = self._term()
        while self.tokens[self.i].kind in _ADDITIVE:
            op = self._advance()
            node = self._grow(BinOp(op.kind, node, self._term(), op.pos), op)
        return node

    def _term(self) -> Node:
        node = self._unary()
        while self.tokens[self.i].kind in _MULTIPLICATIVE:
            op = self._advance()
            node = self._grow(BinOp(op.kind, node, self._unary(), op.pos), op)
        return node

    def _unary(self) -> Node:
        # Signs are gathered by a loop, so '-----x' costs no Python frames.
        signs = self._signs()
        node = self._atom()
        if self._peek().kind == "**":
            node = self._exponent(node)
        for sign in reversed(signs):
            if sign.kind == "-":
                node = self._grow(Neg(node, sign.pos), sign)
        self.depth -= len(signs)
        return node

    def _signs(self) -> list[_Token]:
        signs = []
        while self._peek().kind in ("+", "-"):
            signs.append(self._advance())
            self._descend(signs[-1])
        return signs

    def _exponent(self, base: Node) -> Node:
        op = self._advance()
        self._descend(op)
        exponent = self._unary()
        self.depth -= 1
        return self._grow(BinOp("**", base, exponent, op.pos), op)

    def _atom(self) -> Node:
        token = self._advance()
        if token.kind == "num":
            return Num(token.text, token.pos)
        if token.kind == "name":
            return self._named(token)
        if token.kind == "(":
            return self._group(token)
        raise ParseError(f"expected an expression, found {_describe(token)}", token.pos)

    def _group(self, opening: _Token) -> Node:
        self._descend(opening)
        node = self._sum()
        self._close(opening, "')' to close the '('")
        self.depth -= 1
        return node

    def _named(self, name: _Token) -> Node:
        if self._peek().kind != "(":
            return _variable(name)
        if name.text in _RATES:
            return self._rate(name)
        if name.text in FUNCTIONS:
            return self._call(name)
        raise _unknown_function(name)

    def _call(self, name: _Token) -> Node:
        opening = self._advance()
        self._descend(opening)
        args = [] if self._peek().kind == ")" else [self._sum()]
        while self._peek().kind == ",":
            self._no_trailing_comma(self._advance())
            args.append(self._sum())
        self._close(opening, f"',' or ')' to close the '(' of {name.text}()")
        self.depth -= 1
        _check_arity(name, len(args))
        return self._grow(Call(name.text, tuple(args), name.pos), name)

    def _no_trailing_comma(self, comma: _Token) -> None:
        if self._peek().kind == ")":
            raise ParseError("expected an argument after ',' (no trailing comma)", comma.pos)

    def _rate(self, name: _Token) -> Rate:
        # Token i is '('; the rule is exactly NAME '(' NAME ')', so look, don't recurse.
        arg, closing = self._peek(1), self._peek(2)
        usage = f"{name.text}() takes a name, as in {name.text}(x)"
        if arg.kind != "name" or _is_function(arg.text):
            raise ParseError(usage, arg.pos)
        if closing.kind != ")":
            raise ParseError(f"expected ')' after {_show(name.text + '(' + arg.text)}: {usage}",
                             closing.pos)
        self.i += 3
        return Rate(arg.text, _RATES[name.text], name.pos)

    # Errors.

    def _close(self, opening: _Token, expected: str) -> None:
        if self._peek().kind != ")":
            raise self._unexpected(f"{expected} at {self._where(opening.pos)}")
        self._advance()

    def _unexpected(self, expected: str) -> ParseError:
        """The error for a token where an operator or a closing token should be."""
        token, previous = self._peek(), self.tokens[self.i - 1]
        if token.kind in _OPERAND_START and previous.kind in _OPERAND_END:
            return _missing_operator(previous, token)
        if token.kind == ",":
            return ParseError("',' is only allowed between the arguments of a function",
                              token.pos)
        return ParseError(f"expected {expected}, found {_describe(token)}", token.pos)

    def _where(self, pos: int) -> str:
        # Text from a YAML block scalar may span lines; a bare column would mislead.
        line = self.text.count("\n", 0, pos) + 1
        column = pos - (self.text.rfind("\n", 0, pos) + 1) + 1
        return f"column {column}" if line == 1 else f"line {line}, column {column}"


def _is_function(word: str) -> bool:
    return word in FUNCTIONS or word in _RATES


def _variable(name: _Token) -> Name:
    # A function name as a variable would shadow the function in generated code.
    if _is_function(name.text):
        raise ParseError(f"'{name.text}' is a function; call it as {name.text}(...)", name.pos)
    return Name(name.text, name.pos)


def _unknown_function(name: _Token) -> ParseError:
    known = sorted(FUNCTIONS | _RATES.keys())
    close = difflib.get_close_matches(name.text, known, n=1)
    if close:
        return ParseError(f"unknown function {_show(name.text)} (did you mean '{close[0]}'?)",
                          name.pos)
    return ParseError(f"unknown function {_show(name.text)}; the functions are "
                      f"{', '.join(known)} (and a product needs '*')", name.pos)


def _check_arity(name: _Token, given: int) -> None:
    wanted = _ARITY.get(name.text, 1)
    if given != wanted:
        plural = "" if wanted == 1 else "s"
        raise ParseError(
            f"{name.text}() takes exactly {wanted} argument{plural} ({given} given)", name.pos)


def _missing_operator(previous: _Token, token: _Token) -> ParseError:
    between = f"expected an operator between {_show(previous.text)} and {_show(token.text)}"
    if token.kind == "(":
        return ParseError(f"{between} (only a function name can be called; "
                          "write '*' for a product)", token.pos)
    return ParseError(f"{between} (write '*' for a product)", token.pos)


# --- Using trees -----------------------------------------------------------

_SUM, _PRODUCT, _UNARY, _POWER, _ATOM = 1, 2, 3, 4, 5
_PRECEDENCE = {"+": _SUM, "-": _SUM, "*": _PRODUCT, "/": _PRODUCT, "**": _POWER}
_SPELLING = {"+": " + ", "-": " - ", "*": "*", "/": "/"}


def render(node: Node) -> str:
    """Canonical text of a tree, with minimal parentheses: parse(render(n)) == n."""
    if isinstance(node, Num):
        return node.text
    if isinstance(node, Name):
        return node.id
    if isinstance(node, Rate):
        return f"{_RATE_NAMES[node.order]}({node.name})"
    if isinstance(node, Call):
        return f"{node.func}({', '.join(render(arg) for arg in node.args)})"
    if isinstance(node, Neg):
        return "-" + _operand(node.operand, _UNARY)
    if isinstance(node, BinOp):
        return _render_binop(node)
    raise TypeError(f"not an expression node: {node!r}")


def _precedence(node: Node) -> int:
    if isinstance(node, BinOp):
        return _PRECEDENCE[node.op]
    return _UNARY if isinstance(node, Neg) else _ATOM


def _operand(node: Node, weakest: int) -> str:
    """Render node where nothing binding weaker than ``weakest`` may stand bare."""
    text = render(node)
    return f"({text})" if _precedence(node) < weakest else text


def _render_binop(node: BinOp) -> str:
    if node.op == "**":  # (-x)**y, (a**b)**c: the base must be an atom
        return _operand(node.left, _ATOM) + "**" + _operand(node.right, _UNARY)
    # Follow the left spine of a left-associative chain with a loop: a long
    # sum is a deep tree, and recursing down it would hit the recursion limit.
    level, links = _PRECEDENCE[node.op], []
    left: Node = node
    while isinstance(left, BinOp) and _PRECEDENCE[left.op] == level:
        links.append(left)
        left = left.left
    parts = [_operand(left, level)]
    for link in reversed(links):
        parts += [_SPELLING[link.op], _operand(link.right, level + 1)]
    return "".join(parts)


def _children(node: Node) -> tuple[Node, ...]:
    if isinstance(node, BinOp):
        return (node.left, node.right)
    if isinstance(node, Neg):
        return (node.operand,)
    if isinstance(node, Call):
        return node.args
    return ()


def walk(node: Node) -> Iterator[Node]:
    """Every node of the tree in pre-order, with an explicit stack (any depth)."""
    stack = [node]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(reversed(_children(current)))


def names(node: Node) -> frozenset[str]:
    """The ids of every Name in the tree (not rate names, not function names)."""
    return frozenset(n.id for n in walk(node) if isinstance(n, Name))
