"""Springs and dampers as the forces they are: along the line between their ends, as Kane takes them.

The loader also writes a line as a potential ½ k (ℓ − L)² and a work form
−c ℓ̇ δℓ (gacli.loader.lines), which every other route differentiates in
the coordinates. For the program that is the long way round: an end fixed
in a body turned by Euler parameters has a position quadratic in them, and
∂V/∂e contracted with ė = ½ Eᵀ ω costs far more than the force it is. A
line is a force f = −T d/ℓ at its end B and −f at A, d = B − A,
T = k (ℓ − L) + c ℓ̇ with ℓ̇ = d·(v_B − v_A)/ℓ, all along the nearest frame both
ends' links hang from (a strut between a pan stage and its camera: along the
stage, from the links below their shared point); the loads then go to the
units as any force at a point does (gacli.mechanics.program.loads: the
unit's resultant, and r × f about its centre). With L = 0 the spring's
force is −k d, with no root taken.
"""

from __future__ import annotations

import sympy as sp

from gacli.frame_model import FrameVector, Line, Load
from gacli.mechanics.program.motion import Motion
from gacli.mechanics.program.vectors import ZV, Pass, add, dot, neg, scale


def line_loads(motion: Motion, actual: Pass, lines: tuple[Line, ...]) -> tuple[Load, ...]:
    """Each line's force at both its ends, along N; the lines between the same two points (a spring
    and a damper side by side) as one force, T their tensions summed (a tethered body: 188 → 180
    operations, Kane 180)."""
    tape = motion.tape
    out: list[Load] = []
    between_same: dict[frozenset, list[Line]] = {}
    for line in lines:
        between_same.setdefault(frozenset(line.ends), []).append(line)
    for same in between_same.values():
        a, b = same[0].ends
        frame = motion.tree.common(motion.frame_of(a), motion.frame_of(b))
        d = tape.vec(between(motion, a, b, frame))
        squared = tape.let(dot(d, d))
        per_length = sp.S.Zero  # T / ℓ
        for line in same:
            if line.stiffness is not None:
                if line.length == 0:
                    per_length += line.stiffness
                else:
                    length = tape.let(sp.sqrt(squared))
                    per_length += line.stiffness * (length - line.length) / length
            if line.damping is not None:  # d·(v_B − v_A) whichever way the line was written
                v = add(motion.velocity(b, actual, frame), neg(motion.velocity(a, actual, frame)))
                per_length += line.damping * tape.let(dot(d, v)) / squared
        f = tape.vec(scale(-tape.let(per_length), d))
        out += [Load(FrameVector(((frame, f),)), False, point=b),
                Load(FrameVector(((frame, neg(f)),)), False, point=a)]
    return tuple(out)


def between(motion: Motion, a: str, b: str, frame: str) -> tuple:
    """B − A along ``frame``: the links of each below the last link both hang from, turned into it."""
    def chain(point: str | None) -> list[str]:
        out = []
        while point is not None:
            out.append(point)
            point = motion.links[point].parent
        return out

    above_a, above_b = chain(a), chain(b)
    shared = set(above_a) & set(above_b)
    d = ZV
    for sign, links in ((1, above_b), (-1, above_a)):
        for name in (n for n in links if n not in shared):
            link = motion.links[name]
            d = add(d, scale(sign, motion.tree.express(link.components, link.frame, frame)))
    return d
