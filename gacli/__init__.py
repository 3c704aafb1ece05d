"""gacli: equations of motion by the Gibbs-Appell method.

The Python API mirrors the command line::

    >>> import gacli
    >>> system = gacli.load("systems/sphere_on_turntable.yaml")   # doctest: +SKIP
    >>> d = gacli.derive(system)                                   # doctest: +SKIP
    >>> d.mass_matrix, d.forcing, d.gibbs                          # doctest: +SKIP

Imports are lazy so that ``gacli --help`` does not load SymPy.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gacli.version import __version__

__all__ = [
    "Derivation",
    "DerivationError",
    "Diagnostic",
    "EmitError",
    "GacliError",
    "Location",
    "System",
    "SystemFileError",
    "__version__",
    "derive",
    "emit",
    "load",
    "loads",
]

_LAZY = {
    "Derivation": "gacli.api",
    "derive": "gacli.api",
    "System": "gacli.model",
    "load": "gacli.loader.loading",
    "loads": "gacli.loader.loading",
    "emit": "gacli.api",
    "DerivationError": "gacli.errors",
    "Diagnostic": "gacli.errors",
    "EmitError": "gacli.errors",
    "GacliError": "gacli.errors",
    "Location": "gacli.errors",
    "SystemFileError": "gacli.errors",
}

if TYPE_CHECKING:  # pragma: no cover
    from gacli.api import Derivation, derive, emit
    from gacli.errors import (
        DerivationError,
        Diagnostic,
        EmitError,
        GacliError,
        Location,
        SystemFileError,
    )
    from gacli.loader.loading import load, loads
    from gacli.model import System


def __getattr__(name: str):
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'gacli' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
