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
    "integrals",
    "load",
    "loads",
    "stability",
]

_LAZY = {
    "Derivation": "gacli.api",
    "derive": "gacli.api",
    "System": "gacli.model",
    "load": "gacli.loader.loading",
    "loads": "gacli.loader.loading",
    "emit": "gacli.api",
    "stability": "gacli.api",
    "integrals": "gacli.api",
    "DerivationError": "gacli.errors",
    "Diagnostic": "gacli.errors",
    "EmitError": "gacli.errors",
    "GacliError": "gacli.errors",
    "Location": "gacli.errors",
    "SystemFileError": "gacli.errors",
}

if TYPE_CHECKING:  # pragma: no cover
    from gacli.api import Derivation, derive, emit, integrals, stability
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


# -- gacli.linearize(...) and gacli.simulate(...) --------------------------------------------
# Both names are also modules (gacli/linearize.py, gacli/simulate/), and importing a submodule
# sets it as the package's attribute, over any function of that name: code inside gacli reads
# them as modules (`from gacli import linearize as L`). So those modules are made callable as
# the import sets them, and a call is the API's (gacli.api.linearize, gacli.api.simulate).

import sys as _sys
import types as _types

_CALLABLE_MODULES = ("linearize", "simulate", "steady")
__all__ = sorted([*__all__, "linearize", "simulate", "steady"])


class _CallableModule(_types.ModuleType):
    def __call__(self, *args, **kwargs):
        from gacli import api

        return getattr(api, self.__name__.rpartition(".")[2])(*args, **kwargs)


class _Package(_types.ModuleType):
    def __setattr__(self, name: str, value) -> None:
        if name in _CALLABLE_MODULES and type(value) is _types.ModuleType:
            value.__class__ = _CallableModule
        super().__setattr__(name, value)


_lazy_attribute = __getattr__


def __getattr__(name: str):  # noqa: F811  (the lazy names, and the two callable modules)
    if name in _CALLABLE_MODULES:
        import importlib

        return importlib.import_module(f"gacli.{name}")  # the import sets it, callable, by _Package
    return _lazy_attribute(name)


_sys.modules[__name__].__class__ = _Package
