"""The one call that turns a derivation into generated files."""

from __future__ import annotations

from gacli.equations import Derivation
from gacli.errors import EmitError


def emit(derivation: Derivation, format: str, **options) -> dict[str, str]:
    """Generated files for ``format`` ("python", "c" or "latex"), as {file name: text}."""
    from gacli.emit import EMITTERS

    try:
        emitter = EMITTERS[format]
    except KeyError:
        raise EmitError(f"unknown format '{format}' (one of: {', '.join(sorted(EMITTERS))})") from None
    return emitter(derivation, **options)
