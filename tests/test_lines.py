"""Springs, dampers and torques with a reaction (issue #29, items 1 and 2), against the same loads by hand.

``tests/lines/arm_with_motor_spring_damper.yaml`` declares an elbow motor
(``torque`` with ``reaction``), a spring and a damper ``between`` two
points; ``tests/lines/arm_by_hand.yaml`` is the same arm with the motor's
virtual work, the spring's potential and the damper's work written out by
hand. Their equations must agree at random states, in closed form and in
generated code, and the declared file must pass verify's independent route.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from gacli.algebra import symbols as S
from gacli.errors import SystemFileError
from gacli.loader.loading import load, loads
from gacli.mechanics.equations import derive
from gacli.numeric import Program as Evaluator
from gacli.numeric.parameters import parameter_values
from gacli.verify.run import verify

HERE = Path(__file__).resolve().parent / "lines"
DECLARED = HERE / "arm_with_motor_spring_damper.yaml"
BY_HAND = HERE / "arm_by_hand.yaml"


def _states(system, count: int = 5) -> list[dict]:
    rng = np.random.default_rng(20261126)
    known, _ = parameter_values(system)
    out = []
    for _ in range(count):
        state = dict(known)
        state.update({S.value(c.name): rng.uniform(-3, 3) for c in system.coordinates})
        state.update({S.rate(c.name): rng.uniform(-2, 2) for c in system.coordinates})
        state.update({S.value(i.name): rng.uniform(-1, 1) for i in system.inputs})
        state[S.T] = 0.0
        out.append(state)
    return out


def _closed(d) -> Evaluator:
    return Evaluator([*d.mass_matrix, *d.forcing])


def _code(d) -> Evaluator:
    c = d.code
    k = d.k
    M = [0] * (k * k)
    for (i, j), e in c.mass_matrix:
        M[i * k + j] = e
    return Evaluator([*M, *c.forcing])


def _assert_agree(declared, by_hand) -> None:
    """M and F of ``declared`` (closed forms and generated code's) equal ``by_hand``'s at random states."""
    for state in _states(declared.system):
        theirs = np.real(np.array(_closed(by_hand)(state)))
        for ours in (_closed(declared)(state), _code(declared)(state)):
            assert np.max(np.abs(np.real(np.array(ours)) - theirs)) < 1e-9 * max(1.0, np.max(np.abs(theirs)))


def test_declared_loads_agree_with_the_same_loads_written_by_hand():
    declared, by_hand = derive(load(DECLARED)), derive(load(BY_HAND))
    _assert_agree(declared, by_hand)


def test_the_declared_arm_passes_verify():
    system = load(DECLARED)
    assert verify(system, derive(system), samples=3).passed


ARM = DECLARED.read_text(encoding="utf-8")


@pytest.mark.parametrize("old, new, message", [
    ("between: [wall, wrist]", "between: [wrist, wrist]", "same point"),
    ("between: [wall, wrist]", "between: [wal, wrist]", "'wal' is not a body or a point"),
    ("between: [wall, wrist]", "between: [wall]", "expected two names"),
    ("{spring: k, between: [wall, wrist], length: L0}", "{spring: k, at: wrist}", "needs 'between'"),
    ("{damper: c, between: [c1, floor]}", "{damper: c, between: [c1, floor], length: 1}", "needs 'between'"),
    ("reaction: upper", "reaction: fore", "another body"),
    ("reaction: upper", "reaction: uper", "'uper' is not a body"),
    ("{torque: T, body: fore, reaction: upper}", "{torque: T, spring: k, body: fore}", "a load is one of"),
])
def test_mistakes_are_located_errors(old, new, message):
    assert old in ARM
    with pytest.raises(SystemFileError) as caught:
        loads(ARM.replace(old, new))
    diagnostic = caught.value.diagnostics[0]
    assert message in str(caught.value) and diagnostic.location.line > 1


def test_a_reaction_needs_both_bodies_with_frames():
    text = """
gacli: 1
name: no_frames
parameters: [m, I, T]
coordinates: [a, b]
bodies:
  one: {mass: m, position: [0, 0, 0], inertia: I, rotation: da}
  two: {mass: m, position: [1, 0, 0], inertia: I, rotation: db}
loads:
  - {torque: T, body: two, reaction: one}
"""
    with pytest.raises(SystemFileError, match="both bodies written with a 'frame'"):
        loads(text)


def test_a_torque_on_a_frame_fixed_in_a_body_acts_on_that_body_along_the_frame_s_axes():
    # The rotor frame is the forearm's turned half a turn about x: its z axis is the forearm's -z, so
    # -T along it is the elbow motor's T, and the arm must agree with the one written by hand.
    text = ARM.replace("  fore: {rotations: [[z, th2]]}\n",
                       "  fore: {rotations: [[z, th2]]}\n  rotor: {parent: fore, rotations: [[x, pi]]}\n")
    text = text.replace("{torque: T, body: fore, reaction: upper}", "{torque: -T, body: rotor, reaction: upper}")
    declared, by_hand = derive(loads(text)), derive(load(BY_HAND))
    _assert_agree(declared, by_hand)


def test_a_torque_on_a_frame_fixed_in_no_body_is_a_located_error():
    text = ARM.replace("  fore: {rotations: [[z, th2]]}\n", "  fore: {rotations: [[z, th2]]}\n  loose: {rotations: [[x, th2]]}\n")
    with pytest.raises(SystemFileError, match="'loose' is fixed in no rigid body"):
        loads(text.replace("{torque: T, body: fore, reaction: upper}", "{torque: T, body: loose}"))
