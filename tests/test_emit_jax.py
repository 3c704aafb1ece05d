"""The generated JAX module: pure jax.numpy, under jit, vmap and grad.

The reference is the generated Python module (checked against SymPy in
test_generated_numeric.py): for every system in systems/ and the tests'
own, ``jax.jit(rhs)`` at seeded random states and ``jax.vmap(rhs)`` over a
batch of 64 states agree with it to 1e-12 relative (float64 enabled, as
the module's docstring tells users to). ``jax.grad`` through the rhs of the
rolling disk equals a central finite difference.
"""

from __future__ import annotations

import ast
import importlib.util
import os

import numpy as np
import pytest

from conftest import SYSTEMS
from gacli.emit.jax import emit_jax
from test_emit_octave import case
from test_emit_python import EXTRA, write_python
from test_generated_numeric import RTOL, close, derivation, random_states

try:
    import jax
except ImportError:
    if os.environ.get("CI"):  # the test extra installs JAX: CI must run these tests
        raise
    pytest.skip("jax is not installed (pip install gacli[jax])", allow_module_level=True)
jax.config.update("jax_enable_x64", True)
jnp = jax.numpy

CASES = sorted(p.stem for p in SYSTEMS.glob("*.yaml")) + sorted(EXTRA) + ["octave_words"]
BATCH = 64


def write_jax(d, directory):
    ((name, text),) = emit_jax(d).items()
    path = directory / name
    path.write_text(text, encoding="utf-8")
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("name", CASES)
def test_jit_and_vmap_agree_with_the_python_module(name, tmp_path):
    d = case(name)
    module, reference = write_jax(d, tmp_path), write_python(d, tmp_path)
    states = list(random_states(d, 3000 + CASES.index(name)))
    # One compilation (of rhs): the bicycle's takes most of a minute. M and F run op by op.
    rhs = jax.jit(module.rhs)
    for seed, (t, x, p, r) in enumerate(states[:5]):
        args = (t, jnp.asarray(x), jnp.asarray(p), jnp.asarray(r))
        assert close(rhs(*args), reference.rhs(t, x, p, r)), (seed, "rhs")
        assert close(module.mass_matrix(*args), reference.mass_matrix(t, x, p, r)), (seed, "M")
        assert close(module.forcing(*args), reference.forcing(t, x, p, r)), (seed, "F")
    t, _, p, r = states[0]
    xs = np.random.default_rng(CASES.index(name)).uniform(0.3, 1.2, (BATCH, len(d.state)))
    batched = jax.vmap(module.rhs, in_axes=(None, 0, None, None))(t, xs, jnp.asarray(p), jnp.asarray(r))
    assert batched.shape == (BATCH, len(d.state))
    for i in range(BATCH):
        # A solve's forward error grows with cond(M), as in test_generated_numeric: a random
        # bicycle state can have cond(M) = 6e4, where two exact codes differ by 2e-12.
        cond = np.linalg.cond(reference.mass_matrix(t, xs[i], p, r))
        assert close(batched[i], reference.rhs(t, xs[i], p, r), RTOL * max(1.0, cond / 100)), (i, "vmap")


def test_vmap_over_parameters(tmp_path):
    d = derivation("spinning_top")
    module, reference = write_jax(d, tmp_path), write_python(d, tmp_path)
    t, x, p, r = next(random_states(d, 7))
    ps = np.random.default_rng(7).uniform(0.3, 1.2, (BATCH, len(p)))
    batched = jax.vmap(module.rhs, in_axes=(None, None, 0, None))(t, jnp.asarray(x), ps, jnp.asarray(r))
    for i in range(BATCH):
        assert close(batched[i], reference.rhs(t, x, ps[i], r)), i


def test_grad_with_respect_to_a_parameter_matches_a_central_difference(tmp_path):
    """d/dp_g of a scalar function of the rolling disk's rhs, by jax.grad and by (f(g + h) - f(g - h)) / 2h.

    The difference is of the NumPy module, not of the JAX one, so that a wrong JAX
    derivative cannot agree with itself.
    """
    d = derivation("rolling_disk")
    module, reference = write_jax(d, tmp_path), write_python(d, tmp_path)
    t, x, p, r = next(random_states(d, 11))
    weights = np.linspace(0.5, 1.5, len(x))

    def objective(rhs, p_):
        return (rhs(t, x, p_, r) * weights).sum() + (rhs(t, x, p_, r) ** 2).sum()

    for index in range(len(p)):
        gradient = jax.grad(lambda q: objective(module.rhs, q))(jnp.asarray(p))[index]
        h = 1e-5 * max(1.0, abs(p[index]))
        up, down = np.array(p, dtype=float), np.array(p, dtype=float)
        up[index] += h
        down[index] -= h
        difference = (objective(reference.rhs, up) - objective(reference.rhs, down)) / (2 * h)
        assert abs(gradient - difference) <= 1e-6 * max(1.0, abs(difference)), (index, gradient, difference)


def test_module_imports_only_jax(tmp_path):
    ((_, text),) = emit_jax(derivation("whipple_bicycle")).items()
    imported = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Import):
            imported |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            imported.add(node.module)
    assert imported == {"jax", "jax.numpy", "jax.scipy.linalg"}
    assert "x64" in text and "jax_enable_x64" in text


def test_no_python_branch_on_values():
    """The only `if` is the one on callable(r): a branch on a traced value would fail under jit."""
    ((_, text),) = emit_jax(derivation("sphere_on_turntable")).items()
    tests = [ast.unparse(n.test) for n in ast.walk(ast.parse(text)) if isinstance(n, (ast.If, ast.IfExp, ast.While))]
    assert tests and set(tests) == {"callable(r)"}


def test_readme_example_runs(tmp_path):
    """The README's JAX example: the batch's shape, and its slope against the NumPy module's central difference."""
    import subprocess
    import sys

    from test_emit_octave import readme_block

    d = derivation("rolling_disk")
    ((name, text),) = emit_jax(d).items()
    (tmp_path / name).write_text(text, encoding="utf-8")
    (tmp_path / "example.py").write_text(readme_block("python", "jax.vmap"), encoding="utf-8")
    result = subprocess.run([sys.executable, "example.py"], capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert result.returncode == 0, result.stderr
    shape, slope = result.stdout.rsplit(")", 1)
    assert shape + ")" == f"(10000, {len(d.state)})"
    (tmp_path / "numpy").mkdir()
    reference = write_python(d, tmp_path / "numpy")
    state = np.asarray(jax.random.uniform(jax.random.key(0), (10_000, len(d.state)), minval=0.3, maxval=1.2)[0])
    p = np.array([reference.DEFAULTS[n] for n in reference.PARAMETERS])
    g, lean, h = reference.PARAMETERS.index("g"), reference.STATE.index("dot(lean)"), 1e-5
    up, down = p.copy(), p.copy()
    up[g] += h
    down[g] -= h
    difference = (reference.rhs(0.0, state, up)[lean] - reference.rhs(0.0, state, down)[lean]) / (2 * h)
    assert abs(float(slope) - difference) <= 1e-6 * max(1.0, abs(difference))
