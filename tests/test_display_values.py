"""What `gacli derive` prints for people means what the derivation means.

The display simplifier (:mod:`gacli.algebra.readable`) rewrites every
expression it prints: common denominators, collection on the rates, sin² +
cos² = 1. Each printed line is read back here with the system file's own
parser (the printout is in that grammar) and compared at random points with
the derivation's M, F and rates, which the display never changes.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import sympy as sp

from conftest import derived_file, printed
from gacli.algebra import symbols as S
from gacli.read.expr.build import Scope, build
from gacli.read.expr.parser import parse

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent
FILES = [ROOT / "systems" / "rolling_disk.yaml", ROOT / "systems" / "routh_sphere.yaml",
         ROOT / "systems" / "differential_drive.yaml", TESTS / "frames" / "car.yaml",
         TESTS / "frames" / "unbalanced_disk.yaml", TESTS / "twins" / "tricycle_front_drive.yaml",
         TESTS / "twins" / "car_format1.yaml", TESTS / "twins" / "snakeboard.yaml",
         ROOT / "systems" / "spinning_top.yaml", ROOT / "systems" / "chaplygin_sleigh.yaml"]
EQUATION = re.compile(r"^  dG/d\(ddot\((?P<name>[^)]+)\)\): (?P<lhs>.+) = (?P<rhs>[^=]+)$")
RATE = re.compile(r"^  dot\((?P<name>[^)]+)\) = (?P<value>.+)$")
# A printout too long to write out names its common subexpressions first (docs/printing.md).
# Its names: z1, z2, ... of code's CSE, or the program's physical ones (w_chassis_z), M_1_2 and F_1;
# not G (written "+ ...") or Q_s, which a written-out printout gives as sections of their own.
NAMED = re.compile(r"^  (?P<name>(?!G |Q_)[A-Za-z_]\w*) = (?P<value>[^=]+)$")
# ... and its equations through the entries of M and F it printed: for ddot(q): Σ M_s_r ddot(u_r) = F_s.
ENTRY_EQUATION = re.compile(r"^  for ddot\((?P<name>[^)]+)\): (?P<lhs>.+) = (?P<rhs>[^=]+)$")


def _scope(d) -> Scope:
    names = [*(c.name for c in d.system.coordinates), *(q.name for q in d.system.quasi_coordinates)]
    rates = {(n, order): S.rate(n, order) for n in names for order in (1, 2)}
    symbols = set().union(*(e.free_symbols for e in (*d.mass_matrix, *d.forcing, *d.generalized_forces)))
    symbols |= set().union(*(e.free_symbols for _, e in d.kinematic_equations))
    values = {s.name: s for s in symbols if not S.RATE_NAME.match(s.name)}
    values.update({n: S.value(n) for n in names})
    return Scope(values, rates)


def _read(text: str, scope: Scope) -> sp.Expr:
    return build(parse(text), scope)


def _close(a: sp.Expr, b: sp.Expr, rng) -> None:
    symbols = sorted(a.free_symbols | b.free_symbols, key=lambda s: s.name)
    for _ in range(3):
        point = {s: sp.Float(rng.uniform(0.3, 1.2), 30) for s in symbols}
        x, y = complex(a.xreplace(point).evalf(25)), complex(b.xreplace(point).evalf(25))
        assert abs(x - y) <= 1e-9 * (1 + abs(y)), (a, b)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_printed_equations_and_rates_are_the_derived_ones(path, rng):
    d = derived_file(path)
    exit_code, output = printed(path)
    assert exit_code == 0, output
    scope = _scope(d)
    equations, rates = {}, {}
    for line in output.splitlines():
        if m := NAMED.match(line):
            scope.values[m["name"]] = _read(m["value"], scope)  # each reads only the ones before it
        elif m := EQUATION.match(line) or ENTRY_EQUATION.match(line):
            equations[m["name"]] = _read(m["lhs"], scope) - _read(m["rhs"], scope)
        elif m := RATE.match(line):
            rates[m["name"]] = _read(m["value"], scope)
            # A named printout's later quantities read the dependent rate as it was printed (eq. 14.7).
            scope.rates[(m["name"], 1)] = rates[m["name"]]
    assert set(equations) == set(d.independent)
    for s, name in enumerate(d.independent):
        derived = sum((d.mass_matrix[s, r] * a for r, a in enumerate(d.speed_rates)), sp.S.Zero) - d.forcing[s]
        _close(equations[name], derived, rng)
    for name, value in rates.items():
        _close(value, d.rates.rate(name), rng)
