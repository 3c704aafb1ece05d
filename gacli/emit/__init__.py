"""Emitters: a derivation → the text of generated files.

Every emitter is a pure function ``emit_X(derivation, **options)`` that
returns ``{file name: file text}`` and writes nothing; the CLI writes the
files. The FMU's one file is a zip, so its value is bytes. :data:`EMITTERS` maps each ``--format`` to its emitter. Emitters are
imported on first use, so that ``gacli check`` does not pay for them.

>>> sorted(EMITTERS)
['c', 'fmu', 'jax', 'latex', 'octave', 'python']
"""

from __future__ import annotations

import sys
import types
from collections.abc import Callable
from typing import TYPE_CHECKING

from gacli.errors import EmitError

if TYPE_CHECKING:
    from gacli.mechanics.equations import Derivation

Emitter = Callable[..., dict[str, str]]


def emit_python(derivation: Derivation, **options) -> dict[str, str]:
    """``{"<name>.py": text}``: see :mod:`gacli.emit.python`."""
    from gacli.emit.python import emit_python as emit

    return emit(derivation, **options)


def emit_c(derivation: Derivation, **options) -> dict[str, str]:
    """``{"<name>.h": header, "<name>.c": source}``: see :mod:`gacli.emit.c`."""
    from gacli.emit.c import emit_c as emit

    return emit(derivation, **options)


def emit_latex(derivation: Derivation, **options) -> dict[str, str]:
    """``{"<name>.tex": text}``; ``standalone=True`` for a whole document: see :mod:`gacli.emit.latex`."""
    from gacli.emit.latex import emit_latex as emit

    return emit(derivation, **options)


def emit_fmu(derivation: Derivation, **options) -> dict[str, bytes]:
    """``{"<name>.fmu": zip bytes}``, FMI 2.0 Model Exchange: see :mod:`gacli.emit.fmu`."""
    from gacli.emit.fmu import emit_fmu as emit

    return emit(derivation, **options)


def emit_octave(derivation: Derivation, **options) -> dict[str, str]:
    """``{"<name>_rhs.m": ..., ...}``, Octave/MATLAB function files: see :mod:`gacli.emit.octave`."""
    from gacli.emit.octave import emit_octave as emit

    return emit(derivation, **options)


def emit_jax(derivation: Derivation, **options) -> dict[str, str]:
    """``{"<name>_jax.py": text}``, a ``jax.numpy`` module: see :mod:`gacli.emit.jax`."""
    from gacli.emit.jax import emit_jax as emit

    return emit(derivation, **options)


EMITTERS: dict[str, Emitter] = {
    "python": emit_python,
    "c": emit_c,
    "latex": emit_latex,
    "fmu": emit_fmu,
    "octave": emit_octave,
    "jax": emit_jax,
}


def emit(derivation: Derivation, format: str, **options) -> dict[str, str]:
    """Generated files for ``format`` (a key of :data:`EMITTERS`), as {file name: text}.

    ``derivation`` is what ``gacli.derive`` returns; a System (``gacli.load``) or a system file's
    path is derived first, as a notebook writes ``gacli.emit(gacli.load(path), "c")``."""
    try:
        emitter = EMITTERS[format]
    except KeyError:
        # Worded as the command line words it (gacli.cli_help.choice).
        raise EmitError(f"'{format}' is not a format; choose one of: {', '.join(sorted(EMITTERS))}") from None
    return emitter(derived(derivation), **options)


def derived(what, progress=None) -> Derivation:
    """A Derivation from itself, a System or a system file's path (``progress`` sees the steps of
    deriving it); a TypeError that says which, else."""
    from pathlib import Path

    from gacli.loader.loading import load
    from gacli.mechanics.equations import Derivation, derive
    from gacli.model import System

    if isinstance(what, (str, Path)):
        what = load(what)
    if isinstance(what, System):
        return derive(what, progress=progress)
    if not isinstance(what, Derivation):
        raise TypeError(f"expected what gacli.derive returns, a System (gacli.load) or a path; got {type(what).__name__}")
    return what


__all__ = ["EMITTERS", "Emitter", "emit", "emit_c", "emit_fmu", "emit_jax", "emit_latex", "emit_octave", "emit_python"]


class _CallablePackage(types.ModuleType):
    """This package, callable as :func:`emit`.

    ``gacli.emit(derivation, "c")`` is the documented API, and importing this
    package binds the name ``emit`` on ``gacli`` to the package (Python sets
    a subpackage as its parent's attribute): so the package takes the call.
    """

    def __call__(self, derivation: Derivation, format: str, **options) -> dict[str, str]:
        return emit(derivation, format, **options)


sys.modules[__name__].__class__ = _CallablePackage
