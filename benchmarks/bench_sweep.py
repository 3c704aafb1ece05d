"""The Whipple bicycle's stability over speed and rider-frame mass: gacli sweep against a loop.

``gacli sweep`` linearizes systems/whipple_bicycle.yaml at every point of a
grid (by default 50 speeds from 1 to 10 m/s times 20 values of ``mframe``
from 60 to 110 kg: 1,000 points) and keeps the eigenvalues of the roll and
steer block, once with ``--jobs 2`` and once on a local Dask cluster of two
worker processes; the two tables must be byte-identical. The way without it,
a loop of ``gacli linearize`` processes (each reading, deriving and
compiling the bicycle again), is timed over ``--loop`` points of the same
grid and scaled to the grid's size.

Usage::

    python benchmarks/bench_sweep.py                              # 1,000 points, a loop of 10
    python benchmarks/bench_sweep.py --speeds 10 --masses 2 --loop 2   # a quick look
    python benchmarks/bench_sweep.py --json sweep.json

Wall-clock times on a shared machine vary; the table reports one run of each.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from bench_report import gacli_command, machine, markdown

ROOT = Path(__file__).resolve().parent.parent
BICYCLE = ROOT / "systems" / "whipple_bicycle.yaml"
REAR_RADIUS = 0.3      # m: the rear wheel turns at v / r
STATES = "roll,steer,dot(roll),dot(steer)"


def grid(speeds: int, masses: int) -> list[str]:
    low, high = 1.0 / REAR_RADIUS, 10.0 / REAR_RADIUS
    return ["--grid", f"dot(wheel_R)={low!r}:{high!r}:{speeds}", "--grid", f"mframe=60:110:{masses}"]


def environment() -> dict[str, str]:
    # The workers (spawned processes, Dask's) import this checkout's gacli.
    return {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))}


def timed_run(command: list[str]) -> float:
    start = time.perf_counter()
    done = subprocess.run(command, env=environment(), capture_output=True, text=True)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stderr[-3000:]}")
    return elapsed


def sweep_command(points: list[str], output: Path, *more: str) -> list[str]:
    return [*gacli_command(), "sweep", str(BICYCLE), "--run", "linearize", *points, "--states", STATES,
            "--output", str(output), *more]


def on_dask(points: list[str], output: Path, workers: int) -> float:
    from distributed import LocalCluster

    os.environ["PYTHONPATH"] = environment()["PYTHONPATH"]   # the worker processes inherit it
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        return timed_run(sweep_command(points, output, "--scheduler", cluster.scheduler_address))


def loop(table: list[dict], count: int) -> float:
    """Seconds per point of a loop of gacli linearize processes, over ``count`` rows spread over the grid."""
    step = max(1, len(table) // count)
    picked = table[::step][:count]
    start = time.perf_counter()
    for row in picked:
        timed_run([*gacli_command(), "linearize", str(BICYCLE), "--at", f"dot(wheel_R)={row['dot(wheel_R)']}",
                   "--set", f"mframe={row['mframe']}", "--states", STATES])
    return (time.perf_counter() - start) / len(picked)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--speeds", type=int, default=50)
    parser.add_argument("--masses", type=int, default=20)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--loop", type=int, default=10, help="gacli linearize processes timed (scaled up)")
    parser.add_argument("--json", type=Path)
    options = parser.parse_args()
    points = grid(options.speeds, options.masses)
    total = options.speeds * options.masses
    with tempfile.TemporaryDirectory(prefix="gacli-bench-sweep-") as folder:
        jobs_table, dask_table = Path(folder) / "jobs.csv", Path(folder) / "dask.csv"
        jobs_time = timed_run(sweep_command(points, jobs_table, "--jobs", str(options.jobs)))
        dask_time = on_dask(points, dask_table, options.jobs)
        if jobs_table.read_bytes() != dask_table.read_bytes():
            sys.exit("the --jobs and Dask tables differ")
        table = list(csv.DictReader(jobs_table.open()))
    per_point = loop(table, options.loop)
    stable = sum(row["stable"] == "true" for row in table)
    results = {
        "machine": machine(), "points": total, "jobs": options.jobs, "stable_points": stable,
        "sweep_jobs_s": jobs_time, "sweep_dask_s": dask_time,
        "loop_per_point_s": per_point, "loop_scaled_s": per_point * total, "loop_sampled": options.loop,
    }
    rows = [
        [f"gacli sweep --jobs {options.jobs}", f"{jobs_time:.3g}", f"{jobs_time / total * 1000:.3g}", "1x"],
        [f"gacli sweep on Dask ({options.jobs} workers)", f"{dask_time:.3g}", f"{dask_time / total * 1000:.3g}",
         f"{dask_time / jobs_time:.3g}x"],
        [f"loop of gacli linearize (scaled from {options.loop})", f"{per_point * total:.3g}",
         f"{per_point * 1000:.3g}", f"{per_point * total / jobs_time:.3g}x"],
    ]
    print(f"Whipple bicycle, {total} points ({options.speeds} speeds x {options.masses} frame masses); "
          f"{stable} asymptotically stable; the --jobs and Dask tables are identical.\n")
    print(markdown(["run", "seconds", "ms per point", "vs sweep --jobs"], rows))
    if options.json:
        options.json.write_text(json.dumps(results, indent=2) + "\n")


if __name__ == "__main__":
    main()
