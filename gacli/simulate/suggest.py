"""Which state name a mistyped one meant: ``xdot`` is ``dot(x)``, not the nearest string.

Plain string likeness (difflib) ranks ``xdot`` nearer ``dot(y)`` than
``dot(x)``: both share ``dot`` and one letter. A person writing a rate writes
a base name and a rate mark (``xdot``, ``x_dot``, ``x'``, ``dx``,
``dot_x``), so the mark is read first and the base name matched exactly,
then without regard to case; likeness is the last resort, and is measured on
the base names alone.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Sequence

_RATE = re.compile(r"^(?:dot\((?P<inner>.+)\)|(?P<lead>dot_?|d_?)(?P<after>\w+)|(?P<before>\w+?)(?P<trail>_?dot|'))$")


def _split(name: str) -> list[tuple[str, int]]:
    """Readings of ``name`` as (base, order): as written, and with a rate mark taken off."""
    readings = [(name, 0)]
    match = _RATE.match(name)
    if match:
        base = match.group("inner") or match.group("after") or match.group("before")
        readings.insert(0, (base, 1))
    return readings


def _state_name(base: str, order: int) -> str:
    return f"dot({base})" if order else base


def closest_state(written: str, state: Sequence[str]) -> str | None:
    """The entry of ``state`` that ``written`` most likely means, or None."""
    entries = {(m.group(1), 1) if (m := re.fullmatch(r"dot\((.+)\)", s)) else (s, 0): s for s in state}
    readings = _split(written)
    for same in (str.__eq__, lambda a, b: a.lower() == b.lower()):
        for base, order in readings:
            for (b, o), entry in entries.items():
                if o == order and same(b, base):
                    return entry
    for base, order in readings:
        bases = [b for b, o in entries if o == order]
        close = difflib.get_close_matches(base, bases, n=1, cutoff=0.6)
        if close:
            return _state_name(close[0], order)
    if len(readings) > 1:
        return None  # a rate of nothing like a state name: better no guess than dot(y) for zdot
    close = difflib.get_close_matches(written, list(state), n=1)
    return close[0] if close else None
