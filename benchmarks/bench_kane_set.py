"""A set of systems from SymPy's mechanics tests and docs and PyDy's examples: gacli against KanesMethod.

Each system of ``benchmarks/kane_set/`` is written twice, as a gacli system
file and as a KanesMethod model (``kane_set/models.py``) with the same
coordinates, independent speeds and parameters. For each system this script

1. loads and derives the file with gacli (``gacli.load``, ``gacli.derive``,
   ``Derivation.code``) and builds Kane's model, in a worker process under
   ``--timeout`` seconds (some derivations do not finish today);
2. checks that the two agree at 3 random states: q' of the shared
   coordinates and the solved accelerations u' = M^-1 F (Kane's dependent
   speeds solved from its velocity constraints; holonomic constraints met
   by solving the dependent coordinates), for generated code's q', M, F and
   for the closed forms;
3. counts operations of what a rhs evaluates, kinematics, M and F, after the
   one-pass CSE of ``bench_bicycle.operations``: gacli's ``Derivation.code``,
   Kane's ``kindiffdict``, ``mass_matrix`` and ``forcing`` (all speeds, with
   the constraint rows when there are dependent speeds);
4. times ``gacli derive FILE`` (text) and ``gacli derive FILE --format c``
   in fresh processes (CPU seconds of the child), and runs ``gacli check FILE``;
5. counts the characters of the text printout.

Usage::

    python benchmarks/bench_kane_set.py                    # every system, about 6 minutes
    python benchmarks/bench_kane_set.py --only rattleback --timeout 30 --json out.json

See benchmarks/kane_set/README.md for the systems and today's table.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
for entry in (str(HERE / "kane_set"), str(HERE), str(ROOT)):
    if entry not in sys.path:
        sys.path.insert(0, entry)

STATES = 3
TOLERANCE = 1e-8
# Past this many tree nodes in one expression SymPy's cse is not tried: the rattleback's 500,000
# take it 5 s, the bicycle's millions far longer.
SYMPY_CSE_NODES = 1_000_000


# -- the worker: one system, in its own process ---------------------------------------

class Stages:
    """Results written to a JSON file after each stage, so that a killed worker leaves what it did."""

    def __init__(self, path: Path):
        self.path, self.data = path, {"stage": "start"}

    def enter(self, stage: str) -> None:
        self.data["stage"] = stage
        self._write()

    def record(self, **values) -> None:
        self.data.update(values)
        self._write()

    def _write(self) -> None:
        self.path.write_text(json.dumps(self.data, default=str), encoding="utf-8")


def worker(name: str, out: Path, code_only: bool, seed: int) -> None:
    import numpy as np

    from bench_bicycle import operations
    from bench_util import timed
    from models import SYSTEMS

    path, build, _ = SYSTEMS[name]
    stages = Stages(out)
    stages.enter("KanesMethod")
    timing, reference = timed(build)
    model = reference.model
    kane_exprs = [*model.kinematics, *model.mass_matrix, *model.forcing]
    stages.record(kane_s=timing.cpu, ops_kane=operations(kane_exprs)[0])
    stages.enter("gacli code route only" if code_only else "gacli load + derive")
    timing, derivation = timed(lambda: _derive(path, code_only))
    stages.record(gacli_s=timing.cpu)
    stages.enter("gacli Derivation.code")
    code = derivation.code
    ours = [*(e for _, e in code.kinematic_equations), *(e for _, e in code.mass_matrix), *code.forcing]
    stages.record(ops_gacli=operations(ours)[0], route=getattr(code, "route", "?"), k=derivation.k,
                  code_only=code_only)
    stages.enter("agreement")
    rng = np.random.default_rng(seed)
    errors = {"code": [], "closed": []}
    kane = KaneSide(reference)
    forms = {"code": GacliSide(derivation, code.kinematic_equations, dict(code.mass_matrix), code.forcing)}
    if not code_only:
        forms["closed"] = GacliSide(derivation, derivation.kinematic_equations,
                                    derivation.mass_matrix.todok(), list(derivation.forcing))
    for _ in range(STATES):
        values = random_state(derivation, reference, rng)
        theirs = kane.evaluate(values)
        for label, side in forms.items():
            errors[label].append(compare(side.evaluate(values), theirs))
    stages.record(agreement={label: max(e) for label, e in errors.items() if e})
    stages.enter("SymPy cse")
    stages.record(cse_kane=sympy_cse_ops(kane_exprs))
    stages.record(cse_gacli=sympy_cse_ops(ours))
    stages.enter("done")


def sympy_cse_ops(exprs) -> int | None:
    """``count_ops`` after SymPy's canonical ``cse`` (bench_util.cse_count), the issue's counting; None
    when the expressions are too large to walk as trees (the bicycle's are millions of nodes)."""
    from bench_util import cse_count
    from gacli.algebra.graph import is_small

    if not all(is_small(e, SYMPY_CSE_NODES) for e in exprs):
        return None
    return cse_count(exprs).operations


def _derive(path: Path, code_only: bool):
    if code_only:
        # What `gacli derive --format c` does today for a large frame program (gacli.mechanics.code).
        from gacli.loader.loading import load_source
        from gacli.mechanics.equations import derive_for_code
        from gacli.read.source import read_source

        derivation = derive_for_code(load_source(read_source(path), rolling_rows=False))
        if derivation is None:
            raise RuntimeError("no code-only route for this system")
        return derivation
    import gacli

    derivation = gacli.derive(gacli.load(path))
    derivation.code  # noqa: B018 - part of what generated code needs
    return derivation


class GacliSide:
    """q' (every coordinate) and u' = M^-1 F of one of gacli's forms, evaluated as a straight-line program."""

    def __init__(self, derivation, kinematic, mass, forcing):
        import sympy as sp

        from gacli.numeric import Program

        self.k = k = derivation.k
        self.names = [name for name, _ in kinematic]
        exprs = [*(e for _, e in kinematic), *(mass.get((i, j), sp.S.Zero) for i in range(k) for j in range(k)),
                 *forcing]
        self.program = Program(exprs)
        self.speeds = list(derivation.speeds)

    def evaluate(self, values: dict) -> dict:
        import numpy as np
        import sympy as sp

        out = np.real(np.array(self.program(values["gacli"]), dtype=complex))
        n, k = len(self.names), self.k
        udot = np.linalg.solve(out[n:n + k * k].reshape(k, k), out[n + k * k:])
        return {"qdot": dict(zip(self.names, out[:n])), "udot": udot}


class KaneSide:
    """Kane's q', dependent speeds and u' at a state given in gacli's names."""

    def __init__(self, reference):
        import sympy as sp

        from gacli.algebra.graph import substitute
        from gacli.numeric import Program

        model = reference.model
        self.reference = reference
        self.q_plain = {q: sp.Symbol(f"_q_{name}") for q, name in reference.coordinates.items()}
        self.u_plain = {u: sp.Symbol(f"_u{i}") for i, u in enumerate(model.u)}
        functions = {**self.q_plain, **self.u_plain}
        exprs = [*model.kinematics, *model.mass_matrix, *model.forcing]
        self.program = Program(substitute(exprs, functions))
        self.constraints = Program(substitute([sp.sympify(c) for c in model.velocity_constraints], functions)) \
            if model.u_dep else None

    def evaluate(self, values: dict) -> dict:
        import numpy as np
        import sympy as sp

        model, ref = self.reference.model, self.reference
        point = {sym: values["names"][name] for q, sym in self.q_plain.items()
                 for name in [ref.coordinates[q]]}
        point.update({model.parameters[name]: v for name, v in values["parameters"].items()
                      if name in model.parameters})
        point[sp.Symbol("t")] = values.get("time", 0.0)  # dynamicsymbols' time, where a model holds it
        for u, value in zip(model.u_ind, values["speeds"]):
            point[self.u_plain[u]] = value
        dependent = self._dependent(point)
        point.update({self.u_plain[u]: v for u, v in zip(model.u_dep, dependent)})
        out = np.real(np.array(self.program(point), dtype=complex))
        nq, nu = len(model.q), len(model.u)
        udot = np.linalg.solve(out[nq:nq + nu * nu].reshape(nu, nu), out[nq + nu * nu:])
        qdot = {ref.coordinates[q]: out[i] for i, q in enumerate(model.q)}
        qdot.update({name: dependent[model.u_dep.index(u)] for name, u in ref.dependent_rates.items()})
        return {"qdot": qdot, "udot": udot[:len(model.u_ind)]}

    def _dependent(self, point: dict) -> list[float]:
        """Kane's dependent speeds from its velocity constraints, which are linear in them."""
        import numpy as np

        deps = [self.u_plain[u] for u in self.reference.model.u_dep]
        if not deps:
            return []

        def residual(vector):
            return np.real(np.array(self.constraints({**point, **dict(zip(deps, vector))}), dtype=complex))

        b = residual(np.zeros(len(deps)))
        A = np.column_stack([residual(np.eye(len(deps))[j]) - b for j in range(len(deps))])
        return list(np.linalg.lstsq(A, -b, rcond=None)[0])


def random_state(derivation, reference, rng) -> dict:
    """Coordinates, independent speeds and parameters, in gacli's symbols and by name."""
    from gacli.algebra import symbols as S
    from gacli.emit.naming import parameter_defaults

    spread = reference.spread
    parameters = {p.name: float(rng.uniform(0.5, 1.5)) for p in derivation.system.parameters}
    parameters.update(parameter_defaults(derivation.system.parameters))
    # Inputs are values too (a motor torque): random, under the same names on Kane's side.
    parameters.update({i.name: float(rng.uniform(-1.0, 1.0)) for i in derivation.system.inputs})
    names = {c.name: float(rng.uniform(-spread, spread)) for c in derivation.system.coordinates}
    names.update(_configuration(reference, names, parameters))
    speeds = [float(rng.uniform(-1.0, 1.0)) for _ in derivation.speeds]
    values = {S.value(n): v for n, v in {**parameters, **names}.items()}
    values.update(dict(zip(derivation.speeds, speeds)))
    # A support shaken by A sin(w t) has no acceleration at t = 0: a time that tests it.
    time = float(rng.uniform(0.3, 1.2))
    values[S.T] = time
    return {"gacli": values, "names": names, "parameters": parameters, "speeds": speeds, "time": time}


def _configuration(reference, names: dict, parameters: dict) -> dict:
    """The dependent coordinates that satisfy Kane's holonomic constraints, the others held."""
    if not reference.configuration:
        return {}
    import numpy as np
    import sympy as sp
    from scipy.optimize import fsolve

    plain = {q: sp.Symbol(f"_q_{name}") for q, name in reference.coordinates.items()}
    unknown = [plain[q] for q in reference.q_dep]
    fixed = {sym: names[sym.name[3:]] for sym in plain.values() if sym not in unknown}
    fixed.update({s: parameters[n] for n, s in reference.model.parameters.items() if n in parameters})
    exprs = [sp.sympify(c).xreplace(plain).xreplace(fixed) for c in reference.configuration]
    f = sp.lambdify([unknown], exprs, modules="numpy")
    # A coordinate of Kane's model alone (a slider's x the file places by its loop) starts at its guess, or 0.
    guess = [reference.guess.get(reference.coordinates[q], names.get(reference.coordinates[q], 0.0))
             for q in reference.q_dep]
    solution, _, ok, message = fsolve(lambda v: np.array(f(list(v)), dtype=float), guess, full_output=True)
    if ok != 1:
        raise RuntimeError(f"holonomic constraints not met at a random state: {message}")
    return {reference.coordinates[q]: float(v) for q, v in zip(reference.q_dep, solution)}


def compare(ours: dict, theirs: dict) -> float:
    """The largest difference of q' (shared coordinates) and u', relative to max(1, max |Kane|)."""
    import numpy as np

    names = sorted(set(theirs["qdot"]) & set(ours["qdot"]))
    a = np.array([*(ours["qdot"][n] for n in names), *ours["udot"]])
    b = np.array([*(theirs["qdot"][n] for n in names), *theirs["udot"]])
    if a.shape != b.shape:
        return float("inf")
    return float(np.max(np.abs(a - b)) / max(1.0, float(np.max(np.abs(b)))))


# -- the command line, in fresh processes ---------------------------------------------

def child_run(argv: list[str], timeout: float) -> dict:
    """Run a child under ``timeout`` seconds of CPU: its CPU seconds, exit code, output, or a timeout.

    The limit is on CPU time (RLIMIT_CPU), not wall time, so that a system's
    verdict does not depend on what else the shared machine runs; a wall-clock
    guard of four times the limit catches a child that waits instead.
    """
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))}
    limit = max(1, int(round(timeout)))

    def cpu_limit():
        resource.setrlimit(resource.RLIMIT_CPU, (limit, limit + 5))

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall = time.perf_counter()
    try:
        done = subprocess.run(argv, cwd=ROOT, env=env, capture_output=True, text=True, timeout=4 * limit + 30,
                              preexec_fn=cpu_limit)
        result = {"rc": done.returncode, "chars": len(done.stdout), "stderr": done.stderr[-400:],
                  "too_large": "too large to print" in done.stdout,
                  "out_of_time": "ran out of time" in done.stderr}
        if done.returncode in (-signal.SIGXCPU, -signal.SIGKILL):
            result["timeout"] = True
    except subprocess.TimeoutExpired:
        result = {"rc": None, "timeout": True}
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    result["cpu_s"] = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    result["wall_s"] = time.perf_counter() - wall
    return result


def gacli_commands(path: Path, timeout: float) -> dict:
    gacli = [sys.executable, "-m", "gacli"]
    with tempfile.TemporaryDirectory() as scratch:
        return {
            "derive_text": child_run([*gacli, "derive", str(path), "--timeout", "0"], timeout),
            "derive_c": child_run([*gacli, "derive", str(path), "--format", "c", "--output", scratch,
                                   "--timeout", "0"], timeout),
            "check": child_run([*gacli, "check", str(path), "--timeout", f"{timeout:g}"], timeout),
        }


def measure(name: str, options) -> dict:
    from models import SYSTEMS

    path = SYSTEMS[name][0]
    shown = path.relative_to(ROOT) if path.is_relative_to(ROOT) else path
    result = {"system": name, "file": str(shown), "what": SYSTEMS[name][2]}
    result["worker"] = run_worker(name, options, code_only=False)
    if "ops_gacli" not in result["worker"]:
        # The closed forms did not come: measure the route `--format c` takes, if it has one.
        result["code_only"] = run_worker(name, options, code_only=True)
    result.update(gacli_commands(path, options.timeout))
    return result


def run_worker(name: str, options, code_only: bool) -> dict:
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(scratch) / "result.json"
        argv = [sys.executable, __file__, "--worker", name, "--result", str(out), "--seed", str(options.seed)]
        for path in options.extra:
            argv += ["--extra", str(path.resolve())]
        run = child_run([*argv, "--code-only"] if code_only else argv, options.timeout)
        data = json.loads(out.read_text(encoding="utf-8")) if out.exists() else {"stage": "start"}
    data["cpu_s"], data["timeout"] = run["cpu_s"], bool(run.get("timeout"))
    if run.get("rc") not in (0, None) and not run.get("timeout"):
        data["error"] = run.get("stderr", "").strip().splitlines()[-1:] or ["?"]
    return data


# -- the table ------------------------------------------------------------------------

def _seconds(run: dict) -> str:
    if run.get("timeout"):
        return f"timeout ({run['cpu_s']:.0f})"
    if run.get("out_of_time"):
        return f"out of time ({run['cpu_s']:.0f})"
    return f"{run['cpu_s']:.2f}" + ("" if run.get("rc") == 0 else f" (exit {run.get('rc')})")


def _agreement(w: dict, code_only: dict | None) -> str:
    if "agreement" in w:
        worst = max(w["agreement"].values())
        cell = f"{'ok' if worst <= TOLERANCE else 'FAIL'} {worst:.0e}"
    elif w.get("timeout"):
        cell = f"timeout in {w['stage']}"
    else:
        cell = f"error in {w['stage']}: {' '.join(w.get('error', []))[:60]}"
    if code_only and "agreement" in code_only:
        worst = max(code_only["agreement"].values())
        cell += f"; code {'' if worst <= TOLERANCE else 'FAIL '}{worst:.0e}"
    return cell


def row(result: dict) -> list[str]:
    w = result["worker"]
    # When the worker could not finish gacli's derivation, the code-only worker's numbers stand in.
    ops = w if "ops_gacli" in w else result.get("code_only", {})
    kane, ours = w.get("ops_kane"), ops.get("ops_gacli")
    text = result["derive_text"]
    printed = text.get("rc") == 0 and not text.get("too_large")
    return [result["system"], str(ops.get("k", w.get("k", "?"))), _agreement(w, result.get("code_only")),
            f"{kane:,}" if kane else "n/a",
            (f"{ours:,}" if ours else "n/a") + ("" if ops is w else " (code route only)"),
            f"{ours / kane:.2f}" if kane and ours else "n/a", _sympy_cse(w, ops), ops.get("route", "n/a"),
            _seconds(text), _seconds(result["derive_c"]), _check(result["check"]), _chars(text),
            f"{text['chars'] / ours:.0f}" if printed and ours else "n/a",
            f"{w['gacli_s']:.2f}" if "gacli_s" in w else "n/a", f"{w['kane_s']:.2f}" if "kane_s" in w else "n/a"]


def _sympy_cse(w: dict, ops: dict) -> str:
    theirs = ops if "cse_kane" in ops else w
    cell = f"{_cse_cell(ops, 'cse_gacli')} / {_cse_cell(theirs, 'cse_kane')}"
    if ops.get("cse_gacli") and theirs.get("cse_kane"):
        cell += f" = {ops['cse_gacli'] / theirs['cse_kane']:.2f}"
    return cell


def _check(check: dict) -> str:
    cell = "timeout" if check.get("timeout") else str(check["rc"])
    return cell + (" (ran out of time)" if check.get("out_of_time") else "")


def _chars(text: dict) -> str:
    if text.get("rc") != 0:
        return "n/a"
    return f"{text['chars']:,}" + (" (too large to print)" if text.get("too_large") else "")


def _cse_cell(run: dict, key: str) -> str:
    if key not in run:
        return "timeout" if run.get("timeout") else "n/a"
    return "too large" if run[key] is None else f"{run[key]:,}"


HEADER = ["system", "k", "agree (max rel., 3 states)", "ops Kane", "ops gacli", "gacli/Kane",
          "SymPy cse: gacli / Kane", "route",
          "derive text [s CPU]", "derive C [s CPU]", "check exit", "text chars", "chars/op", "gacli API [s CPU]",
          "Kane [s CPU]"]


def print_table(info: dict, timeout: float, results: list[dict]) -> None:
    from bench_report import markdown

    print(f"# The Kane set: gacli against SymPy's KanesMethod (timeout {timeout:g} s CPU per process)\n")
    print(f"machine: {info['platform']}, {info['cpu_count']} CPUs; Python {info['python']}, "
          f"SymPy {info['sympy']}, gacli {info['gacli']}\n")
    print(markdown(HEADER, [row(r) for r in results]))


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", help="one system, or several separated by commas")
    parser.add_argument("--timeout", type=float, default=60.0, help="CPU seconds per process (default 60)")
    parser.add_argument("--seed", type=int, default=20261126, help="the random states")
    parser.add_argument("--json", type=Path, help="also save every number here")
    parser.add_argument("--from-json", type=Path, help="print the table of a saved run instead of running")
    parser.add_argument("--extra", type=Path, action="append", default=[],
                        help="a Python file whose SYSTEMS (as in kane_set/models.py) join the set (repeatable)")
    parser.add_argument("--variants", action="store_true",
                        help="the variants written as new users would (kane_set/variants/*/models_*.py) instead of "
                             "the set; with --only, any of both")
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    parser.add_argument("--result", type=Path, help=argparse.SUPPRESS)
    parser.add_argument("--code-only", action="store_true", help=argparse.SUPPRESS)
    return parser.parse_args(argv)


_BASE: set = set()  # the set's own systems, before any variants join it
VARIANTS = sorted((HERE / "kane_set" / "variants").glob("*/models_*.py"))


def _join_extra(paths: list[Path]) -> None:
    """Add the systems of files written beside the set (the variants, or one tried by hand)."""
    import importlib.util

    import models

    for path in paths:
        spec = importlib.util.spec_from_file_location(f"kane_set_{path.stem}", path)
        extra = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(extra)
        models.SYSTEMS.update(extra.SYSTEMS)


def main(argv=None) -> int:
    options = parse(argv)
    from models import SYSTEMS as base

    _BASE.update(base)
    if options.variants:
        options.extra = [*VARIANTS, *options.extra]
    _join_extra(options.extra)
    if options.worker:
        worker(options.worker, options.result, options.code_only, options.seed)
        return 0
    if options.from_json:
        saved = json.loads(options.from_json.read_text(encoding="utf-8"))
        print_table(saved["machine"], saved["timeout"], saved["results"])
        return 0
    from bench_report import machine
    from models import SYSTEMS

    names = options.only.split(",") if options.only else [n for n in SYSTEMS if n not in _BASE or not options.variants]
    unknown = sorted(set(names) - set(SYSTEMS))
    if unknown:
        print(f"unknown system(s) {', '.join(unknown)}; the set: {', '.join(SYSTEMS)}", file=sys.stderr)
        return 2
    results, start = [], time.perf_counter()
    for name in names:
        print(f"{name} ... ({time.perf_counter() - start:.0f} s so far)", file=sys.stderr, flush=True)
        results.append(measure(name, options))
    info = machine()
    print_table(info, options.timeout, results)
    if options.json:
        options.json.write_text(json.dumps({"machine": info, "timeout": options.timeout, "results": results},
                                           indent=2, default=str), encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
