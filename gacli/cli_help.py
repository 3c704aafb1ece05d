"""How the command line presents itself in ``--help`` and in usage errors.

Typer shows a parameter's Python type beside it (``{file}``, ``<list[str]>``,
``<float range>``), which means nothing to someone reading a command's help;
here every argument shows only its metavar, every command ends with its
example, a bad choice gets one plain sentence listing the choices, and
option combinations a command refuses are found before any work.
Nothing here imports SymPy: ``gacli --help`` stays fast.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Annotated, Optional

import typer
from typer.core import TyperArgument, TyperCommand, TyperGroup

from gacli.cli_options import StrictOptions


class _PlainArgument(TyperArgument):
    """An argument shown by its metavar alone, in the usage line and in the list."""

    def _usage_display_name(self) -> str:
        # Typer writes a required argument as {NAME}, which reads as a set.
        name = self.metavar or self.name.upper()
        return name + ("..." if self.nargs != 1 and not name.endswith("...") else "")

    def display_type_rich(self, ctx) -> None:
        return None

    def display_type(self, ctx) -> None:
        return None


class _ExampleLast:
    def format_epilog(self, ctx, formatter) -> None:
        # Click rewraps an epilog to the terminal width, which would break a long
        # example across lines; it is written as is, so it can be copied.
        if self.epilog:
            formatter.write_paragraph()
            formatter.write_text("Example:")
            with formatter.indentation():
                formatter.write(" " * formatter.current_indent + self.epilog + "\n")


class Group(StrictOptions, _ExampleLast, TyperGroup):
    """``gacli`` itself: its example, too, comes last."""


class Command(_ExampleLast, TyperCommand):
    """A gacli command: plain argument names; the example (the epilog) printed last."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        for param in self.params:
            if type(param) is TyperArgument:
                param.__class__ = _PlainArgument


def show_version(value: bool) -> None:
    """``--version``, ``-V``: the version, and nothing else."""
    from gacli.version import __version__

    if value:
        typer.echo(f"gacli {__version__}")
        raise typer.Exit()


def example(command_line: str) -> dict:
    """The keyword arguments of ``app.command`` for a command whose help ends with ``command_line``."""
    return {"cls": Command, "epilog": command_line}


def choice(what: str, choices: Callable[[], Sequence[str]]) -> Callable:
    """A callback that accepts one of ``choices()`` and otherwise says which there are.

    The choices are read when the option is used, so a format added to
    :data:`gacli.emit.EMITTERS` is accepted without a change here.
    """
    def check(value: str | None) -> str | None:
        allowed = sorted(choices())
        if value is None or value in allowed:
            return value
        raise typer.BadParameter(f"'{value}' is not {what}; choose one of: {', '.join(allowed)}")
    return check


def formats() -> tuple[str, ...]:
    """``gacli derive --format`` choices: text, then every emitter."""
    from gacli.emit import EMITTERS

    return ("text", *sorted(EMITTERS))


def code_formats() -> tuple[str, ...]:
    """The formats that are generated code alone (they read ``Derivation.code``, gacli.mechanics.code)."""
    return tuple(f for f in formats() if f not in ("text", "latex"))


def derive_usage(format: str, output: Optional[str], steps: bool, reactions: bool,
                 standalone: bool = False) -> Optional[str]:
    """Option combinations derive refuses, found before any work is done; the output to write, None for
    standard output (``-o -`` says so, as with ``FILE``: no file named ``-`` is written)."""
    output = None if output == "-" else output
    if standalone and format != "latex":
        raise typer.BadParameter("--standalone goes with --format latex", param_hint="--standalone")
    if format == "fmu" and output is None:
        raise typer.BadParameter("an FMU is a zip file, not text: pass --output NAME.fmu (or an existing directory)",
                                 param_hint="--output")
    if reactions and format not in ("text", "python", "c"):
        raise typer.BadParameter("--reactions goes with --format text, python or c", param_hint="--reactions")
    if steps and format not in ("text", "latex"):
        raise typer.BadParameter("--steps goes with --format text or latex", param_hint="--steps")
    return output


# Formats that write several files, and the endings of their names (gacli.output: a file name given
# for them must be one of theirs, its companions go beside it).
_SEVERAL_FILES = {"c": (".c", ".h"), "octave": (".m",)}


def output_usage(format: str, output: str, source: Path | None = None) -> None:
    """Refuse, before any work: an output that exists and is no regular file or directory, or is the
    system file ``source`` (gacli.output, exit 1), then a file name that can be none of a several-file
    format's files (a usage error)."""
    from gacli.output import is_directory_target, refuse_input, refuse_special

    refuse_special(output)
    if source is not None:
        refuse_input(output, source)
    endings = _SEVERAL_FILES.get(format)
    if endings is None or is_directory_target(output) or output.endswith(endings):
        return
    raise typer.BadParameter(f"--format {format} writes several files (names ending in {' and '.join(endings)}): "
                             "give a directory (a trailing / makes one) or the name of one of them",
                             param_hint="--output")


def plain_report(title: str, sections) -> str:
    """The text report as ``gacli derive`` prints it, without styling: what ``--output`` writes for text."""
    from gacli.read.textsafe import printable

    lines = [printable(title)] if title else []
    for section in sections:
        lines += ["", printable(section.title), *(f"  {printable(line)}" for line in section.lines)]
    return "\n".join(lines) + "\n"


def existing(path: Path) -> Path:
    """The file argument: ``-`` (standard input) or a path that exists, else a usage error (exit 2)."""
    if str(path) != "-" and not path.exists():
        raise typer.BadParameter(f"File '{path}' does not exist.")
    return path


# The FILE of every command that reads one system file once (gacli.pipeline reads - as standard input).
SystemPath = Annotated[Path, typer.Argument(
    metavar="FILE", help="A system file (YAML), or - for standard input.", dir_okay=False, allow_dash=True,
    callback=existing)]
