"""The ``gacli`` command line: thin commands over the Python API.

Exit codes (tested): 0 success; 1 an invalid system file, a failed
derivation or a failed check; 2 a usage error (bad option, missing file).
Every user error is printed as ``file:line:col: error: ...`` on stderr, with
no traceback; any other exception is a bug in gacli and shows one.
"""

from __future__ import annotations

import contextlib
import enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from gacli import __version__

app = typer.Typer(
    name="gacli",
    help="Derive equations of motion by the Gibbs-Appell method.\n\n"
    "Example: gacli derive systems/sphere_on_turntable.yaml",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_show_locals=False,
    rich_markup_mode=None,
)

# Kept as literals (not read from gacli.emit.EMITTERS) so that --help does not
# import the emitters; tests check the two lists agree.
FORMATS = ("text", "latex", "python", "c")
Format = enum.Enum("Format", {name: name for name in FORMATS}, type=str)
# Likewise gacli.simulate.METHODS, without importing SciPy.
METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")
Method = enum.Enum("Method", {m: m for m in METHODS}, type=str)

SystemPath = Annotated[Path, typer.Argument(help="A system file (YAML).", dir_okay=False, exists=True)]


@contextlib.contextmanager
def _boundary():
    """The single place where gacli's errors become messages and exit code 1."""
    from gacli.errors import GacliError, SystemFileError

    try:
        yield
    except SystemFileError as exc:
        from gacli import console

        console.diagnostics(exc.diagnostics)
        raise typer.Exit(code=1) from None
    except GacliError as exc:
        from gacli import console

        console.error(str(exc))
        raise typer.Exit(code=1) from None


def _derive(path: Path):
    from gacli import console
    from gacli.equations import derive
    from gacli.loading import load

    system = load(path)
    with console.progress(f"deriving {path.name}") as step:
        return derive(system, progress=step)


def _version(value: bool) -> None:
    if value:
        typer.echo(f"gacli {__version__}")
        raise typer.Exit()


@app.callback()
def _main(
    version: Annotated[
        Optional[bool], typer.Option("--version", callback=_version, is_eager=True, help="Show the version and exit.")
    ] = None,
) -> None:
    """Derive equations of motion by the Gibbs-Appell method."""


@app.command()
def derive(
    file: SystemPath,
    format: Annotated[Format, typer.Option("--format", "-f", help="Output form.")] = Format.text,
    output: Annotated[
        Optional[Path],
        typer.Option("--output", "-o", help="Write here instead of stdout (a directory for C: NAME.h and NAME.c)."),
    ] = None,
    standalone: Annotated[bool, typer.Option(help="LaTeX: a complete document for pdflatex.")] = False,
    steps: Annotated[bool, typer.Option(help="Show the worked solution, step by step (text or LaTeX).")] = False,
    reactions: Annotated[bool, typer.Option(help="Also the constraint forces (multipliers): text, or a reactions() function.")] = False,
) -> None:
    """Derive the Gibbs-Appell equations of a system and print them.

    Example: gacli derive systems/sphere_on_turntable.yaml --format c --output build/
    """
    from gacli import console

    with _boundary():
        derivation = _derive(file)
        if format.value == "text":
            from gacli.report import derivation_report, steps_report

            if output is not None:
                raise typer.BadParameter("--output needs --format latex, python or c", param_hint="--output")
            report = steps_report if steps else derivation_report
            console.sections(derivation.system.title or derivation.system.name, report(derivation))
            if reactions:
                from gacli.report import reactions_report

                console.sections("", reactions_report(derivation))
            return
        if reactions and format.value == "latex":
            raise typer.BadParameter("--reactions goes with --format text, python or c", param_hint="--reactions")
        if steps and format.value != "latex":
            raise typer.BadParameter("--steps goes with --format text or latex", param_hint="--steps")
        from gacli.api import emit

        options = {"standalone": standalone, "steps": steps} if format.value == "latex" else {"reactions": reactions}
        files = emit(derivation, format.value, **options)
        if output is None:
            for _, text in sorted(files.items()):
                console.raw(text)
            return
        from gacli.output import write_files

        for path in write_files(files, output):
            console.note(f"wrote {path}")


@app.command()
def gibbs(file: SystemPath) -> None:
    """Print the Gibbs function G (its acceleration terms, eqs. 14.17 and 14.21).

    Example: gacli gibbs systems/particle_in_plane.yaml
    """
    from gacli import console
    from gacli.report import gibbs_report

    with _boundary():
        derivation = _derive(file)
        console.sections("", gibbs_report(derivation))


CHECK_FORMATS = ("text", "json", "github")
CheckFormat = enum.Enum("CheckFormat", {name: name for name in CHECK_FORMATS}, type=str)


@app.command()
def check(
    paths: Annotated[
        list[str],
        typer.Argument(metavar="PATH", help="Files, directories (searched for *.yaml, *.yml) or glob patterns."),
    ],
    format: Annotated[
        CheckFormat, typer.Option("--format", "-f", help="text: a table; json: for machines; github: annotations.")
    ] = CheckFormat.text,
    strict: Annotated[bool, typer.Option("--strict", help="Warnings fail too.")] = False,
    verify: Annotated[bool, typer.Option("--verify", help="Also check each derivation by the independent route.")] = False,
    timeout: Annotated[
        float, typer.Option("--timeout", min=0, help="Seconds allowed per file (0: no limit).")
    ] = 60.0,
) -> None:
    """Check system files: format, expressions, ranks, derivation and the sanity of M.

    Also says which constraints are holonomic and which quasi-coordinates are
    true coordinates. Exit 0 when every file passes, 1 when one has errors
    (or warnings, with --strict), 2 for a usage error.

    Example: gacli check systems/ --strict --format github
    """
    from gacli.check import PathsError, check_paths, to_github, to_json

    with _boundary():
        try:
            if format.value == "text":
                from gacli import check_console, console

                with console.progress("checking") as step:
                    report = check_paths(paths, timeout=timeout, strict=strict, verify=verify,
                                         on_file=lambda p: step(str(p)))
                check_console.show(report)
            else:
                report = check_paths(paths, timeout=timeout, strict=strict)
                typer.echo(to_json(report) if format.value == "json" else to_github(report), nl=False)
        except PathsError as exc:
            raise typer.BadParameter(str(exc), param_hint="PATH") from None
    raise typer.Exit(code=report.exit_code)


@app.command()
def schema() -> None:
    """Print the JSON Schema (draft 2020-12) of the system file format.

    Example: gacli schema > schema/gacli-system-1.schema.json
    """
    from gacli.file_schema import schema_text

    typer.echo(schema_text(), nl=False)


@app.command()
def simulate(
    file: SystemPath,
    set_: Annotated[Optional[list[str]], typer.Option("--set", help='Parameter values, "M=1,a=0.1".')] = None,
    init: Annotated[Optional[list[str]], typer.Option(help="Initial state by STATE name; others start at 0.")] = None,
    input: Annotated[Optional[list[str]], typer.Option(help="Inputs as expressions in t, parameters, state.")] = None,
    function: Annotated[Optional[list[str]], typer.Option(help='Free functions of time, "Omega=2+sin(t)".')] = None,
    t_end: Annotated[float, typer.Option(help="End time.")] = 10.0,
    method: Annotated[Method, typer.Option(help="solve_ivp method.")] = Method.DOP853,
    rtol: Annotated[float, typer.Option(help="Relative tolerance.")] = 1e-9,
    atol: Annotated[float, typer.Option(help="Absolute tolerance.")] = 1e-12,
    points: Annotated[int, typer.Option(help="Evenly spaced output samples.")] = 1001,
    csv: Annotated[Optional[Path], typer.Option(help="Write t and the state to this CSV file.")] = None,
    plot: Annotated[Optional[Path], typer.Option(help="Draw to this .png or .svg file.")] = None,
    show: Annotated[Optional[str], typer.Option(help="States drawn against time, as x,y.")] = None,
    phase: Annotated[Optional[str], typer.Option(help="One state against another, as x,y.")] = None,
) -> None:
    """Integrate the equations of motion; report energy drift and constraint residuals.

    Example: gacli simulate systems/sphere_on_turntable.yaml --function "Omega=2" --input "F_x=0,F_y=0,F_z=0,M_x=0,M_y=0,M_z=0" --init "dot(x)=0.1" --t-end 5
    """
    from gacli import simulate as sim
    from gacli import simulate_console

    with _boundary():
        spec = sim.spec_from_options(set=set_ or (), init=init or (), input=input or (), function=function or (),
                                     show=show, phase=phase, t_end=t_end, method=method.value,
                                     rtol=rtol, atol=atol, points=points)
        sim.require("scipy.integrate")
        if plot is not None:
            from gacli.simulate_plot import check

            check(plot)
        derivation = _derive(file)
        with simulate_console.progress(spec.t_end) as advance:
            result = sim.simulate(derivation, spec, progress=advance)
        if csv is not None:
            from gacli.output import write_files

            for path in write_files({csv.name: sim.to_csv(result)}, csv):
                simulate_console.wrote(path)
        if plot is not None:
            from gacli.simulate_plot import plot as draw

            simulate_console.wrote(draw(result, plot, spec.show, spec.phase))
        simulate_console.summary(result)


@app.command()
def linearize(
    file: SystemPath,
    at: Annotated[Optional[str], typer.Option(help='Operating point: state and input values, "roll=0,dot(wheel_R)=-15".')] = None,
    set_: Annotated[Optional[str], typer.Option("--set", help='Parameter values over the file\'s, "g=9.81".')] = None,
    states: Annotated[Optional[str], typer.Option(help="Keep these states (rows and columns of A), as lean,steer,dot(lean).")] = None,
    symbolic: Annotated[bool, typer.Option(help="A and B as expressions (small systems).")] = False,
) -> None:
    """Linearize about an operating point: A, B and the eigenvalues of A.

    Example: gacli linearize systems/cylinder_in_cylinder.yaml --states "theta,dot(theta)"
    """
    from gacli import console
    from gacli import linearize as L
    from gacli.simulate import parse_assignments

    with _boundary():
        derivation = _derive(file)
        if symbolic:
            A, B = L.linearize_symbolic(derivation)
            console.raw(f"A = {A}\nB = {B}")
            return
        from gacli.emit.naming import parameter_defaults

        defaults = parameter_defaults(derivation.system.parameters)
        overrides = L.evaluate_assignments(parse_assignments(set_ or "", "--set"), defaults, "--set")
        point = L.evaluate_assignments(parse_assignments(at or "", "--at"), {**defaults, **overrides}, "--at")
        result = L.linearize(derivation, point, overrides)
        names = [n.strip() for n in states.split(",")] if states else list(result.state)
        A = result.block(names)
        lines = ["A ="] + L.format_matrix(A, names, names)
        if result.inputs and not states:
            lines += ["", "B ="] + L.format_matrix(result.B, result.state, result.inputs)
        lines += ["", "eigenvalues:"] + [f"  {v.real:.10g} {'+' if v.imag >= 0 else '-'} {abs(v.imag):.10g}i"
                                          for v in result.eigenvalues(names)]
        console.raw("\n".join(lines))


@app.command()
def verify(
    file: SystemPath,
    samples: Annotated[int, typer.Option(min=1, help="Random admissible states to compare at.")] = 20,
    tol: Annotated[float, typer.Option(help="Largest relative difference allowed.")] = 1e-9,
) -> None:
    """Check the derivation by an independent route: eq. (14.10) over all rates, with multipliers.

    Example: gacli verify systems/sphere_on_turntable.yaml --samples 5
    """
    from gacli import console

    with _boundary():
        derivation = _derive(file)
        from gacli.verify import format_report
        from gacli.verify import verify as run_verify

        report = run_verify(derivation.system, derivation, samples=samples, tol=tol)
        console.raw("\n".join(format_report(report)))
        if not report.passed:
            raise typer.Exit(code=1)


def main() -> None:
    app()
