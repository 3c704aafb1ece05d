"""The first derivation in a fresh process: the pendulum as a command-line user meets it.

run.py's derivation table times each tool in one warm process, SymPy's
cache cleared before every run. A user of either tool meets something
else: a new Python process that imports the tool and derives once. Here
each tool runs in its own ``subprocess`` (``sys.executable``), gacli and
Kane alternately, ``repeat`` times, and the medians are reported.

What counts as what, in the child process:

* imports (not timed as derivation): for gacli ``sympy``, ``gacli``,
  ``gacli.loader.loading`` and ``gacli.mechanics.equations`` (the modules behind
  ``gacli.load`` and ``gacli.derive``, which ``gacli derive`` imports
  before it reads the file); for Kane ``sympy``,
  ``sympy.physics.mechanics`` and ``bench_kane`` (the model's code);
* the first derivation (timed): for gacli ``derive(load(path))``, reading
  and parsing the system file included, since writing the model is what
  Kane's side does in Python; for Kane building frames, points,
  particles and loads, ``KanesMethod(...)``, ``kanes_equations`` and
  ``mass_matrix``, ``forcing`` (``bench_kane.pendulum(n)``).

Nothing is warmed, no cache is cleared and the garbage collector is left
as a user has it. Whatever a tool imports lazily during its first
derivation is derivation time. The child reports the CPU time
(``time.process_time``, counted from the process's start) and the wall
time (``time.perf_counter``, from just before the parent started it) at
the end of the imports and of the derivation. The child imports the
gacli of this checkout (the repository root first on ``sys.path``), not
an installed one.

Usage (also part of run.py)::

    python benchmarks/bench_fresh.py --sizes 10 --repeat 5 --clock cpu
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from bench_cases import HERE, ROOT
from make_pendulum import write_pendulum

CHILD = r"""
import sys, time
started, root, bench, tool, size, path = float(sys.argv[1]), *sys.argv[2:]
sys.path[:0] = [root, bench]
if tool == "gacli":
    import sympy, gacli
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load
    def first():
        return derive(load(path))
else:
    import sympy
    from sympy.physics import mechanics
    import bench_kane
    def first():
        model = bench_kane.pendulum(int(size))
        return model.mass_matrix, model.forcing
cpu0, wall0 = time.process_time(), time.perf_counter()
first()
cpu1, wall1 = time.process_time(), time.perf_counter()
tool_file = gacli.__file__ if tool == "gacli" else bench_kane.__file__
print(f"{cpu0!r} {wall0 - started!r} {cpu1 - cpu0!r} {wall1 - wall0!r} {tool_file}")
"""


def run_child(tool: str, size: int, path: Path) -> dict:
    """One fresh process: import, derive once; CPU and wall seconds of imports and derivation."""
    started = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", CHILD, repr(started), str(ROOT), str(HERE), tool, str(size), str(path)],
                          cwd=ROOT, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{tool} child exited with {done.returncode}: {done.stderr.strip()[-300:]}")
    *numbers, where = done.stdout.split(maxsplit=4)
    if tool == "gacli" and not Path(where).resolve().is_relative_to(ROOT):
        raise RuntimeError(f"the child imported another gacli: {where}")
    imports_cpu, imports_wall, derive_cpu, derive_wall = map(float, numbers)
    return {"imports_cpu": imports_cpu, "imports_wall": imports_wall,
            "derive_cpu": derive_cpu, "derive_wall": derive_wall}


def fresh_pendulum(size: int, repeat: int, clock: str, scratch: Path) -> dict:
    """Medians over ``repeat`` fresh processes per tool, gacli and Kane alternately."""
    path = write_pendulum(size, scratch)
    runs: dict[str, list[dict]] = {"gacli": [], "kane": []}
    for _ in range(max(1, repeat)):
        for tool in runs:
            runs[tool].append(run_child(tool, size, path))
    row: dict = {"label": f"pendulum n={size}", "size": size, "repeat": max(1, repeat), "clock": clock, "runs": runs}
    for tool, results in runs.items():
        for key in results[0]:
            row[f"{tool}_{key}"] = statistics.median(r[key] for r in results)
        row[f"{tool}_imports_s"] = row[f"{tool}_imports_{clock}"]
        row[f"{tool}_derive_s"] = row[f"{tool}_derive_{clock}"]
        row[f"{tool}_process_s"] = statistics.median(r[f"imports_{clock}"] + r[f"derive_{clock}"] for r in results)
    row["derive_ratio"] = row["kane_derive_s"] / row["gacli_derive_s"]
    row["process_ratio"] = row["kane_process_s"] / row["gacli_process_s"]
    return row


def fresh_rows(sizes: list[int], repeat: int, clock: str, scratch: Path) -> list[dict]:
    return [fresh_pendulum(n, repeat, clock, scratch) for n in sizes]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", default="10", help="pendulum links, comma-separated (default 10)")
    parser.add_argument("--repeat", type=int, default=5, help="fresh processes per tool and size (default 5)")
    parser.add_argument("--clock", choices=("wall", "cpu"), default="wall")
    options = parser.parse_args(argv)
    from bench_report import fresh_table

    with tempfile.TemporaryDirectory(prefix="gacli-fresh-") as scratch:
        rows = fresh_rows([int(v) for v in options.sizes.split(",") if v.strip()], options.repeat,
                          options.clock, Path(scratch))
    print(fresh_table(rows, options.clock))
    for row in rows:
        print(f"\n{row['label']}, every process [{options.clock}] (imports, derivation):")
        for tool in ("gacli", "kane"):
            pairs = ", ".join(f"({r[f'imports_{options.clock}']:.3f}, {r[f'derive_{options.clock}']:.4f})"
                              for r in row["runs"][tool])
            print(f"  {tool}: {pairs}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
