"""The JAX module of a derivation: the Python module's interface in pure ``jax.numpy``.

:func:`emit_jax` returns ``{"<name>_jax.py": text}``; the module needs JAX
(``pip install gacli[jax]``) and nothing else:

.. code:: text

    STATE, PARAMETERS, INPUTS   tuples of names: the order of x, p and r
    DEFAULTS                    parameter values the system file gives
    mass_matrix(t, x, p, r=())  M, (k, k) array, symmetric
    forcing(t, x, p, r=())      F, (k,) array, with M u' = F
    rhs(t, x, p, r=())          [q', u'], (len(STATE),) array

Every function is array code with no Python branch on a value, so that
``jax.jit``, ``jax.vmap`` (over states or parameters) and ``jax.grad``
apply; ``rhs`` solves M u' = F with ``jax.scipy.linalg.cho_factor`` and
``cho_solve`` on the symmetric M. ``r`` is a sequence, an array or a
callable ``r(t, x)``.
"""

from __future__ import annotations

from collections.abc import Sequence
from string import Template

import sympy as sp

from gacli.emit.assembly import Assembly, assemble, refuse_reactions
from gacli.emit.naming import Layout, header_lines, layout, mass_arguments
from gacli.emit.printers import GacliJaxPrinter
from gacli.emit.python import FUNCTION  # the same def line and docstring as the NumPy module
from gacli.emit.python import python_dict as _dict, python_tuple as _tuple
from gacli.mechanics.equations import Derivation

INDENT = "    "
NP = "jax.numpy"

MODULE = Template('''\
$header
"""Equations of motion of $name, derived by the Gibbs-Appell method, in JAX.

    $mass u' = F(q, u, t)    with k = $k independent rates u
    q' = beta u + beta0        the kinematic equations

x = STATE is (q, u); p = PARAMETERS; r = INPUTS, given as a sequence or as
a callable r(t, x) that returns one. Pure jax.numpy: jax.jit, jax.vmap and
jax.grad apply to every function.

JAX computes in float32 unless told otherwise: for results that agree with
the NumPy and C code to about 1e-12, enable float64 before the first call:

    jax.config.update("jax_enable_x64", True)
"""

import jax
import jax.numpy
import jax.scipy.linalg

STATE = $state
PARAMETERS = $parameters
INPUTS = $inputs
DEFAULTS = $defaults


def _defined(values):
    """values, or NaN in every entry when one of them is not finite: the equations
    are undefined there (a function outside its domain, a division by zero, an
    overflow, NaN given, or M not positive definite). jax.jit cannot raise."""
    return jax.numpy.where(jax.numpy.all(jax.numpy.isfinite(values)), values, jax.numpy.nan)
$functions''')

DOCS = {
    "mass_matrix": "The mass matrix M, shape ({k}, {k}), symmetric positive definite.",
    "forcing": "The forcing F of M u' = F, shape ({k},).",
    "rhs": "d(x)/dt = [q', u'] with M u' = F solved by Cholesky, shape ({nx},).",
}


def emit_jax(derivation: Derivation, *, reactions: bool = False) -> dict[str, str]:
    """The JAX module of a derivation, as ``{"<name>_jax.py": text}``.

    Raises:
        EmitError: when an expression has no JAX rendering, or for ``reactions``.
    """
    refuse_reactions(reactions)
    lay = layout(derivation, reserved={"jax", "qdot", "u_dot"})
    functions = [_mass_matrix(derivation, lay), _forcing(derivation, lay), _rhs(derivation, lay)]
    text = MODULE.substitute(
        header="\n".join(f"# {line}" for line in header_lines(derivation, "jax")),
        name=lay.system, k=lay.k, mass=mass_arguments(derivation), state=_tuple(lay.state), parameters=_tuple(lay.parameters),
        inputs=_tuple(lay.r), defaults=_dict(lay.defaults), functions="".join(functions),
    )
    return {f"{lay.system}_jax.py": text}


def _mass_matrix(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("M",))
    return _function("mass_matrix", lay, code, [*_mass(code.slots["M"], lay.k), "return _defined(M)"])


def _forcing(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("F",))
    return _function("forcing", lay, code, [*_array("F =", [c for _, c in code.slots["F"]]), "return _defined(F)"])


def _rhs(derivation: Derivation, lay: Layout) -> str:
    code = _assemble(derivation, lay, ("qdot", "M_lower", "F"))
    lines = [
        *_mass(code.slots["M_lower"], lay.k),
        # cho_factor reads one triangle, but the derivative of M must be symmetric for grad to be right.
        f"M = M + {NP}.tril(M, -1).T",
        *_array("F =", [c for _, c in code.slots["F"]]),
        *_array("qdot =", [c for _, c in code.slots["qdot"]]),
        "u_dot = jax.scipy.linalg.cho_solve(jax.scipy.linalg.cho_factor(M, lower=True), F)",
        f"return _defined({NP}.concatenate([qdot, u_dot]))",
    ]
    return _function("rhs", lay, code, lines)


class _JaxLiterals(GacliJaxPrinter):
    """Integers past int32 print as floats: JAX's default 32-bit mode takes a Python int as
    an int32, and one beyond 2**31 raises OverflowError under jax.jit."""

    def _print_Integer(self, expr: sp.Integer) -> str:
        return self._wide_literal(expr) if abs(int(expr)) >= INT32_LIMIT else super()._print_Integer(expr)


INT32_LIMIT = 2**31


def _assemble(derivation: Derivation, lay: Layout, parts: Sequence[str]) -> Assembly:
    code, printer = assemble(derivation, lay.identifiers, _JaxLiterals, parts)
    printer.imports()  # raises if the code would need more than jax.numpy
    return code


def _function(name: str, lay: Layout, code: Assembly, lines: Sequence[str]) -> str:
    """Entries read (by index, so that x and p may be traced arrays), temporaries, then the results."""
    prologue = ["if callable(r):", f"{INDENT}r = r(t, x)"] if code.read_entries(lay, "r") else []
    body = [
        *prologue,
        *(f"{e.identifier} = {vector}[{e.index}]"
          for vector in ("x", "p", "r") for e in code.read_entries(lay, vector)),
        *(f"{temporary} = {value}" for temporary, value in code.block.temporaries),
        *lines,
    ]
    doc = DOCS[name].format(k=lay.k, nx=len(lay.state))
    return FUNCTION.substitute(decorator="", name=name, doc=doc, body="\n".join(INDENT + line for line in body))


def _mass(slots: Sequence[tuple[tuple[int, int], str]], k: int) -> list[str]:
    # Only M's nonzero entries are set: a wide system's M is k² entries, nearly all zero.
    return [f"M = {NP}.zeros(({k}, {k}))", *(f"M = M.at[{i}, {j}].set({c})" for (i, j), c in slots)]


def _array(target: str, codes: Sequence[str]) -> list[str]:
    return [f"{target} {NP}.array([", *(f"{INDENT}{c}," for c in codes), "])"]
