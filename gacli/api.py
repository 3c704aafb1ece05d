"""The Python API that ``import gacli`` names: derive, Derivation, emit.

``Derivation`` is that of :mod:`gacli.mechanics.equations`, and ``derive`` its derive, taking
a path too (through :func:`gacli.emit.derived`, which every call here that takes a system uses); importing
:mod:`gacli.notebook` here gives a derivation its typeset face in Jupyter
(the mechanics stage does not import its own display). The dispatch
over formats is :func:`gacli.emit.emit`, beside the emitters it chooses from;
this layer above them only names it, so nothing in :mod:`gacli.emit` reaches
back up here.
"""

from __future__ import annotations

from gacli import notebook  # noqa: F401  (on import, Derivation gets _repr_latex_)
from gacli.emit import derived, emit
from gacli.mechanics.equations import Derivation

__all__ = ["Derivation", "derive", "emit"]


def derive(system, *, progress=None) -> Derivation:
    """The Gibbs-Appell equations of a System (``gacli.load``), or of a system file's path, loaded first
    (the steps: :func:`gacli.mechanics.equations.derive`)."""
    return derived(system, progress=progress)


def _solvable(system) -> Derivation:
    """The derivation of a command that solves M u̇ = F: a row of M zero at every state is the
    located SystemFileError the command line gives, not a solver's exception partway through."""
    from gacli.check.mass import require_regular

    derivation = derived(system)
    require_regular(derivation)
    return derivation


# -- linearize and simulate: the commands of the same names ------------------------------
# `gacli.linearize` and `gacli.simulate` are also the modules that do the work; gacli/__init__.py
# makes those modules callable, and a call lands here.

def linearize(system, at=None, parameters=None):
    """A and B about an operating point, as ``gacli linearize`` prints them.

    ``system``: a path, a System or a Derivation. ``at``: state and input
    values, {"lean": 0, "dot(spin)": -5} (others 0). ``parameters``: values
    over the file's; a file value written in other parameters is computed
    again from them (as ``simulate`` does). Returns a
    :class:`gacli.linearize.Linearization` (``.A``, ``.B``, ``.eigenvalues(names)``).

    >>> import gacli
    >>> gacli.linearize("systems/rolling_disk.yaml", {"dot(spin)": -5}).eigenvalues(["lean", "dot(lean)"])  # doctest: +SKIP
    """
    from gacli.linearize import linearize as run
    from gacli.sweep.work import resolved_parameters

    derivation = _solvable(system)
    return run(derivation, dict(at or {}), resolved_parameters(derivation.system, dict(parameters or {})))


def simulate(system, *, parameters=None, initial=None, inputs=None, functions=None, t_end=10.0,
             method="DOP853", rtol=1e-9, atol=1e-12, points=1001):
    """Integrate with SciPy, as ``gacli simulate`` does; returns a :class:`gacli.simulate.Simulation`.

    ``system``: a path, a System or a Derivation. ``parameters``,
    ``initial``, ``inputs``, ``functions``: mappings from names to numbers
    or to expressions as the command line takes them ("0.1*sin(t)", read by
    gacli's own parser, never eval). ``.t``, ``.states``, ``.column(name)``,
    ``.energy_drift`` and ``.residuals`` hold the result.

    >>> import gacli
    >>> run = gacli.simulate("systems/cylinder_in_cylinder.yaml", initial={"theta": 0.1}, t_end=2)  # doctest: +SKIP
    """
    from gacli.simulate import SimulationSpec, simulate as run

    def text(values) -> tuple[tuple[str, str], ...]:
        return tuple((name, value if isinstance(value, str) else repr(float(value)))
                     for name, value in dict(values or {}).items())

    spec = SimulationSpec(parameters=text(parameters), initial=text(initial), inputs=text(inputs),
                          functions=text(functions), t_end=float(t_end), method=method, rtol=float(rtol),
                          atol=float(atol), points=int(points))
    return run(_solvable(system), spec)


# -- steady motions, their stability, first integrals (gacli.steady; docs/steady.md) ---------

def steady(system):
    """The families of steady motions, as ``gacli steady`` finds them (:class:`gacli.steady.motions.SteadyMotions`).

    >>> import gacli
    >>> gacli.steady("systems/rolling_disk.yaml").families  # doctest: +SKIP
    """
    from gacli.steady.motions import steady_motions

    return steady_motions(derived(system))


def stability(system, at=None, parameters=None, symbolic=False):
    """Linear stability of the motion ``at`` on the constraint manifold (:class:`gacli.steady.stability.Stability`).

    Numerically: ``.eigenvalues``, ``.stable``. With ``symbolic=True``, ``at`` may hold SymPy
    expressions (a free spin rate), and ``.conditions`` are expressions that must all be positive.

    >>> import gacli, sympy
    >>> gacli.stability("systems/rolling_disk.yaml", {"dot(spin)": sympy.Symbol("w")}, symbolic=True).conditions  # doctest: +SKIP
    """
    from gacli.steady.stability import stability as numeric, stability_symbolic
    from gacli.sweep.work import resolved_parameters

    derivation = _solvable(system)
    if symbolic:
        return stability_symbolic(derivation, dict(at or {}))
    return numeric(derivation, dict(at or {}), resolved_parameters(derivation.system, dict(parameters or {})))


def integrals(system, candidates=()):
    """The first integrals found and the candidates checked (:class:`gacli.steady.integrals.Integrals`).

    ``candidates``: SymPy expressions, or text in gacli's grammar ("C*dot(q)").
    """
    from gacli.steady.integrals import integrals as find, parse_candidate

    derivation = derived(system)
    if isinstance(candidates, str):  # one candidate, not its characters
        candidates = [candidates]
    return find(derivation, [c if not isinstance(c, str) else parse_candidate(derivation, c) for c in candidates])
