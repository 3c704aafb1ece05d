"""The command's options and the derivation made into a :class:`gacli.sweep.work.Task`.

The fixed options read as ``gacli linearize`` and ``gacli simulate`` read
theirs: ``--set`` and ``--at`` are expressions in numbers and parameters
(gacli's own grammar, never ``eval``), evaluated once here; simulate's
options stay text, which every point's run parses as ``gacli simulate`` does.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from gacli.mechanics.equations import Derivation
from gacli.sweep.plan import Plan, SweepError, classify
from gacli.sweep.work import MODES, Task


def task_for(derivation: Derivation, mode: str, plan: Plan, *, set_: str = "", at: str = "",
             states: Sequence[str] = (), spec=None) -> Task:
    """The task of a sweep of ``mode`` over ``plan``'s names.

    Raises:
        SweepError: a swept name that is not a parameter or state (or, for
            linearize, an input), or a --states name not in the state.
        GacliError: a --set or --at that does not evaluate.
    """
    from gacli.emit.naming import layout

    if mode not in MODES:
        raise SweepError(f"'{mode}' is not a sweep; choose one of: {', '.join(MODES)}")
    lay = layout(derivation)
    others = lay.r if mode == "linearize" else ()
    kinds = classify(plan.names, lay.parameters, lay.state, others)
    unknown = [n for n in states if n not in lay.state]
    if unknown:
        raise SweepError(f"--states: not in the state: {', '.join(unknown)} (the state is {', '.join(lay.state)})")
    base = Task(mode=mode, names=plan.names, kinds=tuple(kinds[n] for n in plan.names), state=lay.state,
                states=tuple(states))
    if mode == "simulate":
        from gacli.simulate import SimulationSpec

        return replace(base, spec=spec if spec is not None else SimulationSpec())
    parameters, point = _linearize_values(derivation, set_, at)
    return replace(base, parameters=tuple(parameters.items()), at=tuple(point.items()))


def _linearize_values(derivation: Derivation, set_: str, at: str) -> tuple[dict[str, float], dict[str, float]]:
    from gacli.emit.naming import parameter_defaults
    from gacli.linearize import evaluate_assignments
    from gacli.simulate import parse_assignments

    defaults = parameter_defaults(derivation.system.parameters)
    overrides = evaluate_assignments(parse_assignments(set_ or "", "--set"), defaults, "--set")
    point = evaluate_assignments(parse_assignments(at or "", "--at"), {**defaults, **overrides}, "--at")
    return overrides, point
