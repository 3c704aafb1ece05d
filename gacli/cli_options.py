"""What ``linearize`` and ``simulate`` make of their option strings (gacli.simulate.spec's strict
parser) and how ``linearize`` shows its result; a usage error in an option string is exit code 2."""

from __future__ import annotations

import contextlib
import errno
import math
import os
import sys

import typer

# verify's states: each is a 30-digit solve of eq. (14.10), a second or more for a large system, so
# more than this would only run into the time budget; a count like 10**9 is a typo, said at once.
MAX_SAMPLES = 10_000


def numeric_lines(L, derivation, pairs, overrides, names) -> list[str]:
    from gacli.emit.naming import parameter_defaults

    defaults = parameter_defaults(derivation.system.parameters)
    values = L.evaluate_assignments(overrides, defaults, "--set")
    point = L.evaluate_assignments(pairs, {**defaults, **values}, "--at")
    result = L.linearize(derivation, point, values)
    shown = names or list(result.state)
    lines = ["A ="] + L.format_matrix(result.block(shown), shown, shown)
    if result.inputs and not names:
        lines += ["", "B ="] + L.format_matrix(result.B, result.state, result.inputs)
    return lines + ["", "eigenvalues:"] + [f"  {v.real:.10g} {'+' if v.imag >= 0 else '-'} {abs(v.imag):.10g}i"
                                           for v in result.eigenvalues(shown)]


@contextlib.contextmanager
def usage_errors():
    """An option string that cannot be used as written (gacli.simulate.OptionError): exit 2, like click's."""
    from gacli.simulate.spec import OptionError

    try:
        yield
    except OptionError as exc:
        from gacli.display import console

        problems = exc.problems
        console.error(problems[0] if len(problems) == 1 else str(exc).split("\n", 1)[0],
                      problems if len(problems) > 1 else ())
        raise typer.Exit(code=2) from None


def verify_options(samples: int, tol: float) -> None:
    """verify's numbers, refused before any work (an OptionError: exit 2 under :func:`usage_errors`).

    With a tolerance of NaN or below 0 every comparison fails (the report
    read "relative difference 0 > nan"), which says nothing of the file.
    """
    from gacli.simulate.spec import OptionError

    problems = []
    if samples > MAX_SAMPLES:
        problems.append(f"--samples: at most {MAX_SAMPLES:,} states, found {samples:,}")
    if not (math.isfinite(tol) and tol >= 0):
        problems.append(f"--tol: expected a finite number >= 0, found {tol}")
    if problems:
        raise OptionError(problems)


def check_outputs(csv, plot, source=None) -> None:
    """Refused before any work: a plot that is not .png or .svg, an output that is a device or FIFO,
    the system file ``source`` itself, or the table and the plot written to one file."""
    if csv is not None and plot is not None and os.path.abspath(csv) == os.path.abspath(plot):
        raise typer.BadParameter(f"{plot} is also --csv: the plot would replace the table", param_hint="--plot")
    if plot is not None:
        from gacli.simulate.plot import check

        check(plot)
    if csv is not None:
        from gacli.output import refuse_input, refuse_special

        refuse_special(csv)
        if source is not None:
            refuse_input(csv, source)


def write_outputs(result, spec, csv, plot, units=None, source=None) -> None:
    """The CSV (by --output's rule: CSV/ is a directory that receives NAME.csv) and the plot; neither
    may be ``source``, the system file."""
    from gacli.simulate import console, to_csv

    if csv is not None:
        from gacli.output import write_files

        for path in write_files({f"{result.system}.csv": to_csv(result)}, csv, source):
            console.wrote(path)
    if plot is not None:
        from gacli.simulate.plot import plot as draw

        with console.notes_from_warnings():  # Matplotlib's warnings too
            console.wrote(draw(result, plot, spec.show, spec.phase, units))


# -- an option of one value given twice -------------------------------------------------------------

def repeated_options(command, args) -> list[str]:
    """The options of ``command`` that take one value and appear more than once in ``args``.

    Click keeps the last (``linearize --at x=1 --at x=2`` used x=2 without a word); a
    mature CLI says so. Options that collect (``multiple``) and flags are left alone.
    """
    single = {}
    for param in command.params:
        # By duck type: typer vendors its own click (typer._click), whose classes are not click's.
        if getattr(param, "param_type_name", "") == "option" and not param.multiple and not param.count:
            for name in (*param.opts, *param.secondary_opts):
                single[name] = param
    seen: dict[str, int] = {}
    tokens = iter(args)
    for token in tokens:
        if token == "--":
            break
        name, equals, _ = token.partition("=")
        param = single.get(name if token.startswith("--") else token[:2] if token.startswith("-") else "")
        if param is None:
            continue
        if not param.is_flag:
            seen[param.name] = seen.get(param.name, 0) + 1
            if not equals and not (len(token) > 2 and not token.startswith("--")):
                next(tokens, None)  # its value, which may look like an option
    return [f"{_shown_name(command, name)}" for name, count in seen.items() if count > 1]


def _shown_name(command, name: str) -> str:
    param = next(p for p in command.params if p.name == name)
    return max(param.opts, key=len)


class StrictOptions:
    """A mixin for the TyperGroup (``class Group(StrictOptions, _ExampleLast, TyperGroup)``):
    a one-value option given twice is a usage error (exit 2), not the last one silently."""

    def resolve_command(self, ctx, args):
        name, command, rest = super().resolve_command(ctx, args)
        repeated = repeated_options(command, rest) if command is not None else []
        if repeated:  # ctx.fail: the UsageError of whichever click typer runs on (exit 2)
            ctx.fail(f"{', '.join(repeated)} given more than once (the option takes one value; give it once)")
        return name, command, rest


def with_standard_output(run) -> None:
    """``run()`` (the typer app), with a failing standard output said in one line, never a traceback.

    A full disk or a device that refuses writes (``> /dev/full``) is ``error: stdout: No space left on
    device``, exit 1; a reader that stopped reading (``| head``) ends the command quietly with exit 1,
    as click does for the writes it sees, also when the last buffered write fails at exit."""
    code: int | str | None = 0
    try:
        try:
            run()
        except SystemExit as done:
            code = done.code
        sys.stdout.flush()
    except OSError as exc:
        if exc.filename is not None or exc.errno is None:
            raise  # not standard output: another stream's failure, which its command reports
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nothing more to flush at exit
        if exc.errno != errno.EPIPE:
            print(f"error: stdout: {exc.strerror}", file=sys.stderr)
        code = 1
    sys.exit(code)
