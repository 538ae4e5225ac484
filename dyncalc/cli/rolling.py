"""``dyncalc rolling-onset`` (not built yet)."""
from __future__ import annotations

from .pending import pending_command

COMMANDS = [pending_command("rolling-onset", "When a sliding ball, cylinder or hoop starts to roll without slipping.")]
