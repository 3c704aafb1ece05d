"""What ``linearize`` and ``simulate`` make of their option strings (gacli.simulate.spec's strict
parser) and how ``linearize`` shows its result; a usage error in an option string is exit code 2."""

from __future__ import annotations

import contextlib
import math

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


def check_outputs(csv, plot) -> None:
    """Refused before any work: a plot that is not .png or .svg, an output that is a device or FIFO."""
    if plot is not None:
        from gacli.simulate.plot import check

        check(plot)
    if csv is not None:
        from gacli.output import refuse_special

        refuse_special(csv)


def write_outputs(result, spec, csv, plot, units=None) -> None:
    """The CSV (by --output's rule: CSV/ is a directory that receives NAME.csv) and the plot."""
    from gacli.simulate import console, to_csv

    if csv is not None:
        from gacli.output import write_files

        for path in write_files({f"{result.system}.csv": to_csv(result)}, csv):
            console.wrote(path)
    if plot is not None:
        from gacli.simulate.plot import plot as draw

        with console.notes_from_warnings():  # Matplotlib's warnings too
            console.wrote(draw(result, plot, spec.show, spec.phase, units))
