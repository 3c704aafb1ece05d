"""Which constraints are holonomic, which quasi-coordinates are coordinates (Frobenius).

A Pfaffian form ω = Σ a_i dx_i runs over the differentials of the
coordinates, of the quasi-coordinates and of t (time is one more variable);
its coefficients are functions of the coordinates and t (parameters and the
free functions of time ride along: a free function Omega has dOmega/dt =
dot(Omega)). Quasi-coordinates have no value, so no coefficient depends on
them. Then:

* a constraint ω = 0 is integrable (holonomic) iff ω ∧ dω = 0, the Frobenius
  condition for a single form;
* a quasi-coordinate dθ = ω is a true coordinate iff ω is closed, dω = 0
  (then, locally, ω = dθ for a function θ of the coordinates and t).

In components, with c_ij = ∂_i a_j − ∂_j a_i (dω = Σ_{i<j} c_ij dx_i ∧ dx_j)::

    dω = 0       ⇔  c_ij = 0                              for all i < j
    ω ∧ dω = 0   ⇔  a_i c_jk − a_j c_ik + a_k c_ij = 0     for all i < j < k

Each component is decided by :func:`decide_zero`: ``simplify`` while the
expression is small, and otherwise (or when simplify leaves something that
is not a number) by evaluating it at seeded random points.

Each form is tested on its own: a set of constraints can be integrable
together only if each one is integrable modulo the others, which this module
does not test.
"""

from __future__ import annotations

import contextlib
import itertools
import random
import signal
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import sympy as sp

from gacli import symbols as S
from gacli.coerce import as_expr
from gacli.evaluate import _RELATIVE_TOLERANCE, UndefinedValue, evaluate  # noqa: F401 - re-exported
from gacli.errors import GacliError, Location
from gacli.kinematics import function_chain
from gacli.model import Form, System

# simplify() is tried only below this many operations and for at most this
# long: it can take minutes even on small expressions (Piecewise, huge
# integers), and random points decide faster.
SIMPLIFY_MAX_OPS = 120
SIMPLIFY_SECONDS = 1.0
_SEED = 20261122
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


@dataclass(frozen=True)
class Classification:
    """The verdict on one constraint or one quasi-coordinate differential.

    ``kind`` is "constraint" or "quasi_coordinate"; ``integrable`` is True
    for a holonomic constraint or a quasi-coordinate that is a coordinate,
    None when undecided. ``method`` is "relation" (a constraint written as
    f(q, t) = 0), "symbolic", "numeric" or "undecided".
    """

    kind: str
    where: str
    text: str
    location: Location
    integrable: bool | None
    method: str

    @property
    def verdict(self) -> str:
        if self.integrable is None:
            return "undecided"
        if self.kind == "constraint":
            return "holonomic" if self.integrable else "non-holonomic"
        return "a coordinate" if self.integrable else "not a coordinate"


def classify(system: System) -> tuple[Classification, ...]:
    """Classify every constraint and every quasi-coordinate given by a differential."""
    out = []
    for i, constraint in enumerate(system.constraints):
        where = f"constraints[{i}]"
        if constraint.relation is not None:
            out.append(Classification("constraint", where, constraint.text, constraint.location, True, "relation"))
            continue
        decision = is_integrable(constraint.form, system)
        out.append(Classification("constraint", where, constraint.text, constraint.location,
                                  decision.zero, decision.method))
    for q in system.quasi_coordinates:
        if q.differential is None:
            continue
        decision = is_closed(q.differential, system)
        out.append(Classification("quasi_coordinate", f"quasi_coordinates.{q.name}", _form_text(q.differential),
                                  q.location, decision.zero, decision.method))
    return tuple(out)


def is_closed(form: Form, system: System) -> Decision:
    """dω = 0 ?"""
    exterior = _Exterior(form, system)
    return _all_zero(exterior.d_component(i, j) for i, j in itertools.combinations(exterior.variables, 2))


def is_integrable(form: Form, system: System) -> Decision:
    """ω ∧ dω = 0 ?"""
    exterior = _Exterior(form, system)
    return _all_zero(exterior.wedge_component(i, j, k)
                     for i, j, k in itertools.combinations(exterior.variables, 3))


class _Exterior:
    """The coefficients of one form and the derivatives its exterior derivative needs."""

    def __init__(self, form: Form, system: System) -> None:
        self.coordinates = {c.name for c in system.coordinates}
        self.chain = function_chain(system)
        self.a = {name: coefficient for name, coefficient in form.coefficients}
        self.a["t"] = form.dt
        self.variables = self._active(system)
        self._d: dict[tuple[str, str], sp.Expr] = {}

    def _active(self, system: System) -> list[str]:
        """Variables with a coefficient, or on which some coefficient depends (declaration order)."""
        free = set().union(*(as_expr(c).free_symbols for c in self.a.values()))
        timed = S.T in free or bool(free & set(self.chain))
        names = list(system.rate_names) + ["t"]
        return [n for n in names if self.a.get(n, 0) != 0 or S.value(n) in free and n in self.coordinates
                or n == "t" and timed]

    def partial(self, expr: sp.Expr, variable: str) -> sp.Expr:
        if variable == "t":
            return S.time_derivative(as_expr(expr), self.chain)
        if variable in self.coordinates:
            return sp.diff(expr, S.value(variable))
        return sp.S.Zero  # a quasi-coordinate has no value for a coefficient to depend on

    def d_component(self, i: str, j: str) -> sp.Expr:
        """c_ij = ∂_i a_j − ∂_j a_i."""
        if (i, j) not in self._d:
            self._d[(i, j)] = self.partial(self.a.get(j, 0), i) - self.partial(self.a.get(i, 0), j)
        return self._d[(i, j)]

    def wedge_component(self, i: str, j: str, k: str) -> sp.Expr:
        a = self.a
        return (a.get(i, 0) * self.d_component(j, k) - a.get(j, 0) * self.d_component(i, k)
                + a.get(k, 0) * self.d_component(i, j))


def _all_zero(components) -> Decision:
    """All components zero? The first one found nonzero decides; 'numeric' if any needed points."""
    method, undecided = "symbolic", False
    for component in components:
        decision = decide_zero(component)
        if decision.zero is False:
            return decision
        if decision.zero is None:
            undecided = True
        elif decision.method == "numeric":
            method = "numeric"
    return Decision(None, "undecided") if undecided else Decision(True, method)


def decide_zero(expr, seed: int = _SEED) -> Decision:
    """Is ``expr`` identically zero? simplify() when small, else random points."""
    expr = as_expr(expr)
    if expr == 0:
        return Decision(True, "symbolic")
    if expr.is_Number:
        return Decision(False, "symbolic")
    simpler = _simplified(expr) if sp.count_ops(expr) <= SIMPLIFY_MAX_OPS else None
    if simpler == 0:
        return Decision(True, "symbolic")
    if simpler is not None and simpler.is_Number and simpler.is_finite:
        return Decision(False, "symbolic")
    return _numeric_zero(expr, seed)


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
    if not usable or not seconds or seconds <= 0 or outer_handler is None or 0 < outer_left <= seconds:
        yield False
        return
    alarm = _Alarm(error)
    started = time.monotonic()
    signal.signal(signal.SIGALRM, alarm.fire)
    signal.setitimer(signal.ITIMER_REAL, seconds, min(seconds, 0.2))
    try:
        yield True
    finally:
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


def _numeric_zero(expr: sp.Expr, seed: int) -> Decision:
    symbols = sorted(expr.free_symbols, key=lambda s: s.name)
    valid = 0
    # Positive points suit sqrt and log; signed ones catch abs and sign.
    points = sample_points(symbols, _POINTS // 2, seed) + sample_points(symbols, _POINTS // 2, seed + 1, signed=True)
    for point in points:
        try:
            value, scale = evaluate(expr, point)
        except UndefinedValue:
            continue
        valid += 1
        if abs(value) > _RELATIVE_TOLERANCE * max(scale, 1):
            return Decision(False, "numeric")
    return Decision(True, "numeric") if valid >= _MIN_VALID_POINTS else Decision(None, "undecided")


def sample_points(symbols, count: int, seed: int = _SEED, signed: bool = False) -> list[dict[sp.Symbol, float]]:
    """``count`` deterministic generic points: values in [0.3, 1.7] (either sign when ``signed``)."""
    rng = random.Random(seed)
    ordered = sorted(symbols, key=lambda s: s.name)
    points = []
    for _ in range(count):
        point = {}
        for s in ordered:
            value = rng.uniform(0.3, 1.7)
            point[s] = -value if signed and rng.random() < 0.5 else value
        points.append(point)
    return points


def _form_text(form: Form) -> str:
    """The form in the file's grammar (``r**2*dtheta``), for reports."""
    terms = [c * sp.Symbol(f"d{n}") for n, c in form.coefficients]
    return sp.sstr(sp.Add(*terms, form.dt * sp.Symbol("dt")), order="none")
