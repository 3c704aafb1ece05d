"""The validated system: frozen records holding SymPy expressions.

Everything here has been parsed and checked by :mod:`gacli.loader.loading`; the
derivation stages read these records and never the YAML. Differential forms
(eq. 14.1, 14.2, rigid-body rotations, virtual work) are stored as their
coefficients on the differentials of the coordinates and quasi-coordinates,
plus the coefficient of dt.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from gacli.errors import Location
from gacli.frame_model import FrameModel


@dataclass(frozen=True)
class Form:
    """Σ_s c_s dq_s + c_t dt, with the coefficients keyed by coordinate name."""

    coefficients: tuple[tuple[str, sp.Expr], ...]
    dt: sp.Expr = sp.S.Zero

    def coefficient(self, name: str) -> sp.Expr:
        return dict(self.coefficients).get(name, sp.S.Zero)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(name for name, _ in self.coefficients)

    def __add__(self, other: "Form") -> "Form":
        return self._combined(other, 1)

    def __sub__(self, other: "Form") -> "Form":
        return self._combined(other, -1)

    def xreplace(self, values: dict) -> "Form":
        """The form with ``values`` put in its coefficients, those that vanish left out."""
        pairs = ((n, c.xreplace(values)) for n, c in self.coefficients)
        return Form(tuple((n, c) for n, c in pairs if c != 0), self.dt.xreplace(values))

    def _combined(self, other: "Form", sign: int) -> "Form":
        """self ± other, coefficients that cancel left out."""
        names = dict.fromkeys(self.names + other.names)
        pairs = ((n, self.coefficient(n) + sign * other.coefficient(n)) for n in names)
        return Form(tuple((n, c) for n, c in pairs if c != 0), self.dt + sign * other.dt)


@dataclass(frozen=True)
class Declared:
    """Common fields of every declared name."""

    name: str
    location: Location
    description: str = ""
    unit: str = ""
    latex: str = ""


@dataclass(frozen=True)
class Parameter(Declared):
    value: sp.Expr | None = None


@dataclass(frozen=True)
class Function(Declared):
    """A prescribed function of time; free (an argument of generated code) when value is None."""

    value: sp.Expr | None = None


@dataclass(frozen=True)
class Input(Declared):
    pass


@dataclass(frozen=True)
class Coordinate(Declared):
    pass


@dataclass(frozen=True)
class QuasiCoordinate(Declared):
    """θ with dθ = Σ C_s dq_s + C dt (eq. 14.2), or primitive when differential is None."""

    differential: Form | None = None

    @property
    def definition(self) -> Form | None:
        """Its definition as a row of A ṙ + a₀ = 0: dθ − Σ C_s dq_s − C dt (eq. 14.2); None when primitive."""
        return None if self.differential is None else Form(((self.name, sp.S.One),)) - self.differential


@dataclass(frozen=True)
class RateRelation:
    """A constraint g(q, ṙ, t) = 0 not linear in the rates, solved for one of them (docs/nonlinear.md)."""

    relation: sp.Expr
    dependent: str
    solution: sp.Expr


@dataclass(frozen=True)
class Constraint:
    """Σ B_s dq_s + B dt = 0 (eq. 14.1); ``relation`` is f when given as f(q, t) = 0.

    ``derived`` marks rows gacli derived from geometry (rolling contact): one
    that repeats the others (two wheels on one axle) is dropped, not an error.
    """

    form: Form
    location: Location
    text: str
    relation: sp.Expr | None = None
    derived: bool = False
    # Set for a constraint nonlinear in the rates; ``form`` is then its linearization
    # A = ∂g/∂ṙ, a₀ = g − A ṙ, whose coefficients depend on the rates.
    rates: RateRelation | None = None


@dataclass(frozen=True)
class Body:
    """A particle (no inertia) or a rigid body with body-axis inertia and rotation forms."""

    name: str
    location: Location
    mass: sp.Expr
    position: tuple[sp.Expr, sp.Expr, sp.Expr]
    inertia: sp.ImmutableMatrix | None = None
    rotation: tuple[Form, Form, Form] | None = None
    description: str = ""

    @property
    def is_rigid(self) -> bool:
        return self.inertia is not None


@dataclass(frozen=True)
class Force:
    """A force (inertial components) applied at a point given by its position."""

    vector: tuple[sp.Expr, sp.Expr, sp.Expr]
    point: tuple[sp.Expr, sp.Expr, sp.Expr]
    location: Location


@dataclass(frozen=True)
class Torque:
    """A torque on a rigid body, in the body axes of its ``rotation``."""

    vector: tuple[sp.Expr, sp.Expr, sp.Expr]
    body: str
    location: Location


@dataclass(frozen=True)
class System:
    """A mechanical system as the chapter states it, ready for derivation."""

    name: str
    path: str
    sha256: str
    location: Location
    title: str
    description: str
    reference: str
    parameters: tuple[Parameter, ...]
    functions: tuple[Function, ...]
    inputs: tuple[Input, ...]
    coordinates: tuple[Coordinate, ...]
    quasi_coordinates: tuple[QuasiCoordinate, ...]
    constraints: tuple[Constraint, ...]
    independent: tuple[str, ...] | None
    independent_location: Location
    bodies: tuple[Body, ...]
    forces: tuple[Force, ...]
    torques: tuple[Torque, ...]
    work: Form | None
    potential: sp.Expr
    # Written with frames, points or rolling (docs/frames.md): positions come
    # through products of direction cosines, and M and F are reduced by
    # sin² + cos² = 1 as they are formed (docs/readable.md).
    uses_frames: bool = False
    # The frames, points, bodies, rolling and loads as declared (gacli.frame_model), when the
    # file uses frames; None for a format-1 file. Read by gacli.mechanics.program.
    frames: FrameModel | None = None
    # False when loaded without the rolling contacts' rows in N, for the straight-line
    # program alone (gacli.loader.loading.load_source): the chapter's steps refuse it.
    rolling_rows: bool = True

    @property
    def rate_names(self) -> tuple[str, ...]:
        """Coordinates then quasi-coordinates: the n + p names whose rates appear (eq. 14.3)."""
        return tuple(c.name for c in self.coordinates) + tuple(q.name for q in self.quasi_coordinates)

    @property
    def free_functions(self) -> tuple[Function, ...]:
        return tuple(f for f in self.functions if f.value is None)

    def __repr__(self) -> str:
        # One line: the dataclass repr would print every expression of the file.
        counts = [(len(self.coordinates), "coordinate", "coordinates"),
                  (len(self.quasi_coordinates), "quasi-coordinate", "quasi-coordinates"),
                  (len(self.constraints), "constraint", "constraints"), (len(self.bodies), "body", "bodies")]
        parts = ", ".join(f"{n} {one if n == 1 else many}" for n, one, many in counts)
        return f"<System {self.name!r} from {self.path!r}: {parts}>"

    def declared(self, name: str) -> Declared | None:
        for group in (self.parameters, self.functions, self.inputs, self.coordinates, self.quasi_coordinates):
            for item in group:
                if item.name == name:
                    return item
        return None
