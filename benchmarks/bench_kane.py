"""The benchmark systems written for SymPy's KanesMethod.

Each builder constructs the model the way a SymPy user would (frames,
points, particles or rigid bodies, loads, ``KanesMethod.kanes_equations``)
with the same coordinates as the gacli system file, in the same order, and
u = q' for every coordinate. Parameter symbols carry the names of the
system file's parameters, so values can be passed by name.

``KaneModel.q`` is in the order of the system file's coordinates,
``u_ind`` in the order of its ``independent`` names, ``u_dep`` are
KanesMethod's dependent speeds (nonholonomic systems only), and the state
of Kane's own rhs is (q, u_ind, u_dep).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp
from sympy.physics import mechanics as me


@dataclass
class KaneModel:
    kane: me.KanesMethod
    q: list
    u_ind: list
    u_dep: list
    parameters: dict[str, sp.Symbol]
    velocity_constraints: list = field(default_factory=list)

    @property
    def u(self) -> list:
        return self.u_ind + self.u_dep

    @property
    def mass_matrix(self) -> sp.Matrix:
        return self.kane.mass_matrix

    @property
    def forcing(self) -> sp.Matrix:
        return self.kane.forcing

    @property
    def kinematics(self) -> list:
        """q' in the order of q, as KanesMethod gives them (kindiffdict)."""
        rates = self.kane.kindiffdict()
        return [rates[q.diff(me.dynamicsymbols._t)] for q in self.q]


def _real(names: str) -> tuple[sp.Symbol, ...]:
    out = sp.symbols(names, real=True)
    return out if isinstance(out, tuple) else (out,)


def pendulum(n: int) -> KaneModel:
    """n point masses on massless links, absolute angles from the downward vertical."""
    q = list(me.dynamicsymbols(f"q1:{n + 1}"))
    u = list(me.dynamicsymbols(f"u1:{n + 1}"))
    m = _real(f"m1:{n + 1}")
    l = _real(f"l1:{n + 1}")
    (g,) = _real("g")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    previous, particles, loads = O, [], []
    for i in range(n):
        A = N.orientnew(f"A{i + 1}", "Axis", [q[i], N.z])
        A.set_ang_vel(N, u[i] * N.z)
        P = previous.locatenew(f"P{i + 1}", -l[i] * A.y)
        P.v2pt_theory(previous, N, A)
        particles.append(me.Particle(f"pa{i + 1}", P, m[i]))
        loads.append((P, -m[i] * g * N.y))
        previous = P
    kd = [q[i].diff() - u[i] for i in range(n)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(particles, loads)
    parameters = {"g": g, **{s.name: s for s in m + l}}
    return KaneModel(kane, q, u, [], parameters)


def chain(n: int) -> KaneModel:
    """n rigid links joined by ball joints; absolute body-fixed X-Y-Z angles per link."""
    q, u, parameters = [], [], {}
    (g,) = _real("g")
    parameters["g"] = g
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    joint, bodies, loads = O, [], []
    for i in range(1, n + 1):
        angles = list(me.dynamicsymbols(f"phi{i} theta{i} psi{i}"))
        q += angles
        u += list(me.dynamicsymbols(f"u_phi{i} u_theta{i} u_psi{i}"))
        m, L, A, B, C = _real(f"m{i} L{i} A{i} B{i} C{i}")
        parameters.update({s.name: s for s in (m, L, A, B, C)})
        frame = me.ReferenceFrame(f"B{i}")
        frame.orient_body_fixed(N, angles, "XYZ")
        centre = joint.locatenew(f"G{i}", -L / 2 * frame.z)
        centre.v2pt_theory(joint, N, frame)
        bodies.append(me.RigidBody(f"link{i}", centre, frame, m, (me.inertia(frame, A, B, C), centre)))
        loads.append((centre, -m * g * N.z))
        following = joint.locatenew(f"J{i + 1}", -L * frame.z)
        following.v2pt_theory(joint, N, frame)
        joint = following
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return KaneModel(kane, q, u, [], parameters)


def rolling_disk() -> KaneModel:
    """The disk of benchmarks/cases/rolling_disk.yaml, with the contact point (x, y) as coordinates.

    The rolling constraints are not copied from the system file: they are
    formed here as "the disk's material point at the contact is at rest",
    so that agreement with gacli checks the file's hand-written forms.
    """
    q1, q2, q3, x, y = q = list(me.dynamicsymbols("q1 q2 q3 x y"))
    u1, u2, u3, u4, u5 = u = list(me.dynamicsymbols("u1:6"))
    m, r, g = _real("m r g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [q1, N.z])
    L = Y.orientnew("L", "Axis", [q2, Y.x])
    D = L.orientnew("D", "Axis", [q3, L.y])
    Y.set_ang_vel(N, u1 * N.z)
    L.set_ang_vel(N, u1 * N.z + u2 * L.x)
    D.set_ang_vel(N, u1 * N.z + u2 * L.x + u3 * L.y)
    O = me.Point("O")
    O.set_vel(N, 0)
    contact = O.locatenew("C", x * N.x + y * N.y)
    contact.set_vel(N, u4 * N.x + u5 * N.y)
    centre = contact.locatenew("G", r * L.z)
    centre.set_vel(N, u4 * N.x + u5 * N.y + (L.ang_vel_in(N) ^ (r * L.z)))
    material = centre.vel(N) + (D.ang_vel_in(N) ^ (-r * L.z))
    constraints = [material.dot(N.x), material.dot(N.y)]
    disk = me.RigidBody("disk", centre, D, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), centre))
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=constraints)
    kane.kanes_equations([disk], [(centre, -m * g * N.z)])
    return KaneModel(kane, q, [u1, u2, u3], [u4, u5], {"m": m, "r": r, "g": g}, constraints)


BUILDERS = {"pendulum": pendulum, "chain": chain, "disk": lambda n=None: rolling_disk()}
