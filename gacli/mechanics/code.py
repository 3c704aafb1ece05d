"""q̇, M and F as generated code computes them: the straight-line program, wherever it takes the system.

Generated code computes the equations of :mod:`gacli.mechanics.program`: the
same q̇, M and F as the chapter's closed forms (eq. 14.19), as a
straight-line program over the frame tree, or over the bodies' positions and
rotation forms of a file without frames, with the dependent rates and
accelerations solved as numbers (issue #28: one engine). The closed forms
(:mod:`gacli.mechanics.equations`) are what text and LaTeX print; they reach
generated code only where the builder does not take a system, or chooses
other independent speeds than the chapter's route (a rolling contact's rows
with the speeds left to gacli), so that the command line and
``gacli.emit(gacli.derive(...))`` always write the same code.

The program is taken in the cheapest of a few forms (:func:`from_program`):
its inlinings as shared graphs or in SymPy's canonical form, each as given,
tidied by the display's simplifier, reduced by sin² + cos² = 1, or with the
common factors of its sums drawn out; counted by operations after the code
emitters' own CSE (:func:`gacli.algebra.graph.cse_operations`: SymPy's
``cse`` where no tree is large), which is what generated code computes. A
program's expressions are graphs sharing their subexpressions, built
unevaluated (:func:`gacli.mechanics.program.inline`); they must be walked
with :mod:`gacli.algebra.graph`, never as trees.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.angles import reduced
from gacli.algebra.graph import cse_operations, is_small, postorder, trees_within
from gacli.algebra.angle_sums import angle_sums_compacted
from gacli.algebra.readable import readable
from gacli.algebra.spheres import remainder_on
from gacli.algebra.terms import factor_terms
from gacli.errors import OutOfTime
from gacli.mechanics.program import Program, build_program
from gacli.mechanics.program.record import program_operations
from gacli.model import System


@dataclass(frozen=True)
class CodeEquations:
    """What a generated rhs evaluates, and which route it comes from ("closed" or "program")."""

    route: str
    kinematic_equations: tuple[tuple[str, sp.Expr], ...]  # (coordinate, q̇), declaration order
    mass_matrix: tuple[tuple[tuple[int, int], sp.Expr], ...]  # the nonzero entries, row-major
    forcing: tuple[sp.Expr, ...]
    operations: int  # after the code emitters' CSE (gacli.algebra.graph.cse_operations)

    def dense_mass_matrix(self) -> sp.ImmutableMatrix:
        """M as a k × k matrix, zero where code stores no entry."""
        k, entries = len(self.forcing), dict(self.mass_matrix)
        return sp.ImmutableMatrix(k, k, lambda i, j: entries.get((i, j), sp.S.Zero))


def from_program(program: Program, names: tuple[str, ...]) -> CodeEquations:
    """The program's cheapest inlining (:attr:`Program.inlinings`); past the trees
    SymPy's cse takes, its operations are the program's own (what the one-pass CSE counts to).
    Remembered for the last few programs: the builder judges the programs it chose between by it."""
    for seen, seen_names, code in _CODE:
        if seen is program and seen_names == names:
            return code
    code = _from_program(program, names)
    _CODE[:] = [(program, names, code), *_CODE[:_REMEMBERED - 1]]
    return code


# (program, names, code) of the last few programs asked for (the builder's near-cheapest ones).
_CODE: list = []
_REMEMBERED = 6


def _from_program(program: Program, names: tuple[str, ...]) -> CodeEquations:
    forms, small = program.inlinings
    if not small:
        return _inlined(program, names, *forms[0][0], operations=program_operations(program))
    inlined = [_inlined(program, names, *f, operations=count) for f, count in forms]
    # Each entry rewritten once however often it stands: M's twin entries, and the inlinings'
    # shared ones (a wheelchair's readable candidate took 5.7 s, most of it on such repeats).
    tidied, reduced_ = _once(readable), _once(_trigonometric)
    candidates = [factored(c) for c in inlined]
    cheapest = min(inlined, key=lambda c: c.operations)
    exprs = _expressions(cheapest)
    # Each inlining tidied: the tidier's result does not follow the inlining's count (a ball on a
    # turntable: 204 and 208 operations inlined, 129 and 108 tidied).
    for c in inlined:
        if trees_within(_expressions(c), TIDIED_TREES):
            candidates += [_each(c, reduced_)] + ([] if _over_a_loop(c) else [_each(c, tidied)])
    if program.spheres and trees_within(exprs, FACTORED_TREES):
        candidates += _on_spheres(inlined, program.spheres, tidied)
    if trees_within(exprs, FACTORED_TREES) and any(_rational(e) for e in exprs):  # the cheapest form alone
        candidates.append(_each(cheapest, lambda e: _divided(e) if _rational(e) else factor_terms(e)))
    best = min(candidates, key=lambda c: c.operations)
    return min((best, _each(best, _compacted)), key=lambda c: c.operations)  # the first when equal


def _compacted(e: sp.Expr) -> sp.Expr:
    """A small entry with its pairs sin x cos y ± cos x sin y written as one sine or cosine of the sum
    where that is shorter (gacli.algebra.angle_sums.angle_sums_compacted): a double pendulum's
    l₂ m₂ (sin a₁ sin a₂ − cos a₁ cos a₂)/2 is −l₂ m₂ cos(a₁ + a₂)/2, whose cosine F holds already
    (a cart with an inverted double pendulum: 110 → 94 operations, Kane 109)."""
    if not is_small(e, REDUCED_TREE) or not e.has(sp.sin, sp.cos):
        return e
    compact = angle_sums_compacted(e)
    return compact if sp.count_ops(compact) < sp.count_ops(e) else e


def _over_a_loop(code: CodeEquations) -> bool:
    """Whether an entry divides by the sine or cosine of a combination of angles, a loop's dead point
    l sin(θ_a − θ_b): tidied for display, such a linkage's quotients are multiplied out and grow (in
    190 files of the corpus and the Kane set's variants the tidied form never won where this holds,
    and cost ten linkages 10 s)."""
    for node in postorder(_expressions(code)):
        if node.is_Pow and node.exp.is_negative:
            for factor in sp.Mul.make_args(node.base):
                base = factor.base if factor.is_Pow else factor
                if isinstance(base, (sp.sin, sp.cos)) and not base.args[0].is_Symbol:
                    return True
    return False


def _on_spheres(inlined: list[CodeEquations], spheres: tuple, tidied) -> list[CodeEquations]:
    """Each inlining read on the spheres the motion keeps to (gacli.numeric.spheres), then factored
    or tidied: the polynomials in Euler parameters that e·e = 1 shortens (a top's m l² (e·e)², a
    gyrostat's offset wheels written with direction cosines: 283 → 175 operations, Kane 263)."""
    on = _once(lambda e: remainder_on(e, spheres))
    out = []
    for c in inlined:
        read = _each(c, on)
        out += [factored(read), _each(read, tidied)]
    return out


def _once(rewrite):
    """``rewrite`` remembered by its argument, for one choice of code."""
    seen: dict = {}

    def once(e: sp.Expr) -> sp.Expr:
        if e not in seen:
            seen[e] = rewrite(e)
        return seen[e]

    return once


def _inlined(program: Program, names: tuple[str, ...], rates, M, F, operations: int) -> CodeEquations:
    k = program.k
    entries = tuple(((i, j), M[i * k + j]) for i in range(k) for j in range(k) if M[i * k + j] != 0)
    return CodeEquations("program", tuple(zip(names, rates)), entries, tuple(F), operations)


def _expressions(code: CodeEquations) -> list[sp.Expr]:
    return [*(e for _, e in code.kinematic_equations), *(e for _, e in code.mass_matrix), *code.forcing]


def from_closed(kinematic, mass_matrix: sp.MatrixBase, forcing) -> CodeEquations:
    entries = tuple(sorted((key, e) for key, e in mass_matrix.todok().items() if e != 0))
    exprs = [*(e for _, e in kinematic), *(e for _, e in entries), *forcing]
    return CodeEquations("closed", tuple(kinematic), entries, tuple(forcing), cse_operations(exprs))


# Tree nodes up to which the program's cheapest inlining is also tidied by the display's own
# simplifier (gacli.algebra.readable) as a further candidate: a bar's weight projected into its
# frame and back, − g m₁ sin θ₁ cos θ₁ + (m₁/2) sin θ₁ (2 g cos θ₁ + ...), cancels so (a double
# pendulum on a cart: 61 → 49 operations, Kane 57; a three-link chain 92 → 89).
TIDIED_TREES = 5_000

# Tree nodes of one entry up to which it is distributed and reduced by sin² + cos² = 1 as a further
# candidate (_trigonometric): distributing a product of sums multiplies their terms.
REDUCED_TREE = 300

# Tree nodes, all expressions together, up to which common factors are drawn out of their sums as
# a further candidate: SymPy's factor_terms walks the trees (a rattleback's 87,000 nodes: 11 s).
FACTORED_TREES = 20_000


def factored(code: CodeEquations) -> CodeEquations:
    """A program's ``code``, or the same with the common factors of every sum drawn out (SymPy's
    ``factor_terms``) where that costs fewer operations: a rocker's I β γ and m (l/2)² β γ, apart
    in F, are one m l²/3 β γ so (a four-bar: 107 → 99; a three-link chain: 99 → 92). The closed
    forms are taken as the chapter's route gives them, tidied for print as they are printed."""
    if not trees_within(_expressions(code), FACTORED_TREES):
        return code
    return min((code, _each(code, factor_terms)), key=lambda c: c.operations)  # the first when equal


def _each(code: CodeEquations, out) -> CodeEquations:
    kinematic = tuple((n, out(e)) for n, e in code.kinematic_equations)
    mass = tuple((key, out(e)) for key, e in code.mass_matrix)
    forcing = tuple(out(e) for e in code.forcing)
    count = cse_operations([*(e for _, e in kinematic), *(e for _, e in mass), *forcing])
    return CodeEquations(code.route, kinematic, mass, forcing, count)


def _trigonometric(e: sp.Expr) -> sp.Expr:
    """A small entry distributed and reduced as the closed forms are, by sin² + cos² = 1 and angles'
    differences (gacli.algebra.angles.reduced): a rolling disk's M₁₁, m r² (6 sin² θ + cos² θ)/4
    from its turned inertia, is m r² (5 sin² θ + 1)/4 (45 → 41 operations, as its closed forms)."""
    return reduced(e) if is_small(e, REDUCED_TREE) and e.has(sp.sin, sp.cos) else e


def _divided(e: sp.Expr) -> sp.Expr:
    """A quotient of polynomials n/d as q + r/d, n = q d + r divided in d's symbols: the top's
    (e·e)²/(e·e)² goes and a gyroscopic (A − C) ω₂ ω₃ stands apart from what divides by e·e."""
    n, d = sp.fraction(sp.cancel(e))
    if d.is_number:
        return factor_terms(n / d)
    q, r = sp.div(sp.expand(n), sp.expand(d), *sorted(d.free_symbols, key=lambda x: x.name))
    return factor_terms(q) + factor_terms(r) / sp.factor(d)


def _rational(e: sp.Expr) -> bool:
    """A quotient of polynomials in the state (no sine, no root): Euler parameters written by hand,
    whose M and F divide by e·e. Divided out (:func:`_divided`), a heavy top's M is A + m l²
    again (159 → 63 operations, Kane 64). Entries with functions are left to factor_terms: cancel
    would expand their sines and cosines as generators (a four-bar: 94 → 194)."""
    powers = e.atoms(sp.Pow)
    # Small integer powers only: cancelling expands them, and (x + y + z)**40 written in a file
    # would expand past any budget.
    if e.is_number or e.atoms(sp.Function) or any(not p.exp.is_Integer or abs(p.exp) > 4 for p in powers):
        return False
    divisors = {p.base for p in powers if p.exp.is_negative and not p.base.is_Atom}
    # A divisor of a few terms only (e·e has four): a damper's line on a quaternion body divides by
    # one of 67, and cancelling over it took 24 s of a derive for an entry 20 times as long.
    return bool(divisors) and all(is_small(b, DIVISOR_NODES) and len(sp.Add.make_args(sp.expand(b))) <= DIVISOR_TERMS
                                  for b in divisors)


# The divisors :func:`_divided` takes: at most this many nodes, and terms once expanded.
DIVISOR_NODES = 200
DIVISOR_TERMS = 16


class StateNames:
    """The state generated code takes, for a derivation with ``system`` and ``speeds``."""

    @property
    def coordinates(self) -> tuple[sp.Symbol, ...]:
        return tuple(S.value(c.name) for c in self.system.coordinates)

    @property
    def state(self) -> tuple[sp.Symbol, ...]:
        """Coordinates in declaration order, then u in the order of ``independent``."""
        return self.coordinates + self.speeds


def program_for(system: System) -> Program | None:
    """The system's program; None without a frame model, outside what the builder takes, or
    when it fails: the chapter's route, hardened against every file, then says what is wrong.

    Built once per load: a System and the same System with its rolling rows added
    (gacli.loader.loading.load_in_stages) share their frame model and bodies, and the
    program reads the rows it needs from the frame model, so both have the same program.
    """
    anchor = system.frames if system.frames is not None else system  # a tuple cannot be weakly referred to
    key = id(anchor)
    hit = _PROGRAMS.get(key)
    if hit is not None and hit[0] is system.bodies and hit[1] == system.independent:
        return hit[2]
    names = tuple(c.name for c in system.coordinates)
    try:
        program = build_program(system, judge=lambda p: _judged(p, names))
    except OutOfTime:  # the command's budget, not the builder's failure: the closed forms would run on
        raise
    except Exception:  # noqa: BLE001 - see above
        program = None
    _PROGRAMS[key] = (system.bodies, system.independent, program)
    weakref.finalize(anchor, _PROGRAMS.pop, key, None)
    return program


def _judged(program: Program, names: tuple[str, ...]) -> float:
    """What ``program``'s generated code costs; a program whose code cannot be formed is never kept
    for it (the builder's cheapest would otherwise be lost with it)."""
    try:
        return from_program(program, names).operations
    except OutOfTime:
        raise
    except Exception:  # noqa: BLE001 - a judgement, not the derivation
        return float("inf")


# id(frame model) → (its System's bodies, independent, program): forgotten with the frame model.
_PROGRAMS: dict[int, tuple] = {}
