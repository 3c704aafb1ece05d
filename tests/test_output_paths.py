"""Where ``--output`` writes, for every format, and how a failing or special target is met.

The rule (gacli/output.py, docs/generated-code.md): a trailing ``/`` or an
existing directory means a directory, anything else a file; a format that
writes several files takes a file name only when it is one of them. Only
regular files are written; every file-system failure is one message naming
the path; several files are written all or none.
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path

import pytest
from typer.testing import CliRunner

import gacli.output as output
from gacli.cli import app
from gacli.emit import EMITTERS

ROOT = Path(__file__).resolve().parent.parent
SYSTEM = ROOT / "systems" / "cylinder_in_cylinder.yaml"
NAME = "cylinder_in_cylinder"
FORMATS = sorted(EMITTERS)
# What each format writes, as docs/generated-code.md and docs/fmu.md name the files.
WRITES = {
    "c": [f"{NAME}.c", f"{NAME}.h"],
    "fmu": [f"{NAME}.fmu"],
    "jax": [f"{NAME}_jax.py"],
    "latex": [f"{NAME}.tex"],
    "octave": [f"{NAME}_defaults.m", f"{NAME}_forcing.m", f"{NAME}_indices.m", f"{NAME}_mass_matrix.m", f"{NAME}_rhs.m"],
    "python": [f"{NAME}.py"],
}
SINGLE = [f for f in FORMATS if len(WRITES[f]) == 1]
SEVERAL = [f for f in FORMATS if len(WRITES[f]) > 1]


@pytest.fixture(autouse=True)
def _no_compiler(monkeypatch, tmp_path):
    # The FMU is built with its C sources only: placement is what is tested, not a compiler.
    monkeypatch.delenv("CC", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path / "no-compilers"))


def derive(fmt: str, target: str | Path):
    return CliRunner().invoke(app, ["derive", str(SYSTEM), "--format", fmt, "--output", str(target)])


def one_message(result, *parts: str) -> None:
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
    assert len(errors) == 1, result.stderr
    for part in parts:
        assert part in errors[0], errors[0]


def test_every_format_is_listed_here():
    assert set(WRITES) == set(EMITTERS)


# -- the rule ------------------------------------------------------------------------------

@pytest.mark.parametrize("fmt", FORMATS)
def test_a_trailing_slash_makes_a_directory(fmt, tmp_path):
    result = derive(fmt, f"{tmp_path}/new/")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in (tmp_path / "new").iterdir()) == WRITES[fmt]


@pytest.mark.parametrize("fmt", FORMATS)
def test_an_existing_directory_receives_the_files(fmt, tmp_path):
    (tmp_path / "build").mkdir()
    result = derive(fmt, tmp_path / "build")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in (tmp_path / "build").iterdir()) == WRITES[fmt]


@pytest.mark.parametrize("fmt", SINGLE)
def test_any_other_name_is_the_file(fmt, tmp_path):
    target = tmp_path / "sub" / "chosen.out"
    result = derive(fmt, target)
    assert result.exit_code == 0, result.output
    assert target.is_file() and [p.name for p in target.parent.iterdir()] == ["chosen.out"]


@pytest.mark.parametrize("fmt", SEVERAL)
def test_several_files_go_beside_the_one_named(fmt, tmp_path):
    first = WRITES[fmt][0]
    result = derive(fmt, tmp_path / first)
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == WRITES[fmt]


@pytest.mark.parametrize("fmt", SEVERAL)
def test_several_files_never_make_a_directory_of_a_file_name(fmt, tmp_path):
    name = "disk" + WRITES[fmt][0][-2:]  # ends as the format's files do, but is none of them
    result = derive(fmt, tmp_path / name)
    one_message(result, name, f"{len(WRITES[fmt])} files", "trailing /")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("fmt", SEVERAL)
def test_a_name_none_of_the_files_can_have_is_a_usage_error_before_the_work(fmt, tmp_path, monkeypatch):
    # A reviewer's --output build/nodir was refused after a 12 s derivation, with exit 1.
    import gacli.pipeline

    monkeypatch.setattr(gacli.pipeline, "run", lambda *a, **k: pytest.fail("derived before refusing"))
    result = derive(fmt, tmp_path / "nodir")
    assert result.exit_code == 2, result.output
    assert "several files" in result.output and "trailing /" in result.output
    assert list(tmp_path.iterdir()) == []


def test_simulate_csv_into_a_directory(tmp_path):
    pytest.importorskip("scipy")
    result = CliRunner().invoke(app, ["simulate", str(SYSTEM), "--t-end", "0.1", "--points", "3",
                                      "--csv", f"{tmp_path}/results/"])
    assert result.exit_code == 0, result.output
    assert [p.name for p in (tmp_path / "results").iterdir()] == [f"{NAME}.csv"]
    named = CliRunner().invoke(app, ["simulate", str(SYSTEM), "--t-end", "0.1", "--points", "3",
                                     "--csv", str(tmp_path / "run.csv")])
    assert named.exit_code == 0 and (tmp_path / "run.csv").read_text().startswith("t,theta,phi")


# -- special targets -------------------------------------------------------------------------

def _fifo(tmp_path: Path) -> Path:
    path = tmp_path / "pipe"
    os.mkfifo(path)
    return path


def _link_to_null(tmp_path: Path) -> Path:
    path = tmp_path / "null"
    path.symlink_to("/dev/null")
    return path


SPECIAL = {"device": lambda tmp: Path("/dev/null"), "fifo": _fifo, "link-to-device": _link_to_null}


@pytest.mark.parametrize("kind", sorted(SPECIAL))
@pytest.mark.parametrize("fmt", SINGLE)
def test_a_device_fifo_or_link_to_one_is_refused(fmt, kind, tmp_path):
    target = SPECIAL[kind](tmp_path)
    result = derive(fmt, target)  # a FIFO opened for writing would block: refused before opening
    one_message(result, str(target), "not a regular file")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


def test_simulate_refuses_a_device_for_its_csv(tmp_path):
    pytest.importorskip("scipy")
    result = CliRunner().invoke(app, ["simulate", str(SYSTEM), "--t-end", "0.1", "--points", "3",
                                      "--csv", "/dev/null"])
    one_message(result, "/dev/null", "not a regular file")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


@pytest.mark.parametrize("fmt", FORMATS)
def test_a_parent_that_is_a_file_is_one_message(fmt, tmp_path):
    (tmp_path / "plain").write_text("x")
    one_message(derive(fmt, tmp_path / "plain" / "deeper" / WRITES[fmt][0]), "plain is a file, not a directory")
    one_message(derive(fmt, f"{tmp_path}/plain/deeper/"), "plain is a file, not a directory")
    one_message(derive(fmt, f"{tmp_path}/plain/"), "not a directory")


@pytest.mark.parametrize("fmt", ["python", "c"])
def test_a_place_the_system_refuses_is_one_message(fmt, tmp_path):
    one_message(derive(fmt, "/proc/gacli-test/"), "/proc/gacli-test")
    one_message(derive(fmt, f"/proc/{WRITES[fmt][0]}"), f"/proc/{WRITES[fmt][0]}", "cannot write")


def test_a_read_only_directory_is_one_message(tmp_path, monkeypatch):
    # Root writes into a 0555 directory, so the refusal is the system call's, made to fail here.
    def refuse(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr(output.tempfile, "mkstemp", refuse)
    target = tmp_path / "x.py"
    one_message(derive("python", target), str(target), "Permission denied")
    assert list(tmp_path.iterdir()) == []


# -- all or none -----------------------------------------------------------------------------

def _old_pair(tmp_path: Path) -> dict[Path, str]:
    old = {tmp_path / name: f"old {name}\n" for name in WRITES["c"]}
    for path, text in old.items():
        path.write_text(text)
    return old


def test_a_full_disk_leaves_the_c_pair_as_it_was(tmp_path, monkeypatch):
    old = _old_pair(tmp_path)
    real, calls = output._write, []

    def write(temporary, text, mode):
        calls.append(temporary)
        if len(calls) == 2:
            raise OSError(errno.ENOSPC, "No space left on device")
        real(temporary, text, mode)

    monkeypatch.setattr(output, "_write", write)
    result = derive("c", f"{tmp_path}/")
    one_message(result, "No space left on device", "no file was changed")
    assert {p: p.read_text() for p in tmp_path.iterdir()} == old  # and no temporary left behind


def test_a_failed_rename_puts_back_the_files_already_replaced(tmp_path, monkeypatch):
    old = _old_pair(tmp_path)
    real, renamed = os.replace, []

    def replace(source, target):
        if Path(target).suffix == ".h":
            raise OSError(errno.EIO, "Input/output error")
        renamed.append(target)
        real(source, target)

    monkeypatch.setattr(output.os, "replace", replace)
    result = derive("c", f"{tmp_path}/")
    one_message(result, "Input/output error")
    assert renamed, "the .c was renamed before the .h failed"
    assert {p: p.read_text() for p in tmp_path.iterdir()} == old


def test_new_files_are_removed_when_a_later_one_fails(tmp_path, monkeypatch):
    real = os.replace

    def replace(source, target):
        if Path(target).name.endswith("_rhs.m"):
            raise OSError(errno.EIO, "Input/output error")
        real(source, target)

    monkeypatch.setattr(output.os, "replace", replace)
    one_message(derive("octave", f"{tmp_path}/out/"), "Input/output error")
    assert list((tmp_path / "out").iterdir()) == []


@pytest.mark.parametrize("args, where", [
    (["derive", str(SYSTEM), "--output"], "{long}.txt"),
    (["derive", str(SYSTEM), "--format", "c", "--output"], "{long}/"),
    (["simulate", str(ROOT / "systems" / "particle_in_plane.yaml"), "--input", "R=0,S=0", "--t-end", "0.1",
      "--csv"], "{long}.csv"),
], ids=["text", "c", "csv"])
def test_a_name_longer_than_the_file_system_takes_is_one_message(tmp_path, args, where):
    # OSError: [Errno 36] File name too long, from Path.is_dir, as a traceback.
    target = tmp_path / where.format(long="a" * 300)
    result = CliRunner().invoke(app, [*args, str(target)])
    assert result.exit_code == 1, result.output
    assert "cannot write: File name too long" in result.output and "Traceback" not in result.output


@pytest.mark.parametrize("args", [["derive", "{f}", "--output", "{f}"], ["derive", "{f}", "--output", "{link}"],
                                  ["simulate", "{f}", "--input", "R=0,S=0", "--t-end", "0.1", "--csv", "{f}"]],
                         ids=["derive", "derive-through-a-link", "simulate-csv"])
def test_the_system_file_itself_is_never_the_output(tmp_path, args):
    # derive f.yaml --output f.yaml replaced the system file with its own printout.
    source = tmp_path / "particle.yaml"
    source.write_bytes((ROOT / "systems" / "particle_in_plane.yaml").read_bytes())
    before = source.read_bytes()
    (tmp_path / "link.yaml").symlink_to(source)
    result = CliRunner().invoke(app, [a.format(f=source, link=tmp_path / "link.yaml") for a in args])
    assert result.exit_code == 1, result.output
    assert "is the system file this command reads" in result.output
    assert source.read_bytes() == before


def test_the_table_and_the_plot_to_one_file_is_a_usage_error(tmp_path):
    # simulate --csv o.png --plot o.png wrote the table, then the plot over it, and said 'wrote o.png' twice.
    target = tmp_path / "o.png"
    result = CliRunner().invoke(app, ["simulate", str(ROOT / "systems" / "particle_in_plane.yaml"), "--input",
                                      "R=0,S=0", "--t-end", "0.1", "--csv", str(target), "--plot", str(target)])
    assert result.exit_code == 2, result.output
    assert "is also --csv" in result.output and not target.exists()


def test_a_folder_output_never_writes_over_the_system_file_it_read(tmp_path):
    """The input named pend.c, '-f c -o folder/' (NAME.c and NAME.h) replaced it with generated C, exit 0."""
    source = (Path(__file__).resolve().parent.parent / "systems" / "cylinder_in_cylinder.yaml").read_text()
    path = tmp_path / "cylinder_in_cylinder.c"
    path.write_text(source, encoding="utf-8")
    result = CliRunner().invoke(app, ["derive", str(path), "--format", "c", "--output", f"{tmp_path}/"])
    assert result.exit_code == 1, result.output
    assert "is the system file this command reads" in result.output
    assert path.read_text() == source and not (tmp_path / "cylinder_in_cylinder.h").exists()


@pytest.mark.parametrize("args", [["derive", str(SYSTEM), "--output", "-"],
                                  ["derive", str(SYSTEM), "-f", "python", "-o", "-"],
                                  ["sweep", str(SYSTEM), "--run", "linearize", "--grid", "g=9:10:2", "-o", "-"]],
                         ids=["derive-text", "derive-python", "sweep"])
def test_a_dash_output_is_standard_output_as_a_dash_file_is_standard_input(tmp_path, monkeypatch, args):
    # '-o -' wrote a file named '-' in the working directory.
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert not (tmp_path / "-").exists() and list(tmp_path.iterdir()) == []
    assert ("M" in result.output) if args[0] == "derive" else ("g,max_real" in result.output)


def test_an_fmu_to_standard_output_is_refused_before_the_work(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(app, ["derive", str(SYSTEM), "-f", "fmu", "-o", "-"])
    assert result.exit_code == 2 and "an FMU is a zip file" in result.output and list(tmp_path.iterdir()) == []
