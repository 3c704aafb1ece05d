"""The resource budget of one command on one file, shared by every command.

``gacli check`` stops a runaway file with a wall-clock budget (the SIGALRM
:func:`gacli.numeric.zero.time_limit`, main thread only). Every other
command (derive, gibbs, verify, linearize, simulate) uses the same limit
through :func:`budget`, so that a file which makes SymPy work forever ends
in one located message naming the step that was running, never a hang or
a traceback. Running out of memory is reported the same way.
"""

from __future__ import annotations

import contextlib
import traceback
from collections.abc import Iterator

from gacli.errors import Diagnostic, Location, OutOfTime, SystemFileError
from gacli.numeric.zero import time_limit

DEFAULT_TIMEOUT = 120.0
TIMEOUT_HELP = "Seconds allowed for the whole command (0: no limit)."

# The same step names as gacli check's (gacli.check.STEP_READ, STEP_LOAD).
STEP_READ = "reading the file"
STEP_LOAD = "loading the declarations and expressions"
STEP_PROGRAM = "building the program (frames, velocities and accelerations, eq. 14.14)"


class _OutOfTime(OutOfTime):
    """Raised by the alarm inside the work; turned into a located error on the way out."""


class Budget:
    """Remembers the running step (it is derive's progress callback) and whether time ran out."""

    def __init__(self, path: str, seconds: float | None) -> None:
        self.path = path
        self.seconds = seconds
        self.step = STEP_READ
        self.expired = False

    def __call__(self, step: str) -> None:
        self.step = step

    def _alarm(self) -> _OutOfTime:
        self.expired = True
        return _OutOfTime(self.message())

    def message(self) -> str:
        return (f"ran out of time in the step '{self.step}' "
                f"(the budget is {self.seconds:g} s; raise it with --timeout)")

    def error(self, message: str) -> SystemFileError:
        # Line 1, column 1: the whole file is at fault, not one entry of it.
        return SystemFileError([Diagnostic(Location(self.path, 1, 1), message)])


@contextlib.contextmanager
def budget(path: str, seconds: float | None) -> Iterator[Budget]:
    """Run the block within ``seconds`` (None or 0: no limit); yields the step recorder.

    Past the budget, or out of memory, the block ends with a SystemFileError
    located at the file and naming the step. A library that catches the
    alarm's error and raises its own is recognised by the ``expired`` flag.
    """
    state = Budget(path, seconds)
    try:
        with time_limit(seconds or 0, state._alarm):
            yield state
    except MemoryError as exc:
        forget_frames(exc)
        raise state.error(f"ran out of memory in the step '{state.step}'") from None
    except RecursionError as exc:
        # SymPy's polynomial code recurses once per generator: a sum of a thousand loads with
        # sin(i*y) in each is a polynomial in a thousand generators, past Python's stack.
        forget_frames(exc)
        raise state.error(f"the expressions are too deeply nested for SymPy in the step '{state.step}' "
                          "(Python's recursion limit)") from None
    except Exception as exc:
        if state.expired:
            forget_frames(exc)
            raise state.error(state.message()) from None
        raise


def forget_frames(exc: BaseException) -> None:
    """Drop the locals of the frames an abandoned computation left in ``exc``'s traceback.

    The new error keeps the old one as its context, and the old one's
    frames hold the half-built expressions (hundreds of MB for a runaway
    expansion) in reference cycles that the collector frees late: `check`
    over a folder, or a notebook, would grow by that much per file.
    """
    seen: set[int] = set()
    while exc is not None and id(exc) not in seen:
        seen.add(id(exc))
        traceback.clear_frames(exc.__traceback__)
        exc = exc.__context__
