"""C for the benchmark: SymPy's C printer on CSE'd equations, a timing driver, the build.

``rhs_source`` prints what a SymPy user writes by hand around
``sympy.printing.c.C99CodePrinter``: the CSE'd kinematics, M and F of
KanesMethod in one function with gacli's signature

    int NAME(double t, const double *x, const double *p, const double *r, double *xdot)

followed by a dense solve of M u' = F: Cholesky when M is symmetric (only
its lower triangle is printed then), Gaussian elimination with partial
pivoting otherwise (KanesMethod's M with nonholonomic constraints is not
symmetric).

``DRIVER`` is a small main() that reads t, x, p, r from stdin, prints
xdot from one call (for the agreement check), then times the rhs in a
loop: calls doubled until a batch takes about 1 ms, then the fastest of
the batches run in the requested time (a batch that short is rarely
interrupted, so the fastest filters out other load on the machine). The rhs is compiled in its own translation unit (no LTO), so
the compiler cannot hoist the call out of the loop.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from collections.abc import Sequence
from pathlib import Path

import sympy as sp
from sympy.printing.c import C99CodePrinter

DEFAULT_CFLAGS = ("-O2",)

DRIVER = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

int RHS(double t, const double *x, const double *p, const double *r, double *xdot);

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double *read_vector(int n)
{
    double *v = calloc((size_t)n + 1, sizeof(double));
    int i;
    for (i = 0; i < n; i++)
        if (scanf("%lf", &v[i]) != 1) exit(3);
    return v;
}

int main(int argc, char **argv)
{
    double min_time = argc > 1 ? atof(argv[1]) : 0.1;
    int nx, ny, np, nr, i, rep, status;
    long n = 1, j;
    double t, *x, *p, *r, *xdot, start, elapsed, best, total, sink = 0.0;
    if (scanf("%lf %d %d %d %d", &t, &nx, &ny, &np, &nr) != 5) return 3;
    x = read_vector(nx); p = read_vector(np); r = read_vector(nr);
    xdot = calloc((size_t)ny + 1, sizeof(double));
    status = RHS(t, x, p, r, xdot);
    printf("status %d\n", status);
    for (i = 0; i < ny; i++) printf("%.17g\n", xdot[i]);
    /* calls per batch: doubled until a batch takes about 1 ms */
    for (;;) {
        start = now();
        for (j = 0; j < n; j++) { RHS(t, x, p, r, xdot); sink += xdot[0]; }
        elapsed = now() - start;
        if (elapsed >= 1e-3 || n > 100000000L) break;
        n *= 2;
    }
    /* the fastest of the batches run in min_time (at least 5) */
    best = elapsed / (double)n;
    total = now();
    for (rep = 0; rep < 5 || (now() - total < min_time && rep < 100000); rep++) {
        start = now();
        for (j = 0; j < n; j++) { RHS(t, x, p, r, xdot); sink += xdot[0]; }
        elapsed = (now() - start) / (double)n;
        if (elapsed < best) best = elapsed;
    }
    printf("seconds_per_call %.6e\n", best);
    printf("calls_per_batch %ld\n", n);
    fprintf(stderr, "sink %g\n", sink);
    return 0;
}
"""

CHOLESKY = r"""
    /* M = L L^T in place (lower triangle), then forward and back substitution. */
    {
        int i, j, s;
        for (j = 0; j < K; j++) {
            double d = M[j * K + j];
            for (s = 0; s < j; s++) d -= M[j * K + s] * M[j * K + s];
            if (!(d > 0.0)) return 1;
            d = sqrt(d);
            M[j * K + j] = d;
            for (i = j + 1; i < K; i++) {
                double v = M[i * K + j];
                for (s = 0; s < j; s++) v -= M[i * K + s] * M[j * K + s];
                M[i * K + j] = v / d;
            }
        }
        for (i = 0; i < K; i++) {
            double v = F[i];
            for (s = 0; s < i; s++) v -= M[i * K + s] * F[s];
            F[i] = v / M[i * K + i];
        }
        for (i = K - 1; i >= 0; i--) {
            double v = F[i];
            for (s = i + 1; s < K; s++) v -= M[s * K + i] * F[s];
            F[i] = v / M[i * K + i];
        }
    }
"""

GAUSS = r"""
    /* Gaussian elimination with partial pivoting, then back substitution. */
    {
        int i, j, s, pivot;
        for (j = 0; j < K; j++) {
            double big = fabs(M[j * K + j]);
            pivot = j;
            for (i = j + 1; i < K; i++)
                if (fabs(M[i * K + j]) > big) { big = fabs(M[i * K + j]); pivot = i; }
            if (!(big > 0.0)) return 1;
            if (pivot != j) {
                double swap;
                for (s = j; s < K; s++) { swap = M[j * K + s]; M[j * K + s] = M[pivot * K + s]; M[pivot * K + s] = swap; }
                swap = F[j]; F[j] = F[pivot]; F[pivot] = swap;
            }
            for (i = j + 1; i < K; i++) {
                double factor = M[i * K + j] / M[j * K + j];
                for (s = j + 1; s < K; s++) M[i * K + s] -= factor * M[j * K + s];
                F[i] -= factor * F[j];
            }
        }
        for (i = K - 1; i >= 0; i--) {
            double v = F[i];
            for (s = i + 1; s < K; s++) v -= M[i * K + s] * F[s];
            F[i] = v / M[i * K + i];
        }
    }
"""


def rhs_source(name: str, replacements, reduced, *, n: int, k: int, symmetric: bool,
               x: Sequence[sp.Symbol], p: Sequence[sp.Symbol], r: Sequence[sp.Symbol]) -> str:
    """A C rhs from a CSE of [kinematics (n), M (k*k, row-major), F (k)].

    Only the entries that are used are printed (M's lower triangle when
    symmetric); temporaries that only the others need are left to the
    compiler's dead-code elimination.
    """
    printer = C99CodePrinter({"math_macros": {}})
    lines = ["#include <math.h>", "", f"#define K {k}", "",
             f"int {name}(double t, const double *x, const double *p, const double *r, double *xdot)", "{",
             "    double M[K * K], F[K];", "    (void)t; (void)r;"]
    lines += [f"    const double {s} = x[{i}];" for i, s in enumerate(x)]
    lines += [f"    const double {s} = p[{i}];" for i, s in enumerate(p)]
    lines += [f"    const double {s} = r[{i}];" for i, s in enumerate(r)]
    lines += [f"    const double {s} = {printer.doprint(v)};" for s, v in replacements]
    kinematics, mass, forcing = reduced[:n], reduced[n:n + k * k], reduced[n + k * k:]
    lines += [f"    xdot[{i}] = {printer.doprint(e)};" for i, e in enumerate(kinematics)]
    for i in range(k):
        for j in range(i + 1 if symmetric else k):
            lines.append(f"    M[{i * k + j}] = {printer.doprint(mass[i * k + j])};")
    lines += [f"    F[{i}] = {printer.doprint(e)};" for i, e in enumerate(forcing)]
    lines.append(CHOLESKY if symmetric else GAUSS)
    lines += [f"    for (int i = 0; i < K; i++) xdot[{n} + i] = F[i];", "    return 0;", "}", ""]
    return "\n".join(lines)


def compiler() -> str | None:
    return os.environ.get("CC") or shutil.which("gcc") or shutil.which("cc") or shutil.which("clang")


def build(directory: Path, sources: dict[str, str], rhs_name: str, cflags: Sequence[str]) -> Path:
    """Write the sources and the driver, compile each unit, link; returns the executable.

    Raises:
        RuntimeError: with the compiler's output when a step fails.
    """
    cc = compiler()
    if cc is None:
        raise RuntimeError("no C compiler")
    directory.mkdir(parents=True, exist_ok=True)
    for filename, text in sources.items():
        (directory / filename).write_text(text, encoding="utf-8")
    (directory / "bench_driver.c").write_text(DRIVER, encoding="utf-8")
    objects = []
    units = [f for f in sources if f.endswith(".c")] + ["bench_driver.c"]
    for unit in units:
        obj = directory / (unit[:-2] + ".o")
        defines = [f"-DRHS={rhs_name}"] if unit == "bench_driver.c" else []
        _run([cc, "-std=c99", *cflags, *defines, "-I", str(directory), "-c", str(directory / unit), "-o", str(obj)])
        objects.append(str(obj))
    exe = directory / "bench_rhs"
    _run([cc, *cflags, *objects, "-o", str(exe), "-lm"])
    return exe


def _run(command: list[str]) -> None:
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command[:3])} ... failed:\n{done.stderr.strip()[:2000]}")


def time_rhs(exe: Path, t: float, x, p, r, ny: int, min_time: float) -> tuple[list[float], float, int]:
    """(xdot from one call, seconds per call, the status the rhs returned)."""
    numbers = " ".join(repr(float(v)) for v in [*x, *p, *r])
    text = f"{float(t)!r} {len(x)} {ny} {len(p)} {len(r)} {numbers}\n"
    done = subprocess.run([str(exe), repr(min_time)], input=text, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise RuntimeError(f"{exe.name} exited with {done.returncode}: {done.stderr.strip()[:500]}")
    lines = done.stdout.split()
    status = int(lines[1])
    xdot = [float(v) for v in lines[2:2 + ny]]
    seconds = float(lines[lines.index("seconds_per_call") + 1])
    return xdot, seconds, status


def rhs_function_name(c_text: str) -> str | None:
    """The name of ``int <name>_rhs(...)`` in an emitted C source or header."""
    match = re.search(r"\bint\s+(\w+_rhs)\s*\(", c_text)
    return match[1] if match else None
