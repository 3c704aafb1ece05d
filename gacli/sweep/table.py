"""A sweep's table, one row per point: CSV always, Parquet when pyarrow is installed.

CSV floats are written in shortest round-trip form (``repr``), NaN as
``nan``, booleans as ``true``/``false``: pandas, polars and a spreadsheet all
read them back exactly. A path ending in ``.parquet`` is written with
pyarrow (float64, bool and string columns), an optional extra
(``pip install 'gacli[parquet]'``). Either file is written to a temporary name and renamed.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from gacli.sweep.plan import SweepError

FORMATS = (".csv", ".parquet")


@dataclass(frozen=True)
class Table:
    """The header and the rows: swept values, then results (numbers, a bool, the error text)."""

    columns: tuple[str, ...]
    rows: tuple[tuple, ...]

    def column(self, name: str) -> list:
        index = self.columns.index(name)
        return [row[index] for row in self.rows]


def table(columns: Sequence[str], points: Sequence[Sequence[float]], results: Sequence[Sequence]) -> Table:
    return Table(tuple(columns), tuple((*point, *result) for point, result in zip(points, results)))


def check_path(path: Path) -> None:
    """Fail before any work when the table cannot be written to ``path``."""
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise SweepError(f"--output {path}: the table is a .csv or a .parquet file")
    if suffix == ".parquet":
        _pyarrow()


def to_csv(table: Table) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(table.columns)
    for row in table.rows:
        writer.writerow([_cell(v) for v in row])
    return buffer.getvalue()


def _cell(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(float(value))  # NumPy 2's float64 is a float whose repr is 'np.float64(...)'
    return str(value)


def write(table: Table, path: Path) -> Path:
    """Write ``table`` to ``path`` (.csv or .parquet) atomically; returns the path."""
    from gacli.output import atomic_path, write_files

    path = Path(path)
    check_path(path)
    if path.suffix.lower() == ".csv":
        return write_files({path.name: to_csv(table)}, path)[0]
    pyarrow, parquet = _pyarrow()
    data = {name: table.column(name) for name in table.columns}
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path) as tmp:
        parquet.write_table(pyarrow.table(data), str(tmp))
    return path


def _pyarrow():
    try:
        import pyarrow
        import pyarrow.parquet
    except ImportError:
        raise SweepError("a .parquet table needs pyarrow, which is not installed: pip install 'gacli[parquet]' "
                         "(or write a .csv)") from None
    return pyarrow, pyarrow.parquet
