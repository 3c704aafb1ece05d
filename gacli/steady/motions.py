"""Steady motions: families of solutions of q̇_kept = 0, F(q, u) = 0, with the conditions they need.

Along a steady motion the ignorable coordinates move at constant rates, the
kept ones stand still (their rows of eq. 14.20 vanish) and u̇ = 0, which is
F = 0 since M is regular (eq. 14.19). Inputs are zero. The equations are
solved one at a time, as a person would: an equation is split into its
factors (each factor one branch: dot(lean)·(…) = 0 is two), and a factor
is solved for an unknown it is linear in, rates first (the disk's spin from
its lean and turning rate), under the condition that the coefficient is not
zero; the case where that coefficient vanishes is followed as a branch of
its own, which is how the upright disk's family is found beside the
turning ones. A factor linear in no unknown is solved by SymPy for a
coordinate when it can (sin(lean) = 0), and otherwise kept as a relation
that the family's values must satisfy.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, replace

import sympy as sp

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.mechanics.equations import Derivation

_MAX_FAMILIES = 24
_MAX_DEPTH = 12
_TRIGSIMP_OPS = 80
# Operations past which an equation is neither cancelled, factored nor solved: a four-bar's forcing
# (4,000 operations over its loop's determinant) kept SymPy's cancel running past any budget.
_ALGEBRA_OPS = 600
_SOLVE_OPS = 120  # SymPy's solve of a trigonometric equation runs trigsimp over it: far less than that


@dataclass(frozen=True)
class Family:
    """Values of some unknowns in terms of the free ones, relations left over and conditions (≠ 0)."""

    values: tuple[tuple[sp.Symbol, sp.Expr], ...]
    free: tuple[sp.Symbol, ...]
    relations: tuple[sp.Expr, ...]          # each = 0
    conditions: tuple[sp.Expr, ...]         # each ≠ 0
    # False where a value is not real at the file's parameter values (and generic free values): a
    # Chaplygin ball's ψ = asin(√((C − B)/(A − B))) with A < B < C; None when a parameter has none.
    real: bool | None = None
    # Ignorable coordinates whose rates turn along the family: free of M and F, but their kinematic
    # equations hold another that moves (a disk's x, y with its yaw; Euler parameters, ė = ½ E(e) ω).
    drifting: tuple[str, ...] = ()


@dataclass(frozen=True)
class SteadyMotions:
    unknowns: tuple[sp.Symbol, ...]
    ignorable: tuple[str, ...]
    families: tuple[Family, ...]

    @property
    def drifting(self) -> tuple[str, ...]:
        """The ignorable coordinates that do not move at constant rates along some family."""
        return tuple(c for c in self.ignorable if any(c in f.drifting for f in self.families))

    @property
    def steady_rates(self) -> tuple[str, ...]:
        """The ignorable coordinates that move at constant rates along every family."""
        return tuple(c for c in self.ignorable if c not in self.drifting)


def steady_motions(derivation: Derivation) -> SteadyMotions:
    """The families of steady motions of the system (see the module's text)."""
    from gacli.emit.naming import parameter_defaults
    from gacli.steady import require_small
    from gacli.steady.manifold import reduce_state

    require_small(derivation, "steady")
    defaults = parameter_defaults(derivation.system.parameters)
    reduction = reduce_state(derivation, defaults)
    kinematic = dict(derivation.kinematic_equations)
    no_inputs = {S.value(i.name): sp.S.Zero for i in derivation.system.inputs}
    # The equations do not depend on the ignorable coordinates (manifold.py): at zero, the terms that
    # would cancel between them (the top's φ and ψ) are gone before any simplification.
    no_inputs.update({S.value(c): sp.S.Zero for c in reduction.ignorable})
    equations = [kinematic[c] for c in reduction.coordinates] + list(derivation.forcing)
    unknowns = tuple(derivation.speeds) + tuple(S.value(c) for c in reduction.coordinates)
    out: list[Family] = []
    _branch([_readable(e.xreplace(no_inputs)) for e in equations], {}, [], unknowns, out, 0)
    at = {S.value(p.name): sp.Float(defaults[p.name]) for p in derivation.system.parameters if p.name in defaults}
    complete = len(at) == len(derivation.system.parameters)
    rates = {c: as_expr(kinematic.get(c, 0)) for c in reduction.ignorable}
    families = [replace(f, real=_real_at(f, at) if complete else None, drifting=_drifting(f, rates))
                for f in _distinct(out, unknowns)]
    return SteadyMotions(unknowns, reduction.ignorable, tuple(families))


def _drifting(family: Family, rates: dict) -> tuple[str, ...]:
    """The ignorable coordinates whose rates, with the family's values, hold one that moves."""
    values = dict(family.values)
    along = {c: rate.xreplace(values) for c, rate in rates.items()}
    moving = {S.value(c) for c, rate in along.items() if not _vanishes(rate)}
    return tuple(c for c, rate in along.items() if rate.free_symbols & moving)


def _real_at(family: Family, at: dict) -> bool | None:
    """Whether the family's values are real at ``at`` (the parameters) and generic free values."""
    generic = {u: sp.Float(0.3 + 0.17 * i) for i, u in enumerate(family.free)}
    for _, value in family.values:
        try:
            number = complex(value.xreplace(at).xreplace(generic).evalf(15))
        except (TypeError, ValueError, ArithmeticError):
            return None
        if abs(number.imag) > 1e-9 * max(1.0, abs(number.real)):
            return False
    return True


def _branch(equations, values, conditions, unknowns, out, depth, seen=None) -> None:
    seen = set() if seen is None else seen
    equations = [e for e in (_tidy(e.xreplace(values)) for e in equations) if e != 0]
    key = (frozenset(values.items()), frozenset(equations))
    if key in seen:
        return        # the same equations and values reached by another order of the branches
    seen.add(key)
    if any(not e.has(*unknowns) for e in equations) or len(out) >= _MAX_FAMILIES or depth > _MAX_DEPTH:
        return      # a number or the parameters alone = 0: no motion here for generic parameter values
    if any(_vanishes(c.xreplace(values)) for c in conditions):
        return
    step = _next_step(equations, unknowns, values)
    if step is None:
        family = _family(values, equations, conditions, unknowns)
        if family is not None:
            out.append(family)
        return
    kind, factor, unknown, solutions = step
    rest = [e for e in equations if e is not factor[0]]
    for f in factor[1]:
        if kind == "linear" and f is factor[2]:
            coefficient, solution = solutions
            _branch(rest, _with(values, unknown, solution), conditions + [coefficient], unknowns, out, depth + 1,
                    seen)
            for c in _factors(coefficient, tuple(unknowns)):
                _branch(rest + [f, c], values, conditions, unknowns, out, depth + 1, seen)
        elif kind == "solve" and f is factor[2]:
            for solution in solutions:
                _branch(rest, _with(values, unknown, solution), conditions, unknowns, out, depth + 1, seen)
        elif f is not factor[2]:
            _branch(rest + [f], values, conditions, unknowns, out, depth + 1, seen)


def _next_step(equations, unknowns, values):
    """The first factor solvable for an unknown: (kind, (equation, factors, factor), unknown, solution).

    A factor linear with a coefficient free of the unknowns goes first (no case is lost by
    dividing), then any linear one, then SymPy's solve for a single unknown.
    """
    candidates = tuple(u for u in unknowns if u not in values)
    for plain in (True, False):
        for e in equations:
            factors = _factors(e, candidates)
            for f in factors:
                for u in candidates:
                    if f.has(u) and f.is_polynomial(u) and sp.degree(f, u) == 1:
                        a, b = sp.Poly(f, u).all_coeffs()
                        if not plain or not a.has(*candidates):
                            return "linear", (e, factors, f), u, (_tidy(a), _tidy(-b / a))
    for e in equations:
        factors = _factors(e, candidates)
        for f in factors:
            for u in candidates[::-1]:
                solutions = _solve(f, u)
                if solutions:
                    return "solve", (e, factors, f), u, solutions
    return None


@functools.lru_cache(maxsize=1024)
def _solve(f: sp.Expr, u: sp.Symbol) -> list[sp.Expr]:
    if not f.has(u) or len(f.free_symbols & {u}) != 1 or sp.count_ops(f) > _SOLVE_OPS or _mixed(f, u):
        return ()
    try:
        found = sp.solve(f, u)
    except (NotImplementedError, ValueError, TypeError):
        return ()
    return tuple(s for s in found if s.is_real is not False and not s.has(sp.zoo, sp.nan))[:4]


def _mixed(f: sp.Expr, u: sp.Symbol) -> bool:
    """Whether u stands in f in more than one way (sin u and cos u, or u and sin u) beside other
    angles: SymPy's solve then rewrites through half-angles and simplifies without end (a four-bar's
    49-operation equilibrium in θ₁, θ₂, θ₃ ran for minutes)."""
    functions = {a for a in f.atoms(sp.Function) if a.has(u)}
    bare = f.xreplace({a: sp.Dummy() for a in functions}).has(u)  # u outside any function
    others = {a for a in f.atoms(sp.sin, sp.cos) if not a.has(u)}
    return len(functions) + bare > 1 and bool(others)


@functools.lru_cache(maxsize=4096)
def _factors(e: sp.Expr, unknowns: tuple) -> list[sp.Expr]:
    numerator, _ = sp.fraction(sp.factor(e) if sp.count_ops(e) <= _ALGEBRA_OPS else e)
    out = []
    for f in sp.Mul.make_args(numerator):
        base, power = f.as_base_exp()
        if base.has(*unknowns) and base not in out:
            out.append(base)
    return out


def _with(values, unknown, solution):
    updated = {k: _tidy(v.xreplace({unknown: solution})) for k, v in values.items()}
    updated[unknown] = solution
    return updated


def _family(values, relations, conditions, unknowns) -> Family | None:
    """The branch's result, readable; None when a value is undefined (a division by zero on the way)."""
    values = {k: _readable(v) for k, v in values.items()}
    if any(v.has(sp.zoo, sp.nan, sp.oo, -sp.oo) for v in values.values()):
        return None
    free = tuple(u for u in unknowns if u not in values)
    # The parameters are taken nonzero: a condition keeps the factors that hold unknowns.
    kept = [sp.Mul(*[f for f in sp.Mul.make_args(_readable(c.xreplace(values))) if f.has(*unknowns)])
            for c in conditions]
    kept = [c for c in kept if c.has(*unknowns)]
    order = {u: i for i, u in enumerate(unknowns)}
    return Family(tuple(sorted(values.items(), key=lambda kv: order[kv[0]])), free, tuple(relations),
                  tuple(dict.fromkeys(kept)))


def _distinct(families, unknowns) -> list[Family]:
    """Each family once, and none that is a special case of another: a Chaplygin ball at rest with
    θ and ψ free was listed again with ψ = asin(...) fixed, four times."""
    out = []
    for f in families:
        if not any(g.values == f.values and g.relations == f.relations for g in out):
            out.append(f)
    return [f for f in out if not any(g is not f and _within(f, g) for g in out)]


def _within(f: Family, g: Family) -> bool:
    """Whether every motion of ``f`` is one of ``g``: g asks no condition, and its values and relations
    are among f's (f fixes more)."""
    fixed, related = set(f.values), set(f.relations)
    return not g.conditions and set(g.values) <= fixed and set(g.relations) <= related and \
        (set(g.values), set(g.relations)) != (fixed, related)


def _vanishes(e: sp.Expr) -> bool:
    return _tidy(e) == 0


@functools.lru_cache(maxsize=4096)
def _tidy(e: sp.Expr) -> sp.Expr:
    if not e.free_symbols or sp.count_ops(e) > _ALGEBRA_OPS:
        return e
    # sin² + cos² folded while it is cheap: fewer spurious factors, so fewer branches to follow.
    try:
        return sp.factor(sp.cancel(sp.trigsimp(e) if sp.count_ops(e) < _TRIGSIMP_OPS else e))
    except RecursionError:  # a polynomial in a thousand generators (sin(i*y), one per load): left as it is
        return e


def _readable(e: sp.Expr) -> sp.Expr:
    # As _tidy: trigsimp of a long sum (a thousand loads) runs for minutes, and only tidies.
    if not e.free_symbols or sp.count_ops(e) >= _TRIGSIMP_OPS:
        return e
    return sp.factor(sp.trigsimp(e))
