"""Steady motions, their stability on the constraint manifold, and first integrals.

``manifold`` (the reduced state), ``symbolic`` (A as expressions), ``hurwitz``
(conditions from the characteristic polynomial), ``stability``, ``sweep``
(eigenvalues along a parameter or speed, stable intervals), ``integrals``,
``motions`` (steady families).
"""

from gacli.errors import GacliError


class SteadyError(GacliError, ValueError):
    """A system or a request these tools cannot answer (one message, exit code 1)."""


def require_small(derivation, what: str) -> None:
    """Refuse symbolic work on equations too large to print (the bicycle): it would not end."""
    from gacli.algebra.readable import displayable

    # A derivation for code alone (a program of PROGRAM_ALONE operations or more) has no closed forms.
    if derivation.closed and displayable(derivation):
        return
    size = (f"{derivation.code.operations:,} operations even as generated code computes them" if not derivation.closed
            else "millions of terms as trees")
    raise SteadyError(f"{what}: the equations of this system are too large for symbolic work ({size}); "
                      "'gacli linearize --sweep' studies its stability numerically")
