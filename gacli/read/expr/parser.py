"""The recursive-descent parser of the expression grammar (:mod:`gacli.read.expr.grammar`).

:func:`parse` is the way in: text to an immutable tree, or a
:class:`~gacli.read.expr.grammar.ParseError` with the offset of the problem.
The nesting and height limits are checked as the tree is built.
"""

from __future__ import annotations

import difflib

from gacli.read.expr.grammar import (
    ARITY,
    FUNCTIONS,
    MAX_DEPTH,
    MAX_LENGTH,
    RATES,
    BinOp,
    Call,
    Name,
    Neg,
    Node,
    Num,
    ParseError,
    Rate,
    children,
    continues_chain,
)
from gacli.read.expr.tokens import Token, describe, show, tokenize

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
    tokens = tokenize(text)
    if tokens[0].kind == "end":
        raise ParseError("empty expression", 0)
    return _Parser(text, tokens).expression()


class _Parser:
    """Recursive descent over a token list that ends with an 'end' token.

    One level of nesting costs at most six Python frames (sum, term, unary,
    atom, named, call): about 600 at MAX_DEPTH, under the default limit of 1000.
    """

    def __init__(self, text: str, tokens: list[Token]) -> None:
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

    def _peek(self, ahead: int = 0) -> Token:
        return self.tokens[self.i + ahead]

    def _advance(self) -> Token:
        token = self.tokens[self.i]
        self.i += 1
        return token

    def _grow(self, node: Node, token: Token) -> Node:
        """Record the height of a new inner node, refusing trees taller than MAX_DEPTH."""
        # Keys by id() are safe: every node made here stays alive in the tree.
        heights = self.heights
        if isinstance(node, BinOp) and continues_chain(node):  # one more link of a chain: the chain is one level
            height = max(heights.get(id(node.left), 0), 1 + heights.get(id(node.right), 0))
        elif isinstance(node, BinOp):
            height = 1 + max(heights.get(id(node.left), 0), heights.get(id(node.right), 0))
        else:
            height = 1 + max((heights.get(id(child), 0) for child in children(node)), default=0)
        if height > MAX_DEPTH:
            raise ParseError(f"expression is nested too deeply (more than {MAX_DEPTH} levels)", token.pos)
        self.heights[id(node)] = height
        return node

    def _descend(self, token: Token) -> None:
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

    def _signs(self) -> list[Token]:
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
        raise ParseError(f"expected an expression, found {describe(token)}", token.pos)

    def _group(self, opening: Token) -> Node:
        self._descend(opening)
        node = self._sum()
        self._close(opening, "')' to close the '('")
        self.depth -= 1
        return node

    def _named(self, name: Token) -> Node:
        if self._peek().kind != "(":
            return _variable(name)
        if name.text in RATES:
            return self._rate(name)
        if name.text in FUNCTIONS:
            return self._call(name)
        raise _unknown_function(name)

    def _call(self, name: Token) -> Node:
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

    def _no_trailing_comma(self, comma: Token) -> None:
        if self._peek().kind == ")":
            raise ParseError("expected an argument after ',' (no trailing comma)", comma.pos)

    def _rate(self, name: Token) -> Rate:
        # Token i is '('; the rule is exactly NAME '(' NAME ')', so look, don't recurse.
        arg, closing = self._peek(1), self._peek(2)
        usage = f"{name.text}() takes a name, as in {name.text}(x)"
        if arg.kind != "name" or _is_function(arg.text):
            raise ParseError(usage, arg.pos)
        if closing.kind != ")":
            raise ParseError(f"expected ')' after {show(name.text + '(' + arg.text)}: {usage}",
                             closing.pos)
        self.i += 3
        return Rate(arg.text, RATES[name.text], name.pos)

    # Errors.

    def _close(self, opening: Token, expected: str) -> None:
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
        return ParseError(f"expected {expected}, found {describe(token)}", token.pos)

    def _where(self, pos: int) -> str:
        # Text from a YAML block scalar may span lines; a bare column would mislead.
        line = self.text.count("\n", 0, pos) + 1
        column = pos - (self.text.rfind("\n", 0, pos) + 1) + 1
        return f"column {column}" if line == 1 else f"line {line}, column {column}"


def _is_function(word: str) -> bool:
    return word in FUNCTIONS or word in RATES


def _variable(name: Token) -> Name:
    # A function name as a variable would shadow the function in generated code.
    if _is_function(name.text):
        raise ParseError(f"'{name.text}' is a function; call it as {name.text}(...)", name.pos)
    return Name(name.text, name.pos)


def _unknown_function(name: Token) -> ParseError:
    known = sorted(FUNCTIONS | RATES.keys())
    close = difflib.get_close_matches(name.text, known, n=1)
    if close:
        return ParseError(f"unknown function {show(name.text)} (did you mean '{close[0]}'?)",
                          name.pos)
    return ParseError(f"unknown function {show(name.text)}; the functions are "
                      f"{', '.join(known)} (and a product needs '*')", name.pos)


def _check_arity(name: Token, given: int) -> None:
    wanted = ARITY.get(name.text, 1)
    if given != wanted:
        plural = "" if wanted == 1 else "s"
        raise ParseError(
            f"{name.text}() takes exactly {wanted} argument{plural} ({given} given)", name.pos)


def _missing_operator(previous: Token, token: Token) -> ParseError:
    between = f"expected an operator between {show(previous.text)} and {show(token.text)}"
    if token.kind == "(":
        return ParseError(f"{between} (only a function name can be called; "
                          "write '*' for a product)", token.pos)
    return ParseError(f"{between} (write '*' for a product)", token.pos)
