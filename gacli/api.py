"""The one call that turns a derivation into generated files."""

from __future__ import annotations

from gacli.equations import Derivation
from gacli.errors import EmitError


def emit(derivation: Derivation, format: str, **options) -> dict[str, str]:
    """Generated files for ``format`` (a key of :data:`gacli.emit.EMITTERS`), as {file name: text}."""
    from gacli.emit import EMITTERS

    try:
        emitter = EMITTERS[format]
    except KeyError:
        # Worded as the command line words it (gacli.cli_help.choice).
        raise EmitError(f"'{format}' is not a format; choose one of: {', '.join(sorted(EMITTERS))}") from None
    return emitter(derivation, **options)
