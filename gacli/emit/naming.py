"""The one ordering rule of generated code, and the names its slots get.

Every emitter reads the argument vectors through a :class:`Layout`:

.. code:: text

    x  state       coordinates in declaration order, then the rate dot(s)
                   of each independent name s, in the order of ``independent``
    p  parameters  every declared parameter, in declaration order
    r  arguments   inputs in declaration order, then for each free function
                   (in declaration order) its value and its rates dot(f),
                   ddot(f), d3(f) ... up to the highest order that occurs in
                   M, F or the kinematic equations

Each entry has three spellings:

``name``
    as in the system file and the derivation's symbols: ``dot(q_z)``.
``identifier``
    a local variable name valid in both C99 and Python: a rate joins its
    operator and its name with ``_`` (``dot(q_z)`` → ``dot_q_z``,
    ``ddot(Omega)`` → ``ddot_Omega``, ``d3(h)`` → ``d3_h``); a name
    starting with ``_`` gets a ``v`` in front (``_x`` → ``v_x``), so that
    only gacli's own temporaries (``_c0``, ``_c1`` ...) begin with an
    underscore. A name that is a keyword of either language, a name from
    ``<math.h>``, or a name the generated functions use themselves (``t``,
    ``x``, ``p``, ``r``, ``M``, ``F``, ``xdot``, ``math``, ``numpy`` ...) gets
    a trailing ``_`` (the parameter ``M`` is the local ``M_``). A name that
    is still taken gets ``_2``, ``_3`` ... Entries are named in the order
    x, p, r, so the earlier entry keeps the plain name.
``macro``
    the C index macro ``<NAME>_<K>_<SUFFIX>`` with ``<NAME>`` the system name
    in upper case, ``<K>`` the vector (``X``, ``P`` or ``R``) and
    ``<SUFFIX>`` the identifier stem in upper case with runs of ``_``
    collapsed and outer ones dropped: ``SPHERE_ON_TURNTABLE_X_DOT_Q_Z``,
    ``SPHERE_ON_TURNTABLE_P_M``, ``SPHERE_ON_TURNTABLE_R_DOT_OMEGA``. When
    two entries of one vector meet after upper-casing (``m`` and ``M``), the
    later one gets ``_2``, ``_3`` ... The other macros are ``<NAME>_NX``,
    ``<NAME>_NU``, ``<NAME>_NP``, ``<NAME>_NR`` and the include guard
    ``<NAME>_H``; none of them can meet an index macro, whose ``<K>`` is
    followed by ``_``.

Example:

>>> from gacli.loader.loading import loads
>>> from gacli.mechanics.equations import derive
>>> lay = layout(derive(loads('''
... gacli: 1
... name: falling
... parameters: {m: {value: 2}, g: {value: 9.81}}
... coordinates: [x]
... bodies: {ball: {mass: m, position: [0, 0, x]}}
... potential: m*g*x
... ''')))
>>> lay.state, lay.parameters, lay.r, lay.defaults
(('x', 'dot(x)'), ('m', 'g'), (), {'m': 2.0, 'g': 9.81})
>>> [e.identifier for e in lay.entries], [e.macro for e in lay.state_entries]
(['x_', 'dot_x', 'm', 'g'], ['FALLING_X_X', 'FALLING_X_DOT_X'])
"""

from __future__ import annotations

import builtins
import keyword
import math
import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.mechanics.equations import Derivation
from gacli.emit.math_h import RESERVED_PREFIXES, is_math_h_name
from gacli.errors import EmitError
from gacli.read.textsafe import one_line

# The names the generated functions and modules use themselves.
GENERATED_NAMES = frozenset({
    "t", "x", "p", "r", "M", "F", "xdot",
    # Python: modules and builtins the generated functions call (a local of
    # the same name would shadow them in the whole function).
    "math", "numpy", "abs", "callable", "float", "len", "map", "max", "min", "range", "sum",
})

C_KEYWORDS = frozenset("""
    auto break case char const continue default do double else enum extern
    float for goto if inline int long register restrict return short signed
    sizeof static struct switch typedef union unsigned void volatile while
    _Bool _Complex _Imaginary
""".split())

# Functions, macros and types of <math.h> (C99, plus the common M_* and XSI
# extras), so that no local variable hides one the code calls.
MATH_H_NAMES = frozenset("""
    acos acosh asin asinh atan atan2 atanh cbrt ceil copysign cos cosh erf
    erfc exp exp2 expm1 fabs fdim floor fma fmax fmin fmod frexp hypot ilogb
    ldexp lgamma llrint llround log log10 log1p log2 logb lrint lround modf
    nan nearbyint nextafter nexttoward pow remainder remquo rint round
    scalbln scalbn sin sinh sqrt tan tanh tgamma trunc gamma j0 j1 jn y0 y1 yn
    double_t float_t fpclassify isfinite isgreater isgreaterequal isinf isless
    islessequal islessgreater isnan isnormal isunordered signbit
    HUGE_VAL HUGE_VALF HUGE_VALL INFINITY NAN FP_INFINITE FP_NAN FP_NORMAL
    FP_SUBNORMAL FP_ZERO FP_FAST_FMA FP_FAST_FMAF FP_FAST_FMAL FP_ILOGB0
    FP_ILOGBNAN MATH_ERRNO MATH_ERREXCEPT math_errhandling
    M_E M_LOG2E M_LOG10E M_LN2 M_LN10 M_PI M_PI_2 M_PI_4 M_1_PI M_2_PI
    M_2_SQRTPI M_SQRT2 M_SQRT1_2
""".split())

class ReservedNames:
    """A set of names plus everything <math.h> may declare (:func:`gacli.emit.math_h.is_math_h_name`)."""

    def __init__(self, names) -> None:
        self.names = frozenset(names)

    def __contains__(self, name: object) -> bool:
        return name in self.names or (isinstance(name, str) and is_math_h_name(name))

    def __or__(self, other) -> "ReservedNames":
        return ReservedNames(self.names | frozenset(other))

    def made(self, name: str) -> bool:
        """Whether a name gacli made (``M_``, ``x_2``) is taken: families reserved by prefix do not count."""
        return name in self.names or is_math_h_name(name, prefixes=False)


# Python's builtins too: a local `min` or `float` would hide one the module may call.
RESERVED = ReservedNames(GENERATED_NAMES | C_KEYWORDS | MATH_H_NAMES | frozenset(keyword.kwlist)
                         | frozenset(n for n in dir(builtins) if not n.startswith("_")))

# Generated function names, after "<name>_"; the C source calls the last one.
C_FUNCTIONS = ("mass_matrix", "forcing", "rhs", "reactions", "default_parameters", "lu_solve", "cholesky_solve", "solved")

_RATE_NAME = S.RATE_NAME
_RATE_ORDERS = {"dot": 1, "ddot": 2}


@dataclass(frozen=True)
class Entry:
    """One slot of x, p or r."""

    vector: str        # "x", "p" or "r"
    index: int
    name: str          # as in the system file: "dot(q_z)"
    symbol: sp.Symbol
    identifier: str    # local variable in C and Python: "dot_q_z"
    macro: str         # C index macro: "SPHERE_ON_TURNTABLE_X_DOT_Q_Z"


@dataclass(frozen=True)
class Layout:
    """The slots of x, p and r, in the order of the spec, with their names."""

    system: str                          # the system's name: C function prefix
    prefix: str                          # upper case: macro prefix
    state_entries: tuple[Entry, ...]
    parameter_entries: tuple[Entry, ...]
    r_entries: tuple[Entry, ...]
    defaults: dict[str, float]           # parameters whose value the file gives
    k: int                               # number of independent rates

    @property
    def n(self) -> int:
        """Number of coordinates: the state is (q, u) with len(q) = n."""
        return len(self.state_entries) - self.k

    @property
    def state(self) -> tuple[str, ...]:
        return tuple(e.name for e in self.state_entries)

    @property
    def parameters(self) -> tuple[str, ...]:
        return tuple(e.name for e in self.parameter_entries)

    @property
    def r(self) -> tuple[str, ...]:
        return tuple(e.name for e in self.r_entries)

    @property
    def state_symbols(self) -> tuple[sp.Symbol, ...]:
        return tuple(e.symbol for e in self.state_entries)

    @property
    def parameter_symbols(self) -> tuple[sp.Symbol, ...]:
        return tuple(e.symbol for e in self.parameter_entries)

    @property
    def r_symbols(self) -> tuple[sp.Symbol, ...]:
        return tuple(e.symbol for e in self.r_entries)

    @property
    def entries(self) -> tuple[Entry, ...]:
        return self.state_entries + self.parameter_entries + self.r_entries

    @property
    def identifiers(self) -> dict[sp.Symbol, str]:
        """Symbol → local variable name, time included, for the printers."""
        return {S.T: "t", **{e.symbol: e.identifier for e in self.entries}}

    def function(self, suffix: str) -> str:
        """The C name of a generated function: ``<name>_rhs``."""
        return f"{self.system}_{suffix}"


def layout(derivation: Derivation, reserved: Iterable[str] = ()) -> Layout:
    """The layout of the generated code's arguments for a derivation.

    ``reserved``: more names that no identifier may take, for a target
    with keywords and builtins of its own (Octave's ``end``, ``pi``).

    Raises:
        EmitError: when M, F or the kinematic equations hold a symbol that
            is in none of x, p, r (a bug upstream, not in the system file).
    """
    system = derivation.system
    prefix = system.name.upper()
    used = _used_symbols(derivation)
    groups = {
        "x": [(s.name, s) for s in derivation.state],
        "p": [(p.name, S.value(p.name)) for p in system.parameters],
        "r": _r_slots(derivation, used),
    }
    _check_covered(used, groups)
    entries = _name_entries(groups, prefix, reserved=RESERVED | _c_names(system.name, prefix, groups) | reserved)
    return Layout(
        system=system.name, prefix=prefix,
        state_entries=entries["x"], parameter_entries=entries["p"], r_entries=entries["r"],
        defaults=parameter_defaults(system.parameters), k=derivation.k,
    )


def _used_symbols(derivation: Derivation) -> set[sp.Symbol]:
    from gacli.algebra.graph import free_symbols

    # M's nonzero entries only: a wide system's M is k² entries, nearly all zero.
    code = derivation.code
    return free_symbols([*(e for _, e in code.mass_matrix), *code.forcing, *(e for _, e in code.kinematic_equations)])


def _r_slots(derivation: Derivation, used: set[sp.Symbol]) -> list[tuple[str, sp.Symbol]]:
    system = derivation.system
    slots = [(i.name, S.value(i.name)) for i in system.inputs]
    for function in system.free_functions:
        top = highest_rate(function.name, used)
        slots += [(S.rate_name(function.name, o), S.rate(function.name, o)) for o in range(top + 1)]
    return slots


def highest_rate(name: str, symbols: Iterable[sp.Symbol]) -> int:
    """The highest order o such that the rate of order o of ``name`` is among ``symbols`` (0 if none)."""
    orders = [0]
    for symbol in symbols:
        match = _RATE_NAME.match(symbol.name)
        if match and match[3] == name:
            orders.append(int(match[2]) if match[2] else _RATE_ORDERS[match[1]])
    return max(orders)


def _check_covered(used: set[sp.Symbol], groups: Mapping[str, list]) -> None:
    known = {S.T} | {symbol for slots in groups.values() for _, symbol in slots}
    stray = sorted(s.name for s in used - known)
    if stray:
        raise EmitError(f"the equations hold symbols that are not in x, p or r: {', '.join(stray)}")


def parameter_defaults(parameters) -> dict[str, float]:
    """Name → value of the parameters whose value the file fixes, in declaration order.

    A value may use earlier parameters; it counts when, with the earlier
    defaults substituted, it is a finite real number.
    """
    exact: dict[sp.Symbol, sp.Expr] = {}
    defaults: dict[str, float] = {}
    for parameter in parameters:
        if parameter.value is None:
            continue
        value = as_expr(parameter.value).xreplace(exact)
        number = _finite(value)
        if number is not None:
            exact[S.value(parameter.name)] = value
            defaults[parameter.name] = number
    return defaults


def _finite(value: sp.Expr) -> float | None:
    if value.free_symbols:
        return None
    number = value.evalf(30)
    if not number.is_real or not number.is_number:
        return None
    result = float(number)
    return result if math.isfinite(result) else None


# -- spellings ----------------------------------------------------------------

def _stem(name: str) -> str:
    """``dot(q_z)`` → ``dot_q_z``, ``d3(x)`` → ``d3_x``; ``_x`` → ``v_x``."""
    match = _RATE_NAME.match(name)
    if match:
        name = f"{match[1]}_{match[3]}"
    stem = re.sub(r"[^A-Za-z0-9_]", "_", name)
    return "v" + stem if stem.startswith("_") else stem


def _macro_suffix(name: str) -> str:
    return re.sub(r"_+", "_", _stem(name)).strip("_").upper()


def _fresh(stem: str, taken: set[str], reserved: ReservedNames | frozenset[str]) -> str:
    # A whole family is reserved by its prefix (M_PIl, FP_NAN): a suffix cannot leave it, a prefix can.
    base = "v_" + stem if isinstance(reserved, ReservedNames) and stem.startswith(RESERVED_PREFIXES) else stem
    candidate = base + "_" if base in reserved else base
    made = reserved.made if isinstance(reserved, ReservedNames) else reserved.__contains__
    number = 2
    while candidate in taken or (made(candidate) if candidate != stem else candidate in reserved):
        candidate = f"{base}_{number}"
        number += 1
    taken.add(candidate)
    return candidate


def _macros(groups: Mapping[str, list], prefix: str) -> dict[str, list[str]]:
    macros = {}
    for vector, slots in groups.items():
        taken: set[str] = set()
        macros[vector] = [
            f"{prefix}_{vector.upper()}_{_fresh(_macro_suffix(name), taken, frozenset())}"
            for name, _ in slots
        ]
    return macros


def _c_names(system: str, prefix: str, groups: Mapping[str, list]) -> frozenset[str]:
    """Names the C files define: a local variable must not meet one of them."""
    fixed = {f"{prefix}_{suffix}" for suffix in ("NX", "NU", "NP", "NR", "H")}
    functions = {f"{system}_{suffix}" for suffix in C_FUNCTIONS}
    macros = {m for names in _macros(groups, prefix).values() for m in names}
    return frozenset(fixed | functions | macros)


def _name_entries(groups: Mapping[str, list], prefix: str, reserved: ReservedNames) -> dict[str, tuple[Entry, ...]]:
    macros = _macros(groups, prefix)
    taken: set[str] = set()
    entries = {}
    for vector, slots in groups.items():
        entries[vector] = tuple(
            Entry(vector, i, name, symbol, _fresh(_stem(name), taken, reserved), macros[vector][i])
            for i, (name, symbol) in enumerate(slots)
        )
    return entries


# -- provenance -----------------------------------------------------------------

def mass_arguments(derivation: Derivation) -> str:
    """How a module's docstring writes M: M(q, u, t) when a constraint nonlinear in the rates puts u in it."""
    from gacli.algebra.graph import free_symbols

    moving = free_symbols([e for _, e in derivation.code.mass_matrix]) & set(derivation.speeds)
    return "M(q, u, t)" if moving else "M(q, t)"


def header_lines(derivation: Derivation, fmt: str) -> list[str]:
    """The first lines of every generated file, without comment markers.

    They name the tool and its version, the system file (base name only) and
    its SHA-256, and the system's title; nothing that changes between runs.
    """
    from gacli.version import __version__

    system = derivation.system
    source = one_line(os.path.basename(system.path))
    title = one_line(system.title) or system.name
    return [
        f"Generated by gacli {__version__} from {source}. Do not edit:",
        f"regenerate with `gacli derive {source} --format {fmt}`.",
        f"sha256({source}) = {system.sha256}",
        title,
    ]
