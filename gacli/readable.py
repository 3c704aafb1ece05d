"""Simplification for reading, within a time budget.

Everything printed for people goes through :class:`Tidy`; generated code
never does, so display choices cannot change what a simulator computes.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import sympy as sp

# sympy.simplify grows quickly with size; above this many operations only
# cheap rational cancellation is tried.
SIMPLIFY_OPS = 400
STEP_BUDGET_SECONDS = 5.0


@dataclass
class Tidy:
    """Simplify expressions until ``budget`` seconds have been spent, then show them as derived."""

    budget: float = STEP_BUDGET_SECONDS
    started: float = field(default_factory=time.monotonic)

    def __call__(self, expr: sp.Expr) -> sp.Expr:
        if time.monotonic() - self.started > self.budget:
            return expr
        if sp.count_ops(expr) <= SIMPLIFY_OPS:
            return sp.simplify(expr)
        return sp.cancel(expr)

    def collected(self, expr: sp.Expr, accelerations) -> sp.Expr:
        """Collected on the accelerations, each coefficient tidied."""
        expanded = sp.expand(expr) if sp.count_ops(expr) <= SIMPLIFY_OPS else expr
        parts = sp.collect(expanded, list(accelerations), evaluate=False)
        total = sp.S.Zero
        for key in sorted(parts, key=sp.default_sort_key):
            total += self(parts[key]) * key
        return total


def show(expr) -> str:
    """An expression in the system file's grammar (``dot(x)``, ``**``)."""
    return sp.sstr(expr, order="lex")
