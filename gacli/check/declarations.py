"""Declarations nothing uses: warnings (parameters, coordinates) and notes (inputs); declarations
that cost generated code a division the system need not have (a quaternion frame without rates, a
norm kept by its differential)."""

from __future__ import annotations

from gacli.algebra import symbols as S
from gacli.errors import Diagnostic, Location
from gacli.algebra.graph import free_symbols
from gacli.model import System
from gacli.numeric import UndefinedValue, evaluate


def unused_declarations(system: System) -> list[Diagnostic]:
    """Warnings (unused parameters, coordinates no body depends on) and notes (unused inputs).

    An input is the generated code's interface as much as the model's: a file
    may declare a whole force vector (F_x, F_y, F_z) of which a constraint
    makes one component do no work, and ``--strict`` in CI must not fail it
    for that. So an unused input is a note: shown, but never failing.
    """
    used = _symbols_used(system)
    loads = [e for f in system.forces for e in f.vector] + [e for t in system.torques for e in t.vector]
    loaded = _form_symbols(system.work) | free_symbols(loads)
    bodies = _body_dependencies(system)
    out = []
    for p in system.parameters:
        if S.value(p.name) not in used:
            out.append(_warning(p.location, f"parameters.{p.name}", f"parameter '{p.name}' is not used in the equations "
                                "(written nowhere, or only where it cancels, as a height both ends of a spring share)"))
    for i in system.inputs:
        if S.value(i.name) not in loaded:
            out.append(Diagnostic(i.location, f"input '{i.name}' is declared but no load uses it "
                                  "(it stays an input of the generated code, with no effect)",
                                  f"inputs.{i.name}", severity="note"))
    for c in system.coordinates:
        if c.name not in bodies:
            out.append(_unmoving(system, c))
    return (out + _quaternions_without_rates(system) + _norms_by_their_differential(system) + _not_finite(system)
            + _unphysical_bodies(system))


def _unphysical_bodies(system: System) -> list[Diagnostic]:
    """Warnings: a body the file's values make impossible, a mass not positive or an inertia whose
    principal moments break the triangle inequality (as verify's samples judge them; the same values
    are an error where the file gives the inertia about another point or in another frame)."""
    from gacli.numeric import parameter_values
    from gacli.numeric.parameters import body_problem

    values, _ = parameter_values(system)
    out = []
    for body in system.bodies:
        # A massless body is an idealisation, not a mistake.
        if problem := body_problem(body, values, massless=True):
            out.append(_warning(body.location, f"bodies.{body.name}", f"no real body has these values: {problem}"))
    return out


def _not_finite(system: System) -> list[Diagnostic]:
    """Errors: a parameter's value that is no finite number (10**100 to the fourth: simulate refuses it,
    and every numeric check of M would skip it as if it had no value)."""
    values, out = {}, []
    for p in system.parameters:
        if p.value is None:
            continue
        try:
            values[S.value(p.name)] = float(evaluate(p.value, values)[0])
        except UndefinedValue:
            out.append(Diagnostic(p.location, f"the value of '{p.name}' is not a finite real number",
                                  f"parameters.{p.name}", "give a value a double can hold (below about 1e308)"))
            break  # later values built on it would say the same
    return out


def _quaternions_without_rates(system: System) -> list[Diagnostic]:
    """A quaternion frame without ``rates``: three of its Euler parameters' rates are speeds, and the
    fourth is solved from the unit norm, e·ė = 0, dividing by that parameter: generated code divides
    by zero at an ordinary attitude (the identity, for e3). Said at the frame's first parameter."""
    out = []
    coordinates = {c.name: c for c in system.coordinates}
    for edge in (system.frames.edges if system.frames is not None else ()):
        if edge.quaternion is None or edge.rates:
            continue
        first = coordinates.get(str(edge.quaternion[0]))
        names = ", ".join(str(e) for e in edge.quaternion)
        out.append(_warning(first.location if first else system.location, f"frames.{edge.name}",
                            f"frame '{edge.name}' is turned by the quaternion ({names}) without body rates: one "
                            "Euler parameter's rate is solved from the unit norm by dividing by a parameter, so "
                            "the equations are singular where it is zero (an ordinary attitude); give the frame "
                            "'rates: [w_1, w_2, w_3]', three quasi-coordinates (docs/frames.md)"))
    return out


def _norms_by_their_differential(system: System) -> list[Diagnostic]:
    """A Pfaffian row Σ x_i dx_i = 0 over coordinates keeps x·x at its starting value, which the file
    does not name: the kinematics divide by x·x (Euler parameters' ė = ½ Eᵀ ω / e·e), where the
    finite constraint x·x = 1 lets generated code read on the unit sphere (gacli.numeric.spheres).
    A note: the row is right as it stands."""
    out = []
    for i, c in enumerate(system.constraints):
        pairs = c.form.coefficients
        if c.relation is not None or c.derived or c.rates is not None or c.form.dt != 0 or len(pairs) < 2:
            continue
        # Read off the coefficients' shape, c·x with c a rational: nothing in them is evaluated (a
        # hostile exp(exp(exp(exp(100)))) overflowed a division's cancel).
        split = [coefficient.as_coeff_Mul() for _, coefficient in pairs]
        if not all(rest == S.value(name) and c.is_Rational for (name, _), (c, rest) in zip(pairs, split)):
            continue
        if len({c for c, _ in split}) != 1:
            continue
        norm = " + ".join(f"{name}**2" for name, _ in pairs)
        out.append(Diagnostic(c.location, f"this row keeps {norm} at its starting value, which the file does not "
                              "state, so the kinematic equations divide by it; if it is 1 (Euler parameters), "
                              f"write the constraint '{norm} = 1' instead and generated code reads on the unit "
                              "sphere (docs/program.md)", f"constraints[{i}]", severity="note"))
    return out


def _unmoving(system: System, coordinate) -> Diagnostic:
    """A warning for a coordinate no body depends on; a note when a constraint ties it to two or more
    others, as a loop does: the block's travel of an inverted slider-crank placed from the crank pin
    closes the loop, and Euler parameters are held by their unit norm. Tied to one other alone
    (ds = l dθ), it only repeats that one: the warning stands."""
    name, where = coordinate.name, f"coordinates.{coordinate.name}"
    ties = [(i, _tied(c)) for i, c in enumerate(system.constraints)]
    holding = [f"constraints[{i}]" for i, tied in ties if name in tied and len(tied - {name}) >= 2]
    if not holding:
        return _warning(coordinate.location, where, _moves_nothing(system, name))
    return Diagnostic(coordinate.location, f"no body depends on coordinate '{name}', but {', '.join(holding)} "
                      f"{'ties' if len(holding) == 1 else 'tie'} it to two or more others, which it helps to "
                      "fix (as a slider's travel closes a loop)", where, severity="note")


def _tied(constraint) -> set[str]:
    """The names of rates a constraint ties together: those whose coefficient in its differential does
    not vanish (sin(s)**2 + cos(s)**2 in a relation ties s to nothing)."""
    from gacli.numeric.zero import decide_zero

    return {n for n, c in constraint.form.coefficients if decide_zero(c).zero is not True}


def _moves_nothing(system: System, name: str) -> str:
    """What is true of a coordinate that no body's position or rotation depends on.

    It may still turn a frame: the last spin of a pendulum's rod about the rod,
    which carries only a particle (no rotation of its own) and points on the axis.
    """
    turned = _frames_turned_by(system, name)
    if not turned:
        return f"no body depends on coordinate '{name}' (it is in no position or rotation)"
    frames = ", ".join(f"'{f}'" for f in turned)
    return (f"coordinate '{name}' turns frame{'s' if len(turned) > 1 else ''} {frames}, but no body's position "
            f"or rotation depends on it (a particle has no rotation; a point on the axis does not move): "
            f"its equation is 0 = 0")


def _frames_turned_by(system: System, name: str) -> list[str]:
    if system.frames is None:
        return []
    symbol = S.value(name)
    # A chain's inner links are named frame#0, frame#1 ...: the frame is the name before '#'.
    found = [edge.name.split("#")[0] for edge in system.frames.edges if symbol in edge.angle.free_symbols]
    return list(dict.fromkeys(found))


def _warning(location: Location, where: str, message: str) -> Diagnostic:
    return Diagnostic(location, message, where, severity="warning")


def _form_symbols(form) -> set:
    if form is None:
        return set()
    return free_symbols([form.dt, *(c for _, c in form.coefficients)])


def _symbols_used(system: System) -> set:
    """Every symbol in an expression of the system, parameter and function values included."""
    exprs: list = [p.value for p in system.parameters] + [f.value for f in system.functions]
    for body in system.bodies:
        exprs += [body.mass, *body.position]
        exprs += list(body.inertia) if body.inertia is not None else []
    exprs += [e for f in system.forces for e in (*f.vector, *f.point)]
    exprs += [e for t in system.torques for e in t.vector] + [system.potential]
    exprs += [c.relation for c in system.constraints]
    used = free_symbols([e for e in exprs if e is not None])
    forms = [c.form for c in system.constraints] + [q.differential for q in system.quasi_coordinates]
    forms += [f for b in system.bodies if b.rotation for f in b.rotation] + [system.work]
    return used.union(*(_form_symbols(f) for f in forms))


def _body_dependencies(system: System) -> set[str]:
    """Names of the coordinates in a position or in a rotation (as a value or a differential)."""
    names: set[str] = set()
    coordinates = {S.value(c.name): c.name for c in system.coordinates}
    for body in system.bodies:
        symbols = free_symbols(body.position)
        for form in body.rotation or ():
            symbols |= _form_symbols(form)
            names.update(form.names)
        names.update(coordinates[s] for s in symbols if s in coordinates)
    # A rotation in quasi-coordinates (a quaternion frame's rates) turns by the coordinates they are defined by.
    for w in system.quasi_coordinates:
        if w.name in names and w.differential is not None:
            names.update(w.differential.names)
    return names
