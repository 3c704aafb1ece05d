"""The parameter values a system file gives, as every code target writes them.

C's ``NAME_default_parameters``, Octave's ``NAME_defaults`` (and the
``DEFAULTS`` of Python and JAX, the FMU's start values) hold the numbers of
:func:`gacli.emit.naming.parameter_defaults`: a value written as an expression
in earlier parameters (``HTA = pi/2 - pi/10``, ``acos(tempa/tempc)``) is
evaluated exactly, in the file's order, when the code is generated, and the
targets write the number with the formula beside it as a comment. Numbers
rather than formulas: the generated code stays free of anything beyond its
arithmetic, and a user who changes a parameter that others are computed from
changes those too (the comment shows how).
"""

from __future__ import annotations

from dataclasses import dataclass

from gacli.algebra.readable import show
from gacli.emit.naming import Entry, Layout
from gacli.mechanics.equations import Derivation
from gacli.read.textsafe import one_line


@dataclass(frozen=True)
class Default:
    """One entry of p: its value (None when the file gives none, or none that is a number)."""

    entry: Entry
    value: float | None
    formula: str       # the file's expression when it is not a plain number, else ""
    given: bool        # whether the file writes a value at all


def defaults(derivation: Derivation, lay: Layout) -> tuple[Default, ...]:
    """Every parameter in the order of p, with its default."""
    written = {p.name: p.value for p in derivation.system.parameters}
    rows = []
    for entry in lay.parameter_entries:
        text = written[entry.name]
        # In the file's grammar (exp(1), not SymPy's E, which a parameter may be named).
        formula = "" if text is None or text.is_Number else one_line(show(text))
        rows.append(Default(entry, lay.defaults.get(entry.name), formula, text is not None))
    return tuple(rows)


def missing(rows: tuple[Default, ...]) -> int:
    """How many parameters have no default."""
    return sum(row.value is None for row in rows)
