"""Springs and dampers between two points: their potential and their virtual work (eq. 14.13).

A linear spring of stiffness k and free length L between points A and B
stores V = ½ k (ℓ − L)², ℓ = |B − A|; a linear damper of coefficient c
pulls its ends together with the force c ℓ̇ along the line, whose virtual
work is −c ℓ̇ δℓ. With d = B − A (N components, closed forms in the
coordinates and t), ℓ̇ = d·ḋ/ℓ and δℓ = Σ_q (d·∂d/∂q)/ℓ δq, so the damper
adds the work form Σ_q −c ℓ̇ (d·∂d/∂q)/ℓ dq. Both join the file's own
``potential`` and ``work``: every route (the closed forms, the program,
verify's Lagrange route) reads them as it reads those.
"""

from __future__ import annotations

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.frame_model import Line
from gacli.model import Body, Form
from gacli.numeric.zero import decide_zero
from gacli.read.schema import LoadDecl


class Lines:
    """Springs and dampers, for the loader's builder (a mixin, as Geometry and RollingContacts)."""

    def _line_loads(self, bodies: tuple[Body, ...]) -> tuple[sp.Expr, Form | None, tuple[Line, ...]]:
        """(the springs' potential, the dampers' work form or None, the lines between their ends' names)."""
        by_name = {b.name: b for b in bodies}
        potential, work, lines = sp.S.Zero, None, []
        for load in self.decl.loads:
            if load.spring is None and load.damper is None:
                continue
            d = self._line(load, by_name)
            if d is None:
                continue
            ends = (load.between[0].text, load.between[1].text)
            where = f"loads[{load.index}]"
            length = sp.sqrt(sum(x ** 2 for x in d))
            if load.spring is not None:
                k = self.expression(load.spring, f"{where}.spring", self.scopes.constant)
                free = self.expression(load.length, f"{where}.length", self.scopes.constant) if load.length else 0
                if k is not None and free is not None:
                    potential += k * (length - free) ** 2 / 2
                    lines.append(Line(ends, stiffness=k, length=free))
            else:
                c = self.expression(load.damper, f"{where}.damper", self.scopes.load)
                if c is not None:
                    work = (work or Form(())) + self._damper_work(c, d, length)
                    lines.append(Line(ends, damping=c))
        return potential, work, tuple(lines)

    def _line(self, load: LoadDecl, bodies: dict[str, Body]):
        """B − A in N components, or None after a located error (an end unknown, or ends that coincide)."""
        where = f"loads[{load.index}].between"
        ends = [self._place_named(node, where, bodies) for node in load.between]
        if any(e is None for e in ends):
            return None
        d = tuple(as_expr(b) - as_expr(a) for a, b in zip(*ends))
        if decide_zero(sum(x ** 2 for x in d)).zero:
            kind = "spring" if load.spring is not None else "damper"
            self.error(load.node, where, f"the two ends of this {kind} are the same point (its length is "
                                         "always zero, so its direction is undefined)")
            return None
        return d

    def _damper_work(self, c: sp.Expr, d: tuple, length: sp.Expr) -> Form:
        chain = {S.value(q.name): S.rate(q.name) for q in self.decl.of_kind("coordinate")}
        chain.update(self.scopes.function_chain)
        rate = sum(x * S.time_derivative(x, chain) for x in d) / length
        coefficients = []
        for q in self.decl.of_kind("coordinate"):
            along = sum(x * sp.diff(x, S.value(q.name)) for x in d)
            if along != 0:
                coefficients.append((q.name, -c * rate * along / length))
        return Form(tuple(coefficients))

