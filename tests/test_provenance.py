"""Free text from a system file (its name, its title) cannot become live code in generated files."""

from __future__ import annotations

import ast

from conftest import SYSTEMS
from gacli.api import emit
from gacli.mechanics.equations import derive
from gacli.loader.loading import load


def hostile_copy(tmp_path):
    text = (SYSTEMS / "cylinder_in_cylinder.yaml").read_text()
    text = text.replace("title: Cylinder rolling without slipping inside a fixed cylinder",
                        'title: "end */ int evil; /*\\nimport os\\n\\\\input{/etc/passwd}"')
    path = tmp_path / "a\nimport os\n\\input{x}.yaml"
    path.write_text(text)
    return derive(load(path))


def test_generated_python_has_no_injected_line(tmp_path):
    text = emit(hostile_copy(tmp_path), "python")["cylinder_in_cylinder.py"]
    ast.parse(text)
    assert not any(line.startswith(("import os", "\\input")) for line in text.splitlines())


def test_generated_c_comment_cannot_be_closed(tmp_path):
    files = emit(hostile_copy(tmp_path), "c")
    for text in files.values():
        header = text.split("*/", 1)[0]
        assert "int evil" not in text.split("*/", 1)[1]
        assert "\nimport os" not in header


def test_latex_comment_cannot_start_live_tex(tmp_path):
    text = emit(hostile_copy(tmp_path), "latex", standalone=True)["cylinder_in_cylinder.tex"]
    assert not any(line.startswith(("\\input", "import os")) for line in text.splitlines())
