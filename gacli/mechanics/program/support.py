"""Which systems the program builder takes, and why not the others.

The builder works from the frame model (gacli.frame_model) of a file
written with frames, or from the bodies' positions and rotation forms of
one without (format 1), with every row the file states as a form
(constraints, those nonlinear in the rates too, knife edges,
quasi-coordinates) and the rolling contacts on any frame's plane, frames,
points and loads moving with time included. :func:`static_reason` says what rules a file out before
any building (docs/program.md, "What the program takes"); the build itself
can still refuse (:class:`Unsupported`), e.g. when the rows leave a coupled
block larger than the adjugate solve takes.
"""

from __future__ import annotations

import dataclasses

import sympy as sp

from gacli.algebra import symbols as S
from gacli.frame_model import FrameModel, FrameVector
from gacli.model import System


class Unsupported(Exception):
    """Raised inside the builder for what it does not take; caught by build_program, never escapes."""


def static_reason(system: System) -> str | None:
    """Why the builder does not take ``system`` (one sentence), or None when nothing rules it out yet."""
    model = system.frames
    if model is None:
        return _small_numbers(system, None)
    for check in (_small_numbers, _frames, _bodies, _rolling, _loads):
        reason = check(system, model)
        if reason:
            return reason
    return None


def _timed(e: sp.Expr, system: System) -> bool:
    """Whether ``e`` depends on time: through t or a function of time (its value or a rate of it)."""
    if e.has(S.T):
        return True
    names = {f.name for f in system.functions}
    return any(S.RATE_NAME.sub(r"\3", s.name) in names or s.name in names for s in e.free_symbols)


# The tape tells a vanishing entry by its values at generic points, with quantities of order
# one (gacli.mechanics.program.tape): a number written this small in the file (a load of
# 1e-12 K) would pass for a rounding error there.
SMALLEST_NUMBER = 1e-6


def _small_numbers(system: System, model: FrameModel | None) -> str | None:
    exprs = list(_expressions(model if model is not None else (system.bodies, system.forces, system.torques)))
    exprs += list(_expressions(tuple(c.form for c in system.constraints if not c.derived)))
    exprs += [system.potential] + ([c for _, c in system.work.coefficients] if system.work is not None else [])
    for e in exprs:
        for number in e.atoms(sp.Number):
            if number != 0 and abs(float(number)) < SMALLEST_NUMBER:
                return f"the number {number} is smaller than {SMALLEST_NUMBER:g}, where the program's zero tests do not tell it from a rounding error"
    return None


def _expressions(value):
    """Every SymPy expression in the frame model's records."""
    if isinstance(value, sp.MatrixBase):
        yield from (e for e in value if isinstance(e, sp.Basic))
    elif isinstance(value, sp.Basic):
        yield value
    elif isinstance(value, (tuple, list)):
        for item in value:
            yield from _expressions(item)
    elif dataclasses.is_dataclass(value):
        for f in dataclasses.fields(value):
            yield from _expressions(getattr(value, f.name))


def _frames(system: System, model: FrameModel) -> str | None:
    # A frame's origin moves only the plane a body rolls on (`on:`, contacts.py): vectors in
    # frames are free vectors (docs/frames.md), so the origin enters nothing else the program forms.
    for edge in model.edges:
        if edge.quaternion is not None and any(_timed(e, system) for e in edge.quaternion):
            return f"frame '{edge.name}' is turned by a quaternion that depends on time"
    return None


def _bodies(system: System, model: FrameModel) -> str | None:
    for body in model.bodies:
        if body.inertia is not None and body.frame is None:
            return f"the rigid body '{body.name}' has format-1 rotation forms, not a frame"
    return None


def _rolling(system: System, model: FrameModel) -> str | None:
    frames = {b.name: b.frame for b in model.bodies}
    for contact in model.rolling:
        if contact.axle is not None and sum(1 for c in contact.axle if c != 0) != 1:
            return f"the axle of '{contact.body}' is not along one of its frame's axes"
        if not _in_own_axes(contact.centre, frames[contact.body]):
            return f"the centre of '{contact.body}' is not given in its own axes"
    return None


def _in_own_axes(vector: FrameVector, frame: str | None) -> bool:
    return vector.origin is None and all(f == frame for f, _ in vector.terms)


def _loads(system: System, model: FrameModel) -> str | None:
    for load in model.loads:
        if any(f is None for f, _ in load.vector.terms):
            return f"a torque on '{load.body}' is given in body axes of format-1 forms"
    return None
