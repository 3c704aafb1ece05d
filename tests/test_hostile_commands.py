"""The hostile corpus through every command and every format, not only ``check``.

Every file in ``tests/hostile/`` is run through ``check``, ``derive`` (text,
``--steps``, every ``--format`` with ``--output``, LaTeX standalone, the
reactions), ``gibbs``, ``verify``, ``linearize`` and ``simulate``, all in one
fresh process (tests/hostile_driver.py) with a 2 s budget. Each must end in
exit 1 with a located error saying what ``check`` says, no traceback, nothing
written, no injected code run, under 20 s; and the whole run stays under
1 GiB.

Every file in ``tests/accepted_hostile/`` (files ``check`` accepts though
they were written to hurt) must give LaTeX that pdflatex compiles without
shell escape and without opening a file outside the TeX tree and the
document's folder, C that gcc and clang compile strictly, and Python that
imports.
"""

from __future__ import annotations

import importlib.util
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from gacli.cli import app
from hostile_driver import commands
from test_hostile import FILES, expected, planted

HERE = Path(__file__).resolve().parent
ACCEPTED = sorted((HERE / "accepted_hostile").glob("*.yaml"))
CASE_SECONDS = 20
PEAK_MIB = 1024


def _corpus_run(work: Path) -> dict:
    paths = [planted(source, work)[0] for source in FILES]
    env = {**os.environ, "PYTHONPATH": str(HERE.parent)}
    done = subprocess.run([sys.executable, str(HERE / "hostile_driver.py"), str(work), *map(str, paths)],
                          capture_output=True, text=True, timeout=1800, env=env, cwd=work)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def corpus(tmp_path_factory) -> dict:
    return _corpus_run(tmp_path_factory.mktemp("corpus"))


def test_the_corpus_ran_in_under_a_gibibyte(corpus):
    assert corpus["peak_mib"] < PEAK_MIB, corpus["peak_mib"]


@pytest.mark.parametrize("source", FILES, ids=lambda p: p.stem)
def test_every_command_refuses_the_file_cleanly(corpus, source):
    records = [r for r in corpus["records"] if r["file"] == source.stem]
    assert sorted(r["command"] for r in records) == sorted(commands())
    expect = expected(source)
    for r in records:
        where = f"{r['command']}: {r['output']}"
        assert r["crashed"] is None, where + r["crashed"]
        assert r["exit"] == 1, where
        assert "Traceback" not in r["output"] and "internal error" not in r["output"], where
        assert re.search(rf"{re.escape(source.stem)}\.yaml:\d+:\d+: error: ", r["output"]), where
        assert expect in r["output"] or "ran out of time" in r["output"], where
        assert r["written"] == [], where
        assert not r["marker"], where
        assert r["seconds"] < CASE_SECONDS, where


# -- files check accepts: what gacli writes from them must build ------------------------------

def _derive(path: Path, out: Path, *options: str) -> None:
    result = CliRunner().invoke(app, ["derive", *options, "--output", str(out), str(path)])
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("source", ACCEPTED, ids=lambda p: p.stem)
def test_accepted_hostile_latex_compiles_and_reads_no_outside_file(source, tmp_path):
    from conftest import require_tool

    pdflatex = require_tool("pdflatex")
    for options in (("--standalone",), ("--standalone", "--steps")):
        _derive(source, tmp_path / "doc.tex", "--format", "latex", *options)
        run = subprocess.run([pdflatex, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape",
                              "-recorder", "doc.tex"], cwd=tmp_path, capture_output=True, text=True, timeout=180)
        assert run.returncode == 0, run.stdout[-3000:]
        texmf = subprocess.run(["kpsewhich", "-var-value=SELFAUTOPARENT"], capture_output=True, text=True)
        allowed = [str(tmp_path), "/usr/share/texlive", "/usr/share/texmf", "/var/lib/texmf", "/etc/texmf",
                   texmf.stdout.strip() or "/nonexistent"]
        for line in (tmp_path / "doc.fls").read_text(encoding="utf-8", errors="replace").splitlines():
            kind, _, name = line.partition(" ")
            if kind in ("INPUT", "OUTPUT"):
                absolute = str((tmp_path / name).resolve())
                assert any(absolute.startswith(a) for a in allowed), line


@pytest.mark.parametrize("source", ACCEPTED, ids=lambda p: p.stem)
@pytest.mark.parametrize("compiler", ["gcc", "clang"])
@pytest.mark.parametrize("flags", [["-std=c99", "-pedantic"], ["-std=gnu11", "-D_GNU_SOURCE"]],
                         ids=["c99", "gnu11"])
def test_accepted_hostile_c_compiles(source, compiler, flags, tmp_path):
    from conftest import require_tool

    _derive(source, tmp_path, "--format", "c", "--reactions")
    (c_file,) = tmp_path.glob("*.c")
    done = subprocess.run([require_tool(compiler), *flags, "-Wall", "-Wextra", "-Werror", "-c", c_file.name,
                           "-o", "out.o"], cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize("source", ACCEPTED, ids=lambda p: p.stem)
def test_accepted_hostile_python_imports(source, tmp_path):
    _derive(source, tmp_path, "--format", "python", "--reactions")
    (module_file,) = tmp_path.glob("*.py")
    spec = importlib.util.spec_from_file_location(module_file.stem, module_file)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    assert callable(module.rhs)


_UNUSED_Y = ("gacli: 1\nname: h\nparameters: {m: {value: 1}}\ncoordinates: [x, y, z]\n"
             "constraints:\n  - dz = x*dy\nbodies:\n  p: {mass: m, position: [x, 0, 0]}\n")


@pytest.mark.parametrize("args", [["derive", "--reactions"], ["derive", "--format", "c", "--reactions"],
                                  ["linearize", "--symbolic"], ["verify", "--samples", "2"],
                                  ["simulate", "--t-end", "0.1"]], ids=" ".join)
def test_a_row_of_m_zero_at_every_state_is_one_located_error_in_every_solving_command(tmp_path, args):
    # A coordinate that moves nothing: these commands solve M u' = F and ended in SymPy's
    # NonInvertibleMatrixError or mpmath's TypeError, as tracebacks; check said why.
    path = tmp_path / "h.yaml"
    path.write_text(_UNUSED_Y, encoding="utf-8")
    out = tmp_path / "out"
    extra = ["--output", f"{out}/"] if "--format" in args else []
    result = CliRunner().invoke(app, [*args, str(path), *extra])
    assert result.exit_code == 1, result.output
    assert f"{path}:4:18: error: mass_matrix: M is singular at every state: its row for dot(y) is zero" in result.output
    assert "Traceback" not in result.output and not out.exists()


@pytest.mark.parametrize("call", ["simulate", "linearize", "stability"])
def test_the_api_s_solving_calls_raise_the_same_located_error(tmp_path, call):
    import gacli
    from gacli.errors import SystemFileError

    path = tmp_path / "h.yaml"
    path.write_text(_UNUSED_Y, encoding="utf-8")
    with pytest.raises(SystemFileError) as raised:
        getattr(gacli, call)(str(path))
    assert "M is singular at every state: its row for dot(y) is zero" in str(raised.value)


_KINKS = {  # a place the equations differentiate → (its lines, the kinked call's line and column)
    "position": ('bodies:\n  b: {mass: m, position: [x, "y + @(x)"]}\n', 6, 35),
    "potential": ("bodies:\n  b: {mass: m, position: [x, y]}\npotential: k*x*@(x)\n", 7, 16),
    "constraint": ("bodies:\n  b: {mass: m, position: [x, y]}\nconstraints:\n  - dy - @(x)*dx\n", 8, 10),
    "rate in a constraint": ("bodies:\n  b: {mass: m, position: [x, y]}\nconstraints:\n  - dot(y) - @(dot(x))\n",
                             8, 14),
    "quasi-coordinate": ("quasi_coordinates:\n  w: dx + @(y)*dy\nindependent: [w, y]\n"
                         "bodies:\n  b: {mass: m, position: [x, y]}\n", 6, 11),
    "frame angle": ("frames:\n  A: {rotations: [[z, \"@(x)\"]]}\n"
                    "bodies:\n  b: {mass: m, frame: A, inertia: [1, 1, 1], position: [x, y]}\n", 6, 24),
    "function value": ("functions:\n  f: {value: \"@(sin(t))\"}\nbodies:\n  b: {mass: m, position: [x, y*f]}\n",
                       6, 15),
}


@pytest.mark.parametrize("args", [["derive"], ["derive", "--format", "python"], ["check"], ["verify"],
                                  ["linearize"], ["steady"], ["integrals"]], ids=" ".join)
@pytest.mark.parametrize("place", _KINKS)
def test_sign_of_what_moves_where_it_is_differentiated_is_one_located_error(tmp_path, args, place):
    """Its derivative is a DiracDelta: tracebacks in linearize, steady, integrals and verify, an
    unlocated error in the code formats, DiracDelta(x) printed in text (reviewers' files)."""
    lines, line, column = _KINKS[place]
    path = tmp_path / "kink.yaml"
    path.write_text("gacli: 1\nname: kink\nparameters: {m: {value: 1}, k: {value: 2}}\ncoordinates: [x, y]\n"
                    + lines.replace("@", "sign"), encoding="utf-8")
    result = CliRunner().invoke(app, [*args, str(path)])
    assert result.exit_code == 1, result.output
    assert f"{path}:{line}:{column}: error: " in result.output
    assert "sign() of something that moves" in result.output
    assert "Traceback" not in result.output and "DiracDelta(" not in result.output


@pytest.mark.parametrize("place", ["position", "frame angle", "function value"])
def test_abs_of_what_moves_in_a_position_is_refused_and_elsewhere_taken(tmp_path, place):
    lines, line, column = _KINKS[place]
    path = tmp_path / "kink.yaml"
    path.write_text("gacli: 1\nname: kink\nparameters: {m: {value: 1}, k: {value: 2}}\ncoordinates: [x, y]\n"
                    + lines.replace("@", "abs"), encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 1 and f"{path}:{line}:{column}: error: " in result.output, result.output
    assert "abs() of something that moves" in result.output


def test_abs_in_a_potential_and_sign_in_a_force_are_taken(tmp_path):
    """Differentiated once (a potential) or never (work), abs and sign give no impulse: V = k|x| is
    a V-shaped well whose force -k sign(x) the equations hold; dry friction stays."""
    path = tmp_path / "well.yaml"
    path.write_text("gacli: 1\nname: well\nparameters: {m: {value: 1}, k: {value: 2}, mu: {value: 1}}\n"
                    "coordinates: [x]\nbodies:\n  b: {mass: m, position: [x, 0]}\npotential: k*abs(x)\n"
                    "work: -mu*sign(dot(x))*dx\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["derive", "--format", "python", str(path), "--output", "-"])
    assert result.exit_code == 0, result.output
    namespace: dict = {}
    exec(result.output, namespace)  # noqa: S102 - our own generated code
    p = [namespace["DEFAULTS"][name] for name in namespace["PARAMETERS"]]
    for x, v in [(0.7, 0.3), (-0.4, 0.9), (0.2, -1.1), (-1.5, -0.2)]:
        acceleration = namespace["rhs"](0.0, [x, v], p)[1]
        assert acceleration == pytest.approx((-2 * (1 if x > 0 else -1) - (1 if v > 0 else -1)) / 1)


@pytest.mark.parametrize("args", [["check"], ["derive"], ["verify"], ["linearize"]], ids=" ".join)
@pytest.mark.parametrize("lines, line, column", [
    # A finite relation is differentiated twice, as a position is (it took abs() as a form's once).
    ("constraints:\n  - y - abs(x)\nbodies:\n  b: {mass: m, position: [x, y]}\n", 6, 9),
    # SymPy builds sqrt(x**2) as Abs(x) for a real x: refused from the built expression.
    ('bodies:\n  b: {mass: m, position: ["sqrt(x**2)", y]}\n', 6, 28),
], ids=["holonomic", "sqrt_of_square"])
def test_abs_that_the_parse_tree_does_not_show_as_twice_differentiated_is_refused(tmp_path, args, lines, line, column):
    path = tmp_path / "kink.yaml"
    path.write_text("gacli: 1\nname: kink\nparameters: {m: {value: 1}, k: {value: 2}}\ncoordinates: [x, y]\n"
                    + lines, encoding="utf-8")
    result = CliRunner().invoke(app, [*args, str(path)])
    assert result.exit_code == 1, result.output
    assert f"{path}:{line}:{column}: error: " in result.output and "abs() of something that moves" in result.output
    assert "Traceback" not in result.output and "DiracDelta(" not in result.output
