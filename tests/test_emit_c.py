"""The generated C: strict compilation with gcc and clang, the header, rhs's return code.

The helpers here (``compile_c``, ``CLibrary``) are also used by
test_generated_numeric.py. C tests skip when the compiler is missing.
"""

from __future__ import annotations

import ctypes
import re
import subprocess

import numpy as np
import pytest

from conftest import SYSTEMS, derived
from gacli.emit.c import emit_c
from gacli.emit.naming import layout
from gacli.mechanics.equations import derive
from test_emit_python import EXTRA, extra

ALL = sorted(p.stem for p in SYSTEMS.glob("*.yaml"))
COMPILERS = ("gcc", "clang")
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]

_DOUBLES = ctypes.POINTER(ctypes.c_double)


def need(compiler: str) -> str:
    """The compiler's path; a skip without it, a failure in CI (which installs both)."""
    from conftest import require_tool

    return require_tool(compiler)


def write_c(derivation, directory):
    directory.mkdir(parents=True, exist_ok=True)
    for name, text in emit_c(derivation).items():
        (directory / name).write_text(text, encoding="utf-8")
    return directory / f"{derivation.system.name}.c"


def compile_c(derivation, directory, compiler="gcc"):
    """Write the C files under ``directory`` and build a shared library with the strict flags."""
    source = write_c(derivation, directory)
    library = directory / f"lib{derivation.system.name}_{compiler}.so"
    command = [need(compiler), *STRICT, "-O2", "-shared", "-fPIC", str(source), "-o", str(library), "-lm"]
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 0 and not result.stderr, result.stderr
    return library


class CLibrary:
    """ctypes access to <name>_mass_matrix, _forcing and _rhs."""

    def __init__(self, path, derivation):
        self.lib = ctypes.CDLL(str(path))
        self.name, self.k = derivation.system.name, derivation.k
        for suffix, restype in (("mass_matrix", None), ("forcing", None), ("rhs", ctypes.c_int)):
            function = getattr(self.lib, f"{self.name}_{suffix}")
            function.argtypes = [ctypes.c_double, _DOUBLES, _DOUBLES, _DOUBLES, _DOUBLES]
            function.restype = restype

    def _call(self, suffix, size, t, x, p, r):
        out = np.full(size, np.nan)
        arrays = [np.ascontiguousarray(v, dtype=float) for v in (x, p)]
        r_array = np.ascontiguousarray(r, dtype=float) if len(r) else None
        status = getattr(self.lib, f"{self.name}_{suffix}")(
            t, *(_pointer(a) for a in arrays), _pointer(r_array), _pointer(out))
        return out, status

    def mass_matrix(self, t, x, p, r=()):
        return self._call("mass_matrix", self.k * self.k, t, x, p, r)[0].reshape(self.k, self.k)

    def forcing(self, t, x, p, r=()):
        return self._call("forcing", self.k, t, x, p, r)[0]

    def rhs(self, t, x, p, r=()):
        """(xdot, status)."""
        return self._call("rhs", len(x), t, x, p, r)


def _pointer(array):
    return None if array is None else array.ctypes.data_as(_DOUBLES)


# -- compilation ---------------------------------------------------------------------

@pytest.mark.parametrize("compiler", COMPILERS)
@pytest.mark.parametrize("name", ALL)
def test_compiles_cleanly_under_strict_flags(name, compiler, tmp_path):
    compile_c(derived(name), tmp_path, compiler)


@pytest.mark.parametrize("compiler", COMPILERS)
@pytest.mark.parametrize("name", [n for n in ALL if n not in ("whipple_bicycle", "toroidal_bicycle")])
def test_reactions_compile_cleanly_under_strict_flags(name, compiler, tmp_path):
    """With --reactions too: a system without constraints leaves lambda unwritten, and says so."""
    d = derived(name)
    (tmp_path / f"{name}.h").write_text(emit_c(d, reactions=True)[f"{name}.h"], encoding="utf-8")
    source = tmp_path / f"{name}.c"
    source.write_text(emit_c(d, reactions=True)[f"{name}.c"], encoding="utf-8")
    command = [need(compiler), *STRICT, "-Wunused", "-c", str(source), "-o", str(tmp_path / "out.o")]
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 0 and not result.stderr, result.stderr


@pytest.mark.parametrize("compiler", COMPILERS)
@pytest.mark.parametrize("name", sorted(EXTRA))
def test_the_tests_own_systems_compile(name, compiler, tmp_path):
    compile_c(extra(name), tmp_path, compiler)


@pytest.mark.parametrize("compiler", ["g++", "clang++"])
def test_header_is_usable_from_cpp(compiler, tmp_path):
    write_c(derived("sphere_on_turntable"), tmp_path)
    user = tmp_path / "user.cpp"
    user.write_text('#include "sphere_on_turntable.h"\n'
                    "int main() { double x[SPHERE_ON_TURNTABLE_NX] = {0}; (void)x; return 0; }\n")
    result = subprocess.run([need(compiler), "-std=c++11", "-Wall", "-Wextra", "-Werror", "-pedantic",
                             "-fsyntax-only", str(user)], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr


# -- the files -------------------------------------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_header_defines_sizes_and_one_index_per_entry(name):
    d = derived(name)
    lay = layout(d)
    header = emit_c(d)[f"{name}.h"]
    defines = dict(re.findall(r"^#define (\w+) +(\d+)", header, flags=re.M))
    prefix = name.upper()
    assert defines[f"{prefix}_NX"] == str(len(lay.state))
    assert defines[f"{prefix}_NU"] == str(d.k)
    assert defines[f"{prefix}_NP"] == str(len(lay.parameters))
    assert defines[f"{prefix}_NR"] == str(len(lay.r))
    for entry in lay.entries:
        assert defines[entry.macro] == str(entry.index)
    assert len(defines) == 4 + len(lay.entries)
    assert header.count(f"#ifndef {prefix}_H") == 1 and 'extern "C"' in header


@pytest.mark.parametrize("name", ALL)
def test_source_uses_only_math_h_and_no_globals(name):
    source = emit_c(derived(name))[f"{name}.c"]
    assert re.findall(r"#include .*", source) == ["#include <math.h>", f'#include "{name}.h"']
    assert not re.search(r"\b(malloc|calloc|free|M_PI|M_E)\b", source)
    top_level = [line for line in source.splitlines() if line and not line[0].isspace()]
    allowed = ("/*", "#include", "{", "}", f"void {name}_", f"int {name}_", f"static int {name}_cholesky_solve(",
               f"static int {name}_solved(", f"static int {name}_finite(", f"static double {name}_nan(")
    assert all(line.startswith(allowed) for line in top_level), top_level


# -- rhs's return code -------------------------------------------------------------------

@pytest.fixture(scope="module")
def library(tmp_path_factory):
    cache = {}

    def get(name, compiler="gcc"):
        if (name, compiler) not in cache:
            d = derived(name)
            path = compile_c(d, tmp_path_factory.mktemp(f"{name}_{compiler}"), compiler)
            cache[name, compiler] = CLibrary(path, d)
        return cache[name, compiler]

    return get


@pytest.mark.parametrize("name", ALL)
def test_rhs_returns_nonzero_when_mass_matrix_is_not_positive_definite(name, library, rng):
    lib, lay = library(name), layout(derived(name))
    x = rng.uniform(0.3, 1.7, len(lay.state))
    p, r = rng.uniform(0.3, 1.7, len(lay.parameters)), rng.uniform(0.3, 1.7, len(lay.r))
    assert lib.rhs(0.2, x, p, r)[1] == 0
    assert lib.rhs(0.2, x, -p, r)[1] != 0  # every mass and moment negative: M < 0


def test_rhs_returns_the_number_of_the_failing_pivot(library):
    lib = library("rigid_body")
    x, r = np.full(9, 0.5), np.zeros(6)
    assert lib.rhs(0.0, x, [2.0, 1.0, 2.0, 3.0], r)[1] == 0
    assert lib.rhs(0.0, x, [2.0, 1.0, 0.0, 3.0], r)[1] == 5  # I_y: pivot 5 of 6
    assert lib.rhs(0.0, x, [-2.0, 1.0, 2.0, 3.0], r)[1] == 1
    xdot, status = lib.rhs(0.0, x, [2.0, 1.0, 2.0, np.nan], r)
    assert status == -1 and np.isnan(xdot).all()  # not finite: undefined before any pivot (docs/generated-code.md)


def test_r_may_be_null_without_inputs(library):
    lib = library("cylinder_in_cylinder")
    xdot, status = lib.rhs(0.0, [0.3, 0.0, 1.0], [1.0, 9.81, 0.1, 0.5, 0.4], ())
    assert status == 0
    np.testing.assert_allclose(xdot, [1.0, 4.0, -9.81 * np.sin(0.3) / (1.5 * 0.4)], rtol=1e-14)


def test_readme_main_compiles_and_runs(tmp_path):
    """The main() shown in the README (kept as docs/sphere_main.c) builds against the generated code."""
    import subprocess

    from conftest import ROOT, require_tool
    from gacli.cli import app
    from typer.testing import CliRunner

    cc = require_tool("gcc")
    main = (ROOT / "docs" / "sphere_main.c").read_text()
    assert main.strip() in (ROOT / "README.md").read_text()
    result = CliRunner().invoke(app, ["derive", str(ROOT / "systems" / "sphere_on_turntable.yaml"),
                                      "--format", "c", "--output", f"{tmp_path}/build/"])
    assert result.exit_code == 0, result.output
    (tmp_path / "main.c").write_text(main)
    subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-Ibuild", "main.c",
                    "build/sphere_on_turntable.c", "-lm", "-o", "sphere"], cwd=tmp_path, check=True)
    out = subprocess.run([str(tmp_path / "sphere")], capture_output=True, text=True, check=True).stdout
    assert out.startswith("x = ")


MACRO_NAMED = """\
gacli: 1
name: macro_named
parameters: [MAXFLOAT, HUGE, M_PIl, M_El, FP_INT_UPWARD, FP_NAN, sinf, cospi, fminimum, float, len, I]
coordinates: [x]
bodies: {b: {mass: MAXFLOAT + len, position: [x, 0, 0]}}
potential: HUGE*x**2 + M_PIl*x + FP_INT_UPWARD*M_El*I*x + FP_NAN*sinf*cospi*fminimum*float*x
"""


@pytest.mark.parametrize("flags", [["-std=c99"], ["-std=gnu11", "-D_GNU_SOURCE"], ["-std=c2x", "-D_GNU_SOURCE"]])
@pytest.mark.parametrize("compiler", COMPILERS)
def test_names_that_math_h_defines_are_renamed(compiler, flags, tmp_path):
    """<math.h> under _GNU_SOURCE or C23 defines HUGE, MAXFLOAT, M_PIl, FP_INT_UPWARD... as macros."""
    from gacli.loader.loading import loads

    d = derive(loads(MACRO_NAMED))
    source = write_c(d, tmp_path)
    command = [need(compiler), *flags, "-Wall", "-Wextra", "-Werror", "-pedantic", "-c", str(source),
               "-o", str(tmp_path / "out.o")]
    result = subprocess.run(command, capture_output=True, text=True)
    assert result.returncode == 0 and not result.stderr, result.stderr
    header = (tmp_path / "macro_named.h").read_text()
    assert "MACRO_NAMED_P_M_PIL" in header and "MACRO_NAMED_P_HUGE" in header  # the file's own names


def test_math_h_names():
    from gacli.emit.math_h import is_math_h_name

    for name in ("HUGE", "MAXFLOAT", "M_PIl", "FP_INT_UPWARD", "sinf", "cosf128", "sinpi", "sinpif", "fabsl"):
        assert is_math_h_name(name), name
    for name in ("x", "theta", "m_c", "phi_L", "yaw", "spin", "lean", "Omega"):
        assert not is_math_h_name(name), name


@pytest.mark.parametrize("name", ["chaplygin_sleigh", "four_bar_linkage", "rolling_disk"])
def test_the_header_sizes_lambda_as_many_as_the_python_reactions_return(name):
    """A caller must allocate lambda: NAME_NLAMBDA, the count Python's reactions() returns."""
    from gacli.emit.python import emit_python

    d = derived(name)
    lay = layout(d)
    header = emit_c(d, reactions=True)[f"{name}.h"]
    size = int(re.search(rf"#define {lay.prefix}_NLAMBDA (\d+)", header)[1])
    namespace: dict = {}
    (source,) = emit_python(d, reactions=True).values()
    exec(source, namespace)  # noqa: S102 - our own generated code
    p = [namespace["DEFAULTS"].get(n, 0.7) for n in namespace["PARAMETERS"]]
    x = np.linspace(0.2, 0.6, len(namespace["STATE"]))
    assert len(namespace["reactions"](0.0, x, p, [0.1] * len(namespace["INPUTS"]))) == size


def test_a_default_written_with_eulers_number_is_commented_in_the_file_s_grammar(tmp_path):
    """'/* E */' beside m = exp(1) read as the parameter E."""
    from gacli.loader.loading import loads

    system = loads("gacli: 1\nname: s\nparameters: {m: {value: exp(1)}, E: 3}\ncoordinates: [x]\n"
                   "bodies: {b: {mass: m, position: [x, 0]}}\npotential: E*x**2\n")
    source = emit_c(derive(system))["s.c"]
    assert "/* exp(1) */" in source and "/* E */" not in source
