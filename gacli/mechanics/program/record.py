"""The program as a record: assignments in evaluation order, and the outputs q̇, M, F over them.

M u̇ = F in the independent speeds (eq. 14.19) and q̇ of every coordinate
(eqs. 14.7, 14.20), each output a state symbol, a number, or a symbol the
assignments define, so that code can evaluate the assignments in order and
read the outputs off. :func:`inline` gives closed forms instead, as
expression graphs sharing their subexpressions.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy as sp

from gacli.algebra.graph import cse_operations, free_symbols, operations, substitute, trees_within
from gacli.mechanics.program.tape import Tape


@dataclass(frozen=True)
class Program:
    """A straight-line program for q̇, M and F (see the module)."""

    assignments: tuple[tuple[sp.Symbol, sp.Expr], ...]  # in evaluation order; each symbol assigned once
    rates: tuple[tuple[str, sp.Expr], ...]  # (coordinate, q̇), every coordinate, in declaration order
    mass_matrix: tuple[sp.Expr, ...]  # k × k entries, row-major (symmetric)
    forcing: tuple[sp.Expr, ...]  # k entries
    stages: tuple[tuple[str, int], ...]  # (stage, number of assignments written in it), in order
    independent: tuple[str, ...] = ()  # the speeds u of M u̇ = F, in their order
    # (symbol, label) of the assignments the tape labelled (gacli.mechanics.program.tape), in order:
    # what the printout names them by (gacli.display.named).
    labels: tuple[tuple[sp.Symbol, tuple], ...] = ()
    # Q of eq. (14.13), k entries over the assignments, for the printout alone (not an output: code
    # never computes it); None where it would read an assignment the outputs do not need.
    generalized_forces: tuple[sp.Expr, ...] | None = None
    # The spheres the system keeps coordinates on (gacli.numeric.spheres): code may read its
    # polynomials on them, where the motion is.
    spheres: tuple = ()

    @property
    def k(self) -> int:
        return len(self.forcing)

    @functools.cached_property
    def inlinings(self) -> tuple[list[tuple[tuple, int | None]], bool]:
        """:func:`inlinings` of this program, found once (a frozen dataclass may cache in its __dict__)."""
        return inlinings(self)

    @property
    def outputs(self) -> list[sp.Expr]:
        """q̇ of every coordinate, M row-major, then F."""
        return [*(e for _, e in self.rates), *self.mass_matrix, *self.forcing]

    def __repr__(self) -> str:
        # One line: the dataclass repr would print every assignment.
        return (f"<Program: {len(self.assignments)} assignments; {len(self.rates)} rates, "
                f"M {self.k}x{self.k}, F {self.k}x1>")


def finish(tape: Tape, rates: dict[str, sp.Expr], sums, k: int) -> Program:
    """Sum M (r ≤ s, mirrored) and F, and keep only the assignments the outputs need."""
    tape.stage = "M"
    M = [[None] * k for _ in range(k)]
    for r in range(k):
        for s in range(r, k):
            # Shares that cancel across units, or across Euler parameters' terms (a top's M₁₂), are zero.
            M[r][s] = M[s][r] = tape.nonzero(sp.Add(*sums.M[r][s]), name=("M", r, s))
    tape.stage = "F"
    F = [tape.nonzero(sp.Add(*sums.F[r]), name=("F", r)) for r in range(k)]
    outputs = [*rates.values(), *(x for row in M for x in row), *F]
    assignments = _needed(tape.assignments, outputs)
    stages: dict[str, int] = {}
    for _, _, stage in assignments:
        stages[stage] = stages.get(stage, 0) + 1
    labels = tuple((name, tape.labels[name]) for name, _, _ in assignments if name in tape.labels)
    return Program(tuple((name, e) for name, e, _ in assignments), tuple(rates.items()),
                   tuple(x for row in M for x in row), tuple(F), tuple(stages.items()), labels=labels,
                   generalized_forces=_forces(tape, assignments, sums.Q))


def _forces(tape: Tape, kept: list, terms: list) -> tuple[sp.Expr, ...] | None:
    """Q_r, the loads' terms of F_r summed. A load's component the outputs no longer read (−m g,
    folded with the inertia into one assignment) is written into Q by its value; None where that
    takes more than a few rounds."""
    Q = tuple(sp.Add(*t) for t in terms)
    values = {name: e for name, e, _ in tape.assignments}
    for name, _, _ in kept:
        values.pop(name)
    for _ in range(_FORCE_ROUNDS):
        missing = {s: values[s] for s in free_symbols(Q) if s in values}
        if not missing:
            return Q
        Q = tuple(q.xreplace(missing) for q in Q)
    return None


# Assignments written into Q one inside another, at most: a load's component is one or two deep.
_FORCE_ROUNDS = 4


def _needed(assignments: list, outputs: list) -> list:
    """The assignments the outputs depend on, in order: the others were written to test or to choose
    (a row entry that vanished, a moment that cancelled)."""
    live = free_symbols(outputs)
    kept = []
    for name, e, stage in reversed(assignments):
        if name in live:
            kept.append((name, e, stage))
            live |= e.free_symbols
    return kept[::-1]


def inline(program: Program, evaluate: bool = False) -> tuple[list[sp.Expr], list[sp.Expr], list[sp.Expr]]:
    """(q̇, M, F) with the assignments substituted, as expression graphs sharing their subexpressions.

    Sums, products and powers are rebuilt unevaluated: SymPy's evaluation
    flattens a sum into the sum it is a term of and distributes a number
    over a sum, so that a shared subexpression is copied into each of its
    uses (the bicycle: 1,053 operations as a program, 1,540 inlined with
    ``evaluate=True``, 1,048 without). The unevaluated forms have the same
    values; ``evaluate=True`` gives SymPy's canonical ones.
    """
    outputs = _inlined(program, program.outputs, evaluate)
    n, kk = len(program.rates), program.k * program.k
    return outputs[:n], outputs[n:n + kk], outputs[n + kk:]


def inline_with_forces(program: Program) -> tuple[list[sp.Expr], ...] | None:
    """(q̇, M, F, Q) in SymPy's canonical forms, for the printout (gacli.mechanics.read_off); None
    without Q (:attr:`Program.generalized_forces`)."""
    if program.generalized_forces is None:
        return None
    outputs = _inlined(program, [*program.outputs, *program.generalized_forces], True)
    n, kk, k = len(program.rates), program.k * program.k, program.k
    return outputs[:n], outputs[n:n + kk], outputs[n + kk:n + kk + k], outputs[n + kk + k:]


def _inlined(program: Program, outputs: list[sp.Expr], evaluate: bool) -> list[sp.Expr]:
    values: dict[sp.Symbol, sp.Expr] = {}
    for name, e in program.assignments:
        values[name] = substitute([e], values, evaluate)[0]
    return substitute(outputs, values, evaluate)


def program_operations(program: Program) -> int:
    """The program's operations: its assignments and outputs, each repeated piece once."""
    return operations([*(e for _, e in program.assignments), *program.outputs])


def inlinings(program: Program) -> tuple[list[tuple[tuple, int | None]], bool]:
    """The forms generated code may take the program in (:func:`inline`), each with its operations
    after the code emitters' CSE: as shared graphs, and, where their trees are within what
    SymPy's cse takes (gacli.algebra.graph.CSE_TREES), in SymPy's canonical form too. Evaluation
    gathers a bar's I + m (l/2)² into m l²/3 (a three-link chain: 110 operations against 99; a
    rattleback: 1,195 against 894), but copies a shared sum into each sum it is a term of (the
    bicycle: 1,469 → 2,047 as a graph). Returns ``[((q̇, M, F), operations), ...]`` and whether
    the trees are within that size (past it, the one form's operations are None: the program's
    own count stands for them). Found once per program (:attr:`Program.inlinings`: the builder
    costs its candidates, and generated code then takes the cheapest).
    """
    plain = inline(program)
    if not trees_within([e for part in plain for e in part]):
        return [(plain, None)], False
    forms = [plain]
    evaluated = inline(program, evaluate=True)
    if trees_within([e for part in evaluated for e in part]):
        forms.append(evaluated)
    return [(f, cse_operations([*f[0], *f[1], *f[2]])) for f in forms], True


def cost(program: Program) -> int:
    """The operations of the program's cheapest inlining after the code emitters' CSE."""
    forms, small = program.inlinings
    if not small:
        return program_operations(program)
    return min(count for _, count in forms)
