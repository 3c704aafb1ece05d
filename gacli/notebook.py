"""How a derivation shows itself in a notebook (its one-line repr is its own).

Jupyter shows ``_repr_latex_`` through MathJax: text as text, ``$...$`` and
``align*`` as mathematics. The equations are those of ``gacli derive
--format latex`` (:mod:`gacli.emit.latex`, imported on first display: there
is one LaTeX path, not two), with the file comments turned into the lines of
text they stand for. A system too large to read gets a summary instead,
decided by counting nodes (which stops early) before any LaTeX is made: the
bicycle's equations would take minutes to print and pages to scroll.
"""

from __future__ import annotations

from gacli.mechanics.equations import Derivation

# Tree nodes of M and F together, above which a notebook shows a summary.
# The shipped systems other than the bicycle stay under 2,000; a page of
# equations is about this many.
REPR_NODES = 6_000
TOO_LARGE = "too large to show; use gacli.emit(d, 'latex')"


def readable_size(d: Derivation, limit: int = REPR_NODES) -> bool:
    """Whether M and F together have at most ``limit`` tree nodes (counting stops there)."""
    import sympy as sp

    count = 0
    for entry in (*d.mass_matrix, *d.forcing):
        for count, _ in enumerate(sp.preorder_traversal(entry), start=count + 1):
            if count > limit:
                return False
    return True


def derivation_latex(d: Derivation) -> str:
    """Jupyter: the equations as ``gacli derive --format latex`` prints them, or a summary when too large."""
    from gacli.emit.latex import emit_latex
    from gacli.emit.latex_text import tex_text

    title = tex_text(d.system.title or d.system.name)
    if not readable_size(d):
        return "\n\n".join([title, *_summary(d), TOO_LARGE]) + "\n"
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
        out.append(line)
    return out + ([" ".join(comment)] if comment else [])


def _summary(d: Derivation) -> list[str]:
    from gacli.emit.latex_printer import printer_for

    import sympy as sp

    printer = printer_for(d.system)
    names = ", ".join(printer.doprint(sp.Symbol(c.name)) for c in d.system.coordinates)
    speeds = ", ".join(printer.doprint(u) for u in d.speeds)
    k = d.k
    return [
        f"{len(d.system.coordinates)} coordinates ${names}$;",
        f"{k} independent speeds ${speeds}$;",
        f"$M$ is ${k} \\times {k}$ and $F$ is ${k} \\times 1$, with more than {REPR_NODES:,} terms as trees:",
    ]


# The derivation is a record of the mechanics stage, which knows nothing of LaTeX; it gets its
# notebook face here, a stage above, when this module is imported. gacli.api imports it, so every
# Derivation reached through gacli.derive shows itself typeset, and gacli.mechanics.equations never imports
# the emitter that prints it (which would close a circle through gacli.display.steps).
Derivation._repr_latex_ = derivation_latex

