"""Steady motions, their stability on the constraint manifold, and first integrals.

``manifold`` (the reduced state), ``symbolic`` (A as expressions), ``hurwitz``
(conditions from the characteristic polynomial), ``stability``, ``sweep``
(eigenvalues along a parameter or speed, stable intervals), ``integrals``,
``motions`` (steady families).
"""
