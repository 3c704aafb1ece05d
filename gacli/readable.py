"""Simplification for reading, within a budget of operations per step.

Everything printed for people goes through :class:`Tidy`; generated code
never does, so display choices cannot change what a simulator computes.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.graph import LARGE_TREE, is_large, is_small

# sympy.simplify grows quickly with size; above this many operations only
# cheap rational cancellation is tried.
SIMPLIFY_OPS = 250
# The budget of one step, counted in operations handed to simplify rather
# than in seconds, so that the output is the same on a slow machine.
STEP_BUDGET_OPS = 5_000
# An equation of motion too large to walk as a tree is not printed for people
# either: the code emitters share its subexpressions instead.
DISPLAY_NODES = LARGE_TREE
TOO_LARGE = ("The equations of this system are too large to print for reading "
             f"(an entry of M or F has more than {DISPLAY_NODES:,} terms as a tree). "
             "Generate code instead, which shares their common subexpressions: "
             "--format python or --format c.")


@dataclass
class Tidy:
    """Simplify expressions until ``budget`` operations have been simplified, then show them as derived."""

    budget: int = STEP_BUDGET_OPS
    spent: int = 0

    def __call__(self, expr: sp.Expr) -> sp.Expr:
        if not is_small(expr, 8 * SIMPLIFY_OPS):
            return expr
        ops = sp.count_ops(expr)
        if self.spent + ops > self.budget:
            return expr
        self.spent += ops
        if ops <= SIMPLIFY_OPS:
            return sp.simplify(expr)
        return sp.cancel(expr)

    def collected(self, expr: sp.Expr, accelerations) -> sp.Expr:
        """Collected on the accelerations, each coefficient tidied."""
        expanded = sp.expand(expr) if is_small(expr, 2 * SIMPLIFY_OPS) else expr
        parts = sp.collect(expanded, list(accelerations), evaluate=False)
        total = sp.S.Zero
        for key in sorted(parts, key=sp.default_sort_key):
            total += self(parts[key]) * key
        return total


def displayable(d) -> bool:
    """Whether the derivation's M and F are small enough to print as formulas."""
    return not any(is_large(e) for e in (*d.mass_matrix, *d.forcing))


def show(expr) -> str:
    """An expression in the system file's grammar (``dot(x)``, ``**``)."""
    return sp.sstr(expr, order="lex")
