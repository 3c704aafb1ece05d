"""The Python module of a derivation (interface 1 of the generated-code spec).

:func:`emit_python` returns ``{"<name>.py": text}``; the module needs only
NumPy and the standard library:

.. code:: text

    STATE, PARAMETERS, INPUTS   tuples of names: the order of x, p and r
    DEFAULTS                    parameter values the system file gives
    mass_matrix(t, x, p, r=())  M, (k, k) ndarray, symmetric
    forcing(t, x, p, r=())      F, (k,) ndarray, with M u' = F
    rhs(t, x, p, r=())          [q', u'], (len(STATE),) ndarray

``r`` is a sequence or a callable ``r(t, x)``. Every function shares common
subexpressions (SymPy's ``cse``) within itself; ``rhs`` computes M and F in
one block and solves M u' = F by a Cholesky factorization, never by a
symbolic inverse. Scalars go through the ``math`` module: the state of an
ODE solver is a handful of floats, for which ``math`` is faster than NumPy.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from string import Template

import sympy as sp

from gacli.emit.assembly import Assembly, assemble, live_block, reaction_equations, reaction_solve
from gacli.emit.naming import Layout, header_lines, layout, mass_arguments
from gacli.emit.printers import Block, GacliPythonPrinter, print_block
from gacli.mechanics.equations import Derivation

INDENT = "    "

MODULE = Template('''\
$header
"""Equations of motion of $name, derived by the Gibbs-Appell method.

    $mass u' = F(q, u, t)    with k = $k independent rates u
    q' = beta u + beta0        the kinematic equations

x = STATE is (q, u); p = PARAMETERS; r = INPUTS, given as a sequence or as
a callable r(t, x) that returns one.
"""

$imports

STATE = $state
PARAMETERS = $parameters
INPUTS = $inputs
DEFAULTS = $defaults
$undefined$functions''')

# Where the model is undefined, every target says so in its own way
# (docs/generated-code.md, "Undefined points"); here one exception class.
UNDEFINED = '''

class UndefinedPointError(ValueError):
    """The equations are undefined at this point: a number they compute is not
    finite (a function outside its domain, a division by zero, an overflow, a
    NaN or infinity given) or M is not positive definite."""


class SingularMassMatrixError(UndefinedPointError, numpy.linalg.LinAlgError):
    """M is not positive definite at this point."""


def _defined(function):
    """function(t, x, p, r) on floats, raising UndefinedPointError where it is undefined."""
    @functools.wraps(function)
    def checked(t, x, p, r=()):
        if callable(r):
            r = r(t, x)
        x, p, r = tuple(map(float, x)), tuple(map(float, p)), tuple(map(float, () if r is None else r))
        if (len(x), len(p), len(r)) != (len(STATE), len(PARAMETERS), len(INPUTS)):
            raise ValueError(f"expected {len(STATE)} states, {len(PARAMETERS)} parameters and "
                             f"{len(INPUTS)} inputs; got {len(x)}, {len(p)} and {len(r)}")
        try:
            out = function(t, x, p, r)
        except UndefinedPointError:
            raise
        except (ArithmeticError, ValueError, TypeError) as error:  # math's domain errors; a complex power
            raise UndefinedPointError(f"{function.__name__} is undefined at t = {t!r}: {error}") from None
        if not numpy.isfinite(out).all():
            raise UndefinedPointError(f"{function.__name__} is undefined at t = {t!r}: a value is not finite")
        return out
    return checked
'''

FUNCTION = Template('''

${decorator}def $name(t, x, p, r=()):
    """$doc"""
$body
''')

CHOLESKY_SOLVE = '''

def _cholesky_solve(M, F):
    """Solve M u = F for symmetric positive definite M, overwriting F with u.

    Only the lower triangle of M is read (its rows may stop at the
    diagonal); M = L L^T is factored in place, L over that triangle. Raises
    UndefinedPointError when an entry is not finite, SingularMassMatrixError
    when a pivot is not positive. Plain loops: for the few rates of a mechanical system they
    beat NumPy's call overhead.
    """
    if not all(map(math.isfinite, F)) or not all(math.isfinite(v) for row in M for v in row):
        raise UndefinedPointError("M or F is not finite")
    k = len(F)
    for j in range(k):
        Mj = M[j]
        d = Mj[j]
        for s in range(j):
            d -= Mj[s] * Mj[s]
        if not d > 0.0:
            raise SingularMassMatrixError("the mass matrix is not positive definite")
        d = math.sqrt(d)
        Mj[j] = d
        for i in range(j + 1, k):
            Mi = M[i]
            v = Mi[j]
            for s in range(j):
                v -= Mi[s] * Mj[s]
            Mi[j] = v / d
    for i in range(k):
        v = F[i]
        for s in range(i):
            v -= M[i][s] * F[s]
        F[i] = v / M[i][i]
    for i in range(k - 1, -1, -1):
        v = F[i]
        for s in range(i + 1, k):
            v -= M[s][i] * F[s]
        F[i] = v / M[i][i]
    return F
'''

DOCS = {
    "mass_matrix": "The mass matrix M, shape ({k}, {k}), symmetric positive definite.",
    "forcing": "The forcing F of M u' = F, shape ({k},).",
    "rhs": "d(x)/dt = [q', u'] with M u' = F solved by Cholesky, shape ({nx},).",
    "reactions": "The constraint forces: one multiplier per constraint, in the file's order (docs/verify.md).",
}


def emit_python(derivation: Derivation, *, reactions: bool = False) -> dict[str, str]:
    """The Python module of a derivation, as ``{"<name>.py": text}``.

    ``reactions`` adds ``reactions(t, x, p, r)``, the constraint forces.

    Raises:
        EmitError: when an expression has no Python rendering.
    """
    lay = layout(derivation)
    functions = [
        _mass_matrix(derivation, lay), _forcing(derivation, lay), _rhs(derivation, lay), CHOLESKY_SOLVE,
    ]
    if reactions:
        functions.insert(3, _reactions(derivation, lay))
    text = MODULE.substitute(
        header="\n".join(f"# {line}" for line in header_lines(derivation, "python")),
        name=lay.system, k=lay.k, mass=mass_arguments(derivation), imports="import functools\nimport math\n\nimport numpy",
        state=python_tuple(lay.state), parameters=python_tuple(lay.parameters), inputs=python_tuple(lay.r),
        defaults=python_dict(lay.defaults), undefined=UNDEFINED, functions="".join(functions),
    )
    return {f"{lay.system}.py": text}


# -- the three functions ----------------------------------------------------------

def _mass_matrix(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("M",))
    if code.dense("M"):
        rows = _rows([c for _, c in code.slots["M"]], lay.k)
        body = [*_prologue(lay, code.block), "return numpy.array([", *_items(rows, 1), "], dtype=float)"]
    else:
        # Only M's nonzero entries are set: a wide system's M is k² entries, nearly all zero.
        body = [*_prologue(lay, code.block), f"M = numpy.zeros(({lay.k}, {lay.k}))",
                *(f"M[{i}, {j}] = {c}" for (i, j), c in code.slots["M"]), "return M"]
    return _function("mass_matrix", lay, body)


def _forcing(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("F",))
    codes = [c for _, c in code.slots["F"]]
    body = [*_prologue(lay, code.block), "return numpy.array([", *_items(codes, 1), "], dtype=float)"]
    return _function("forcing", lay, body)


def _rhs(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("qdot", "M_lower", "F"))
    qdot, force = [c for _, c in code.slots["qdot"]], [c for _, c in code.slots["F"]]
    if code.dense("M_lower"):
        mass = ["M = [  # the lower triangle: all that _cholesky_solve reads",
                *_items(_lower_rows([c for _, c in code.slots["M_lower"]], lay.k), 1), "]"]
    else:
        mass = [f"M = [[0.0] * (i + 1) for i in range({lay.k})]  # the lower triangle: all that _cholesky_solve reads",
                *(f"M[{i}][{j}] = {c}" for (i, j), c in code.slots["M_lower"])]
    body = [
        *_prologue(lay, code.block), *mass,
        "F = [", *_items(force, 1), "]",
        "return numpy.array([", *_items([*qdot, "*_cholesky_solve(M, F)"], 1), "], dtype=float)",
    ]
    return _function("rhs", lay, body)


def _reactions(derivation: Derivation, lay: Layout) -> str:
    solve = reaction_solve(derivation)
    if solve is None:
        block = _block(lay, reaction_equations(derivation))
        body = [*_prologue(lay, block), "return numpy.array([", *_items(block.results, 1), "], dtype=float)"]
        return _function("reactions", lay, body)
    block = _block(lay, solve.equations)
    entries, rhs = block.results[:len(solve.nonzero)], block.results[len(solve.nonzero):]
    if solve.redundant:
        # Repeated constraint rows: the share of the reaction among them is not determined;
        # the minimum-norm one, as the closed form gives for smaller systems.
        solved = ["_z = numpy.linalg.lstsq(_K, _b, rcond=1e-10)[0]"]
    else:
        solved = [
            "if numpy.linalg.cond(_K) > 1e12:  # about the precision left in the multipliers: 1e-4",
            f"{INDENT}raise numpy.linalg.LinAlgError('the fundamental equations are singular at this state')",
            "_z = numpy.linalg.solve(_K, _b)",
        ]
    body = [
        *_prologue(lay, block),
        "# The fundamental equations in all the rates and multipliers (docs/verify.md), solved numerically:",
        "# closed-form multipliers of a system this large would be millions of terms long.",
        f"_K = numpy.zeros(({solve.size}, {solve.size}))",
        *(f"_K[{i}, {j}] = {code}" for (i, j), code in zip(solve.nonzero, entries)),
        "_b = numpy.array([", *_items(rhs, 1), "], dtype=float)",
        *solved,
        f"return _z[{solve.first}:{solve.first + solve.count}]",
    ]
    return _function("reactions", lay, body)


# -- pieces of code ------------------------------------------------------------

def _assemble(derivation: Derivation, lay: Layout, parts: Sequence[str]) -> Assembly:
    code, printer = assemble(derivation, lay.identifiers, GacliPythonPrinter, parts)
    printer.imports()  # raises if the code would need more than math and numpy
    return code


def _block(lay: Layout, equations: list[tuple[str, sp.Expr]]) -> Block:
    block, printer = print_block(GacliPythonPrinter, lay.identifiers, equations)
    printer.imports()  # raises if the code would need more than math and numpy
    return live_block(block, lay.identifiers)  # the reactions' route too


def _prologue(lay: Layout, block: Block) -> list[str]:
    """Unpack the vectors the block reads, then its temporaries."""
    lines = []
    if block.symbols & set(lay.r_symbols):
        lines += ["if callable(r):", f"{INDENT}r = r(t, x)"]
    for vector, entries in (("x", lay.state_entries), ("p", lay.parameter_entries), ("r", lay.r_entries)):
        if block.symbols & {e.symbol for e in entries}:
            lines.append(f"{_targets([e.identifier for e in entries])} = map(float, {vector})")
    return lines + [f"{name} = {code}" for name, code in block.temporaries]


def _function(name: str, lay: Layout, body: Sequence[str]) -> str:
    doc = DOCS[name].format(k=lay.k, nx=len(lay.state))
    decorator = "" if name == "reactions" else "@_defined\n"
    return FUNCTION.substitute(decorator=decorator, name=name, doc=doc, body="\n".join(INDENT + line for line in body))


def _rows(results: Sequence[str], k: int) -> list[str]:
    return ["[" + ", ".join(results[i * k:(i + 1) * k]) + "]" for i in range(k)]


def _lower_rows(results: Sequence[str], k: int) -> list[str]:
    starts = [i * (i + 1) // 2 for i in range(k + 1)]
    return ["[" + ", ".join(results[starts[i]:starts[i + 1]]) + "]" for i in range(k)]


def _items(codes: Sequence[str], depth: int) -> list[str]:
    return [INDENT * depth + code + "," for code in codes]


def _targets(names: Sequence[str]) -> str:
    return f"[{names[0]}]" if len(names) == 1 else ", ".join(names)


def python_tuple(names: Sequence[str]) -> str:
    items = [json.dumps(n) for n in names]
    return f"({items[0]},)" if len(items) == 1 else "(" + ", ".join(items) + ")"


def python_dict(values: dict[str, float]) -> str:
    return "{" + ", ".join(f"{json.dumps(n)}: {v!r}" for n, v in values.items()) + "}"
