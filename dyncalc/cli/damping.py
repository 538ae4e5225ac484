"""``dyncalc damping-ratio`` (not built yet)."""
from __future__ import annotations

from .pending import pending_command

COMMANDS = [pending_command("damping-ratio", "Damping ratio, log decrement and damped period from any measurement.")]
