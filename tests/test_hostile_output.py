"""Hostile places, third round (issue 33, items 1 and 2): through every command and format.

Each case runs in one fresh process (tests/hostile_driver.py) under the
corpus's limits: 20 s a case, 1 GiB for the run, no traceback, one message
that names the place, nothing written, nothing half-written.

* Output to special or failing places: every format of ``derive`` and
  ``simulate --csv`` told to write to a character device, a FIFO, a link to
  a device, a path under a regular file, and ``/proc``. The device stays a
  device, the FIFO a FIFO (it is never opened: that would block), the file
  keeps its text.
* System files that are not files: a link to ``/dev/zero`` and a link loop,
  through every command (check, derive in every format, gibbs, verify,
  linearize, simulate).
"""

from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest

from hostile_driver import commands, output_commands

HERE = Path(__file__).resolve().parent
SYSTEM = HERE.parent / "systems" / "cylinder_in_cylinder.yaml"
CASE_SECONDS = 20
PEAK_MIB = 1024


def _drive(work: Path, files: list[Path], *options: str) -> dict:
    env = {**os.environ, "PYTHONPATH": str(HERE.parent), "PATH": str(work / "no-compilers")}
    env.pop("CC", None)  # the FMU with its sources only: the output is what is tested, not a compiler
    done = subprocess.run([sys.executable, str(HERE / "hostile_driver.py"), *options, str(work), *map(str, files)],
                          capture_output=True, text=True, timeout=1800, env=env, cwd=work)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout)


def _within_limits(run: dict) -> None:
    assert run["peak_mib"] < PEAK_MIB, run["peak_mib"]
    for r in run["records"]:
        where = f"{r['file']} {r['command']}: {r['output']}"
        assert r["crashed"] is None, where + str(r["crashed"])
        assert "Traceback" not in r["output"] and "internal error" not in r["output"], where
        assert r["seconds"] < CASE_SECONDS, where
        assert r["written"] == [], where


def _fifo(work: Path) -> str:
    os.mkfifo(work / "pipe.out")
    return str(work / "pipe.out")


def _link_to_device(work: Path) -> str:
    (work / "null.out").symlink_to("/dev/null")
    return str(work / "null.out")


def _under_a_file(work: Path) -> str:
    (work / "plain").write_text("precious\n")
    return str(work / "plain" / "deeper" / "x.out")


TARGETS = {
    "device": (lambda work: "/dev/null", "not a regular file"),
    "device-as-directory": (lambda work: "/dev/null/", "not a directory"),
    "fifo": (_fifo, "not a regular file"),
    "link-to-device": (_link_to_device, "not a regular file"),
    "under-a-file": (_under_a_file, "plain is a file, not a directory"),
    "proc": (lambda work: "/proc/gacli-hostile/", "cannot make the directory"),
}


@pytest.mark.parametrize("case", sorted(TARGETS))
def test_output_to_a_special_or_failing_place(case, tmp_path):
    make, expect = TARGETS[case]
    target = make(tmp_path)
    before = sorted(p.name for p in tmp_path.iterdir())
    run = _drive(tmp_path, [SYSTEM], f"--output-target={target}", "--budget=10")
    assert sorted(r["command"] for r in run["records"]) == sorted(output_commands(target))
    _within_limits(run)
    for r in run["records"]:
        where = f"{r['command']}: {r['output']}"
        assert r["exit"] == 1, where
        errors = [line for line in r["output"].splitlines() if line.startswith("error:")]
        assert len(errors) == 1 and expect in errors[0], where
        assert target.rstrip("/").split("/")[-1] in errors[0] or "plain" in errors[0], where
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
    assert sorted(p.name for p in tmp_path.iterdir() if p.name != "out") == [n for n in before if n != "out"]
    if case == "fifo":
        assert stat.S_ISFIFO(os.stat(target).st_mode)
    if case == "under-a-file":
        assert (tmp_path / "plain").read_text() == "precious\n"


def _link_loop(work: Path) -> Path:
    (work / "loop_a.yaml").symlink_to("loop_b.yaml")
    (work / "loop_b.yaml").symlink_to("loop_a.yaml")
    return work / "loop_a.yaml"


def _link_to_zero(work: Path) -> Path:
    (work / "zero.yaml").symlink_to("/dev/zero")
    return work / "zero.yaml"


def test_system_files_that_are_not_files_through_every_command(tmp_path):
    files = [_link_to_zero(tmp_path), _link_loop(tmp_path)]
    run = _drive(tmp_path, files)
    assert len(run["records"]) == len(files) * len(commands())
    _within_limits(run)
    for r in run["records"]:
        where = f"{r['file']} {r['command']}: {r['output']}"
        assert r["exit"] in (1, 2), where  # 2: the command line's own check that FILE exists
        assert f"{r['file']}.yaml" in r["output"], where
        if r["file"] == "zero" and r["exit"] == 1:
            assert "zero.yaml:1:1: error: " in r["output"] and "not a regular file" in r["output"], where
