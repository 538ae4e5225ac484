"""Which module under ``dyncalc.cli`` defines each command (in its ``COMMANDS``): the group
imports a command's module only when that command is run, completed or listed."""
from __future__ import annotations

import importlib

__all__ = ["COMMAND_MODULES", "click_command"]

#: Command name -> the module under ``dyncalc.cli`` that defines it, in ``--help``'s order.
COMMAND_MODULES = {
    "spring-series": "springs", "spring-parallel": "springs",
    "natural-frequency": "natural_frequency", "damping-ratio": "damping_ratio",
    "rolling-onset": "rolling_onset", "coriolis": "coriolis",
    "forced-response": "forced_response", "modes": "modes", "inertia": "inertia",
    "rigid-body": "rigid_body", "eom": "eom", "scenes": "scenes",
}


def click_command(name: str):
    """The click command ``name`` (its module imported now)."""
    module = importlib.import_module(f"dyncalc.cli.{COMMAND_MODULES[name]}")
    return next(c for c in module.COMMANDS if c.name == name)
