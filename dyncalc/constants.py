"""Physical constants and defaults, each written once: standard gravity and the Earth's
sidereal rotation rate (docs/commands.md gives each command's defaults)."""
from __future__ import annotations

__all__ = ["STANDARD_GRAVITY", "STANDARD_GRAVITY_TEXT", "EARTH_RATE"]

#: Standard gravity, m/s^2 (the CGPM's conventional value, exact by definition): the default of
#: every parameter ``g``.
STANDARD_GRAVITY = 9.80665
#: The same as a quantity text, the default a scene or command reads when ``g`` is not given.
STANDARD_GRAVITY_TEXT = "9.80665 m/s^2"

#: The Earth's sidereal rotation rate, rad/s (IERS conventional mean angular velocity).
EARTH_RATE = 7.2921159e-5
