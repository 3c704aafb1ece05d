"""What ``gacli check`` reads, and the reports CI parses (issue 33, items 1 and 3; issue 32's folders).

A secret outside the checked tree is planted behind links; it must appear in
no report of any format. The JSON report is read by a strict parser, the
GitHub annotations by an independent implementation of the runner's
unescaping (actions/toolkit, ``command.ts``).
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from gacli.check import check_paths
from gacli.cli import app

ROOT = Path(__file__).resolve().parent.parent
GOOD = (ROOT / "systems" / "cylinder_in_cylinder.yaml").read_text(encoding="utf-8")
SECRET = "root:x:0:0:hunter2-SECRET"
FORMATS = ("text", "json", "github")
GENEROUS = 60  # seconds: a subprocess that takes this long is hung (a link loop), not slow


@pytest.fixture
def tree(tmp_path, monkeypatch) -> Path:
    """models/ with one good file and every kind of link out; a secret outside; cwd = tmp_path/work."""
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "passwd.yaml").write_text(f"gacli: 1\n{SECRET}\n", encoding="utf-8")
    (outside / "sub").mkdir()
    (outside / "sub" / "inner.yaml").write_text(f"gacli: 1\nname: {SECRET}\n", encoding="utf-8")
    work = tmp_path / "work"
    models = work / "models"
    (models / "deep").mkdir(parents=True)
    (models / "good.yaml").write_text(GOOD, encoding="utf-8")
    (models / "passwd.yaml").symlink_to(outside / "passwd.yaml")
    (models / "linked_dir").symlink_to(outside / "sub")
    (models / "deep" / "up.yaml").symlink_to("../../../outside/passwd.yaml")
    (models / "deep" / "loop").symlink_to("..")              # a directory loop under **
    (models / "self.yaml").symlink_to("self.yaml")           # a file link loop
    (models / "inside.yaml").symlink_to("good.yaml")         # a link that stays: followed
    monkeypatch.chdir(work)
    return work


def check(*args: str):
    return CliRunner().invoke(app, ["check", "--timeout", "30", *args])


@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("pattern", ["models", "models/", "models/*.yaml", "models/**/*.yaml", "**/*.yaml",
                                     "models/*/*.yaml"])
def test_no_link_out_of_the_tree_is_read(tree, pattern, fmt):
    result = check("--format", fmt, pattern)
    assert SECRET not in result.output and "hunter2" not in result.output
    assert "Traceback" not in result.output
    if fmt == "json":
        report = json.loads(result.stdout)
        checked = {f["path"] for f in report["files"]}
        assert checked <= {"models/good.yaml", "models/inside.yaml"}, checked
        reasons = {s["path"]: s["reason"] for s in report["skipped"]}
        for path, reason in reasons.items():
            assert "link" in reason, (path, reason)


def test_links_are_named_as_skipped_and_the_inside_link_is_checked(tree):
    report = check_paths(["models"], timeout=30)
    assert [f.path for f in report.files] == ["models/good.yaml", "models/inside.yaml"]
    skipped = {s.path: s.reason for s in report.skipped}
    assert skipped == {
        "models/deep/up.yaml": "a symbolic link that leads out of models; not followed",
        "models/passwd.yaml": "a symbolic link that leads out of models; not followed",
        "models/self.yaml": "a symbolic link loop; not followed",
    }
    assert report.exit_code == 0


def test_a_named_link_out_of_the_working_directory_is_an_error_and_not_read(tree):
    for fmt in FORMATS:
        result = check("--format", fmt, "models/passwd.yaml", "models/deep/up.yaml")
        assert result.exit_code == 1
        assert SECRET not in result.output and "leads out of the working directory" in result.output


def test_a_named_link_loop_is_an_error(tree):
    result = check("models/self.yaml")
    assert result.exit_code == 1 and "models/self.yaml:1:1: error: a symbolic link loop" in result.stderr


def test_a_link_loop_under_double_star_ends(tree):
    """In a real process, bounded by a generous timeout: the loop must not be walked until the budget."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-m", "gacli", "check", "--format", "json", "**/*.yaml"],
                          capture_output=True, text=True, timeout=GENEROUS, env=env, cwd=tree)
    assert done.returncode == 0, done.stderr
    assert len(json.loads(done.stdout)["files"]) == 2


# -- files that are not gacli files ---------------------------------------------------------------

@pytest.fixture
def repository(tmp_path, monkeypatch) -> Path:
    (tmp_path / ".github" / "workflows").mkdir(parents=True)
    (tmp_path / ".github" / "workflows" / "ci.yml").write_text("name: ci\non: push\njobs: {}\n")
    (tmp_path / "docker-compose.yml").write_text("services:\n  web: {image: nginx}\n")
    (tmp_path / "mkdocs.yaml").write_text("site_name: docs\n")
    (tmp_path / "model.yaml").write_text(GOOD)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_a_folder_skips_other_yaml_and_says_how_many(repository):
    result = check(".")
    assert result.exit_code == 0, result.output
    assert "skipped 2 files (not a gacli file: 2)" in result.stdout


def test_the_pre_commit_hook_passes_a_repository_with_other_yaml(repository):
    named = [".github/workflows/ci.yml", "docker-compose.yml", "mkdocs.yaml", "model.yaml"]
    assert check(*named).exit_code == 1  # named without the option: each is checked, as asked
    result = check("--skip-other-yaml", "--format", "json", *named)
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert [f["path"] for f in report["files"]] == ["model.yaml"]
    assert report["summary"]["skipped"] == 3


def test_a_broken_gacli_file_is_not_skipped(repository):
    (repository / "broken.yaml").write_text("gacli: 1\nname: [\n")
    result = check("--format", "json", ".")
    assert result.exit_code == 1
    assert {f["path"] for f in json.loads(result.stdout)["files"] if f["failed"]} == {"broken.yaml"}


@pytest.mark.parametrize("text", [
    "\ufeffgacli: 1\nname: [\n",                                   # a byte-order mark, as Windows editors write
    '{"gacli": 1, "name": "h", "coordinates": "x"}\n',               # JSON, or YAML's flow style
    "? gacli\n: 1\nname: h\ncoordinates: x\n",                     # an explicit key
    "&top gacli: 1\nname: h\ncoordinates: x\n",                      # an anchor
    '"g\\x61cli": 1\nname: h\ncoordinates: x\n',                 # an escape
    "  gacli: 1\n  name: h\n  coordinates: x\n",                      # the whole mapping indented
], ids=["bom", "flow", "explicit-key", "anchor", "escape", "indented"])
def test_a_broken_gacli_file_written_any_way_the_loader_reads_is_not_skipped(repository, text):
    # The gate skipped these as "not a gacli file" and passed, where derive read them and failed.
    (repository / "broken.yaml").write_bytes(text.encode("utf-8"))
    result = check("--format", "json", ".")
    assert result.exit_code == 1, result.output
    assert {f["path"] for f in json.loads(result.stdout)["files"] if f["failed"]} == {"broken.yaml"}


# -- the reports --------------------------------------------------------------------------------

def _bad_name(tmp_path: Path) -> Path:
    folder = tmp_path / "names"
    folder.mkdir()
    # Not UTF-8 (Python sees a lone surrogate), and GitHub's own syntax.
    name = os.fsdecode(b"m\xff%0A::error file=x.yaml,line=9::injected,col=1:b.yaml")
    path = folder / name
    path.write_text("gacli: 1\nname: n\nunknown: 1\n", encoding="utf-8")
    return path


def test_json_is_strict_utf8(tmp_path):
    path = _bad_name(tmp_path)
    result = CliRunner().invoke(app, ["check", "--format", "json", str(path.parent)])
    raw = result.stdout_bytes
    data = json.loads(raw.decode("utf-8", errors="strict"), strict=True)
    # Python's parser accepts an escaped lone surrogate (jq does not); it comes back as one.
    json.dumps(data, ensure_ascii=False).encode("utf-8", errors="strict")
    assert data["files"][0]["path"].endswith(":b.yaml") and "\\udcff" in data["files"][0]["path"]
    jq = shutil.which("jq")
    if jq:
        done = subprocess.run([jq, ".files[0].path"], input=raw, capture_output=True)
        assert done.returncode == 0, done.stderr


def _unescape_property(text: str) -> str:
    # actions/toolkit's toCommandProperties escaping, undone.
    return text.replace("%2C", ",").replace("%3A", ":").replace("%0A", "\n").replace("%0D", "\r").replace("%25", "%")


def _parse_command(line: str) -> tuple[str, dict[str, str], str]:
    """``::name key=value,key=value::message`` as the runner splits it."""
    match = re.fullmatch(r"::(\w+)(?: ([^:]*))?::(.*)", line)
    assert match, line
    properties = dict(item.split("=", 1) for item in (match[2] or "").split(",") if item)
    return match[1], {k: _unescape_property(v) for k, v in properties.items()}, match[3]


def test_github_properties_are_escaped_as_github_documents(tmp_path):
    path = _bad_name(tmp_path)
    result = CliRunner().invoke(app, ["check", "--format", "github", str(path.parent)])
    lines = result.stdout.splitlines()
    assert lines and all(line.startswith("::error ") for line in lines), lines
    for line in lines:
        command, properties, _ = _parse_command(line)
        assert command == "error"
        assert set(properties) == {"file", "line", "col", "title"}, properties
        # The location is the file's own: the name's ",line=9" and "::error" are text in it.
        assert properties["file"] == str(path).encode("utf-8", "backslashreplace").decode(), properties
        assert properties["line"].isdigit() and properties["col"].isdigit()
    assert any("line=3," in line and "unknown key" in line for line in lines)


def test_a_long_file_name_stays_whole_in_its_annotation(tmp_path):
    folder = tmp_path / ("d" * 200)
    folder.mkdir()
    path = folder / ("n" * 200 + ".yaml")
    path.write_text("gacli: 1\nname: n\nunknown: 1\n", encoding="utf-8")
    result = CliRunner().invoke(app, ["check", "--format", "github", str(path)])
    for line in result.stdout.splitlines():
        assert _parse_command(line)[1]["file"] == str(path)


def _many_errors(tmp_path: Path) -> Path:
    path = tmp_path / "many.yaml"
    path.write_text(GOOD.replace("  - a*dphi", "  - __x\n" * 3000 + "  - a*dphi"), encoding="utf-8")
    return path


@pytest.mark.parametrize("fmt", FORMATS)
def test_a_report_stops_after_a_hundred_problems_per_file_and_says_how_many_more(tmp_path, fmt):
    path = _many_errors(tmp_path)
    result = CliRunner().invoke(app, ["check", "--format", fmt, str(path)])
    assert result.exit_code == 1
    assert result.output.count("name '__x' contains '__'") == 100
    assert "2900 more problems not shown" in result.output
    assert len(result.output) < 40_000
