"""The ``coriolis`` command's scalar set-ups, for its inverse problems (not listed in the
catalog: they are what ``coriolis`` solves when a result is given, ``a_c=... vr=?``).

:data:`PERPENDICULAR` is the scalar form (``--omega 2rad/s --vr 3m/s``: perpendicular
vectors, ``a_c = 2 Omega v_r``); :data:`EARTH` horizontal motion over the rotating Earth
(``--latitude``: ``|a_c| = 2 Omega_E v sqrt(sin^2 phi + cos^2 phi sin^2 psi)``, its horizontal
part ``2 Omega_E v |sin phi|``), heading north unless ``--heading`` says otherwise. Both run
through :func:`dyncalc.scenes.inverse.solve` like every scene.
"""
from __future__ import annotations

import math

from ..physics.relative_motion import coriolis_earth, coriolis_perpendicular
from ..units import ANGLE, ANGULAR_RATE, MASS, VELOCITY
from . import Constraint, Param, Scene

__all__ = ["PERPENDICULAR", "EARTH", "TARGETS"]

_REFERENCE = "Gross et al., Engineering Mechanics 3, Chapter 6 (relative motion)"

#: The results a coriolis inverse problem may start from, by set-up.
TARGETS = {"perpendicular": ("a_c", "F_c"),
           "earth": ("a_c_mag", "a_c_horizontal_mag", "F_c_mag", "F_c_horizontal_mag")}

PERPENDICULAR = Scene(
    name="coriolis-perpendicular",
    summary="the Coriolis term of a velocity perpendicular to the rotation axis",
    figure="a point moving at v_r across a frame turning at Omega about an axis "
           "perpendicular to v_r",
    params=(Param("omega", ANGULAR_RATE, "angular velocity of the frame"),
            Param("vr", VELOCITY, "speed relative to the frame", symbol="v_{r}"),
            Param("mass", MASS, "mass", optional=True)),
    compute=coriolis_perpendicular,
    equation="a_c = 2 Omega x v_r",
    formula="a_c = 2 Omega v_r, F_c = m a_c",
    reference=_REFERENCE,
    example="dyncalc coriolis a_c=12m/s^2 --omega 2rad/s vr=?",
    accepts_zeta=False, no_zeta_because="it does not oscillate",
)

EARTH = Scene(
    name="coriolis-earth",
    summary="the Coriolis term of horizontal motion over the rotating Earth",
    figure="a body moving horizontally at speed v with compass heading psi at latitude phi; "
           "the Earth turns at Omega_E about its axis",
    params=(Param("latitude", ANGLE, "latitude (positive north)", constraint=None,
                  symbol=r"\varphi"),
            Param("vr", VELOCITY, "horizontal speed over the ground", symbol="v_{r}"),
            Param("heading", ANGLE, "compass heading (0 north, 90 deg east)", default="0 deg",
                  constraint=None, symbol=r"\psi"),
            Param("omega", ANGULAR_RATE, "the Earth's rotation rate",
                  default="7.2921159e-5 rad/s", symbol=r"\Omega_{E}"),
            Param("mass", MASS, "mass", optional=True)),
    compute=coriolis_earth,
    constraints=(Constraint("-90 deg <= latitude <= 90 deg",
                            lambda si: abs(si["latitude"]) <= math.pi / 2),),
    equation="a_c = 2 Omega x v_r, Omega = Omega_E (0, cos phi, sin phi)",
    formula="|a_c| = 2 Omega_E v sqrt(sin^2 phi + cos^2 phi sin^2 psi), "
            "|a_c,h| = 2 Omega_E v |sin phi|",
    reference=_REFERENCE,
    example="dyncalc coriolis a_c_mag=0.01m/s^2 --latitude 45deg vr=?",
    accepts_zeta=False, no_zeta_because="it does not oscillate",
)
