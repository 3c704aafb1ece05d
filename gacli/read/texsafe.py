"""A small math-TeX grammar: which ``latex:`` overrides may reach a .tex file.

A system file's ``latex:`` override is pasted into the generated LaTeX as
is, so TeX reads it as a program: ``\\input{/etc/passwd}``, ``\\openout``,
``\\def\\a{\\a}\\a`` or an unbalanced brace would run, write, loop or break the
document. An override is therefore accepted only if it is a *math name*
in this grammar (no SymPy, no regular expressions: a tokenizer and a
recursive-descent parser, so that every rejection has a position):

.. code:: text

    math     := item*                        (at most MAX_LENGTH characters)
    item     := nucleus scripts | script     (a script may open a group: {}^a)
    nucleus  := letter | digit | ',' | ' ' | group | symbol | accent argument
    scripts  := "'"* ('^' argument)? ('_' argument)?   (each at most once, any order)
    argument := letter | digit | symbol | group
    group    := '{' math '}'                  (nested at most MAX_DEPTH deep)

``symbol`` is an allowed command without argument (Greek letters, \\infty,
\\prime ...) and ``accent`` one that takes one (\\dot, \\hat, \\mathrm,
\\operatorname ...); every one of them is defined by LaTeX or amsmath, which
the generated document loads. Anything else (another command, ``\\,``, ``%``,
``#``, ``$``, ``&``, ``~``, a tab, a non-ASCII character) is rejected.

The same parser, with the commands of :data:`PRINTED`, decides whether the
LaTeX that SymPy's printer makes of a plain name is something the document
can typeset (``beth`` becomes ``\\beth``, which needs amssymb).

>>> check_math(r"\\bar{I}_{x}") is None
True
>>> check_math(r"\\input{/etc/passwd}").message
"'\\\\input' is not an allowed LaTeX command"
"""

from __future__ import annotations

from dataclasses import dataclass

MAX_LENGTH = 64
MAX_DEPTH = 8

GREEK = frozenset("""
    alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa
    lambda mu nu xi pi varpi rho varrho sigma varsigma tau upsilon phi varphi chi
    psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega
""".split())
# Symbols of plain LaTeX that make sense in a name.
SYMBOLS = GREEK | frozenset("prime ast star infty ell hbar imath jmath partial nabla circ bullet dagger".split())
# Commands of one argument: accents (amsmath has \dddot and \ddddot) and math fonts.
ACCENTS = frozenset("""
    dot ddot dddot ddddot hat bar tilde vec check breve acute grave mathring
    widehat widetilde overline underline
    mathrm mathbf mathcal mathit mathsf mathtt boldsymbol operatorname
""".split())


@dataclass(frozen=True)
class Dialect:
    """What a math name may contain: commands with no argument, with one, and plain characters."""

    symbols: frozenset[str]
    accents: frozenset[str]
    characters: str
    control_symbols: str = ""
    max_length: int = MAX_LENGTH


_LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
_DIGITS = "0123456789"
OVERRIDE = Dialect(SYMBOLS, ACCENTS, _LETTERS + _DIGITS + "', ")
# What SymPy's LatexPrinter writes for a plain name that the document can typeset:
# the override commands plus its \left|x\right| style modifiers. Not \beth, \gimel,
# \daleth, \mho, \eth, \hslash, \varkappa (amssymb), \mathscr (mathrsfs), \mathfrak (amsfonts).
PRINTED = Dialect(SYMBOLS | frozenset("aleph wp left right langle rangle".split()), ACCENTS,
                  _LETTERS + _DIGITS + "', |()", control_symbols="|", max_length=10**9)


@dataclass(frozen=True)
class TexProblem:
    """Why a text is not a math name, and the offset (0-based) of the culprit."""

    message: str
    offset: int


class _Reject(Exception):
    def __init__(self, message: str, offset: int) -> None:
        super().__init__(message)
        self.problem = TexProblem(message, offset)


@dataclass(frozen=True)
class _Token:
    kind: str   # "char", "command", "control", "{", "}", "^", "_", "bad", "end"
    text: str
    offset: int


def _describe(c: str) -> str:
    if c.isascii() and c.isprintable():
        return f"'{c}'"
    return f"U+{ord(c):04X}"


def tokenize(tex: str, dialect: Dialect = OVERRIDE) -> list[_Token]:
    """TeX's own split: a control word is a backslash and the letters after it.

    A character outside the dialect ends the list as a "bad" token, which the
    parser reports when it gets there (so ``\\input{/x}`` names ``\\input``).
    """
    tokens: list[_Token] = []
    i = 0
    while i < len(tex):
        c = tex[i]
        if c == "\\":
            j = i + 1
            while j < len(tex) and tex[j] in _LETTERS:
                j += 1
            if j == i + 1:
                if j < len(tex) and tex[j] in dialect.control_symbols:
                    tokens.append(_Token("control", tex[i:j + 1], i))
                    i = j + 1
                    continue
                shown = _describe(tex[j]) if j < len(tex) else "nothing"
                tokens.append(_Token("bad", f"a backslash followed by {shown} is not allowed", i))
                break
            tokens.append(_Token("command", tex[i:j], i))
            i = j
        elif c in "{}^_":
            tokens.append(_Token(c, c, i))
            i += 1
        elif c in dialect.characters:
            tokens.append(_Token("char", c, i))
            i += 1
        else:
            tokens.append(_Token("bad", f"the character {_describe(c)} is not allowed", i))
            break
    tokens.append(_Token("end", "", len(tex)))
    return tokens


class _Parser:
    """Recursive descent over the tokens; raises _Reject at the first problem."""

    def __init__(self, tokens: list[_Token], dialect: Dialect) -> None:
        self.tokens, self.dialect, self.at = tokens, dialect, 0

    def peek(self) -> _Token:
        return self.tokens[self.at]

    def take(self) -> _Token:
        token = self.tokens[self.at]
        if token.kind == "bad":
            raise _Reject(token.text, token.offset)
        self.at += 1
        return token

    def math(self, depth: int) -> None:
        """Items until '}' or the end (the caller checks which)."""
        while self.peek().kind not in ("}", "end"):
            if self.peek().kind not in ("^", "_"):
                self.nucleus(depth)
            self.scripts(depth)

    def nucleus(self, depth: int) -> None:
        token = self.take()
        if token.kind == "{":
            self.group(token, depth)
        elif token.kind == "command":
            self.command(token, depth)
        # a char or a control symbol stands alone

    def command(self, token: _Token, depth: int) -> None:
        name = token.text[1:]
        if name in self.dialect.accents:
            self.argument(token, depth)
        elif name not in self.dialect.symbols:
            raise _Reject(f"'{token.text}' is not an allowed LaTeX command", token.offset)

    def group(self, opening: _Token, depth: int) -> None:
        if depth >= MAX_DEPTH:
            raise _Reject(f"braces are nested more than {MAX_DEPTH} deep", opening.offset)
        self.math(depth + 1)
        if self.take().kind != "}":
            raise _Reject("this '{' is never closed", opening.offset)

    def argument(self, owner: _Token, depth: int) -> None:
        """One argument of an accent or a script: a character, a symbol, or a group."""
        while self.peek().text == " ":  # TeX skips spaces before an argument
            self.take()
        token = self.take()
        if token.kind == "{":
            self.group(token, depth)
        elif token.kind == "command" and token.text[1:] in self.dialect.symbols:
            return
        elif token.kind not in ("char", "control"):
            raise _Reject(f"'{owner.text}' needs an argument, as {owner.text}{{x}}", owner.offset)

    def scripts(self, depth: int) -> None:
        """Primes, then at most one '^' and one '_' (TeX's double-script errors otherwise)."""
        seen: set[str] = set()
        while self.peek().kind in ("^", "_") or (self.peek().text == "'" and not seen):
            token = self.take()
            if token.text == "'":
                continue
            if token.kind in seen:
                raise _Reject(f"a second '{token.kind}' on the same letter (write {{x^a}}^b)", token.offset)
            seen.add(token.kind)
            self.argument(token, depth)
        if self.peek().text == "'" and "^" in seen:
            raise _Reject("a prime after '^' is a second superscript (write x'^a)", self.peek().offset)


def check_math(tex: str, dialect: Dialect = OVERRIDE) -> TexProblem | None:
    """None if ``tex`` is a math name in ``dialect``; otherwise the first problem.

    The grammar is checked before the length, so that a long hostile text is
    reported for what it tries to do (the parser is linear, its depth bounded).
    """
    if not tex.strip():
        return TexProblem("it is empty", 0)
    try:
        parser = _Parser(tokenize(tex, dialect), dialect)
        parser.math(0)
        if parser.peek().kind == "}":
            raise _Reject("this '}' closes nothing", parser.peek().offset)
    except _Reject as error:
        return error.problem
    if len(tex) > dialect.max_length:
        return TexProblem(f"it is longer than {dialect.max_length} characters", dialect.max_length)
    return None


def is_printable_name(tex: str) -> bool:
    """Whether SymPy's LaTeX for a plain name uses only what the document provides."""
    return check_math(tex, PRINTED) is None
