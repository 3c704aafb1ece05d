"""``gacli sweep``: ``simulate`` or ``linearize`` over a grid or a random sample, derived once.

.. code:: text

    plan      the points: --grid NAME=START:STOP:COUNT (a product) or
              --random NAME=LOW:HIGH with --samples and --seed
    work      one point as a row: the eigenvalues of A (linearize), or the
              final state, energy drift and constraint residual (simulate)
    execute   where the points run: here, --jobs N local processes, or a
              Dask cluster (--scheduler ADDRESS); rows in the plan's order
    table     one table: CSV, or Parquet with pyarrow

The derivation is made once by the command and sent to each worker once;
each worker imports the generated module once (docs/sweep.md).
"""

from gacli.sweep.execute import require_distributed, run
from gacli.sweep.options import task_for
from gacli.sweep.plan import Plan, SweepError, classify, plan
from gacli.sweep.table import Table, check_path, table, to_csv, write
from gacli.sweep.work import MODES, Job, Task, columns, resolved_parameters, run_point

__all__ = [
    "MODES", "Job", "Plan", "SweepError", "Table", "Task", "check_path", "classify", "columns", "plan",
    "require_distributed", "resolved_parameters", "run", "run_point", "table", "task_for", "to_csv", "write",
]
