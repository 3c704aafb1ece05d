"""Errors raised by gacli.

The tree::

    GacliError                      base of everything gacli raises on purpose
    ├── SystemFileError(ValueError) the system file is wrong; holds Diagnostics
    ├── DerivationError             a derivation step failed (e.g. out of time)
    └── EmitError                   an expression cannot be printed in a format

Anything else that escapes is a bug in gacli, not in the user's file.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True, order=True)
class Location:
    """A place in a system file; line and column count from 1."""

    path: str
    line: int = 0
    column: int = 0

    def __str__(self) -> str:
        if self.line <= 0:
            return self.path
        return f"{self.path}:{self.line}:{self.column}"


@dataclass(frozen=True)
class Diagnostic:
    """One problem found in a system file.

    ``where`` is the dotted path of the offending entry (``bodies.sphere.mass``),
    ``severity`` is ``"error"`` or ``"warning"``.
    """

    location: Location
    message: str
    where: str = ""
    hint: str = ""
    severity: str = "error"

    def __str__(self) -> str:
        where = f"{self.where}: " if self.where else ""
        hint = f" ({self.hint})" if self.hint else ""
        return f"{self.location}: {self.severity}: {where}{self.message}{hint}"


class GacliError(Exception):
    """Base class of the errors gacli raises for the user to read."""


@dataclass
class SystemFileError(GacliError, ValueError):
    """A system file that cannot be used, with every problem found in it."""

    diagnostics: list[Diagnostic] = field(default_factory=list)

    def __post_init__(self) -> None:
        super().__init__(str(self))

    def __str__(self) -> str:
        return "\n".join(str(d) for d in self.diagnostics)


class DerivationError(GacliError):
    """A derivation step could not be completed (for instance it ran out of time)."""


class OutOfTime(DerivationError):
    """A command's time budget ran out inside the work (gacli.budget raises it from its alarm): never
    taken for a failure of the step it interrupts, which may have a fallback of its own."""


class EmitError(GacliError):
    """An expression has no rendering in the requested output format."""
