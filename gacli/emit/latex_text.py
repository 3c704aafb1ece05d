"""Free text from a system file (a title, a source, a body's name) as LaTeX text.

What pdflatex accepts, ASCII out: TeX's special characters escaped, Greek
letters and accents as commands, anything else as ``?``; and in lines short
enough for its input buffer.
"""

from __future__ import annotations

import re
import unicodedata

from gacli.read.textsafe import one_line

# Characters of free text (a title, a source) on one line of the .tex file.
TEXT_LINE = 240

_TEXT_SPECIALS = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
    "%": r"\%", "_": r"\_", "^": r"\^{}", "~": r"\~{}", "<": r"\textless{}", ">": r"\textgreater{}",
    "|": r"\textbar{}",
    "\u2013": "--", "\u2014": "---", "\u2018": "`", "\u2019": "'", "\u201c": "``", "\u201d": "''",
    "\u2026": r"\dots{}", "\u2202": r"$\partial$", "\u03a3": r"$\Sigma$", "\u00d7": r"$\times$", "\u00b0": r"$^\circ$", "\u00a0": "~",
}
_GREEK = re.compile(r"^GREEK (SMALL|CAPITAL) LETTER (?:FINAL )?([A-Z]+)$")
_GREEK_COMMANDS = frozenset(
    "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi pi rho sigma tau upsilon "
    "phi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega".split()
)
_ACCENTS = {"\u0307": ".", "\u0300": "`", "\u0301": "'", "\u0302": "^", "\u0303": "~", "\u0304": "=", "\u0306": "u",
            "\u0308": '"', "\u030a": "r", "\u030c": "v", "\u0327": "c"}


def tex_text(text: str) -> str:
    """Free text from the system file as LaTeX text that pdflatex accepts (ASCII out), in lines."""
    units: list[str] = []  # the LaTeX of each character: lines break between them, never inside
    for c in unicodedata.normalize("NFC", one_line(text)):
        if c in _ACCENTS and units:
            # A combining mark left over after NFC (u̇ has no precomposed form): accent the last letter.
            units[-1] = rf"\{_ACCENTS[c]}{{{units[-1]}}}"
        else:
            units.append(_text_char(c))
    # TeX sets -- and --- as dashes; an option such as --format must keep its two hyphens.
    units = [re.sub(r"-(?=-)", "-{}", u) for u in units]
    for i in range(len(units) - 1):
        if units[i].endswith("-") and units[i + 1].startswith("-"):
            units[i] += "{}"
    return _wrap(units)


def _wrap(units: list[str]) -> str:
    """Lines of about TEXT_LINE characters: pdflatex cannot read a line longer than its buffer.

    A line ends at the first space past TEXT_LINE; a run without spaces is cut
    at 2 * TEXT_LINE, the cut hidden from TeX by a ``%`` (every unit ends in a
    character that cannot continue a control word).
    """
    lines, line, size = [], [], 0
    for unit in units:
        if unit == " " and size >= TEXT_LINE:
            lines.append("".join(line))
            line, size = [], 0
            continue
        if size >= 2 * TEXT_LINE:
            lines.append("".join(line) + "%")
            line, size = [], 0
        line.append(unit)
        size += len(unit)
    lines.append("".join(line))
    return "\n".join(lines)


def _text_char(c: str) -> str:
    if c in _TEXT_SPECIALS:
        return _TEXT_SPECIALS[c]
    if c.isascii():
        return c
    greek = _GREEK.match(unicodedata.name(c, ""))
    if greek:
        letter = greek[2].lower().replace("lamda", "lambda")
        letter = letter.capitalize() if greek[1] == "CAPITAL" else letter
        return rf"$\{letter}$" if letter in _GREEK_COMMANDS else "?"
    base, *marks = unicodedata.normalize("NFD", c)
    if base.isascii() and marks and all(m in _ACCENTS for m in marks):
        out = _TEXT_SPECIALS.get(base, base)
        for mark in marks:
            out = rf"\{_ACCENTS[mark]}{{{out}}}"
        return out
    return "?"
