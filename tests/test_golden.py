"""Generated code byte for byte: golden files, and the same bytes under any hash seed.

The golden files are tests/golden/cylinder_in_cylinder.{py,h,c}, its
Octave function files cylinder_in_cylinder_*.m (five) and its JAX module
cylinder_in_cylinder_jax.py, generated
from systems/cylinder_in_cylinder.yaml; they are small on purpose, to be
read in review. After a deliberate change to the emitters, regenerate them
with

    GACLI_UPDATE_GOLDEN=1 python -m pytest tests/test_golden.py

and review the diff. (An environment variable rather than a pytest option:
an option would have to be declared in conftest.py.)
"""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys

import pytest

from conftest import ROOT, SYSTEMS, derived
from gacli.emit import EMITTERS

GOLDEN = ROOT / "tests" / "golden"
GOLDEN_SYSTEM = "cylinder_in_cylinder"
UPDATE = os.environ.get("GACLI_UPDATE_GOLDEN") == "1"
FORMATS = ("python", "c", "octave", "jax")
FILES_PER_SYSTEM = 1 + 2 + 5 + 1


def generated(name: str) -> dict[str, str]:
    files = {}
    for fmt in FORMATS:
        files.update(EMITTERS[fmt](derived(name)))
    return files


@pytest.mark.parametrize("file_name", [
    f"{GOLDEN_SYSTEM}{suffix}" for suffix in (
        ".py", ".h", ".c", "_rhs.m", "_mass_matrix.m", "_forcing.m", "_indices.m", "_defaults.m", "_jax.py")])
def test_matches_golden_file(file_name):
    text = generated(GOLDEN_SYSTEM)[file_name]
    path = GOLDEN / file_name
    if UPDATE:
        GOLDEN.mkdir(exist_ok=True)
        path.write_bytes(text.encode("utf-8"))
    expected = path.read_bytes().decode("utf-8")
    assert text == expected, f"{file_name} differs from its golden file; see this module's docstring"


def test_output_holds_no_absolute_path():
    for text in generated(GOLDEN_SYSTEM).values():
        assert str(ROOT) not in text and str(SYSTEMS) not in text


# Emit every system in a fresh interpreter; print file name → sha256.
_SCRIPT = """
import hashlib, json, pathlib
from gacli.emit import EMITTERS
from gacli.mechanics.equations import derive
from gacli.loader.loading import load
out = {}
for path in sorted(pathlib.Path(%r).glob("*.yaml")):
    d = derive(load(path))
    for fmt in %r:
        for name, text in EMITTERS[fmt](d).items():
            out[name] = hashlib.sha256(text.encode("utf-8")).hexdigest()
print(json.dumps(out, sort_keys=True))
"""


def _hashes_under_seed(seed: str) -> dict[str, str]:
    env = {**os.environ, "PYTHONHASHSEED": seed}
    result = subprocess.run([sys.executable, "-c", _SCRIPT % (str(SYSTEMS), FORMATS)],
                            capture_output=True, text=True, env=env, cwd=ROOT, check=False)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_same_bytes_under_any_hash_seed():
    first, second = _hashes_under_seed("0"), _hashes_under_seed("12345")
    assert first == second
    here = {name: hashlib.sha256(text.encode("utf-8")).hexdigest()
            for p in sorted(SYSTEMS.glob("*.yaml")) for name, text in generated(p.stem).items()}
    assert here == first
    assert len(first) == FILES_PER_SYSTEM * len(list(SYSTEMS.glob("*.yaml")))
