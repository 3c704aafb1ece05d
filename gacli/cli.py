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
            return
        if steps and format.value != "latex":
            raise typer.BadParameter("--steps goes with --format text or latex", param_hint="--steps")
        from gacli.api import emit

        options = {"standalone": standalone, "steps": steps} if format.value == "latex" else {}
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


def main() -> None:
    app()
