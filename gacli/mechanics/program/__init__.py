"""The right-hand side of a system as a straight-line program.

:func:`build_program` writes q̇, M and F of M u̇ = F (the same M and F as
:func:`gacli.mechanics.equations.derive`, eq. 14.19) as ordered scalar
assignments from the state, the parameters and the inputs, working from
the frame model (gacli.frame_model) rather than from closed forms: frames
as a tree of simple rotations, velocities by passes of rates, the rows
(rolling, and those the file states as forms) solved by numbers, bodies
gathered into units; a file without frames from its bodies' positions and
rotation forms. :func:`unsupported`
says why a system is outside what it takes; :func:`inline` gives the
closed forms as shared expression graphs.

Modules: ``tape`` (assignments, value numbering, the zero test), ``vectors``,
``frames`` (the frame tree), ``contacts`` and ``motion`` (points, rolling),
``forms`` (rows stated as forms), ``formbodies`` (bodies of a file without frames;
``heading``: their points along the heading the stated rows were solved along),
``rows`` and ``solve`` (eqs. 14.1, 14.7), ``units``, ``loads`` and
``assemble`` (eqs. 14.13-14.19), ``build`` (the steps in order), ``record``
(the :class:`Program`), ``support`` (what is taken).
"""

from __future__ import annotations

from gacli.mechanics.program.build import program_of
from gacli.mechanics.program.record import Program, inline
from gacli.mechanics.program.support import Unsupported, static_reason
from gacli.model import System

__all__ = ["Program", "build_program", "inline", "unsupported"]


def _attempt(system: System, judge=None) -> Program | str:
    reason = static_reason(system)
    if reason is not None:
        return reason
    try:
        return program_of(system, judge)
    except Unsupported as exc:
        return str(exc)


def build_program(system: System, judge=None) -> Program | None:
    """The program of ``system``, or None when it is outside what the builder takes (see :func:`unsupported`);
    ``judge``: what generated code would cost, for the programs built that cost nearly the least."""
    result = _attempt(system, judge)
    return result if isinstance(result, Program) else None


def unsupported(system: System) -> str | None:
    """Why :func:`build_program` does not take ``system``, in one sentence; None when it does."""
    result = _attempt(system)
    return None if isinstance(result, Program) else result
