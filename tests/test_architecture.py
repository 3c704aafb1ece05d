"""The shape of the package (issue #20): stages in the order data flows, no circle, short rooms.

The stage order is read from docs/architecture.md (its ``stages`` block), so
the map and this test cannot drift apart: a module that is not on the map, or
an import from a lower stage to a higher one, fails here with its name.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "gacli"
MAP = ROOT / "docs" / "architecture.md"
MAX_MODULE_LINES = 400
MAX_FUNCTION_LINES = 50


def _modules() -> dict[str, Path]:
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        name = ".".join(path.relative_to(ROOT).with_suffix("").parts)
        out[name.removesuffix(".__init__")] = path
    return out


MODULES = _modules()


def _stages() -> list[tuple[str, tuple[str, ...]]]:
    """[(stage, (module or package prefixes...))], lowest first, from the map's ``stages`` block."""
    block = re.search(r"```stages\n(.*?)```", MAP.read_text(encoding="utf-8"), re.S)
    assert block, "docs/architecture.md has no ```stages block"
    rows = [line.split() for line in block.group(1).splitlines() if line.strip() and not line.startswith("#")]
    return [(row[0], tuple(row[1:])) for row in rows]


STAGES = _stages()


def stage_of(module: str) -> int | None:
    """The rank of the stage whose prefix matches ``module`` most closely."""
    best, rank = -1, None
    for i, (_, prefixes) in enumerate(STAGES):
        for prefix in prefixes:
            matches = module == prefix or (prefix != "gacli" and module.startswith(prefix + "."))
            if matches and len(prefix) > best:
                best, rank = len(prefix), i
    return rank


def _resolve(target: str) -> str | None:
    while target and target not in MODULES:
        target = target.rpartition(".")[0]
    return target or None


def imports_of(module: str) -> set[str]:
    """Every gacli module ``module`` imports, at any depth of its code (lazy imports count)."""
    path = MODULES[module]
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[: len(parts) - node.level + 1] + ([base] if base else []))
            targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in MODULES else base for a in node.names]
        else:
            continue
        out |= {t for t in map(_resolve, targets) if t and t.startswith("gacli") and t != module}
    return out


GRAPH = {m: imports_of(m) for m in MODULES}


@pytest.mark.parametrize("module", sorted(MODULES))
def test_every_module_is_on_the_map(module):
    assert stage_of(module) is not None, f"{module} belongs to no stage of docs/architecture.md"


@pytest.mark.parametrize("module", sorted(MODULES))
def test_no_import_goes_up_the_pipeline(module):
    own = stage_of(module)
    upward = sorted(t for t in GRAPH[module] if (stage_of(t) or 0) > (own or 0))
    names = [f"{t} ({STAGES[stage_of(t)][0]})" for t in upward]
    assert not upward, f"{module} ({STAGES[own][0]}) imports a later stage: {', '.join(names)}"


def test_the_imports_have_no_circle():
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    circles = []

    def visit(v: str) -> None:  # Tarjan's strongly connected components
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in GRAPH[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                circles.append(sorted(component))

    for module in sorted(GRAPH):
        if module not in index:
            visit(module)
    assert not circles, f"import circles: {circles}"


@pytest.mark.parametrize("module", sorted(MODULES))
def test_rooms_are_short(module):
    """No module over 400 lines, no function over 50 (its docstring aside)."""
    text = MODULES[module].read_text(encoding="utf-8")
    assert text.count("\n") + 1 <= MAX_MODULE_LINES, f"{module} has {text.count(chr(10)) + 1} lines"
    long = []
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            length = node.end_lineno - node.lineno + 1
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str):
                length -= first.end_lineno - first.lineno + 1
            if length > MAX_FUNCTION_LINES:
                long.append(f"{node.name} ({length} lines)")
    assert not long, f"{module}: {', '.join(long)}"


def test_the_map_names_only_what_exists():
    for stage, prefixes in STAGES:
        for prefix in prefixes:
            assert prefix in MODULES, f"docs/architecture.md's stage {stage} names {prefix}, which does not exist"
