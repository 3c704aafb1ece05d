"""Tests of the expression grammar: structure, errors, hostile input, round trips."""

from __future__ import annotations

import ast
import pathlib
import pickle

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gacli.read.expr import grammar, parser, tokens
from gacli.read.expr.grammar import (
    FUNCTIONS,
    MAX_DEPTH,
    MAX_LENGTH,
    BinOp,
    Call,
    Name,
    Neg,
    Num,
    ParseError,
    Rate,
    names,
    render,
    walk,
)
from gacli.read.expr.parser import parse

x, y, z = Name("x"), Name("y"), Name("z")
a, b, c = Name("a"), Name("b"), Name("c")


def error(text: str) -> ParseError:
    with pytest.raises(ParseError) as info:
        parse(text)
    return info.value


# --- Structure ---------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "tree"),
    [
        ("a-b-c", BinOp("-", BinOp("-", a, b), c)),
        ("a/b/c", BinOp("/", BinOp("/", a, b), c)),
        ("a+b*c", BinOp("+", a, BinOp("*", b, c))),
        ("(a+b)*c", BinOp("*", BinOp("+", a, b), c)),
        ("a*b**c", BinOp("*", a, BinOp("**", b, c))),
        ("2**3**2", BinOp("**", Num("2"), BinOp("**", Num("3"), Num("2")))),
        ("-x**2", Neg(BinOp("**", x, Num("2")))),
        ("(-x)**2", BinOp("**", Neg(x), Num("2"))),
        ("2**-x", BinOp("**", Num("2"), Neg(x))),
        ("2**-x**2", BinOp("**", Num("2"), Neg(BinOp("**", x, Num("2"))))),
        ("-a*b", BinOp("*", Neg(a), b)),
        ("a*-b", BinOp("*", a, Neg(b))),
        ("a - -b", BinOp("-", a, Neg(b))),
        ("+x", x),
        ("-+-x", Neg(Neg(x))),
        ("--x", Neg(Neg(x))),
        ("-2", Neg(Num("2"))),
        ("((x))", x),
        (" \t x\n*\r\n y ", BinOp("*", x, y)),
    ],
)
def test_precedence_and_associativity(text: str, tree: grammar.Node) -> None:
    assert parse(text) == tree


@pytest.mark.parametrize("text", ["2", "0.5", ".5", "5.", "1.5e-3", "2E+4", "1e5", "007", "1.e5"])
def test_numbers_keep_their_text(text: str) -> None:
    assert parse(text) == Num(text)
    assert parse(text).text == text


def test_number_limits() -> None:
    assert parse("9" * 40) == Num("9" * 40)
    assert parse("1234567890." + "0" * 30) == Num("1234567890." + "0" * 30)
    assert parse("1e300") == Num("1e300")
    assert parse("1e-300") == Num("1e-300")
    assert parse("1e+0000300") == Num("1e+0000300")


@pytest.mark.parametrize("text", ["9" * 41, "0." + "1" * 40, "1e400", "1e-301", "1e" + "9" * 5000])
def test_number_limits_are_enforced(text: str) -> None:
    err = error(text)
    assert err.pos == 0
    assert "digits" in err.message or "out of range" in err.message


@pytest.mark.parametrize("func", sorted(FUNCTIONS - {"atan2"}))
def test_every_function(func: str) -> None:
    assert parse(f"{func}(x + 1)") == Call(func, (BinOp("+", x, Num("1")),))


def test_atan2_takes_two_arguments() -> None:
    assert parse("atan2(y, x)") == Call("atan2", (y, x))
    assert error("atan2(x)").message == "atan2() takes exactly 2 arguments (1 given)"
    assert error("atan2(x, y, z)").message == "atan2() takes exactly 2 arguments (3 given)"
    assert error("sin(x, y)").message == "sin() takes exactly 1 argument (2 given)"
    assert error("cos()").message == "cos() takes exactly 1 argument (0 given)"
    assert error("  cos()").pos == 2


def test_function_set() -> None:
    assert FUNCTIONS == frozenset(
        "sin cos tan asin acos atan atan2 sinh cosh tanh exp log sqrt abs sign".split()
    )


def test_rates() -> None:
    assert parse("dot(x)") == Rate("x", 1)
    assert parse("ddot( theta )") == Rate("theta", 2)
    assert parse("F_x + dot(x)*c") == BinOp("+", Name("F_x"), BinOp("*", Rate("x", 1), c))


@pytest.mark.parametrize(
    ("text", "pos"),
    [("dot(2)", 4), ("dot()", 4), ("dot(dot(x))", 4), ("ddot((x))", 5), ("dot(sin)", 4),
     ("dot(x + y)", 6), ("dot(x", 5), ("dot(x, y)", 5)],
)
def test_rate_takes_a_bare_name(text: str, pos: int) -> None:
    err = error(text)
    assert err.pos == pos
    func = text[: text.index("(")]
    assert f"{func}() takes a name, as in {func}(x)" in err.message


def test_positions() -> None:
    tree = parse("a + b*c")
    assert tree.pos == 2 and tree.left.pos == 0
    assert tree.right.pos == 5 and tree.right.left.pos == 4 and tree.right.right.pos == 6
    call = parse("  sin(-dot(q))")
    assert call.pos == 2 and call.args[0].pos == 6 and call.args[0].operand.pos == 7
    assert parse("x**2").pos == 1
    assert parse("(  1.5)").pos == 3


def test_nodes_compare_by_structure_and_hash() -> None:
    assert parse("x+1") == parse("  x + 1 ")
    assert hash(parse("x+1")) == hash(BinOp("+", x, Num("1")))
    assert len({parse("sin(x)"), parse(" sin( x )"), parse("cos(x)")}) == 2
    assert parse("1.0") != parse("1")  # the text is kept, not the value
    with pytest.raises(AttributeError):
        parse("x").id = "y"  # type: ignore[misc]


def test_nodes_check_their_invariants() -> None:
    with pytest.raises(ValueError):
        BinOp("%", x, y)
    with pytest.raises(ValueError):
        Rate("x", 3)


def test_names_and_walk() -> None:
    tree = parse("F_x + dot(x)*c + sin(theta)*theta")
    assert names(tree) == {"F_x", "c", "theta"}
    assert names(parse("2*dot(q)")) == frozenset()
    kinds = [type(n).__name__ for n in walk(parse("-a + sin(b)*2"))]
    assert kinds == ["BinOp", "Neg", "Name", "BinOp", "Call", "Name", "Num"]


def test_render_follows_long_chains_with_a_loop() -> None:
    # Built by hand, so taller than parse allows; render and walk must still cope.
    tree: grammar.Node = x
    for i in range(5000):
        tree = BinOp("+" if i % 2 else "-", tree, Name(f"k{i % 10}"))
    text = render(tree)
    assert text.startswith("x - k0 + k1 - k2")
    assert names(tree) == {f"k{i}" for i in range(10)} | {"x"}
    assert sum(1 for _ in walk(tree)) == 10_001


def test_render_examples() -> None:
    assert render(BinOp("**", Neg(x), y)) == "(-x)**y"
    assert render(BinOp("**", BinOp("**", x, y), z)) == "(x**y)**z"
    assert render(BinOp("-", a, BinOp("-", b, c))) == "a - (b - c)"
    assert render(BinOp("/", a, BinOp("*", b, c))) == "a/(b*c)"
    assert render(Neg(BinOp("*", a, b))) == "-(a*b)"
    assert render(Neg(Num("2"))) == "-2"
    assert render(Call("atan2", (y, Neg(x)))) == "atan2(y, -x)"
    assert render(Rate("q", 2)) == "ddot(q)"
    with pytest.raises(TypeError):
        render("x")  # type: ignore[arg-type]


# --- Errors ------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "pos", "message"),
    [
        ("", 0, "empty expression"),
        (" \t\n ", 0, "empty expression"),
        ("x +", 3, "expected an expression, found end of text"),
        ("x * * y", 4, "expected an expression, found '*'"),
        ("()", 1, "expected an expression, found ')'"),
        ("(x + 1", 6, "expected ')' to close the '(' at column 1, found end of text"),
        ("y*(x + 1", 8, "expected ')' to close the '(' at column 3, found end of text"),
        ("x +\n (y", 7, "expected ')' to close the '(' at line 2, column 2, found end of text"),
        ("sin(x", 5, "expected ',' or ')' to close the '(' of sin() at column 4, found end of text"),
        ("x)", 1, "unmatched ')'"),
        ("x^2", 1, "'^' is not an operator here; write ** for a power"),
        ("a.b", 1, "attribute access ('.') is not allowed in an expression"),
        ("x.__class__", 1, "attribute access ('.') is not allowed in an expression"),
        ("2..real", 2, "attribute access ('.') is not allowed in an expression"),
        ("a[0]", 1, "'[' is not allowed in an expression (no indexing or lists)"),
        ("'x'", 0, "strings are not allowed in an expression"),
        ('f"{x}"', 1, "strings are not allowed in an expression"),
        ("x = 1", 2, "comparisons and assignments are not allowed in an expression"),
        ("x == 1", 2, "comparisons and assignments are not allowed in an expression"),
        ("x != 1", 2, "comparisons and assignments are not allowed in an expression"),
        ("x<1", 1, "comparisons and assignments are not allowed in an expression"),
        ("x >= 1", 2, "comparisons and assignments are not allowed in an expression"),
        ("(x := 1)", 3, "comparisons and assignments are not allowed in an expression"),
        ("x // 2", 2, "'//' (floor division) is not allowed in an expression; write / for division"),
        ("2x", 1, "expected an operator between '2' and 'x' (write '*' for a product)"),
        ("2 x", 2, "expected an operator between '2' and 'x' (write '*' for a product)"),
        ("x y", 2, "expected an operator between 'x' and 'y' (write '*' for a product)"),
        ("(x) 2", 4, "expected an operator between ')' and '2' (write '*' for a product)"),
        ("sin(x y)", 6, "expected an operator between 'x' and 'y' (write '*' for a product)"),
        ("(x)(y)", 3, "expected an operator between ')' and '(' "
                      "(only a function name can be called; write '*' for a product)"),
        ("2(y)", 1, "expected an operator between '2' and '(' "
                    "(only a function name can be called; write '*' for a product)"),
        ("atan2(x, y,)", 10, "expected an argument after ',' (no trailing comma)"),
        ("x, y", 1, "',' is only allowed between the arguments of a function"),
        ("(x, y)", 2, "',' is only allowed between the arguments of a function"),
        ("sin(,x)", 4, "expected an expression, found ','"),
        ("son(x)", 0, "unknown function 'son' (did you mean 'sin'?)"),
        ("  sqr(x)", 2, "unknown function 'sqr' (did you mean 'sqrt'?)"),
        ("sin", 0, "'sin' is a function; call it as sin(...)"),
        ("1 + dot", 4, "'dot' is a function; call it as dot(...)"),
        ("2e", 1, "malformed number '2e': an exponent needs digits, as in 1.5e-3 "
                  "(and a product needs '*')"),
        ("2e+x", 1, "malformed number '2e': an exponent needs digits, as in 1.5e-3 "
                    "(and a product needs '*')"),
        ("lambda: 0", 0, "'lambda' is a Python keyword, not allowed in an expression"),
        ("1 if x else 2", 2, "'if' is a Python keyword, not allowed in an expression"),
        ("not x", 0, "'not' is a Python keyword, not allowed in an expression"),
        ("x and y", 2, "'and' is a Python keyword, not allowed in an expression"),
        ("x or y", 2, "'or' is a Python keyword, not allowed in an expression"),
        ("x in y", 2, "'in' is a Python keyword, not allowed in an expression"),
        ("x is y", 2, "'is' is a Python keyword, not allowed in an expression"),
        ("import os", 0, "'import' is a Python keyword, not allowed in an expression"),
        ("None", 0, "'None' is a Python keyword, not allowed in an expression"),
        ("__x", 0, "name '__x' contains '__': dunder names are not allowed"),
        ("a__b", 0, "name 'a__b' contains '__': dunder names are not allowed"),
        ("x @ y", 2, "'@' is not allowed in an expression (no matrix products or decorators)"),
        ("x % 2", 2, "'%' is not allowed in an expression (no remainder or formatting)"),
        ("{x}", 0, "'{' is not allowed in an expression (no sets, dicts or formatting)"),
        ("x}", 1, "'}' is not allowed in an expression (no sets, dicts or formatting)"),
        ("x: 1", 1, "':' is not allowed in an expression (no slices, lambdas or annotations)"),
        ("x; y", 1, "';' is not allowed in an expression (write a single expression)"),
        ("x!", 1, "'!' is not allowed in an expression"),
        ("x & y", 2, "'&' is not allowed in an expression (no bitwise or logical operators)"),
        ("x | y", 2, "'|' is not allowed in an expression (no bitwise or logical operators)"),
        ("~x", 0, "'~' is not allowed in an expression (no bitwise or logical operators)"),
        ("x << 1", 2, "'<<' is not allowed in an expression (no bit shifts)"),
        ("x \\\n+ y", 2, "a backslash is not allowed in an expression"),
        ("x # note", 2, "'#' is not allowed in an expression (no comments)"),
        ("x ? y", 2, "'?' is not allowed in an expression"),
        ("$x", 0, "'$' is not allowed in an expression"),
        ("x\x00", 1, "control character U+0000 is not allowed in an expression"),
        ("x\fy", 1, "control character U+000C is not allowed in an expression"),
    ],
)
def test_error_messages_and_positions(text: str, pos: int, message: str) -> None:
    err = error(text)
    assert (err.pos, err.message) == (pos, message)
    assert str(err) == message


@pytest.mark.parametrize(
    ("text", "pos", "fragment"),
    [
        ("2*θ", 2, "'θ' (U+03B8 GREEK SMALL LETTER THETA) is not allowed in an expression; "
                   "write 'theta'"),
        ("Ω", 0, "U+03A9 GREEK CAPITAL LETTER OMEGA) is not allowed in an expression; "
                 "write 'Omega'"),
        ("a\u2212b", 1, "U+2212 MINUS SIGN) is not allowed in an expression; write '-'"),
        ("x\u00b2", 1, "write '**2'"),
        ("x\u00a0+ y", 1, "U+00A0 NO-BREAK SPACE) is not allowed in an expression"),
        ("\u0661", 0, "U+0661 ARABIC-INDIC DIGIT ONE"),
        ("x\u0661", 1, "U+0661"),
        ("é", 0, "non-ASCII character 'é'"),
    ],
)
def test_non_ascii_is_named(text: str, pos: int, fragment: str) -> None:
    err = error(text)
    assert err.pos == pos
    assert err.message.startswith("non-ASCII character")
    assert fragment in err.message


def test_unknown_function_without_a_close_match_lists_the_functions() -> None:
    err = error("system(x)")
    assert err.pos == 0
    assert err.message.startswith("unknown function 'system'; the functions are abs, acos,")


def test_messages_shorten_long_names() -> None:
    err = error("q" * 5000 + "(x)")
    assert err.pos == 0 and len(err.message) < 300


def test_parse_error_pickles() -> None:
    err = pickle.loads(pickle.dumps(error("x +")))
    assert (err.message, err.pos) == ("expected an expression, found end of text", 3)


def test_parse_takes_only_text() -> None:
    with pytest.raises(TypeError):
        parse(2)  # type: ignore[arg-type]


# --- Hostile input -----------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "pos"),
    [
        ("__import__('os').system('x')", 0),
        ("().__class__.__bases__", 2),
        ("lambda: 0", 0),
        ("[x for x in y]", 0),
        ('f"{x}"', 1),
        ("1 if x else 2", 2),
        ("x; y", 1),
        ("open('/etc/passwd').read()", 5),
        ("eval('1')", 5),
        ("exec('x')", 5),
        ("getattr(x, 'y')", 11),
        ("sin.__globals__", 3),
        ("x\n__import__", 2),
    ],
)
def test_hostile_inputs_are_rejected(text: str, pos: int) -> None:
    assert error(text).pos == pos


def test_huge_powers_parse_since_nothing_is_evaluated() -> None:
    assert parse("10**10**10**10") == BinOp(
        "**", Num("10"), BinOp("**", Num("10"), BinOp("**", Num("10"), Num("10"))))
    assert render(parse("2**2**2**99")) == "2**2**2**99"


def test_length_limit() -> None:
    assert parse("x" * MAX_LENGTH) == Name("x" * MAX_LENGTH)
    err = error("x" * (MAX_LENGTH + 1))
    assert err.pos == MAX_LENGTH and "too long" in err.message
    # 10_001 characters: the length check comes first, before any nesting.
    assert "too long" in error("(" * 5000 + "x" + ")" * 5000).message


NESTED_TOO_DEEPLY = f"expression is nested too deeply (more than {MAX_DEPTH} levels)"


@pytest.mark.parametrize(
    ("opening", "closing", "levels_per_repeat", "pos"),
    [
        ("(", ")", 1, 100),
        ("-", "", 1, 100),
        ("+", "", 1, 100),
        ("sin(", ")", 1, 403),
        ("x**", "", 1, 301),
        ("2**-", "", 2, 201),
        ("(-", ")", 2, 100),
    ],
)
def test_depth_limit(opening: str, closing: str, levels_per_repeat: int, pos: int) -> None:
    def nested(repeats: int) -> str:
        return opening * repeats + "x" + closing * repeats

    allowed = MAX_DEPTH // levels_per_repeat
    assert isinstance(parse(nested(allowed)), grammar.Node)
    err = error(nested(allowed + 1))
    assert (err.message, err.pos) == (NESTED_TOO_DEEPLY, pos)


TOO_TALL = NESTED_TOO_DEEPLY
# (a+b*(a+b*(...))): each parenthesis is one level of nesting and two of height, a sum and a product.
ALTERNATING = "(a+b*" * (MAX_DEPTH // 2 + 1) + "c" + ")" * (MAX_DEPTH // 2 + 1)


@pytest.mark.parametrize("operator", ["+", "-", "*", "/"])
def test_a_chain_of_any_length_is_one_level(operator: str) -> None:
    # A sum of more than 100 terms, pasted from a CAS, was refused as 'nested too deeply'.
    text = "x" + f" {operator} y" * 2400
    assert len(text) < MAX_LENGTH
    tree = parse(text)
    assert parse(render(tree)) == tree
    assert parse("(" * 90 + text + ")" * 90) == tree


@pytest.mark.parametrize("text", [ALTERNATING, "(" * 60 + "a*" + "b+" * 3000 + "c" + ")" * 60 + "+" + ALTERNATING])
def test_tree_height_counts_every_change_of_operator(text: str) -> None:
    assert MAX_DEPTH // 2 + 1 <= MAX_DEPTH  # within the nesting limit: the height is what refuses it
    err = error(text)
    assert err.message == TOO_TALL and 0 <= err.pos < len(text)


def test_long_chains_compare_hash_and_print_without_recursion() -> None:
    # Parse bounds the height because ==, hash and repr of the nodes recurse, but not along a chain.
    text = "+".join(["x"] * 3000)
    tree = parse(text)
    assert tree == parse(text.replace("+", "+ ")) and tree != parse(text[:-2])
    assert tree != parse(text[:-1] + "y") and tree != parse(text[:-2] + "-x")
    assert hash(tree) == hash(parse(text))
    assert repr(tree).startswith("BinOp(op='+', left=BinOp(") and repr(tree).count("BinOp(") == 2999
    assert render(tree) == " + ".join(["x"] * 3000)
    deepest = parse("(" + "a+b*(" * (MAX_DEPTH // 2 - 1) + "c" + ")" * (MAX_DEPTH // 2 - 1) + ")" + "*x" * 2000)
    assert deepest == parse(render(deepest)) and hash(deepest) == hash(parse(render(deepest)))


def test_a_long_chain_builds_the_expression_written() -> None:
    import sympy as sp

    from gacli.read.expr.build import BuildError, Scope, build

    x, y = sp.symbols("x y")
    scope = Scope(values={"x": x, "y": y})
    assert build(parse("+".join(["x"] * 2000) + "-y" * 1000), scope) == 2000 * x - 1000 * y
    assert build(parse("x" + "*y" * 1500 + "/x" * 500), scope) == x ** -499 * y ** 1500
    with pytest.raises(BuildError) as info:
        build(parse("x" + "*y" * 1000 + "/(x-x)" + "*y" * 10), scope)
    assert info.value.message == "division by zero" and info.value.pos == 1 + 2 * 1000


def test_depth_counts_every_kind_of_nesting() -> None:
    # 25 levels each of parentheses, calls, signs and powers: exactly the limit.
    assert MAX_DEPTH == 100
    assert parse("(" * 25 + "sin(" * 25 + "-" * 25 + "x**" * 25 + "x" + ")" * 50)
    err = error("(" * 25 + "sin(" * 25 + "-" * 25 + "x**" * 25 + "(x)" + ")" * 50)
    assert err.message == NESTED_TOO_DEEPLY


@pytest.mark.parametrize(
    "text",
    ["(" * 4999 + "x" + ")" * 4999, "-" * 5000 + "x", "sin(" * 2000, "x**" * 3000 + "x",
     "(" * MAX_LENGTH],
)
def test_deep_input_fails_cleanly_without_recursion_error(text: str) -> None:
    err = error(text)
    assert err.message == NESTED_TOO_DEEPLY
    assert err.pos < 5 * MAX_DEPTH


def test_a_full_length_expression_parses() -> None:
    # Long names and calls: a sum of 90 terms at the length limit.
    terms = [f"sin(theta_{i:02}_{'q' * 80})*dot(psi)" for i in range(90)]
    text = " + ".join(terms)
    assert MAX_LENGTH - 500 < len(text) <= MAX_LENGTH
    tree = parse(text)
    assert parse(render(tree)) == tree
    assert len(names(tree)) == 90


def test_module_never_evaluates() -> None:
    # The grammar's safety rests on its imports: no sympy, no ast, no eval.
    source = pathlib.Path(grammar.__file__).read_text()
    module = ast.parse(source)
    imported = {alias.name for n in ast.walk(module) if isinstance(n, ast.Import) for alias in n.names}
    imported |= {n.module for n in ast.walk(module) if isinstance(n, ast.ImportFrom)}
    assert imported <= {"__future__", "collections.abc", "dataclasses", "difflib", "keyword",
                        "re", "typing", "unicodedata"}
    called = {n.func.id for n in ast.walk(module)
              if isinstance(n, ast.Call) and isinstance(n.func, ast.Name)}
    assert not called & {"eval", "exec", "compile", "__import__", "getattr", "sympify"}


@pytest.mark.parametrize("module", [tokens, parser])
def test_the_tokenizer_and_parser_never_evaluate(module) -> None:
    # The same guarantee for the modules that read the text; they may import only each other and grammar.
    tree = ast.parse(pathlib.Path(module.__file__).read_text())
    imported = {alias.name for n in ast.walk(tree) if isinstance(n, ast.Import) for alias in n.names}
    imported |= {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    assert imported <= {"__future__", "difflib", "keyword", "re", "typing", "unicodedata",
                        "gacli.read.expr.grammar", "gacli.read.expr.tokens"}
    called = {n.func.id for n in ast.walk(tree) if isinstance(n, ast.Call) and isinstance(n.func, ast.Name)}
    assert not called & {"eval", "exec", "compile", "__import__", "getattr", "sympify"}


# --- Properties --------------------------------------------------------------

DIGITS = "0123456789"
NAMES = st.sampled_from(["x", "y", "theta", "F_x", "m1", "_q", "Omega", "e", "E", "pi"])


@st.composite
def number_texts(draw: st.DrawFn) -> str:
    whole = draw(st.text(DIGITS, max_size=6))
    fraction = draw(st.none() | st.text(DIGITS, max_size=6))
    mantissa = whole if fraction is None else f"{whole}.{fraction}"
    if not any(ch in DIGITS for ch in mantissa):
        mantissa = "0" + mantissa
    exponent = draw(st.none() | st.tuples(st.sampled_from("eE"), st.sampled_from(["", "+", "-"]),
                                          st.integers(0, 300)))
    return mantissa if exponent is None else mantissa + "".join(map(str, exponent))


LEAVES = st.one_of(
    st.builds(Num, number_texts()),
    st.builds(Name, NAMES),
    st.builds(Rate, NAMES, st.sampled_from([1, 2])),
)


def nested(leaves, max_depth: int, branches) -> st.SearchStrategy[grammar.Node]:
    """Trees at most max_depth nodes tall: a leaf, or a branch over smaller trees."""
    strategy = leaves
    for _ in range(max_depth):
        strategy = st.one_of(leaves, *(branch(strategy) for branch in branches))
    return strategy


def trees(max_depth: int) -> st.SearchStrategy[grammar.Node]:
    """Random trees of every node type, at most max_depth nodes tall."""
    return nested(LEAVES, max_depth, [
        lambda sub: st.builds(Neg, sub),
        lambda sub: st.builds(BinOp, st.sampled_from(["+", "-", "*", "/", "**"]), sub, sub),
        lambda sub: st.builds(Call, st.sampled_from(sorted(FUNCTIONS - {"atan2"})), st.tuples(sub)),
        lambda sub: st.builds(Call, st.just("atan2"), st.tuples(sub, sub)),
    ])


@settings(max_examples=400)
@given(trees(6))
def test_render_round_trips(tree: grammar.Node) -> None:
    text = render(tree)
    assert parse(text) == tree
    assert render(parse(text)) == text


@given(trees(4))
def test_names_and_walk_agree(tree: grammar.Node) -> None:
    nodes = list(walk(tree))
    assert nodes[0] is tree
    assert names(tree) == {n.id for n in nodes if isinstance(n, Name)}
    assert names(tree) == names(parse(render(tree)))


def check_parse_is_total(text: str) -> None:
    try:
        tree = parse(text)
    except ParseError as err:
        assert 0 <= err.pos <= len(text)
        assert err.message and str(err) == err.message
    else:
        assert parse(render(tree)) == tree


@settings(max_examples=500)
@given(st.text())
def test_arbitrary_text_parses_or_raises_parse_error(text: str) -> None:
    check_parse_is_total(text)


@settings(max_examples=1000)
@given(st.text(alphabet="xy12.eE+-*/()^,_ \tsinatdo", max_size=40))
def test_expression_like_text_parses_or_raises_parse_error(text: str) -> None:
    check_parse_is_total(text)


# --- Building SymPy from trees ---------------------------------------------

SMALL_LEAVES = st.one_of(st.builds(Num, st.sampled_from(["0", "1", "2", "0.5", "3"])),
                         st.builds(Name, st.sampled_from(["x", "y", "z"])))


def small_trees(max_depth: int) -> st.SearchStrategy[grammar.Node]:
    return nested(SMALL_LEAVES, max_depth, [
        lambda sub: st.builds(Neg, sub),
        lambda sub: st.builds(BinOp, st.sampled_from(["+", "-", "+", "-", "*"]), sub, sub),
        lambda sub: st.builds(Call, st.sampled_from(["sin", "cos", "sqrt"]), st.tuples(sub)),
    ])


def pairwise(node: grammar.Node, symbols: dict):
    """The SymPy expression built one binary operation at a time (the reference)."""
    import sympy as sp

    if isinstance(node, Num):
        return sp.Rational(node.text)
    if isinstance(node, Name):
        return symbols[node.id]
    if isinstance(node, Neg):
        return -pairwise(node.operand, symbols)
    if isinstance(node, Call):
        return getattr(sp, node.func)(*(pairwise(a, symbols) for a in node.args))
    left, right = pairwise(node.left, symbols), pairwise(node.right, symbols)
    if node.op == "+":
        return left + right
    return left - right if node.op == "-" else left * right


@settings(max_examples=300, deadline=None)
@given(small_trees(6))
def test_sums_built_at_once_are_the_pairwise_expressions(tree: grammar.Node) -> None:
    """build adds a chain a ± b ± ... in one Add: exactly what adding pair by pair gives."""
    import sympy as sp

    from gacli.read.expr.build import BuildError, Scope, build

    symbols = {n: sp.Symbol(n, real=True) for n in "xyz"}
    built, expected = build(tree, Scope(values=symbols)), pairwise(tree, symbols)
    assert built == expected and sp.srepr(built) == sp.srepr(expected)


@pytest.mark.parametrize(("text", "words"), [
    ("0x1F", ["hexadecimal literal", "write 31"]),
    ("2*0b101", ["binary literal", "write 5"]),
    ("0o17 + x", ["octal literal", "write 15"]),
    ("1_000*x", ["'_' between digits", "'1000'"]),
    (".inf", ["YAML's spelling of infinity"]),
    ("-.NaN", ["not-a-number"]),
])
def test_numbers_from_other_languages_are_named(text: str, words: list[str]) -> None:
    # Before: "expected an operator between '0' and 'x1F'", "attribute access ('.')".
    err = error(text)
    assert text.index(text.lstrip("-2*")[0]) <= err.pos <= len(text)
    for word in words:
        assert word in err.message
    assert "attribute access" not in err.message and "expected an operator" not in err.message


def test_t_where_time_is_not_allowed_and_dot_t_are_said_so_not_undeclared() -> None:
    """'mass: 1 + t' said "'t' is not declared"; 'dot(t)' said so and asked "did you mean 't'?"."""
    import sympy as sp

    from gacli.read.expr.build import BuildError, Scope, build

    with pytest.raises(BuildError, match="'t' is not allowed here: this value may not depend on time"):
        build(parse("1 + t"), Scope(values={}))
    with pytest.raises(BuildError, match=r"'dot\(t\)' is not allowed: t is time, not a coordinate"):
        build(parse("x*dot(t)"), Scope(values={"x": sp.Symbol("x"), "t": sp.Symbol("t")}))
