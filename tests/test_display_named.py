"""Long equations printed through named quantities mean the derivation's M, F and q̇.

Each printed line ``name = value`` of the named form (gacli.display.named)
is read back with the system file's own parser and evaluated in order at a
random point, every name taking the number its line gives; the printed
M_r_s, F_r and q̇ are then compared with the derivation's own M, F and
kinematic equations evaluated at the same point by gacli.numeric, which never
sees the printout.
"""

from __future__ import annotations

import random
import re
from pathlib import Path

import pytest
import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.graph import free_symbols
from gacli.display.labels import identifier, label_name, point_words
from gacli.display.report import derivation_report, long_form
from gacli.numeric import Program
from gacli.numeric.spheres import spheres
from gacli.pipeline import run
from gacli.read.expr.build import Scope, build
from gacli.read.expr.parser import parse
from gacli.cli import app
from typer.testing import CliRunner

ROOT = Path(__file__).resolve().parent.parent
# A program-route bicycle (frames, rolling), a closed-form body in quasi-coordinates, a format-1 car.
FILES = [ROOT / "systems" / "whipple_bicycle.yaml", ROOT / "tests" / "cases" / "quaternion_body_rates.yaml",
         ROOT / "tests" / "twins" / "ackermann_car_format1.yaml"]
LINE = re.compile(r"^(?P<name>[A-Za-z_][A-Za-z0-9_]*|dot\((?P<rate>[A-Za-z0-9_]+)\)) = (?P<value>.+)$")
EQUATION = re.compile(r"^for ddot\((?P<name>[^)]+)\): (?P<lhs>.+) = F_(?P<row>\d+)$")


def _point(d, rng) -> dict[sp.Symbol, float]:
    code = d.code
    exprs = [*(e for _, e in code.kinematic_equations), *(e for _, e in code.mass_matrix), *code.forcing,
             *d.mass_matrix.values(), *d.forcing]
    # Angles and lengths alike in (0.3, 1.2): away from the bicycle's singular upright-and-straight pose.
    symbols = sorted(free_symbols(exprs) | set(d.speeds), key=lambda s: s.name)
    point = {s: rng.uniform(0.3, 1.2) for s in symbols}
    for sphere in spheres(d.system):  # the printout and the closed forms agree there, where the motion is
        norm = sum(point[x] ** 2 for x in sphere.symbols) ** 0.5 / float(sphere.radius2) ** 0.5
        point.update({x: point[x] / norm for x in sphere.symbols})
    # A rate that is not a speed takes the value its kinematic equation gives it (F may hold it).
    kinematic = [(q, e) for q, e in d.kinematic_equations if e != S.rate(q)]
    for (q, _), value in zip(kinematic, Program([e for _, e in kinematic])(point)):
        point[S.rate(q)] = value.real
    return point


def _printed_values(lines, point: dict[sp.Symbol, float]) -> tuple[dict[str, complex], dict[str, complex]]:
    """Every ``name = value`` line evaluated in order: (names, rates dot(q) the lines define)."""
    values = {s.name: sp.Float(v, 30) for s, v in point.items() if not S.RATE_NAME.match(s.name)}
    rates = {(S.RATE_NAME.match(s.name).group(3), 1): sp.Float(v, 30)
             for s, v in point.items() if S.RATE_NAME.match(s.name)}
    names, defined = {}, {}
    for line in lines:
        m = LINE.match(line)
        if m is None:
            continue
        value = complex(build(parse(m["value"]), Scope({**values, **names}, rates)).evalf(30))
        if m["rate"]:
            rates[(m["rate"], 1)] = sp.Float(value.real, 30)
            defined[m["rate"]] = value
        else:
            names[m["name"]] = sp.Float(value.real, 30)
    return names, defined


def _close(x: complex, y: complex) -> bool:
    return abs(x - y) <= 1e-8 * (1 + abs(y))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_named_printout_is_the_derived_m_f_and_rates(path):
    d = run(path).derivation
    assert long_form(d) is not None, "these systems' equations are long: they print through names"
    sections = derivation_report(d)
    lines = [line for s in sections[1:] for line in s.lines]  # after the degrees of freedom
    assert not any("too large" in line for line in lines)
    rng = random.Random(7)
    point = _point(d, rng)
    names, rates = _printed_values(lines, point)
    k = d.k
    M, F = d.mass_matrix, d.forcing
    reference = Program([*M, *F, *(e for _, e in d.kinematic_equations)])(point)
    for r in range(k):
        for s in range(k):
            printed = names.get(f"M_{min(r, s) + 1}_{max(r, s) + 1}", 0)
            assert _close(complex(printed), reference[r * k + s]), (r, s)
        assert _close(complex(names[f"F_{r + 1}"]), reference[k * k + r]), r
    # q̇ of each coordinate whose rate is not a speed: printed, by a name's line or the kinematic section.
    for (q, e), value in zip(d.kinematic_equations, reference[k * k + k:]):
        if e != S.rate(q):
            assert q in rates and _close(rates[q], value), q
    # Each equation line is M's row through the printed names: M_s_r u̇_r = F_s.
    rows = [EQUATION.match(line) for line in lines if EQUATION.match(line)]
    assert [m["name"] for m in rows] == list(d.independent)


def test_small_systems_print_written_out():
    d = run(ROOT / "systems" / "rolling_disk.yaml").derivation
    assert long_form(d) is None
    titles = [s.title for s in derivation_report(d)]
    assert "Generalized forces, eq. (14.13)" in titles


@pytest.mark.parametrize("label, name, words", [
    (("w", "rolled", "actual", 0), "w_rolled_x", "angular velocity of rolled"),
    (("w", "fork", "u_steer", 2), "w_fork_steer_z", "partial angular velocity of fork for dot(steer)"),
    (("v", "frame+rear_wheel", "actual", "head_tube", 1), "v_frame_rear_wheel_y",
     "velocity of the mass centre of frame and rear_wheel [head_tube]"),
    (("v", "bob@", "u_q", "B", 0), "v_bob_q_x", "the mass centre of bob"),
    (("I", "G1", "A", 2, 2), "I_G1_zz", "inertia of G1 about it [A]"),
    (("I", "G1", "A", (1, 2), (1, 2)), "I_G1_yyzz", "equal about y and z [A]"),
])
def test_labels_name_physical_quantities(label, name, words):
    got, _, about = label_name(label)
    assert got == name and words in about


def test_names_are_identifiers():
    assert identifier("loads[2]@") == "loads_2"
    assert identifier("a++b") == "a_b"
    assert point_words("loads[1]@") == "the point of application of loads[1]"


def test_no_named_quantity_is_only_another_quantity_s_name():
    # A five-bar's two loop rows share their determinant: its pieces came out as z3 = z1, z5 = z2.
    d = run(ROOT / "benchmarks" / "kane_set" / "variants" / "linkages" / "l3_five_bar.yaml").derivation
    lines = [line for s in derivation_report(d)[1:] for line in s.lines]
    assert any(re.match(r"^z\d+ = ", line) for line in lines)
    assert not [line for line in lines if re.match(r"^z\d+ = z\d+$", line)]


def test_a_bars_equal_moments_are_named_for_both_axes():
    """A bar's inertia [0, I, I] is one value on the tape: named for y alone, a planar chain's printout
    said I_G1_yy where the moment is about z."""
    text = CliRunner().invoke(app, ["derive", str(ROOT / "benchmarks/kane_set/variants/chains/chain4_relative.yaml")]).output
    assert "I_G1_yyzz = l1**2*m1/12" in text and "I_G1_yy " not in text


@pytest.mark.parametrize("path", [ROOT / "tests/cases/fourbar_heights.yaml",
                                  ROOT / "tests/cases/hoop_with_a_point_mass.yaml"], ids=lambda p: p.stem)
def test_no_quantity_is_named_for_a_number_times_a_symbol(path):
    # A reviewer's hoop printed z5 = 3*m, z21 = -z8, z16 = 2*g: a name reads no better than those.
    d = run(path).derivation
    lines = [line.strip() for s in derivation_report(d)[1:] for line in s.lines]
    assert any(re.match(r"^z\d+ = ", line) for line in lines)
    assert not [line for line in lines if re.match(r"^z\d+ = -?\d*\*?-?[A-Za-z_]\w*$", line)]
