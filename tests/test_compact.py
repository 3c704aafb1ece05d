"""Systems written with frames and rolling print about as compactly as by hand, and mean the same.

The reductions that make them short (:mod:`gacli.algebra.trig`, rolling rows along
the wheel) are checked against the derivation without them, numerically at
random states: M and F must agree entry for entry.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from conftest import derived_file, printed
from gacli.display.long import CHARS_PER_OPERATION
from gacli.loader import frames
from gacli.algebra import trig
from gacli.mechanics.equations import derive
from gacli.loader.loading import load

FRAMES = Path(__file__).resolve().parent / "frames"
FILES = sorted(FRAMES.glob("*.yaml"))
SYSTEMS = Path(__file__).resolve().parent.parent / "systems"
# Issue #17: every system in systems/ prints under 5,000 characters, the bicycle
# aside (its limit is in docs/readable.md).
PRINTED = FILES + sorted(p for p in SYSTEMS.glob("*.yaml") if p.stem not in ("whipple_bicycle", "toroidal_bicycle", "rattleback"))


@pytest.mark.parametrize("path", PRINTED, ids=lambda p: p.stem)
def test_printed_in_under_5000_characters(path):
    exit_code, output = printed(path)
    assert exit_code == 0, output
    assert len(output) < 5_000


def _unreduced(path: Path, monkeypatch):
    """The derivation with every reduction switched off: rows in N, no identity applied."""
    with monkeypatch.context() as m:
        m.setattr(trig, "reduce", lambda expr, cancel=False: expr)
        m.setattr(frames, "in_wheel_heading", lambda rows, axle: rows)
        return derive(load(path))


@pytest.mark.parametrize("path", FILES + [SYSTEMS / "routh_sphere.yaml"], ids=lambda p: p.stem)
def test_reductions_change_no_value(path, monkeypatch, rng):
    reduced, plain = derived_file(path), _unreduced(path, monkeypatch)
    assert reduced.independent == plain.independent
    symbols = sorted(set().union(*(e.free_symbols for e in (*plain.mass_matrix, *plain.forcing))), key=str)
    for _ in range(3):
        point = {s: sp.Float(rng.uniform(0.2, 1.2)) for s in symbols}
        for a, b in zip((*reduced.mass_matrix, *reduced.forcing), (*plain.mass_matrix, *plain.forcing)):
            x, y = complex(a.xreplace(point).evalf()), complex(b.xreplace(point).evalf())
            assert abs(x - y) <= 1e-9 * (1 + abs(y)), (a, b)
    # And the reduction did its work: no sum of sin² and cos² of one angle is left in F.
    assert all(sp.count_ops(f) < sp.count_ops(g) or sp.count_ops(g) < 50
               for f, g in zip(reduced.forcing, plain.forcing))



# -- the vocabulary against the same system written by hand (issue #17) ---------

TWINS = Path(__file__).resolve().parent / "twins"
TWIN_FILES = sorted(TWINS.glob("*_format1.yaml"))


def _vocabulary(twin: Path) -> Path:
    stem = twin.stem.removesuffix("_format1")
    return TWINS / f"{stem}.yaml" if (TWINS / f"{stem}.yaml").exists() else FRAMES / f"{stem}.yaml"


def _printed(path: Path) -> str:
    exit_code, output = printed(path)
    assert exit_code == 0, output
    return output


NAMED = "Named quantities, each computed once"


@pytest.mark.parametrize("twin", TWIN_FILES, ids=lambda p: p.stem)
def test_the_vocabulary_prints_within_one_and_a_half_times_its_format1_twin(twin):
    vocabulary, by_hand = _printed(_vocabulary(twin)), _printed(twin)
    if NAMED in by_hand and NAMED not in vocabulary:
        # The twin's program got so short that its printout names its quantities
        # (docs/printing.md), where the vocabulary's equations are written out within the same
        # bound: lengths of the two forms do not compare (the tricycle: 4,988 written out, 3,159
        # named). The vocabulary's is then held to 1.5 times what the twin may print written out.
        bound = 1.5 * CHARS_PER_OPERATION * derived_file(twin).code.operations
        assert len(vocabulary) <= bound, (len(vocabulary), bound)
        return
    assert len(vocabulary) <= 1.5 * len(by_hand), (len(vocabulary), len(by_hand))


@pytest.mark.parametrize("twin", TWIN_FILES, ids=lambda p: p.stem)
def test_a_twin_has_the_same_equations(twin, rng):
    # The ratio above means something only if the twin is the same system.
    a, b = derived_file(_vocabulary(twin)), derived_file(twin)
    assert a.independent == b.independent
    exprs_a, exprs_b = (*a.mass_matrix, *a.forcing), (*b.mass_matrix, *b.forcing)
    names = sorted({s.name for e in (*exprs_a, *exprs_b) for s in e.free_symbols})
    for _ in range(3):
        values = {n: sp.Float(rng.uniform(0.3, 1.2), 30) for n in names}
        for x, y in zip(exprs_a, exprs_b):
            vx = complex(x.xreplace({s: values[s.name] for s in x.free_symbols}).evalf(25))
            vy = complex(y.xreplace({s: values[s.name] for s in y.free_symbols}).evalf(25))
            assert abs(vx - vy) <= 1e-9 * (1 + abs(vy)), (twin.stem, x, y)


# -- a format-1 file written with sines and cosines of sums of angles -----------

def test_rows_written_with_angle_sums_print_as_short_as_rows_in_the_heading_frame(rng):
    # A steered wheel's rows along its heading θ + δ, as a first derivation writes
    # them, beside the same rows written in the chassis frame (car_format1): the
    # same equations, and printed about as short (103,922 characters before the
    # sums were written out, against 4,045).
    sums, heading = TWINS / "car_angle_sums.yaml", TWINS / "car_format1.yaml"
    assert len(_printed(sums)) <= 1.1 * len(_printed(heading))
    a, b = derived_file(sums), derived_file(heading)
    names = sorted({s.name for e in (*a.mass_matrix, *a.forcing, *b.mass_matrix, *b.forcing) for s in e.free_symbols})
    values = {n: sp.Float(rng.uniform(0.3, 1.2), 30) for n in names}
    for x, y in zip((*a.mass_matrix, *a.forcing), (*b.mass_matrix, *b.forcing)):
        vx = complex(x.xreplace({s: values[s.name] for s in x.free_symbols}).evalf(25))
        vy = complex(y.xreplace({s: values[s.name] for s in y.free_symbols}).evalf(25))
        assert abs(vx - vy) <= 1e-9 * (1 + abs(vy))
