"""dyncalc: a units-aware calculator for vibration and dynamics.

The Python API (docs/api.md) is one function per command, taking the command's parameters as
keywords (:mod:`dyncalc.api`)::

    >>> import dyncalc
    >>> print(dyncalc.natural_frequency(k="2 kN/m", m=4)["omega"])
    22.360679774997898 radian / second

and the formula library the command line is built on::

    >>> from dyncalc import Q_, series_stiffness
    >>> series_stiffness([Q_(200, "N/m"), Q_(300, "N/m")])
    <Quantity(120.0, 'newton / meter')>

Names are loaded on first use, so ``import dyncalc`` costs nothing until one is used.
"""
from ._version import __version__

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (a one-off's start-up)

if TYPE_CHECKING:
    from .api import (ArrayResult, Result, coriolis, damping_ratio, eom, forced_response,
                      inertia, modes, natural_frequency, rigid_body, rolling_onset,
                      spring_parallel, spring_series)
    from .errors import InputError, PhysicsError

#: The command functions (:mod:`dyncalc.api`), one per command record.
COMMAND_FUNCTIONS = ("spring_series", "spring_parallel", "natural_frequency", "damping_ratio",
                     "rolling_onset", "coriolis", "forced_response", "modes", "inertia",
                     "rigid_body", "eom")

__all__ = [
    "__version__", *COMMAND_FUNCTIONS, "Result", "ArrayResult", "InputError", "PhysicsError",
    "Q_", "registry", "parse_quantity", "parse_vector",
    "series_stiffness", "parallel_stiffness", "cantilever_stiffness", "midspan_stiffness",
    "beam_stiffness", "axial_stiffness", "torsion_bar_stiffness", "coil_spring_stiffness",
    "network_stiffness",
]

_HOME = {
    "Q_": "units", "registry": "units", "parse_quantity": "units", "parse_vector": "units",
    "InputError": "errors", "PhysicsError": "errors", "network_stiffness": "commands.springs",
    "Result": "api", "ArrayResult": "api", **dict.fromkeys(COMMAND_FUNCTIONS, "api"),
    **{name: "physics.springs" for name in __all__ if name.endswith("_stiffness")
       and name != "network_stiffness"},
}


def __getattr__(name):
    if name in _HOME:
        import importlib

        return getattr(importlib.import_module(f".{_HOME[name]}", __name__), name)
    raise AttributeError(f"module 'dyncalc' has no attribute {name!r}")
