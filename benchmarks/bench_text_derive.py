"""CPU time of ``gacli derive FILE`` (the text printout) for every system file of the repository.

Issue 28 asks that a system derive in text in under 10 s of CPU. Each file
runs in a fresh process, as a user runs it (imports included), and the
children's user + system time is read from ``resource.getrusage``; the
printout's MD5 is shown too, so that two checkouts can be compared for the
same output as well as for time::

    python benchmarks/bench_text_derive.py                # this checkout
    python benchmarks/bench_text_derive.py --root ../old  # another one, the same files
    python benchmarks/bench_text_derive.py --only corpus/ball,kane_set/four_bar

Times are comparable only between runs on the same machine under the same load.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import resource
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
FOLDERS = ("systems", "tests/frames", "tests/twins", "benchmarks/corpus", "benchmarks/kane_set")
TARGET_CPU = 10.0  # seconds, the bound


def files(root: Path, only: list[str]) -> list[str]:
    found = sorted(str(p.relative_to(root)) for folder in FOLDERS for p in (root / folder).glob("*.yaml"))
    return [f for f in found if not only or any(key in f for key in only)]


def cpu_of(root: Path, path: str, timeout: float) -> tuple[float, str, str]:
    """(CPU seconds, exit code, MD5 of the printout) of one fresh ``gacli derive``."""
    env = dict(os.environ, PYTHONPATH=str(root), PYTHONHASHSEED="0")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        done = subprocess.run([sys.executable, "-m", "gacli", "derive", path], cwd=root, env=env,
                              capture_output=True, timeout=timeout)
        code, out = str(done.returncode), done.stdout
    except subprocess.TimeoutExpired:
        code, out = "timeout", b""
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return cpu, code, hashlib.md5(out).hexdigest()[:8]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=HERE.parent, help="the checkout to run")
    parser.add_argument("--only", default="", help="comma-separated parts of paths to keep")
    parser.add_argument("--timeout", type=float, default=180.0)
    args = parser.parse_args()
    root = args.root.resolve()
    rows = []
    print("| file | CPU s | exit | printout |\n|---|--:|---|---|")
    for path in files(root, [k for k in args.only.split(",") if k]):
        cpu, code, digest = cpu_of(root, path, args.timeout)
        rows.append(cpu)
        print(f"| {path} | {cpu:.1f} | {code} | {digest} |", flush=True)
    over = sum(1 for cpu in rows if cpu >= TARGET_CPU)
    print(f"\n{len(rows)} files, {sum(rows):.0f} s CPU in all, the slowest {max(rows, default=0):.1f} s, "
          f"{over} at or over {TARGET_CPU:.0f} s")


if __name__ == "__main__":
    main()
