"""The ``gacli`` command line: thin commands over the Python API.

Exit codes (tested): 0 success; 1 an invalid system file, a failed
derivation or a failed check; 2 a usage error (bad option, missing file).
Every user error is printed as ``file:line:col: error: ...`` on stderr, with
no traceback; any other exception is a bug in gacli and shows one.
"""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import Annotated, Optional

import typer

from gacli.cli_help import (
    Group, SystemPath, choice, code_formats, derive_usage, example, formats, output_usage, plain_report, show_version,
)
from gacli.cli_options import usage_errors
from gacli.cli_steady import SweepOption, register as register_steady
from gacli.cli_sweep import register as register_sweep

app = typer.Typer(
    name="gacli",
    cls=Group,
    help="Derive equations of motion by the Gibbs-Appell method.",
    epilog="gacli derive systems/sphere_on_turntable.yaml",
    no_args_is_help=True,
    add_completion=True,  # --install-completion, --show-completion (docs/shell.md)
    pretty_exceptions_show_locals=False,
    rich_markup_mode=None,
)

# Read from gacli.emit.EMITTERS (a light module: emitters load on first use),
# so a new emitter is a new --format with no change here.
FORMATS = formats()
CODE_FORMATS = code_formats()
# gacli.simulate.METHODS, kept as a literal so that --help does not import SciPy;
# a test checks the two agree.
METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")

# The same budget as gacli check's --timeout (gacli.budget); the literals are
# here so that --help does not import SymPy. A test checks they agree.
DEFAULT_TIMEOUT = 120.0
# Problems printed for one file, as gacli.check.MAX_DIAGNOSTICS (a test checks they agree).
MAX_DIAGNOSTICS = 100
Timeout = Annotated[float, typer.Option(
    "--timeout", min=0, metavar="SECONDS", help="Seconds allowed for the whole command, past which it stops with "
    "'ran out of time in the step ...' (0: no limit).")]


@contextlib.contextmanager
def _boundary():
    """The single place where gacli's errors become messages and exit code 1."""
    from gacli.errors import GacliError, SystemFileError

    try:
        yield
    except SystemFileError as exc:
        from gacli.check.report import capped
        from gacli.display import console

        # As gacli check's reports: a file of aliases can hold thousands; the count is located too.
        console.diagnostics(capped(exc.diagnostics, MAX_DIAGNOSTICS))
        raise typer.Exit(code=1) from None
    except GacliError as exc:
        from gacli.display import console

        # Several problems (gacli simulate's options) are one line each, not one line with \n in it.
        problems = getattr(exc, "problems", ())
        if len(problems) > 1:
            console.error(str(exc).split("\n", 1)[0], problems)
        else:
            console.error(str(exc))
        raise typer.Exit(code=1) from None
    except MemoryError:  # outside a budget (which names the step): still one message, not a traceback
        from gacli.display import console

        console.error("ran out of memory (the system is too large for this machine)")
        raise typer.Exit(code=1) from None


@contextlib.contextmanager
def _budget(path: Path, seconds: float):
    """The command's time and memory budget on ``path`` (gacli check's mechanism); yields the step recorder."""
    from gacli.budget import budget

    with budget(str(path), seconds) as state:
        yield state


def _derive(path: Path, state, needs: str | None = None, *, solves: bool = False):
    """Read, load and derive once (gacli.pipeline) within the budget, telling it (and the spinner) each step;
    ``needs`` is what the command reads of the equations: gacli.pipeline's CODE, PRINTOUT, STEPS or CLOSED
    (None). A command that solves M u̇ = F (``solves``, and every one of CLOSED) meets a row of M zero at
    every state as check's located error, not a solver's."""
    from gacli.display import console
    from gacli.pipeline import CLOSED, run

    with console.progress(f"deriving {path.name}") as spinner:
        def step(name: str) -> None:
            state(name)
            spinner(name)

        derivation = run(path, needs=needs or CLOSED, progress=step).derivation
    if solves or needs in (None, CLOSED):
        from gacli.check.mass import require_regular

        require_regular(derivation)
    return derivation


@app.callback()
def _main(
    version: Annotated[
        Optional[bool], typer.Option("--version", "-V", callback=show_version, is_eager=True, help="Show the version and exit.")
    ] = None,
) -> None:
    """Derive equations of motion by the Gibbs-Appell method."""


@app.command(**example("gacli derive systems/sphere_on_turntable.yaml --format c --output build/"))
def derive(
    file: SystemPath,
    format: Annotated[str, typer.Option(
        "--format", "-f", metavar="FORMAT", callback=choice("a format", formats),
        help=f"Output form: {', '.join(FORMATS)}.")] = "text",
    output: Annotated[Optional[str], typer.Option(
        "--output", "-o", metavar="PATH",
        help="Write here instead of stdout (- is stdout): a file, or a directory when PATH ends in / or is one (text: NAME.txt).")] = None,
    standalone: Annotated[bool, typer.Option(help="LaTeX: a complete document for pdflatex.")] = False,
    steps: Annotated[bool, typer.Option(help="Show the worked solution, step by step (text or LaTeX).")] = False,
    reactions: Annotated[bool, typer.Option(help="Also the constraint forces (multipliers): text, or a reactions() function.")] = False,
    timeout: Timeout = DEFAULT_TIMEOUT,
) -> None:
    """Derive the Gibbs-Appell equations of a system and print them."""
    from gacli.display import console

    output = derive_usage(format, output, steps, reactions, standalone)
    with _boundary():
        if output is not None:  # a device or FIFO, or a name none of the files can have: before the work
            output_usage(format, str(output), file)
        with _budget(file, timeout) as state:
            from gacli.pipeline import needs_of
            derivation = _derive(file, state, needs=needs_of(format in CODE_FORMATS, reactions, steps))
            state(f"writing the {format} output")
            if format == "text":
                title, sections = _text_report(derivation, steps, reactions)
                files = {f"{derivation.system.name}.txt": plain_report(title, sections)}
            else:
                from gacli.api import emit

                options = {"standalone": standalone, "steps": steps} if format == "latex" else {"reactions": reactions}
                if format == "fmu":
                    options = {"note": console.note}
                files = emit(derivation, format, **options)
        # Printed once the work is done: running out of time never leaves half an output.
        if format == "text" and output is None:
            console.sections(title, sections)
        elif output is None:
            for _, text in sorted(files.items()):
                console.raw(text)
        else:
            from gacli.output import write_files

            for path in write_files(files, output, file):
                console.note(f"wrote {path}")


def _text_report(derivation, steps: bool, reactions: bool):
    from gacli.display.report import derivation_report, reactions_report, steps_report

    sections = tuple((steps_report if steps else derivation_report)(derivation))
    if reactions:
        sections += tuple(reactions_report(derivation))
    return derivation.system.title or derivation.system.name, sections


@app.command(**example("gacli gibbs systems/particle_in_plane.yaml"))
def gibbs(file: SystemPath, timeout: Timeout = DEFAULT_TIMEOUT) -> None:
    """Print the Gibbs function G of a system.

    Only its acceleration terms, eqs. (14.17) and (14.21): the terms free of
    accelerations play no part in the equations.
    """
    from gacli.display import console
    from gacli.display.report import gibbs_report

    with _boundary():
        with _budget(file, timeout) as state:
            from gacli.pipeline import PRINTOUT
            derivation = _derive(file, state, needs=PRINTOUT)
            state("writing the Gibbs function")
            sections = tuple(gibbs_report(derivation))
        console.sections("", sections)


CHECK_FORMATS = ("text", "json", "github")


@app.command(**example("gacli check systems/ --strict --format github"))
def check(
    paths: Annotated[
        list[str],
        typer.Argument(metavar="PATH...", help="Files, directories (searched for *.yaml, *.yml) or glob patterns."),
    ],
    format: Annotated[str, typer.Option(
        "--format", "-f", metavar="FORMAT", callback=choice("a check format", lambda: CHECK_FORMATS),
        help="text: a table; json: for machines; github: annotations.")] = "text",
    strict: Annotated[bool, typer.Option("--strict", help="Warnings fail too.")] = False,
    verify: Annotated[bool, typer.Option("--verify", help="Also check each derivation by the independent route.")] = False,
    timeout: Annotated[
        float, typer.Option("--timeout", min=0, metavar="SECONDS", help="Seconds allowed per file (0: no limit).")
    ] = DEFAULT_TIMEOUT,
    skip_other_yaml: Annotated[bool, typer.Option(
        "--skip-other-yaml", help="Skip named YAML files that are not gacli files (no 'gacli:' key), as in "
        "folders and globs; the pre-commit hook names every YAML file.")] = False,
) -> None:
    """Check system files, as a gate in CI.

    Checks the format, the expressions, the ranks, the derivation and the
    sanity of M, and says which constraints are holonomic and which
    quasi-coordinates are true coordinates. Exit 0 when every file passes, 1
    when one has errors (or warnings, with --strict), 2 for a usage error.
    """
    from gacli.check import PathsError, check_paths, to_github, to_json

    with _boundary():
        try:
            if format == "text":
                from gacli.display import console
                from gacli.check import console as check_console

                with console.progress("checking") as step:
                    report = check_paths(paths, timeout=timeout, strict=strict, verify=verify,
                                         on_file=lambda p: step(str(p)), skip_other_yaml=skip_other_yaml)
                check_console.show(report)
            else:
                report = check_paths(paths, timeout=timeout, strict=strict, verify=verify,
                                     skip_other_yaml=skip_other_yaml)
                typer.echo(to_json(report) if format == "json" else to_github(report), nl=False)
        except PathsError as exc:
            raise typer.BadParameter(str(exc), param_hint="PATH") from None
    raise typer.Exit(code=report.exit_code)


@app.command(**example("gacli schema > schema/gacli-system-1.schema.json"))
def schema() -> None:
    """Print the JSON Schema of the system file format.

    The schema is JSON Schema draft 2020-12, for editors and validators.
    """
    from gacli.read.file_schema import schema_text

    typer.echo(schema_text(), nl=False)


_SIMULATE_EXAMPLE = ('gacli simulate systems/sphere_on_turntable.yaml --function "Omega=2" '
                     '--input "F_x=0,F_y=0,F_z=0,M_x=0,M_y=0,M_z=0" --init "dot(x)=0.1" --t-end 5')


@app.command(**example(_SIMULATE_EXAMPLE))
def simulate(
    file: SystemPath,
    set_: Annotated[Optional[list[str]], typer.Option(
        "--set", metavar="NAME=VALUE,...", help='Parameter values over the file\'s, "M=1,a=0.1".')] = None,
    init: Annotated[Optional[list[str]], typer.Option(
        metavar="STATE=VALUE,...", help='Initial state, "x=0.1,dot(y)=0"; others start at 0.')] = None,
    input: Annotated[Optional[list[str]], typer.Option(
        metavar="NAME=EXPR,...", help='Inputs as expressions in t, parameters and state, "F_x=0.1*sin(t)".')] = None,
    function: Annotated[Optional[list[str]], typer.Option(
        metavar="NAME=EXPR,...", help='Free functions of time, "Omega=2+sin(t)".')] = None,
    t_end: Annotated[float, typer.Option(metavar="SECONDS", help="End time.")] = 10.0,
    method: Annotated[str, typer.Option(
        metavar="METHOD", callback=choice("a method", lambda: METHODS),
        help=f"SciPy's solve_ivp method: {', '.join(METHODS)}.")] = "DOP853",
    rtol: Annotated[float, typer.Option(metavar="NUMBER", help="Relative tolerance.")] = 1e-9,
    atol: Annotated[float, typer.Option(metavar="NUMBER", help="Absolute tolerance.")] = 1e-12,
    points: Annotated[int, typer.Option(metavar="N", help="Evenly spaced output samples.")] = 1001,
    csv: Annotated[Optional[str], typer.Option(
        metavar="PATH", help="Write t and the state to this CSV file (into a directory: PATH/, as NAME.csv).")] = None,
    plot: Annotated[Optional[Path], typer.Option(metavar="FILE", help="Draw to this .png or .svg file.")] = None,
    show: Annotated[Optional[str], typer.Option(metavar="STATE,...", help="States drawn against time, as x,y.")] = None,
    phase: Annotated[Optional[str], typer.Option(metavar="STATE,STATE", help="One state against another, as x,y.")] = None,
    timeout: Timeout = DEFAULT_TIMEOUT,
) -> None:
    """Integrate the equations of motion with SciPy.

    Reports the energy drift (when the model conserves energy) and the
    residual of each constraint along the path; writes a CSV or a plot.
    """
    from gacli import simulate as sim
    from gacli.cli_options import check_outputs, write_outputs
    from gacli.pipeline import STEPS
    from gacli.simulate import console as simulate_console

    with _boundary(), usage_errors():
        spec = sim.spec_from_options(set=set_ or (), init=init or (), input=input or (), function=function or (),
                                     show=show, phase=phase, t_end=t_end, method=method,
                                     rtol=rtol, atol=atol, points=points)
        sim.require("scipy.integrate")
        check_outputs(csv, plot, file)
        with _budget(file, timeout) as state, simulate_console.notes_from_warnings():
            derivation = _derive(file, state, STEPS, solves=True)
            state("simulating")
            with simulate_console.progress(spec.t_end) as advance:
                result = sim.simulate(derivation, spec, progress=advance)
        from gacli.simulate.plot import state_units

        write_outputs(result, spec, csv, plot, state_units(derivation.system), source=file)
        simulate_console.summary(result)


@app.command(**example('gacli linearize systems/rolling_disk.yaml --at "lean=0,dot(spin)=-5" --states "lean,dot(yaw),dot(lean)"'))
def linearize(
    file: SystemPath,
    at: Annotated[Optional[str], typer.Option(
        metavar="NAME=VALUE,...", help='Operating point: state and input values, "lean=0,dot(spin)=-5".')] = None,
    set_: Annotated[Optional[str], typer.Option(
        "--set", metavar="NAME=VALUE,...", help='Parameter values over the file\'s, "g=9.81".')] = None,
    states: Annotated[Optional[str], typer.Option(
        metavar="STATE,...", help='Keep these states (rows and columns of A), "lean,dot(yaw),dot(lean)".')] = None,
    symbolic: Annotated[bool, typer.Option(
        help='A and B as expressions (small systems); --at may name new symbols, "dot(spin)=w".')] = False,
    sweep: SweepOption = None,
    timeout: Timeout = DEFAULT_TIMEOUT,
) -> None:
    """Linearize about an operating point.

    Prints A, B and the eigenvalues of A, numerically (or A and B
    symbolically, with --symbolic, at an --at of expressions in the parameters).
    With --sweep, the eigenvalues on the constraint manifold along a value,
    the intervals where they are stable and the critical values (docs/steady.md).
    """
    from gacli.display import console
    from gacli import linearize as L
    from gacli.cli_options import numeric_lines
    from gacli.cli_steady import sweep_lines, sweep_usage, symbolic_lines
    from gacli.simulate.console import notes_from_warnings
    from gacli.simulate.spec import parse_assignments, state_names

    with _boundary(), usage_errors():
        pairs = parse_assignments(at or "", "--at")
        overrides = parse_assignments(set_ or "", "--set")
        names = state_names(states or "", "--states")
        sweep_usage(sweep, symbolic)
        with _budget(file, timeout) as state, notes_from_warnings():
            from gacli.pipeline import CODE, PRINTOUT
            derivation = _derive(file, state, needs=PRINTOUT if symbolic else CODE, solves=True)
            state("linearizing")
            if symbolic:
                lines = symbolic_lines(derivation, pairs, overrides, names)
            elif sweep:
                lines = sweep_lines(derivation, sweep, pairs, overrides, names)
            else:
                lines = numeric_lines(L, derivation, pairs, overrides, names)
        console.raw("\n".join(lines))


@app.command(**example("gacli verify systems/sphere_on_turntable.yaml --samples 5"))
def verify(
    file: SystemPath,
    samples: Annotated[int, typer.Option(min=1, metavar="N", help="Random admissible states to compare at.")] = 20,
    tol: Annotated[float, typer.Option(metavar="NUMBER", help="Largest relative difference allowed.")] = 1e-9,
    timeout: Timeout = DEFAULT_TIMEOUT,
) -> None:
    """Check a derivation by an independent route.

    Eq. (14.10) over all the rates, with multipliers, compared with the
    derivation and with what generated code computes, at random admissible states.
    """
    from gacli.display import console

    with _boundary():
        from gacli.cli_options import verify_options
        from gacli.verify import format_report
        from gacli.verify import verify as run_verify

        with usage_errors():
            verify_options(samples, tol)
        with _budget(file, timeout) as state:
            derivation = _derive(file, state)
            state("verifying by the independent route (eq. 14.10)")
            report = run_verify(derivation.system, derivation, samples=samples, tol=tol)
            lines = format_report(report)
        console.raw("\n".join(lines))
        if not report.passed:
            raise typer.Exit(code=1)


register_sweep(app, example, _boundary, _budget, _derive)
register_steady(app, example, _boundary, _budget, _derive)


def main() -> None:
    from gacli.cli_options import with_standard_output

    with_standard_output(app)
