"""The restricted grammar of expressions in system files, parsed without eval.

System files may come from untrusted pull requests, so their expressions never
reach ``eval``, ``exec``, ``sympify`` or ``parse_expr``. They are read with
gacli's own tokenizer (:mod:`gacli.read.expr.tokens`) and recursive-descent
parser (:mod:`gacli.read.expr.parser`, whose :func:`parse` is the way in), all
standard library only, into the immutable tree defined here; turning the tree
into SymPy is a separate step (:mod:`gacli.read.expr.build`). This module
holds what the others share: the limits, the functions, the tree and the
walks over it.

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
* a tree at most MAX_DEPTH nodes tall, where a chain ``a+b-c+...`` or
  ``a*b/c*...`` (a left-leaning tree, one BinOp per operator) counts as one
  level, whatever its length: a sum of 2,000 terms pasted from a CAS is an
  expression like any other. Everything that goes down a chain does so by a
  loop (the nodes' own ``==``, ``hash`` and ``repr`` here, :func:`render`,
  :func:`walk`, the SymPy builder), and recursion is left for the levels,
  so anything that recurses over a parsed tree is safe.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field

MAX_LENGTH = 10_000
MAX_DEPTH = 100
MAX_MANTISSA_DIGITS = 40
MAX_LITERAL_EXPONENT = 300

FUNCTIONS: frozenset[str] = frozenset(
    "sin cos tan asin acos atan atan2 sinh cosh tanh exp log sqrt abs sign".split()
)
RATES = {"dot": 1, "ddot": 2}
_RATE_NAMES = {order: name for name, order in RATES.items()}
ARITY = {"atan2": 2}
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


@dataclass(frozen=True, slots=True, eq=False, repr=False)
class BinOp:
    """A binary operation; ``op`` is one of ``+ - * / **``.

    ``==``, ``hash`` and ``repr`` are those a dataclass would make, computed by a loop down the
    left spine: a long sum is a tree as tall as it has terms (see the module).
    """

    op: str
    left: Node
    right: Node
    pos: int = field(default=0, compare=False)

    def __post_init__(self) -> None:
        if self.op not in _OPERATORS:
            raise ValueError(f"unknown operator {self.op!r}")

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, BinOp):
            return NotImplemented
        mine, theirs = _spine(self), _spine(other)
        return (len(mine) == len(theirs) and all(a.op == b.op for a, b in zip(mine, theirs))
                and mine[-1].left == theirs[-1].left and all(a.right == b.right for a, b in zip(mine, theirs)))

    def __hash__(self) -> int:
        links = _spine(self)
        return hash((tuple(link.op for link in links), links[-1].left, tuple(link.right for link in links)))

    def __repr__(self) -> str:
        links = _spine(self)
        opened = "".join(f"BinOp(op={link.op!r}, left=" for link in links)
        closed = "".join(f", right={link.right!r}, pos={link.pos!r})" for link in reversed(links))
        return opened + repr(links[-1].left) + closed


def _spine(node: BinOp) -> list[BinOp]:
    """``node`` and the BinOps down its left children, outermost first."""
    links = [node]
    while isinstance(links[-1].left, BinOp):
        links.append(links[-1].left)
    return links


Node = Num | Name | Rate | Call | Neg | BinOp


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
    level = _PRECEDENCE[node.op]
    first, links = chain(node)
    parts = [_operand(first, level)]
    for link in links:
        parts += [_SPELLING[link.op], _operand(link.right, level + 1)]
    return "".join(parts)


def chain(node: BinOp) -> tuple[Node, list[BinOp]]:
    """The first operand of the left-associative chain ``node`` ends (a ± b ± c ..., or a product) and
    its links, left to right, found by a loop: a long sum is a deep tree, and recursing down it would
    hit the recursion limit."""
    level, links = _PRECEDENCE[node.op], []
    left: Node = node
    while isinstance(left, BinOp) and _PRECEDENCE[left.op] == level:
        links.append(left)
        left = left.left
    return left, links[::-1]


def continues_chain(node: BinOp) -> bool:
    """Whether ``node``'s left operand is a link of the same sum or product (a power is never one)."""
    left = node.left
    return node.op != "**" and isinstance(left, BinOp) and _PRECEDENCE[left.op] == _PRECEDENCE[node.op]


def children(node: Node) -> tuple[Node, ...]:
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
        stack.extend(reversed(children(current)))


def names(node: Node) -> frozenset[str]:
    """The ids of every Name in the tree (not rate names, not function names)."""
    return frozenset(n.id for n in walk(node) if isinstance(n, Name))
