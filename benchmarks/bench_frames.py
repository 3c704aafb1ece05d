"""Issue #17, kinematics by frames: what a frame layer would cost, measured four ways.

For the rolling disk and the Whipple bicycle (frames, points and bodies of
their system files; rolling left out) each route builds the mass centres'
accelerations a and the bodies' ω, α, then per body ½ m a·a and
½ α·Iα + α·(ω × Iω) (I in body axes), every coordinate's rate and
acceleration an unknown (no constraint solved): the same scalar by all four
routes, checked against the first at a random point.

  a. sympy.physics.vector the usual way: dynamicsymbols, orientnew,
     v2pt_theory, Point.acc, Vector.dot (pairwise, through dcm);
  b. the same ReferenceFrame/Vector algebra on gacli's plain symbols, d/dt by
     the transport theorem with gacli's memoised time differentiator;
  c. a minimal frame layer of our own (below): components per frame, d/dt by
     the transport theorem, each pair of parts dotted midway on the tree;
  d. gacli today: gacli.loader.frames as gacli.loader.loading uses it (DCMs to N, points in
     N), d/dt twice, a·a in N, trig.reduce (as gacli.mechanics.gibbs);
  d*. for scale, gacli.mechanics.gibbs's G after the constraints are solved (in u, u̇).

Counts: count_ops of the trees and after bench_bicycle.py's one-pass CSE. For
c and d also M (upper) and F over all q̈ from the partials (M_rs = Σ m V_r·V_s
+ Ω_rᵀIΩ_s, dots as the route dots a·a): a rhs before the constraints apply.
Usage: ``PYTHONPATH=. python benchmarks/bench_frames.py`` (about 30 s).
"""

from __future__ import annotations

import argparse
import random
import time
from dataclasses import dataclass
from pathlib import Path

import sympy as sp
import yaml
from sympy.physics import vector as pv

from gacli.loader import frames as F
from gacli.algebra import symbols as S
from gacli.algebra import trig
from gacli.mechanics.gibbs import _body_gibbs, acceleration_chain
from gacli.algebra.graph import shared_subexpressions, substitute
from gacli.mechanics.motions import body_motions
from gacli.mechanics.rates import solve_rates
from gacli.loader.loading import load
from gacli.numeric import Program

ROOT = Path(__file__).resolve().parent.parent
SYSTEMS = {"rolling disk": "rolling_disk.yaml", "bicycle": "whipple_bicycle.yaml"}
AXES = "xyz"


@dataclass(frozen=True)
class Geometry:
    """The frames, points and bodies of a system file, in gacli's plain symbols."""

    path: Path
    coordinates: tuple[str, ...]
    frames: tuple[tuple[str, str, str, sp.Expr], ...]  # (name, parent, axis, angle): one rotation each
    points: dict[str, tuple[str | None, str, tuple]]  # name → (origin, frame, components)
    bodies: tuple[tuple[str, str, str, sp.Expr, sp.Matrix], ...]  # (name, point, frame, mass, inertia)


def geometry(path: Path) -> Geometry:
    doc = yaml.safe_load(path.read_text(encoding="utf-8"))
    names = {n: S.value(n) for n in [*doc["parameters"], *doc["coordinates"]]}
    expr = lambda text: sp.sympify(str(text), locals=names)  # noqa: E731
    frames = []
    for name, decl in doc["frames"].items():
        parent, rotations = decl.get("parent", "N"), decl["rotations"]
        # A frame of several rotations becomes a chain of one-rotation frames: the tree stays simple.
        for i, (axis, angle) in enumerate(rotations):
            child = name if i == len(rotations) - 1 else f"{name}_{i}"
            frames.append((child, parent, axis.lower(), expr(angle)))
            parent = child
    points = {}
    for name, decl in doc["points"].items():
        (frame, comps), = [(k, v) for k, v in decl.items() if k != "from"]
        points[name] = (decl.get("from"), frame, tuple(expr(c) for c in comps))
    bodies = []
    for name, decl in doc["bodies"].items():
        i = decl["inertia"]
        matrix = sp.diag(*map(expr, i)) if not isinstance(i[0], list) else sp.Matrix([[expr(c) for c in r] for r in i])
        bodies.append((name, decl["position"], decl["frame"], expr(decl["mass"]), matrix))
    return Geometry(path, tuple(doc["coordinates"]), tuple(frames), points, tuple(bodies))


def chain(geo: Geometry):
    """d/dt on plain symbols: q → dot(q) → ddot(q) (no constraint solved)."""
    links = {S.value(c): S.rate(c) for c in geo.coordinates}
    return S.time_differentiator({**links, **{S.rate(c): S.rate(c, 2) for c in geo.coordinates}})


def rotational(omega, alpha, inertia) -> sp.Expr:
    """½ α·Iα + α·(ω × Iω), all three in body axes (as lists)."""
    w, al = sp.Matrix(omega), sp.Matrix(alpha)
    return (al.T * inertia * al)[0] / 2 + al.dot(w.cross(inertia * w))


# -- a. sympy.physics.vector with dynamicsymbols -----------------------------

def route_dynamic(geo: Geometry):
    q = {S.value(c): pv.dynamicsymbols(c) for c in geo.coordinates}
    N = pv.ReferenceFrame("N")
    frames = {"N": N}
    for name, parent, axis, angle in geo.frames:
        frames[name] = frames[parent].orientnew(name, "Axis", [angle.xreplace(q), getattr(frames[parent], axis)])
    (origin := pv.Point("O")).set_vel(N, 0)
    points = {}
    for name, (base, frame, comps) in geo.points.items():
        offset = sum((c.xreplace(q) * getattr(frames[frame], a) for c, a in zip(comps, AXES)), pv.Vector(0))
        if base is None:
            points[name] = origin.locatenew(name, offset)
            points[name].set_vel(N, offset.dt(N))
        else:
            points[name] = points[base].locatenew(name, offset)
            points[name].v2pt_theory(points[base], N, frames[frame])
    motions = [(points[pt].acc(N), frames[fr].ang_vel_in(N), frames[fr].ang_acc_in(N), frames[fr])
               for _, pt, fr, _, _ in geo.bodies]
    return motions, q


def products_dynamic(geo: Geometry, built):
    return [(mass * a.dot(a) / 2, rotational(w.to_matrix(B), al.to_matrix(B), inertia))
            for (_, _, _, mass, inertia), (a, w, al, B) in zip(geo.bodies, built[0])]


def to_plain(terms, q):
    """q(t), q', q'' → gacli's symbols, so that all routes are counted in the same symbols (not timed)."""
    t = pv.dynamicsymbols._t
    mapping = {}
    for s, f in q.items():  # the derivatives first: q(t) inside them must not be replaced before
        mapping.update({f.diff(t, 2): S.rate(s.name, 2), f.diff(t): S.rate(s.name), f: s})
    flat = substitute([e for pair in terms for e in pair], mapping)
    return list(zip(flat[::2], flat[1::2]))


# -- b. sympy.physics.vector on plain symbols, transport theorem ourselves ---

def route_plain_pv(geo: Geometry):
    d = chain(geo)
    N = pv.ReferenceFrame("N")
    frames = {"N": N}
    for name, parent, axis, angle in geo.frames:
        p = frames[parent]
        f = p.orientnew(name, "Axis", [angle, getattr(p, axis)])
        # orientnew differentiates the DCM in its own t: with plain symbols that is 0, so ω is set here.
        f.set_ang_vel(p, d(angle) * getattr(p, axis))
        frames[name] = f
    positions = {}
    for name, (base, frame, comps) in geo.points.items():
        offset = pv.Vector([(sp.Matrix(comps), frames[frame])])
        positions[name] = offset if base is None else positions[base] + offset
    motions = []
    for _, pt, fr, _, _ in geo.bodies:
        B = frames[fr]
        a = pv_dt(pv_dt(positions[pt], N, d), N, d)
        w = B.ang_vel_in(N).to_matrix(B)
        motions.append((a, w, w.applyfunc(d), B))
    return motions, None


def pv_dt(v, N, d):
    """d/dt in N of a Vector: each part's components differentiated, plus ω_part × part, kept in its frame."""
    out = pv.Vector(0)
    for comps, frame in v.args:
        part = pv.Vector([(comps, frame)])
        own = pv.Vector([(comps.applyfunc(d), frame)])
        out += own if frame == N else own + (frame.ang_vel_in(N).express(frame) ^ part)
    return out


# -- c. a minimal frame layer of our own ---------------------------------------

class Tree:
    """Frames as a tree: each child's DCM to its parent and its ω (relative to N) in its own axes."""

    def __init__(self, geo: Geometry, d):
        self.parent, self.dcm, self.omega, self.depth = {"N": None}, {}, {"N": (sp.S.Zero,) * 3}, {"N": 0}
        for name, parent, axis, angle in geo.frames:
            R = F.simple_rotation(axis, angle).tolist()  # v_parent = R v_child
            carried = F.rotate(transpose(R), self.omega[parent])
            spin = tuple(d(angle) if a == axis else sp.S.Zero for a in AXES)
            self.parent[name], self.dcm[name], self.depth[name] = parent, R, self.depth[parent] + 1
            self.omega[name] = add(carried, spin)

    def path(self, a: str, b: str) -> list[str]:
        """The frames from a to b along the tree, through their nearest common ancestor."""
        up_a, up_b = [a], [b]
        while up_a[-1] != up_b[-1]:
            deeper = up_a if self.depth[up_a[-1]] >= self.depth[up_b[-1]] else up_b
            deeper.append(self.parent[deeper[-1]])
        return up_a + up_b[-2::-1]

    def express(self, comps, path: list[str]):
        """Components carried along ``path`` (one frame to the next: up by R, down by Rᵀ)."""
        for here, there in zip(path, path[1:]):
            if self.parent.get(here) == there:
                comps = F.rotate(self.dcm[here], comps)
            else:
                comps = F.rotate(transpose(self.dcm[there]), comps)
        return comps


def transpose(rows):
    return [list(col) for col in zip(*rows)]


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def vec_dt(tree: Tree, v: dict, d) -> dict:
    """Transport theorem per part: d/dt_N (v in B) = (dv/dt in B) + ω_B × v, the result still in B."""
    return {f: add(tuple(map(d, c)), cross(tree.omega[f], c)) for f, c in v.items()}


def vec_dot(tree: Tree, u: dict, v: dict) -> sp.Expr:
    """Σ over pairs of parts, each pair met in the frame midway along the tree path between them."""
    terms = []
    for fu, cu in u.items():
        for fv, cv in v.items():
            mid = len(path := tree.path(fu, fv)) // 2
            x, y = tree.express(cu, path[:mid + 1]), tree.express(cv, path[::-1][:len(path) - mid])
            terms += [p * q for p, q in zip(x, y) if p != 0 and q != 0]
    return sp.Add(*terms)


def route_own(geo: Geometry):
    d = chain(geo)
    tree = Tree(geo, d)
    positions = {}
    for name, (base, frame, comps) in geo.points.items():
        # Components stay in the frame they are given in: a point's vector is its origin's plus one part.
        here = dict(positions[base]) if base else {}
        here[frame] = add(here[frame], comps) if frame in here else comps
        positions[name] = here
    motions = []
    for _, pt, fr, _, _ in geo.bodies:
        a = vec_dt(tree, vec_dt(tree, positions[pt], d), d)
        w = tree.omega[fr]
        motions.append((a, w, tuple(map(d, w))))
    return motions, tree


def products_own(geo: Geometry, built):
    """½ m a·a by the route's own dot product (c: the tree's; b: Vector.dot), then the rotational part."""
    motions, tree = built
    dot = (lambda a: vec_dot(tree, a, a)) if tree else (lambda a: a.dot(a))
    return [(mass * dot(a) / 2, rotational(w, al, inertia))
            for (_, _, _, mass, inertia), (a, w, al, *_) in zip(geo.bodies, motions)]


# -- d. gacli today: inertial components, trig.reduce ------------------------

def route_gacli(geo: Geometry):
    """gacli.loader.frames as gacli.loader.loading uses it: DCMs to N, positions in N, ω dt as forms in body axes."""
    d, coords = chain(geo), [S.value(c) for c in geo.coordinates]
    differential = lambda e: sp.Matrix([[sp.diff(e, c) for c in coords] + [0]])  # noqa: E731
    frames = {"N": F.inertial_frame(len(coords) + 1)}
    for name, parent, axis, angle in geo.frames:
        frames[name] = F.oriented(name, frames[parent], [(axis, angle)], differential)
    positions = {}
    for name, (base, frame, comps) in geo.points.items():
        here = F.in_inertial({frame: comps}, frames)
        positions[name] = here if base is None else F.add_vectors(positions[base], here)
    rates = sp.Matrix([S.rate(c) for c in geo.coordinates] + [0])
    motions = []
    for _, pt, fr, _, _ in geo.bodies:
        w = list(sp.Matrix(frames[fr].omega) * rates)
        motions.append(([d(d(c)) for c in positions[pt]], w, [d(e) for e in w]))
    return motions


def products_gacli(geo: Geometry, motions):
    return [(trig.reduce(mass * sp.Add(*[c ** 2 for c in a]) / 2), trig.reduce(rotational(w, al, inertia)))
            for (_, _, _, mass, inertia), (a, w, al) in zip(geo.bodies, motions)]


def route_gacli_real(geo: Geometry):
    """gacli's own G per body, constraints solved (what gacli.mechanics.gibbs forms): built and multiplied together."""
    system = load(geo.path)
    rates = solve_rates(system)
    d = S.time_differentiator(acceleration_chain(system, rates))
    return [(trig.reduce(_body_gibbs(m, rates, d, bool(rates.nonlinear))), sp.S.Zero)
            for m in body_motions(system, rates)]


# -- measuring -------------------------------------------------------------------

ROUTES = {  # label: (title, build, products)
    "a": ("a. physics.vector, dynamicsymbols", route_dynamic, products_dynamic),
    "b": ("b. physics.vector, plain symbols", route_plain_pv, products_own),
    "c": ("c. own frame layer (prototype)", route_own, products_own),
    "d": ("d. gacli today: N + trig.reduce", route_gacli, products_gacli),
    "d*": ("d*. gacli's G (gacli.mechanics.gibbs), constraints solved", route_gacli_real, None),
}


def run_route(label: str, geo: Geometry, repeat: int):
    """(best build seconds, best products seconds, built, [(½ m a·a, rotational part)] per body)."""
    _, build, products = ROUTES[label]
    best = [float("inf"), float("inf")]
    for _ in range(repeat):
        sp.core.cache.clear_cache()
        start = time.perf_counter()
        built = build(geo)
        middle = time.perf_counter()
        terms = products(geo, built) if products else built
        best = [min(best[0], middle - start), min(best[1], time.perf_counter() - middle)]
    return best[0], best[1], built, (to_plain(terms, built[1]) if label == "a" else terms)


def mass_forcing_ops(geo: Geometry, label: str, built) -> int:
    """CSE ops of M (upper) and F over all q̈, from partials, each dot product in the route's frames."""
    motions, tree = built if label == "c" else ([({"N": tuple(a)}, w, al) for a, w, al in built],
                                                Tree(geo, chain(geo)))
    acc = [S.rate(c, 2) for c in geo.coordinates]
    zero, entries = {q: 0 for q in acc}, {}
    for (_, _, _, m, inertia), (a, w, al) in zip(geo.bodies, motions):
        V = [{f: tuple(sp.diff(x, q) for x in c) for f, c in a.items()} for q in acc]
        rest = {f: tuple(x.xreplace(zero) for x in c) for f, c in a.items()}
        Om = [sp.Matrix([sp.diff(x, q) for x in al]) for q in acc]
        wv = sp.Matrix(w)  # the torque-like Iα_rest + ω × Iω, in body axes
        torque = inertia * sp.Matrix(al).xreplace(zero) + wv.cross(inertia * wv)
        for r in range(len(acc)):
            for s in range(r, len(acc)):
                entries.setdefault((r, s), []).append(m * vec_dot(tree, V[r], V[s]) + (Om[r].T * inertia * Om[s])[0])
            entries.setdefault(r, []).append(-m * vec_dot(tree, V[r], rest) - Om[r].dot(torque))
    exprs = [sp.Add(*parts) for parts in entries.values()]
    if label == "d":  # as gacli would: sin² + cos² reduced entry by entry
        exprs = [trig.reduce(e) for e in exprs]
    return cse_ops([e for e in exprs if e != 0])


def cse_ops(exprs) -> int:
    replacements, reduced = shared_subexpressions(list(exprs), sp.numbered_symbols("_t"))
    return int(sum(sp.count_ops(v) for _, v in replacements) + sum(sp.count_ops(e) for e in reduced))


def agreement(reference, terms, seed: int = 17) -> float:
    """Relative difference of Σ G between two routes at one random point (all symbols in [0.4, 1.6])."""
    ours, theirs = sp.Add(*[e for pair in terms for e in pair]), sp.Add(*[e for pair in reference for e in pair])
    rng, symbols = random.Random(seed), sorted(theirs.free_symbols | ours.free_symbols, key=lambda s: s.name)
    values = {s: rng.uniform(0.4, 1.6) for s in symbols}
    a, b = (Program([e])(values)[0] for e in (ours, theirs))
    return abs(a - b) / max(1.0, abs(b))


def measure(name: str, routes, repeat: int):
    """The table's rows for one system, and count_ops of ½ m a·a body by body for each route."""
    geo = geometry(ROOT / "systems" / SYSTEMS[name])
    rows, reference, per_body = [], None, {}
    for label in routes:
        build, prod, built, terms = run_route(label, geo, repeat)
        total, title = cse_ops([e for pair in terms for e in pair]), ROUTES[label][0]
        if label == "d*":  # as trees these G are millions of nodes: count_ops of the trees runs for minutes
            rows.append([name, title, f"{build:.3f}", "(in build)", "(too large)", "-", f"{total:,}", "-",
                         "(other scalar)"])
            continue
        per_body[label] = [int(sp.count_ops(t[0])) for t in terms]
        rot = sum(int(sp.count_ops(t[1])) for t in terms)
        mf = f"{mass_forcing_ops(geo, label, built):,}" if label in ("c", "d") else "-"
        check = "reference" if reference is None else f"{agreement(reference, terms):.0e}"
        reference = reference or terms
        rows.append([name, title, f"{build:.3f}", f"{prod:.3f}", f"{sum(per_body[label]):,}", f"{rot:,}",
                     f"{total:,}", mf, check])
    return rows, [b[0] for b in geo.bodies], per_body


def table(headers, rows) -> str:
    widths = [max(len(str(r[i])) for r in [headers, *rows]) for i in range(len(headers))]
    line = lambda r: "| " + " | ".join(str(c).ljust(w) for c, w in zip(r, widths)) + " |"  # noqa: E731
    return "\n".join([line(headers), "|" + "|".join("-" * (w + 2) for w in widths) + "|", *map(line, rows)])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--systems", default=",".join(SYSTEMS), help="comma-separated: " + ", ".join(SYSTEMS))
    parser.add_argument("--routes", default=",".join(ROUTES), help="comma-separated: " + ", ".join(ROUTES))
    parser.add_argument("--repeat", type=int, default=3, help="timings: best of this many rounds (default 3)")
    options = parser.parse_args(argv)
    rows, breakdown = [], []
    for name in options.systems.split(","):
        found, bodies, per_body = measure(name, options.routes.split(","), max(1, options.repeat))
        rows += found
        breakdown += [[name, ROUTES[label][0], ", ".join(f"{b} {n:,}" for b, n in zip(bodies, counts))]
                      for label, counts in per_body.items()]
    print(table(["system", "route", "build [s]", "G terms [s]", "ops ½ma·a", "ops rot.", "ops G after CSE",
                 "ops M,F after CSE", "agrees (rel.)"], rows))
    print("\n" + table(["system", "route", "count_ops of ½ m a·a per body (trees)"], breakdown))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
