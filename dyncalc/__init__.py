"""dyncalc: a units-aware calculator for vibration and dynamics.

The Python API is the formula library the command line is built on::

    >>> from dyncalc import Q_, series_stiffness
    >>> series_stiffness([Q_(200, "N/m"), Q_(300, "N/m")])
    <Quantity(120.0, 'newton / meter')>

Names are loaded on first use, so ``import dyncalc`` costs nothing until a formula is called.
"""
from ._version import __version__

__all__ = [
    "__version__", "Q_", "registry", "parse_quantity", "parse_vector", "InputError",
    "series_stiffness", "parallel_stiffness", "cantilever_stiffness", "midspan_stiffness",
    "beam_stiffness", "axial_stiffness", "torsion_bar_stiffness", "coil_spring_stiffness",
    "network_stiffness",
]

_HOME = {
    "Q_": "units", "registry": "units", "parse_quantity": "units", "parse_vector": "units",
    "InputError": "errors", "network_stiffness": "commands.springs",
    **{name: "physics.springs" for name in __all__ if name.endswith("_stiffness")
       and name != "network_stiffness"},
}


def __getattr__(name):
    if name in _HOME:
        import importlib

        return getattr(importlib.import_module(f".{_HOME[name]}", __name__), name)
    raise AttributeError(f"module 'dyncalc' has no attribute {name!r}")
