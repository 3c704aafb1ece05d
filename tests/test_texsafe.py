"""The math-TeX grammar of latex: overrides (gacli.read.texsafe), and the names gacli.read.system_name refuses."""

from __future__ import annotations

import pytest

from gacli.read.system_name import name_problem
from gacli.read.texsafe import MAX_LENGTH, PRINTED, check_math, is_printable_name

ACCEPTED = [
    r"\bar{I}", r"\vartheta", r"\dot x", r"x'^2", r"x_a'", r"{}^a_b", r"x^{a}_{b}", r"x_b^a",
    r"\mathrm{d}\theta_{1}", r"\operatorname{atan}", r"\hat{\mathbf{e}}_{x}", r"\mathcal{L}",
    r"\boldsymbol{\omega}", r"a,b c", "x" * MAX_LENGTH, r"\tilde{\Omega}_{\mathrm{rear}}", r"m_\infty",
    "{" * 8 + "x" + "}" * 8, r"\ddddot{q}", "5",
]


@pytest.mark.parametrize("tex", ACCEPTED)
def test_math_names_are_accepted(tex):
    assert check_math(tex) is None


# (text, message part, offset of the culprit)
REJECTED = [
    (r"\input{/etc/passwd}", r"'\input' is not an allowed", 0),
    (r"x\openout1=f", r"'\openout' is not an allowed", 1),
    (r"\def\a{\a}\a", r"'\def' is not an allowed", 0),
    (r"\mathrm{\input x}", r"'\input' is not an allowed", 8),
    (r"\alphax", r"'\alphax' is not an allowed", 0),
    ("{x", "this '{' is never closed", 0),
    ("x}", "this '}' closes nothing", 1),
    ("{x}}", "this '}' closes nothing", 3),
    ("x^a^b", "a second '^'", 3),
    ("x_a_b", "a second '_'", 3),
    ("x^2'", "a prime after '^'", 3),
    ("x_", "'_' needs an argument", 1),
    (r"\dot", r"'\dot' needs an argument", 0),
    (r"\hat}", r"'\hat' needs an argument", 0),
    ("x%", "the character '%' is not allowed", 1),
    ("a$b", "the character '$' is not allowed", 1),
    ("#1", "the character '#' is not allowed", 0),
    ("x&", "the character '&' is not allowed", 1),
    ("x~", "the character '~' is not allowed", 1),
    ("x\ny", "U+000A", 1),
    ("\u03b8", "U+03B8", 0),
    ("x\\", "a backslash followed by nothing", 1),
    ("\\,", "a backslash followed by ','", 0),
    ("\\\\", "a backslash followed by '\\'", 0),
    ("{" * 9 + "x" + "}" * 9, "nested more than 8 deep", 8),
    ("x" * (MAX_LENGTH + 1), f"longer than {MAX_LENGTH}", MAX_LENGTH),
    ("   ", "it is empty", 0),
]


@pytest.mark.parametrize(("tex", "message", "offset"), REJECTED)
def test_everything_else_is_rejected_at_its_place(tex, message, offset):
    problem = check_math(tex)
    assert problem is not None and message in problem.message, problem
    assert problem.offset == offset


def test_a_long_hostile_text_is_reported_for_its_command_not_its_length():
    problem = check_math(r"\immediate\write18{" + "x" * 200 + "}")
    assert problem is not None and r"'\immediate'" in problem.message


def test_the_parser_is_linear_on_long_input():
    assert check_math("x " * 100_000) is not None  # too long, but parsed without recursion trouble


@pytest.mark.parametrize(("tex", "ok"), [
    (r"\theta_{1}", True), (r"\left\|{x}\right\|", True), (r"\left|{x}\right|", True), (r"\aleph", True),
    (r"\beth", False), (r"\gimel", False), (r"\daleth", False), (r"\mho_{2}", False), (r"\eth", False),
    (r"\hslash", False), (r"\varkappa", False), (r"\mathscr{x}", False), (r"\mathfrak{x}", False),
    (r"x_{\beth}", False), ("__x", False), ("_", False),
])
def test_what_the_document_can_typeset(tex, ok):
    assert is_printable_name(tex) is ok
    assert PRINTED.max_length > 10**6


@pytest.mark.parametrize(("name", "message"), [
    ("n" * 65, "at most 64 characters"),
    ("math", "C standard header (math.h)"),
    ("MATH", "C standard header (math.h)"),
    ("stdlib", "C standard header"),
    ("tgmath", "C standard header"),
    ("stdckdint", "C standard header"),
    ("numpy", "Python module"),
    ("sys", "Python module"),
    ("os", "Python module"),
    ("gacli", "Python module"),
    ("class", "Python keyword"),
    ("lambda", "Python keyword"),
    ("namespace", "C or C++ keyword"),
    ("restrict", "C or C++ keyword"),
    ("_Bool", "reserved in C"),
    ("__x", "reserved in C"),
    ("2small", "a letter or '_'"),
    ("a-b", "a letter or '_'"),
    ("", "a letter or '_'"),
])
def test_refused_system_names(name, message):
    problem = name_problem(name)
    assert problem is not None and message in problem


@pytest.mark.parametrize("name", ["pendulum", "n" * 64, "_x", "x_", "Pendulum2", "whipple_bicycle", "matrix"])
def test_accepted_system_names(name):
    assert name_problem(name) is None
