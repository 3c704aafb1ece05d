"""Issue 33, third round: what the second round left (docs/check.md, docs/generated-code.md, docs/verify.md).

Each test names the class of the issue it belongs to.
"""

from __future__ import annotations

import ctypes
import os
import re
import stat
import subprocess
from pathlib import Path
from typing import Optional

import numpy as np
import pytest
import typer
import test_undefined_points as undefined
from conftest import require_tool

from gacli.check import capped
from gacli.errors import Diagnostic, Location

_LOCATED = re.compile(r"^[^:]+:\d+:\d+: (error|warning|note): ")


def _problems(severities: str) -> list[Diagnostic]:
    kinds = {"e": "error", "w": "warning", "n": "note"}
    return [Diagnostic(Location("m.yaml", i + 1, 3), f"problem {i}", severity=kinds[s])
            for i, s in enumerate(severities)]


# -- class 3: a flood of problems, every line located --------------------------------------------

def test_a_capped_report_ends_in_one_located_line_that_counts_the_rest():
    shown = capped(_problems("e" * 250), limit=100)
    assert len(shown) == 101
    assert all(_LOCATED.match(str(d)) for d in shown)
    assert str(shown[-1]) == "m.yaml:101:3: error: 150 more problems not shown (150 errors)"


def test_errors_past_the_limit_keep_the_file_failing():
    shown = capped(_problems("w" * 100 + "n" + "e" + "w" * 3), limit=100)
    assert all(d.severity == "warning" for d in shown[:100])
    assert shown[-1].severity == "error"
    assert shown[-1].message == "5 more problems not shown (1 error, 3 warnings, 1 note)"
    assert shown[-1].location == Location("m.yaml", 101, 3)


def test_a_report_within_the_limit_is_left_as_it_is():
    problems = _problems("ewn")
    assert capped(problems, limit=3) == tuple(problems)


# -- class 5: the C target's undefined points under -ffast-math ----------------------------------

FAST_MATH = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2", "-ffast-math"]


@pytest.fixture(scope="module")
def undefined_point_c(tmp_path_factory):
    from gacli.emit import emit_c
    from gacli.loader.loading import loads
    from gacli.mechanics.equations import derive
    directory = tmp_path_factory.mktemp("fast_math")
    for name, text in emit_c(derive(loads(undefined.SYSTEM, path="undefined_point.yaml"))).items():
        (directory / name).write_text(text, encoding="utf-8")
    return directory / "undefined_point.c"


@pytest.mark.parametrize("compiler", ["gcc", "clang"])
def test_c_rhs_reports_undefined_points_when_built_with_fast_math(compiler, undefined_point_c):
    """-ffast-math lets a compiler fold isfinite(x) to 1; the bit test it replaced must still see NaN and inf."""
    cc = require_tool(compiler)
    library = undefined_point_c.with_name(f"libfast_{compiler}.so")
    result = subprocess.run([cc, *FAST_MATH, "-shared", "-fPIC", str(undefined_point_c), "-o", str(library), "-lm"],
                            capture_output=True, text=True)
    assert result.returncode == 0 and not result.stderr, result.stderr
    rhs = ctypes.CDLL(str(library)).undefined_point_rhs
    doubles = ctypes.POINTER(ctypes.c_double)
    rhs.argtypes = [ctypes.c_double, doubles, doubles, doubles, doubles]
    rhs.restype = ctypes.c_int
    for case in undefined.CASES:
        x, p = (np.ascontiguousarray(v, dtype=float) for v in undefined.point(case))
        xdot = np.zeros(2)
        status = rhs(0.0, *(a.ctypes.data_as(doubles) for a in (x, p)), None, xdot.ctypes.data_as(doubles))
        if case is None:
            assert status == 0
            np.testing.assert_allclose(xdot, undefined.expected_rhs(), rtol=1e-12)
        else:
            assert status == (1 if case.startswith("mass") else -1), case
            assert np.isnan(xdot).all(), case


# -- class 6: the wheelchair's constraint forces in closed form, within the budget ---------------

WHEELCHAIR = Path(__file__).resolve().parents[1] / "benchmarks" / "corpus" / "wheelchair.yaml"


def test_wheelchair_reactions_in_c_finish_and_agree_with_the_fundamental_equation(tmp_path, rng):
    """Seven multipliers with u̇ = M⁻¹F put in: put in over the graph, not by xreplace (which took > 120 s).

    The generated λ is compared with the 30-digit solve of eq. (14.10) over all rates (verify's route).
    """
    from gacli.algebra import symbols as S
    from gacli.emit import emit_c
    from gacli.emit.naming import layout
    from gacli.loader.loading import load
    from gacli.mechanics.equations import derive
    from gacli.reactions import multipliers_numeric

    d = derive(load(WHEELCHAIR))
    for name, text in emit_c(d, reactions=True).items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    library = tmp_path / "libwheelchair.so"
    subprocess.run([require_tool("gcc"), *FAST_MATH[:5], "-shared", "-fPIC", str(tmp_path / "wheelchair.c"),
                    "-o", str(library), "-lm"], check=True)
    c = ctypes.CDLL(str(library))
    doubles = ctypes.POINTER(ctypes.c_double)
    for function in (c.wheelchair_rhs, c.wheelchair_reactions):
        function.argtypes = [ctypes.c_double, doubles, doubles, doubles, doubles]
    lay = layout(d)
    coordinates = [c_.name for c_ in d.system.coordinates]
    m = len(d.system.constraints)
    for _ in range(3):
        x, p, r = (np.ascontiguousarray(rng.uniform(0.3, 1.2, len(v))) for v in (lay.state, lay.parameters, lay.r))
        xdot, lam = np.zeros(len(x)), np.zeros(m)
        pointers = [a.ctypes.data_as(doubles) for a in (x, p, r)]
        assert c.wheelchair_rhs(0.0, *pointers, xdot.ctypes.data_as(doubles)) == 0
        c.wheelchair_reactions(0.0, *pointers, lam.ctypes.data_as(doubles))
        values = dict(zip(lay.state_symbols + lay.parameter_symbols + lay.r_symbols, [*x, *p, *r]))
        values.update({S.rate(n): v for n, v in zip(coordinates, xdot[:len(coordinates)])})
        _, expected = multipliers_numeric(d.system, values)
        np.testing.assert_allclose(lam, expected[:m], rtol=1e-8, atol=1e-8)


# -- class 2: an output name that is a link -------------------------------------------------------

def _outside(tmp_path: Path) -> Path:
    """A file outside the output folder, executable, that a link in it leads to."""
    outside = tmp_path / "elsewhere" / "tool"
    outside.parent.mkdir()
    outside.write_text("secret\n", encoding="utf-8")
    outside.chmod(0o4755)
    return outside


def test_a_link_among_the_outputs_is_replaced_not_written_through(tmp_path):
    from gacli.output import write_files
    outside = _outside(tmp_path)
    folder = tmp_path / "build"
    folder.mkdir()
    (folder / "m.h").symlink_to(outside)
    write_files({"m.c": "c\n", "m.h": "h\n"}, folder)
    assert outside.read_text(encoding="utf-8") == "secret\n"
    assert stat.S_IMODE(outside.stat().st_mode) == 0o4755
    header = folder / "m.h"
    assert not header.is_symlink() and header.read_text(encoding="utf-8") == "h\n"
    assert stat.S_IMODE(header.stat().st_mode) & 0o7111 == 0  # neither the target's x bits nor set-id


def test_a_failed_write_puts_a_link_back_as_it_was(tmp_path, monkeypatch):
    import gacli.output as output
    outside = _outside(tmp_path)
    folder = tmp_path / "build"
    folder.mkdir()
    (folder / "m.c").symlink_to(outside)
    (folder / "m.h").symlink_to(tmp_path / "nowhere")  # dangling
    real_replace = os.replace

    def failing(source, target):
        if str(target).endswith("m.h"):
            raise OSError(28, "No space left on device")
        return real_replace(source, target)

    monkeypatch.setattr(output.os, "replace", failing)
    with pytest.raises(output.OutputError, match="no file was changed"):
        output.write_files({"m.c": "c\n", "m.h": "h\n"}, folder)
    assert os.readlink(folder / "m.c") == str(outside)
    assert os.readlink(folder / "m.h") == str(tmp_path / "nowhere")
    assert sorted(p.name for p in folder.iterdir()) == ["m.c", "m.h"]
    assert outside.read_text(encoding="utf-8") == "secret\n"


def test_a_setuid_output_does_not_pass_its_bit_to_the_new_file(tmp_path):
    from gacli.output import write_files
    target = tmp_path / "m.py"
    target.write_text("old\n", encoding="utf-8")
    target.chmod(0o4750)
    write_files({"m.py": "new\n"}, target)
    assert stat.S_IMODE(target.stat().st_mode) == 0o750


# -- class 4: option strings ---------------------------------------------------------------------

CYLINDER = Path(__file__).resolve().parents[1] / "systems" / "cylinder_in_cylinder.yaml"


def _gacli(*args: str):
    from typer.testing import CliRunner

    from gacli.cli import app
    return CliRunner().invoke(app, [*args])


@pytest.mark.parametrize("command, option, text", [
    (["linearize"], "--at", "theta=1,,phi=0"),
    (["linearize"], "--at", "theta=1,,"),
    (["linearize"], "--states", "theta, ,phi"),
    (["linearize"], "--set", ",M=1"),
    (["simulate", "--t-end", "0.01"], "--init", "theta=1,,"),
    (["simulate", "--t-end", "0.01"], "--show", "theta,,phi"),
])
def test_an_empty_item_in_an_option_string_is_a_usage_error(command, option, text):
    result = _gacli(command[0], str(CYLINDER), *command[1:], option, text)
    assert result.exit_code == 2, result.output
    assert f"{option} '{text}': empty item at column" in result.output
    assert "Traceback" not in result.output


@pytest.mark.parametrize("seconds", ["1e400", "inf", "1e12"])
def test_a_timeout_past_what_a_timer_holds_is_no_limit_not_a_traceback(seconds):
    for command in (["derive"], ["check"]):
        result = _gacli(*command, str(CYLINDER), "--timeout", seconds)
        assert result.exit_code == 0, result.output
        assert "Traceback" not in result.output and result.exception is None


@pytest.mark.parametrize("samples, tol, message", [
    (10**9, 1e-9, "--samples: at most 10,000 states, found 1,000,000,000"),
    (5, float("nan"), "--tol: expected a finite number >= 0, found nan"),
    (5, -1.0, "--tol: expected a finite number >= 0, found -1.0"),
    (5, float("inf"), "--tol: expected a finite number >= 0, found inf"),
])
def test_verify_refuses_its_numbers_before_any_work(samples, tol, message, capsys):
    import typer

    from gacli.cli_options import usage_errors, verify_options
    with pytest.raises(typer.Exit) as caught, usage_errors():
        verify_options(samples, tol)
    assert caught.value.exit_code == 2
    assert message in capsys.readouterr().err


def test_verify_accepts_ordinary_numbers():
    from gacli.cli_options import verify_options
    verify_options(20, 1e-9)
    verify_options(10_000, 0.0)


# -- class 1: links in the checked tree ----------------------------------------------------------

_STDERR_LINE = re.compile(r"^[^\n]+:\d+:\d+: (error|warning|note): ")


@pytest.fixture
def linked_tree(tmp_path, monkeypatch):
    """models/ with a good file, a dangling link, a link out, a loop and a linked directory out."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "outside").mkdir()
    (tmp_path / "outside" / "s.yaml").write_text("gacli: 1\nsecret: TOPSECRET\n", encoding="utf-8")
    models = tmp_path / "models"
    (models / "sub").mkdir(parents=True)
    (models / "good.yaml").write_text(CYLINDER.read_text(encoding="utf-8"), encoding="utf-8")
    (models / "dangling.yaml").symlink_to("nowhere.yaml")
    (models / "out.yaml").symlink_to("../outside/s.yaml")
    (models / "loop_a.yaml").symlink_to("loop_b.yaml")
    (models / "loop_b.yaml").symlink_to("loop_a.yaml")
    (models / "sub" / "linked").symlink_to("../../outside")
    return models


@pytest.mark.parametrize("fmt", ["text", "json", "github"])
def test_a_dangling_link_in_a_folder_is_skipped_and_said_so(linked_tree, fmt):
    result = _gacli("check", "--format", fmt, "models")
    assert result.exit_code == 0, result.output
    assert "TOPSECRET" not in result.output and "No such file" not in result.output
    if fmt == "json":
        import json
        assert {"path": "models/dangling.yaml", "reason": "a symbolic link to a file that does not exist; not followed"} \
            in json.loads(result.stdout)["skipped"]
    else:
        assert "a dangling link: 1" in result.output
    if fmt == "text":
        lines = result.stderr.splitlines()
        assert lines and all(_STDERR_LINE.match(line) for line in lines), lines
        assert "models/dangling.yaml:1:1: note: skipped, a symbolic link to a file that does not exist" \
            in result.stderr


def test_a_dangling_link_named_is_an_error_that_says_what_it_is(linked_tree):
    result = _gacli("check", "models/dangling.yaml")
    assert result.exit_code == 1
    assert "models/dangling.yaml:1:1: error: a symbolic link to a file that does not exist" in result.stderr


# -- class 6: integrals of many coordinates, block by block ----------------------------------------

def test_det_and_adjugate_by_blocks_agree_with_the_whole_matrix():
    import sympy as sp

    from gacli.steady.integrals import _blocks, _det_and_adjugate_times
    a, b, c, d, e, q = sp.symbols("a b c d e q")
    # Blocks {0, 2}, {1}, {3, 4} interleaved: the pattern, not the order, makes them.
    M = sp.Matrix([[a, 0, sp.cos(q), 0, 0],
                   [0, b, 0, 0, 0],
                   [sp.cos(q), 0, c, 0, 0],
                   [0, 0, 0, d, 1],
                   [0, 0, 0, 1, e]])
    F = sp.Matrix(sp.symbols("f0:5"))
    assert _blocks(M) == [[0, 2], [1], [3, 4]]
    det, adj_F = _det_and_adjugate_times(M, F)
    assert sp.expand(det - M.det()) == 0
    assert all(sp.expand(x - y) == 0 for x, y in zip(adj_F, M.adjugate() * F))


def test_integrals_of_a_chain_of_sixty_particles_prove_the_energy():
    """SymPy's adjugate of the 60 x 60 identity took 3,600 cofactors of size 59: it did not end in 40 s."""
    from gacli.loader.loading import loads
    from gacli.mechanics.equations import derive
    from gacli.steady.integrals import integrals

    n = 60
    bodies = "\n".join(f"  b{i}: {{mass: 1, position: [q{i}, 0, 0]}}" for i in range(n))
    potential = " + ".join(f"(q{i + 1} - q{i})**2/2" for i in range(n - 1))
    text = (f"gacli: 1\nname: h3_chain\ncoordinates: [{', '.join(f'q{i}' for i in range(n))}]\n"
            f"bodies:\n{bodies}\npotential: {potential}\n")
    found = integrals(derive(loads(text, path="h3_chain.yaml")))
    energy = next(i for i in found.found if i.name == "energy T + V")
    assert energy.conserved is True


def test_a_recursion_error_in_sympy_is_one_located_message():
    """steady on a thousand loads with sin(i*y): SymPy's polys recurse once per generator."""
    from gacli.budget import budget
    from gacli.errors import SystemFileError

    def deep(n):
        return deep(n + 1)

    with pytest.raises(SystemFileError) as caught, budget("m.yaml", 0) as state:
        state("solving for the steady motions")
        deep(0)
    (problem,) = caught.value.diagnostics
    assert str(problem) == ("m.yaml:1:1: error: the expressions are too deeply nested for SymPy in the step "
                            "'solving for the steady motions' (Python's recursion limit)")


# -- class 4: a one-value option given twice ----------------------------------------------------------

def _strict_app():
    """A small app on the mixin, as gacli's Group is to use it (gacli.cli_options.StrictOptions)."""
    from typer.core import TyperGroup

    from gacli.cli_options import StrictOptions

    class Group(StrictOptions, TyperGroup):
        pass

    app = typer.Typer(cls=Group)

    @app.command()
    def linearize(file: str, at: Optional[str] = None, output: Optional[str] = typer.Option(None, "--output", "-o"),
                  symbolic: bool = False, set_: list[str] = typer.Option([], "--set")) -> None:
        print(f"at={at} output={output}")

    @app.command()
    def other() -> None:
        pass

    return app


@pytest.mark.parametrize("args", [
    ["--at", "x=1", "--at", "x=2"],
    ["--at=x=1", "--at", "x=2"],
    ["-o", "a", "--output", "b"],
    ["-oa", "-o", "b"],
])
def test_a_one_value_option_given_twice_is_a_usage_error(args):
    from typer.testing import CliRunner
    result = CliRunner().invoke(_strict_app(), ["linearize", "f.yaml", *args])
    assert result.exit_code == 2, result.output
    assert "given more than once" in result.output


@pytest.mark.parametrize("args", [
    ["--at", "x=1"],
    ["--set", "a=1", "--set", "b=2"],          # an option that collects
    ["--symbolic", "--symbolic"],               # a flag
    ["--at", "--output", "-o", "b"],            # a value that looks like an option is a value
    ["--at", "x=1", "--", "--at"],
])
def test_options_given_once_or_collected_pass(args):
    from typer.testing import CliRunner
    result = CliRunner().invoke(_strict_app(), ["linearize", "f.yaml", *args])
    assert "given more than once" not in result.output
