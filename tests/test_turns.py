"""Sines and cosines of whole combinations of angles as sums of turns (gacli.algebra.turns)."""

from __future__ import annotations

import sympy as sp

from gacli.algebra.turns import folded, turns

q1, q2, q3, x, l, a = sp.symbols("q1 q2 q3 x l a")


def test_a_sum_written_either_way_is_the_same_turns():
    summed = l * sp.cos(q1 + q2) + sp.I * l * sp.sin(q1 + q2)
    expanded = l * (sp.cos(q1) * sp.cos(q2) - sp.sin(q1) * sp.sin(q2)) \
        + sp.I * l * (sp.sin(q1) * sp.cos(q2) + sp.cos(q1) * sp.sin(q2))
    assert turns(summed, [q1, q2]) == turns(expanded, [q1, q2]) == {(1, 1): l}


def test_a_potential_with_its_sums_multiplied_out_folds_back_and_keeps_its_value():
    potential = a * sp.sin(q1) + l * sp.expand_trig(sp.sin(q1 + q2 + q3)) + x ** 2 * sp.cos(q2)
    out = folded(potential, [q1, q2, q3, x])
    assert sp.simplify(sp.expand_trig(out - potential)) == 0
    assert out.has(sp.sin(q1 + q2 + q3)) and sp.count_ops(out) < sp.count_ops(potential)


def test_what_is_not_a_sum_of_turns_is_refused():
    assert turns(sp.cos(q1 / 2), [q1]) is None
    assert turns(sp.cos(q1 ** 2), [q1]) is None
    assert turns(sp.tan(q1), [q1]) is None
    assert turns(sp.sqrt(1 + sp.cos(q1)), [q1]) is None
