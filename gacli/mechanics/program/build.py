"""The whole right-hand side as a straight-line program: rows, β, q̇, γ, then M and F unit by unit.

The chapter's steps, each one a few numbers at a time: the rolling rows
A = [A_d | A_i] (eq. 14.1) over the rates left once a free root is carried
by its contact; β = −A_d⁻¹ A_i and the dependent rates (eq. 14.7); the
kinematic equations; γ = −A_d⁻¹ b₀ from the rows' velocity-product term
b₀ (eq. 14.14); then each unit's share of M and F (eq. 14.19), the loads'
virtual work (eq. 14.13), and the potential's and the work form's.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra import turns
from gacli.algebra.matrices import rank
from gacli.algebra.spheres import Sphere, read_on
from gacli.frame_model import INERTIAL
from gacli.mechanics.program import rows as R
from gacli.mechanics.program.assemble import Passes, Sums, assemble
from gacli.mechanics.program.contacts import contact
from gacli.mechanics.program.formbodies import FormMotion, assemble_bodies
from gacli.mechanics.program.forms import TURNINGS, FormRows, form_rows, rates_held
from gacli.mechanics.program.frames import FrameTree
from gacli.mechanics.program.lines import line_loads
from gacli.mechanics.program.loads import distribute
from gacli.mechanics.program.motion import Motion
from gacli.mechanics.program.planar import planar_frames
from gacli.mechanics.program.record import Program, cost, finish
from gacli.mechanics.program.solve import Solver
from gacli.mechanics.program.support import Unsupported
from gacli.mechanics.program.tape import Tape
from gacli.mechanics.program.units import units
from gacli.mechanics.program.vectors import ONE, Pass, dot
from gacli.numeric.spheres import spheres
from gacli.model import System


def _setup(system: System, independent: tuple[str, ...] | None,
           forms: FormRows, above: bool = False) -> tuple[Motion, list, tuple | None]:
    """The tape, frames, contacts and points (none for a file without frames); the free root only
    once the independent rates are known, and only when no form row holds its coordinates;
    ``above``: spheres along their planes' frames (contacts.contact)."""
    model = system.frames
    coordinates = {c.name: S.value(c.name) for c in system.coordinates}
    time = S.time_chain(f.name for f in system.free_functions)
    tree = FrameTree(Tape(spheres(system)), model.edges if model is not None else (), coordinates, time)
    tree.tape.stage = "rows"
    links = {p.name: p for p in model.points} if model is not None else {}
    bodies = {b.name: b for b in model.bodies} if model is not None else {}
    rolling = model.rolling if model is not None else ()
    origins = dict(model.origins) if model is not None else {}
    contacts = [contact(tree, links, bodies[r.body], r, set(coordinates.values()), origins, above)
                for r in rolling]
    level = frozenset({INERTIAL, *(c.plane for c in contacts if _level(tree, c.plane, origins))})
    root = R.free_root(links, contacts, coordinates, independent, level) if independent is not None else None
    if root is not None and set(R.root_coordinates(links, root[0], coordinates)) & forms.names:
        root = None
    return Motion(tree, links, coordinates, contacts, root), contacts, root


def _level(tree: FrameTree, plane: str, origins: dict) -> bool:
    """Whether a frame's plane z = 0 is N's, its normal ±N.z: turned from N by constant angles alone
    (a z-down ground, [[x, pi]]), with no origin of its own."""
    chain, nz = tree.chain(plane)[:-1], tree.nz(plane)
    return (all(tree.constant(f) for f in chain) and not any(f in origins for f in chain)
            and nz[:2] == (0, 0) and nz[2] in (1, -1))


def _columns(motion: Motion, contacts: list, forms: FormRows, reduced: list[str]) -> tuple[R.Rows, dict]:
    """The contacts' kept rows, and every row's column per rate: the contacts' rows, then the forms'."""
    kept = R.rows(motion, contacts, reduced)
    stated = forms.columns(motion.tape, reduced)
    return kept, {q: kept.columns[q] + stated[q] for q in reduced}


def independent_rates(system: System) -> tuple[str, ...]:
    """The file's independent rates, or gacli's automatic choice from the rows over every rate."""
    if system.independent is not None:
        return tuple(system.independent)
    forms = form_rows(system)
    motion, contacts, _ = _setup(system, None, forms)
    names = list(system.rate_names)
    _, columns = _columns(motion, contacts, forms, names)
    return R.earliest_independent(R.numbers(motion.tape, columns, names), names)


def program_of(system: System, judge=None) -> Program:
    """The program of ``system`` (supported: support.static_reason is None); Unsupported otherwise.

    Where rows stated as forms can be turned (forms.FormRows.turnings), the program is built
    for the rows as stated and for each turning, and the cheapest kept (record.cost): turned,
    a linkage written with frames solves its loop by −l₃ and l₂ sin(θ₂ − θ₃); written in N
    components alone, its velocities stay in N, where the loop's plain rows cost as much.
    """
    independent = independent_rates(system)
    if set(independent) - set(system.rate_names):
        raise Unsupported("an independent rate is not a rate of the file")
    stated = _program(system, independent, None, False)
    planar = planar_frames(system)  # a planar chain written out, read as the frames its angle sums turn
    read = [] if planar is None else [p for p in _framed(replace(system, frames=planar), independent) if p is not None]
    grams = (False, True) if system.frames is None and not _far_cheaper(read, stated) else (False,)
    programs = [stated] + ([_program(system, independent, None, True)] if True in grams else [])
    for turning in range(TURNINGS):
        built = [_program(system, independent, turning, g) for g in grams]
        if built[0] is None:
            break
        programs += built
    programs += read
    if _spheres_above(system):
        programs.append(_program(system, independent, None, False, above=True))
    if form_rows(system).forms:  # rows stated in N's axes may turn with a vehicle's heading
        programs += [p for g in grams if (p := _program(system, independent, None, g, columns=True)) is not None]
    return _cheapest(programs, judge)


def _far_cheaper(read: list[Program], stated: Program) -> bool:
    """Whether the planar read of a large file without frames costs far less than its stated program:
    the program through the positions' dot products (gram) is then not built. It lost there in every
    file met (a five-link chain multiplied out: 1,008 against 368, 2 s of its 7 s text derive); it wins
    only small ones, where the read costs 0.6 of the stated program or more."""
    return bool(read) and cost(stated) > GRAM_SKIPPED_ABOVE and min(map(cost, read)) <= GRAM_FAR * cost(stated)


GRAM_SKIPPED_ABOVE = 300
GRAM_FAR = 0.55


def _cheapest(programs: list[Program], judge) -> Program:
    """The program of least cost (record.cost), or, among those within NEAR of it while they are
    small, the one whose generated code ``judge`` finds cheapest: the program's own count does not
    follow what code's candidates make of it (an offset slider-crank written out: programs of 91 and
    93 operations give code of 86 and 82, Kane 82)."""
    least = min(programs, key=cost)
    near = [p for p in programs if cost(p) <= NEAR * cost(least)]
    if judge is None or len(near) < 2 or cost(least) > JUDGED_OPERATIONS:
        return least
    return min(near, key=lambda p: (judge(p), cost(p)))


# Programs within this factor of the cheapest are judged by their generated code, while the cheapest
# has at most JUDGED_OPERATIONS operations (each judgement forms code's candidates).
NEAR = 1.05
JUDGED_OPERATIONS = 400


def _framed(system: System, independent: tuple[str, ...]) -> list[Program | None]:
    try:
        return [_program(system, independent, None, False)]
    except Unsupported:
        return []


def _spheres_above(system: System) -> bool:
    """A sphere rolls on a plane whose frame its own frame hangs from: the program is also built
    with that sphere's contact along the plane (contacts.contact), and the cheaper kept. Angles'
    rates as speeds: a spherical robot's ω along N is short; body rates: along the sphere's own
    frame it is u."""
    model = system.frames
    if model is None:
        return False
    bodies = {b.name: b for b in model.bodies}
    for r in model.rolling:
        if r.axle is None and r.semi_axes is None and bodies[r.body].frame != (r.on or INERTIAL):
            return True
    return False


def _program(system: System, independent: tuple[str, ...], turning: int | None, gram: bool,
             above: bool = False, columns: bool = False) -> Program | None:
    """The program with the stated rows as stated (``turning`` None) or turned (the turning-th of
    forms.FormRows.turnings), a file without frames' points through their dot products or not
    (``gram``, gacli.mechanics.program.gram); ``columns``: the dependent rates solved through
    the pairs of them that turn with an angle (solve.turned_columns). None when there is no
    such turning, or no such pair."""
    names = list(system.rate_names)
    forms = form_rows(system)
    motion, contacts, root = _setup(system, independent, forms, above)
    at_root = R.root_coordinates(motion.links, motion.root, motion.coordinates)
    _check_root_alone(motion, at_root)
    reduced = [q for q in names if q not in at_root]
    dependent = [q for q in reduced if q not in independent]
    if turning is not None:
        turnings = forms.turnings(dependent)
        if turning >= len(turnings):
            return None
        forms = turnings[turning]
    held = rates_held(forms, dependent)
    if held:
        raise Unsupported(f"a constraint nonlinear in the rates holds the dependent rate '{held[0]}'")
    others = [c for c in contacts if root is None or c is not root[1]]
    kept, rows = _columns(motion, others, forms, reduced)
    if len(kept.directions) + len(forms.forms) != len(dependent):
        raise Unsupported(f"the rows determine {len(kept.directions) + len(forms.forms)} rates, not the "
                          f"{len(dependent)} dependent ones")
    kept_on = motion.tape.spheres
    solver, passes = _rates(kept_on, motion, rows, R.time_column(motion, kept) + forms.dt(motion.tape), independent,
                            dependent, columns)
    if columns and not solver.turns:
        return None
    rates = _kinematics(motion, [c.name for c in system.coordinates], at_root, passes.actual)
    passes = _gamma(system, motion, kept, forms, solver, dependent, passes)
    return replace(_dynamics(system, motion, passes, rates, at_root, gram), independent=tuple(independent),
                   spheres=kept_on)


def _check_root_alone(motion: Motion, at_root) -> None:
    """The free root's coordinates (x, y of a vehicle) have no rates in the passes: their velocity
    is the root's, from its contact. A point other than the root written with them (a payload at
    [x, y, h], a force at [x, y, r]) would move as if they stood still."""
    symbols = {motion.coordinates[q] for q in at_root}
    for name, link in motion.links.items():
        if name != motion.root and any(c.free_symbols & symbols for c in link.components):
            raise Unsupported(f"the point '{name.rstrip('@')}' is written with the coordinates of the "
                              "rolling root; write it from the root instead")


def _rates(on: tuple[Sphere, ...], motion: Motion, columns: dict, dt: list, independent, dependent,
           turn: bool = False) -> tuple[Solver, Passes]:
    """β from A_d β = −A_i (eq. 14.7), β₀ from A_d β₀ = −a₀ where rows move with time, the dependent
    rates β u + β₀, and the partial passes (eq. 14.8)."""
    tape = motion.tape
    tape.stage = "solve"
    n = len(dependent)
    A_d = [[columns[q][i] for q in dependent] for i in range(n)]
    numeric = np.array([[tape.values(x)[0] if x != 0 else 0 for x in row] for row in A_d], dtype=complex)
    if n and rank(numeric) < n:
        raise Unsupported("the rows do not determine the dependent rates from the independent ones")
    solver = Solver(tape, A_d, on_spheres(motion, on), turn)
    beta, along = {}, {qi: {} for qi in (*independent, None)}
    for qi in independent:
        for qd, x in zip(dependent, solver.solve([-columns[qi][i] for i in range(n)], along[qi])):
            beta[(qd, qi)] = x
    beta0 = dict(zip(dependent, solver.solve([-a for a in dt], along[None]))) if any(a != 0 for a in dt) else {}
    rates = {qi: S.rate(qi) for qi in independent}
    for qd in dependent:
        rates[qd] = tape.let(sp.Add(*(beta[(qd, qi)] * rates[qi] for qi in independent), beta0.get(qd, 0)))
    heading = _heading(solver, dependent)
    partial = tuple(Pass(f"u_{qi}", {qi: ONE, **{qd: beta[(qd, qi)] for qd in dependent}},
                         along=_along(solver, heading, along[qi])) for qi in independent)
    if not beta0 and not any(motion.tree.timed(e) for e in motion.tree.edges):
        motion.tree.speeds = [(p, S.rate(qi)) for p, qi in zip(partial, independent)]
    moving = _along(solver, heading, along[None])  # β₀'s part, where rows move with time
    actual = {q: tape.let(sp.Add(*(p.rate_along(q) * rates[qi] for p, qi in zip(partial, independent)), moving[q]))
              for q in moving}
    return solver, Passes(partial, Pass("actual", rates, timed=True, along=actual), Pass("gamma", {}), heading)


def _heading(solver: Solver, dependent: list[str]) -> tuple | None:
    """(x, y, θ) of the solver's first turned pair (solve.turned_columns), or None."""
    if not solver.turns:
        return None
    a, b, _, _, angle = solver.turns[0]
    return dependent[a], dependent[b], angle


def _along(solver: Solver, heading: tuple | None, values: dict) -> dict:
    """The heading pair's rates along it, from what Solver.solve kept of one solve (zero if none)."""
    if heading is None:
        return {}
    a, b, _, _, _ = solver.turns[0]
    y = values.get((a, b), (sp.S.Zero, sp.S.Zero))
    return {heading[0]: y[0], heading[1]: y[1]}


def on_spheres(motion: Motion, kept: tuple[Sphere, ...]):
    """A squared row length read on the spheres the system keeps its coordinates on (gacli.mechanics
    .spheres), or None without such. Euler parameters' rows (body rates 2 G(e) ė and the unit norm
    e·ė = 0) are orthogonal, of squared length 4 e·e and e·e, and e·e = 1 is the system's own
    constraint: the program divides by 4 and 1, as Kane's ½ Eᵀ ω does, where the rows' own
    lengths cost a sum of squares and a division (a top in a quaternion frame: 73 → 61 operations
    after SymPy's cse, Kane 64). The closed forms keep e·e; both agree on the sphere, where the motion is
    (tests/test_program.py, tests/test_generated_numeric.py compare them there)."""
    if not kept:
        return None
    tape = motion.tape

    def length(e: sp.Expr) -> sp.Expr:
        on = read_on(tape.closed(e), kept)
        return e if on is None else tape.let(on)

    return length


def _kinematics(motion: Motion, names: list[str], at_root: dict, actual: Pass) -> dict[str, sp.Expr]:
    """q̇ of every coordinate: the solved rates, and the free root's N components (eq. 14.20)."""
    tape = motion.tape
    tape.stage = "kinematics"
    rates = {q: actual.rate(q) for q in names if q not in at_root}
    if motion.root is not None:
        v = motion.velocity(motion.root, actual, INERTIAL)
        for i, x in enumerate(motion.links[motion.root].components):
            if i not in at_root.values() and not tape.vanishes(v[i]):
                raise Unsupported(f"the root point '{motion.root}' moves along N's {'xyz'[i]} axis, where it "
                                  "has no coordinate")
        rates.update({q: v[i] for q, i in at_root.items()})
    return {q: rates[q] for q in names}


def _gamma(system: System, motion: Motion, kept: R.Rows, forms: FormRows, solver: Solver, dependent,
           passes: Passes) -> Passes:
    """γ = −A_d⁻¹ b₀, b₀ the rows' velocity-product term (eq. 14.14): the contacts', then the forms';
    the pass ρ = γ."""
    tape = motion.tape
    tape.stage = "gamma"
    acceleration = {}
    for c, _ in kept.directions:
        if c.body.name not in acceleration:
            acceleration[c.body.name] = motion.contact_acceleration0(c, passes.actual)
    b0 = [tape.let(dot(e, acceleration[c.body.name])) for c, e in kept.directions]
    b0 += forms.rest(tape, system, passes.actual)
    along: dict = {}
    gamma = dict(zip(dependent, solver.solve([-b for b in b0], along))) if dependent else {}
    gamma_pass = Pass("gamma", gamma, along=_along(solver, passes.heading, along))
    return Passes(passes.partial, passes.actual, gamma_pass, passes.heading)


def _dynamics(system: System, motion: Motion, passes: Passes, rates: dict, at_root: dict, gram: bool) -> Program:
    """M and F (eq. 14.19): every unit (or, without frames, every body), the loads at points of no
    unit, the potential and work."""
    tape, k = motion.tape, len(passes.partial)
    sums = Sums.empty(k)
    actual = passes.actual
    substitution = {S.rate(q): actual.rate(q) for q in system.rate_names if actual.rate(q) != S.rate(q)}
    substitution.update({S.rate(q): e for q, e in rates.items()})
    if system.frames is None:
        assemble_bodies(FormMotion(tape, system, passes, substitution, gram), sums)
    else:
        _units(system, motion, passes, substitution, sums)
    _potential_and_work(system, motion, passes, at_root, substitution, sums)
    return finish(tape, rates, sums, k)


def _units(system: System, motion: Motion, passes: Passes, substitution: dict, sums: Sums) -> None:
    tape = motion.tape
    coordinates = set(motion.coordinates.values())
    tape.stage = "body setup"
    groups = units(motion.tree, motion.links, system.frames.bodies, coordinates, passes.partial)
    tape.stage = "loads"
    # At its point a spring's force costs a dot product per speed; with the units, a moment r × f and f
    # read twice: the point is cheaper for few speeds (a crank-rocker's spring: 151 -> 137 operations,
    # Kane 131), the units for a free body's six (a spring at a corner: 129 against 164). A damper's
    # force, over ℓ², stays with the units: at its point the printout's quotients doubled an arm's
    # derive (5.8 -> 12 s) for 8 operations.
    few = len(passes.partial) <= LINE_POINT_SPEEDS
    at_points = [few and line.damping is None for line in system.frames.lines]
    apart, along = (line_loads(motion, passes.actual, tuple(line for line, at in zip(system.frames.lines, at_points)
                                                            if at is wanted)) for wanted in (True, False))
    shares, loose = distribute(motion.tree, motion.links, groups, system.frames.loads + along,
                               substitution, coordinates, apart)
    for u, share in zip(groups, shares):
        assemble(motion, u, share, passes, sums)
    tape.stage = "F"
    for point, f, frame in loose:
        for r, p in enumerate(passes.partial):
            sums.load(r, tape.let(dot(motion.velocity(point, p, frame), f)))


# Speeds up to which a line's force off its unit's centre does its work at its point (loads.distribute).
LINE_POINT_SPEEDS = 3


def _potential_and_work(system: System, motion: Motion, passes: Passes, at_root: dict, substitution: dict,
                        sums: Sums) -> None:
    """F_r += Σ_s (c_s − ∂V/∂q_s) δr_s/δu_r (eq. 14.13), the work form's coefficients c_s over every rate."""
    tape = motion.tape
    names = list(system.rate_names)
    # The lines are forces here (_units); the file's own potential and work are the rest.
    apart = system.frames is not None and system.frames.lines
    potential, work = (system.frames.potential, system.frames.work) if apart else (system.potential, system.work)
    potential = _folded(potential, [S.value(c.name) for c in system.coordinates])
    coefficient = {q: -sp.diff(potential, S.value(q)) for q in names}
    if work is not None:
        for q in names:
            coefficient[q] += work.coefficient(q).xreplace(substitution)
    coefficient = {q: tape.let(c) for q, c in coefficient.items() if c != 0}
    for r, p in enumerate(passes.partial):
        root = motion.velocity(motion.root, p, INERTIAL) if set(coefficient) & set(at_root) else None
        for q, c in coefficient.items():
            sums.load(r, c * (root[at_root[q]] if q in at_root else p.rate(q)))


def _folded(potential: sp.Expr, coordinates: list[sp.Symbol]) -> sp.Expr:
    """V with its products of sines and cosines folded into sines and cosines of sums, where shorter
    (gacli.algebra.turns): a chain's weight written with its angle sums multiplied out."""
    if not potential.has(sp.sin, sp.cos):
        return potential
    folded = turns.folded(potential, sorted(coordinates, key=str))
    return folded if folded is not None and sp.count_ops(folded) < sp.count_ops(potential) else potential
