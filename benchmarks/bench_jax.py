"""The JAX rhs vmapped over many states, against a loop of the NumPy rhs and of the C rhs.

For the n-link pendulum (benchmarks/make_pendulum.py; 10 links by default)
gacli writes the three targets, then each evaluates [q', u'] at the same
10,000 seeded random states on the CPU:

    jax     jax.jit(jax.vmap(rhs)) over the whole batch, float64 (compilation not timed)
    numpy   a Python loop calling the generated NumPy module's rhs once per state
    c       a C loop calling the generated <name>_rhs once per state (gcc -O2)

and prints the time per state (the fastest of a few repeats), the speed-up
against the NumPy loop, and the largest relative difference from the NumPy
results.

Usage::

    python benchmarks/bench_jax.py                  # 10 links, 10,000 states
    python benchmarks/bench_jax.py --links 5 --states 100000
"""

from __future__ import annotations

import argparse
import importlib.util
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
# benchmarks/profile.py would shadow the standard library's profile (cProfile imports it).
sys.path[:] = [str(HERE.parent), str(HERE)] + [p for p in sys.path if Path(p or ".").resolve() != HERE]

from make_pendulum import write_pendulum  # noqa: E402

REPEATS = 5

C_LOOP = r"""
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "@NAME@.h"

/* argv[1] states from stdin (@PREFIX@_NX each, after the @PREFIX@_NP parameters); prints the best
   seconds per state over REPEATS loops, then every result. */
int main(int argc, char **argv)
{
    long n = atol(argv[1]), i;
    int j, rep;
    double p[@PREFIX@_NP + 1], *x = malloc(sizeof(double) * @PREFIX@_NX * n), *y = malloc(sizeof(double) * @PREFIX@_NX * n);
    double best = 1e300;
    for (j = 0; j < @PREFIX@_NP; ++j) if (scanf("%lf", &p[j]) != 1) return 3;
    for (i = 0; i < @PREFIX@_NX * n; ++i) if (scanf("%lf", &x[i]) != 1) return 3;
    for (rep = 0; rep < REPEATS; ++rep) {
        struct timespec a, b;
        clock_gettime(CLOCK_MONOTONIC, &a);
        for (i = 0; i < n; ++i) @NAME@_rhs(0.0, x + i * @PREFIX@_NX, p, NULL, y + i * @PREFIX@_NX);
        clock_gettime(CLOCK_MONOTONIC, &b);
        double s = (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
        if (s < best) best = s;
    }
    printf("%.9g\n", best / (double)n);
    for (i = 0; i < @PREFIX@_NX * n; ++i) printf("%.17g\n", y[i]);
    return 0;
}
"""


def emit(path: Path, directory: Path) -> dict[str, str]:
    from gacli.api import emit as emit_format
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    derivation = derive(load(path))
    files = {}
    for fmt in ("python", "c", "jax"):
        for name, text in emit_format(derivation, fmt).items():
            (directory / name).write_text(text, encoding="utf-8")
            files[fmt] = name
    return files


def load_module(path: Path):
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def time_numpy(module, xs, p) -> tuple[float, np.ndarray]:
    best, out = float("inf"), None
    for _ in range(REPEATS):
        start = time.perf_counter()
        out = [module.rhs(0.0, x, p) for x in xs]
        best = min(best, time.perf_counter() - start)
    return best / len(xs), np.array(out)


def time_jax(module, xs, p) -> tuple[float, np.ndarray]:
    import jax

    jax.config.update("jax_enable_x64", True)
    batched = jax.jit(jax.vmap(module.rhs, in_axes=(None, 0, None)))
    xs_, p_ = jax.numpy.asarray(xs), jax.numpy.asarray(p)
    out = batched(0.0, xs_, p_).block_until_ready()  # compile
    best = float("inf")
    for _ in range(REPEATS):
        start = time.perf_counter()
        out = batched(0.0, xs_, p_).block_until_ready()
        best = min(best, time.perf_counter() - start)
    return best / len(xs), np.asarray(out)


def time_c(directory: Path, name: str, xs, p) -> tuple[float, np.ndarray]:
    cc = shutil.which("gcc") or shutil.which("cc")
    if cc is None:
        raise SystemExit("no C compiler (gcc or cc)")
    (directory / "loop.c").write_text(C_LOOP.replace("@NAME@", name).replace("@PREFIX@", name.upper()).replace("REPEATS", str(REPEATS)))
    exe = directory / "loop"
    subprocess.run([cc, "-O2", "-std=c99", str(directory / "loop.c"), str(directory / f"{name}.c"),
                    "-o", str(exe), "-lm"], check=True)
    data = "\n".join(repr(float(v)) for v in [*p, *xs.ravel()])
    result = subprocess.run([str(exe), str(len(xs))], input=data, capture_output=True, text=True, check=True)
    lines = result.stdout.split()
    return float(lines[0]), np.array(lines[1:], dtype=float).reshape(xs.shape)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--links", type=int, default=10)
    parser.add_argument("--states", type=int, default=10_000)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        directory = Path(tmp)
        files = emit(write_pendulum(args.links, directory), directory)
        numpy_module = load_module(directory / files["python"])
        jax_module = load_module(directory / files["jax"])
        p = np.array([numpy_module.DEFAULTS[n] for n in numpy_module.PARAMETERS])
        xs = np.random.default_rng(20261124).uniform(-1.0, 1.0, (args.states, len(numpy_module.STATE)))
        results = {"numpy": time_numpy(numpy_module, xs, p), "jax": time_jax(jax_module, xs, p),
                   "c": time_c(directory, Path(files["c"]).stem, xs, p)}
    reference = results["numpy"][1]
    scale = np.maximum(np.abs(reference), 1.0)
    print(f"{args.links}-link pendulum, {args.states} states, {len(xs[0])} entries each (CPU)")
    print(f"{'target':<8} {'per state':>12} {'vs numpy':>9} {'max rel diff':>13}")
    for label, (seconds, values) in results.items():
        difference = float(np.max(np.abs(values - reference) / scale))
        print(f"{label:<8} {seconds * 1e6:>9.3f} us {results['numpy'][0] / seconds:>8.1f}x {difference:>13.1e}")


if __name__ == "__main__":
    main()
