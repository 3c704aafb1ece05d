"""Text from a system file made safe to show: one sanitizer, and quotes kept short.

Used by every place that prints or serialises file text (the console, the
check reports in every format); it has no dependency, so that JSON output
does not need the terminal's libraries.
"""

from __future__ import annotations

import re

# Quoted file text in a message is cut to this many characters: a file that is
# one 900 kB scalar, or a link to some other file, must not fill the terminal.
MAX_QUOTED = 400


def printable(text: str, keep: str = "") -> str:
    """The one sanitizer for text that may come from a file, before it reaches a terminal.

    Control characters, bidi overrides, zero-width characters, line
    separators and lone surrogates (anything not ``str.isprintable``) are
    shown as visible escapes (``\\x1b``, ``\\u202e``, ``\\ud800``): a file must
    not drive the terminal, reorder what is shown, hide text, or make
    printing fail with a UnicodeEncodeError. ``keep`` lists characters
    (newline, tab) that generated source may contain as they are.
    """
    if text.isprintable():  # the usual case, at C speed
        return text
    if keep:
        pattern = "(" + "|".join(re.escape(c) for c in keep) + ")"
        return "".join(part if part in keep else printable(part) for part in re.split(pattern, text))
    return "".join(c if c.isprintable() or c == " " else c.encode("unicode_escape").decode("ascii") for c in text)


def shortened(text: str, limit: int = MAX_QUOTED) -> str:
    """``text`` with its middle left out past ``limit`` characters (the end often says the most)."""
    if len(text) <= limit:
        return text
    half = limit // 2
    return f"{text[:half]}... ({len(text) - 2 * half} characters not shown) ...{text[-half:]}"


def quoted(text: str) -> str:
    """A message, place or hint that quotes a file: shortened, then made printable."""
    return printable(shortened(text))


def one_line(text: str) -> str:
    """Free text for a comment in a generated file: one line, printable characters only.

    A file name or title with a newline must not start a line of live code
    (or live TeX) in a generated file.
    """
    return " ".join("".join(c if c.isprintable() else " " for c in text).split())
