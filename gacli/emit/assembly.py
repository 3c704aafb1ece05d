"""What every code target computes, assembled once: the equations, CSE'd and printed.

A target (C, Python, Octave, JAX) is a printer and a template around one
:class:`Assembly`: which equations a function computes and in what order,
the shared subexpressions, the code of each result, the nonzero entries of
M, and which arguments and which entries of x, p and r the code reads (an
argument it does not read is unused; an entry it does not read need not
be unpacked).

M is walked through its nonzero entries only (the sparse representation
that SymPy keeps anyway): a wide system of n uncoupled bodies has k = n
rates but only k nonzero entries of M among k², and the targets fill the
rest of the array with zeros in one step.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.emit.naming import Entry, Layout
from gacli.emit.printers import CSE_PREFIX, Block, print_block
from gacli.errors import EmitError
from gacli.mechanics.equations import Derivation

# The parts a generated function may compute, in the order its block computes them.
PARTS = ("qdot", "M", "M_lower", "F")


@dataclass(frozen=True)
class Assembly:
    """One function's block and, per part, ``(slot, code)`` of each result.

    ``slots["M"]`` holds ``((i, j), code)`` for the nonzero entries of M,
    row-major; ``slots["M_lower"]`` those with ``j <= i`` (all that a
    Cholesky factorization reads); ``slots["qdot"]`` and ``slots["F"]``
    hold ``(index, code)`` for every entry.
    """

    block: Block
    slots: dict[str, tuple]
    k: int

    def dense(self, part: str) -> bool:
        """Whether every entry of the part is set: M with no zero entry, say."""
        full = {"M": self.k * self.k, "M_lower": self.k * (self.k + 1) // 2}.get(part)
        return full is None or len(self.slots[part]) == full

    def reads(self, lay: Layout, argument: str) -> bool:
        """Whether the code reads ``t``, or any entry of ``x``, ``p`` or ``r``."""
        if argument == "t":
            return S.T in self.block.symbols
        return bool(self.read_entries(lay, argument))

    def unused(self, lay: Layout) -> list[str]:
        """The arguments t, x, p, r that the code never reads, in that order."""
        return [arg for arg in ("t", "x", "p", "r") if not self.reads(lay, arg)]

    def read_entries(self, lay: Layout, vector: str) -> list[Entry]:
        """The entries of one vector that the code reads, in their order."""
        return [e for e in vector_entries(lay, vector) if e.symbol in self.block.symbols]


def refuse_reactions(reactions: bool) -> None:
    """The targets other than Python and C have no reactions() function: say so, for API callers
    (the command line refuses the option before deriving)."""
    if reactions:
        raise EmitError("the constraint forces are generated for Python and C only; leave out --reactions")


def vector_entries(lay: Layout, vector: str) -> tuple[Entry, ...]:
    return {"x": lay.state_entries, "p": lay.parameter_entries, "r": lay.r_entries}[vector]


def assemble(derivation: Derivation, names: dict, printer_class, parts: Sequence[str],
             prefix: str = CSE_PREFIX) -> tuple[Assembly, object]:
    """CSE over the parts' equations, in the order given, and print them with ``printer_class``.

    ``names`` maps each symbol to its code name (:attr:`Layout.identifiers`).
    Returns the assembly and the printer, from which a target reads what the
    code needs (``includes()``, ``imports()``).
    """
    keyed = [(part, equations(derivation, part)) for part in parts]
    flat = [(name, expr) for _, group in keyed for _, name, expr in group]
    block, printer = print_block(printer_class, names, flat, prefix=prefix)
    block = live_block(block, names)
    slots, start = {}, 0
    for part, group in keyed:
        codes = block.results[start:start + len(group)]
        slots[part] = tuple((slot, code) for (slot, _, _), code in zip(group, codes))
        start += len(group)
    return Assembly(block, slots, derivation.k), printer


_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def live_block(block: Block, names: Mapping[sp.Symbol, str]) -> Block:
    """The block without the temporaries that no result needs, found by reachability from the results.

    After CSE a temporary can be dead: terms that cancel when the reduced
    expressions are rebuilt (``_c2**2 - _c1**2`` with ``_c2 = -_c1``) take
    their uses with them, and C's ``-Werror=unused-variable`` refuses the
    declaration. Read on the printed code, so it holds for every target and
    whatever CSE ran. A symbol that only a dead temporary read is dropped from
    ``symbols`` too, so that its entry of x, p or r is not unpacked.
    """
    needed = {token for code in block.results for token in _TOKEN.findall(code)}
    kept = []
    for name, code in reversed(block.temporaries):
        if name in needed:
            kept.append((name, code))
            needed.update(_TOKEN.findall(code))
    if len(kept) == len(block.temporaries):
        return block
    dead = {token for name, code in block.temporaries if name not in needed for token in _TOKEN.findall(code)}
    symbols = frozenset(s for s in block.symbols if names.get(s, s.name) in needed or names.get(s, s.name) not in dead)
    return Block(tuple(reversed(kept)), block.results, symbols)


def equations(derivation: Derivation, part: str) -> list[tuple[object, str, sp.Expr]]:
    """``(slot, name, expression)`` of one part; the name is for error messages.

    The expressions are :attr:`Derivation.code`'s: the closed forms, or the
    straight-line program's where that costs fewer operations (gacli.mechanics.code).
    """
    code = derivation.code
    if part == "qdot":
        return [(i, f"dot({name})", expr) for i, (name, expr) in enumerate(code.kinematic_equations)]
    if part == "F":
        return [(s, f"F[{s}]", code.forcing[s]) for s in range(derivation.k)]
    return [((i, j), f"M[{i}, {j}]", expr) for (i, j), expr in mass_matrix_entries(derivation, part == "M_lower")]


def mass_matrix_entries(derivation: Derivation, lower: bool = False) -> list[tuple[tuple[int, int], sp.Expr]]:
    """The entries of M that are not identically zero, row-major; ``lower``: only those with j <= i.

    Read from the sparse form of M, never entry by entry: linear in the
    number of nonzero entries, not in k².
    """
    return [((i, j), expr) for (i, j), expr in derivation.code.mass_matrix if not (lower and j > i)]


# -- the constraint forces ------------------------------------------------------

def reaction_equations(derivation: Derivation) -> list[tuple[str, sp.Expr]]:
    """The multipliers λ of the constraints (docs/verify.md), in the state, one per constraint."""
    from gacli.reactions import constraint_forces

    forces = constraint_forces(derivation, simplify=False)
    return [(f"lambda[{i}]", forces[i]) for i in range(len(forces))]


@dataclass(frozen=True)
class ReactionSolve:
    """λ found by a numeric solve in the generated code: K z = b, λ = z[first:first + count].

    For systems too large to print, whose symbolic λ (:func:`reaction_equations`)
    would need a solve of equations millions of terms long; K and b are the
    fundamental equations in all the rates (:class:`gacli.reactions.ReactionSystem`).
    """

    size: int
    first: int
    count: int
    redundant: bool  # K is singular by construction: λ is the minimum-norm solution
    nonzero: tuple[tuple[int, int], ...]  # the entries of K that are not identically 0, row-major
    equations: list[tuple[str, sp.Expr]]  # those entries of K, then the size entries of b


def reaction_solve(derivation: Derivation) -> ReactionSolve | None:
    """How generated code finds λ numerically; None when :func:`reaction_equations` gives it in closed form."""
    from gacli.algebra.readable import displayable
    from gacli.reactions import reaction_system

    if displayable(derivation):
        return None
    system = reaction_system(derivation)
    size = system.K.rows
    nonzero = tuple((i, j) for i in range(size) for j in range(size) if system.K[i, j] != 0)
    equations = [(f"K[{i}, {j}]", system.K[i, j]) for i, j in nonzero]
    equations += [(f"b[{i}]", system.b[i]) for i in range(size)]
    return ReactionSolve(size, system.rates, system.constraint_count, system.redundant, nonzero, equations)
