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


def whipple_bicycle() -> KaneModel:
    """The Whipple bicycle as SymPy's own bicycle test builds it (test_kane3.py, after Autolev).

    Coordinates q1 (yaw), q2 (roll), q4 (pitch), q5 (steer) are
    systems/whipple_bicycle.yaml's yaw, roll, pitch and steer; u3 and u6 are
    the wheels' rates relative to the frame and the fork, that is
    dot(wheel_R) and dot(wheel_F). The wheel angles and the rear contact
    point (x, y) are ignorable there and not introduced; the rear contact is
    set at rest, the front contact's velocity is constrained to zero.
    """
    q1, q2, q4, q5 = me.dynamicsymbols("q1 q2 q4 q5")
    q1d, q2d, q4d, q5d = me.dynamicsymbols("q1 q2 q4 q5", 1)
    u1, u2, u3, u4, u5, u6 = me.dynamicsymbols("u1:7")
    names = ("WFrad WRrad htangle forkoffset forklength framelength forkcg1 forkcg3 framecg1 framecg3 "
             "Iwr11 Iwr22 Iwf11 Iwf22 Iframe11 Iframe22 Iframe33 Iframe31 Ifork11 Ifork22 Ifork33 Ifork31 "
             "g mframe mfork mwf mwr")
    P = dict(zip(names.split(), sp.symbols(names)))
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [q1, N.z])
    R = Y.orientnew("R", "Axis", [q2, Y.x])
    Frame = R.orientnew("Frame", "Axis", [q4 + P["htangle"], R.y])
    WR = me.ReferenceFrame("WR")
    TempFrame = Frame.orientnew("TempFrame", "Axis", [-P["htangle"], Frame.y])
    Fork = Frame.orientnew("Fork", "Axis", [q5, Frame.x])
    TempFork = Fork.orientnew("TempFork", "Axis", [-P["htangle"], Fork.y])
    WF = me.ReferenceFrame("WF")
    WR_cont = me.Point("WR_cont")
    WR_mc = WR_cont.locatenew("WR_mc", P["WRrad"] * R.z)
    Steer = WR_mc.locatenew("Steer", P["framelength"] * Frame.z)
    Frame_mc = WR_mc.locatenew("Frame_mc", -P["framecg1"] * Frame.x + P["framecg3"] * Frame.z)
    Fork_mc = Steer.locatenew("Fork_mc", -P["forkcg1"] * Fork.x + P["forkcg3"] * Fork.z)
    WF_mc = Steer.locatenew("WF_mc", P["forklength"] * Fork.x + P["forkoffset"] * Fork.z)
    WF_cont = WF_mc.locatenew("WF_cont", P["WFrad"] * (me.dot(Fork.y, Y.z) * Fork.y - Y.z).normalize())
    Y.set_ang_vel(N, u1 * Y.z)
    R.set_ang_vel(Y, u2 * R.x)
    WR.set_ang_vel(Frame, u3 * Frame.y)
    Frame.set_ang_vel(R, u4 * Frame.y)
    Fork.set_ang_vel(Frame, u5 * Fork.x)
    WF.set_ang_vel(Fork, u6 * Fork.y)
    WR_cont.set_vel(N, 0)
    WR_mc.v2pt_theory(WR_cont, N, WR)
    Steer.v2pt_theory(WR_mc, N, Frame)
    Frame_mc.v2pt_theory(WR_mc, N, Frame)
    Fork_mc.v2pt_theory(Steer, N, Fork)
    WF_mc.v2pt_theory(Steer, N, Fork)
    WF_cont.v2pt_theory(WF_mc, N, WF)
    frame_inertia = me.inertia(TempFrame, P["Iframe11"], P["Iframe22"], P["Iframe33"], 0, 0, P["Iframe31"])
    fork_inertia = me.inertia(TempFork, P["Ifork11"], P["Ifork22"], P["Ifork33"], 0, 0, P["Ifork31"])
    bodies = [
        me.RigidBody("BodyFrame", Frame_mc, Frame, P["mframe"], (frame_inertia, Frame_mc)),
        me.RigidBody("BodyFork", Fork_mc, Fork, P["mfork"], (fork_inertia, Fork_mc)),
        me.RigidBody("BodyWR", WR_mc, WR, P["mwr"], (me.inertia(Frame, P["Iwr11"], P["Iwr22"], P["Iwr11"]), WR_mc)),
        me.RigidBody("BodyWF", WF_mc, WF, P["mwf"], (me.inertia(Fork, P["Iwf11"], P["Iwf22"], P["Iwf11"]), WF_mc)),
    ]
    kd = [q1d - u1, q2d - u2, q4d - u4, q5d - u5]
    speed_constraints = [WF_cont.vel(N) & Y.x, WF_cont.vel(N) & Y.y, WF_cont.vel(N) & Y.z]
    g = P["g"]
    loads = [(Frame_mc, -P["mframe"] * g * Y.z), (Fork_mc, -P["mfork"] * g * Y.z),
             (WF_mc, -P["mwf"] * g * Y.z), (WR_mc, -P["mwr"] * g * Y.z)]
    kane = me.KanesMethod(N, q_ind=[q1, q2, q5], q_dependent=[q4],
                          configuration_constraints=[WF_cont.pos_from(WR_cont) & Y.z],
                          u_ind=[u2, u3, u5], u_dependent=[u1, u4, u6], velocity_constraints=speed_constraints,
                          kd_eqs=kd, constraint_solver="CRAMER")
    kane.kanes_equations(bodies, loads)
    return KaneModel(kane, [q1, q2, q5, q4], [u2, u3, u5], [u1, u4, u6], P, speed_constraints)


BUILDERS = {"pendulum": pendulum, "chain": chain, "disk": lambda n=None: rolling_disk()}
