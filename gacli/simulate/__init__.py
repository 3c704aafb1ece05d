"""Integrate the generated equations of motion and measure what a user checks first.

The generated Python module (``gacli.api.emit(derivation, "python")``, the
very code users vendor) is written to a temporary directory, imported under
a unique name and integrated with SciPy's ``solve_ivp``. Values come from the
command line (``SimulationSpec``) or from the system file:

.. code:: text

    --set       parameters     expressions in numbers and parameters; a file
                               value that names other parameters is recomputed
    --init      state          by STATE name; unspecified entries start at 0
    --function  free functions expressions in t and parameters; the rates the
                               equations need (dot(Omega), ...) are their
                               symbolic derivatives
    --input     inputs         expressions in t, parameters and the state

Every expression goes through gacli's own grammar (:mod:`gacli.read.expr`), never
``eval``. Along the computed path the report measures (docs/simulate.md):

* the drift of the energy E = ½ uᵀ M u + V when the system conserves it
  (:func:`conservation_problems` says why not otherwise; M from generated code);
* for each Pfaffian constraint, its residual A(q, t) ṙ + a₀ with the
  coordinate rates differentiated from the dense solution and the
  quasi-coordinate rates from the state or their differentials (eq. 14.2);
* for each finite constraint f(q, t) = 0, the drift of f.

Nothing here prints: :mod:`gacli.simulate.console` shows progress and the
summary, :mod:`gacli.simulate.plot` draws.
"""

from gacli.simulate.energy import conservation_problems, energy_expressions, path_rates
from gacli.simulate.results import ConstraintResidual, Simulation, summary_lines, to_csv
from gacli.simulate.run import load_generated, simulate
from gacli.simulate.spec import (
    DEFAULT_ATOL,
    DEFAULT_METHOD,
    DEFAULT_POINTS,
    DEFAULT_RTOL,
    DEFAULT_T_END,
    INSTALL,
    METHODS,
    MissingExtraError,
    OptionError,
    SimulationError,
    SimulationSpec,
    parse_assignments,
    require,
    spec_from_options,
    split_top_level,
    state_names,
)

__all__ = [
    "DEFAULT_ATOL", "DEFAULT_METHOD", "DEFAULT_POINTS", "DEFAULT_RTOL", "DEFAULT_T_END", "INSTALL", "METHODS",
    "ConstraintResidual", "MissingExtraError", "OptionError", "Simulation", "SimulationError", "SimulationSpec",
    "conservation_problems", "energy_expressions", "load_generated", "parse_assignments", "path_rates", "require",
    "simulate", "spec_from_options", "split_top_level", "state_names", "summary_lines", "to_csv",
]
