"""One route from a system file to its equations, for every command and the API (issue #28).

file (or standard input) → :class:`SourceFile` → ``System`` → equations, each
step once: the file is read once and loaded once (the rolling rows, which
only the chapter's closed forms need, are added to the same load when they
are needed, :func:`gacli.loader.loading.load_in_stages`), and the equations
are built once. ``gacli derive``, ``gacli check``, ``gacli gibbs``,
``gacli verify`` and the other commands call :func:`run`; each reports the
steps to its budget through ``progress``.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from gacli.algebra.graph import tree_nodes, trees_within
from gacli.budget import STEP_LOAD, STEP_PROGRAM, STEP_READ
from gacli.loader.loading import load_in_stages
from gacli.mechanics.equations import Derivation, derive, derive_for_code
from gacli.mechanics.program.record import program_operations
from gacli.mechanics.read_off import read_off
from gacli.display.long import limit, printed_expressions
from gacli.display.report import prints_written_out
from gacli.model import System
from gacli.read.source import MAX_FILE_BYTES, SourceFile, parse_source, read_source

STDIN = "-"
STDIN_NAME = "<stdin>"


@dataclass(frozen=True)
class Run:
    """What one command built from one file: its source, its System, its equations."""

    source: SourceFile
    system: System
    derivation: Derivation  # for a code-only run, possibly without closed forms (Derivation.closed)


def read(path: str | Path) -> SourceFile:
    """The source of a system file, or of standard input for ``-`` (read up to the same size limit)."""
    if str(path) == STDIN:
        data = sys.stdin.buffer.read(MAX_FILE_BYTES + 1)
        return parse_source(data, STDIN_NAME)
    return read_source(path)


# Operations of a program from which a printout names the program's quantities without forming
# the closed forms at all (PRINTOUT, below): no system of the repository whose program
# is this large prints written out, and forming its closed forms is what costs a bicycle its time.
PROGRAM_ALONE = 800


# What a command reads of the derivation, which decides how much of it is formed.
CLOSED = "closed"  # the chapter's closed forms: β, the motions, Q, G (verify, --reactions, the API)
CODE = "code"  # q̇, M and F as generated code computes them
MATRICES = "matrices"  # the same, of the System with its rolling rows (check, which classifies every row)
PRINTOUT = "printout"  # q̇, M, F and Q as derive, gibbs and LaTeX print them, read off the program
STEPS = "steps"  # the closed forms, unless the program is so large that a printout names its quantities
# (--steps, steady, integrals, check, and simulate, whose integrals read them where small)


def needs_of(code: bool, reactions: bool, steps: bool = False) -> str:
    """What ``derive`` reads: generated code or a printout, unless reactions ask for the closed
    forms, or the worked solution for the steps that lead to them."""
    return CLOSED if reactions else CODE if code else STEPS if steps else PRINTOUT


def run(path: str | Path, *, needs: str = CLOSED, progress: Callable[[str], None] | None = None,
        loaded: Callable[[System], None] | None = None) -> Run:
    """Read, load and derive ``path`` once.

    ``needs``: for CODE, a system the program builder takes is derived by the program alone
    (:func:`gacli.mechanics.equations.derive_for_code`): generated code computes it, and
    neither the closed forms nor the rolling rows are formed; for MATRICES the same program, of the
    System with its rolling rows. For PRINTOUT, q̇, M, F and Q
    are read off that program (:func:`gacli.mechanics.read_off.read_off`) and the closed
    route is not run, where they print written out within the bound (docs/printing.md); where
    they would not, the closed forms are formed as before, since inlined they can print far
    longer (a tricycle's dependent accelerations: 18,637 characters for one entry of Q − F
    that prints in 869 in closed form). For STEPS, the closed forms are formed. Either way, a
    system whose program has at least PROGRAM_ALONE operations prints the program's named
    quantities, and forms nothing. The rolling rows are added for either, for the count ℓ
    of the rows it reports. ``loaded`` sees the System before it is derived (gacli check's notes on the
    declarations, kept if the derivation fails).
    """
    step = progress or (lambda name: None)
    step(STEP_READ)
    source = read(path)
    return run_source(source, needs=needs, progress=step, loaded=loaded)


def run_source(source: SourceFile, *, needs: str = CLOSED, progress: Callable[[str], None] | None = None,
               loaded: Callable[[System], None] | None = None) -> Run:
    """:func:`run` from a source already read."""
    step = progress or (lambda name: None)
    step(STEP_LOAD)
    system, complete = load_in_stages(source)
    step(STEP_PROGRAM)
    if needs == CODE and (program := derive_for_code(system)) is not None:
        return Run(source, system, program)
    step(STEP_LOAD)
    system = complete()
    if loaded is not None:
        loaded(system)
    step(STEP_PROGRAM)
    if needs == MATRICES and (program := derive_for_code(system)) is not None:
        return Run(source, system, program)
    if needs in (PRINTOUT, STEPS) and (program := derive_for_code(system)) is not None:
        if program_operations(program.program) >= PROGRAM_ALONE:
            return Run(source, system, program)
        if needs == PRINTOUT and (read := read_off(system, program.program)) is not None:
            if prints_written_out(read) or not _closed_may_print_shorter(read):
                return Run(source, system, read)
            return Run(source, system, _printout(read, derive(system, progress=step)))
    return Run(source, system, derive(system, progress=step))


def _closed_may_print_shorter(read: Derivation) -> bool:
    """Whether the closed forms are worth forming to see if they print shorter than the forms read off
    the program, which did not print within the bound: only where those print, untidied, past
    CLOSED_WORTH times the bound (a tricycle's entry of 18,637 characters, which prints in 869 in closed
    form). Below it the read-off forms are named as they are: a five-bar's 6,486 characters for a
    bound of 5,125 spent 2 s of its derive forming closed forms it never printed."""
    exprs, worth = printed_expressions(read), CLOSED_WORTH * limit(read)
    # Each node prints at least one character: past ``worth`` nodes they print past it, unprinted.
    return not trees_within(exprs, worth) or sum(len(str(e)) for e in exprs) > worth


CLOSED_WORTH = 2


def _printout(read: Derivation, closed: Derivation) -> Derivation:
    """What prints where the forms read off the program do not print written out: the closed forms,
    when they are smaller and so may; else the read-off derivation, whose printout then names the
    program's quantities as the closed one's would, without tidying the closed forms only to find
    them too long (an Ackermann car's 5.7 s). Of the 40 such files of bench_text_derive, the 6 whose
    closed forms print written out have at most 0.91 of the read-off forms' nodes; none at 1 or more does."""
    return closed if tree_nodes(printed_expressions(closed)) < tree_nodes(printed_expressions(read)) else read
