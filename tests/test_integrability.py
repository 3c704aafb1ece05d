"""Frobenius classification: holonomic constraints and quasi-coordinates that are coordinates."""

from __future__ import annotations

import signal
import time

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from gacli.integrability import (
    SIMPLIFY_MAX_OPS, Decision, UndefinedValue, classify, decide_zero, evaluate, time_limit,
)
from gacli.loading import load, loads

from conftest import SYSTEMS


def verdicts(system) -> dict[str, str]:
    return {c.where: c.verdict for c in classify(system)}


def system(constraints=(), quasi=None, extra="") -> object:
    quasi_text = "{" + ", ".join(f"{k}: '{v}'" for k, v in (quasi or {}).items()) + "}"
    return loads(f"""
gacli: 1
name: forms
parameters: [m, a]
functions: {{Omega: angular rate, w: {{value: a*t}}}}
coordinates: [x, y, z]
quasi_coordinates: {quasi_text}
constraints: [{", ".join(repr(c) for c in constraints)}]
bodies: {{p: {{mass: m, position: [x, y, z]}}}}
{extra}
""")


# -- the shipped systems ---------------------------------------------------------------------

def test_the_rolling_sphere_constraints_are_not_integrable():
    found = classify(load(SYSTEMS / "sphere_on_turntable.yaml"))
    assert [(c.where, c.kind, c.verdict) for c in found] == [
        ("constraints[0]", "constraint", "non-holonomic"),
        ("constraints[1]", "constraint", "non-holonomic"),
    ]
    assert found[0].text == "dx - a*dq_y = -Omega*y*dt"
    lines = (SYSTEMS / "sphere_on_turntable.yaml").read_text(encoding="utf-8").splitlines()
    assert found[0].text in lines[found[0].location.line - 1]


def test_the_rolling_cylinder_constraint_is_integrable():
    (found,) = classify(load(SYSTEMS / "cylinder_in_cylinder.yaml"))
    assert (found.where, found.integrable, found.verdict, found.method) == (
        "constraints[0]", True, "holonomic", "symbolic")


def test_the_areal_velocity_is_not_a_coordinate():
    (found,) = classify(load(SYSTEMS / "particle_in_plane.yaml"))
    assert (found.kind, found.where, found.verdict) == ("quasi_coordinate", "quasi_coordinates.q", "not a coordinate")


def test_the_spin_of_the_top_is_not_a_coordinate():
    assert verdicts(load(SYSTEMS / "spinning_top.yaml")) == {"quasi_coordinates.q": "not a coordinate"}


def test_primitive_quasi_coordinates_are_not_classified():
    assert classify(load(SYSTEMS / "rigid_body.yaml")) == ()


# -- forms written for the test ----------------------------------------------------------

@pytest.mark.parametrize("differential, verdict", [
    ("dx + dy", "a coordinate"),                    # q = x + y
    ("y*dx + x*dy", "a coordinate"),                # q = x y
    ("x*dt + t*dx", "a coordinate"),                # q = x t: t is one more variable
    ("cos(x)*dx - a*dy + Omega*dt", "a coordinate"),  # a free function of t is still exact in dt
    ("y*dx - x*dy", "not a coordinate"),
    ("w*dx", "not a coordinate"),                   # w = a*t is substituted: d(a t dx) = a dt^dx
    ("dx + dq", "a coordinate"),                    # another quasi-coordinate's differential: q2 = x + q
])
def test_quasi_coordinate(differential, verdict):
    found = verdicts(system(quasi={"q": "dz", "p": differential}))
    assert found["quasi_coordinates.p"] == verdict


@pytest.mark.parametrize("constraint, verdict", [
    ("x*dx + y*dy + z*dz = 0", "holonomic"),        # a sphere
    ("y*dx - x*dy = 0", "holonomic"),               # not closed, but 1/y**2 integrates it
    ("dz = y*dx", "non-holonomic"),                 # the standard contact form
    ("dx = t*dy", "non-holonomic"),                 # time is a variable too
    ("dx = Omega*dt", "holonomic"),                 # x = the integral of Omega
    ("dx = y*Omega*dt", "non-holonomic"),
    ("sin(w)*dx = cos(w)*dy", "non-holonomic"),     # a knife edge turned at the rate a
    ("sin(a)*dx = cos(a)*dy", "holonomic"),         # ... and one held at a fixed angle
    ("x**2 + y**2 = a**2", "holonomic"),            # a relation f(q, t) = 0
])
def test_constraint(constraint, verdict):
    found = classify(system([constraint]))[0]
    assert found.verdict == verdict
    if "d" not in constraint.replace("dot", ""):
        assert found.method == "relation"


def exact_forms():
    """df for small polynomials f(x, y, t): always closed; g df is always integrable."""
    x, y, t = (sp.Symbol(n, real=True) for n in "xyt")
    monomial = st.tuples(st.integers(-3, 3), st.integers(0, 2), st.integers(0, 2), st.integers(0, 2))
    return st.lists(monomial, min_size=1, max_size=4).map(
        lambda terms: sum(c * x**i * y**j * t**k for c, i, j, k in terms))


def form_text(f, factor=1) -> str:
    x, y, t = (sp.Symbol(n, real=True) for n in "xyt")
    parts = [f"({sp.sstr(factor * sp.diff(f, v))})*d{v.name}" for v in (x, y, t)]
    return " + ".join(parts)


@settings(max_examples=15, deadline=None, derandomize=True)
@given(f=exact_forms(), g=exact_forms())
def test_exact_forms_are_closed_and_their_multiples_integrable(f, g):
    if sp.diff(f, sp.Symbol("x", real=True)) == 0 and sp.diff(f, sp.Symbol("y", real=True)) == 0:
        return  # no dx or dy term: not a form over the coordinates
    s = system([form_text(f, 1 + g**2) + " = 0"], {"q": form_text(f)})
    assert verdicts(s) == {"constraints[0]": "holonomic", "quasi_coordinates.q": "a coordinate"}


# -- deciding zero ---------------------------------------------------------------------------

x, y = sp.symbols("x y", real=True)


def test_zero_by_simplify():
    assert decide_zero(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1) == Decision(True, "symbolic")
    assert decide_zero(sp.Integer(3)) == Decision(False, "symbolic")


def test_zero_by_points_when_too_big_to_simplify():
    big = sum(sp.sin(k * x + y) ** 2 + sp.cos(k * x + y) ** 2 for k in range(40)) - 40
    assert sp.count_ops(big) > SIMPLIFY_MAX_OPS
    assert decide_zero(big) == Decision(True, "numeric")
    assert decide_zero(big + sp.exp(-x) / 1000) == Decision(False, "numeric")


def test_abs_is_not_mistaken_for_the_identity():
    assert decide_zero(sp.Abs(x) - x).zero is False


def test_undecided_when_nothing_can_be_evaluated():
    assert decide_zero(sp.sqrt(-1 - x**2) * y).zero is None


def test_evaluation_refuses_huge_values_at_once():
    start = time.perf_counter()
    for expr in (sp.exp(sp.exp(sp.exp(100))) * x, sp.exp(sp.exp(sp.exp(sp.exp(x)))), x ** (10**50)):
        with pytest.raises(UndefinedValue):
            evaluate(expr, {x: 1.5})
    assert time.perf_counter() - start < 5


def test_a_slow_simplify_falls_back_to_points():
    omega = sp.Symbol("Omega", real=True)
    nasty = sp.atan2(sp.atan2(sp.atan2(omega, x), sp.pi - y), sp.sign(sp.Integer(10) ** 300 - sp.log(omega)))
    start = time.perf_counter()
    decide_zero(sp.diff(nasty, y) * x - y)
    assert time.perf_counter() - start < 30  # simplify alone runs for minutes


# -- nested time limits ----------------------------------------------------------------------------

class Outer(Exception):
    pass


class Inner(Exception):
    pass


def spin(seconds: float) -> None:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        pass


def test_an_inner_limit_fires_and_the_outer_one_survives():
    with pytest.raises(Outer):
        with time_limit(1.0, Outer) as armed:
            assert armed
            with pytest.raises(Inner):
                with time_limit(0.05, Inner):
                    spin(5)
            spin(5)


def test_an_outer_limit_that_ends_first_is_left_to_fire():
    with pytest.raises(Outer):
        with time_limit(0.1, Outer):
            with time_limit(5, Inner) as armed:
                assert not armed
                spin(5)
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)


def test_no_limit_means_no_alarm():
    with time_limit(0, Inner) as armed:
        assert not armed
        assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
