"""``dyncalc coriolis`` (not built yet)."""
from __future__ import annotations

from .pending import pending_command

COMMANDS = [pending_command("coriolis", "Coriolis and relative-motion acceleration in a rotating frame.")]
