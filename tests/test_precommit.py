"""The README's pre-commit snippet, used as written, on a temporary git repository.

Without network, two substitutions and nothing else (docs/pre-commit.md says
why): the snippet's ``repo`` URL becomes a local git repository made from
this checkout's files, in which the test creates the tag the snippet names
(its ``rev``, as written); and pre-commit's virtualenv sees this Python's
site-packages with pip's index off, so that installing the hook finds
gacli's dependencies here instead of downloading them.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys

import pytest
import yaml

from conftest import ROOT, SYSTEMS

HOOK_REPO = "https://github.com/OWNER/gacli"
SHIPPED = ("gacli", "pyproject.toml", "README.md", ".pre-commit-hooks.yaml")
SYSTEM_FILES = ("cylinder_in_cylinder.yaml", "particle_in_plane.yaml")


def readme_snippet() -> str:
    """The pre-commit block of the README, as written."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```yaml\n(repos:\n.*?)```", text, re.S)
    (block,) = [b for b in blocks if "gacli-check" in b]
    return block


def test_the_snippets_rev_is_this_version():
    from gacli.version import __version__

    (repo,) = yaml.safe_load(readme_snippet())["repos"]
    assert repo["repo"] == HOOK_REPO
    assert repo["rev"] == f"v{__version__}"   # docs/release.md: the tag of a release is v + gacli.version
    assert [h["id"] for h in repo["hooks"]] == ["gacli-check"]


def test_the_hook_is_given_yaml_files():
    (hook,) = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    assert hook["id"] == "gacli-check" and hook["language"] == "python"
    assert hook["entry"] == "gacli check --skip-other-yaml"  # every YAML file: gacli check keeps its own
    assert hook["types"] == ["yaml"]


def git(*args: str, cwd) -> None:
    subprocess.run(["git", *args], cwd=cwd, check=True, capture_output=True, text=True,
                   env={**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@example.com",
                        "GIT_COMMITTER_NAME": "t", "GIT_COMMITTER_EMAIL": "t@example.com"})


@pytest.fixture(scope="module")
def hooked(tmp_path_factory):
    """A repository of two system files with the README's snippet; returns (folder, run)."""
    pytest.importorskip("pre_commit")
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    base = tmp_path_factory.mktemp("precommit")
    snippet = readme_snippet()
    rev = yaml.safe_load(snippet)["repos"][0]["rev"]

    hooks = base / "gacli"     # stands for the hosted repository at the release tag
    for name in SHIPPED:
        source = ROOT / name
        copy = shutil.copytree if source.is_dir() else shutil.copy2
        copy(source, hooks / name, **({"ignore": shutil.ignore_patterns("__pycache__")} if source.is_dir() else {}))
    git("init", "-q", cwd=hooks)
    git("add", "-A", cwd=hooks)
    git("commit", "-q", "-m", "release", cwd=hooks)
    git("tag", rev, cwd=hooks)

    user = base / "user"
    user.mkdir()
    for name in SYSTEM_FILES:
        shutil.copy2(SYSTEMS / name, user / name)
    (user / ".pre-commit-config.yaml").write_text(snippet.replace(HOOK_REPO, str(hooks)), encoding="utf-8")
    git("init", "-q", cwd=user)
    git("add", "-A", cwd=user)

    environment = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    environment.update(PRE_COMMIT_HOME=str(base / "cache"), VIRTUALENV_SYSTEM_SITE_PACKAGES="1",
                       PIP_NO_INDEX="1", PIP_NO_BUILD_ISOLATION="0", PIP_DISABLE_PIP_VERSION_CHECK="1")

    def run(*files: str) -> subprocess.CompletedProcess:
        # The files named: .pre-commit-config.yaml is YAML too, and is not a gacli file.
        return subprocess.run([sys.executable, "-m", "pre_commit", "run", "--files", *files], cwd=user,
                              env=environment, capture_output=True, text=True, timeout=600)

    return user, run


def test_the_snippet_as_written_passes_good_system_files(hooked):
    user, run = hooked
    done = run(*SYSTEM_FILES)
    assert done.returncode == 0, done.stdout + done.stderr
    assert re.search(r"gacli check\.+Passed", done.stdout), done.stdout


def test_the_snippet_as_written_fails_a_broken_system_file(hooked):
    user, run = hooked
    broken = user / "broken.yaml"
    broken.write_text((SYSTEMS / SYSTEM_FILES[0]).read_text().replace("coordinates:", "coordinatez:", 1))
    git("add", "broken.yaml", cwd=user)
    done = run("broken.yaml", *SYSTEM_FILES)
    assert done.returncode == 1, done.stdout + done.stderr
    assert re.search(r"gacli check\.+Failed", done.stdout)
    assert "broken.yaml" in done.stdout and "coordinatez" in done.stdout


def test_the_snippet_as_written_skips_other_yaml(hooked):
    """A CI workflow and pre-commit's own config are YAML handed to the hook: skipped, not failed."""
    user, run = hooked
    workflow = user / "workflow.yml"
    workflow.write_text("on: push\njobs:\n  test:\n    runs-on: ubuntu-latest\n", encoding="utf-8")
    git("add", "workflow.yml", cwd=user)
    done = run("workflow.yml", ".pre-commit-config.yaml", *SYSTEM_FILES)
    assert done.returncode == 0, done.stdout + done.stderr
    assert re.search(r"gacli check\.+Passed", done.stdout), done.stdout
