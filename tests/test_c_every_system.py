"""The generated C of every valid system file in the repository compiles strictly (issue #33).

Every file of systems/, of tests/ that gacli accepts (tests/hostile/ and
tests/invalid/ are refused on purpose) and of benchmarks/corpus/ is derived
to C once, and each translation unit compiled
by gcc and clang with ``-std=c99 -Wall -Wextra -Werror -pedantic``: a dead
temporary, an unused argument or a non-C99 construct in any of them fails.

The derivations run in two worker processes (each imports gacli once and
derives its half of the files); the compilations run two at a time. Without
a compiler the test skips. The constraint forces (``--reactions``) are
compiled for systems/ by tests/test_emit_c.py and for tests/accepted_hostile/
by tests/test_hostile_commands.py: here they would double the run.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from conftest import require_tool

ROOT = Path(__file__).resolve().parent.parent
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
FOLDERS = ["systems", "tests/accepted_hostile", "tests/cases", "tests/frames", "tests/twins", "benchmarks/corpus",
           "benchmarks/cases"]
FILES = sorted(path for folder in FOLDERS for path in (ROOT / folder).glob("*.yaml"))
WORKERS = 2

# Derives its files to C, one folder each, and prints {file: exit code and output} as JSON.
_DERIVE = """
import json, sys
from pathlib import Path
from typer.testing import CliRunner
from gacli.cli import app
out, files = Path(sys.argv[1]), sys.argv[2:]
done = {}
for i, name in enumerate(files):
    folder = out / Path(name).parent.name / Path(name).stem
    result = CliRunner().invoke(app, ["derive", "--format", "c", "--output", f"{folder}/", name])
    done[name] = [result.exit_code, result.output[-2000:]]
print(json.dumps(done))
"""


def test_the_set_is_the_repository_s_valid_files():
    assert len(FILES) > 60
    assert not {p.parent.name for p in FILES} & {"hostile", "invalid"}


@pytest.fixture(scope="module")
def generated(tmp_path_factory) -> tuple[Path, dict]:
    out = tmp_path_factory.mktemp("c_every_system")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    halves = [[str(p) for p in FILES[i::WORKERS]] for i in range(WORKERS)]
    workers = [subprocess.Popen([sys.executable, "-c", _DERIVE, str(out), *half], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, env=env) for half in halves]
    done: dict = {}
    for worker in workers:
        stdout, stderr = worker.communicate(timeout=1800)
        assert worker.returncode == 0, stderr[-3000:]
        done.update(json.loads(stdout))
    return out, done


def test_every_file_derives_to_c(generated):
    _, done = generated
    failed = {name: output for name, (code, output) in done.items() if code != 0}
    assert not failed, failed


@pytest.mark.parametrize("compiler", ["gcc", "clang"])
def test_every_translation_unit_compiles_strictly(compiler, generated):
    path = require_tool(compiler)
    out, _ = generated
    sources = sorted(out.glob("*/*/*.c"))
    assert len(sources) == len(FILES)

    def build(source: Path) -> tuple[str, str]:
        done = subprocess.run([path, *STRICT, "-c", source.name, "-o", os.devnull], cwd=source.parent,
                              capture_output=True, text=True, timeout=600)
        return str(source.relative_to(out)), done.stderr if done.returncode or done.stderr else ""

    with ThreadPoolExecutor(WORKERS) as pool:
        failures = {name: error for name, error in pool.map(build, sources) if error}
    assert not failures, "\n".join(f"{name}:\n{error[-1500:]}" for name, error in failures.items())
