"""A rotation written as one angle sum or as two frames: the same equations at the same cost (issue #28).

SymPy's bicycle turns its fork frame by ``q4 + htangle`` and its frame body
back by ``-htangle``; systems/whipple_bicycle.yaml turns by ``pitch`` and
then ``htangle``. The loader writes both as one chain of simple rotations
from N, so that the derivation cannot tell them apart.
"""

from __future__ import annotations

import sympy as sp

from conftest import ROOT

BICYCLE = ROOT / "systems" / "whipple_bicycle.yaml"
TWO_FRAMES = """  frame_body: {parent: rolled, rotations: [[y, pitch]]}
  head_tube: {parent: frame_body, rotations: [[y, htangle]]}"""
ANGLE_SUM = """  head_tube: {parent: rolled, rotations: [[y, pitch + htangle]]}
  frame_body: {parent: head_tube, rotations: [[y, -htangle]]}"""


def _differential(*coordinates):
    def differential(angle):
        return sp.Matrix([[sp.diff(angle, q) for q in coordinates] + [0]])
    return differential


def test_a_turn_back_about_the_same_axis_cancels():
    from gacli.loader import frames as F

    q, h = sp.symbols("q h", real=True)
    d = _differential(q)
    N = F.inertial_frame(2)
    tube = F.oriented("tube", N, [("y", q + h)], d)
    body = F.oriented("body", tube, [("y", -h)], d)
    assert body.chain == (("y", q),)
    assert body.dcm == F.simple_rotation("y", q)
    assert body.omega == sp.Matrix([[0, 0], [1, 0], [0, 0]])
    # The sum is split coordinates first, whatever SymPy's order of the sum's terms.
    assert tube.chain == (("y", q), ("y", h))
    assert sp.simplify(sp.Matrix(tube.dcm) - F.simple_rotation("y", q + h)) == sp.zeros(3, 3)


def test_rotations_as_written_keep_their_order_and_form():
    """Nothing to merge: the frame is built as before (outputs of existing files unchanged)."""
    from gacli.loader import frames as F

    q, r = sp.symbols("q r", real=True)
    d = _differential(q, r)
    A = F.oriented("A", F.inertial_frame(3), [("z", q), ("z", r)], d)
    assert A.chain == (("z", q), ("z", r))
    expected = F.simple_rotation("z", q) * F.simple_rotation("z", r)
    assert sp.simplify(sp.Matrix(A.dcm) - expected) == sp.zeros(3, 3)


def test_the_bicycle_written_with_an_angle_sum_is_the_two_frame_bicycle():
    from gacli.loader.loading import loads
    from gacli.mechanics.equations import derive
    from gacli.algebra.graph import free_symbols, operations
    from gacli.numeric import Program

    text = BICYCLE.read_text()
    assert TWO_FRAMES in text
    by_frames = loads(text, "two_frames.yaml")
    by_sum = loads(text.replace(TWO_FRAMES, ANGLE_SUM), "angle_sum.yaml")
    for a, b in ((by_frames, by_sum), (derive(by_frames), derive(by_sum))):
        left, right = _entries(a), _entries(b)
        assert operations(left) == operations(right)
        symbols = sorted(free_symbols(left + right), key=str)
        point = {s: 0.3 + 0.1 * i for i, s in enumerate(symbols)}
        for x, y in zip(Program(left)(point), Program(right)(point)):
            assert abs(x - y) <= 1e-12 * max(1.0, abs(x))


def _entries(thing) -> list[sp.Expr]:
    """A system's constraint rows and body positions, or a derivation's M and F."""
    if hasattr(thing, "mass_matrix"):
        return list(thing.mass_matrix) + list(thing.forcing)
    rows = [e for c in thing.constraints for _, e in c.form.coefficients]
    return rows + [e for b in thing.bodies for e in b.position]



def test_reduction_walks_a_shared_expression_once():
    """A sum of angles in an expression whose pieces are shared: its tree has 2^60 paths."""
    from gacli.algebra import trig
    from gacli.numeric.zero import time_limit

    a, b, x = sp.symbols("a b x", real=True)
    e = x
    for _ in range(60):
        e = sp.Mul(sp.Add(e, sp.cos(a + b)), sp.Add(e, sp.sin(a)), evaluate=False)
    with time_limit(120, lambda: AssertionError("the reduction walked the tree, not the graph")):
        trig.reduce(sp.cos(a) * sp.cos(b) + e)
