"""A rigid body's inertia given about another point or in another frame, carried to its centre and axes.

Declared about a point P fixed in the body and along the axes of a frame F
fixed in it, the inertia is turned into the body's axes B, I_B = R I_F Rᵀ
with R = C_Bᵀ C_F (both direction-cosine matrices to N, R constant), and
moved to the mass centre G by the parallel-axis theorem,

    I_G = I_P − m (|r|² E − r rᵀ),   r = G − P along B (constant).

Where the parameters have values, the result must be the inertia of a body:
its principal moments non-negative and each at most the sum of the other two
(the triangle inequalities), or no distribution of mass has it.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra import trig
from gacli.algebra.spheres import Sphere, remainder_on
from gacli.numeric import Program
from gacli.read.schema import BodyDecl

# Relative to the largest principal moment: rounding in the shift is not a violation.
_TOLERANCE = 1e-9


class MovedInertia:
    """For the loader's builder (a mixin): the declared inertia about the centre, in the body's axes."""

    def _moved_inertia(self, decl: BodyDecl, where: str, inertia: sp.Matrix, mass: sp.Expr,
                       position) -> sp.ImmutableMatrix | None:
        body = self.frames.get(decl.frame.text) if decl.frame is not None else None
        if body is None:
            return sp.ImmutableMatrix(inertia)  # the frame's own error is reported where it is named
        if decl.inertia_in is not None:
            turned = self._turn(decl, where, inertia, body)
            if turned is None:
                return None
            inertia = turned
        if decl.inertia_about is not None:
            point = self._point_named(decl.inertia_about, f"{where}.inertia_about")
            if point is None:
                return None
            r = self._constant(sp.Matrix(body.dcm).T * (sp.Matrix(position) - sp.Matrix(point)))
            if r is None:
                self.error(decl.inertia_about, f"{where}.inertia_about",
                           f"'{decl.inertia_about.text}' is not fixed in the body: it moves relative to its centre")
                return None
            inertia = inertia - mass * ((r.T * r)[0] * sp.eye(3) - r * r.T)
        inertia = sp.ImmutableMatrix(inertia.applyfunc(sp.expand))
        problem = self._not_a_body(inertia)
        if problem:
            self.error(decl.inertia_node, f"{where}.inertia", problem)
            return None
        return inertia

    def _turn(self, decl: BodyDecl, where: str, inertia: sp.Matrix, body) -> sp.Matrix | None:
        frame = self.frames.get(decl.inertia_in.text)
        if frame is None:
            self.not_a_frame(decl.inertia_in, f"{where}.inertia_in")
            return None
        R = self._fixed_turn(body, frame)
        if R is None:
            self.error(decl.inertia_in, f"{where}.inertia_in",
                       f"the frame '{frame.name}' turns relative to the body's frame: the inertia in its axes "
                       "would change with the motion")
            return None
        return R * inertia * R.T

    def _fixed_turn(self, outer, inner) -> sp.Matrix | None:
        """The turn from ``inner``'s axes to ``outer``'s, C_outerᵀ C_inner, when it is constant (the
        frame fixed in the other); None when it moves."""
        return self._constant(sp.Matrix(outer.dcm).T * sp.Matrix(inner.dcm))

    def _constant(self, m: sp.Matrix) -> sp.Matrix | None:
        """``m`` reduced by sin² + cos² = 1 and by each quaternion frame's unit norm, or None when
        anything but parameters is left in it (coordinates, t, functions)."""
        # A quaternion frame's turns are homogeneous quadratics (gacli.loader.frames), and C_Bᵀ C_B is
        # (e·e)² E, which is E on the unit sphere where the motion is.
        units = tuple(Sphere(tuple(S.value(n) for n in q.parameters), sp.S.One) for q in self.quaternion_frames)
        m = m.applyfunc(lambda x: remainder_on(trig.reduce(sp.expand(x)), units))
        allowed = set(self.known) | self._parameter_symbols()
        return None if any(not x.free_symbols <= allowed for x in m) else m

    def _parameter_symbols(self) -> set:
        return {S.value(s.name) for s in self.decl.of_kind("parameter")}

    def _not_a_body(self, inertia: sp.ImmutableMatrix) -> str | None:
        """Why no body has this inertia (with the parameters' values), or None."""
        if not all(x.free_symbols <= set(self.known) for x in inertia):
            return None
        values = np.real(np.array(Program(list(inertia))(self.known), dtype=complex)).reshape(3, 3)
        moments = np.linalg.eigvalsh((values + values.T) / 2)
        scale = max(1.0, float(np.max(np.abs(moments))))
        a, b, c = sorted(moments)
        if a < -_TOLERANCE * scale:
            return f"the inertia about the centre has a negative principal moment ({a:.6g}): no body has it"
        if a + b < c - _TOLERANCE * scale:
            return (f"the inertia about the centre breaks the triangle inequality: its principal moments "
                    f"{a:.6g} + {b:.6g} < {c:.6g}, and no body has such moments")
        return None
