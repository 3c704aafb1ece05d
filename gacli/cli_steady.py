"""The ``steady`` and ``integrals`` commands, and what ``linearize --sweep`` and ``--symbolic`` print.

:mod:`gacli.cli` registers the commands with :func:`register`, handing over
the helpers every command shares (the error boundary, the budget, the
derivation with its spinner), as for ``gacli sweep``: this module never
imports ``gacli.cli``. Nothing here imports SymPy at import time.
"""

from __future__ import annotations

import math

from collections.abc import Callable
from typing import Annotated, Optional

import typer

from gacli.cli_help import SystemPath, choice

STEADY_FORMATS = ("text", "latex", "json")
_SWEEP_POINTS = 101
SweepOption = Annotated[Optional[str], typer.Option(
    "--sweep", metavar="NAME=START:STOP", help='Eigenvalues along a state, input or parameter, and where the '
    'motion is stable, "dot(wheel_R)=0:33" (101 values; NAME=START:STOP:COUNT for others).')]


# -- linearize --symbolic and --sweep ------------------------------------------------------------

def symbolic_lines(derivation, pairs, overrides, names) -> list[str]:
    """A (and B) as expressions with their rows and columns named; --set puts numbers in."""
    import sympy as sp

    from gacli import linearize as L
    from gacli.algebra import symbols as S
    from gacli.emit.naming import layout, parameter_defaults

    lay = layout(derivation)
    values = L.evaluate_assignments(overrides, parameter_defaults(derivation.system.parameters), "--set")
    given = {S.value(n): sp.Float(v) for n, v in values.items()}
    point = {n: e.xreplace(given) for n, e in L.symbolic_point(derivation, pairs).items()}
    A, B = L.linearize_symbolic(derivation, point)
    if given:
        A, B = (m.xreplace(given).applyfunc(sp.simplify) for m in (A, B))
    shown = list(names) or list(lay.state)
    idx = L.state_indices(shown, lay.state)
    lines = ["A ="] + L.format_cells(_cells(A.extract(idx, idx)), shown, shown)
    if lay.r and not names:
        lines += ["", "B ="] + L.format_cells(_cells(B), lay.state, lay.r)
    return lines


def _cells(matrix) -> list[list[str]]:
    return [[str(matrix[i, j]) for j in range(matrix.cols)] for i in range(matrix.rows)]


def sweep_usage(sweep: Optional[str], symbolic: bool) -> None:
    """--sweep's usage errors, found before any work."""
    if sweep and symbolic:
        raise typer.BadParameter("--sweep computes eigenvalues numerically; leave out --symbolic",
                                 param_hint="--sweep")
    if sweep:
        parse_sweep(sweep)


def parse_sweep(text: str) -> tuple[str, float, float, int]:
    """``NAME=START:STOP`` (or ``NAME=START:STOP:COUNT``) → its parts; a usage error otherwise."""
    from gacli.simulate.spec import OptionError, canonical_name

    name, equals, span = text.partition("=")
    parts = span.split(":")
    try:
        if not equals or not name.strip() or len(parts) not in (2, 3):
            raise ValueError
        start, stop = float(parts[0]), float(parts[1])
        count = int(parts[2]) if len(parts) == 3 else _SWEEP_POINTS
    except ValueError:
        raise OptionError([f"--sweep '{text}': expected NAME=START:STOP or NAME=START:STOP:COUNT"]) from None
    if count < 2 or not start < stop:
        raise OptionError([f"--sweep '{text}': needs START < STOP and a COUNT of at least 2"])
    if not (math.isfinite(start) and math.isfinite(stop) and math.isfinite(stop - start)):
        raise OptionError([f"--sweep '{text}': START and STOP are finite numbers, and so is their distance"])
    if count > _SWEEP_MAX:  # as simulate's --points: refused before the values are made
        raise OptionError([f"--sweep '{text}': COUNT {count} is more than {_SWEEP_MAX:,} values"])
    return canonical_name(name), start, stop, count


_SWEEP_MAX = 1_000_000


def sweep_lines(derivation, text: str, pairs, overrides, names) -> list[str]:
    """The eigenvalues at each value, then the stable intervals and the critical values."""
    from gacli import linearize as L
    from gacli.emit.naming import parameter_defaults
    from gacli.steady.sweep import sweep

    name, start, stop, count = parse_sweep(text)
    defaults = parameter_defaults(derivation.system.parameters)
    values = L.evaluate_assignments(overrides, defaults, "--set")
    point = L.evaluate_assignments(pairs, {**defaults, **values}, "--at")
    _not_also_given(name, point, values)
    result = sweep(derivation, name, start, stop, at=point, parameters=values, states=names or None, points=count)
    lines = [f"eigenvalues of A on {', '.join(result.state)}"
             + (f" ({result.zero_roots} at zero along the family, not counted)" if result.zero_roots else ""),
             f"{name:>14}  stable  eigenvalues"]
    for v, ok, row in zip(result.values, result.stable, result.eigenvalues):
        shown = "not defined here" if ok is None else "  ".join(_complex(e) for e in row)
        lines.append(f"{v:>14.8g}  {'-' if ok is None else 'yes' if ok else 'no':>6}  {shown}")
    lines.append("")
    if result.undefined:
        n = result.stable.count(None)
        lines.append(f"note: {n} of the {len(result.values)} values {'is' if n == 1 else 'are'} not defined "
                     f"(the first: {result.undefined})")
    if not result.steady:
        lines.append("note: the point is not a steady motion at both ends (the rates of the kept coordinates or "
                     "the accelerations are not zero there); complete it with --at")
    lines += [f"critical {name} = {c:.10g}" for c in result.critical]
    lines += [f"stable for {name} in [{a:.10g}, {b:.10g}]" for a, b in result.intervals] or \
        [f"stable nowhere in [{start:g}, {stop:g}]"]
    return lines


def _not_also_given(name: str, point, values) -> None:
    """The swept name takes the sweep's values; one given by --at or --set too was silently dropped."""
    from gacli.simulate.spec import OptionError

    for option, given in (("--at", point), ("--set", values)):
        if name in given:
            raise OptionError([f"--sweep {name}: {name} takes the sweep's values; leave it out of {option}"])


def _complex(value: complex) -> str:
    return f"{value.real:.6g}{'+' if value.imag >= 0 else '-'}{abs(value.imag):.6g}i"


_SHARED: dict[str, Callable] = {}
_Format = Annotated[str, typer.Option(
    "--format", metavar="FORMAT", callback=choice("a format", lambda: STEADY_FORMATS),
    help="text, latex or json.")]
_Candidate = Annotated[Optional[list[str]], typer.Option(
    "--candidate", metavar="EXPR", help='An expression in the coordinates, rates and parameters to check for '
    'conservation along the equations, "C*dot(q)"; may be repeated.')]
_Timeout = Annotated[float, typer.Option(
    "--timeout", min=0, metavar="SECONDS", help="Seconds allowed for the whole command (0: no limit).")]
DEFAULT_TIMEOUT = 120.0   # gacli.budget.DEFAULT_TIMEOUT, a literal so that --help does not import SymPy


def register(app: typer.Typer, example: Callable, boundary: Callable, budget: Callable, derive: Callable) -> None:
    """Add ``steady`` and ``integrals`` to ``app``, with the shared helpers of :mod:`gacli.cli`."""
    _SHARED.update(boundary=boundary, budget=budget, derive=derive)
    app.command(**example("gacli steady systems/rolling_disk.yaml"))(steady)
    app.command(**example('gacli integrals systems/spinning_top.yaml --candidate "C*dot(q)"'))(integrals)


def steady(file: SystemPath, format_: _Format = "text", timeout: _Timeout = DEFAULT_TIMEOUT) -> None:
    """Find the families of steady motions.

    Each with its free values and the conditions it needs.

    The coordinates the equations do not contain move at constant rates,
    the others stand still, and the accelerations vanish (docs/steady.md).
    """
    from gacli.display import console

    from gacli.pipeline import STEPS  # a system too large to print is refused without its closed forms

    with _SHARED["boundary"](), _SHARED["budget"](file, timeout) as state:
        derivation = _SHARED["derive"](file, state, STEPS)
        state("solving for the steady motions")
        from gacli.steady.motions import steady_motions
        from gacli.steady.report import motions_text

        text = motions_text(steady_motions(derivation), format_, derivation.system)
    console.raw(text)


def integrals(file: SystemPath, candidate: _Candidate = None, format_: _Format = "text",
              timeout: _Timeout = DEFAULT_TIMEOUT) -> None:
    """List the first integrals and check candidates.

    Those the system provably has.

    The energy when nothing works on the system, a momentum for each
    ignorable coordinate whose rate the constraints let it keep, and each
    --candidate, differentiated along the equations (docs/steady.md). Exit
    code 1 when a candidate is not conserved.
    """
    from gacli.display import console

    from gacli.pipeline import STEPS

    with _SHARED["boundary"](), usage_errors_here(), _SHARED["budget"](file, timeout) as state:
        derivation = _SHARED["derive"](file, state, STEPS)
        from gacli.steady.integrals import parse_candidate

        expressions = [parse_candidate(derivation, text) for text in candidate or ()]
        state("differentiating along the equations")
        from gacli.steady.integrals import integrals as find
        from gacli.steady.report import integrals_text

        result = find(derivation, expressions)
        text = integrals_text(result, format_, derivation.system)
    console.raw(text)
    if any(c.conserved is False for c in result.candidates):
        raise typer.Exit(code=1)


def usage_errors_here():
    from gacli.cli_options import usage_errors

    return usage_errors()
