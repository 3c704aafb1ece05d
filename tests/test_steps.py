"""The worked solution (``--steps``) contains the chapter's intermediate results.

Lines of the text output are parsed back with gacli's own grammar (the
output is written in it) and compared symbolically with the chapter.
"""

from __future__ import annotations

import subprocess

import pytest
import sympy as sp
from typer.testing import CliRunner

from conftest import SYSTEMS, require_tool
from gacli.cli import app
from gacli.read.expr.build import Scope, build
from gacli.read.expr.grammar import Name, Rate, walk
from gacli.read.expr.parser import parse


def sym(name):
    return sp.Symbol(name, real=True)


def expression(text: str) -> sp.Expr:
    """Parse one side of an output line (δx is written delta_x for the grammar)."""
    tree = parse(text.replace("δ", "delta_"))
    values = {n.id: sym(n.id) for n in walk(tree) if isinstance(n, Name)}
    rates = {(r.name, r.order): sym(("dot", "ddot")[r.order - 1] + f"({r.name})") for r in walk(tree) if isinstance(r, Rate)}
    return build(tree, Scope(values=values, rates=rates))


def steps_output(name: str) -> list[str]:
    result = CliRunner().invoke(app, ["derive", str(SYSTEMS / f"{name}.yaml"), "--steps"])
    assert result.exit_code == 0, result.output
    return [line.strip() for line in result.output.splitlines()]


def equations_for(lines: list[str], lhs: str) -> list[sp.Expr]:
    """Right-hand sides of the output equations whose left side is ``lhs``."""
    out = []
    for line in lines:
        left, sep, right = line.partition(" = ")
        if sep and left == lhs:
            out.append(expression(right))
    assert out, f"no line '{lhs} = ...'"
    return out


def holds(candidates, expected) -> bool:
    return any(sp.simplify(c - expected) == 0 for c in candidates)


def test_particle_steps():
    lines = steps_output("particle_in_plane")
    r, R, S = sym("r"), sym("R"), sym("S")
    assert holds(equations_for(lines, "dot(q)"), r**2 * sym("dot(theta)"))  # q̇ = r²θ̇
    assert holds(equations_for(lines, "Q_r"), R)
    assert holds(equations_for(lines, "Q_q"), S / r)
    assert "k = n + p - d - l = 2 + 1 - 1 - 0 = 2 degrees of freedom" in lines


def test_cylinder_steps():
    lines = steps_output("cylinder_in_cylinder")
    a, c, M, g, th = sym("a"), sym("c"), sym("M"), sym("g"), sym("theta")
    assert holds(equations_for(lines, "ddot(phi)"), c * sym("ddot(theta)") / a)  # aφ̈ = cθ̈
    assert holds(equations_for(lines, "Q_theta"), -M * g * c * sp.sin(th))


def test_sphere_steps_14_26_to_14_28():
    lines = steps_output("sphere_on_turntable")
    s = {n: sym(n) for n in "a M I Omega dot(Omega) x y dot(x) dot(y) ddot(x) ddot(y) ddot(q_z) F_x F_y M_x M_y M_z".split()}
    a, W, dW = s["a"], s["Omega"], s["dot(Omega)"]
    # (14.26)
    assert holds(equations_for(lines, "ddot(q_y)"), (s["ddot(x)"] + W * s["dot(y)"] + dW * s["y"]) / a)
    assert holds(equations_for(lines, "ddot(q_x)"), (-s["ddot(y)"] + W * s["dot(x)"] + dW * s["x"]) / a)
    # (14.27): the whole G, compared through its acceleration terms
    I, M = s["I"], s["M"]
    acc = (s["ddot(x)"], s["ddot(y)"], s["ddot(q_z)"])
    printed = (M / 2 * (acc[0] ** 2 + acc[1] ** 2)
               + I / (2 * a**2) * (acc[0] + W * s["dot(y)"] + dW * s["y"]) ** 2
               + I / (2 * a**2) * (-acc[1] + W * s["dot(x)"] + dW * s["x"]) ** 2 + I / 2 * acc[2] ** 2)
    whole = equations_for(lines, "G")[0]
    assert sp.simplify(whole - printed) == 0
    # (14.28)
    dW_ = equations_for(lines, "δW")[0]
    expected = ((s["F_x"] + s["M_y"] / a) * sym("delta_x") + (s["F_y"] - s["M_x"] / a) * sym("delta_y")
                + s["M_z"] * sym("delta_q_z"))
    assert sp.simplify(dW_ - expected) == 0


def test_top_steps_use_the_quasi_coordinate():
    lines = steps_output("spinning_top")
    th, phi_dot, psi_dot = sym("theta"), sym("dot(phi)"), sym("dot(psi)")
    assert holds(equations_for(lines, "dot(q)"), psi_dot + sp.cos(th) * phi_dot)  # dq = dψ + cos θ dφ
    assert holds(equations_for(lines, "dot(psi)"), sym("dot(q)") - sp.cos(th) * phi_dot)
    assert holds(equations_for(lines, "δpsi"), sym("delta_q") - sp.cos(th) * sym("delta_phi"))


def test_steps_need_text_or_latex():
    result = CliRunner().invoke(app, ["derive", str(SYSTEMS / "particle_in_plane.yaml"), "--steps", "--format", "c"])
    assert result.exit_code == 2


@pytest.mark.parametrize("name", ["particle_in_plane", "cylinder_in_cylinder", "sphere_on_turntable", "spinning_top"])
def test_latex_worked_solution_compiles(name, tmp_path):
    pdflatex = require_tool("pdflatex")
    out = tmp_path / f"{name}.tex"
    result = CliRunner().invoke(app, ["derive", str(SYSTEMS / f"{name}.yaml"), "--steps", "--format", "latex",
                                      "--standalone", "--output", str(out)])
    assert result.exit_code == 0, result.output
    run = subprocess.run([pdflatex, "-interaction=nonstopmode", "-halt-on-error", out.name],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]
    assert (tmp_path / f"{name}.pdf").exists()
