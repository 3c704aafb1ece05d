"""Frames, points, rolling contact: systems beyond the textbook, checked against KanesMethod.

Each system is written with the frame vocabulary in ``systems/`` and derived
independently here with SymPy's KanesMethod, in its own coordinates and
speeds; u̇ from both agree at random states.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
import sympy.physics.mechanics as me

from conftest import derived


def gacli_accelerations(d, values: dict[str, float]) -> np.ndarray:
    """u̇ = M⁻¹ F of a derivation at named values (state, parameters, inputs)."""
    point = {s: values[s.name] for s in (d.mass_matrix.free_symbols | d.forcing.free_symbols)}
    M = np.array(d.mass_matrix.xreplace(point).evalf(30).tolist(), dtype=float)
    F = np.array(d.forcing.xreplace(point).evalf(30).tolist(), dtype=float).ravel()
    return np.linalg.solve(M, F)


def kane_accelerations(kane: me.KanesMethod, point: dict) -> np.ndarray:
    M = np.array(me.msubs(kane.mass_matrix, point).evalf(30).tolist(), dtype=float)
    F = np.array(me.msubs(kane.forcing, point).evalf(30).tolist(), dtype=float).ravel()
    return np.linalg.solve(M, F)


def close(a, b, rtol=1e-10) -> bool:
    """Compare u̇; Kane's solution also holds the dependent speeds' rates, after the independent ones."""
    b = b[: len(a)]
    return np.linalg.norm(a - b) <= rtol * max(1.0, np.linalg.norm(b))


# -- the rolling disk -----------------------------------------------------------

def kane_rolling_disk():
    yaw, lean, spin = me.dynamicsymbols("yaw lean spin")
    u1, u2, u3 = me.dynamicsymbols("u1:4")
    m, r, g = sp.symbols("m r g")
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    R = L.orientnew("R", "Axis", [spin, L.y])
    R.set_ang_vel(N, u1 * N.z + u2 * Y.x + u3 * L.y)
    C = me.Point("C")
    C.set_vel(N, 0)                      # the material point at the contact: rolling
    D = C.locatenew("D", r * L.z)
    D.v2pt_theory(C, N, R)
    disk = me.RigidBody("disk", D, R, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), D))
    kd = [yaw.diff() - u1, lean.diff() - u2, spin.diff() - u3]
    kane = me.KanesMethod(N, q_ind=[yaw, lean, spin], u_ind=[u1, u2, u3], kd_eqs=kd)
    kane.kanes_equations([disk], [(D, -m * g * N.z)])
    return kane, (yaw, lean, spin), (u1, u2, u3), (m, r, g)


def test_rolling_disk_against_kane(rng):
    d = derived("rolling_disk")
    assert d.independent == ("yaw", "lean", "spin")
    kane, q, u, params = kane_rolling_disk()
    for _ in range(20):
        values = {"x": rng.uniform(-1, 1), "y": rng.uniform(-1, 1), "yaw": rng.uniform(-3, 3),
                  "lean": rng.uniform(-1.2, 1.2), "spin": rng.uniform(-3, 3),
                  "m": rng.uniform(0.5, 2), "r": rng.uniform(0.2, 1), "g": 9.81}
        rates = rng.uniform(-2, 2, 3)
        values.update({f"dot({n})": w for n, w in zip(("yaw", "lean", "spin"), rates)})
        point = {**dict(zip(q, (values["yaw"], values["lean"], values["spin"]))), **dict(zip(u, rates)),
                 **dict(zip(params, (values["m"], values["r"], values["g"])))}
        assert close(gacli_accelerations(d, values), kane_accelerations(kane, point))


# -- the Chaplygin sleigh ---------------------------------------------------------

def kane_sleigh():
    x, y, th = me.dynamicsymbols("x y theta")
    u1, u2, u3 = me.dynamicsymbols("u1:4")      # along the blade, turning rate, across the blade
    m, I, b, F = sp.symbols("m I b F")
    N = me.ReferenceFrame("N")
    S = N.orientnew("S", "Axis", [th, N.z])
    S.set_ang_vel(N, u2 * N.z)
    P = me.Point("P")
    P.set_vel(N, u1 * S.x + u3 * S.y)
    G = P.locatenew("G", b * S.x)
    G.v2pt_theory(P, N, S)
    body = me.RigidBody("sleigh", G, S, m, (me.inertia(S, 0, 0, I), G))
    kd = [x.diff() - (u1 * sp.cos(th) - u3 * sp.sin(th)), y.diff() - (u1 * sp.sin(th) + u3 * sp.cos(th)),
          th.diff() - u2]
    kane = me.KanesMethod(N, q_ind=[x, y, th], u_ind=[u1, u2], u_dependent=[u3],
                          velocity_constraints=[u3], kd_eqs=kd)
    kane.kanes_equations([body], [(P, F * S.x)])
    return kane, th, (u1, u2, u3), (m, I, b, F)


def test_chaplygin_sleigh_against_kane(rng):
    d = derived("chaplygin_sleigh")
    assert d.independent == ("s", "theta")
    kane, th, (u1, u2, u3), (m, I, b, F) = kane_sleigh()
    for _ in range(20):
        v = {"x": rng.uniform(-1, 1), "y": rng.uniform(-1, 1), "theta": rng.uniform(-3, 3),
             "dot(s)": rng.uniform(-2, 2), "dot(theta)": rng.uniform(-2, 2),
             "m": rng.uniform(0.5, 2), "I": rng.uniform(0.05, 1), "b": rng.uniform(0.1, 1), "F": rng.uniform(-1, 1)}
        point = {th: v["theta"], u1: v["dot(s)"], u2: v["dot(theta)"], u3: 0,
                 m: v["m"], I: v["I"], b: v["b"], F: v["F"]}
        assert close(gacli_accelerations(d, v), kane_accelerations(kane, point))


# -- the differential-drive robot ----------------------------------------------------

def kane_differential_drive():
    x, y, th, pl, pr = me.dynamicsymbols("x y theta phi_L phi_R")
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1:6")
    m_c, I_c, m_w, A_w, C_w, r, w, d, T_L, T_R = sp.symbols("m_c I_c m_w A_w C_w r w d T_L T_R")
    N = me.ReferenceFrame("N")
    C = N.orientnew("C", "Axis", [th, N.z])
    WL = C.orientnew("WL", "Axis", [pl, C.y])
    WR = C.orientnew("WR", "Axis", [pr, C.y])
    C.set_ang_vel(N, u5 * N.z)
    WL.set_ang_vel(N, u5 * N.z + u1 * C.y)
    WR.set_ang_vel(N, u5 * N.z + u2 * C.y)
    A = me.Point("A")
    A.set_vel(N, u3 * N.x + u4 * N.y)
    G = A.locatenew("G", d * C.x)
    HL = A.locatenew("HL", w * C.y)
    HR = A.locatenew("HR", -w * C.y)
    for p in (G, HL, HR):
        p.v2pt_theory(A, N, C)
    # The wheels' material points at the contacts do not slip.
    vL = HL.vel(N) + WL.ang_vel_in(N).cross(-r * N.z)
    vR = HR.vel(N) + WR.ang_vel_in(N).cross(-r * N.z)
    constraints = [vL.dot(N.x), vL.dot(N.y), vR.dot(C.x)]
    bodies = [me.RigidBody("chassis", G, C, m_c, (me.inertia(C, I_c, I_c, I_c), G)),
              me.RigidBody("left", HL, WL, m_w, (me.inertia(WL, A_w, C_w, A_w), HL)),
              me.RigidBody("right", HR, WR, m_w, (me.inertia(WR, A_w, C_w, A_w), HR))]
    loads = [(WL, T_L * C.y), (WR, T_R * C.y), (C, -(T_L + T_R) * C.y)]
    kd = [x.diff() - u3, y.diff() - u4, th.diff() - u5, pl.diff() - u1, pr.diff() - u2]
    kane = me.KanesMethod(N, q_ind=[x, y, th, pl, pr], u_ind=[u1, u2], u_dependent=[u3, u4, u5],
                          velocity_constraints=constraints, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    params = (m_c, I_c, m_w, A_w, C_w, r, w, d, T_L, T_R)
    return kane, (th, pl, pr), (u1, u2, u3, u4, u5), params


def test_differential_drive_against_kane(rng):
    d = derived("differential_drive")
    assert d.independent == ("phi_L", "phi_R")
    kane, (th, pl, pr), u, params = kane_differential_drive()
    names = ("m_c", "I_c", "m_w", "A_w", "C_w", "r", "w", "d", "T_L", "T_R")
    for _ in range(20):
        v = {n: rng.uniform(0.1, 2) for n in names}
        v.update({"x": rng.uniform(-1, 1), "y": rng.uniform(-1, 1), "theta": rng.uniform(-3, 3),
                  "phi_L": rng.uniform(-3, 3), "phi_R": rng.uniform(-3, 3),
                  "dot(phi_L)": rng.uniform(-2, 2), "dot(phi_R)": rng.uniform(-2, 2)})
        # The dependent speeds of Kane's formulation, from the rolling kinematics.
        rate = {n: float(e.xreplace({s: v[s.name] for s in e.free_symbols}))
                for n, e in d.kinematic_equations}
        point = {th: v["theta"], pl: v["phi_L"], pr: v["phi_R"], u[0]: v["dot(phi_L)"], u[1]: v["dot(phi_R)"],
                 u[2]: rate["x"], u[3]: rate["y"], u[4]: rate["theta"],
                 **{p: v[n] for p, n in zip(params, names)}}
        assert close(gacli_accelerations(d, v), kane_accelerations(kane, point))


def test_rolling_disk_in_frames_equals_format_1(rng):
    """The frame vocabulary derives what the hand-written format-1 file states."""
    from conftest import ROOT
    from gacli.mechanics.equations import derive
    from gacli.loader.loading import load

    by_hand = derive(load(ROOT / "tests" / "cases" / "rolling_disk_format1.yaml"))
    derived_ = derived("rolling_disk")
    for _ in range(10):
        v = {"x": 0.1, "y": 0.2, "yaw": rng.uniform(-3, 3), "lean": rng.uniform(-1, 1), "spin": rng.uniform(-3, 3),
             "m": 2.0, "r": 0.3, "g": 9.81, "dot(yaw)": rng.uniform(-2, 2), "dot(lean)": rng.uniform(-2, 2),
             "dot(spin)": rng.uniform(-2, 2)}
        assert close(gacli_accelerations(derived_, v), gacli_accelerations(by_hand, v), rtol=1e-11)


def test_vectors_in_frames_are_the_matrix_products_exactly():
    """in_inertial skips Matrix for speed; its entries must be the very expressions Matrix forms."""
    from gacli.loader import frames as F

    q, r, a, b = sp.symbols("q r a b", real=True)
    width = 3

    def differential(angle):
        return sp.Matrix([[sp.diff(angle, q), sp.diff(angle, r), 0]])

    N = F.inertial_frame(width)
    A = F.oriented("A", N, [("z", q), ("x", r)], differential)
    B = F.oriented("B", A, [("y", sp.pi / 2)], differential)  # an integer dcm
    frames = {"N": N, "A": A, "B": B}
    vectors = [(a, 0, b * sp.cos(q)), (0, 0, 0), (1, 2, sp.Rational(1, 3)), (a + b, -a, 0), (0, r, 1)]
    for name in frames:
        for v in vectors:
            expected = tuple(sp.Matrix(frames[name].dcm) * sp.Matrix(v))
            assert F.in_inertial({name: v}, frames) == expected
    for u in vectors:
        for v in vectors:
            expected = tuple(sp.zeros(3, 1) + sp.Matrix(A.dcm) * sp.Matrix(u) + sp.Matrix(B.dcm) * sp.Matrix(v))
            assert F.in_inertial({"A": u, "B": v}, frames) == expected
            assert F.add_vectors(u, v) == tuple(sp.Matrix(u) + sp.Matrix(v))
