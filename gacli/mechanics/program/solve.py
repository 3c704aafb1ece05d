"""A_d ṙ_d = b for the dependent rates (eq. 14.7) and their accelerations' rest (eq. 14.14), by numbers.

A_d is fixed and solved for several right-hand sides (one per independent
speed for β, one for γ). Rows with one unknown left are solved first, in
the triangular order the vanishing entries give; each such pivot is a
factor of det A_d, so it vanishes only where A_d is singular. What remains
is solved by the adjugate (cofactors from memoised minors), dividing only
by its determinant, as gacli.algebra.matrices.solve_linear does; or, when
its rows are orthogonal (B Bᵀ = D diagonal, identically: Euler parameters'
kinematics with their unit norm), by x = Bᵀ D⁻¹ b, dividing by the rows'
squared lengths, which vanish only where a row does.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.algebra.angles import reduced
from gacli.algebra.blocks import block_triangular
from gacli.algebra.graph import is_small
from gacli.mechanics.program.support import Unsupported
from gacli.mechanics.program.tape import Tape
from gacli.mechanics.program.vectors import turned

BLOCK = 6  # the adjugate's minors grow as 2^n: a larger coupled block is refused (never met yet)
# Orthogonality is tested pair by pair at generic points: beyond this many rows the test itself
# would cost more than the closed route, and no system met has such a block.
ORTHOGONAL_LIMIT = 24
_SMALL = 200  # tree nodes of a minor's closed form past which it is not reduced


def adjugate(tape: Tape, A: list[list]) -> tuple[list[list], sp.Expr]:
    """(adj A, 1/det A) as program values, by cofactors of memoised minors."""
    n = len(A)
    if n == 1:
        return [[sp.S.One]], tape.let(1 / A[0][0])
    minors: dict[tuple, sp.Expr] = {}

    def minor(rows: tuple, cols: tuple) -> sp.Expr:
        """det of A[rows][cols], expanded along its first row."""
        if len(rows) == 1:
            return A[rows[0]][cols[0]]
        key = (rows, cols)
        if key not in minors:
            terms = [(-1) ** j * A[rows[0]][c] * minor(rows[1:], cols[:j] + cols[j + 1:])
                     for j, c in enumerate(cols) if A[rows[0]][c] != 0]
            minors[key] = _reduced(tape, tape.let(sp.Add(*terms)))
        return minors[key]

    every = tuple(range(n))
    cofactor = [[(-1) ** (i + j) * minor(every[:i] + every[i + 1:], every[:j] + every[j + 1:])
                 for j in range(n)] for i in range(n)]
    det = _reduced(tape, tape.let(sp.Add(*(A[0][j] * cofactor[0][j] for j in range(n)))))
    return [[cofactor[j][i] for j in range(n)] for i in range(n)], tape.let(1 / det)


# A minor is reduced in closed form when it reads at most this many assignments (rows stated as
# forms, a few contact entries); a bicycle's read hundreds and are taken as they are.
_CLOSED_NAMES = 30


def _reduced(tape: Tape, value: sp.Expr) -> sp.Expr:
    """A minor or determinant with sin² + cos² = 1 applied where that shortens its closed form:
    Euler angles' rates, stated as quasi-coordinates, have det sin θ (sin² ψ + cos² ψ), which the
    program would otherwise divide by (gacli.algebra.angles.reduced)."""
    closed = tape.closed_within(value, _CLOSED_NAMES)
    if closed is None or not is_small(closed, _SMALL) or not closed.has(sp.sin, sp.cos):
        return value
    shorter = reduced(closed)
    return tape.let(shorter) if sp.count_ops(shorter) < sp.count_ops(closed) else value


def plan(A: list[list]) -> tuple[list[tuple[int, int]], list[int], list[int]]:
    """The pivots (row, column) in the order they are solved, and the rows and columns left for the block."""
    rows, cols, order = list(range(len(A))), list(range(len(A))), []
    while rows:
        hit = next(((i, live[0]) for i in rows if len(live := [j for j in cols if A[i][j] != 0]) == 1), None)
        if hit is None:
            break
        order.append(hit)
        rows.remove(hit[0])
        cols.remove(hit[1])
    return order, rows, cols



class Solver:
    """x = A⁻¹ b for a fixed A (program values, structural zeros exact) and several b.

    Built once per A: a plan of pivots (row, column, 1/pivot), then the
    rest as one block, or, when that is larger than the adjugate takes and
    not orthogonal, as the square blocks of its block-triangular order
    (gacli.algebra.blocks), each solved in turn. A builder object: it writes
    the plan's values on the tape once, then each solve writes only its own.
    """

    def __init__(self, tape: Tape, A: list[list], length=None, turn: bool = False) -> None:
        """``length``: a squared row length as the program may take it (on the constraints, where
        the motion is; see gacli.mechanics.program.build), or None to take it as it is; ``turn``:
        solved through the pairs of columns that turn with an angle (:func:`turned_columns`)."""
        A, self.turns = turned_columns(tape, A) if turn else (A, [])
        self.tape, self.A = tape, A
        order, rows, cols = plan(A)
        self.pivots = [(i, j, tape.let(1 / A[i][j])) for i, j in order]
        self.blocks = [_Block.of(tape, A, r, c, orthogonal, length or (lambda e: e))
                       for r, c, orthogonal in _split(tape, A, rows, cols)]

    def solve(self, b: list, along: dict | None = None) -> list[sp.Expr]:
        """x = A⁻¹ b; ``along``, when given, receives y of each turned pair (a, b) before x = R y."""
        tape, A = self.tape, self.A
        x: dict[int, sp.Expr] = {}
        for i, j, inverse in self.pivots:
            rest = b[i] - sp.Add(*(A[i][k] * x[k] for k in x))
            x[j] = tape.let(tape.let(rest) * inverse)
        for block in self.blocks:
            rest = [tape.let(b[i] - sp.Add(*(A[i][k] * x[k] for k in x))) for i in block.rows]
            x.update(block.solve(tape, A, rest))
        for i, j, c, s, _ in self.turns:  # x = R y on the turned pair
            if along is not None:
                along[(i, j)] = (x[i], x[j])
            x[i], x[j] = tape.let(c * x[i] - s * x[j]), tape.let(s * x[i] + c * x[j])
        return [x[j] for j in range(len(A))]


def _split(tape: Tape, A: list[list], rows: list[int], cols: list[int]) -> list[tuple[list, list, bool]]:
    """The rest after the pivots as blocks (rows, columns, whether orthogonal): one, or its
    block-triangular order when it is too large and not orthogonal."""
    if not rows:
        return []
    rest = _sub(A, rows, cols)
    whole = _orthogonal(tape, rest)
    if len(rows) <= BLOCK or whole:
        return [(rows, cols, whole)]
    blocks = block_triangular([[x != 0 for x in row] for row in rest]) or [(tuple(range(len(rows))),) * 2]
    out = []
    for r, c in blocks:
        r, c = [rows[i] for i in r], [cols[j] for j in c]
        orthogonal = _orthogonal(tape, _sub(A, r, c))
        if len(r) > BLOCK and not orthogonal:
            raise Unsupported("the rows couple more dependent rates than the adjugate solve takes")
        out.append((r, c, orthogonal))
    return out


def _sub(A: list[list], rows, cols) -> list[list]:
    return [[A[i][j] for j in cols] for i in rows]


@dataclass(frozen=True)
class _Block:
    """Rows and columns solved together: by Bᵀ D⁻¹ (``lengths``, orthogonal rows) or by the adjugate."""

    rows: tuple[int, ...]
    cols: tuple[int, ...]
    lengths: list | None
    adjugate: tuple | None

    @staticmethod
    def of(tape: Tape, A: list[list], rows, cols, orthogonal: bool, length) -> "_Block":
        B = _sub(A, rows, cols)
        if orthogonal:
            # A row of a turn's cosines, (−sin θ, cos θ), is of length 1, not sin² θ + cos² θ.
            lengths = [tape.let(1 / length(_reduced(tape, tape.let(sp.Add(*(x * x for x in row)))))) for row in B]
            return _Block(tuple(rows), tuple(cols), lengths, None)
        return _Block(tuple(rows), tuple(cols), None, adjugate(tape, B))

    def solve(self, tape: Tape, A: list[list], rest: list) -> dict[int, sp.Expr]:
        if self.lengths is not None:
            scaled = [tape.let(r * inverse) for r, inverse in zip(rest, self.lengths)]
            return {j: tape.let(sp.Add(*(A[i][j] * y for i, y in zip(self.rows, scaled)))) for j in self.cols}
        adj, inverse = self.adjugate
        return {j: tape.let(inverse * tape.let(sp.Add(*(adj[a][t] * rest[t] for t in range(len(rest))))))
                for a, j in enumerate(self.cols)}


def _orthogonal(tape: Tape, B: list[list]) -> bool:
    """Whether the rows of B (more than one) are orthogonal identically (the tape's zero test)."""
    n = len(B)
    if n < 2 or n > ORTHOGONAL_LIMIT:
        return False
    return all(tape.vanishes(sp.Add(*(x * y for x, y in zip(B[i], B[j])))) for i in range(n) for j in range(i + 1, n))


def turned_columns(tape: Tape, A: list[list]) -> tuple[list[list], list[tuple]]:
    """A R and the turns R: pairs of columns (a, b) whose entries in every row turn with one angle θ,
    (p, q) = (p', q') turned by θ with p', q' free of θ, solved as A R y = b and x = R y, R the
    turn by θ on (a, b). Rows written in N's axes for a vehicle's x, y (cos θ ẋ + sin θ ẏ − w θ̇
    = r φ̇): along its heading they are constant, and the adjugate's cofactors of sines and
    cosines, which the program multiplied out and never cancelled, are numbers."""
    n, turns = len(A), []
    closed = [[_closed(tape, x) for x in row] for row in A]
    A = [list(row) for row in A]
    free = set(range(n))
    for a in range(n):
        for b in range(a + 1, n):
            if a not in free or b not in free:
                continue
            turn = _turn(closed, a, b)
            if turn is None:
                continue
            angle, entries = turn
            for i, (p, q) in enumerate(entries):
                A[i][a], A[i][b] = (tape.let(p) if p != 0 else 0), (tape.let(q) if q != 0 else 0)
            turns.append((a, b, tape.let(sp.cos(angle)), tape.let(sp.sin(angle)), angle))
            free -= {a, b}
    return A, turns


def _closed(tape: Tape, x) -> sp.Expr | None:
    if x == 0:
        return sp.S.Zero
    closed = tape.closed_within(x, _CLOSED_NAMES)
    return closed if closed is not None and is_small(closed, _SMALL) else None


def _turn(closed: list[list], a: int, b: int) -> tuple[sp.Symbol, list[tuple]] | None:
    """(θ, the pair's entries of A R) where both columns' entries are known and turn with θ; else None."""
    pairs = [(row[a], row[b]) for row in closed]
    if any(p is None or q is None for p, q in pairs):
        return None
    angles = {f.args[0] for p, q in pairs for f in (p + q).atoms(sp.sin, sp.cos) if f.args[0].is_Symbol}
    for angle in sorted(angles, key=lambda x: x.name):
        back = [turned((p, q, 0), 2, sp.cos(angle), -sp.sin(angle))[:2] for p, q in pairs]
        if not all(_constant_in(e, angle) for pair in back for e in pair):
            continue  # told by numbers first: reducing a rattleback's body-rate rows to find no turn took 4.5 s
        entries = [(reduced(p), reduced(q)) for p, q in back]
        if not any(angle in p.free_symbols or angle in q.free_symbols for p, q in entries):
            return angle, entries
    return None


# Generic values for the numeric test of _constant_in (fixed: the choice must not depend on chance).
_AT = (0.4137, -0.7291, 1.1963, 0.6512, -0.2879, 0.9347)


def _constant_in(e: sp.Expr, angle: sp.Symbol) -> bool:
    """Whether ``e`` takes the same value at two values of ``angle``, the others at generic values."""
    if angle not in e.free_symbols:
        return True
    others = {x: sp.Float(_AT[i % len(_AT)] + i / 7) for i, x in enumerate(sorted(e.free_symbols - {angle},
                                                                                   key=lambda x: x.name))}
    fixed = e.xreplace(others)
    try:
        a, b = complex(fixed.xreplace({angle: sp.Float(0.37)})), complex(fixed.xreplace({angle: sp.Float(1.91)}))
    except (TypeError, ValueError, ZeroDivisionError):
        return False
    return abs(a - b) <= 1e-9 * (1 + abs(a) + abs(b))
