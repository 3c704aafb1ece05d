"""Frames, vectors in frames, and rolling contact: geometry behind format-1 forms.

A frame is oriented from its parent by a chain of simple rotations about its
own successive axes. From the chain gacli derives the direction cosines
(``dcm``: components in the frame → components in N) and the body-axis
components of ω dt as differential forms, exactly what a format-1 ``rotation``
states by hand. A *form vector* is a 3 × (R + 1) matrix: the coefficients of
the differentials of the R coordinates and quasi-coordinates, then of dt.

Rolling without slipping (the material point of the body at the contact has
the velocity of the surface) becomes Pfaffian constraints, eq. (14.1).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import sympy as sp

from gacli.algebra import trig

AXES = {"x": 0, "y": 1, "z": 2}
_ZERO = sp.S.Zero
_TRIGSIMP_OPS = 40
INERTIAL = "N"


def simple_rotation(axis: str, angle: sp.Expr) -> sp.Matrix:
    """R with v_parent = R v_child, for the child turned by ``angle`` about the common ``axis``."""
    c, s = sp.cos(angle), sp.sin(angle)
    if axis == "x":
        return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == "y":
        return sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def unit(axis: str) -> sp.Matrix:
    e = sp.zeros(3, 1)
    e[AXES[axis]] = 1
    return e


@dataclass(frozen=True)
class Frame:
    """A frame's direction cosines (frame → N), ω dt in its own axes (a form vector), and the
    N components of its origin (None: N's origin, where a frame without one turns)."""

    name: str
    dcm: sp.ImmutableMatrix
    omega: sp.ImmutableMatrix
    origin: tuple[sp.Expr, ...] | None = None
    # The simple rotations from N that reach it, runs about one axis merged (see canonical_chain).
    chain: tuple[tuple[str, sp.Expr], ...] = ()
    # False for a frame turned by a quaternion and every frame below it: no chain of simple
    # rotations reaches them, and their turns are built as written.
    chained: bool = True


def inertial_frame(width: int) -> Frame:
    return Frame(INERTIAL, sp.ImmutableMatrix(sp.eye(3)), sp.ImmutableMatrix(sp.zeros(3, width)))


def oriented(name: str, parent: Frame, rotations: Sequence[tuple[str, sp.Expr]],
             differential: Callable[[sp.Expr], sp.Matrix]) -> Frame:
    """The frame reached from ``parent`` by successive rotations about the current axes.

    ω_child = R_relᵀ ω_parent + Σ_i (axis_i in child axes) d(angle_i), where
    the i-th axis is carried to the child by the rotations after it.

    A frame turned by an angle sum (``q4 + htangle``), or turned back about the
    axis its parent was turned about (``-htangle``), is built from its
    canonical chain, one simple rotation at a time from N: exactly as the same
    turns written as one frame each, so that either writing gives the same
    expressions, and so the same equations at the same cost.
    """
    chain, changed = canonical_chain(parent.chain, rotations, differential) if parent.chained else ((), False)
    if changed:
        return _from_chain(name, chain, parent.omega.cols, differential)
    relative = sp.eye(3).tolist()
    for axis, angle in rotations:
        relative = _product(relative, simple_rotation(axis, angle).tolist())
    omega = sp.Matrix(_product(_transposed(relative), sp.Matrix(parent.omega).tolist()))
    after = sp.eye(3)
    for axis, angle in reversed(rotations):
        omega += (after.T * unit(axis)) * differential(angle)
        after = simple_rotation(axis, angle) * after
    # Sines and cosines of sums are written out (a rotation by 2q or q + c); of plain angles there is
    # nothing to write out, and the walk would cost the tree of a long chain, not its graph.
    plain = all(angle.is_Symbol or angle.is_number or (-angle).is_Symbol for _, angle in rotations)
    return Frame(name, sp.ImmutableMatrix(_product(parent.dcm.tolist(), relative)),
                 sp.ImmutableMatrix(omega if plain else omega.applyfunc(sp.expand_trig)), chain=chain,
                 chained=parent.chained)


def quaternion_rotation(e: Sequence[sp.Expr]) -> sp.Matrix:
    """R with v_parent = R v_child for the Euler parameters e = (e0, e1, e2, e3), scalar first.

    The homogeneous form (e0² + e1² − e2² − e3², ...): every entry a quadratic, so no
    attitude is special; on the unit sphere it is the rotation by 2 acos(e0) about (e1, e2, e3).
    """
    a, b, c, d = e
    return sp.Matrix([
        [a*a + b*b - c*c - d*d, 2*(b*c - a*d), 2*(b*d + a*c)],
        [2*(b*c + a*d), a*a - b*b + c*c - d*d, 2*(c*d - a*b)],
        [2*(b*d - a*c), 2*(c*d + a*b), a*a - b*b - c*c + d*d],
    ])


def quaternion_rates(e: Sequence[sp.Expr]) -> sp.Matrix:
    """G(e), 3 × 4, with ω (child axes, relative to the parent) = 2 G(e) ė on the unit sphere;
    G Gᵀ = (e·e) E and G e = 0, so ė = ½ Gᵀ ω there."""
    a, b, c, d = e
    return sp.Matrix([[-b, a, d, -c], [-c, -d, a, b], [-d, c, -b, a]])


def quaternion_oriented(name: str, parent: Frame, e: Sequence[sp.Expr], relative: sp.Matrix) -> Frame:
    """The frame turned from ``parent`` by the Euler parameters ``e``, with ``relative`` its ω dt
    relative to the parent along its own axes (a form vector): ω = Rᵀ ω_parent + relative."""
    R = quaternion_rotation(e).tolist()
    omega = sp.Matrix(_product(_transposed(R), sp.Matrix(parent.omega).tolist())) + relative
    return Frame(name, sp.ImmutableMatrix(_product(parent.dcm.tolist(), R)), sp.ImmutableMatrix(omega),
                 chained=False)


def canonical_chain(start: Sequence[tuple[str, sp.Expr]], rotations: Sequence[tuple[str, sp.Expr]],
                    differential: Callable[[sp.Expr], sp.Matrix]) -> tuple[tuple[tuple[str, sp.Expr], ...], bool]:
    """``start`` followed by ``rotations``, each run about one axis written as one turn per term of its sum.

    Turns about one axis commute, so a run is the sum of its angles: terms that
    cancel go, and the rest are ordered coordinates first. Whether anything
    changed (an angle split, a term cancelled): otherwise the chain is the
    rotations as written, and the frame is built as it always was.
    """
    chain: list[tuple[str, sp.Expr]] = list(start)
    changed = False
    for axis, angle in rotations:
        run = [angle]
        while chain and chain[-1][0] == axis:
            run.insert(0, chain.pop()[1])
        terms = [t for t in sp.Add.make_args(sp.Add(*run)) if t != 0]
        if sorted(map(sp.srepr, terms)) != sorted(map(sp.srepr, run)):
            changed = True
            terms.sort(key=lambda t: (bool(differential(t).is_zero_matrix), sp.default_sort_key(t)))
        else:
            terms = run
        chain.extend((axis, t) for t in terms)
    return tuple(chain), changed


def _from_chain(name: str, chain: Sequence[tuple[str, sp.Expr]], width: int,
                differential: Callable[[sp.Expr], sp.Matrix]) -> Frame:
    """The frame at the end of ``chain``, built as a chain of one-turn frames from N."""
    frame = inertial_frame(width)
    for axis, angle in chain:
        frame = oriented(name, frame, [(axis, angle)], differential)
    return Frame(name, frame.dcm, frame.omega, chain=tuple(chain))


def _product(a: list[list[sp.Expr]], b: list[list[sp.Expr]]) -> list[list[sp.Expr]]:
    """a · b as lists, each entry the sum of the nonzero products (as :func:`rotate`): a Matrix
    product of 3 × 3 direction cosines costs far more than its 27 multiplications."""
    columns = list(zip(*b))
    return [list(rotate([row], column)[0] for column in columns) for row in a]


def _transposed(a: list[list[sp.Expr]]) -> list[list[sp.Expr]]:
    return [list(column) for column in zip(*a)]


def sequence_rotations(sequence: str, angles: Sequence[sp.Expr]) -> list[tuple[str, sp.Expr]]:
    """'ZXZ' with three angles → successive body-axis rotations."""
    return [(axis.lower(), angle) for axis, angle in zip(sequence, angles)]


def in_inertial(components: Mapping[str, Sequence[sp.Expr]], frames: Mapping[str, Frame]) -> tuple[sp.Expr, ...]:
    """Σ over frames of their components, expressed in N."""
    total = (_ZERO,) * 3
    for frame_name, values in components.items():
        frame = frames[frame_name]
        part = tuple(values) if frame.name == INERTIAL else rotate(frame.dcm.tolist(), values)
        total = add_vectors(total, part)
    return total


def rotate(rows: Sequence[Sequence[sp.Expr]], vector: Sequence[sp.Expr]) -> tuple[sp.Expr, ...]:
    """``rows · vector`` as SymPy's Matrix product forms it, without building matrices.

    A Matrix product costs far more than its few multiplications (domain
    matrices, and for each entry a test 0·e for infinities, which asks the
    assumptions of every term). Entries here are finite (a real symbol is
    finite, and an expression is refused where it is infinite), so each
    entry is Add of the products of nonzero pairs, as the sparse product
    makes it, and the expressions are those Matrix would give.
    """
    out = []
    for row in rows:
        terms = [a * b for a, b in zip(row, vector) if a and b]
        out.append(sp.Add(*terms) if terms else _ZERO)
    return tuple(e if e else _ZERO for e in out)


def add_vectors(a: Sequence[sp.Expr], b: Sequence[sp.Expr]) -> tuple[sp.Expr, ...]:
    """a + b entrywise, with a zero entry taken as absent (as Matrix addition does)."""
    return tuple((x + y if x and y else (x if x else y)) or _ZERO for x, y in zip(a, b))


def cross_form(form: sp.Matrix, vector: sp.Matrix) -> sp.Matrix:
    """(form vector) × (plain vector), column by column."""
    out = sp.zeros(3, form.cols)
    for j in range(form.cols):
        out[:, j] = form[:, j].cross(vector)
    return out


def contact_point(centre: sp.Matrix, radius: sp.Expr, axle: sp.Matrix | None,
                  tube: sp.Expr = sp.S.Zero) -> sp.Matrix:
    """Where a wheel (axle ≠ None) or a sphere of ``radius`` touches the plane z = 0 below it.

    For a wheel the contact lies in the wheel's plane, straight "down" from
    the centre: along n − (n·a)a normalised, n the plane's normal. The wheel is
    taken to be above the plane, so |cos| of its tilt is its cos. A wheel with
    a round tyre of radius ``tube`` (a torus, ``radius`` that of the circle of
    the tube's centres) touches a further ``tube`` below that circle, along −n.
    """
    normal = sp.Matrix([0, 0, 1])
    if axle is None:
        return centre - radius * normal
    along = normal - normal.dot(axle) * axle
    # |n − (n·a)a|² = 1 − (n·a)² = a_x² + a_y² for a unit axle; trigsimp
    # turns the rear wheel's into cos² but costs seconds on a steered wheel's.
    square = axle[0] ** 2 + axle[1] ** 2
    if sp.count_ops(square) <= _TRIGSIMP_OPS:
        square = sp.trigsimp(square)
    length = sp.sqrt(square).replace(sp.Abs, lambda arg: arg)
    return centre - radius * along / length - tube * normal


def in_wheel_heading(rows: sp.Matrix, axle: sp.Matrix | None) -> sp.Matrix:
    """Rolling rows (inertial components) re-expressed along the wheel: forward, sideways, up.

    The rows in N carry the heading of the vehicle in every entry, and the
    count ℓ keeps only some of them (two wheels on one axle repeat a row):
    keeping N's x row of one wheel but not its y row makes the rates depend
    on the heading through a quotient that no identity removes. Along the
    wheel each row is a scalar that the heading cannot change, so the
    solved rates are free of it, as by hand. The horizontal part of the axle
    fixes the directions where its length is a single factor (a leaned
    wheel: cos of the lean); otherwise, and for a sphere (no axle), N's rows
    are kept.
    """
    if axle is None:
        return rows
    sideways = sp.Matrix([axle[0], axle[1], 0])
    square = trig.reduce(axle[0] ** 2 + axle[1] ** 2)
    if square == 0:
        return rows
    if square.is_Pow and square.exp == 2:
        sideways = sideways / square.base
    elif square != 1:
        # No single factor (a steered and leaned wheel): dividing by the root
        # would lengthen every row, and N's rows are kept.
        return rows
    forward = sp.Matrix([sideways[1], -sideways[0], 0])  # sideways × up
    basis = sp.Matrix.hstack(forward, sideways, sp.Matrix([0, 0, 1])).T
    return (basis * rows).applyfunc(trig.reduce)


def rolling_rows(centre_form: sp.Matrix, omega_form: sp.Matrix, offset: sp.Matrix,
                 surface_form: sp.Matrix) -> sp.Matrix:
    """v dt of the body's material point at the contact minus the surface's (eq. 14.1 rows).

    v_P dt = dr_G + (ω dt) × (r_P − r_G); the surface point moves by
    ``surface_form``.
    """
    return centre_form + cross_form(omega_form, offset) - surface_form
