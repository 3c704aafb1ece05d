"""KanesMethod references for the b6_ Whipple bicycles (reviewer 6).

b6_a, b6_b, b6_c reuse bench_kane.whipple_bicycle (SymPy's test_kane3 model;
its front contact formed from the wheel's geometry, at rest) with the
coordinates mapped to each file's names. b6_d, b6_e and b6_f are built here
from the physics: the material contact points of both wheels at rest.
"""
from pathlib import Path

import sympy as sp
from sympy.physics import mechanics as me

import bench_kane
from bench_kane import KaneModel
from models import Reference, _named, _symbols

HERE = Path(__file__).resolve().parent
t = me.dynamicsymbols._t


def _moore(names: dict, front: str) -> Reference:
    model = bench_kane.whipple_bicycle()
    q1, q2, q5, q4 = model.q
    u1, u4, u6 = model.u_dep
    return Reference(model, {q1: names["yaw"], q2: names["roll"], q5: names["steer"], q4: names["pitch"]},
                     {front: u6}, list(getattr(model.kane, "_f_h", [])), [q4], spread=0.3)


def b6_a() -> Reference:
    return _moore({"yaw": "q1", "roll": "q2", "steer": "q5", "pitch": "q4"}, "q6")


def b6_b() -> Reference:
    return _moore({"yaw": "yaw", "roll": "roll", "steer": "steer", "pitch": "pitch"}, "wheel_F")


def b6_c() -> Reference:
    return _moore({"yaw": "psi", "roll": "phi", "steer": "delta", "pitch": "theta"}, "thF")


SYSTEMS = {
    "b6_a": (HERE / "b6_a.yaml", b6_a, None),
    "b6_b": (HERE / "b6_b.yaml", b6_b, None),
    "b6_c": (HERE / "b6_c.yaml", b6_c, None),
}


# -- b6_d: the paper's names and axes (z down), rider point mass, steer torque -----

def b6_d() -> Reference:
    psi, phi, delta, theta = q = list(me.dynamicsymbols("psi phi delta theta"))
    u_psi, u_phi, u_theta, u_delta, uR, uF = me.dynamicsymbols("u_psi u_phi u_theta u_delta uR uF")
    P = _symbols("w c lam g rR mR IRxx IRyy xB zB mB IBxx IByy IBzz IBxz xH zH mH IHxx IHyy IHzz IHxz "
                 "rF mF IFxx IFyy mP xP zP T_delta")
    S = lambda n: P[n]  # noqa: E731
    N = me.ReferenceFrame("N")  # z down
    Yw = N.orientnew("Yw", "Axis", [psi, N.z])
    Rl = Yw.orientnew("Rl", "Axis", [phi, Yw.x])
    B = Rl.orientnew("B", "Axis", [theta, Rl.y])
    Hd = B.orientnew("Hd", "Axis", [S("lam"), B.y])   # Hd.z: the steer axis, down and forward
    Hs = Hd.orientnew("Hs", "Axis", [delta, Hd.z])
    H = Hs.orientnew("H", "Axis", [-S("lam"), Hs.y])
    Rw = me.ReferenceFrame("Rw")
    Fw = me.ReferenceFrame("Fw")
    Yw.set_ang_vel(N, u_psi * N.z)
    Rl.set_ang_vel(Yw, u_phi * Yw.x)
    B.set_ang_vel(Rl, u_theta * Rl.y)
    Hs.set_ang_vel(Hd, u_delta * Hd.z)
    H.set_ang_vel(Hs, 0)
    Rw.set_ang_vel(B, uR * B.y)
    Fw.set_ang_vel(H, uF * H.y)
    # rear: the geometric contact point is at rest as the material one is (rolling), hub from the wheel
    C_R = me.Point("C_R")
    C_R.set_vel(N, 0)
    hubR = C_R.locatenew("hubR", -S("rR") * Rl.z)
    hubR.v2pt_theory(C_R, N, Rw)
    Bcm = hubR.locatenew("Bcm", S("xB") * B.x + (S("zB") + S("rR")) * B.z)
    Bcm.v2pt_theory(hubR, N, B)
    rider = hubR.locatenew("rider", S("xP") * B.x + (S("zP") + S("rR")) * B.z)
    rider.v2pt_theory(hubR, N, B)
    axis = hubR.locatenew("axis", (S("w") + S("c")) * B.x + S("rR") * B.z)
    axis.v2pt_theory(hubR, N, B)
    hubF = axis.locatenew("hubF", -S("c") * H.x - S("rF") * H.z)
    hubF.v2pt_theory(axis, N, H)
    Hcm = axis.locatenew("Hcm", (S("xH") - S("w") - S("c")) * H.x + S("zH") * H.z)
    Hcm.v2pt_theory(axis, N, H)
    # front contact: lowest point of the front wheel's circle (z down: along +N.z in the wheel plane)
    down = N.z
    radial = (down - (down & H.y) * H.y).normalize()
    C_F = hubF.locatenew("C_F", S("rF") * radial)
    C_F.v2pt_theory(hubF, N, Fw)
    conf = [C_F.pos_from(C_R) & N.z]
    vel = [C_F.vel(N) & Yw.x, C_F.vel(N) & Yw.y, C_F.vel(N) & Yw.z]
    bodies = [
        me.RigidBody("rear_wheel", hubR, Rw, S("mR"), (me.inertia(B, S("IRxx"), S("IRyy"), S("IRxx")), hubR)),
        me.RigidBody("rear_frame", Bcm, B, S("mB"),
                     (me.inertia(B, S("IBxx"), S("IByy"), S("IBzz"), 0, 0, S("IBxz")), Bcm)),
        me.Particle("rider", rider, S("mP")),
        me.RigidBody("fork", Hcm, H, S("mH"), (me.inertia(H, S("IHxx"), S("IHyy"), S("IHzz"), 0, 0, S("IHxz")), Hcm)),
        me.RigidBody("front_wheel", hubF, Fw, S("mF"), (me.inertia(H, S("IFxx"), S("IFyy"), S("IFxx")), hubF)),
    ]
    g = S("g")
    loads = [(hubR, S("mR") * g * N.z), (Bcm, S("mB") * g * N.z), (rider, S("mP") * g * N.z),
             (Hcm, S("mH") * g * N.z), (hubF, S("mF") * g * N.z),
             (H, S("T_delta") * Hd.z), (B, -S("T_delta") * Hd.z)]
    kd = [psi.diff(t) - u_psi, phi.diff(t) - u_phi, theta.diff(t) - u_theta, delta.diff(t) - u_delta]
    kane = me.KanesMethod(N, q_ind=[psi, phi, delta], q_dependent=[theta], configuration_constraints=conf,
                          u_ind=[u_phi, u_delta, uR], u_dependent=[u_psi, u_theta, uF],
                          velocity_constraints=vel, kd_eqs=kd, constraint_solver="CRAMER")
    kane.kanes_equations(bodies, loads)
    model = KaneModel(kane, [psi, phi, delta, theta], [u_phi, u_delta, uR], [u_psi, u_theta, uF], P, vel)
    return Reference(model, {psi: "psi", phi: "phi", delta: "delta", theta: "theta"}, {"thF": uF},
                     conf, [theta], spread=0.3, guess={"theta": 0.0})


SYSTEMS["b6_d"] = (HERE / "b6_d.yaml", b6_d, None)


# -- b6_e, b6_f: SymPy's test_kane3 geometry, other speeds ----------------------------

def _moore_speeds(forward: bool, u_ind_names: list, coords: dict, rates: dict) -> Reference:
    """The test_kane3 bicycle with a chosen independent set.

    forward: the rear contact point moves at v along Y.x (v a speed) and the
    rear wheel's material contact point is at rest (its Y.x row a velocity
    constraint); otherwise the rear contact is taken at rest as in the test.
    """
    q1, q2, q4, q5 = me.dynamicsymbols("q1 q2 q4 q5")
    U = dict(zip("u1 u2 u3 u4 u5 u6 v".split(), me.dynamicsymbols("u1 u2 u3 u4 u5 u6 v")))
    u1, u2, u3, u4, u5, u6, v = (U[n] for n in "u1 u2 u3 u4 u5 u6 v".split())
    names = ("WFrad WRrad htangle forkoffset forklength framelength forkcg1 forkcg3 framecg1 framecg3 "
             "Iwr11 Iwr22 Iwf11 Iwf22 Iframe11 Iframe22 Iframe33 Iframe31 Ifork11 Ifork22 Ifork33 Ifork31 "
             "g mframe mfork mwf mwr")
    P = _symbols(names)
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [q1, N.z])
    R = Y.orientnew("R", "Axis", [q2, Y.x])
    Frame = R.orientnew("Frame", "Axis", [q4 + P["htangle"], R.y])
    TempFrame = Frame.orientnew("TempFrame", "Axis", [-P["htangle"], Frame.y])
    Fork = Frame.orientnew("Fork", "Axis", [q5, Frame.x])
    TempFork = Fork.orientnew("TempFork", "Axis", [-P["htangle"], Fork.y])
    WR = me.ReferenceFrame("WR")
    WF = me.ReferenceFrame("WF")
    Y.set_ang_vel(N, u1 * Y.z)
    R.set_ang_vel(Y, u2 * R.x)
    Frame.set_ang_vel(R, u4 * Frame.y)
    Fork.set_ang_vel(Frame, u5 * Fork.x)
    WR.set_ang_vel(Frame, u3 * Frame.y)
    WF.set_ang_vel(Fork, u6 * Fork.y)
    C_R = me.Point("C_R")
    hubR = C_R.locatenew("hubR", P["WRrad"] * R.z)
    vel = []
    if forward:
        C_R.set_vel(N, v * Y.x)
        hubR.v2pt_theory(C_R, N, R)           # the vector C_R -> hub is fixed in R
        matR = hubR.locatenew("matR", -P["WRrad"] * R.z)
        matR.v2pt_theory(hubR, N, WR)         # the rear wheel's material point at the contact
        vel.append(matR.vel(N) & Y.x)         # its Y.y and Y.z parts vanish identically
    else:
        C_R.set_vel(N, 0)
        hubR.v2pt_theory(C_R, N, WR)
    steer = hubR.locatenew("steer", P["framelength"] * Frame.z)
    steer.v2pt_theory(hubR, N, Frame)
    frame_mc = hubR.locatenew("frame_mc", -P["framecg1"] * Frame.x + P["framecg3"] * Frame.z)
    frame_mc.v2pt_theory(hubR, N, Frame)
    fork_mc = steer.locatenew("fork_mc", -P["forkcg1"] * Fork.x + P["forkcg3"] * Fork.z)
    fork_mc.v2pt_theory(steer, N, Fork)
    hubF = steer.locatenew("hubF", P["forklength"] * Fork.x + P["forkoffset"] * Fork.z)
    hubF.v2pt_theory(steer, N, Fork)
    down = -Y.z
    C_F = hubF.locatenew("C_F", P["WFrad"] * (down - (down & Fork.y) * Fork.y).normalize())
    C_F.v2pt_theory(hubF, N, WF)
    vel += [C_F.vel(N) & Y.x, C_F.vel(N) & Y.y, C_F.vel(N) & Y.z]
    conf = [C_F.pos_from(C_R) & Y.z]
    bodies = [
        me.RigidBody("frame", frame_mc, Frame, P["mframe"],
                     (me.inertia(TempFrame, P["Iframe11"], P["Iframe22"], P["Iframe33"], 0, 0, P["Iframe31"]), frame_mc)),
        me.RigidBody("fork", fork_mc, Fork, P["mfork"],
                     (me.inertia(TempFork, P["Ifork11"], P["Ifork22"], P["Ifork33"], 0, 0, P["Ifork31"]), fork_mc)),
        me.RigidBody("wr", hubR, WR, P["mwr"], (me.inertia(Frame, P["Iwr11"], P["Iwr22"], P["Iwr11"]), hubR)),
        me.RigidBody("wf", hubF, WF, P["mwf"], (me.inertia(Fork, P["Iwf11"], P["Iwf22"], P["Iwf11"]), hubF)),
    ]
    g = P["g"]
    loads = [(b.masscenter, -b.mass * g * Y.z) for b in bodies]
    kd = [q1.diff(t) - u1, q2.diff(t) - u2, q4.diff(t) - u4, q5.diff(t) - u5]
    all_u = ["u1", "u2", "u3", "u4", "u5", "u6"] + (["v"] if forward else [])
    u_ind = [U[n] for n in u_ind_names]
    u_dep = [U[n] for n in all_u if n not in u_ind_names]
    kane = me.KanesMethod(N, q_ind=[q1, q2, q5], q_dependent=[q4], configuration_constraints=conf,
                          u_ind=u_ind, u_dependent=u_dep, velocity_constraints=vel, kd_eqs=kd,
                          constraint_solver="CRAMER")
    kane.kanes_equations(bodies, loads)
    model = KaneModel(kane, [q1, q2, q5, q4], u_ind, u_dep, P, vel)
    qs = {"yaw": q1, "roll": q2, "steer": q5, "pitch": q4}
    return Reference(model, {qs[k]: name for k, name in coords.items()}, {k: U[n] for k, n in rates.items()},
                     conf, [q4], spread=0.3)


def b6_e() -> Reference:
    return _moore_speeds(True, ["u2", "v", "u5"], {"yaw": "yaw", "roll": "roll", "steer": "steer", "pitch": "pitch"},
                         {"wheel_R": "u3", "wheel_F": "u6"})


def b6_f() -> Reference:
    return _moore_speeds(False, ["u5", "u2", "u6"], {"yaw": "yaw", "roll": "roll", "steer": "steer", "pitch": "pitch"},
                         {"wheel_R": "u3"})


SYSTEMS["b6_e"] = (HERE / "b6_e.yaml", b6_e, None)
SYSTEMS["b6_f"] = (HERE / "b6_f.yaml", b6_f, None)
