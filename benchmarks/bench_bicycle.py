"""The Whipple bicycle: gacli against SymPy's KanesMethod, in one run.

gacli derives ``systems/whipple_bicycle.yaml``; KanesMethod derives the
model of SymPy's own bicycle test (``bench_kane.whipple_bicycle``), the same
bicycle in the same angles. For each tool the table gives the derivation time
(best of ``--repeat`` interleaved rounds, SymPy's cache cleared before each)
and the operation count of what a rhs evaluates (kinematics, M, F) after
common-subexpression elimination. Both counts use the same one-pass CSE over
distinct subexpressions (``gacli.algebra.graph.shared_subexpressions``): SymPy's
canonical ``cse`` sorts arguments by tree size, and as trees the bicycle's
equations are millions of nodes. Kane's M and F are 6 x 6 and 6 x 1 (all six
speeds, with the constraint rows); gacli's are 3 x 3 and 3 x 1.

Before anything is reported, both are evaluated at a random state (the
paper's parameter values) and must agree: the accelerations of roll, rear
wheel and steer, and the rates of yaw, pitch and front wheel.

Usage::

    python benchmarks/bench_bicycle.py                 # best of 3, wall clock
    python benchmarks/bench_bicycle.py --clock cpu --repeat 5 --json bicycle.json
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np
import sympy as sp
from sympy.core.cache import clear_cache
from sympy.physics import mechanics as me

import bench_kane
from bench_report import machine, markdown
from bench_util import timed

ROOT = Path(__file__).resolve().parent.parent
BICYCLE = ROOT / "systems" / "whipple_bicycle.yaml"
TOLERANCE = 1e-9
# gacli's names of Kane's coordinates and speeds (see bench_kane.whipple_bicycle).
KANE_NAMES = {"q1": "yaw", "q2": "roll", "q4": "pitch", "q5": "steer",
              "u1": "dot(yaw)", "u2": "dot(roll)", "u3": "dot(wheel_R)", "u4": "dot(pitch)",
              "u5": "dot(steer)", "u6": "dot(wheel_F)"}


def derive_gacli():
    """What `gacli derive --format c` derives: the straight-line program alone (gacli.mechanics.code),
    from a system loaded without the rolling rows in N that only the closed forms need."""
    from gacli.loader.loading import load_source
    from gacli.mechanics.equations import derive_for_code
    from gacli.read.source import read_source

    derivation = derive_for_code(load_source(read_source(BICYCLE), rolling_rows=False))
    derivation.code  # noqa: B018 - the inlined q', M, F the emitters print
    return derivation


def derive_gacli_closed():
    """gacli's closed forms (eq. 14.19 as the chapter writes it), what text, LaTeX and verify read."""
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    return derive(load(BICYCLE))


def derive_kane():
    model = bench_kane.whipple_bicycle()
    model.mass_matrix, model.forcing  # noqa: B018 - part of the derivation
    return model


def operations(exprs) -> tuple[int, int]:
    """(count_ops after the one-pass CSE, number of temporaries)."""
    from gacli.algebra.graph import shared_subexpressions

    replacements, reduced = shared_subexpressions(list(exprs), sp.numbered_symbols("_t"))
    ops = sum(sp.count_ops(v) for _, v in replacements) + sum(sp.count_ops(e) for e in reduced)
    return int(ops), len(replacements)


def plain_kane(model) -> tuple[list[sp.Expr], dict[str, sp.Symbol]]:
    """Kane's kinematics, M, F with q(t), u(t) as plain symbols named as gacli names them."""
    from gacli.algebra.graph import substitute

    t = me.dynamicsymbols._t
    functions = {f: sp.Symbol(KANE_NAMES[f.func.__name__]) for f in model.q + model.u}
    exprs = [*model.kinematics, *model.mass_matrix, *model.forcing]
    exprs = [e.xreplace({f.diff(t): sp.Symbol(f"_d{f.func.__name__}") for f in model.q}) for e in exprs]
    return substitute(exprs, functions), {name: sym for name, sym in model.parameters.items()}


def agreement(derivation, model, seed: int) -> tuple[float, dict]:
    """The largest relative difference between the two at a random state."""
    from gacli.algebra import symbols as S
    from gacli.emit.naming import parameter_defaults
    from gacli.numeric import Program

    rng = np.random.default_rng(seed)
    values: dict[sp.Symbol, float] = {S.value(name): float(v) for name, v in
                                      parameter_defaults(derivation.system.parameters).items()}
    for c in derivation.system.coordinates:
        values[S.value(c.name)] = float(rng.uniform(-0.3, 0.3))
    for u in derivation.speeds:
        values[u] = float(rng.uniform(-1.0, 1.0))
    values[S.T] = 0.0
    # gacli: the kinematic equations give the dependent rates; M u' = F the accelerations.
    k, n = derivation.k, len(derivation.coordinates)
    code = derivation.code
    dense = dict(code.mass_matrix)
    ours = Program([*(e for _, e in code.kinematic_equations), *(dense.get((i, j), sp.S.Zero) for i in range(k)
                                                                  for j in range(k)), *code.forcing])
    out = np.real(ours(values))
    qdot = dict(zip((c.name for c in derivation.system.coordinates), out[:n]))
    udot = np.linalg.solve(out[n:n + k * k].reshape(k, k), out[n + k * k:])
    # Kane: the dependent speeds are the rates gacli found (checked below against
    # Kane's own constraints), the rest as above.
    exprs, parameters = plain_kane(model)
    kane_values = {sym: values[S.value(name)] for name, sym in parameters.items()}
    for name in ("yaw", "roll", "pitch", "steer"):
        kane_values[sp.Symbol(name)] = values[S.value(name)]
    for name in ("roll", "wheel_R", "steer"):
        kane_values[sp.Symbol(f"dot({name})")] = values[S.rate(name)]
    for name in ("yaw", "pitch", "wheel_F"):
        kane_values[sp.Symbol(f"dot({name})")] = qdot[name]
    constraints = Program([sp.sympify(c) for c in _plain_constraints(model)])
    residual = np.max(np.abs(constraints(kane_values)))
    theirs = np.real(Program(exprs)(kane_values))
    nq, nu = len(model.q), len(model.u)
    M = theirs[nq:nq + nu * nu].reshape(nu, nu)
    kane_udot = np.linalg.solve(M, theirs[nq + nu * nu:])
    ours_v = np.array([*udot, qdot["yaw"], qdot["pitch"], qdot["wheel_F"]])
    kane_v = np.array([*kane_udot[:3], kane_values[sp.Symbol("dot(yaw)")], kane_values[sp.Symbol("dot(pitch)")],
                       kane_values[sp.Symbol("dot(wheel_F)")]])
    scale = max(1.0, float(np.max(np.abs(kane_v))))
    error = max(float(np.max(np.abs(ours_v - kane_v))) / scale, float(residual) / scale)
    return error, {"gacli": ours_v.tolist(), "kane": kane_v.tolist(), "constraint_residual": float(residual)}


def _plain_constraints(model):
    from gacli.algebra.graph import substitute

    functions = {f: sp.Symbol(KANE_NAMES[f.func.__name__]) for f in model.q + model.u}
    return substitute([sp.sympify(c) for c in model.velocity_constraints], functions)


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=3, help="derivation rounds of both tools, best kept (default 3)")
    parser.add_argument("--clock", choices=("wall", "cpu"), default="wall", help="time.perf_counter or process_time")
    parser.add_argument("--seed", type=int, default=2007, help="the random state of the agreement check")
    parser.add_argument("--json", type=Path, help="also save the results here")
    return parser.parse_args(argv)


def main(argv=None) -> int:
    options = parse(argv)
    tools = {"gacli": derive_gacli, "closed": derive_gacli_closed, "kane": derive_kane}
    best = {name: math.inf for name in tools}
    results = {}
    for _ in range(max(1, options.repeat)):
        for name, run in tools.items():
            clear_cache()
            timing, results[name] = timed(run)
            best[name] = min(best[name], timing.get(options.clock))
        print("round: " + ", ".join(f"{n} {best[n]:.2f} s" for n in tools) + " (best so far)", file=sys.stderr)
    derivation, closed, model = results["gacli"], results["closed"], results["kane"]
    error, state = agreement(derivation, model, options.seed)
    error_closed, _ = agreement(closed, model, options.seed)
    if max(error, error_closed) > TOLERANCE:
        print(f"MISMATCH: gacli and KanesMethod differ by {max(error, error_closed):.2e} (relative)", file=sys.stderr)
        return 1
    code = derivation.code
    ops = {"gacli": operations([*(e for _, e in code.kinematic_equations), *(e for _, e in code.mass_matrix),
                                *code.forcing]),
           "closed": operations([*(e for _, e in closed.kinematic_equations), *closed.mass_matrix, *closed.forcing]),
           "kane": operations([*model.kinematics, *model.mass_matrix, *model.forcing])}
    clock = "s CPU" if options.clock == "cpu" else "s"
    label = {"gacli": "gacli, generated code (program)", "closed": "gacli, closed forms"}
    rows = [[label[n], f"{best[n]:.3f}", f"{best['kane']:.2f}", f"{best['kane'] / best[n]:.2f}x",
             f"{ops['kane'][0]:,}", f"{ops[n][0]:,}", f"{ops[n][0] / ops['kane'][0]:.2f}",
             f"ok {(error if n == 'gacli' else error_closed):.0e}"] for n in ("gacli", "closed")]
    info = machine()
    print("# The Whipple bicycle: gacli vs SymPy KanesMethod\n")
    print(f"machine: {info['platform']}, {info['cpu_count']} CPUs; Python {info['python']}, "
          f"SymPy {info['sympy']}, gacli {info['gacli']}\n")
    print(markdown(["case", f"derive gacli [{clock}]", f"derive Kane [{clock}]", "Kane/gacli",
                    "ops Kane", "ops gacli", "gacli/Kane", "agree"], rows))
    print(f"\nops: count_ops after one-pass CSE of kinematics, M and F ({ops['kane'][1]:,} temporaries for Kane, "
          f"{ops['gacli'][1]:,} for gacli's code); Kane's M is {model.mass_matrix.shape[0]}x{model.mass_matrix.shape[1]}, "
          f"gacli's {derivation.k}x{derivation.k}. The code route is what `gacli derive --format c` does: "
          "read, load without the rolling rows in N, the straight-line program (gacli.mechanics.code).")
    if options.json:
        options.json.write_text(json.dumps({"machine": info, "derive_s": best, "clock": options.clock,
                                            "ops": {n: v[0] for n, v in ops.items()},
                                            "agreement": error, "state": state}, indent=2), encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
