"""Parameter values in every code target: C's NAME_default_parameters, Octave's NAME_defaults,
the DEFAULTS of Python and JAX, the FMU's start values.

The values are checked against numbers computed here from the file's formulas
(the Whipple bicycle's HTA = pi/2 - pi/10, rake, tempc, ForkCGNorm), and the
bicycle's C, given nothing but its own defaults, is integrated and compared
with the linear benchmark of Meijaard et al. (2007) and with the Python module.
"""

from __future__ import annotations

import ctypes
import math
import subprocess

import numpy as np
import pytest

from typer.testing import CliRunner

from conftest import SYSTEMS, derived
from gacli.cli import app
from gacli.emit import emit
from gacli.emit.naming import layout
from test_bicycle import REAR_RADIUS, reference
from test_emit_c import STRICT, need, write_c

BICYCLE = "whipple_bicycle"
SPEED = 5.0          # m/s: inside the benchmark's self-stable range (4.29 to 6.02)
ROLL0 = 1e-3         # rad: small, so that the linear benchmark describes the motion
T_END, STEPS = 3.0, 6000


def paper_values() -> dict[str, float]:
    """A few of the bicycle's parameters, from the file's formulas, computed here by hand."""
    hta = math.pi / 2 - math.pi / 10
    rake = -(0.08 * math.sin(hta) - 0.35 * math.cos(hta))
    tempa, tempb = 0.7 - 0.35, 1.02 - 0.9
    tempc = math.hypot(tempa, tempb)
    fork_cg_norm = rake + tempc * math.sin(math.pi / 2 - hta - math.acos(tempa / tempc))
    return {"HTA": hta, "htangle": hta, "rake": rake, "forkoffset": rake, "tempc": tempc,
            "ForkCGNorm": fork_cg_norm, "forkcg3": fork_cg_norm, "Iframe22": 11.0, "WRrad": 0.3}


MAIN = r"""
#include <stdio.h>
#include "whipple_bicycle.h"

#define NX WHIPPLE_BICYCLE_NX

static void step(double t, double h, double *x, const double *p)
{
    double k[4][NX], y[NX];
    int s, i;
    for (s = 0; s < 4; ++s) {
        const double c = s == 0 ? 0.0 : (s == 3 ? h : h/2);
        for (i = 0; i < NX; ++i) {
            y[i] = x[i] + (s == 0 ? 0.0 : c*k[s - 1][i]);
        }
        whipple_bicycle_rhs(t + c, y, p, NULL, k[s]);
    }
    for (i = 0; i < NX; ++i) {
        x[i] += h/6*(k[0][i] + 2*k[1][i] + 2*k[2][i] + k[3][i]);
    }
}

int main(void)
{
    double p[WHIPPLE_BICYCLE_NP], x[NX] = {0.0};
    int missing = whipple_bicycle_default_parameters(p), n, i;
    const double h = %(t_end)r/%(steps)d;
    x[WHIPPLE_BICYCLE_X_ROLL] = %(roll)r;
    x[WHIPPLE_BICYCLE_X_DOT_WHEEL_R] = %(rate)r;
    for (n = 0; n < %(steps)d; ++n) {
        step(n*h, h, x, p);
    }
    printf("%%d\n", missing);
    for (i = 0; i < NX; ++i) {
        printf("%%.17g\n", x[i]);
    }
    return 0;
}
"""


@pytest.fixture(scope="module")
def bicycle_c(tmp_path_factory):
    """The bicycle's C built once: a program that integrates from the defaults, and a shared library."""
    directory = tmp_path_factory.mktemp("bicycle_c")
    written = CliRunner().invoke(app, ["derive", str(SYSTEMS / f"{BICYCLE}.yaml"), "--format", "c",
                                       "--output", str(directory)])
    assert written.exit_code == 0, written.output
    source = directory / f"{BICYCLE}.c"
    main = directory / "main.c"
    main.write_text(MAIN % {"t_end": T_END, "steps": STEPS, "roll": ROLL0, "rate": SPEED / REAR_RADIUS})
    program, library = directory / "bicycle", directory / "libbicycle.so"
    gcc = need("gcc")
    for command in ([gcc, *STRICT, "-O1", str(main), str(source), "-o", str(program), "-lm"],
                    [gcc, *STRICT, "-O1", "-shared", "-fPIC", str(source), "-o", str(library), "-lm"]):
        built = subprocess.run(command, capture_output=True, text=True)
        assert built.returncode == 0 and not built.stderr, built.stderr
    return program, library


def c_defaults(library, count: int) -> tuple[int, np.ndarray]:
    lib = ctypes.CDLL(str(library))
    function = getattr(lib, f"{BICYCLE}_default_parameters")
    function.argtypes, function.restype = [ctypes.POINTER(ctypes.c_double)], ctypes.c_int
    p = np.zeros(count)
    missing = function(p.ctypes.data_as(ctypes.POINTER(ctypes.c_double)))
    return missing, p


def test_c_defaults_are_the_files_values_evaluated_in_order(bicycle_c):
    lay = layout(derived(BICYCLE))
    missing, p = c_defaults(bicycle_c[1], len(lay.parameters))
    assert missing == 0
    for name, value in paper_values().items():
        assert p[lay.parameters.index(name)] == pytest.approx(value, rel=1e-15, abs=1e-16), name


def python_module(name: str) -> dict:
    from gacli.simulate import load_generated

    return vars(load_generated(derived(name)))


def test_c_integrates_from_its_defaults_alone_and_agrees_with_python_and_the_benchmark(bicycle_c):
    from scipy.integrate import solve_ivp
    from scipy.linalg import expm

    run = subprocess.run([str(bicycle_c[0])], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    missing, *final = run.stdout.split()
    assert missing == "0"
    final = np.array([float(v) for v in final])

    module = python_module(BICYCLE)
    state = list(module["STATE"])
    p = [module["DEFAULTS"][n] for n in module["PARAMETERS"]]
    x0 = np.zeros(len(state))
    x0[state.index("roll")], x0[state.index("dot(wheel_R)")] = ROLL0, SPEED / REAR_RADIUS
    python = solve_ivp(lambda t, x: module["rhs"](t, x, p), (0, T_END), x0, rtol=1e-11, atol=1e-13).y[:, -1]
    np.testing.assert_allclose(final, python, rtol=1e-8, atol=1e-11)

    # The benchmark's linear equations in roll, steer and their rates (independent of gacli).
    picked = [state.index(n) for n in ("roll", "steer", "dot(roll)", "dot(steer)")]
    linear = expm(reference(SPEED) * T_END) @ np.array([ROLL0, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(final[picked], linear, rtol=0, atol=1e-3 * ROLL0)
    assert abs(final[state.index("roll")]) < ROLL0  # self-stable at 5 m/s: the lean dies away


def test_python_jax_and_fmu_defaults_agree_with_the_formulas():
    import json
    import zipfile
    import io
    import xml.etree.ElementTree as ET

    expected = paper_values()
    python = python_module(BICYCLE)["DEFAULTS"]
    (jax_text,) = emit(derived(BICYCLE), "jax").values()
    jax_defaults = _assigned_dict(jax_text, "DEFAULTS")
    fmu = emit(derived(BICYCLE), "fmu", binary=False)
    (blob,) = fmu.values()
    with zipfile.ZipFile(io.BytesIO(blob)) as archive:
        root = ET.fromstring(archive.read("modelDescription.xml"))
    starts = {v.get("name"): float(v.find("Real").get("start"))
              for v in root.iter("ScalarVariable") if v.get("causality") == "parameter"}
    for name, value in expected.items():
        assert python[name] == pytest.approx(value, rel=1e-15), name
        assert starts[name] == pytest.approx(value, rel=1e-15), name
    assert jax_defaults == python
    assert json.dumps(python)  # plain floats


def _assigned_dict(text: str, name: str) -> dict:
    import ast

    for node in ast.parse(text).body:
        if isinstance(node, ast.Assign) and node.targets[0].id == name:
            return ast.literal_eval(node.value)
    raise AssertionError(f"{name} is not assigned")


SPARE = """
gacli: 1
name: spare
parameters:
  m: {value: 2}
  k: {description: stiffness}
  w: {value: "sqrt(k/m)"}
  L: {value: "2*m + 1/4"}
coordinates: [x]
bodies: {ball: {mass: m, position: [x, 0, 0]}}
potential: "k*x**2/2 + L*x"
"""


@pytest.fixture(scope="module")
def spare():
    from gacli.loader.loading import loads
    from gacli.mechanics.equations import derive

    return derive(loads(SPARE))


def test_c_sets_a_parameter_without_value_to_nan_and_counts_it(spare, tmp_path):
    source = write_c(spare, tmp_path)
    library = tmp_path / "libspare.so"
    built = subprocess.run([need("gcc"), *STRICT, "-shared", "-fPIC", str(source), "-o", str(library), "-lm"],
                           capture_output=True, text=True)
    assert built.returncode == 0 and not built.stderr, built.stderr
    lib = ctypes.CDLL(str(library))
    lib.spare_default_parameters.argtypes = [ctypes.POINTER(ctypes.c_double)]
    p = np.zeros(4)
    assert lib.spare_default_parameters(p.ctypes.data_as(ctypes.POINTER(ctypes.c_double))) == 2  # k, and w = f(k)
    assert p[0] == 2.0 and np.isnan(p[1]) and np.isnan(p[2]) and p[3] == 4.25


def test_octave_defaults_returns_the_files_values(spare, tmp_path):
    from conftest import require_tool

    octave = require_tool("octave")
    (tmp_path / "spare.yaml").write_text(SPARE)
    written = CliRunner().invoke(app, ["derive", str(tmp_path / "spare.yaml"), "--format", "octave",
                                       "--output", str(tmp_path)])
    assert written.exit_code == 0, written.output
    script = f"cd('{tmp_path}'); p = spare_defaults(); printf('%.17g\\n', p);"
    run = subprocess.run([octave, "--no-gui", "--no-window-system", "--quiet", "--eval", script],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    values = [float(v) for v in run.stdout.split()]
    assert values[0] == 2.0 and math.isnan(values[1]) and math.isnan(values[2]) and values[3] == 4.25
