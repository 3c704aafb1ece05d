"""gacli against SymPy's KanesMethod: derivation time, operation counts, rhs speed, cold start.

In one run on one machine, each case is derived by gacli (``load`` +
``derive``) and by ``KanesMethod`` with the same coordinates and speeds;
both right-hand sides are checked to agree at a random state (relative
1e-8) before anything is timed. Then, per case:

* derivation time of each tool (best of a few, SymPy's cache cleared first);
* ``count_ops`` of the CSE of the kinematics, M and F of each tool, and of
  what gacli's code generator actually CSE's for its ``rhs``;
* time per call of gacli's generated C and Python ``rhs``, of
  ``KanesMethod`` + ``lambdify(cse=True)`` + ``numpy.linalg.solve``, and of
  SymPy's C printer on KanesMethod's CSE'd M and F with a dense solve;

and once per run, the cold-start time of ``gacli --help`` and of
``gacli derive systems/sphere_on_turntable.yaml``. Parts of gacli that do
not exist yet (an emitter) are shown as n/a, with the reason listed below
the tables.

Usage::

    python benchmarks/run.py                         # default cases and sizes
    python benchmarks/run.py --quick                 # a smoke run
    python benchmarks/run.py --cases pendulum --sizes 1,5,10,20,30 --json out.json

See benchmarks/README.md for the columns.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.util
import json
import math
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import sympy as sp
from sympy.core.cache import clear_cache

import bench_c
from bench_cases import CASE_NAMES, DEFAULT_CASES, ROOT, Case, cases
from bench_fresh import fresh_rows
from bench_report import TOLERANCE, cold_start, machine, report
from bench_util import (
    Equations, Timing, cse_count, counted, lambdify_rhs, per_call, plain_symbols,
    random_values, relative_error, timed,
)

DEFAULT_SIZES = (1, 5, 10, 20)
DEFAULT_CHAIN_SIZES = (1, 2, 3)
QUICK_SIZES = (1, 5)
QUICK_CHAIN_SIZES = (1,)


class NotAvailable(Exception):
    """A part of the comparison that cannot run (yet): shown as n/a, with this reason."""


# -- the gacli side ------------------------------------------------------------------

def derive_gacli(path: Path):
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    return derive(load(path))


def gacli_slots(derivation):
    """The symbols of x, p and r in the order of gacli's generated code."""
    try:
        from gacli.emit.naming import layout
    except ImportError:
        from gacli.algebra import symbols as S

        system = derivation.system
        return (tuple(derivation.state), tuple(S.value(p.name) for p in system.parameters),
                tuple(S.value(i.name) for i in system.inputs) + tuple(S.value(f.name) for f in system.free_functions))
    lay = layout(derivation)
    return lay.state_symbols, lay.parameter_symbols, lay.r_symbols


def gacli_equations(derivation) -> tuple[Equations, list[str]]:
    """gacli's kinematics, M, F in plain symbols, and the parameter names in order."""
    X, P, R = gacli_slots(derivation)
    x, p, r = plain_symbols("x", len(X)), plain_symbols("p", len(P)), plain_symbols("r", len(R))
    sub = dict(zip((*X, *P, *R), (*x, *p, *r)))
    kinematics = tuple(sp.sympify(e).xreplace(sub) for _, e in derivation.kinematic_equations)
    eqs = Equations(kinematics, derivation.mass_matrix.xreplace(sub), derivation.forcing.xreplace(sub),
                    tuple(x), tuple(p), tuple(r))
    _check_symbols(eqs, "gacli")
    return eqs, [s.name for s in P]


def _check_symbols(eqs: Equations, who: str) -> None:
    known = {*eqs.x, *eqs.p, *eqs.r, sp.Symbol("t", real=True)}
    stray = set().union(*(sp.sympify(e).free_symbols for e in eqs.expressions())) - known
    if stray or any(sp.sympify(e).has(sp.Derivative) for e in eqs.expressions()):
        raise RuntimeError(f"{who}: the equations hold symbols outside x, p, r: {sorted(map(str, stray))}")


def parameter_defaults(derivation) -> dict[str, float]:
    """The parameter values the system file gives (empty when gacli's naming module is missing)."""
    try:
        from gacli.emit.naming import parameter_defaults as defaults
    except ImportError:
        return {}
    return defaults(derivation.system.parameters)


# -- the KanesMethod side ------------------------------------------------------------

def kane_equations(model, parameter_names: list[str]) -> tuple[Equations, dict]:
    """KanesMethod's kinematics, M, F in plain symbols; x = (q, u_ind, u_dep)."""
    x = plain_symbols("x", len(model.q) + len(model.u))
    p = plain_symbols("p", len(parameter_names))
    sub = dict(zip(model.q + model.u, x))
    missing = sorted(set(model.parameters) - set(parameter_names))
    if missing:
        raise RuntimeError(f"KanesMethod model has parameters the system file lacks: {missing}")
    sub.update({model.parameters[name]: p[j] for j, name in enumerate(parameter_names) if name in model.parameters})
    kinematics = tuple(sp.sympify(e).xreplace(sub) for e in model.kinematics)
    eqs = Equations(kinematics, sp.ImmutableMatrix(model.mass_matrix).xreplace(sub),
                    sp.ImmutableMatrix(model.forcing).xreplace(sub), tuple(x), tuple(p), ())
    _check_symbols(eqs, "KanesMethod")
    return eqs, sub


def dependent_speeds(model, sub, x_ind: list[float], p: list[float], eqs: Equations) -> list[float]:
    """KanesMethod's dependent speeds at a state, from its velocity constraints (linear in them)."""
    if not model.u_dep:
        return []
    nq, ni = len(model.q), len(model.u_ind)
    dep = list(eqs.x[nq + ni:])
    constraints = sp.Matrix([sp.sympify(c).xreplace(sub) for c in model.velocity_constraints])
    A = constraints.jacobian(dep)
    b = constraints.xreplace({d: 0 for d in dep})
    values = dict(zip(eqs.x[:nq + ni], x_ind)) | dict(zip(eqs.p, p))
    A_num = np.array(A.xreplace(values).evalf().tolist(), dtype=float)
    b_num = np.array(b.xreplace(values).evalf().tolist(), dtype=float).ravel()
    return [float(v) for v in np.linalg.solve(A_num, -b_num)]


# -- gacli's generated code ------------------------------------------------------------

_CSE_CALLS: list | None = None
_ORIGINAL_CSE = sp.cse


def _recording_cse(*args, **kwargs):
    result = _ORIGINAL_CSE(*args, **kwargs)
    if _CSE_CALLS is not None:
        _CSE_CALLS.append((args[0] if args else kwargs.get("exprs"), result))
    return result


@contextlib.contextmanager
def recording_cse():
    """Record every ``sympy.cse`` call an emitter makes: (expressions, (replacements, reduced))."""
    global _CSE_CALLS
    calls: list = []
    targets = [sp] + [m for name, m in list(sys.modules.items())
                      if name.startswith("gacli") and getattr(m, "cse", None) is _ORIGINAL_CSE]
    _CSE_CALLS = calls
    for module in targets:
        module.cse = _recording_cse
    # Equations too large for SymPy's canonical cse go through gacli's one-pass CSE.
    try:
        import gacli.emit.printers as printers
    except ImportError:
        printers = None
    one_pass = getattr(printers, "shared_subexpressions", None)
    if one_pass is not None:
        def recording_one_pass(exprs, symbols):
            result = one_pass(exprs, symbols)
            calls.append((exprs, result))
            return result
        printers.shared_subexpressions = recording_one_pass
    try:
        yield calls
    finally:
        for module in targets:
            module.cse = _ORIGINAL_CSE
        if one_pass is not None:
            printers.shared_subexpressions = one_pass
        _CSE_CALLS = None


def emit(derivation, fmt: str):
    """gacli's generated files for ``fmt`` and the CSE calls made; NotAvailable if the emitter is missing or fails."""
    try:
        from gacli.api import emit as api_emit
    except Exception as error:  # noqa: BLE001 - any failure means the emitter is not usable yet
        raise NotAvailable(f"gacli.api: {type(error).__name__}: {error}") from None
    try:
        with recording_cse() as calls:
            files = api_emit(derivation, fmt)
    except Exception as error:  # noqa: BLE001
        raise NotAvailable(f"emit({fmt!r}): {type(error).__name__}: {str(error).splitlines()[0] if str(error) else ''}") from None
    return files, calls


def emitted_rhs_ops(calls, derivation) -> int | None:
    """count_ops of the emitter's CSE for its rhs: the call that holds all of F and the kinematics.

    (The emitters also CSE M and F alone for ``mass_matrix`` and ``forcing``.)
    """
    code = derivation.code  # what the emitters print: the closed forms or the program (gacli.mechanics.code)
    wanted = {sp.sympify(e) for e in code.forcing} | {sp.sympify(e) for _, e in code.kinematic_equations}
    wanted.discard(sp.S.Zero)
    candidates = [(list(exprs), result) for exprs, result in calls
                  if exprs is not None and wanted <= {sp.sympify(e) for e in exprs}]
    if not candidates:
        return None
    _, (replacements, reduced) = max(candidates, key=lambda c: len(c[0]))
    return counted(replacements, reduced).operations


def load_module(text: str, directory: Path, name: str):
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / f"{name}.py"
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location(f"bench_generated_{name}_{os.getpid()}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _faster(a: Timing, b: Timing) -> Timing:
    """The best of two timings, clock by clock."""
    return Timing(min(a.wall, b.wall), min(a.cpu, b.cpu))


# -- one case -------------------------------------------------------------------------

class CaseRun:
    """Runs one case stage by stage; a stage that fails leaves n/a and a note, and the rest goes on."""

    def __init__(self, case: Case, options, scratch: Path) -> None:
        self.case, self.options = case, options
        self.scratch = scratch / case.label.replace(" ", "_").replace("=", "")
        self.row: dict = {"case": case.name, "size": case.size, "label": case.label,
                          "system_file": str(case.path), "notes": []}
        self.agreed = False

    def note(self, text: str) -> None:
        self.row["notes"].append(text)
        if self.options.verbose:
            print(f"    {self.case.label}: {text}", file=sys.stderr)

    def stage(self, name: str, fn):
        try:
            return fn()
        except NotAvailable as reason:
            self.note(f"{name}: n/a ({reason})")
        except Exception as error:  # noqa: BLE001 - a benchmark reports and carries on
            self.note(f"{name}: failed ({type(error).__name__}: {str(error).strip()[:300]})")
        return None

    def progress(self, text: str) -> None:
        if not self.options.silent:
            print(f"[{time.strftime('%H:%M:%S')}] {self.case.label}: {text}", file=sys.stderr, flush=True)

    def run(self) -> dict:
        self.progress("derivations (gacli and KanesMethod, interleaved)")
        derived = self.stage("derivation", self.derive_both)
        if derived is None:
            return self.row
        derivation, geq, names, kane = derived
        if self.case.kane is None:
            self.note("KanesMethod: n/a (no KanesMethod model of this system in bench_kane.py)")
        self.progress("operation counts")
        self.stage("ops gacli", lambda: self.count_gacli(geq))
        if kane:
            self.stage("ops KanesMethod", lambda: self.count_kane(kane[1]))
        self.progress("agreement at a random state")
        state = self.stage("agreement", lambda: self.sample(derivation, geq, names, kane))
        if state is None:
            return self.row
        self.progress("generated code")
        self.stage("gacli Python rhs", lambda: self.gacli_python(derivation, state))
        self.stage("gacli C rhs", lambda: self.gacli_c(derivation, state))
        if kane and self.agreed:
            self.stage("KanesMethod + lambdify rhs", lambda: self.kane_lambdify(state))
            self.stage("KanesMethod C rhs", lambda: self.kane_c(kane[1], state))
        self.finish()
        return self.row

    # -- derivations
    def derive_both(self):
        """Best of up to ``--repeat`` rounds, each timing gacli then KanesMethod, until ``--budget`` is spent.

        Interleaving gives both tools the same number of runs under the same
        load; SymPy's cache is cleared before every run.
        """
        # SymPy's cache is cleared before each timed call, outside it: emptying a cache
        # the other tool has just filled is not part of either derivation.
        def gacli_once():
            return derive_gacli(self.case.path)

        def kane_once():
            model = self.case.kane()
            model.mass_matrix, model.forcing  # noqa: B018 - part of the derivation
            return model

        best: dict[str, Timing | None] = {"gacli": Timing(math.inf, math.inf), "kane": Timing(math.inf, math.inf)}
        derivation = model = None
        spent, rounds = 0.0, 0
        for rounds in range(1, max(1, self.options.repeat) + 1):
            clear_cache()
            timing, derivation = timed(gacli_once)
            best["gacli"], spent = _faster(best["gacli"], timing), spent + timing.wall
            if self.case.kane is not None and best["kane"] is not None:
                try:
                    clear_cache()
                    timing, model = timed(kane_once)
                    best["kane"], spent = _faster(best["kane"], timing), spent + timing.wall
                except Exception as error:  # noqa: BLE001
                    self.note(f"KanesMethod derivation: failed ({type(error).__name__}: {str(error)[:300]})")
                    best["kane"], model = None, None
            if spent > self.options.budget:
                break
        geq, names = gacli_equations(derivation)
        clock = self.options.clock
        self.row.update(derive_gacli_s=best["gacli"].get(clock), derive_gacli_wall_s=best["gacli"].wall,
                        derive_gacli_cpu_s=best["gacli"].cpu, n=len(derivation.system.coordinates), k=derivation.k,
                        derive_rounds=rounds, clock=clock)
        kane = None
        if model is not None:
            eqs, sub = kane_equations(model, names)
            self.row.update(derive_kane_s=best["kane"].get(clock), derive_kane_wall_s=best["kane"].wall,
                            derive_kane_cpu_s=best["kane"].cpu)
            kane = (model, eqs, sub)
        return derivation, geq, names, kane

    # -- operation counts
    def count_gacli(self, geq: Equations) -> None:
        self.row["ops_gacli"] = cse_count(geq.expressions()).operations

    def count_kane(self, keq: Equations) -> None:
        count = cse_count(keq.expressions())
        self.kane_cse = count
        self.row["ops_kane"] = count.operations
        self.row["kane_cse_temporaries"] = count.temporaries

    # -- the random state and the agreement check
    def sample(self, derivation, geq: Equations, names: list[str], kane):
        rng = np.random.default_rng(self.options.seed)
        n, k = len(derivation.system.coordinates), derivation.k
        c = self.case.coordinate_range
        x = random_values(rng, n, -c, c) + random_values(rng, k, -1.0, 1.0)
        p = random_values(rng, len(geq.p), 0.5, 1.5)
        if self.case.default_parameters:
            defaults = parameter_defaults(derivation)
            p = [defaults.get(name, value) for name, value in zip(names, p)]
        r = random_values(rng, len(geq.r), -1.0, 1.0)
        t = 0.3
        reference = lambdify_rhs(geq)(t, x, p, r)
        self.row["state"] = {"t": t, "x": x, "p": p, "r": r}
        self.reference = reference
        state = {"t": t, "x": x, "p": p, "r": r, "reference": reference}
        if kane:
            model, keq, sub = kane
            xk = x + dependent_speeds(model, sub, x, p, keq)
            kane_rhs = lambdify_rhs(keq)
            out = kane_rhs(t, xk, p, ())
            error = relative_error(out[:n + k], reference)
            self.row["agreement"] = error
            self.agreed = error <= TOLERANCE
            if not self.agreed:
                self.note(f"MISMATCH: KanesMethod and gacli differ by {error:.2e} (relative) at the random state; "
                          "Kane's rhs is not timed")
            state.update(xk=xk, kane_rhs=kane_rhs, kane_eqs=keq)
        return state

    def check(self, what: str, out, n_out: int | None = None) -> bool:
        ref = self.reference
        error = relative_error(list(out)[:len(ref)] if n_out is None else list(out)[:n_out], ref[:n_out])
        self.row[f"error_{what}"] = error
        if error > TOLERANCE:
            self.note(f"{what}: disagrees with the derivation by {error:.2e} (relative); not timed")
            return False
        return True

    # -- gacli's generated code
    def gacli_python(self, derivation, state) -> None:
        files, calls = emit(derivation, "python")
        ops = emitted_rhs_ops(calls, derivation)
        if ops is not None:
            self.row["ops_gacli_emitted_python"] = ops
        (name, text), = [(f, t) for f, t in files.items() if f.endswith(".py")]
        module = load_module(text, self.scratch / "gacli_py", Path(name).stem)
        t, x, p, r = state["t"], state["x"], state["p"], state["r"]
        if self.check("gacli_python", module.rhs(t, x, p, r)):
            self.row["rhs_py_gacli_us"] = 1e6 * per_call(lambda: module.rhs(t, x, p, r), self.options.min_time)

    def gacli_c(self, derivation, state) -> None:
        files, calls = emit(derivation, "c")
        ops = emitted_rhs_ops(calls, derivation)
        if ops is not None:
            self.row["ops_gacli_emitted_c"] = ops
        source = "".join(t for f, t in sorted(files.items()) if f.endswith((".c", ".h")))
        rhs_name = bench_c.rhs_function_name(source)
        if rhs_name is None:
            raise NotAvailable("no 'int <name>_rhs(' in the emitted C")
        exe = bench_c.build(self.scratch / "gacli_c", files, rhs_name, self.options.cflags)
        self.timed_c("gacli_c", exe, state["x"], len(state["x"]), state)

    def timed_c(self, what: str, exe: Path, x, ny: int, state, n_out: int | None = None) -> None:
        xdot, seconds, status = bench_c.time_rhs(exe, state["t"], x, state["p"], state["r"] if what == "gacli_c" else [],
                                                 ny, self.options.min_time)
        if status != 0:
            self.note(f"{what}: rhs returned status {status}")
        if self.check(what, xdot, n_out):
            self.row[f"rhs_{what}_us"] = 1e6 * seconds

    # -- KanesMethod's rhs
    def kane_lambdify(self, state) -> None:
        f, t, xk, p = state["kane_rhs"], state["t"], state["xk"], state["p"]
        self.row["rhs_lambdify_kane_us"] = 1e6 * per_call(lambda: f(t, xk, p, ()), self.options.min_time)

    def kane_c(self, keq: Equations, state) -> None:
        count = getattr(self, "kane_cse", None) or cse_count(keq.expressions())
        n, k = len(keq.kinematics), keq.k
        _, M, _ = state["kane_rhs"].parts(state["t"], state["xk"], state["p"], ())
        M = np.asarray(M, dtype=float)
        symmetric = bool(np.allclose(M, M.T, rtol=1e-12, atol=0))
        self.row["kane_c_solve"] = "Cholesky" if symmetric else "Gaussian elimination"
        source = bench_c.rhs_source("kane_rhs", count.replacements, count.reduced, n=n, k=k, symmetric=symmetric,
                                    x=keq.x, p=keq.p, r=keq.r)
        exe = bench_c.build(self.scratch / "kane_c", {"kane_rhs.c": source}, "kane_rhs", self.options.cflags)
        ref_len = len(self.reference)
        self.timed_c("kane_c", exe, state["xk"], n + k, state, n_out=ref_len)

    # -- ratios
    def finish(self) -> None:
        row = self.row
        if row.get("derive_gacli_s") and row.get("derive_kane_s"):
            row["derive_ratio"] = row["derive_kane_s"] / row["derive_gacli_s"]
        emitted = row.get("ops_gacli_emitted_c", row.get("ops_gacli_emitted_python"))
        if emitted is not None:
            row["ops_gacli_emitted"] = emitted
            row["ops_gacli_emitted_from"] = "c" if "ops_gacli_emitted_c" in row else "python"
        if row.get("ops_kane"):
            if row.get("ops_gacli") is not None:
                row["ops_ratio"] = row["ops_gacli"] / row["ops_kane"]
            if emitted is not None:
                row["ops_emitted_ratio"] = emitted / row["ops_kane"]
        if row.get("rhs_gacli_c_us") and row.get("rhs_kane_c_us"):
            row["rhs_c_ratio"] = row["rhs_kane_c_us"] / row["rhs_gacli_c_us"]
        if row.get("rhs_py_gacli_us") and row.get("rhs_lambdify_kane_us"):
            row["rhs_py_ratio"] = row["rhs_lambdify_kane_us"] / row["rhs_py_gacli_us"]


# -- main ----------------------------------------------------------------------

def _sizes(text: str) -> list[int]:
    return [int(v) for v in text.split(",") if v.strip()]


def parse(argv: list[str] | None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cases", default=",".join(DEFAULT_CASES),
                        help=f"comma-separated, of {','.join(CASE_NAMES)} (default {','.join(DEFAULT_CASES)}; "
                             "the bicycle is benchmarks/bench_bicycle.py)")
    parser.add_argument("--sizes", type=_sizes, help=f"pendulum links (default {','.join(map(str, DEFAULT_SIZES))})")
    parser.add_argument("--chain-sizes", type=_sizes,
                        help=f"chain links, 3 dof each (default {','.join(map(str, DEFAULT_CHAIN_SIZES))})")
    parser.add_argument("--quick", action="store_true", help="small sizes, one derivation each, short timings")
    parser.add_argument("--repeat", type=int, default=3,
                        help="derivations: best of up to this many rounds of both tools (default 3)")
    parser.add_argument("--budget", type=float, default=6.0,
                        help="derivations: no further round once a case has spent this many seconds (default 6)")
    parser.add_argument("--clock", choices=("wall", "cpu"), default="wall",
                        help="derivations and cold start: wall time (time.perf_counter, default) or CPU time "
                             "(time.process_time; steadier on a loaded machine); the JSON has both")
    parser.add_argument("--min-time", type=float, default=0.2, help="rhs timing: roughly the seconds per measurement (default 0.2)")
    parser.add_argument("--cflags", default=" ".join(bench_c.DEFAULT_CFLAGS), help='C compiler flags (default -O2), e.g. --cflags="-O3 -march=native"')
    parser.add_argument("--seed", type=int, default=20261122, help="random state and parameters")
    parser.add_argument("--no-cold-start", action="store_true", help="skip the gacli subprocess timings")
    parser.add_argument("--fresh-sizes", type=_sizes,
                        help="pendulum links for the first derivation in fresh processes (default 10, --quick 5; '' skips)")
    parser.add_argument("--fresh-repeat", type=int, help="fresh processes per tool there, median (default 5, --quick 1)")
    parser.add_argument("--json", type=Path, help="also save the results here")
    parser.add_argument("--keep", type=Path, help="keep generated system files and code in this directory")
    parser.add_argument("--silent", action="store_true", help="no progress on stderr")
    parser.add_argument("--verbose", action="store_true", help="print notes as they occur")
    options = parser.parse_args(argv)
    options.cflags = options.cflags.split()
    if options.quick:
        options.sizes = options.sizes or list(QUICK_SIZES)
        options.chain_sizes = options.chain_sizes or list(QUICK_CHAIN_SIZES)
        options.repeat, options.min_time = 1, min(options.min_time, 0.05)
        options.fresh_sizes = [5] if options.fresh_sizes is None else options.fresh_sizes
        options.fresh_repeat = options.fresh_repeat or 1
    options.fresh_sizes = [10] if options.fresh_sizes is None else options.fresh_sizes
    options.fresh_repeat = options.fresh_repeat or 5
    options.sizes = options.sizes or list(DEFAULT_SIZES)
    options.chain_sizes = options.chain_sizes or list(DEFAULT_CHAIN_SIZES)
    return options


def warm_up(scratch: Path) -> None:
    """Import and exercise both tools once, so that no timing pays for first imports."""
    import bench_kane
    from make_pendulum import write_pendulum

    derive_gacli(write_pendulum(1, scratch))
    bench_kane.pendulum(1).forcing  # noqa: B018
    clear_cache()


def main(argv: list[str] | None = None) -> int:
    options = parse(argv)
    started = time.perf_counter()
    with contextlib.ExitStack() as stack:
        if options.keep:
            scratch = options.keep.resolve()
            scratch.mkdir(parents=True, exist_ok=True)
        else:
            scratch = Path(stack.enter_context(tempfile.TemporaryDirectory(prefix="gacli-bench-")))
        with contextlib.suppress(Exception):
            warm_up(scratch / "warm-up")
        names = [c.strip() for c in options.cases.split(",") if c.strip()]
        selected, skipped = cases(names, options.sizes, options.chain_sizes, scratch / "systems")
        if "bicycle" not in names:
            skipped.append("bicycle: see python benchmarks/bench_bicycle.py")
        rows = [CaseRun(case, options, scratch).run() for case in selected]
        fresh = None
        if options.fresh_sizes:
            if not options.silent:
                print(f"[{time.strftime('%H:%M:%S')}] first derivation in fresh processes", file=sys.stderr, flush=True)
            try:
                fresh = fresh_rows(options.fresh_sizes, options.fresh_repeat, options.clock, scratch / "fresh")
            except Exception as error:  # noqa: BLE001
                skipped.append(f"fresh process: failed ({error})")
    cold = None
    if not options.no_cold_start:
        if not options.silent:
            print(f"[{time.strftime('%H:%M:%S')}] cold start", file=sys.stderr, flush=True)
        try:
            cold = cold_start(3 if options.quick else 5, options.clock)
        except Exception as error:  # noqa: BLE001
            skipped.append(f"cold start: failed ({error})")
    info = machine()
    print(report(info, rows, cold, skipped, options, fresh))
    total = time.perf_counter() - started
    print(f"\n(total run time {total:.0f} s)")
    if options.json:
        payload = {"machine": info, "options": {k: (str(v) if isinstance(v, Path) else v) for k, v in vars(options).items()},
                   "rows": rows, "fresh_process": fresh, "cold_start": cold, "skipped": skipped, "run_seconds": total}
        options.json.write_text(json.dumps(payload, indent=2, default=str), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
