"""The variables of an FMU and its ``modelDescription.xml`` (FMI 2.0, Model Exchange).

One Real variable per slot of the generated code's vectors (naming.Layout),
named as in the system file, with value references in this order:

.. code:: text

    x       the state (q, u)    causality output, continuous, initial exact, start 0
    der(x)  its derivative      local, continuous, calculated, derivative="index of x"
    p       the parameters      parameter, fixed, exact, start = the file's value (or 0)
    r       inputs, free        input, continuous, start 0
            functions and their rates

The XML is built with :mod:`xml.etree.ElementTree`, whose attributes keep
the order they are set in, so the text is the same on every run.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass

from gacli.algebra import symbols as S
from gacli.algebra.coerce import as_expr
from gacli.emit.naming import Layout
from gacli.read.textsafe import one_line
from gacli.mechanics.equations import Derivation
from gacli.errors import EmitError


@dataclass(frozen=True)
class Variable:
    """One ScalarVariable: its value reference is its position in :func:`variables`."""

    name: str
    causality: str
    variability: str
    initial: str | None
    start: float | None
    description: str = ""
    unit: str = ""
    derivative: int | None = None  # of der(x): the 1-based index of x among the variables


def variables(derivation: Derivation, lay: Layout) -> list[Variable]:
    """The FMU's variables in value-reference order (x, der(x), p, r).

    Raises:
        EmitError: when two slots would get one name (FMI names are unique).
    """
    system = derivation.system
    rates = _rate_names(system, lay)
    states = [Variable(name, "output", "continuous", "exact", 0.0, *_about(system, name, rates))
              for name in lay.state]
    derivatives = [Variable(f"der({name})", "local", "continuous", "calculated", None,
                            f"time derivative of {name}", derivative=i + 1)
                   for i, name in enumerate(lay.state)]
    parameters = [_parameter(system, name, lay.defaults) for name in lay.parameters]
    inputs = [Variable(name, "input", "continuous", None, 0.0, *_about(system, name, rates)) for name in lay.r]
    result = states + derivatives + parameters + inputs
    seen: set[str] = set()
    for variable in result:
        if variable.name in seen:
            raise EmitError(f"two variables of the FMU would both be named '{variable.name}'")
        seen.add(variable.name)
    return result


def _parameter(system, name: str, defaults: dict[str, float]) -> Variable:
    description, unit = _about(system, name, {})
    value = next(p.value for p in system.parameters if p.name == name)
    if name not in defaults:
        # The start attribute is required; the description says that 0 is a placeholder.
        description = f"{description} (no value in the system file: set it)".strip()
    elif as_expr(value).free_symbols:
        # The FMU holds the number: setting the others later does not change it.
        description = f"{description} (start: {one_line(str(value))} at the other start values)".strip()
    return Variable(name, "parameter", "fixed", "exact", defaults.get(name, 0.0), description, unit)


def _rate_names(system, lay: Layout) -> dict[str, tuple[str, int]]:
    """``dot(x)`` → ("x", 1), ``ddot(Omega)`` → ("Omega", 2): the rates among the slots."""
    bases = [*(d.name for d in system.coordinates), *(d.name for d in system.quasi_coordinates),
             *(f.name for f in system.free_functions)]
    slots = set(lay.state) | set(lay.r)
    # r holds every rate up to the highest that occurs, so no order exceeds the number of slots.
    return {S.rate_name(base, order): (base, order) for base in bases for order in range(1, len(slots) + 1)}


def _about(system, name: str, rates: dict[str, tuple[str, int]]) -> tuple[str, str]:
    """(description, unit) of a slot, from the file: a rate is described through its quantity."""
    if name in rates:
        base, order = rates[name]
        declared = system.declared(base)
        what = f"rate of {base}" if order == 1 else f"time derivative of order {order} of {base}"
        extra = one_line(declared.description) if declared is not None else ""
        return (f"{what}: {extra}" if extra else what), ""
    declared = system.declared(name)
    if declared is None:
        return "", ""
    return one_line(declared.description), one_line(declared.unit)


# -- modelDescription.xml --------------------------------------------------------

def model_description(derivation: Derivation, lay: Layout, table: list[Variable], *, guid: str,
                      sources: list[str], tool: str) -> bytes:
    """The text of modelDescription.xml, UTF-8."""
    system = derivation.system
    root = ET.Element("fmiModelDescription", _attributes(
        fmiVersion="2.0", modelName=system.name, guid=guid,
        description=one_line(system.title), generationTool=tool,
        variableNamingConvention="flat", numberOfEventIndicators="0"))
    me = ET.SubElement(root, "ModelExchange", _attributes(modelIdentifier=lay.system))
    files = ET.SubElement(me, "SourceFiles")
    for source in sources:
        ET.SubElement(files, "File", name=source)
    units = sorted({v.unit for v in table if v.unit})
    if units:
        definitions = ET.SubElement(root, "UnitDefinitions")
        for unit in units:
            ET.SubElement(definitions, "Unit", name=unit)
    _model_variables(ET.SubElement(root, "ModelVariables"), table)
    _model_structure(ET.SubElement(root, "ModelStructure"), table)
    ET.indent(root, space="  ")
    return (b'<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode").encode("utf-8")
            + b"\n")


def _attributes(**pairs: str | None) -> dict[str, str]:
    """The pairs with a value, in the order given (ElementTree writes them so)."""
    return {key: value for key, value in pairs.items() if value}


def _model_variables(parent: ET.Element, table: list[Variable]) -> None:
    for reference, v in enumerate(table):
        scalar = ET.SubElement(parent, "ScalarVariable", _attributes(
            name=v.name, valueReference=str(reference), description=v.description or None,
            causality=v.causality, variability=v.variability, initial=v.initial))
        ET.SubElement(scalar, "Real", _attributes(
            derivative=str(v.derivative) if v.derivative else None,
            start=_number(v.start) if v.start is not None else None, unit=v.unit or None))


def _number(value: float) -> str:
    # repr is the shortest text that reads back as the same double; the XML wants no 'inf'.
    if value != value or value in (float("inf"), float("-inf")):
        raise EmitError(f"a start value of the FMU is not finite: {value}")
    return repr(float(value))


def _model_structure(parent: ET.Element, table: list[Variable]) -> None:
    # Indices count from 1 in the order of ModelVariables. No dependencies are listed:
    # the standard then takes every output and derivative to depend on every known.
    indexed = list(enumerate(table, start=1))
    groups = [
        ("Outputs", [i for i, v in indexed if v.causality == "output"]),
        ("Derivatives", [i for i, v in indexed if v.derivative]),
        ("InitialUnknowns", [i for i, v in indexed if v.initial == "calculated"
                             or (v.causality == "output" and v.initial in ("approx", None))]),
    ]
    for tag, indices in groups:
        if indices:
            group = ET.SubElement(parent, tag)
            for index in indices:
                ET.SubElement(group, "Unknown", index=str(index))



def guid_from(digest: str) -> str:
    """A GUID in the usual braces and dashes, from the first 32 hex digits of a SHA-256."""
    h = digest[:32]
    return f"{{{h[:8]}-{h[8:12]}-{h[12:16]}-{h[16:20]}-{h[20:]}}}"
