"""The generated Octave/MATLAB function files: their shape, and their numbers in GNU Octave.

The reference is the generated Python module (itself checked against SymPy
in test_generated_numeric.py): for every system in systems/ and the tests'
own (test_emit_python.EXTRA, plus HOSTILE below, whose names are Octave's
keywords and builtins), NAME_rhs, NAME_mass_matrix and NAME_forcing agree
with it at seeded random states to 1e-12 relative. One octave-cli process
evaluates every state of every system: Octave is slow to start.
"""

from __future__ import annotations

import re
import subprocess

import numpy as np
import pytest

from conftest import SYSTEMS, require_tool
from gacli.emit import EMITTERS
from gacli.emit.naming import layout
from gacli.emit.octave import emit_octave
from gacli.mechanics.equations import derive
from gacli.loader.loading import loads
from test_emit_python import EXTRA, write_python
from test_generated_numeric import close, derivation, random_states

# Names that Octave and MATLAB read as keywords, constants or the functions the code calls.
HOSTILE = """
gacli: 1
name: octave_words
parameters:
  end: {value: 2}
  i: {value: 0.5}
  j: {value: 0.25}
  e: {value: 3}
  L: {value: 1.5}
  idx: {value: 0.7}
  eps: {value: 0.1}
  Inf: {value: 0.2}
  NaN: {value: 0.3}
  zeros: {value: 1.1}
  chol: {value: 0.9}
  c_0: {value: 0.4}
coordinates: [function, switch]
bodies:
  b1: {mass: end + chol, position: [function, i*switch, 0]}
  b2: {mass: e*idx, position: [L*cos(function), j*sin(switch), 0]}
potential: (eps + Inf)*function**2 + NaN*zeros*switch**2 + c_0*exp(switch) + pi*exp(1)*function
"""

CASES = sorted(p.stem for p in SYSTEMS.glob("*.yaml")) + sorted(EXTRA) + ["octave_words"]
STATES = 5


def case(name):
    if name == "octave_words":
        return derive(loads(HOSTILE, path="/somewhere/octave_words.yaml"))
    return derivation(name)


def octave_vector(values) -> str:
    return "[" + "; ".join(repr(float(v)) for v in values) + "]"


def evaluation_script(cases) -> str:
    """Octave code that prints, per system and state, rhs, M (column-major) and F on one line each."""
    lines = ["format long;", "more off;"]
    for name, d, states in cases:
        for t, x, p, r in states:
            args = f"{float(t)!r}, {octave_vector(x)}, {octave_vector(p)}, {octave_vector(r)}"
            for function in ("rhs", "mass_matrix", "forcing"):
                lines.append(f"v = {name}_{function}({args}); fprintf('%.17g ', v(:)); fprintf('\\n');")
    return "\n".join(lines)


@pytest.fixture(scope="module")
def octave_results(tmp_path_factory):
    """name → [(state, rhs, M, F)] from one octave-cli run over every case."""
    octave = require_tool("octave-cli")
    directory = tmp_path_factory.mktemp("octave")
    cases = []
    for name in CASES:
        d = case(name)
        for file_name, text in emit_octave(d).items():
            (directory / file_name).write_text(text, encoding="utf-8")
        cases.append((name, d, list(random_states(d, 2000 + CASES.index(name)))[:STATES]))
    script = directory / "evaluate_all.m"
    script.write_text(evaluation_script(cases), encoding="utf-8")
    result = subprocess.run([octave, "--no-gui", "--norc", "--quiet", "--eval", f"cd('{directory}'); evaluate_all"],
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    rows = iter(result.stdout.splitlines())
    return {name: [(state, *(np.array(next(rows).split(), dtype=float) for _ in range(3))) for state in states]
            for name, d, states in cases}, directory


@pytest.mark.parametrize("name", CASES)
def test_octave_agrees_with_the_python_module(name, octave_results, tmp_path):
    results, _ = octave_results
    d = case(name)
    module = write_python(d, tmp_path)
    for seed, ((t, x, p, r), xdot, M, F) in enumerate(results[name]):
        assert close(M.reshape(d.k, d.k, order="F"), module.mass_matrix(t, x, p, r)), (seed, "M")
        assert close(F, module.forcing(t, x, p, r)), (seed, "F")
        assert close(xdot, module.rhs(t, x, p, r)), (seed, "rhs")


def test_indices_struct_matches_the_layout(octave_results):
    _, directory = octave_results
    octave = require_tool("octave-cli")
    name = "sphere_on_turntable"
    script = (f"cd('{directory}'); idx = {name}_indices(); "
              "fprintf('%d %d %d %d %d %d %d\\n', idx.nx, idx.nu, idx.np, idx.nr, idx.x.dot_q_z, idx.p.I_, "
              "idx.r.dot_Omega);")
    result = subprocess.run([octave, "--no-gui", "--norc", "--quiet", "--eval", script],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    lay = layout(derivation(name))
    assert result.stdout.split() == [str(v) for v in (
        len(lay.state), lay.k, len(lay.parameters), len(lay.r),
        lay.state.index("dot(q_z)") + 1, lay.parameters.index("I") + 1, lay.r.index("dot(Omega)") + 1)]


def test_ode45_integrates_the_rhs(octave_results):
    """The README's call: ode45 over an anonymous function of NAME_rhs."""
    _, directory = octave_results
    octave = require_tool("octave-cli")
    script = (f"cd('{directory}'); p = [1; 9.81; 0.1; 0.5; 0.4];"
              "[t, x] = ode45(@(t, x) cylinder_in_cylinder_rhs(t, x, p, []), [0 1], [0.3; 0; 0]);"
              "fprintf('%d %.6f\\n', size(x, 2), x(end, 1));")
    result = subprocess.run([octave, "--no-gui", "--norc", "--quiet", "--eval", script],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    columns, angle = result.stdout.split()
    assert columns == "3" and abs(float(angle)) <= 0.3 + 1e-6


# -- the text, without Octave ----------------------------------------------------

def test_files_and_signatures():
    files = EMITTERS["octave"](derivation("cylinder_in_cylinder"))
    assert sorted(files) == [f"cylinder_in_cylinder_{f}.m" for f in ("defaults", "forcing", "indices", "mass_matrix", "rhs")]
    assert "function xdot = cylinder_in_cylinder_rhs(t, x, p, r)" in files["cylinder_in_cylinder_rhs.m"]
    assert "function idx = cylinder_in_cylinder_indices()" in files["cylinder_in_cylinder_indices.m"]
    assert all(text.startswith("% Generated by gacli") for text in files.values())


def test_octave_names_are_renamed_and_never_start_with_an_underscore():
    files = emit_octave(case("octave_words"))
    code = files["octave_words_rhs.m"]
    assigned = set(re.findall(r"^\s*(\w+) = ", code, flags=re.M))
    for word in ("end", "i", "j", "e", "L", "idx", "eps", "Inf", "NaN", "zeros", "chol", "function", "switch"):
        assert f"{word}_" in assigned or f"dot_{word}" in assigned, word
        assert word not in assigned - {"L"}, word  # L is the rhs's own Cholesky factor
    assert "c_0 = p(" in code and "cc_0 = " in code  # the temporaries step around the parameter c_0
    assert not re.search(r"(^|[^\w])_\w", re.sub(r"%.*", "", code), flags=re.M)


def test_reactions_are_refused():
    from gacli.errors import EmitError

    with pytest.raises(EmitError, match="Python and C only"):
        emit_octave(derivation("cylinder_in_cylinder"), reactions=True)


def readme_block(language: str, marker: str) -> str:
    """The README's fenced ``language`` block that contains ``marker``."""
    from conftest import ROOT

    blocks = re.findall(rf"```{language}\n(.*?)```", (ROOT / "README.md").read_text(encoding="utf-8"), flags=re.S)
    (block,) = [b for b in blocks if marker in b]
    return block


def test_readme_example_runs_and_rolls_on_the_circle(tmp_path):
    """The README's ode45 example, against the closed form of test_generated_numeric's circle (eq. 14.30)."""
    octave = require_tool("octave-cli")
    build = tmp_path / "build"
    build.mkdir()
    for file_name, text in EMITTERS["octave"](derivation("sphere_on_turntable")).items():
        (build / file_name).write_text(text, encoding="utf-8")
    (tmp_path / "readme_example.m").write_text(readme_block("matlab", "ode45"), encoding="utf-8")
    result = subprocess.run([octave, "--no-gui", "--norc", "--quiet", "--eval", f"cd('{tmp_path}'); readme_example"],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    x, y = (float(v) for v in re.fullmatch(r"x = (\S+), y = (\S+)\n", result.stdout).groups())
    omega, w0 = 2 * 2.0 / 7, 0.1
    z = w0 * (np.exp(1j * omega * 5.0) - 1) / (1j * omega)
    assert abs(x - z.real) <= 1e-4 and abs(y - z.imag) <= 1e-4
