"""The report of run.py: machine, cold start, markdown tables, the issue's targets."""

from __future__ import annotations

import math
import os
import platform
import shutil
import subprocess
import sys
import time

import numpy as np
import sympy as sp

import bench_c
from bench_cases import ROOT

TOLERANCE = 1e-8
SPHERE = ROOT / "systems" / "sphere_on_turntable.yaml"


# -- cold start ---------------------------------------------------------------------

def gacli_command() -> list[str]:
    exe = shutil.which("gacli")
    return [exe] if exe else [sys.executable, "-m", "gacli"]


def cold_start(repeat: int, clock: str) -> dict:
    """Best times of fresh processes: python itself, ``gacli --help``, ``gacli derive`` of the sphere.

    Wall time by ``time.perf_counter``; CPU time as the children's user +
    system time from ``resource.getrusage``.
    """
    import resource

    command = gacli_command()

    def best(args: list[str], times: int) -> tuple[float, float]:
        walls, cpus = [], []
        for _ in range(times):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            start = time.perf_counter()
            done = subprocess.run(args, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            walls.append(time.perf_counter() - start)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
            if done.returncode != 0:
                raise RuntimeError(f"{' '.join(args)} exited with {done.returncode}: {done.stderr.strip()[:300]}")
        return min(walls), min(cpus)

    out: dict = {"command": " ".join(command), "clock": clock}
    runs = {"python_startup": ([sys.executable, "-c", "pass"], repeat),
            "help": ([*command, "--help"], repeat),
            "derive_sphere": ([*command, "derive", str(SPHERE.relative_to(ROOT))], max(1, repeat // 2 + 1))}
    for key, (args, times) in runs.items():
        wall, cpu = best(args, times)
        out.update({f"{key}_wall_s": wall, f"{key}_cpu_s": cpu, f"{key}_s": cpu if clock == "cpu" else wall})
    return out


# -- the machine and the tables ----------------------------------------------------------

def machine() -> dict:
    cc = bench_c.compiler()
    version = ""
    if cc:
        done = subprocess.run([cc, "--version"], capture_output=True, text=True)
        version = done.stdout.splitlines()[0] if done.stdout else ""
    try:
        import gacli
        gacli_version = gacli.__version__
    except Exception:  # noqa: BLE001
        gacli_version = "?"
    return {
        "platform": platform.platform(), "processor": platform.processor() or platform.machine(),
        "cpu_count": os.cpu_count(), "python": platform.python_version(), "sympy": sp.__version__,
        "numpy": np.__version__, "gacli": gacli_version, "cc": version,
    }


def _num(value, fmt: str) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "n/a"
    return format(value, fmt)


def _ratio(value) -> str:
    return "n/a" if value is None else f"{value:.3g}x" if value < 100 else f"{value:.0f}x"


def _seconds(value) -> str:
    return "n/a" if value is None else f"{value:.3g}"


def _us(value) -> str:
    if value is None:
        return "n/a"
    return f"{value:.3g}" if value < 1000 else f"{value:,.0f}"


def markdown(headers: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(headers)]
    line = lambda cells: "| " + " | ".join(c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(cells, widths))) + " |"
    rule = "|" + "|".join("-" * (w + 1) + ":" if i else ":" + "-" * (w + 1) for i, w in enumerate(widths)) + "|"
    return "\n".join([line(headers), rule, *(line(r) for r in rows)])


def _check(row: dict) -> str:
    if "agreement" in row:
        return ("ok " if row["agreement"] <= TOLERANCE else "FAIL ") + f"{row['agreement']:.0e}"
    return "n/a"


def derivation_table(rows: list[dict], clock: str) -> str:
    unit = "s CPU" if clock == "cpu" else "s"
    headers = ["case", "k", f"derive gacli [{unit}]", f"derive Kane [{unit}]", "Kane/gacli",
               "ops Kane", "ops gacli", "gacli/Kane", "ops emitted", "emitted/Kane", "agree"]
    body = [[r["label"], _num(r.get("k"), "d"), _seconds(r.get("derive_gacli_s")), _seconds(r.get("derive_kane_s")),
             _ratio(r.get("derive_ratio")), _num(r.get("ops_kane"), ","), _num(r.get("ops_gacli"), ","),
             _num(r.get("ops_ratio"), ".2f"), _num(r.get("ops_gacli_emitted"), ","),
             _num(r.get("ops_emitted_ratio"), ".2f"), _check(r)] for r in rows]
    return markdown(headers, body)


def rhs_table(rows: list[dict]) -> str:
    headers = ["case", "gacli C", "Kane ccode+solve", "KaneC/gacliC", "gacli Python", "Kane lambdify", "lambdify/gacliPy"]
    body = [[r["label"], _us(r.get("rhs_gacli_c_us")), _us(r.get("rhs_kane_c_us")), _ratio(r.get("rhs_c_ratio")),
             _us(r.get("rhs_py_gacli_us")), _us(r.get("rhs_lambdify_kane_us")), _ratio(r.get("rhs_py_ratio"))]
            for r in rows]
    return markdown(headers, body)


def cold_table(cold: dict) -> str:
    rows = [["python -c pass (baseline)", _seconds(cold.get("python_startup_s")), ""],
            ["gacli --help", _seconds(cold.get("help_s")), "< 0.3"],
            ["gacli derive systems/sphere_on_turntable.yaml", _seconds(cold.get("derive_sphere_s")), "< 1.5"]]
    return markdown(["command (best of a few)", "seconds", "target"], rows)


def fresh_table(rows: list[dict], clock: str) -> str:
    """The first derivation in a fresh process (bench_fresh.py): medians of the processes."""
    unit = "s CPU" if clock == "cpu" else "s"
    headers = ["case", "runs", f"gacli imports [{unit}]", f"gacli 1st derive [{unit}]", f"Kane imports [{unit}]",
               f"Kane 1st derive [{unit}]", "Kane/gacli", "process Kane/gacli"]
    body = [[r["label"], str(r["repeat"]), _seconds(r.get("gacli_imports_s")), _seconds(r.get("gacli_derive_s")),
             _seconds(r.get("kane_imports_s")), _seconds(r.get("kane_derive_s")), _ratio(r.get("derive_ratio")),
             _ratio(r.get("process_ratio"))] for r in rows]
    return markdown(headers, body)


def targets(rows: list[dict], cold: dict | None, fresh: list[dict] | None = None) -> list[str]:
    """The issue's targets, each as 'PASS'/'FAIL'/'n/a' with the numbers.

    They are set for the pendulum at n = 10 and n = 20 only; the other rows
    are in the tables, not judged here.
    """
    out = []
    judged = [r for r in rows if r["case"] == "pendulum" and r["size"] in (10, 20)]
    for r in judged:
        v = r.get("derive_ratio")
        out.append(f"derive >= 20x faster than Kane, {r['label']}: " + ("n/a" if v is None else f"{'PASS' if v >= 20 else 'FAIL'} ({v:.1f}x)"))
    for r in judged:
        basis = "ops_emitted_ratio" if r.get("ops_emitted_ratio") is not None else "ops_ratio"
        v = r.get(basis)
        what = "emitted rhs" if basis == "ops_emitted_ratio" else "derivation, emitter n/a"
        out.append(f"generated ops <= 1/2 of Kane's, {r['label']}: " + ("n/a" if v is None else f"{'PASS' if v <= 0.5 else 'FAIL'} ({v:.2f}, {what})"))
    for r in judged:
        v = r.get("rhs_c_ratio")
        out.append(f"gacli C faster than Kane ccode+solve, {r['label']}: " + ("n/a" if v is None else f"{'PASS' if v > 1 else 'FAIL'} ({v:.2f}x)"))
    for r in fresh or []:
        if r["size"] == 10:
            v = r["derive_ratio"]
            out.append(f"first derive in a fresh process >= 20x faster than Kane, {r['label']}: "
                       f"{'PASS' if v >= 20 else 'FAIL'} ({v:.1f}x, median of {r['repeat']})")
    if cold:
        for key, limit, text in (("help_s", 0.3, "gacli --help"), ("derive_sphere_s", 1.5, "gacli derive sphere")):
            v = cold.get(key)
            out.append(f"{text} < {limit} s: " + ("n/a" if v is None else f"{'PASS' if v < limit else 'FAIL'} ({v:.3f} s)"))
    return out


def report(info: dict, rows: list[dict], cold: dict | None, skipped: list[str], options,
           fresh: list[dict] | None = None) -> str:
    lines = [
        "# gacli vs SymPy KanesMethod",
        "",
        f"machine: {info['platform']}, {info['processor']}, {info['cpu_count']} CPUs; "
        f"Python {info['python']}, SymPy {info['sympy']}, NumPy {info['numpy']}, gacli {info['gacli']}; "
        f"{info['cc'] or 'no C compiler'} {' '.join(options.cflags)}",
        "",
        "## Derivation and operation counts (count_ops after CSE of kinematics, M, F)",
        "",
        derivation_table(rows, options.clock),
        "",
        "## rhs: time per call [µs]",
        "",
        rhs_table(rows),
    ]
    if fresh:
        lines += ["", "## First derivation in a fresh process (imports not timed; median)", "",
                  fresh_table(fresh, options.clock)]
    if cold:
        lines += ["", "## Cold start" + (" (CPU time of the process)" if options.clock == "cpu" else ""), "", cold_table(cold)]
    lines += ["", "## Targets", "", *(f"- {t}" for t in targets(rows, cold, fresh))]
    notes = [f"- {r['label']}: {note}" for r in rows for note in r["notes"]] + [f"- {s}" for s in skipped]
    solves = sorted({f"{r['label']}: {r['kane_c_solve']}" for r in rows if r.get("kane_c_solve")})
    if solves:
        notes.append("- Kane ccode+solve used " + "; ".join(solves))
    if notes:
        lines += ["", "## Notes (n/a and failures)", "", *notes]
    return "\n".join(lines)
