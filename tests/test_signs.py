"""u/|u| is read as sign(u) in what people read (gacli.algebra.signs), never in generated code."""

from __future__ import annotations

import random

import sympy as sp
from typer.testing import CliRunner

from gacli.algebra.signs import with_signs
from gacli.cli import app

x, w, k, L0, r, th = sp.symbols("x w k L0 r th", real=True)


def _agree_at_random_points(a: sp.Expr, b: sp.Expr) -> None:
    rng = random.Random(7)
    symbols = sorted(a.free_symbols | b.free_symbols, key=str)
    for _ in range(20):
        point = {s: rng.uniform(-3, 3) for s in symbols}
        assert abs(float(a.subs(point)) - float(b.subs(point))) < 1e-12


def test_a_wall_springs_quotient_reads_as_a_sign():
    quotient = -k * (sp.Abs(x + 1) - L0) * (x + 1) / sp.Abs(x + 1)
    signed = with_signs(quotient)
    assert signed.has(sp.sign) and not signed.has(sp.Pow)
    _agree_at_random_points(quotient, signed)


def test_a_multiplied_out_spring_force_is_gathered_over_its_length_first():
    spread = k * r * (w - L0 * w / sp.Abs(w + x) - L0 * x / sp.Abs(w + x) + x) * sp.sin(th)
    signed = with_signs(spread)
    assert signed.has(sp.sign) and len(str(signed)) < len(str(spread))
    _agree_at_random_points(spread, signed)


def test_a_quotient_of_other_things_is_left_alone():
    for e in (x / sp.Abs(w), (x + 1) / sp.Abs(x - 1), x * sp.Abs(x)):
        assert with_signs(e) == e


def test_the_printout_of_a_wall_spring_shows_its_sign_and_the_code_its_quotient(tmp_path):
    path = tmp_path / "wall.yaml"
    path.write_text("gacli: 1\nname: wall\nparameters: [m, k, L0]\ncoordinates: [x]\n"
                    "bodies: {cart: {mass: m, position: [x, 0, 0]}}\n"
                    "points: {A: {N: [-1, 0, 0]}, B: {N: [x, 0, 0]}}\n"
                    "loads:\n  - {spring: k, between: [A, B], length: L0}\n",
                    encoding="utf-8")
    text = CliRunner().invoke(app, ["derive", str(path)])
    assert text.exit_code == 0, text.output
    assert "sign(x + 1)" in text.output and "/abs(" not in text.output
    code = CliRunner().invoke(app, ["derive", str(path), "--format", "python"])
    assert code.exit_code == 0 and "sign" not in code.output
