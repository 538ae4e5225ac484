"""The Python API: one function per command, generated from its
:class:`~dyncalc.commands.record.Command` record (``dyncalc.natural_frequency``,
``dyncalc.spring_series``, ...; a new command gets its function from its record alone).

    >>> import pint, dyncalc
    >>> ureg = pint.UnitRegistry()
    >>> r = dyncalc.natural_frequency(k=ureg.Quantity(2, "kN/m"), m="4 kg")
    >>> print(r["f"])
    3.5588127170858854 hertz

Parameters are keywords named as on the command line (``k=``, ``m=``, ``scene=``,
``method=``); a scene's parameters are further keywords (``J=``, ``a=``), a spring network's
elements (or ``inertia``'s bodies) positional arguments and its shared values keywords (``EI=``). A value may be a
pint Quantity of *any* registry, a str as typed on the command line, or a plain number in
the canonical unit (the SI unit of its dimension, as a bare number on the command line).
Arrays (numpy, and Dask or xarray arrays) are computed elementwise, through the column kernels
batch mode uses (:mod:`.run`). Bad input raises :class:`~dyncalc.errors.InputError` with the
message of the CLI's ``Error:`` line; nothing is printed.

**Registries.** A Quantity is read through its magnitude and the text of its unit
(``format(units, "~D")``: ``kN / m``), into dyncalc's own registry, the same way the command
line reads ``"2 kN / m"``; results are built in the registry of the first Quantity argument
(else dyncalc's) from their value and canonical unit. So quantities of two registries are
never mixed (pint's "different registries" error cannot occur), the caller keeps their own
registry, and a number through the API is the CLI's to the bit. The other choice, pint's
application registry, was not taken: it is process-wide state that any library may replace
(``pint.set_application_registry``), dyncalc's registry carries its own definitions (angles,
cycle and angular rates kept apart) and cache, and a user's own ``UnitRegistry()``, the usual
case in notebooks, would still not mix with it.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Protocol

from ..errors import InputError, PhysicsError
from .results import ArrayResult, Result

__all__ = ["Result", "ArrayResult", "CommandFunction", "InputError", "PhysicsError",
           "command_function", "function_names",
           "spring_series", "spring_parallel", "natural_frequency", "damping_ratio",
           "rolling_onset", "coriolis", "forced_response", "modes", "inertia", "rigid_body",
           "eom"]


class CommandFunction(Protocol):
    """A command as a function: ``natural_frequency(k=..., m=...) -> Result``."""

    __name__: str

    def __call__(self, *elements: object, rtol: float | None = None,
                 strict_units: bool = False, **parameters: object) -> Result | ArrayResult:
        ...


if TYPE_CHECKING:  # made on first use by __getattr__ below; declared here for type checkers
    spring_series: CommandFunction
    spring_parallel: CommandFunction
    natural_frequency: CommandFunction
    damping_ratio: CommandFunction
    rolling_onset: CommandFunction
    coriolis: CommandFunction
    forced_response: CommandFunction
    modes: CommandFunction
    inertia: CommandFunction
    rigid_body: CommandFunction
    eom: CommandFunction


#: The records' free words taken as positional arguments (a network's elements, bodies).
POSITIONAL_WORDS = ("ELEMENT...", "BODY...")


def _records() -> dict[str, Any]:
    """Every command record, by function name (``natural_frequency``): the
    :class:`~dyncalc.commands.record.Command` objects of the modules of
    :mod:`dyncalc.commands`."""
    import importlib
    import pkgutil

    from .. import commands
    from ..commands.record import Command

    found: dict[str, Any] = {}
    for module_info in pkgutil.iter_modules(commands.__path__):
        module = importlib.import_module(f"{commands.__name__}.{module_info.name}")
        for value in vars(module).values():
            if isinstance(value, Command):
                name: str = getattr(value, "name")  # a slot, set by Command's constructor
                found.setdefault(name.replace("-", "_"), value)
    return found


def function_names() -> list[str]:
    """The names of the command functions (one per command record)."""
    return sorted(_records())


def _record(name: str):
    """The record of function ``name``: its own module's ``COMMAND`` when it has one (one
    import), else found among all the records."""
    import importlib

    try:
        module = importlib.import_module(f"{__package__.rpartition('.')[0]}.commands.{name}")
        record: Any = getattr(module, "COMMAND", None)
        if record is not None and record.name.replace("-", "_") == name:
            return record
    except ImportError:
        pass
    return _records().get(name)


def __getattr__(name: str) -> Any:
    if name.startswith("_"):
        raise AttributeError(name)
    record = _record(name)
    if record is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    function = command_function(record)
    globals()[name] = function
    return function


def command_function(record) -> CommandFunction:
    """The API function of a command record: keywords for its parameters (settings such as
    ``scene`` and ``method`` included), further keywords for a scene's parameters or a
    network's shared values, positional arguments for a network's elements; ``rtol`` and
    ``strict_units`` as ``--rtol`` and ``--strict-units``."""
    import inspect

    from .call import call

    name = record.name.replace("-", "_")

    def function(*elements: object, rtol: float | None = None, strict_units: bool = False,
                 **parameters: object) -> Result | ArrayResult:
        return call(record, elements, parameters, rtol, strict_units)

    function.__name__ = function.__qualname__ = name
    function.__module__ = "dyncalc"
    function.__doc__ = _doc(record)
    kinds = inspect.Parameter
    signature = []
    if record.words in POSITIONAL_WORDS:
        signature.append(kinds("elements", kinds.VAR_POSITIONAL))
    signature += [kinds(p.name, kinds.KEYWORD_ONLY, default=None) for p in record.parameters
                  if p.kind != "after"]
    signature += [kinds("rtol", kinds.KEYWORD_ONLY, default=None),
                  kinds("strict_units", kinds.KEYWORD_ONLY, default=False)]
    if record.words is not None and record.words != "BODY...":
        signature.append(kinds("parameters", kinds.VAR_KEYWORD))
    function.__signature__ = inspect.Signature(signature)  # type: ignore[attr-defined]
    function.record = record  # type: ignore[attr-defined]
    return function


def _doc(record) -> str:
    """The function's docstring, from the record: summary, parameters, results."""
    lines = [record.summary, "", "Parameters (keywords, as the command line's options)", ""]
    if record.words == "ELEMENT...":
        lines.append("*elements : the network's elements, as on the command line")
    elif record.words == "BODY...":
        lines.append("*elements : the bodies, as on the command line ('rod(m=2kg, l=1m)')")
    for p in record.parameters:
        if p.kind == "after":
            continue
        unit = f" [{p.dim.si}]" if p.dim is not None and p.dim.si else ""
        lines.append(f"{p.name}{unit} : {p.help}")
    if record.words is not None and record.words != "BODY...":
        lines.append("**parameters : scene parameters (NAME=QUANTITY) or shared values")
    lines += ["", "Results (Quantities in their canonical unit)", ""]
    lines += [f"{r.name} [{r.unit}] : {r.description}" if r.unit else
              f"{r.name} : {r.description}" for r in record.results]
    lines += ["", f"The command line: dyncalc {record.name} --help"]
    return "\n".join(lines)
