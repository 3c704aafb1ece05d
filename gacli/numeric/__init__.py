"""Numbers from expressions: the one evaluator, its function table, parameter values, sample points.

* :mod:`~gacli.numeric.evaluator`: :class:`Program`, a straight-line program
  over an expression graph, with complex, mpmath and guarded backends
  (:mod:`~gacli.numeric.backends`);
* :mod:`~gacli.numeric.functions`: the supported functions, per backend;
* :mod:`~gacli.numeric.guarded`: :func:`evaluate`, one bounded value or
  :class:`UndefinedValue`;
* :mod:`~gacli.numeric.compiled`: many matrices as one function of a values
  dict, and ``lambdify`` for the vectorised and per-step code of simulate;
* :mod:`~gacli.numeric.parameters`: the parameters as numbers, and physical
  random samples of those without a value;
* :mod:`~gacli.numeric.samples`: seeded generic points.
"""

from gacli.numeric.evaluator import COMPLEX, GUARDED, MPMATH, Program
from gacli.numeric.guarded import UndefinedValue, evaluate
from gacli.numeric.parameters import (
    ParameterSample,
    parameter_values,
    precise_parameter_values,
    sample_parameters,
    unphysical,
)
from gacli.numeric.samples import random_point, sample_points

__all__ = [
    "COMPLEX", "GUARDED", "MPMATH", "ParameterSample", "Program", "UndefinedValue", "evaluate",
    "parameter_values", "precise_parameter_values", "random_point", "sample_parameters", "sample_points",
    "unphysical",
]
