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
    if not derivation.closed or not displayable(derivation):
        raise SteadyError(f"{what}: the equations of this system are too large for symbolic work "
                          "(millions of terms as trees); 'gacli linearize --sweep' studies its stability "
                          "numerically")
