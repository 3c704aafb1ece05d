"""--format fmu: the FMU checked by FMPy against the generated Python, and its reproducibility.

For every system in systems/, tests/cases/ and the tests' own (EXTRA), the
FMU passes ``fmpy.validate_fmu``, and its derivatives through FMPy's
low-level FMI 2.0 calls agree with the generated Python module's rhs (an
independent code path: Python printer, NumPy solve) at 20 seeded random
states. ``fmpy.simulate_fmu`` of the sphere on a turntable follows the
circle of eq. (14.30). The zip is byte-identical across runs and hash
seeds with the binary left out (the binary is whatever the compiler makes).
Tests skip without FMPy or gcc, and fail in CI, which installs both.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import subprocess
import sys
import zipfile

import numpy as np
import pytest

from conftest import ROOT, SYSTEMS, require_tool
from gacli.emit.fmu import emit_fmu, platform_folder
from gacli.emit.naming import layout
from gacli.mechanics.equations import derive
from gacli.loader.loading import load
from test_emit_python import EXTRA, extra, write_python

CASES_DIR = ROOT / "tests" / "cases"
CASES = ([f"systems/{p.stem}" for p in sorted(SYSTEMS.glob("*.yaml"))]
         + [f"tests/cases/{p.stem}" for p in sorted(CASES_DIR.glob("*.yaml"))] + sorted(EXTRA))
STATES = 20
RTOL = 1e-12
SPHERE = SYSTEMS / "sphere_on_turntable.yaml"


def binary_name(name):
    """Where the FMU's binary goes on this machine: binaries/linux64/NAME.so on the usual one."""
    folder, suffix = platform_folder()
    return f"binaries/{folder}/{name}{suffix}"


def need_fmpy():
    """FMPy; a skip without it, a failure in CI (the test extra installs it)."""
    try:
        import fmpy
    except ImportError:
        if os.environ.get("CI"):
            pytest.fail("fmpy is required in CI (pip install -e '.[test]' installs it)")
        pytest.skip("fmpy is not installed")
    return fmpy


def derivation(case):
    return extra(case) if case in EXTRA else derive(load(ROOT / f"{case}.yaml"))


@pytest.fixture
def compiler(monkeypatch):
    """gcc as the FMU's compiler, named through CC as a user would."""
    path = require_tool("gcc")
    monkeypatch.setenv("CC", path)
    return path


def write_fmu(d, directory, **options):
    ((name, data),) = emit_fmu(d, **options).items()
    path = directory / name
    path.write_bytes(data)
    return path


def validate(path):
    from fmpy.validation import validate_fmu

    return validate_fmu(str(path))


class Model:
    """The FMU loaded by FMPy's FMU2Model: parameters set in initialization mode, then x, r and t."""

    def __init__(self, path, unzipped):
        from fmpy import read_model_description
        from fmpy.fmi2 import FMU2Model

        self.md = read_model_description(str(path))
        self.fmu = FMU2Model(guid=self.md.guid, unzipDirectory=str(unzipped),
                             modelIdentifier=self.md.modelExchange.modelIdentifier, instanceName="test")
        self.fmu.instantiate()
        self.refs = {v.name: v.valueReference for v in self.md.modelVariables}

    def derivatives(self, lay, t, x, p, r):
        fmu = self.fmu
        fmu.reset()
        fmu.setupExperiment(startTime=t)
        fmu.enterInitializationMode()
        fmu.setReal([self.refs[n] for n in lay.parameters], list(p))
        fmu.exitInitializationMode()
        fmu.enterContinuousTimeMode()
        fmu.setTime(t)
        states = np.ascontiguousarray(x, dtype=float)
        fmu.setContinuousStates(states.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), len(states))
        fmu.setReal([self.refs[n] for n in lay.r], list(r))
        dx = np.full(len(states), np.nan)
        fmu.getDerivatives(dx.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), len(dx))
        by_name = fmu.getReal([self.refs[f"der({n})"] for n in lay.state])
        return dx, np.array(by_name)

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()


def random_states(lay, seed):
    """(t, x, p, r) in [0.3, 1.2], away from the angles where M of the rolling disk is singular."""
    rng = np.random.default_rng(seed)
    for _ in range(STATES):
        yield (rng.uniform(0.3, 1.2), rng.uniform(0.3, 1.2, len(lay.state)),
               rng.uniform(0.3, 1.2, len(lay.parameters)), rng.uniform(0.3, 1.2, len(lay.r)))


def close(a, b, rtol):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return np.linalg.norm(a - b) <= rtol * max(1.0, np.linalg.norm(b))


@pytest.mark.parametrize("case", CASES)
def test_fmu_derivatives_agree_with_the_generated_python(case, compiler, tmp_path):
    fmpy = need_fmpy()
    d = derivation(case)
    lay, module = layout(d), write_python(d, tmp_path)
    path = write_fmu(d, tmp_path)
    assert validate(path) == []
    model = Model(path, fmpy.extract(str(path), str(tmp_path / "unzipped")))
    try:
        for seed, (t, x, p, r) in enumerate(random_states(lay, 2000 + CASES.index(case))):
            dx, by_name = model.derivatives(lay, t, x, p, r)
            # A solve's forward error grows with cond(M): the tolerance of test_generated_numeric.
            tolerance = RTOL * max(1.0, np.linalg.cond(module.mass_matrix(t, x, p, r)) / 100)
            assert close(dx, module.rhs(t, x, p, r), tolerance), (seed, dx, module.rhs(t, x, p, r))
            assert np.array_equal(dx, by_name), seed  # fmi2GetReal of der(x) is the same rhs
    finally:
        model.close()


def test_simulate_fmu_moves_the_sphere_on_the_circle_of_14_30(compiler, tmp_path):
    """Ω constant, no force: (ẋ, ẏ) turns at ω = 2Ω/7, the centre on a circle of radius 7|v₀|/(2Ω)."""
    fmpy = need_fmpy()
    path = write_fmu(derivation("systems/sphere_on_turntable"), tmp_path)
    omega_plane, z0, w0 = 3.0, 0.2 - 0.1j, 0.05 + 0.08j
    start = {"Omega": omega_plane, "x": z0.real, "y": z0.imag, "dot(x)": w0.real, "dot(y)": w0.imag,
             "dot(q_z)": 1.5}
    result = fmpy.simulate_fmu(str(path), stop_time=10.0, output_interval=0.05, relative_tolerance=1e-10,
                               start_values=start, output=["x", "y", "dot(x)", "dot(y)", "dot(q_z)"])
    times, z = result["time"], result["x"] + 1j * result["y"]
    assert times[-1] == pytest.approx(10.0) and len(times) > 100
    omega = 2 * omega_plane / 7
    centre, radius = z0 + 1j * w0 / omega, 7 * abs(w0) / (2 * omega_plane)
    assert np.max(np.abs(np.abs(z - centre) - radius)) < 1e-7
    expected = z0 + w0 * (np.exp(1j * omega * times) - 1) / (1j * omega)
    assert np.max(np.abs(z - expected)) < 1e-7
    assert np.ptp(np.angle(z - centre)) > 3  # it went round, not only a few degrees
    np.testing.assert_allclose(result["dot(q_z)"], 1.5, rtol=1e-9)  # M_z = 0: the spin keeps


# -- modelDescription.xml ------------------------------------------------------------

def test_variables_carry_the_files_names_descriptions_units_and_values(tmp_path):
    fmpy = need_fmpy()
    d = derivation("systems/sphere_on_turntable")
    md = fmpy.read_model_description(str(write_fmu(d, tmp_path, binary=False)))
    by_name = {v.name: v for v in md.modelVariables}
    lay = layout(d)
    assert [v.name for v in md.modelVariables] == [
        *lay.state, *(f"der({n})" for n in lay.state), *lay.parameters, *lay.r]
    assert [v.valueReference for v in md.modelVariables] == list(range(len(md.modelVariables)))
    for parameter in d.system.parameters:
        v = by_name[parameter.name]
        assert (v.causality, v.variability, v.initial) == ("parameter", "fixed", "exact")
        assert float(v.start) == lay.defaults[parameter.name]
        assert v.description.startswith(parameter.description) and (v.unit or "") == parameter.unit
    assert by_name["M"].unit == "kg" and by_name["a"].description == "radius"
    assert "2*M*a**2/5" in by_name["I"].description  # the file's formula, frozen at the start values
    assert by_name["x"].description == "centre of mass, inertial x" and by_name["x"].causality == "output"
    assert by_name["Omega"].causality == "input" and by_name["Omega"].description == "angular rate of the plane"
    assert by_name["dot(Omega)"].causality == "input" and "rate of Omega" in by_name["dot(Omega)"].description
    assert [u.variable.name for u in md.derivatives] == [f"der({n})" for n in lay.state]
    assert all(by_name[f"der({n})"].derivative is by_name[n] for n in lay.state)
    assert md.modelExchange.modelIdentifier == "sphere_on_turntable" and md.coSimulation is None
    assert md.guid.startswith("{") and len(md.guid) == 38


def test_a_parameter_without_a_value_starts_at_0_and_says_so(tmp_path):
    fmpy = need_fmpy()
    md = fmpy.read_model_description(str(write_fmu(extra("shaken"), tmp_path, binary=False)))
    k = next(v for v in md.modelVariables if v.name == "k")
    assert float(k.start) == 0.0 and "no value in the system file" in k.description
    assert validate(tmp_path / "shaken.fmu") == []


def test_the_guid_follows_the_system_and_the_wrapper_checks_it(compiler, tmp_path):
    fmpy = need_fmpy()
    from fmpy.fmi2 import FMU2Model

    sphere, cylinder = (fmpy.read_model_description(str(write_fmu(derivation(f"systems/{n}"), tmp_path)))
                        for n in ("sphere_on_turntable", "cylinder_in_cylinder"))
    assert sphere.guid != cylinder.guid
    unzipped = fmpy.extract(str(tmp_path / "sphere_on_turntable.fmu"), str(tmp_path / "u"))
    wrong = FMU2Model(guid=cylinder.guid, unzipDirectory=unzipped, modelIdentifier="sphere_on_turntable",
                      instanceName="wrong")
    with pytest.raises(Exception, match="(?i)instantiate"):
        wrong.instantiate()


# -- the C wrapper ---------------------------------------------------------------------------

@pytest.mark.parametrize("cc", ["gcc", "clang"])
def test_wrapper_compiles_against_the_official_fmi2_headers(cc, tmp_path):
    """FMPy ships the Modelica Association's fmi2Functions.h: included first, it checks our signatures."""
    fmpy = need_fmpy()
    tool = require_tool(cc)
    with zipfile.ZipFile(write_fmu(extra("shaken"), tmp_path, binary=False)) as archive:
        archive.extractall(tmp_path / "fmu")
    headers = os.path.join(os.path.dirname(fmpy.__file__), "c-code")
    sources = tmp_path / "fmu" / "sources"
    for extra_flags in ([], ["-I", headers, "-include", "fmi2Functions.h"]):
        command = [tool, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", *extra_flags, "-c",
                   "shaken_fmu.c", "-o", "wrapper.o"]
        result = subprocess.run(command, cwd=sources, capture_output=True, text=True)
        assert result.returncode == 0 and not result.stderr, result.stderr


def test_function_prefix_renames_the_exports_for_static_linking(tmp_path):
    tool = require_tool("gcc")
    with zipfile.ZipFile(write_fmu(extra("bare"), tmp_path, binary=False)) as archive:
        archive.extractall(tmp_path / "fmu")
    library = tmp_path / "bare_prefixed.so"
    subprocess.run([tool, "-std=c99", "-shared", "-fPIC", "-DFMI2_FUNCTION_PREFIX=bare_", "bare_fmu.c", "bare.c",
                    "-o", str(library), "-lm"], cwd=tmp_path / "fmu" / "sources", check=True)
    lib = ctypes.CDLL(str(library))
    assert hasattr(lib, "bare_fmi2GetDerivatives") and not hasattr(lib, "fmi2GetDerivatives")


# -- reproducibility -----------------------------------------------------------------------

def _members(path):
    with zipfile.ZipFile(path) as archive:
        return [(i.filename, i.date_time, i.external_attr >> 16, i.create_system, i.compress_type,
                 archive.read(i.filename)) for i in archive.infolist()]


def _cli_fmu(system, out, seed, **env):
    environment = {**os.environ, "PYTHONHASHSEED": seed, "PYTHONPATH": str(ROOT), **env}
    result = subprocess.run([sys.executable, "-m", "gacli", "derive", str(system), "--format", "fmu",
                             "--output", str(out)], env=environment, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return out


def test_the_fmu_is_the_same_zip_under_any_hash_seed_but_for_its_binary(compiler, tmp_path):
    """Names, order, times, permissions and bytes of every member but the compiler's binary."""
    awkward = tmp_path / "shaken.yaml"
    awkward.write_text(EXTRA["shaken"], encoding="utf-8")
    for system in (SPHERE, awkward):
        a, b = (_members(_cli_fmu(system, tmp_path / f"{system.stem}_{seed}.fmu", seed, CC=compiler))
                for seed in ("1", "4242"))
        name = system.stem
        assert [m[0] for m in a] == ["modelDescription.xml", f"sources/{name}.c", f"sources/{name}.h",
                                     f"sources/{name}_fmu.c", binary_name(name)]
        assert [m[:5] for m in a] == [m[:5] for m in b]
        assert [m[5] for m in a[:-1]] == [m[5] for m in b[:-1]]
        assert {m[1] for m in a} == {(1980, 1, 1, 0, 0, 0)} and {m[3] for m in a} == {3}
        assert [m[2] for m in a] == [0o100644] * 4 + [0o100755]


_SOURCE_ONLY = """
import hashlib, sys
from gacli.emit.fmu import emit_fmu, platform_folder
from gacli.mechanics.equations import derive
from gacli.loader.loading import load
(data,) = emit_fmu(derive(load(sys.argv[1])), binary=False).values()
print(hashlib.sha256(data).hexdigest())
"""


def test_a_source_fmu_is_byte_identical_under_any_hash_seed(tmp_path):
    digests = set()
    for seed in ("0", "1", "4242"):
        environment = {**os.environ, "PYTHONHASHSEED": seed, "PYTHONPATH": str(ROOT)}
        result = subprocess.run([sys.executable, "-c", _SOURCE_ONLY, str(SPHERE)], env=environment,
                                capture_output=True, text=True, check=True)
        digests.add(result.stdout.strip())
    assert len(digests) == 1
    in_process = next(iter(emit_fmu(derivation("systems/sphere_on_turntable"), binary=False).values()))
    assert digests == {hashlib.sha256(in_process).hexdigest()}


def test_a_source_fmu_is_the_fmu_without_its_binary(compiler, tmp_path):
    d = derivation("systems/cylinder_in_cylinder")
    (tmp_path / "with").mkdir()
    (tmp_path / "without").mkdir()
    whole = _members(write_fmu(d, tmp_path / "with"))
    sources = _members(write_fmu(d, tmp_path / "without", binary=False))
    assert whole[:-1] == sources and whole[-1][0] == binary_name("cylinder_in_cylinder")


# -- the command line -----------------------------------------------------------------------

def _run(*args):
    from typer.testing import CliRunner

    from gacli.cli import app

    return CliRunner().invoke(app, ["derive", str(SPHERE), "--format", "fmu", *args])


def test_an_fmu_is_not_printed_to_stdout():
    result = _run()
    assert result.exit_code == 2 and "--output NAME.fmu" in result.output and "Traceback" not in result.output


def test_reactions_do_not_go_into_an_fmu(tmp_path):
    result = _run("--reactions", "--output", str(tmp_path / "s.fmu"))
    assert result.exit_code == 2 and "--reactions" in result.output


def test_the_cli_writes_the_fmu_into_a_directory(compiler, tmp_path):
    result = _run("--output", str(tmp_path))
    assert result.exit_code == 0, result.output
    assert (tmp_path / "sphere_on_turntable.fmu").read_bytes()[:2] == b"PK"


def test_a_compiler_failure_is_one_error_and_leaves_the_target_untouched(monkeypatch, tmp_path):
    monkeypatch.setenv("CC", require_tool("false"))
    target = tmp_path / "s.fmu"
    target.write_bytes(b"precious")
    result = _run("--output", str(target))
    assert result.exit_code == 1
    assert result.stderr.startswith("error: the C compiler failed to build the FMU's binary")
    assert len(result.stderr.strip().splitlines()) == 1 and "Traceback" not in result.output
    assert target.read_bytes() == b"precious"


def test_without_a_compiler_the_fmu_carries_sources_and_says_so(monkeypatch, tmp_path):
    monkeypatch.delenv("CC", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    result = _run("--output", str(tmp_path / "s.fmu"))
    assert result.exit_code == 0, result.output
    assert "no C compiler found" in result.stderr and "carries its C sources only" in result.stderr
    with zipfile.ZipFile(tmp_path / "s.fmu") as archive:
        assert not any(n.startswith("binaries/") for n in archive.namelist())
    need_fmpy()
    assert validate(tmp_path / "s.fmu") == []


def test_readme_fmu_example_runs(compiler, tmp_path):
    """The README's commands (the Python kept as docs/fmu_example.py): the sphere ends on eq. (14.30)'s circle."""
    import cmath
    import re

    need_fmpy()
    readme = (ROOT / "README.md").read_text()
    example = (ROOT / "docs" / "fmu_example.py").read_text()
    assert "gacli derive systems/sphere_on_turntable.yaml --format fmu --output sphere.fmu" in readme
    assert example.strip() in readme
    _cli_fmu(SPHERE, tmp_path / "sphere.fmu", "0")
    (tmp_path / "example.py").write_text(example)
    out = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, capture_output=True, text=True, check=True)
    x, y = map(float, re.fullmatch(r"x = (\S+), y = (\S+)\n", out.stdout).groups())
    omega = 2 * 2.0 / 7  # (dot x, dot y) turns at 2 Omega / 7 from (0.1, 0)
    z = 0.1 * (cmath.exp(1j * omega * 5.0) - 1) / (1j * omega)
    assert abs(x - z.real) <= 1e-4 and abs(y - z.imag) <= 1e-4


def test_a_source_fmu_builds_with_fmpy_and_simulates(tmp_path):
    """FMPy's own build (CMake, its copy of the official headers) turns the source FMU into a working one."""
    fmpy = need_fmpy()
    from fmpy.build import build_platform_binary

    require_tool("gcc")
    unzipped = tmp_path / "sphere"
    with zipfile.ZipFile(write_fmu(derivation("systems/sphere_on_turntable"), tmp_path, binary=False)) as archive:
        archive.extractall(unzipped)
    (tmp_path / "build").mkdir()
    build_platform_binary(str(unzipped), build_dir=str(tmp_path / "build"))
    assert (unzipped / binary_name("sphere_on_turntable")).is_file()
    result = fmpy.simulate_fmu(str(unzipped), stop_time=4.0, relative_tolerance=1e-10,
                               start_values={"Omega": 2.0, "dot(y)": 0.1})
    omega = 2 * 2.0 / 7
    radius = 7 * 0.1 / (2 * 2.0)
    centre = 1j * 0.1j / omega  # z0 + i w0 / omega with z0 = 0, w0 = 0.1i
    assert np.max(np.abs(np.abs(result["x"] + 1j * result["y"] - centre) - radius)) < 1e-7


def test_misuse_and_a_singular_mass_matrix_are_fmi2_errors_with_a_message(compiler, tmp_path, capfd):
    fmpy = need_fmpy()
    from fmpy.fmi1 import FMICallException

    d = derivation("systems/sphere_on_turntable")
    path = write_fmu(d, tmp_path)
    model = Model(path, fmpy.extract(str(path), str(tmp_path / "u")))
    refs, fmu = model.refs, model.fmu
    try:
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        fmu.setReal([refs["M"], refs["I"]], [0.0, 0.0])  # no mass, no inertia: M is zero
        fmu.exitInitializationMode()
        with pytest.raises(FMICallException):
            fmu.setReal([refs["a"]], [0.2])
        with pytest.raises(FMICallException):
            fmu.setReal([refs["der(x)"]], [1.0])
        dx = np.zeros(len(layout(d).state))
        with pytest.raises(FMICallException):
            fmu.getDerivatives(dx.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), len(dx))
        log = capfd.readouterr().out
        assert "parameters are fixed" in log and "only states, parameters and inputs" in log
        assert "mass matrix is not positive definite at t = 0 (pivot 1)" in log
    finally:
        model.close()
