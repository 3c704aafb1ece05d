"""Profile gacli's derivation (load + derive) with cProfile.

Prints the top functions by cumulative time, then by own time, for each
size; SymPy's cache is cleared before each profile so that it measures a
cold derivation, as ``run.py`` does.

Usage::

    python benchmarks/profile.py                      # pendulum, n = 10 and 20, top 25
    python benchmarks/profile.py --case chain --sizes 2,3 --top 40
    python benchmarks/profile.py --dump /tmp/prof     # also write .prof files for snakeviz etc.
"""

from __future__ import annotations

import argparse
import io
import sys
import tempfile
import time
from pathlib import Path

# This file is named profile.py: with benchmarks/ first on sys.path, the
# standard library's `profile` (which cProfile imports) would be this
# module. Import cProfile without this directory on the path.
_HERE = str(Path(__file__).resolve().parent)
_saved = list(sys.path)
sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != Path(_HERE)]
import cProfile  # noqa: E402
import pstats  # noqa: E402

sys.path[:] = _saved
sys.path.insert(0, str(Path(_HERE).parent))  # this checkout's gacli, not an installed one

from sympy.core.cache import clear_cache  # noqa: E402

from make_chain import write_chain  # noqa: E402
from make_pendulum import write_pendulum  # noqa: E402

DISK = Path(_HERE) / "cases" / "rolling_disk.yaml"


def system_file(case: str, n: int, directory: Path) -> Path:
    if case == "pendulum":
        return write_pendulum(n, directory)
    if case == "chain":
        return write_chain(n, directory)
    if case == "disk":
        return DISK
    raise SystemExit(f"unknown case {case!r} (pendulum, chain or disk)")


def profile(path: Path) -> tuple[float, pstats.Stats, cProfile.Profile]:
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    clear_cache()
    profiler = cProfile.Profile()
    start = time.perf_counter()
    profiler.enable()
    derive(load(path))
    profiler.disable()
    elapsed = time.perf_counter() - start
    return elapsed, pstats.Stats(profiler, stream=io.StringIO()), profiler


def stage_times(path: Path) -> tuple[float, list[tuple[str, float]]]:
    """Seconds of load and of each stage derive() announces through its ``progress`` callback (no profiler)."""
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    clear_cache()
    marks: list[tuple[str, float]] = []
    start = time.perf_counter()
    system = load(path)
    marks.append(("load", time.perf_counter()))
    derive(system, progress=lambda name: marks.append((name, time.perf_counter())))
    end = time.perf_counter()
    stages = []
    names = [name for name, _ in marks]
    times = [t for _, t in marks] + [end]
    # marks[0] closes "load"; each later mark opens its stage, closed by the next mark (or the end).
    stages.append(("load", times[0] - start))
    for i in range(1, len(marks)):
        stages.append((names[i], times[i + 1] - times[i]))
    return end - start, stages


def table(stats: pstats.Stats, sort: str, top: int) -> str:
    stream = io.StringIO()
    stats.stream = stream
    stats.sort_stats(sort).print_stats(top)
    text = stream.getvalue()
    start = text.find("   ncalls")  # drop pstats' preamble
    return text[start:] if start >= 0 else text


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", default="pendulum", help="pendulum, chain or disk (default pendulum)")
    parser.add_argument("--sizes", default="10,20", help="comma-separated sizes (default 10,20)")
    parser.add_argument("--top", type=int, default=25, help="rows per table (default 25)")
    parser.add_argument("--dump", type=Path, help="write <case>_<n>.prof here")
    args = parser.parse_args(argv)

    # Warm up the imports so that the profile shows the derivation only.
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    with tempfile.TemporaryDirectory(prefix="gacli-profile-") as scratch:
        derive(load(write_pendulum(1, Path(scratch))))
        for n in [int(v) for v in args.sizes.split(",") if v.strip()]:
            path = system_file(args.case, n, Path(scratch))
            label = args.case if args.case == "disk" else f"{args.case} n={n}"
            total, stages = stage_times(path)
            print(f"\n=== {label}: stages of load + derive, no profiler: {total:.2f} s ===")
            for name, seconds in stages:
                print(f"  {seconds:7.3f} s  {100 * seconds / total:5.1f} %  {name}")
            elapsed, stats, profiler = profile(path)
            print(f"\n=== {label}: load + derive under cProfile: {elapsed:.2f} s ===")
            print(f"\n--- top {args.top} by cumulative time ---")
            print(table(stats, "cumulative", args.top))
            print(f"--- top {args.top} by own time ---")
            print(table(stats, "tottime", args.top))
            if args.dump:
                args.dump.mkdir(parents=True, exist_ok=True)
                profiler.dump_stats(str(args.dump / f"{args.case}_{n}.prof"))
            if args.case == "disk":
                break


if __name__ == "__main__":
    main()
