"""Is an expression identically zero? simplify() while it is small, else seeded random points.

Used by the loader (:func:`vanishes`) and by ``gacli check``
(:func:`decide_zero`, in :mod:`gacli.check.integrability` and
:mod:`gacli.check.mass`); the points and the bounded evaluator are
:mod:`gacli.numeric`'s. Also the SIGALRM time limit every step uses.
"""

from __future__ import annotations

import cmath
import contextlib
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import sympy as sp

from gacli.algebra.coerce import as_expr
from gacli.errors import GacliError
from gacli.algebra.graph import is_small
from gacli.numeric.guarded import RELATIVE_TOLERANCE as _RELATIVE_TOLERANCE
from gacli.numeric.evaluator import Program
from gacli.numeric.guarded import UndefinedValue, evaluate
from gacli.numeric.samples import SEED as _SEED
from gacli.numeric.samples import random_point, sample_points

# simplify() is tried only below this many operations and for at most this
# long: it can take minutes even on small expressions (Piecewise, huge
# integers), and random points decide faster.
SIMPLIFY_MAX_OPS = 120
SIMPLIFY_SECONDS = 1.0
_POINTS = 10
_MIN_VALID_POINTS = 3


@dataclass(frozen=True)
class Decision:
    """Whether an expression is identically zero; ``zero`` is None when undecided.

    ``method`` is "symbolic" (proved by SymPy), "numeric" (random points) or
    "undecided" (no point could be evaluated).
    """

    zero: bool | None
    method: str


def decide_zero(expr, seed: int = _SEED, place: Callable[[dict], dict] | None = None) -> Decision:
    """Is ``expr`` identically zero? simplify() when small, else random points; ``place`` moves each
    point onto where the question is asked (Euler parameters onto their unit sphere)."""
    expr = as_expr(expr)
    if expr == 0:
        return Decision(True, "symbolic")
    if expr.is_Number:
        return Decision(False, "symbolic")
    if place is None and _clearly_nonzero(expr):  # simplify would take up to a second to say so
        return Decision(False, "numeric")
    simpler = _simplified(expr) if sp.count_ops(expr) <= SIMPLIFY_MAX_OPS else None
    if simpler == 0:
        return Decision(True, "symbolic")
    if simpler is not None and simpler.is_Number and simpler.is_finite:
        return Decision(False, "symbolic")
    return _numeric_zero(expr, seed, place)


class _TooSlow(Exception):
    pass


def _simplified(expr: sp.Expr) -> sp.Expr | None:
    """simplify(expr), or None when it is slow or fails (then random points decide)."""
    try:
        with time_limit(SIMPLIFY_SECONDS, _TooSlow):
            return sp.simplify(expr)
    except GacliError:  # an enclosing time budget ran out: not simplify's failure
        raise
    except Exception:  # noqa: BLE001 - _TooSlow, or SymPy gave up (PolynomialError, ...)
        return None


MAX_TIMER = 365 * 24 * 3600.0


@contextlib.contextmanager
def time_limit(seconds: float, error: Callable[[], BaseException]) -> Iterator[bool]:
    """Raise ``error()`` inside the block once ``seconds`` have passed; yields whether armed.

    SIGALRM, so only in the main thread (elsewhere nothing is armed). Limits
    nest: an enclosing limit that ends sooner is left to fire by itself, and
    the enclosing handler and timer are restored afterwards. The alarm
    repeats until the block gives up, in case a library swallows the error.
    """
    usable = hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
    outer_handler = signal.getsignal(signal.SIGALRM) if usable else None
    outer_left, outer_interval = signal.getitimer(signal.ITIMER_REAL) if usable else (0.0, 0.0)
    if not usable or not seconds or not seconds > 0 or outer_handler is None or 0 < outer_left <= seconds:
        yield False
        return
    # setitimer overflows (OverflowError) past what time_t in nanoseconds holds: --timeout 1e400 or inf
    # is a limit no run reaches, so it is a year, which the timer can hold.
    seconds = min(seconds, MAX_TIMER)
    alarm = _Alarm(error)
    started = time.monotonic()
    unraisable_hook = sys.unraisablehook
    sys.unraisablehook = alarm.quiet(unraisable_hook)
    signal.signal(signal.SIGALRM, alarm.fire)
    signal.setitimer(signal.ITIMER_REAL, seconds, min(seconds, 0.2))
    try:
        yield True
    finally:
        sys.unraisablehook = unraisable_hook
        while True:  # an alarm may land between two statements here: retry until disarmed
            try:
                alarm.armed = False
                signal.setitimer(signal.ITIMER_REAL, 0)
                signal.signal(signal.SIGALRM, outer_handler)
                if outer_left > 0:
                    left = max(outer_left - (time.monotonic() - started), 1e-3)
                    signal.setitimer(signal.ITIMER_REAL, left, outer_interval)
                break
            except BaseException as exc:  # noqa: BLE001 - re-raised unless it is our own late alarm
                if exc is not alarm.raised:
                    raise


class _Alarm:
    """The SIGALRM handler of one time limit; remembers what it raised."""

    def __init__(self, error: Callable[[], BaseException]) -> None:
        self.error = error
        self.armed = True
        self.raised: BaseException | None = None

    def fire(self, signum, frame) -> None:
        if self.armed:
            self.raised = self.error()
            raise self.raised

    def quiet(self, previous: Callable) -> Callable:
        """An unraisable-exception hook that drops this alarm's own error: fired inside a
        finalizer (__del__) while the frames unwind, it cannot be raised there, and Python
        would print it with a traceback; the alarm fires again in code that can raise it."""
        def hook(unraisable) -> None:
            if unraisable.exc_value is None or unraisable.exc_value is not self.raised:
                previous(unraisable)
        return hook


def _numeric_zero(expr: sp.Expr, seed: int, place: Callable[[dict], dict] | None = None) -> Decision:
    symbols = sorted(expr.free_symbols, key=lambda s: s.name)
    valid = 0
    # Positive points suit sqrt and log; signed ones catch abs and sign.
    points = sample_points(symbols, _POINTS // 2, seed) + sample_points(symbols, _POINTS // 2, seed + 1, signed=True)
    for point in map(place, points) if place else points:
        try:
            value, scale = evaluate(expr, point)
        except UndefinedValue:
            continue
        valid += 1
        if abs(value) > _RELATIVE_TOLERANCE * max(scale, 1):
            return Decision(False, "numeric")
    return Decision(True, "numeric") if valid >= _MIN_VALID_POINTS else Decision(None, "undecided")


# A value past this, relative to the largest of its terms, at one point in floating point is no
# rounding error: the expression is not zero, and neither expanded nor evaluated to 20 digits.
_CLEARLY = 1e-6


def _clearly_nonzero(expr: sp.Expr) -> bool:
    """Whether ``expr`` is far from zero at one generic point, in complex floating point: the cheap
    answer for most questions (a loop's turnings ask a thousand, nearly all nonzero: 3.7 ms each
    expanded and evaluated to 20 digits, a five-bar's 4 s)."""
    terms = sp.Add.make_args(expr)
    try:
        program = Program([expr, *terms])
        point = {s: complex(v) for s, v in random_point(program.symbols, 1).items()}
        value, *parts = program(point)
    except (ArithmeticError, ValueError, TypeError, OverflowError, UndefinedValue):
        return False
    if not all(cmath.isfinite(v) and abs(v.imag) <= 1e-12 * abs(v) for v in (value, *parts)):
        return False  # a complex value at a real point: left to the tests that say undefined
    return abs(value) > _CLEARLY * max([1.0, *(abs(v) for v in parts)])


def vanishes(expr: sp.Expr, simplify: bool = True) -> bool:
    """Zero exactly when cheap to see, else at three generic points (never hangs on a huge tree).

    The loader's test (a form's terms without a differential, a rolling row
    that vanishes): cheaper than :func:`decide_zero`, and it says no rather
    than undecided.

    Without ``simplify`` a small expression is only expanded before the
    numeric test: cheaper, for the many rows of a rolling contact.
    """
    if expr == 0:
        return True
    if _clearly_nonzero(expr):
        return False
    if is_small(expr, 200):
        try:
            if sp.expand(expr) == 0:
                return True
            if simplify:
                return sp.simplify(expr) == 0
        except (ArithmeticError, ValueError, TypeError, RecursionError):
            return False
    for seed in (1, 2, 3):
        try:
            value = complex(expr.xreplace(random_point(expr.free_symbols, seed)).evalf(20))
        except (ArithmeticError, ValueError, TypeError):
            return False
        if abs(value) > 1e-12:
            return False
    return True
