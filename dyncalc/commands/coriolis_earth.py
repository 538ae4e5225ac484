"""The Earth form of ``coriolis`` (``--latitude``): a local east-north-up frame turning with
``Omega_E (0, cos phi, sin phi)``, the velocity from ``--vr`` or ``--speed``/``--heading``/
``--vertical``, the explanation's lines, and how each uncertain input moves Omega and v_r.
"""
from __future__ import annotations

from ..lazy import numpy as np
from ..result.entries import Result
from .coriolis_read import CoriolisInputs
from .coriolis_slopes import _MASS
from .coriolis_terms import _fmt, _latitude_words
from .coriolis_vectors import _compute

def _earth(inputs: CoriolisInputs) -> Result:
    from ..physics.frames import EARTH_RATE, earth_angular_velocity, enu_velocity

    latitude, degrees = inputs.parsed["latitude"], inputs.degrees
    rate_text = "Omega_E = 7.2921159e-05 rad/s (the Earth's sidereal rate)"
    rate = EARTH_RATE
    if "omega" in inputs.parsed:
        rate = inputs.si("omega")
        rate_text = f"Omega_E = {_fmt(rate, 'rad/s')} (given by --omega)"
    derived = "vr" not in inputs.parsed
    if derived:
        speed, heading = inputs.parsed.get("speed"), inputs.parsed.get("heading")
        vertical = inputs.si("vertical")
        v_r = enu_velocity(0.0 if speed is None else speed.quantity,
                           0.0 if heading is None else heading.quantity,
                           0.0 if vertical is None else vertical)
    else:
        v_r = inputs.si("vr")

    Omega = earth_angular_velocity(latitude.quantity, rate)
    lines = [f"latitude phi = {_latitude_words(degrees)}; axes x east, y north, z up",
             f"Omega = Omega_E (0, cos phi, sin phi) = {_fmt(Omega, 'rad/s')}, "
             f"{rate_text}"]
    if derived:
        lines.append(f"v_r = (speed sin heading, speed cos heading, vertical) = "
                     f"{_fmt(v_r, 'm/s')}")
    else:
        lines.append(f"v_r = {_fmt(v_r, 'm/s')}")
    hemisphere = ("northern" if degrees > 0 else "southern" if degrees < 0 else "")
    assumptions = ["a local frame fixed to the Earth's surface: x east, y north, z up; it "
                   "turns with Omega = Omega_E (0, cos phi, sin phi)",
                   "horizontal motion is deflected to the right in the northern hemisphere "
                   "and to the left in the southern" + (f" (here: {hemisphere})" if hemisphere
                                                         else " (here: the equator, no "
                                                              "horizontal deflection of "
                                                              "horizontal motion)")]
    if "r" not in inputs.parsed:
        assumptions.append("the centrifugal effect of the Earth's spin is part of the measured "
                           "g; only the Coriolis term is computed")
    earth = {"lines": lines, "assumptions": assumptions, "warnings": inputs.warnings,
             "derived_v": derived}
    return _compute(inputs, Omega, v_r, model="Earth, east-north-up", earth=earth,
                    moves=lambda: _earth_moves(inputs, rate))


def _earth_moves(inputs: CoriolisInputs, rate: float) -> dict[str, tuple]:
    """How each uncertain Earth input moves ``Omega = W (0, cos phi, sin phi)`` (rad/s) and
    ``v_r = (v sin psi, v cos psi, w)`` (m/s), per SI unit of the input:
    ``dOmega/dphi = W (0, -sin phi, cos phi)``, ``dOmega/dW = (0, cos phi, sin phi)``,
    ``dv_r/dv = (sin psi, cos psi, 0)``, ``dv_r/dpsi = v (cos psi, -sin psi, 0)``,
    ``dv_r/dw = (0, 0, 1)``. ``side`` is +1 (-1) for an input at its lower (upper) bound,
    which can only grow (shrink): a speed or rate of 0, a latitude of -90 (90) deg.
    """
    from ..physics.frames import earth_angular_velocity, enu_velocity

    zero = np.zeros(3)
    _, c, s = earth_angular_velocity(inputs.parsed["latitude"].quantity, 1.0)
    degrees = inputs.degrees
    moves = {"latitude": (rate * np.array([0.0, -s, c]), zero, 0.0,
                          -1 if degrees >= 90.0 else 1 if degrees <= -90.0 else 0),
             "omega": (np.array([0.0, c, s]), zero, 0.0, 1 if rate == 0 else 0),
             "vertical": (zero, np.array([0.0, 0.0, 1.0]), 0.0, 0),
             "mass": _MASS}
    heading = inputs.parsed.get("heading")
    if heading is not None and "speed" in inputs.parsed:
        east, north, _ = enu_velocity(1.0, heading.quantity, 0.0)
        speed = float(inputs.si("speed"))
        moves["speed"] = (zero, np.array([east, north, 0.0]), 0.0, 1 if speed == 0 else 0)
        moves["heading"] = (zero, speed * np.array([north, -east, 0.0]), 0.0, 0)
    return moves


