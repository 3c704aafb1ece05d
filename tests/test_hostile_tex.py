"""Hostile TeX and system names, through every command; tricky-but-valid files through pdflatex.

tests/test_hostile.py runs ``gacli check`` on every ``tests/hostile/tex_*.yaml``
and ``name_*.yaml``. Here: each of them is accepted once its one hostile
value is replaced (so they are refused for that value, not for something
else), every command refuses them without writing anything, the LaTeX
printer maps names the document cannot typeset, long free text is broken
into lines, and the standalone documents of accepted tricky files compile
with ``pdflatex -no-shell-escape -halt-on-error``.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest
import sympy as sp
from typer.testing import CliRunner

from conftest import require_tool
from gacli.cli import app
from gacli.emit.latex import emit_latex
from gacli.emit.latex_printer import GacliLatexPrinter
from gacli.mechanics.equations import derive
from gacli.loader.loading import loads

HOSTILE = Path(__file__).resolve().parent / "hostile"
TEX_FILES = sorted(HOSTILE.glob("tex_*.yaml"))
NAME_FILES = sorted(HOSTILE.glob("name_*.yaml"))
_LATEX_VALUE = re.compile(r"""latex: (?:'(?:[^']|'')*'|"(?:[^"\\]|\\.)*")""")


def defused(path: Path, tmp_path: Path) -> Path:
    """The hostile file with its hostile value replaced by a harmless one."""
    text = path.read_text(encoding="utf-8")
    if path.name.startswith("tex_"):
        text, count = _LATEX_VALUE.subn("latex: 'z_{1}'", text)
    else:
        text, count = re.subn(r"(?m)^name: .*$", "name: target", text)
    assert count == 1, f"{path.name}: expected one hostile value"
    target = tmp_path / path.name
    target.write_text(text, encoding="utf-8")
    return target


def test_there_are_hostile_tex_and_name_files():
    assert len(TEX_FILES) >= 20 and len(NAME_FILES) >= 8


@pytest.mark.parametrize("source", TEX_FILES + NAME_FILES, ids=lambda p: p.stem)
def test_hostile_file_is_refused_only_for_its_hostile_value(source, tmp_path):
    result = CliRunner().invoke(app, ["check", "--timeout", "5", str(defused(source, tmp_path))])
    assert result.exit_code == 0, result.output


COMMANDS = [
    ["derive"], ["derive", "--steps"], ["gibbs"], ["verify"],
    ["derive", "--format", "latex", "--standalone", "--output", "{out}/s.tex"],
    ["derive", "--format", "latex", "--steps", "--output", "{out}/s.tex"],
    ["derive", "--format", "python", "--output", "{out}/s.py"],
    ["derive", "--format", "c", "--output", "{out}"],
]


@pytest.mark.parametrize("stem", ["tex_input_file", "tex_def_loop", "name_too_long", "name_math_header"])
@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: "-".join(c[:3]).replace("--", ""))
def test_every_command_refuses_and_writes_nothing(stem, command, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    path = tmp_path / f"{stem}.yaml"
    path.write_text((HOSTILE / f"{stem}.yaml").read_text(encoding="utf-8"), encoding="utf-8")
    result = CliRunner().invoke(app, [part.format(out=out) for part in command] + [str(path)])
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output and "internal error" not in result.output, result.output
    assert re.search(rf"^{re.escape(str(path))}:\d+:\d+: error: ", result.output, re.MULTILINE), result.output
    assert list(out.iterdir()) == []


def test_errors_point_into_the_override(tmp_path):
    path = tmp_path / "at.yaml"
    path.write_text((HOSTILE / "tex_input_file.yaml").read_text(encoding="utf-8"), encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    line = "  m: {description: mass, value: 1, latex: '\\input{/etc/passwd}'}"
    assert f"{path}:6:{line.index('input')}: error: parameters.m.latex: bad LaTeX override" in result.output


# -- names the document cannot typeset --------------------------------------------

@pytest.mark.parametrize(("name", "tex"), [
    ("beth", r"\mathrm{beth}"), ("gimel", r"\mathrm{gimel}"), ("daleth", r"\mathrm{daleth}"),
    ("mho", r"\mathrm{mho}"), ("eth", r"\mathrm{eth}"), ("hslash", r"\mathrm{hslash}"),
    ("varkappa", r"\mathrm{varkappa}"), ("xscr", r"\mathrm{xscr}"), ("xfrak", r"\mathrm{xfrak}"),
    ("x_beth", r"\mathrm{x\_beth}"), ("_K", r"\mathrm{\_K}"), ("__x", r"\mathrm{\_\_x}"), ("y_", r"\mathrm{y\_}"),
    ("theta", r"\theta"), ("aleph", r"\aleph"), ("q_1", "q_{1}"), ("xhat", r"\hat{x}"),
])
def test_names_print_as_something_the_document_provides(name, tex):
    printer = GacliLatexPrinter()
    assert printer.doprint(sp.Symbol(name)) == tex
    assert printer.doprint(sp.Symbol(f"dot({name})")).startswith(r"\dot{")


# -- the tricky-but-valid files ------------------------------------------------------

TRICKY = r"""gacli: 1
name: tricky_names
title: TITLE
source: SOURCE
parameters:
  beth: {value: 1}
  gimel: {value: 1}
  mho: {value: 1}
  _K: {value: 1}
  xscr: {value: 2}
  varkappa: {value: 1}
  I_: {value: 1, latex: '\mathcal{I}_{\mathrm{rear}}^{\prime}'}
  c: {latex: "\\operatorname{Re} c'^2"}
inputs:
  F: {latex: '\hat{\mathbf{F}}_x'}
  T:
coordinates:
  x: {latex: '\boldsymbol{\xi}'}
  y_:
quasi_coordinates:
  w: {latex: '{{\tilde{\omega}_{\infty}}}'}
bodies:
  disc:
    mass: beth + gimel*mho + _K*xscr + varkappa
    position: [x, y_]
    inertia: I_
    rotation: dw
loads:
  - force: [F, c]
    at: disc
  - torque: T
    body: disc
"""
# pdflatex reads a line into a buffer of 200,000 characters: a title longer than that on one line fails.
LONG_TITLE = "word " * 50_000 + "x" * 5_000 + " {%$#&_^~\\} " * 100


def tricky(title: str = "Tricky {names} & 100% $", source: str = r"\input{/etc/passwd}") -> str:
    quote = lambda s: "'" + s.replace("'", "''") + "'"  # noqa: E731
    return TRICKY.replace("TITLE", quote(title)).replace("SOURCE", quote(source))


def test_long_free_text_is_broken_into_lines():
    derivation = derive(loads(tricky(LONG_TITLE, LONG_TITLE)))
    for options in ({}, {"standalone": True}):
        (text,) = emit_latex(derivation, **options).values()
        assert max(len(line) for line in text.splitlines()) < 1000
        header = text.split("% Requires")[0]
        assert all(line.startswith("%") for line in header.splitlines())
        assert header.count("word") == 2 * 50_000
    body = text.split(r"\begin{document}")[1]
    assert body.count("word") == 2 * 50_000 and "x" * 5_000 in body.replace("%\n", "")


def _compile(text: str, tmp_path: Path) -> None:
    pdflatex = require_tool("pdflatex")  # a skip here, a failure in CI
    (tmp_path / "doc.tex").write_text(text, encoding="utf-8")
    run = subprocess.run([pdflatex, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape", "doc.tex"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-3000:]


@pytest.mark.parametrize("steps", [False, True], ids=["results", "steps"])
def test_tricky_names_compile(steps, tmp_path):
    (text,) = emit_latex(derive(loads(tricky())), standalone=True, steps=steps).values()
    assert r"\mathrm{beth}" in text and r"\operatorname{Re} c'^2" in text
    _compile(text, tmp_path)


def test_a_title_longer_than_the_input_buffer_compiles(tmp_path):
    (text,) = emit_latex(derive(loads(tricky(LONG_TITLE, LONG_TITLE))), standalone=True).values()
    _compile(text, tmp_path)


def test_every_allowed_command_exists_in_the_generated_preamble(tmp_path):
    """The grammar's allowlist is only safe to promise if article + amsmath define all of it."""
    from gacli.read.texsafe import ACCENTS, SYMBOLS, check_math

    names = [rf"\{name}" for name in sorted(SYMBOLS)] + [rf"\{name}{{x}}" for name in sorted(ACCENTS)]
    assert all(check_math(tex) is None for tex in names)
    preamble = emit_latex(derive(loads(tricky())), standalone=True)["tricky_names.tex"].split(r"\begin{document}")[0]
    body = "\n".join(f"${tex}$" for tex in names + [r"\left\|{x}\right\| \left\langle{x}\right\rangle \aleph \wp"])
    _compile(preamble + "\\begin{document}\n" + body + "\n\\end{document}\n", tmp_path)
