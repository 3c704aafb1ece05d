"""Which equations generated code computes (gacli.mechanics.code), and that they are the same equations.

A system written with frames has two routes to q̇, M and F: the closed forms
of the chapter's steps and the straight-line program (gacli.mechanics.program).
Generated code takes the one of fewer operations; the command line takes the
program alone, without the closed forms, when it is large. Whatever the route,
the generated module must agree with the closed forms at random states, and the
command line must write what ``gacli.emit(gacli.derive(...))`` writes.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp
from typer.testing import CliRunner

import gacli
from conftest import derived_file
from gacli.cli import app
from gacli.algebra.graph import cse_operations, shared_subexpressions
from gacli.errors import DerivationError
from gacli.loader.loading import load, load_source, loads
from gacli.mechanics.derivation import Derivation
from gacli.mechanics.equations import derive_for_code
from gacli.mechanics.equations import derive
from gacli.read.source import read_source
from test_generated_numeric import close, random_states, rhs_agrees, sympy_values
from test_emit_c import COMPILERS, compile_c
from test_emit_python import write_python

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent
BICYCLE = ROOT / "systems" / "whipple_bicycle.yaml"
ROBOTS = [TESTS / "twins" / "robot_trailer.yaml", TESTS / "twins" / "tricycle_front_drive.yaml",
          TESTS / "frames" / "car.yaml"]


def _bench_operations(exprs) -> int:
    """count_ops after one-pass CSE: benchmarks/bench_bicycle.py's count, not the one the choice uses."""
    replacements, reduced = shared_subexpressions(list(exprs), sp.numbered_symbols("_t"))
    return int(sum(sp.count_ops(v) for _, v in replacements) + sum(sp.count_ops(e) for e in reduced))


@pytest.mark.parametrize("path", [*ROBOTS, ROOT / "systems" / "rolling_disk.yaml", BICYCLE], ids=lambda p: p.stem)
def test_generated_code_is_never_longer_than_the_closed_forms(path):
    # Counted as the benchmark counts both tools: the route taken costs at most the closed forms'
    # operations (a few more where the choice's cheaper count ranks two routes close together),
    # a vehicle's program fewer, and a bicycle's or a trailer's less than half of them.
    d = derived_file(path)
    code = d.code
    taken = _bench_operations([*(e for _, e in code.kinematic_equations), *(e for _, e in code.mass_matrix),
                               *code.forcing])
    closed = _bench_operations([*(e for _, e in d.kinematic_equations), *d.mass_matrix, *d.forcing])
    assert taken <= 1.05 * closed, (taken, closed)
    if path in (*ROBOTS, BICYCLE):
        assert code.route == "program" and taken < closed, (taken, closed)
    if path.parent.name == "twins" or path == BICYCLE:
        assert taken < closed / 2, (taken, closed)


@pytest.mark.parametrize("path, taken", [
    # Euler parameters written by hand: M and F divide by e·e, divided out (code._divided).
    (ROOT / "benchmarks" / "kane_set" / "quaternion_top.yaml", "program"),
    # A ball with its body rates as speeds: ω is u, its rest's vanishing parts exact zeros.
    (TESTS / "frames" / "ball_body_rates.yaml", "program"),
    # A bar's weight turned into its frame and back, tidied by the display's simplifier.
    (ROOT / "benchmarks" / "kane_set" / "double_cart_pendulum.yaml", "program"),
    # Body rates with an offset centre: the rest formed with u̇ = 0 (α = u̇, no term to cancel).
    (TESTS / "frames" / "routh_body_rates.yaml", "program"),
    # Euler angles' rates: the sphere's contact along N, its ω summed from the rates there.
    (TESTS / "frames" / "spherical_robot.yaml", "program"),
    # On a turntable: along N, above both the ball and the table; the shell's ω × Iω not formed.
    (TESTS / "frames" / "unbalanced.yaml", "program"),
    # On a tilting plate: the ball's rotation along the frame between its second and third turn.
    (ROOT / "benchmarks" / "corpus" / "ball_and_plate.yaml", "program"),
    # Written without frames: each wheel's rotation forms read along the axes that do not spin with it.
    (TESTS / "twins" / "car_format1.yaml", "program"),
    (TESTS / "twins" / "car_angle_sums.yaml", "program"),
    # A mass centre placed from the geometric centre along the body's axes: the contact read from
    # the centre, where the offset and the contact's centre would cancel only as closed forms.
    (TESTS / "twins" / "unbalanced_sphere_turntable.yaml", "program"),
], ids=lambda p: getattr(p, "stem", p))
def test_the_program_now_costs_no_more_than_the_closed_forms(path, taken):
    # Counted alike, after SymPy's cse (gacli.algebra.graph.cse_operations, the counting).
    d = derived_file(path)
    code = d.code
    closed = cse_operations([*(e for _, e in d.kinematic_equations), *d.mass_matrix, *d.forcing])
    assert code.route == taken
    assert code.operations <= closed, (code.operations, closed)


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: p.stem)
def test_the_programs_code_agrees_with_the_closed_forms(path, tmp_path):
    # The vehicles take the program (a trailer's: 353 operations against 1,395): their generated
    # module is checked against the chapter's closed forms, an independent derivation.
    d = derived_file(path)
    assert d.code.route == "program"
    module = write_python(d, tmp_path)
    for state in list(random_states(d, 7))[:5]:
        M, F, xdot = sympy_values(d, *state)
        assert close(module.mass_matrix(*state), M)
        assert close(module.forcing(*state), F)
        assert rhs_agrees(module.rhs(*state), M, F, xdot, len(d.coordinates))


def test_the_command_line_writes_what_the_api_writes(tmp_path):
    # The command line derives a bicycle by the program alone (no closed forms, no rolling rows in N);
    # the API derives everything and chooses the same route, so the two files are the same.
    out = tmp_path / "bicycle.py"
    result = CliRunner().invoke(app, ["derive", str(BICYCLE), "--format", "python", "--output", str(out)])
    assert result.exit_code == 0, result.output
    (text,) = gacli.emit(derive(load(BICYCLE)), "python").values()
    assert out.read_text(encoding="utf-8") == text


def test_the_bicycle_is_derived_for_code_without_its_closed_forms():
    system = load_source(read_source(BICYCLE), rolling_rows=False)
    assert not system.rolling_rows and not any(c.derived for c in system.constraints)
    d = derive_for_code(system)
    assert d is not None and d.code.route == "program" and d.k == 3
    # One record type reaches the emitters, with or without its closed forms.
    assert type(d) is Derivation and not d.closed and type(derive(load(BICYCLE))) is Derivation
    with pytest.raises(DerivationError, match="without its rolling rows"):
        derive(system)


@pytest.mark.parametrize("path", [ROOT / "systems" / "rolling_disk.yaml", ROOT / "systems" / "cylinder_in_cylinder.yaml"],
                         ids=lambda p: p.stem)
def test_a_small_system_is_derived_for_code_by_its_program_alone(path, tmp_path):
    # One engine for code (issue 28): a rolling disk's program ties with its closed forms (41
    # operations), and generated code takes the program without forming them, on the command
    # line as through the API, which derives the closed forms and still writes the program's code.
    system = load_source(read_source(path), rolling_rows=False)
    d = derive_for_code(system)
    assert d is not None and not d.closed and d.code.route == "program"
    out = tmp_path / "out.py"
    result = CliRunner().invoke(app, ["derive", str(path), "--format", "python", "--output", str(out)])
    assert result.exit_code == 0, result.output
    (text,) = gacli.emit(derive(load(path)), "python").values()
    assert out.read_text(encoding="utf-8") == text


def test_loading_without_rolling_rows_still_reads_every_declaration(tmp_path):
    text = BICYCLE.read_text(encoding="utf-8").replace("axle: [0, 1, 0]", "axle: [0, 0, 0]", 1)
    assert "axle: [0, 0, 0]" in text
    path = tmp_path / "bicycle.yaml"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(app, ["derive", str(path), "--format", "c"])
    assert result.exit_code != 0
    assert "axle is the zero vector" in result.output and "bicycle.yaml:" in result.output
    assert "Traceback" not in result.output


def test_a_format1_file_computes_its_program():
    # A file without frames has a program too (its bodies' positions and rotation forms), and
    # generated code computes it: M and F as the chapter's closed forms give them.
    system = loads("gacli: 1\nname: fall\nparameters: [m, g]\ncoordinates: [z]\n"
                   "bodies: {ball: {mass: m, position: [0, 0, z]}}\npotential: m*g*z\n")
    d = derive(system)
    m, g = (next(s for s in d.mass_matrix.free_symbols | d.forcing.free_symbols if s.name == n) for n in "mg")
    assert system.frames is None and d.code.route == "program"
    at = {m: sp.Rational(3, 2), g: sp.Rational(49, 5)}  # the program's graphs are built unevaluated
    assert (d.code.dense_mass_matrix()[0, 0] - m).subs(at) == 0 and (d.code.forcing[0] + g * m).subs(at) == 0
    assert d.mass_matrix == sp.Matrix([[m]]) and d.forcing == sp.Matrix([[-g * m]])  # the closed forms


PROGRAM_ROUTE = [p for p in sorted([*(TESTS / "frames").glob("*.yaml"), *(TESTS / "twins").glob("*.yaml")])
                 if not p.stem.endswith("_format1")]


@pytest.mark.parametrize("compiler", COMPILERS)
@pytest.mark.parametrize("path", PROGRAM_ROUTE, ids=lambda p: p.stem)
def test_the_code_of_every_frame_fixture_compiles_strictly(path, compiler, tmp_path):
    # -Wall -Wextra -Werror -pedantic: no dead temporary, whichever route the code takes (a
    # program's sums are inlined unevaluated, and terms that cancel when the CSE rebuilds them
    # once left names nothing used).
    compile_c(derived_file(path), tmp_path, compiler)


@pytest.mark.parametrize("framed, unframed", [
    (TESTS / "frames" / "car.yaml", TESTS / "twins" / "car_format1.yaml"),
    (TESTS / "twins" / "tricycle_front_drive.yaml", TESTS / "twins" / "tricycle_front_drive_format1.yaml"),
    (ROOT / "benchmarks" / "corpus" / "forklift.yaml", ROOT / "benchmarks" / "corpus" / "forklift_format1.yaml"),
], ids=lambda p: p.stem)
def test_a_vehicle_written_without_frames_costs_near_its_framed_twin(framed, unframed):
    # Rows stated in N's axes (cos θ ẋ + sin θ ẏ − w θ̇ = r φ̇) turn with the heading: solved along
    # it (solve.turned_columns), their cofactors are numbers, not products of sines and cosines, and
    # the bodies' points formed along it (program/heading.py) carry no sin θ, cos θ of a hitch.
    # The car: 215 → 182 → 101 operations (133 with frames); the tricycle 392 → 355 → 284 (249);
    # the forklift 391 → 381 → 294 (233).
    assert derived_file(unframed).code.operations <= 1.3 * derived_file(framed).code.operations


def test_only_short_divisors_are_divided_out():
    # Dividing out e·e (four terms) gives a top's M back as A + m l²; a damper's line on a
    # quaternion body divides by a polynomial of 67 terms, and cancelling over it took 24 s of a
    # derive for a longer entry (gacli.mechanics.code._rational).
    import sympy as sp

    from gacli.mechanics.code import _rational

    e = sp.symbols("e0:4", real=True)
    x = sp.Symbol("x", real=True)
    norm = sum(c ** 2 for c in e)
    assert _rational(x * e[0] ** 2 / norm)
    many = sp.symbols("a0:20", real=True)
    assert not _rational(x / (norm + sum(a * b for a, b in zip(many, many[1:]))))


def test_a_loops_dead_point_is_told_from_a_single_angles_divisor():
    """The display's simplifier is not tried on code that divides by the sine of a combination of
    angles (a linkage's l sin(θ_a − θ_b)), where it never shortened; a wheel's cos θ keeps it."""
    from gacli.mechanics.code import CodeEquations, _over_a_loop

    q2, q3, th, l, m = sp.symbols("q2 q3 theta l m")

    def code(entry):
        return CodeEquations("program", (), (((0, 0), entry),), (entry,), 0)

    assert _over_a_loop(code(m / (l * sp.sin(q2 - q3)) ** 2))
    assert not _over_a_loop(code(m / sp.cos(th) ** 2))
    assert not _over_a_loop(code(m * sp.sin(q2 - q3)))
