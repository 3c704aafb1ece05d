"""Literals and temporaries of generated code (issue 33, items 5 and 6).

JAX in its default 32-bit mode takes a Python int as an int32: an integer
literal beyond 2**31 raised OverflowError under ``jax.jit``. Such literals are
printed as floats; the module is run under jit in both modes and compared with
the NumPy module. Temporaries that no result reads after CSE are removed (C
refuses them with ``-Werror=unused-variable``).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp

from gacli.api import emit
from gacli.emit.assembly import live_block
from gacli.emit.printers import Block
from gacli.loader.loading import load
from gacli.mechanics.equations import derive

ROOT = Path(__file__).resolve().parent.parent
TEXT = (ROOT / "systems" / "cylinder_in_cylinder.yaml").read_text(encoding="utf-8")
WIDE = 3_000_000_001  # past int32


def _system(tmp_path: Path, force: str) -> Path:
    path = tmp_path / "wide.yaml"
    path.write_text(TEXT.replace("  c: {description", "  k: {value: 1e-9}\n  c: {description").replace(
        "potential: -M*g*c*cos(theta)",
        f"potential: -M*g*c*cos(theta)\nloads:\n  - {{force: [{force}, 0], at: cylinder}}"), encoding="utf-8")
    return path


RUN = """
import importlib.util, json, sys
import jax, numpy
if sys.argv[3] == "64":
    jax.config.update("jax_enable_x64", True)
def module(path):
    spec = importlib.util.spec_from_file_location(path.rsplit("/", 1)[-1][:-3], path)
    m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m); return m
j, n = module(sys.argv[1]), module(sys.argv[2])
x = [0.3, 0.1, 2.0]
p = [n.DEFAULTS[name] for name in n.PARAMETERS]
print(json.dumps({"jax": [float(v) for v in jax.jit(j.rhs)(0.0, numpy.array(x), numpy.array(p))],
                  "numpy": [float(v) for v in n.rhs(0.0, x, p)]}))
"""


@pytest.mark.parametrize("bits", ["32", "64"])
def test_jax_takes_integers_past_int32_under_jit(tmp_path, bits):
    pytest.importorskip("jax")
    derivation = derive(load(_system(tmp_path, f"-{WIDE}*k*dot(theta)")))
    paths = []
    for fmt in ("jax", "python"):
        (name, text), = emit(derivation, fmt).items()
        (tmp_path / name).write_text(text, encoding="utf-8")
        paths.append(str(tmp_path / name))
    jax_text = Path(paths[0]).read_text()
    assert f"{float(WIDE)!r}" in jax_text and not re.search(rf"\b{WIDE}\b(?!\.)", jax_text)
    env = {k: v for k, v in os.environ.items() if k != "JAX_ENABLE_X64"}
    env["JAX_PLATFORMS"] = "cpu"
    done = subprocess.run([sys.executable, "-c", RUN, *paths, bits], capture_output=True, text=True,
                          timeout=300, env=env)
    assert done.returncode == 0, done.stderr[-3000:]
    values = json.loads(done.stdout)
    tolerance = 1e-5 if bits == "32" else 1e-12
    assert values["jax"] == pytest.approx(values["numpy"], rel=tolerance, abs=tolerance)


def test_a_dead_temporary_is_removed_with_what_only_it_read():
    theta, a, b, g = sp.symbols("theta a b g")
    block = Block((("_c0", "sin(theta)"), ("_c1", "a - b"), ("_c2", "-_c1"), ("_c3", "cos(_c0)"), ("_c4", "g*_c3")),
                  ("2*_c4", "_c0"), frozenset({theta, a, b, g}))
    live = live_block(block, {theta: "theta", a: "a", b: "b", g: "g"})
    assert live.temporaries == (("_c0", "sin(theta)"), ("_c3", "cos(_c0)"), ("_c4", "g*_c3"))
    assert live.symbols == {theta, g}
    assert live.results == block.results
    assert live_block(live, {}) is live


@pytest.mark.parametrize("fmt", ["c", "python", "octave", "jax"])
@pytest.mark.parametrize("system", ["cylinder_in_cylinder", "rolling_disk", "sphere_on_turntable"])
def test_no_generated_temporary_is_dead(fmt, system):
    """Every temporary assigned is read later in the same function, for every target."""
    files = emit(derive(load(ROOT / "systems" / f"{system}.yaml")), fmt, **({"reactions": True} if fmt in ("c", "python") else {}))
    for text in files.values():
        for name in set(re.findall(r"\b(_c\d+|_t\d+|t_\d+|[A-Za-z]*_c\d+)\s*=(?!=)", text)):
            assignments = len(re.findall(rf"\b{re.escape(name)}\s*=(?!=)", text))
            uses = len(re.findall(rf"\b{re.escape(name)}\b", text))
            assert uses > assignments, (system, fmt, name)
