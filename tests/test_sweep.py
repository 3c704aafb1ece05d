"""gacli sweep: the plan, the table, and the same table here, on --jobs 2 and on a local Dask cluster.

The numbers are checked against the textbook, not against the tool: the thin
rolling disk's upright motion is stable exactly when its spin rate exceeds
sqrt(g/(3r)) (Kane and Levinson 1985), and a cylinder rolling inside a
cylinder swings as a pendulum of frequency sqrt(2g/(3c)), c = b - a, which
the file computes from b (so sweeping b must move c).
"""

from __future__ import annotations

import csv
import io
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from conftest import SYSTEMS, derived
from gacli.cli import app
from gacli.sweep import SweepError, plan

DISK = str(SYSTEMS / "rolling_disk.yaml")
DISK_GRID = ["--grid", "r=0.2:0.3:2", "--grid", "dot(spin)=-8:-2:7", "--states", "lean,dot(yaw),dot(lean)"]
CYLINDER = str(SYSTEMS / "cylinder_in_cylinder.yaml")


def invoke(*args: str):
    return CliRunner().invoke(app, list(args))


def rows(text: str) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(text)))


def csv_part(output: str) -> str:
    """The CSV on stdout (CliRunner mixes in stderr's one-line summary, which starts with a digit and 'points')."""
    return "".join(line for line in output.splitlines(keepends=True) if " points " not in line)


# -- the plan -------------------------------------------------------------------------

def test_a_grid_is_the_product_with_the_last_name_fastest():
    p = plan(grid=["a=0:1:3", "b=5:6:2"])
    assert p.names == ("a", "b")
    assert p.points == ((0.0, 5.0), (0.0, 6.0), (0.5, 5.0), (0.5, 6.0), (1.0, 5.0), (1.0, 6.0))


def test_a_random_sample_is_reproducible_and_inside_its_bounds():
    first = plan(random=["m=0.5:2", "x=-1:1"], samples=50, seed=7)
    assert first == plan(random=["m=0.5:2", "x=-1:1"], samples=50, seed=7)
    assert first != plan(random=["m=0.5:2", "x=-1:1"], samples=50, seed=8)
    values = np.array(first.points)
    assert values.shape == (50, 2)
    assert (values[:, 0] >= 0.5).all() and (values[:, 0] < 2).all() and (values[:, 1] >= -1).all()


@pytest.mark.parametrize("options, message", [
    ({"grid": ["a=0:1:3"], "random": ["b=0:1"], "samples": 3}, "not both"),
    ({}, "nothing to sweep"),
    ({"random": ["b=0:1"]}, "--samples"),
    ({"grid": ["a=0:1"]}, "NAME=START:STOP:COUNT"),
    ({"grid": ["a=0:1:0"]}, "COUNT"),
    ({"grid": ["a=0:inf:3"]}, "finite"),
    ({"grid": ["a=0:x:3"]}, "not a number"),
    ({"random": ["b=1:0"], "samples": 2}, "LOW must be below HIGH"),
    ({"grid": ["a=0:1:2", "a=0:1:2"]}, "swept twice"),
])
def test_plan_mistakes_are_one_sentence(options, message):
    with pytest.raises(SweepError, match=message):
        plan(**options)


# -- linearize: here, on two processes, on Dask ------------------------------------------

@pytest.fixture(scope="module")
def disk_tables():
    """The same sweep run here, with --jobs 2 and on a local Dask cluster (two in-process workers)."""
    distributed = pytest.importorskip("distributed")
    here = invoke("sweep", DISK, "--run", "linearize", *DISK_GRID)
    jobs = invoke("sweep", DISK, "--run", "linearize", *DISK_GRID, "--jobs", "2")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster:
        dask = invoke("sweep", DISK, "--run", "linearize", *DISK_GRID, "--scheduler", cluster.scheduler_address)
    for result in (here, jobs, dask):
        assert result.exit_code == 0, result.output
    return {"here": csv_part(here.output), "jobs": csv_part(jobs.output), "dask": csv_part(dask.output)}


def test_the_table_is_the_same_here_on_processes_and_on_dask(disk_tables):
    assert disk_tables["jobs"] == disk_tables["here"]
    assert disk_tables["dask"] == disk_tables["here"]
    assert len(rows(disk_tables["here"])) == 14


def test_the_disk_is_stable_above_the_textbooks_spin_rate(disk_tables):
    g = 9.81
    for row in rows(disk_tables["here"]):
        r, spin = float(row["r"]), float(row["dot(spin)"])
        marginal = float(row["max_real"]) < 1e-9   # conservative: at best the real parts vanish
        assert marginal == (spin**2 > g / (3 * r)), row
        assert row["error"] == ""
        assert row["stable"] == "false"  # asymptotically stable it never is: nothing dissipates


def test_rows_match_gacli_linearize_at_two_points(disk_tables):
    from gacli.linearize import linearize

    table = rows(disk_tables["here"])
    for row in (table[0], table[-1]):
        direct = linearize(derived("rolling_disk"), {"dot(spin)": float(row["dot(spin)"])},
                           {"r": float(row["r"])}).eigenvalues(["lean", "dot(yaw)", "dot(lean)"])
        swept = [complex(float(row[f"eig{i}_re"]), float(row[f"eig{i}_im"])) for i in (1, 2, 3)]
        np.testing.assert_allclose(swept, direct, rtol=1e-12, atol=1e-12)


# -- simulate ----------------------------------------------------------------------------

def test_simulate_sweep_swings_as_the_textbooks_pendulum_and_matches_gacli_simulate(tmp_path):
    from gacli.simulate import SimulationSpec, simulate

    out = tmp_path / "swing.csv"
    result = invoke("sweep", CYLINDER, "--run", "simulate", "--grid", "b=0.5:0.8:2", "--grid", "theta=0.001:0.002:2",
                    "--t-end", "1", "--output", str(out))
    assert result.exit_code == 0, result.output
    table = rows(out.read_text())
    assert [(r["b"], r["theta"]) for r in table] == [("0.5", "0.001"), ("0.5", "0.002"), ("0.8", "0.001"),
                                                    ("0.8", "0.002")]
    for row in table:
        b, theta0 = float(row["b"]), float(row["theta"])
        omega = math.sqrt(2 * 9.81 / (3 * (b - 0.1)))
        assert float(row["final_theta"]) == pytest.approx(theta0 * math.cos(omega), rel=1e-5, abs=1e-9)
        assert float(row["energy_drift"]) < 1e-6
    direct = simulate(derived("cylinder_in_cylinder"), SimulationSpec(
        parameters=(("b", "0.8"),), initial=(("theta", "0.002"),), t_end=1.0, points=101))
    swept = [float(table[-1][f"final_{n}"]) for n in direct.state_names]
    np.testing.assert_allclose(swept, direct.states[-1], rtol=1e-12, atol=1e-15)


def test_a_point_that_fails_is_a_row_with_its_reason(tmp_path):
    # b = a = 0.1 makes c = 0: the cylinder cannot move and M is singular there.
    result = invoke("sweep", CYLINDER, "--run", "simulate", "--grid", "b=0.5:0.1:2", "--init", "theta=0.1",
                    "--t-end", "0.1")
    assert result.exit_code == 0, result.output
    table = rows(csv_part(result.output))
    assert table[0]["error"] == "" and table[1]["error"] != ""
    assert table[1]["final_theta"] == "nan"
    assert "1 failed" in result.output


# -- mistakes --------------------------------------------------------------------------

@pytest.mark.parametrize("args, code, message", [
    (["--run", "linearize", "--grid", "mass=1:2:2"], 2, "not a parameter or state of the system: mass"),
    (["--run", "simulate", "--grid", "m=1:2:2", "--at", "lean=0"], 2, "only with --run linearize"),
    (["--run", "linearize", "--grid", "m=1:2:2", "--t-end", "3"], 2, "only with --run simulate"),
    (["--run", "linearize", "--grid", "m=1:2:2", "--output", "table.txt"], 1, ".csv or a .parquet"),
    (["--run", "linearize", "--grid", "m=1:2:2", "--jobs", "2", "--scheduler", "tcp://x:1"], 2, "give one"),
    (["--run", "bounce", "--grid", "m=1:2:2"], 2, "choose one of: linearize, simulate"),
    (["--run", "linearize", "--grid", "m=1:2:2", "--states", "wobble"], 2, "not in the state: wobble"),
    (["--run", "linearize", "--grid", "m=1:2"], 2, "expected NAME=START:STOP:COUNT"),
    (["--run", "linearize", "--random", "m=1:2", "--samples", "2", "--seed", "-1"], 2, "--seed -1"),
])
def test_mistakes_are_one_message_and_no_traceback(args, code, message):
    result = invoke("sweep", DISK, *args)
    assert result.exit_code == code, result.output
    assert message in " ".join(result.output.split())
    assert "Traceback" not in result.output


def test_an_existing_table_is_untouched_when_the_sweep_fails(tmp_path):
    out = tmp_path / "table.csv"
    out.write_text("before\n")
    result = invoke("sweep", DISK, "--run", "linearize", "--grid", "mass=1:2:2", "--output", str(out))
    assert result.exit_code == 2  # the unknown name: a usage error
    assert out.read_text() == "before\n"


def test_parquet_holds_the_same_table_as_csv(tmp_path):
    pyarrow = pytest.importorskip("pyarrow.parquet")
    args = ["sweep", DISK, "--run", "linearize", "--grid", "dot(spin)=-5:-2:2"]
    assert invoke(*args, "--output", str(tmp_path / "t.csv")).exit_code == 0
    assert invoke(*args, "--output", str(tmp_path / "t.parquet")).exit_code == 0
    parquet = pyarrow.read_table(tmp_path / "t.parquet").to_pydict()
    table = rows((tmp_path / "t.csv").read_text())
    assert list(parquet) == list(table[0])
    assert parquet["max_real"] == [float(r["max_real"]) for r in table]


def test_the_methods_and_timeout_literals_agree_with_the_library():
    from gacli import cli_sweep, simulate
    from gacli.budget import DEFAULT_TIMEOUT

    assert cli_sweep.METHODS == simulate.METHODS
    assert cli_sweep.DEFAULT_TIMEOUT == DEFAULT_TIMEOUT


def test_a_random_sample_through_the_cli_is_reproducible_and_in_bounds():
    args = ["sweep", DISK, "--run", "linearize", "--random", "dot(spin)=-8:-4", "--random", "r=0.25:0.35",
            "--samples", "3", "--seed", "5"]
    first, again = invoke(*args), invoke(*args)
    assert first.exit_code == 0, first.output
    assert csv_part(first.output) == csv_part(again.output)
    table = rows(csv_part(first.output))
    assert len(table) == 3
    for row in table:
        assert -8 <= float(row["dot(spin)"]) < -4 and 0.25 <= float(row["r"]) < 0.35


def test_without_distributed_the_scheduler_option_says_what_to_install(monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "distributed", None)
    result = invoke("sweep", DISK, "--run", "linearize", "--grid", "m=1:2:2", "--scheduler", "tcp://x:1")
    assert result.exit_code == 1
    assert "pip install 'gacli[sweep]'" in result.output and "Traceback" not in result.output


@pytest.mark.parametrize("kwargs, said", [
    ({"random": ["theta=0:1"], "samples": 1_000_000_000}, "--samples 1000000000: more than"),
    ({"grid": ["theta=0:1:1000000000"]}, "COUNT 1000000000 is more than"),
    ({"random": ["theta=0:1"], "samples": 2, "seed": -1}, "--seed -1: a seed is a whole number"),
], ids=["samples", "grid-count", "seed"])
def test_a_plan_past_its_bounds_is_refused_before_any_point_is_made(kwargs, said):
    # A billion samples, or one axis of a billion values, filled 14 GB before the check (or none) came.
    with pytest.raises(SweepError, match=said.replace("(", r"\(")):
        plan(**kwargs)


def test_a_numpy_float_is_written_as_a_number_not_as_its_repr():
    import numpy as np

    from gacli.sweep.table import _cell

    assert _cell(np.float64(0.5)) == "0.5" and _cell(0.25) == "0.25"
