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
