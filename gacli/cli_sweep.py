"""The ``gacli sweep`` command: its options, and the run over gacli.sweep.

:mod:`gacli.cli` registers the command with :func:`register`, handing over
the helpers every command shares (the error boundary, the budget, the
derivation with its spinner): this module never imports ``gacli.cli``, so
the two make no circle. Nothing here imports SymPy
at import time: ``gacli --help`` stays fast.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path
from typing import Annotated, Optional

import typer

from gacli.cli_help import choice

SWEEP_EXAMPLE = ('gacli sweep systems/rolling_disk.yaml --run linearize --grid "dot(spin)=-8:-2:7" '
                 '--states "lean,dot(yaw),dot(lean)" --output disk_stability.csv')
MODES = ("linearize", "simulate")
METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")   # gacli.simulate.METHODS (a test checks)
SIMULATE_ONLY = ("--init", "--input", "--function", "--t-end", "--method", "--rtol", "--atol", "--points")
LINEARIZE_ONLY = ("--at", "--states")


def sweep_usage(mode: str, given: dict[str, bool], jobs: int, scheduler: Optional[str]) -> None:
    """Option combinations sweep refuses, found before any work."""
    wrong = [o for o in (SIMULATE_ONLY if mode == "linearize" else LINEARIZE_ONLY) if given.get(o)]
    if wrong:
        other = "simulate" if mode == "linearize" else "linearize"
        raise typer.BadParameter(f"{', '.join(wrong)}: only with --run {other}", param_hint="--run")
    if scheduler and jobs != 1:
        raise typer.BadParameter("--jobs runs local processes, --scheduler a Dask cluster: give one",
                                 param_hint="--jobs")


_File = Annotated[Path, typer.Argument(metavar="FILE", help="A system file (YAML).", dir_okay=False, exists=True)]
_Run = Annotated[str, typer.Option(
    "--run", metavar="COMMAND", callback=choice("a sweep", lambda: MODES),
    help="What runs at each point: linearize (eigenvalues of A) or simulate (the final state).")]
_Grid = Annotated[Optional[list[str]], typer.Option(
    metavar="NAME=START:STOP:COUNT",
    help='Evenly spaced values, both ends included; several make a product: "dot(spin)=-8:-2:7".')]
_Random = Annotated[Optional[list[str]], typer.Option(
    metavar="NAME=LOW:HIGH", help='Uniform random values (with --samples): "m=0.5:2".')]
_Samples = Annotated[Optional[int], typer.Option(min=1, metavar="N", help="Points drawn with --random.")]
_Seed = Annotated[int, typer.Option(metavar="N", help="Seed of --random's draws.")]
_Set = Annotated[Optional[list[str]], typer.Option(
    "--set", metavar="NAME=VALUE,...", help='Fixed parameter values over the file\'s, "g=9.81".')]
_At = Annotated[Optional[str], typer.Option(
    metavar="NAME=VALUE,...", help='linearize: the rest of the operating point, "lean=0".')]
_States = Annotated[Optional[str], typer.Option(
    metavar="STATE,...", help='linearize: the block of A whose eigenvalues count, "lean,dot(lean)".')]
_Init = Annotated[Optional[list[str]], typer.Option(
    metavar="STATE=VALUE,...", help='simulate: the rest of the initial state, "lean=0.1".')]
_Input = Annotated[Optional[list[str]], typer.Option(
    metavar="NAME=EXPR,...", help="simulate: inputs, as gacli simulate takes them.")]
_Function = Annotated[Optional[list[str]], typer.Option(
    metavar="NAME=EXPR,...", help='simulate: free functions of time, "Omega=2".')]
_TEnd = Annotated[Optional[float], typer.Option(metavar="SECONDS", help="simulate: end time (10).")]
_Method = Annotated[Optional[str], typer.Option(
    metavar="METHOD", callback=choice("a method", lambda: METHODS), help="simulate: solve_ivp's method (DOP853).")]
_Rtol = Annotated[Optional[float], typer.Option(metavar="NUMBER", help="simulate: relative tolerance (1e-9).")]
_Atol = Annotated[Optional[float], typer.Option(metavar="NUMBER", help="simulate: absolute tolerance (1e-12).")]
_Points = Annotated[Optional[int], typer.Option(
    min=2, metavar="N", help="simulate: samples the energy drift and residuals are measured at (101).")]
_Output = Annotated[Optional[Path], typer.Option(
    "--output", "-o", metavar="FILE", help="Write the table here (.csv, or .parquet with pyarrow); else (or with -) CSV to stdout.")]
_Jobs = Annotated[int, typer.Option("--jobs", "-j", min=1, metavar="N", help="Local processes to run the points on.")]
_Scheduler = Annotated[Optional[str], typer.Option(
    metavar="ADDRESS", help="Run the points on this Dask scheduler (tcp://host:8786) instead.")]
DEFAULT_TIMEOUT = 120.0   # gacli.budget.DEFAULT_TIMEOUT, a literal so that --help does not import SymPy
_Timeout = Annotated[float, typer.Option(
    "--timeout", min=0, metavar="SECONDS", help="Seconds allowed to derive the system and run the first point "
    "(0: no limit); the other points have no limit.")]

_SHARED: dict[str, Callable] = {}


def register(app, example: Callable, boundary: Callable, budget: Callable, derive: Callable) -> None:
    """Add ``sweep`` to ``app`` with the helpers every command of gacli.cli shares."""
    _SHARED.update(boundary=boundary, budget=budget, derive=derive)
    app.command(**example(SWEEP_EXAMPLE))(sweep)


def sweep(file: _File, run: _Run, grid: _Grid = None, random: _Random = None, samples: _Samples = None,
          seed: _Seed = 0, set_: _Set = None, at: _At = None, states: _States = None, init: _Init = None,
          input: _Input = None, function: _Function = None, t_end: _TEnd = None, method: _Method = None,
          rtol: _Rtol = None, atol: _Atol = None, points: _Points = None, output: _Output = None, jobs: _Jobs = 1,
          scheduler: _Scheduler = None, timeout: _Timeout = DEFAULT_TIMEOUT) -> None:
    """Run linearize or simulate at many parameter values and states.

    Parameters and initial states (or the operating point) take each
    point's values; the system is derived once, and the table has one row
    per point, in order, whatever runs them (docs/sweep.md).
    """
    given = {"--at": at is not None, "--states": states is not None, "--init": bool(init),
             "--input": bool(input), "--function": bool(function), "--t-end": t_end is not None,
             "--method": method is not None, "--rtol": rtol is not None, "--atol": atol is not None,
             "--points": points is not None}
    sweep_usage(run, given, jobs, scheduler)
    numbers = {k: v for k, v in {"t_end": t_end, "method": method, "rtol": rtol, "atol": atol,
                                 "points": 101 if points is None else points}.items() if v is not None}
    from gacli.cli_options import usage_errors

    with _SHARED["boundary"](), usage_errors():
        _sweep(file, run, dict(grid=grid or (), random=random or (), samples=samples, seed=seed), dict(
            set_=",".join(set_ or ()), at=at or "", states=states, init=init, input=input, function=function,
            numbers=numbers), output, jobs, scheduler, timeout)


def _sweep(file: Path, mode: str, plan_options: dict, options: dict,
           output: Optional[Path], jobs: int, scheduler: Optional[str], timeout: float) -> None:
    from gacli import sweep as S
    from gacli.pipeline import CODE, STEPS
    from gacli.sweep import console

    from gacli.simulate.spec import OptionError

    output = None if str(output) == "-" else output  # - is standard output, as for FILE
    try:
        plan = S.plan(**plan_options)
    except S.SweepError as exc:  # a malformed --grid, --random, --samples or --seed: a usage error (exit 2)
        raise OptionError([str(exc)]) from None
    if output is not None:
        S.check_path(output)
    if scheduler:
        S.require_distributed()   # a missing extra is said before the derivation, not after
    spec = _spec(mode, options)
    states = [n.strip() for n in options["states"].split(",") if n.strip()] if options["states"] else []
    with _SHARED["budget"](file, timeout) as state:
        # Generated code runs every point; simulate's integrals read the closed forms where they are small.
        derivation = _SHARED["derive"](file, state, STEPS if mode == "simulate" else CODE, solves=True)
        state(f"setting up the sweep ({mode})")
        try:
            task = S.task_for(derivation, mode, plan, set_=options["set_"], at=options["at"], states=states, spec=spec)
        except S.SweepError as exc:  # a name swept that the system does not have: a usage error (exit 2)
            raise OptionError([str(exc)]) from None
        job = S.Job(f"{time.time_ns()}-{id(task)}", derivation, task)
        # The options' mistakes are found at the first point, within the budget, before any worker starts.
        first = S.run_point(job, plan.points[0])
    started = time.perf_counter()
    with console.progress(mode, len(plan)) as advance:
        rows = S.run(job, plan, jobs=jobs, scheduler=scheduler, progress=advance, first=first)
    table = S.table(S.columns(task), plan.points, rows)
    used = min(jobs, len(plan) - 1)  # the processes started: the first point ran here, the rest in chunks
    where = f"on {scheduler}" if scheduler else f"on {used} processes" if used > 1 else "here"
    console.summary(len(plan), sum(1 for r in rows if r[-1]), f"{where} in {time.perf_counter() - started:.3g} s")
    if output is None:
        typer.echo(S.to_csv(table), nl=False)
    else:
        console.wrote(S.write(table, output))


def _spec(mode: str, options: dict):
    if mode != "simulate":
        return None
    from gacli import simulate as sim

    sim.require("scipy.integrate")
    return sim.spec_from_options(set=[options["set_"]] if options["set_"] else (), init=options["init"] or (),
                                 input=options["input"] or (), function=options["function"] or (),
                                 **options["numbers"])
