"""Runs system files through every command and format in one fresh process; prints JSON.

Used by tests/test_hostile_commands.py: a fresh process, so that its peak
memory (VmHWM) is the most any one case used, whatever ran before in
the test session. Each case gets an empty output folder; the record says
what the command printed, its exit code, its time, which files it left in
the output folder and whether the injection marker appeared.

    python tests/hostile_driver.py WORKDIR FILE...
    python tests/hostile_driver.py --output-target=PATH [--budget=SECONDS] WORKDIR FILE...

With ``--output-target``, the commands are those that write (derive in every
format, simulate's CSV), each told to write to PATH (a device, a FIFO, a
path under a file: tests/test_hostile_output.py).
"""

from __future__ import annotations

import json
import resource
import sys
import time
from pathlib import Path

from sympy.core.cache import clear_cache
from typer.testing import CliRunner

from gacli.cli import app
from gacli.emit import EMITTERS

BUDGET = "1"
SIMULATE = ["--t-end", "0.1", "--points", "3"]
NEEDS_A_FILE_NAME = {"latex": "doc.tex"}  # one-file formats whose name the test chooses


def commands() -> dict[str, list[str]]:
    """Every command, and derive in every format (with the options that change what it writes)."""
    out = {"check": ["check"], "derive": ["derive"], "derive-steps": ["derive", "--steps"],
           "gibbs": ["gibbs"], "verify": ["verify", "--samples", "1"], "linearize": ["linearize"],
           "simulate": ["simulate", *SIMULATE]}
    for fmt in sorted(EMITTERS):
        target = "{out}/" + NEEDS_A_FILE_NAME.get(fmt, "")
        out[f"derive-{fmt}"] = ["derive", "--format", fmt, "--output", target]
    out["derive-latex-standalone-steps"] = ["derive", "--format", "latex", "--standalone", "--steps",
                                           "--output", "{out}/doc.tex"]
    for fmt in ("python", "c"):
        out[f"derive-{fmt}-reactions"] = ["derive", "--format", fmt, "--reactions", "--output", "{out}/"]
    return out


def output_commands(target: str) -> dict[str, list[str]]:
    """Every command that writes a file, told to write to ``target``."""
    out = {f"derive-{fmt}": ["derive", "--format", fmt, "--output", target] for fmt in sorted(EMITTERS)}
    out["simulate-csv"] = ["simulate", *SIMULATE, "--csv", target]
    return out


def peak_mib() -> float:
    """This process's peak resident memory, in MiB.

    /proc's VmHWM belongs to this program's own address space; ru_maxrss
    would also count the pytest process it was forked from (Linux keeps
    the larger of the two across exec).
    """
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def run_case(name: str, command: list[str], path: Path, work: Path, budget: str = BUDGET) -> dict:
    out = work / "out" / path.stem / name
    out.mkdir(parents=True)
    marker = work / "MARKER"
    args = [part.format(out=out) for part in command]
    if command[0] != "check":
        args += ["--timeout", budget]
    else:
        args[1:1] = ["--timeout", budget]
    clear_cache()  # each case as a fresh `gacli` process meets it, not warmed (or bloated) by the others
    start = time.perf_counter()
    result = CliRunner().invoke(app, [*args, str(path)])
    elapsed = time.perf_counter() - start
    crashed = result.exception is not None and not isinstance(result.exception, SystemExit)
    return {"file": path.stem, "command": name, "exit": result.exit_code, "output": result.output[-4000:],
            "seconds": elapsed, "written": sorted(p.name for p in out.iterdir()),
            "marker": marker.exists(), "crashed": repr(result.exception) if crashed else None,
            "peak_mib_after": peak_mib()}


def main(argv: list[str]) -> None:
    chosen, budget = commands(), BUDGET
    while argv and argv[0].startswith("--"):
        option, _, value = argv.pop(0).partition("=")
        if option == "--output-target":
            chosen = output_commands(value)
        elif option == "--budget":  # a valid system, whose derivation is not what is tested
            budget = value
    work, files = Path(argv[0]), [Path(a) for a in argv[1:]]
    records = [run_case(name, command, path, work, budget) for path in files for name, command in chosen.items()]
    json.dump({"records": records, "peak_mib": peak_mib()}, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1:])
