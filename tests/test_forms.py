"""The rows stated as forms, combined along the angles their links turn by (gacli.mechanics.program.forms)."""

from __future__ import annotations

import sympy as sp

from gacli.mechanics.program import forms as F
from gacli.model import Form

q1, q2, q3, q4, l1, l2, l3, l4 = sp.symbols("q1 q2 q3 q4 l1 l2 l3 l4")


def _loop() -> tuple[Form, Form]:
    """A five-bar's loop closed in N, its right coupler hung from its crank (turned by q3 + q4), the
    rows as the loader writes them: the sum's sine and cosine multiplied out."""
    s34 = sp.sin(q3) * sp.cos(q4) + sp.cos(q3) * sp.sin(q4)
    c34 = sp.cos(q3) * sp.cos(q4) - sp.sin(q3) * sp.sin(q4)
    x = Form((("q1", l1 * sp.sin(q1)), ("q2", l2 * sp.sin(q2)), ("q3", -l3 * s34), ("q4", -l3 * s34 - l4 * sp.sin(q4))))
    y = Form((("q1", -l1 * sp.cos(q1)), ("q2", -l2 * sp.cos(q2)), ("q3", l3 * c34), ("q4", l3 * c34 + l4 * sp.cos(q4))))
    return x, y


def test_a_link_turned_by_a_sum_of_angles_gives_the_rows_an_angle_to_turn_along():
    x, y = _loop()
    assert q3 + q4 in F._angles(x, y)


def test_the_loop_turned_along_both_couplers_holds_one_dependent_rate_per_row():
    """Along the links, each row leaves one of the dependent rates out, and each pivot is the sine of
    the loop's one dead-point angle, q3 + q4 − q2 (as by hand)."""
    turned = F.FormRows(_loop()).turnings(["q2", "q3"])
    assert turned
    best = turned[0].forms
    held = [{q for q in ("q2", "q3") if f.coefficient(q) != 0} for f in best]
    assert sorted(map(len, held)) == [1, 1] and held[0] != held[1]
    for f, (q,) in zip(best, held):
        pivot = f.coefficient(q)
        assert sp.simplify(pivot / sp.sin(q3 + q4 - q2)).free_symbols <= {l2, l3}


def test_a_large_coefficient_is_not_written_through_its_turns():
    """Writing a coefficient through e^(iq) costs in its products' terms: past FOLDED_NODES it is left."""
    big = sp.Add(*(sp.Symbol(f"a{i}") * sp.sin(q1) * sp.cos(q2) * sp.sin(q3) for i in range(30)))
    assert F._folded(big) == big
    small = sp.sin(q3) * sp.cos(q4) + sp.cos(q3) * sp.sin(q4)
    assert F._folded(small) == sp.sin(q3 + q4)
