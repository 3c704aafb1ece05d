"""How derive scales with the width of a system: n uncoupled particles on springs.

Each particle i has its own coordinate x_i and spring force -k x_i (one
mass m and one stiffness k for all: a file declares at most 500 names, so
n = 498 is the widest such file): the equations are diagonal, so a derivation linear in n is
possible and anything steeper is overhead (issue 18). Prints the time of
load + derive + the requested output for each n, and the fitted exponent
(the slope of log time against log n).

Usage::

    python benchmarks/bench_wide.py                     # n = 100..498, text and C
    python benchmarks/bench_wide.py --sizes 50,100,200 --formats c
    python benchmarks/bench_wide.py --profile 300       # cProfile of one run, top 25 by cumulative time
"""

from __future__ import annotations

import argparse
import math
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
# benchmarks/profile.py would shadow the standard library's profile (cProfile imports it).
sys.path[:] = [str(HERE.parent)] + [p for p in sys.path if Path(p or ".").resolve() != HERE]


def wide_yaml(n: int) -> str:
    """The system file of n uncoupled particles on springs, one coordinate each."""
    lines = ["gacli: 1", f"name: particles_{n}", f"title: {n} uncoupled particles on springs", "",
             "parameters:", "  m: {value: 1}", "  k: {value: 2}"]
    lines += ["", "coordinates:"] + [f"  x{i}: position of particle {i}" for i in range(1, n + 1)]
    lines += ["", "bodies:"]
    for i in range(1, n + 1):
        lines += [f"  p{i}:", "    mass: m", f"    position: [x{i}, 0]"]
    lines += ["", "loads:"]
    for i in range(1, n + 1):
        lines += [f"  - force: [-k*x{i}, 0]", f"    at: p{i}"]
    return "\n".join(lines) + "\n"


CLOCKS = {"wall": time.perf_counter, "cpu": time.process_time}
clock = time.perf_counter


def run_once(path: Path, fmt: str) -> float:
    """Seconds for load, derive and the output in ``fmt`` (what ``gacli derive`` does)."""
    from gacli.api import emit
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load
    from gacli.display.report import derivation_report

    from sympy.core.cache import clear_cache

    clear_cache()  # each size as a fresh `gacli derive` would see it, not warmed by the smaller ones
    start = clock()
    derivation = derive(load(path))
    if fmt == "text":
        tuple(derivation_report(derivation))
    else:
        emit(derivation, fmt)
    return clock() - start


def slope(sizes: list[int], times: list[float]) -> float:
    """Least-squares slope of log(time) against log(n): time ~ n**slope."""
    xs, ys = [math.log(n) for n in sizes], [math.log(t) for t in times]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="100,200,300,400,498", help="numbers of particles, comma separated")
    parser.add_argument("--formats", default="text,c", help="outputs timed (text, latex, python, c)")
    parser.add_argument("--profile", type=int, metavar="N", help="profile one run of N particles instead")
    parser.add_argument("--clock", choices=sorted(CLOCKS), default="wall",
                        help="wall time, or this process's CPU time (steadier on a busy machine)")
    args = parser.parse_args(argv)
    global clock
    clock = CLOCKS[args.clock]
    directory = Path(tempfile.mkdtemp(prefix="gacli-wide-"))
    if args.profile:
        import cProfile
        import pstats

        path = directory / "wide.yaml"
        path.write_text(wide_yaml(args.profile), encoding="utf-8")
        profiler = cProfile.Profile()
        profiler.runcall(run_once, path, args.formats.split(",")[0])
        pstats.Stats(profiler).sort_stats("cumulative").print_stats(25)
        return
    sizes = [int(s) for s in args.sizes.split(",")]
    for fmt in args.formats.split(","):
        times = []
        for n in sizes:
            path = directory / f"wide_{n}.yaml"
            path.write_text(wide_yaml(n), encoding="utf-8")
            times.append(run_once(path, fmt))
            print(f"{fmt:>6}  n = {n:4d}  {times[-1]:7.2f} s", flush=True)
        if len(sizes) > 1:
            print(f"{fmt:>6}  time ~ n^{slope(sizes, times):.2f}", flush=True)


if __name__ == "__main__":
    main()
