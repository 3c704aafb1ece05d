"""How long `gacli derive` prints, for systems written with frames and by hand (issue #17).

Each system written in the frame vocabulary is paired with its format-1 twin
(`NAME_format1.yaml`, written by hand: positions in N, rotation forms,
rolling rows derived on paper; same coordinates, parameters and independent
rates). The issue asks that the vocabulary print within 1.5 x its twin, and
under 5,000 characters where there is no twin. `tests/twins/` holds the pairs
the tests check; `benchmarks/corpus/` a wider set of robots on wheels and
rolling bodies kept for measurement only (each twin was checked to give the
same M and F at random states when it was written).

Usage::

    python benchmarks/bench_compact.py                       # tests/twins and benchmarks/corpus
    python benchmarks/bench_compact.py benchmarks/corpus --json compact.json
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from typer.testing import CliRunner

from gacli.cli import app

ROOT = Path(__file__).resolve().parent.parent
FOLDERS = (ROOT / "tests" / "twins", ROOT / "benchmarks" / "corpus")


def printed(path: Path) -> tuple[int, float]:
    """(characters of `gacli derive PATH`, CPU seconds)."""
    start = time.process_time()
    result = CliRunner().invoke(app, ["derive", str(path)])
    if result.exit_code != 0:
        raise SystemExit(f"{path}: {result.output}")
    return len(result.output), time.process_time() - start


def rows(folder: Path) -> list[dict]:
    out = []
    for path in sorted(p for p in folder.glob("*.yaml") if not p.stem.endswith("_format1")):
        chars, seconds = printed(path)
        twin = folder / f"{path.stem}_format1.yaml"
        twin_chars = printed(twin)[0] if twin.exists() else None
        out.append({"system": f"{folder.name}/{path.stem}", "chars": chars, "twin": twin_chars,
                    "seconds": round(seconds, 2)})
    return out


def verdict(row: dict) -> str:
    if row["twin"] is not None:
        ratio = row["chars"] / row["twin"]
        return f"{ratio:.2f} x twin, {'ok' if ratio <= 1.5 else 'OVER'}"
    return "ok (< 5,000)" if row["chars"] < 5_000 else "OVER 5,000, no twin"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folders", nargs="*", type=Path, default=list(FOLDERS))
    parser.add_argument("--json", type=Path, help="also save the rows here")
    options = parser.parse_args(argv)
    table = [row for folder in options.folders for row in rows(folder)]
    print("| system | printed | its twin | s CPU | verdict |\n|:--|--:|--:|--:|:--|")
    for row in table:
        twin = f"{row['twin']:,}" if row["twin"] is not None else ""
        print(f"| {row['system']} | {row['chars']:,} | {twin} | {row['seconds']} | {verdict(row)} |")
    if options.json:
        options.json.write_text(json.dumps(table, indent=1), encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
