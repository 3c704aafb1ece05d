"""The Python API (gacli.load, gacli.derive, gacli.emit) as a notebook uses it."""

from __future__ import annotations

import subprocess
import sys

from conftest import SYSTEMS

_SCRIPT = """
import gacli
d = gacli.derive(gacli.load(%r))
first = gacli.emit(d, "python")
import gacli.emit.c  # binds gacli.emit to the subpackage
again = gacli.emit(d, "python")
print(first == again, sorted(gacli.emit(d, "c")))
"""


def test_emit_can_be_called_again_after_its_package_is_imported():
    # A fresh interpreter: the name is rebound only on the first import of the package.
    path = str(SYSTEMS / "particle_in_plane.yaml")
    done = subprocess.run([sys.executable, "-c", _SCRIPT % path], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["True", "['particle_in_plane.c',", "'particle_in_plane.h']"]


def test_derive_and_emit_take_a_path_or_a_system_as_a_notebook_writes_them():
    # gacli.derive("f.yaml") and gacli.emit(gacli.load(f), "c") ended in AttributeErrors.
    from pathlib import Path

    import pytest

    import gacli

    path = Path(__file__).resolve().parent.parent / "systems" / "particle_in_plane.yaml"
    by_path, by_system = gacli.derive(str(path)), gacli.derive(gacli.load(path))
    assert by_path.mass_matrix == by_system.mass_matrix
    assert gacli.emit(gacli.load(path), "c") == gacli.emit(by_system, "c") == gacli.emit(path, "c")
    with pytest.raises(TypeError, match="a System \\(gacli.load\\) or a path; got int"):
        gacli.emit(3, "c")


def test_derive_from_a_path_reports_its_steps_to_progress():
    import gacli

    seen: list[str] = []
    gacli.derive(str(SYSTEMS / "rolling_disk.yaml"), progress=seen.append)
    assert seen and any("14.19" in step for step in seen)
