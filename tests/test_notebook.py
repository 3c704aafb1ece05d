"""Derivations and systems in a notebook (LaTeX) and at the prompt (one line)."""

from __future__ import annotations

import re
import subprocess

import pytest

from conftest import SYSTEMS, derived, require_tool
from gacli.api import emit


def compile_math(tex: str, tmp_path) -> None:
    """``tex`` inside a minimal amsmath document must build with pdflatex."""
    pdflatex = require_tool("pdflatex")  # a skip here, a failure in CI
    document = "\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n" + tex + "\\end{document}\n"
    (tmp_path / "repr.tex").write_text(document, encoding="utf-8")
    run = subprocess.run([pdflatex, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape", "repr.tex"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-3000:]


def blocks(tex: str) -> list[str]:
    return re.findall(r"\\begin\{align\*\}.*?\\end\{align\*\}", tex, re.S)


def test_the_rolling_disk_shows_its_equations_as_latex(tmp_path):
    d = derived("rolling_disk")
    tex = d._repr_latex_()
    # The same equations as `gacli derive --format latex`, not a second rendering.
    assert blocks(tex) == blocks(emit(d, "latex")["rolling_disk.tex"]) and len(blocks(tex)) == 4
    assert tex.startswith("Thin disk rolling without slipping on a plane\n")
    # Comments would show as text in a notebook: each became the line it stands for.
    assert not any(line.startswith("%") for line in tex.splitlines())
    assert "Gibbs-Appell equations (eq. 14.19). $\\partial G" in tex
    compile_math(tex, tmp_path)


def test_the_bicycle_shows_its_equations_through_named_quantities(tmp_path):
    d = derived("whipple_bicycle")
    tex = d._repr_latex_()
    # The same LaTeX as `gacli derive --format latex`, which names the long equations' pieces.
    assert blocks(tex) == blocks(emit(d, "latex")["whipple_bicycle.tex"])
    assert "Named quantities" in tex and "M_{1,1}" in tex and "too large" not in tex
    assert "\\omega_{\\mathrm{rolled},y}" in tex  # the lean frame's angular velocity, by its name
    # Its note once, as text: it stood in the section's comment and again after \noindent, which
    # MathJax shows as it is.
    assert tex.count("Each quantity is computed once") == 1 and "\\noindent" not in tex
    compile_math(tex, tmp_path)


def test_a_plain_repr_says_what_it_is_in_one_line():
    d = derived("whipple_bicycle")
    text = repr(d)
    assert text == ("<Derivation of 'whipple_bicycle': k = 3, coordinates x, y, yaw, roll, pitch, steer, "
                    "wheel_R, wheel_F; speeds dot(roll), dot(wheel_R), dot(steer); M 3x3, F 3x1>")
    assert repr(d.system) == (f"<System 'whipple_bicycle' from {str(SYSTEMS / 'whipple_bicycle.yaml')!r}: "
                              "8 coordinates, 0 quasi-coordinates, 5 constraints, 4 bodies>")


def test_the_api_objects_are_what_the_reprs_belong_to():
    import gacli

    system = gacli.load(SYSTEMS / "cylinder_in_cylinder.yaml")
    assert repr(system).endswith(": 2 coordinates, 0 quasi-coordinates, 1 constraint, 1 body>")
    d = gacli.derive(system)
    assert "\\begin{align*}" in d._repr_latex_()
    assert "\n" not in repr(d)


@pytest.mark.parametrize("name", ["sphere_on_turntable", "chaplygin_sleigh", "particle_in_plane"])
def test_small_systems_show_their_equations(name):
    assert "\\begin{align*}" in derived(name)._repr_latex_()


def test_the_api_words_a_wrong_format_as_the_command_line_does():
    import gacli
    from gacli.emit import EMITTERS

    with pytest.raises(gacli.EmitError, match=rf"^'pdf' is not a format; choose one of: {', '.join(sorted(EMITTERS))}$"):
        gacli.emit(derived("cylinder_in_cylinder"), "pdf")
