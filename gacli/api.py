"""The Python API behind ``gacli.emit``: the one call that turns a derivation into generated files.

The dispatch over formats is :func:`gacli.emit.emit`, beside the emitters it
chooses from; this layer above them only names it, so that nothing in
:mod:`gacli.emit` reaches back up here.
"""

from __future__ import annotations

from gacli.emit import emit

__all__ = ["emit"]
