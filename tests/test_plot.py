"""gacli simulate --plot as documented: the state-vs-time panel always, units from the file on the axes.

matplotlib's SVG keeps every text it draws as a comment beside its glyphs
(``<!-- x [m] -->``) and each panel as a group ``axes_N``: the tests read both.
"""

from __future__ import annotations

import re

import pytest
from typer.testing import CliRunner

from gacli.cli import app

pytest.importorskip("matplotlib")
pytest.importorskip("scipy")

OSCILLATOR = """\
gacli: 1
name: two_springs
parameters: {m: {value: 1, unit: kg}, k: {value: 4, unit: N/m}}
coordinates:
  x: {description: stretch of the first spring, unit: m}
  theta: {description: second coordinate, unit: rad}
  s: second coordinate without a unit
bodies: {p: {mass: m, position: [x, theta, s]}}
potential: k*x**2/2 + k*theta**2/2 + k*s**2/2
"""


@pytest.fixture(scope="module")
def system(tmp_path_factory):
    path = tmp_path_factory.mktemp("plot") / "two_springs.yaml"
    path.write_text(OSCILLATOR)
    return path


def draw(system, tmp_path, *options: str) -> tuple[list[str], int]:
    target = tmp_path / "plot.svg"
    result = CliRunner().invoke(app, ["simulate", str(system), "--init", "x=0.1,theta=0.2", "--t-end", "1",
                                      "--points", "11", "--plot", str(target), *options])
    assert result.exit_code == 0, result.output
    svg = target.read_text()
    return re.findall(r"<!-- (.*?) -->", svg), len(set(re.findall(r'id="axes_(\d+)"', svg)))


def test_phase_alone_keeps_the_state_against_time_panel(system, tmp_path):
    texts, panels = draw(system, tmp_path, "--phase", "x,theta")
    assert panels == 2
    assert "t [s]" in texts                                   # the left panel, against time
    assert {"x [m]", "theta [rad]", "s"} <= set(texts)        # its legend: the coordinates, by default
    assert texts.count("x [m]") == 2                          # and the phase panel's x axis


def test_rates_are_per_second_and_a_shared_unit_labels_the_axis(system, tmp_path):
    texts, panels = draw(system, tmp_path, "--show", "x,dot(x)")
    assert panels == 1
    assert {"x [m]", "dot(x) [m/s]"} <= set(texts)
    assert "m" not in texts   # two units: no common y label
    texts, _ = draw(system, tmp_path, "--show", "x")
    assert "m" in texts       # one unit: it labels the y axis


def test_units_of_the_file_never_reach_matplotlibs_math_mode(tmp_path):
    path = tmp_path / "dollar.yaml"
    path.write_text(OSCILLATOR.replace("unit: rad", "unit: \"$\\\\frac{\""))
    texts, _ = draw(path, tmp_path, "--phase", "x,theta")
    assert any("frac" in t for t in texts)


def test_per_second():
    from gacli.simulate.plot import per_second

    assert [per_second(u) for u in ("m", "rad", "m^2", "m/s", "N m")] == ["m/s", "rad/s", "m^2/s", "(m/s)/s",
                                                                        "(N m)/s"]
