"""Operation count of each systems/ file's generated rhs, after the emitter's CSE.

    python benchmarks/systems_ops.py

Prints a markdown table (the README's performance section keeps one): the
degrees of freedom k, the derivation time and the count_ops of what the C
emitter computes in its rhs (kinematics, M's lower triangle and F, after CSE).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from run import emit, emitted_rhs_ops  # noqa: E402

from gacli.mechanics.equations import derive  # noqa: E402
from gacli.loader.loading import load  # noqa: E402


def main() -> None:
    rows = ["| system | k | derive [s] | rhs ops after CSE |", "|:--|--:|--:|--:|"]
    for path in sorted((HERE.parent / "systems").glob("*.yaml")):
        start = time.perf_counter()
        derivation = derive(load(path))
        seconds = time.perf_counter() - start
        _, calls = emit(derivation, "c")
        rows.append(f"| {path.stem} | {derivation.k} | {seconds:.2f} | {emitted_rhs_ops(calls, derivation)} |")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
