"""What a run is asked for: the options as a :class:`SimulationSpec`, and the errors of a run."""

from __future__ import annotations

import importlib
from collections.abc import Sequence
from dataclasses import dataclass
from types import ModuleType

from gacli.errors import GacliError

METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")
DEFAULT_METHOD = "DOP853"
DEFAULT_RTOL = 1e-9
DEFAULT_ATOL = 1e-12
DEFAULT_T_END = 10.0
DEFAULT_POINTS = 1001
INSTALL = "pip install 'gacli[sim]'"

MAX_FUNCTION_ORDER = 8      # rates of a free function that generated code may ask for
# Output samples: the path, energy and residuals are arrays of points x entries (docs/simulate.md).
MAX_POINTS = 1_000_000
MAX_VALUES = 10_000_000     # points x state entries: 80 MB a copy of the path

Assignments = tuple[tuple[str, str], ...]

class SimulationError(GacliError, ValueError):
    """Options that cannot be simulated, or an integration that failed; holds every problem."""

    def __init__(self, problems: Sequence[str]) -> None:
        self.problems = tuple(problems)
        super().__init__(str(self))

    def __str__(self) -> str:
        if len(self.problems) == 1:
            return self.problems[0]
        lines = [f"{len(self.problems)} problems with the simulation:"]
        return "\n".join(lines + [f"  {p}" for p in self.problems])


class OptionError(SimulationError):
    """An option string that cannot be used as written: a malformed piece, a name given
    twice or unknown, options that conflict. A usage error (exit code 2), found before
    any integration."""


class MissingExtraError(GacliError, ImportError):
    """An optional dependency of ``gacli simulate`` is not installed."""


def require(module: str, purpose: str = "simulation") -> ModuleType:
    """Import ``module`` or say what to install (``scipy.integrate``, ``matplotlib``)."""
    try:
        return importlib.import_module(module)
    except ImportError:
        top = module.split(".")[0]
        raise MissingExtraError(f"{purpose} needs {top}, which is not installed: {INSTALL}") from None

# -- options --------------------------------------------------------------------

@dataclass(frozen=True)
class SimulationSpec:
    """What to simulate, as given on the command line (values still unparsed text)."""

    parameters: Assignments = ()
    initial: Assignments = ()
    inputs: Assignments = ()
    functions: Assignments = ()
    t_end: float = DEFAULT_T_END
    method: str = DEFAULT_METHOD
    rtol: float = DEFAULT_RTOL
    atol: float = DEFAULT_ATOL
    points: int = DEFAULT_POINTS
    show: tuple[str, ...] = ()
    phase: tuple[str, ...] = ()


def spec_from_options(*, set: Sequence[str] = (), init: Sequence[str] = (), input: Sequence[str] = (),
                      function: Sequence[str] = (), show: str | None = None, phase: str | None = None,
                      **numbers) -> SimulationSpec:
    """A spec from the raw option strings (each option may be repeated).

    >>> spec_from_options(set=["M=1,a=f(1,2)"], t_end=2.0).parameters
    (('M', '1'), ('a', 'f(1,2)'))
    """
    def joined(texts, option):
        return tuple(pair for text in texts for pair in parse_assignments(text, option))

    points = numbers.get("points", DEFAULT_POINTS)
    if points > MAX_POINTS:
        raise OptionError([f"--points: at most {MAX_POINTS:,} output samples, found {points:,} "
                           "(the integrator's own steps do not depend on it)"])
    return SimulationSpec(
        parameters=joined(set, "--set"), initial=joined(init, "--init"),
        inputs=joined(input, "--input"), functions=joined(function, "--function"),
        show=tuple(state_names(show or "", "--show")), phase=tuple(state_names(phase or "", "--phase")),
        **numbers,
    )


def split_top_level(text: str, option: str = "") -> list[str]:
    """Split on the commas outside parentheses; an empty text is no pieces, an empty piece an OptionError.

    ``"a=1,,b=2"`` and ``",a=1"`` are refused rather than read as ``a=1,b=2``
    (one comma at the end is allowed, as in a Python list):
    a piece left out by a script that joined a list with an empty entry is
    a mistake to report, not to guess around (docs/security.md, "Option strings").

    >>> split_top_level("a=1, b=atan2(1, 2)")
    ['a=1', 'b=atan2(1, 2)']
    """
    if not text.strip():
        return []
    pieces, depth, start = [], 0, 0
    for i, char in enumerate(text):
        depth += {"(": 1, ")": -1}.get(char, 0)
        if depth < 0:
            raise OptionError([f"{option} '{text}': unmatched ')' at column {i + 1}".lstrip()])
        if char == "," and depth == 0:
            pieces.append(text[start:i])
            start = i + 1
    if depth:
        raise OptionError([f"{option} '{text}': unclosed '('".lstrip()])
    pieces.append(text[start:])
    if len(pieces) > 1 and not pieces[-1].strip():
        pieces.pop()  # one comma at the end, as Python's lists allow
    empty = [i for i, p in enumerate(pieces) if not p.strip()]
    if empty:
        column = sum(len(p) + 1 for p in pieces[:empty[0]]) + 1
        raise OptionError([f"{option} '{text}': empty item at column {column} (two commas, or one at the start)"
                           .lstrip()])
    return [p.strip() for p in pieces]


def parse_assignments(text: str, option: str = "") -> list[tuple[str, str]]:
    """``"a=1,b=f(1,2)"`` → ``[("a", "1"), ("b", "f(1,2)")]``; commas inside parentheses stay.

    Names are written as gacli writes them (``dot( x )`` is ``dot(x)``); a name given
    twice is an OptionError, as is a piece that is not name=value.

    >>> parse_assignments("x=1, dot(x)=-2*a")
    [('x', '1'), ('dot(x)', '-2*a')]
    """
    out = []
    for piece in split_top_level(text, option):
        name, equals, value = piece.partition("=")
        if not equals or not name.strip() or not value.strip():
            raise OptionError([f"{option} '{piece}': expected name=value".lstrip()])
        out.append((canonical_name(name), value.strip()))
    _refuse_twice([n for n, _ in out], option)
    return out


def state_names(text: str, option: str = "") -> list[str]:
    """``"x, dot( y )"`` → ``["x", "dot(y)"]``; a name given twice is an OptionError."""
    names = [canonical_name(n) for n in split_top_level(text, option)]
    _refuse_twice(names, option)
    return names


def canonical_name(text: str) -> str:
    """A name or rate as gacli writes it (``dot( x )`` → ``dot(x)``); other text stripped, as given."""
    from gacli.algebra import symbols as S
    from gacli.read.expr.grammar import Name, ParseError, Rate
    from gacli.read.expr.parser import parse

    try:
        node = parse(text.strip())
    except ParseError:
        return text.strip()
    if isinstance(node, Rate):
        return S.rate_name(node.name, node.order)
    return node.id if isinstance(node, Name) else text.strip()


def _refuse_twice(names: Sequence[str], option: str) -> None:
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise OptionError([f"{option}: {', '.join(repr(n) for n in twice)} given twice".lstrip()])
