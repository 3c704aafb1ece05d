"""Steady motions, their stability on the constraint manifold, and first integrals.

``manifold`` (the reduced state), ``symbolic`` (A as expressions), ``hurwitz``
(conditions from the characteristic polynomial), ``stability``, ``sweep``
(eigenvalues along a parameter or speed, stable intervals), ``integrals``,
``motions`` (steady families).
"""

from gacli.errors import Diagnostic, SystemFileError


class SteadyError(SystemFileError):
    """A system these tools cannot answer for: one message located at its file, exit code 1."""


def require_small(derivation, what: str) -> None:
    """Refuse symbolic work on equations too large to print (the bicycle): it would not end."""
    from gacli.algebra.readable import displayable

    # A derivation for code alone (equations.derive_for_code) has no closed forms.
    if derivation.closed and displayable(derivation):
        return
    size = (f"{derivation.code.operations:,} operations even as generated code computes them" if not derivation.closed
            else "millions of terms as trees")
    message = (f"{what}: the equations of this system are too large for symbolic work ({size}); "
               "'gacli linearize --sweep' studies its stability numerically")
    raise SteadyError([Diagnostic(derivation.system.location, message)])
