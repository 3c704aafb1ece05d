"""How a derivation shows itself in a notebook (its one-line repr is its own).

Jupyter shows ``_repr_latex_`` through MathJax: text as text, ``$...$`` and
``align*`` as mathematics. The equations are those of ``gacli derive
--format latex`` (:mod:`gacli.emit.latex`, imported on first display: there
is one LaTeX path, not two), with the file comments turned into the lines of
text they stand for. A system whose equations are long shows them through
named quantities, as the text report does (:mod:`gacli.display.long`): the
bicycle's, written out, would take minutes to print and pages to scroll.
"""

from __future__ import annotations

from gacli.mechanics.equations import Derivation


def derivation_latex(d: Derivation) -> str:
    """Jupyter: the equations as ``gacli derive --format latex`` prints them (long ones through
    named quantities, docs/printing.md)."""
    from gacli.emit.latex import emit_latex
    from gacli.emit.latex_text import tex_text

    title = tex_text(d.system.title or d.system.name)
    ((_, tex),) = emit_latex(d).items()
    return title + "\n" + "\n".join(_comments_as_text(tex)) + "\n"


def _comments_as_text(tex: str) -> list[str]:
    """The fragment without its file header, each section's comment made a line of text."""
    body = tex.split("\n\n", 1)[1] if "\n\n" in tex else ""  # the header is the first block of comments
    out: list[str] = []
    comment: list[str] = []
    for line in body.splitlines():
        if line.startswith("% "):
            comment.append(line[2:])
            continue
        if comment:
            out.append(" ".join(comment))
            comment = []
        out.append(line.removeprefix("\\noindent "))  # a paragraph command, not text MathJax shows
    return out + ([" ".join(comment)] if comment else [])


# The derivation is a record of the mechanics stage, which knows nothing of LaTeX; it gets its
# notebook face here, a stage above, when this module is imported. gacli.api imports it, so every
# Derivation reached through gacli.derive shows itself typeset, and gacli.mechanics.equations never imports
# the emitter that prints it (which would close a circle through gacli.display.steps).
Derivation._repr_latex_ = derivation_latex

