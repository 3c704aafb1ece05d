"""The Python API that ``import gacli`` names: derive, Derivation, emit.

``derive`` and ``Derivation`` are those of :mod:`gacli.mechanics.equations`; importing
:mod:`gacli.notebook` here gives a derivation its typeset face in Jupyter
(the mechanics stage does not import its own display). The dispatch
over formats is :func:`gacli.emit.emit`, beside the emitters it chooses from;
this layer above them only names it, so nothing in :mod:`gacli.emit` reaches
back up here.
"""

from __future__ import annotations

from gacli import notebook  # noqa: F401  (on import, Derivation gets _repr_latex_)
from gacli.emit import emit
from gacli.mechanics.equations import Derivation, derive

__all__ = ["Derivation", "derive", "emit"]
