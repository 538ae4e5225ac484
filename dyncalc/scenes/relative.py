"""Catalog: the relative-motion scenes of ``coriolis --scene`` (../shared/SCENES.md,
"Relative-motion scenes").

The ``example_result`` values were computed independently with mpmath at 30 digits from the
formulas of ../shared/SCENES.md (``mpmath.acosh``, ``mpmath.cosh``, ``mpmath.sinh``, ``mpmath.cos`` of
the angle in radians).
"""
from __future__ import annotations

from ..physics.relative_scenes import radial_slot_release, slotted_link
from ..units import ANGLE, ANGULAR_RATE, LENGTH, MASS, TIME
from . import Constraint, Param, Scene, register

__all__ = ["relative_scene_names"]


def relative_scene_names() -> list[str]:
    """The scenes ``coriolis --scene`` takes (those this module registers), in catalog order."""
    from . import RELATIVE_MODULE, catalog, registered_by

    return [name for name in catalog() if registered_by(name) == RELATIVE_MODULE]


register(Scene(
    name="radial-slot-release",
    summary="a block released in a radial slot of a turning platform slides outward",
    figure="a horizontal platform turns at constant Omega about its vertical central axis; a "
           "block in a straight frictionless radial slot through the centre is released at "
           "the distance a with no velocity relative to the platform and slides out to r",
    params=(Param("Omega", ANGULAR_RATE, "rate of the platform (rad/s, rpm, ...)"),
            Param("a", LENGTH, "release radius"),
            Param("r", LENGTH, "radius reached (the rim, say)"),
            Param("m", MASS, "mass of the block (for the side forces)", optional=True),
            Param("t", TIME, "a time after the release (0 <= t <= t_R)", optional=True,
                  constraint="nonnegative")),
    constraints=(Constraint("0 < a < r", lambda si: si["a"] < si["r"],
                            ": the block is released inside the radius r it reaches (a block "
                            "released at the centre stays there, unstably)"),),
    compute=radial_slot_release,
    equation="x'' - Omega^2 x = 0 (x along the slot, relative to the platform)",
    formula="x = a cosh(Omega t); v_r = Omega sqrt(r^2 - a^2), t_R = acosh(r/a)/Omega, "
            "v_abs = Omega sqrt(2 r^2 - a^2), F_slot = 2 m Omega v_r; with t: x_t = "
            "a cosh(Omega t), v_t = a Omega sinh(Omega t), F_t = 2 m Omega v_t",
    latex=(r"$v_r = $Omega\,\sqrt{$r^2 - $a^2}",
           r"$t_R = \frac{\operatorname{arcosh}($r/$a)}{$Omega}",
           r"$v_abs = $Omega\,\sqrt{2 $r^2 - $a^2}"),
    reference="E6.7",
    example="dyncalc coriolis --scene radial-slot-release Omega=30rpm a=0.1m r=0.5m m=0.2kg "
            "t=0.5s",
    example_result={"v_r": "1.53905979619423691 m/s", "t_R": "0.729703663822135696 s",
                    "v_abs": "2.19911485751285527 m/s", "F_slot": "1.93403957966368765 N",
                    "x_t": "0.250917847865805678 m", "v_t": "0.722974372520285286 m/s",
                    "F_t": "0.908516390977367497 N"},
    accepts_zeta=False, no_zeta_because="the slot is frictionless",
    assumptions=("frictionless slot, constant Omega",),
))

register(Scene(
    name="slotted-link",
    summary="a drum's pin sliding in the slot of a link turning about a fixed pivot",
    figure="a link turns about a fixed pivot A and has a straight slot through A; a drum turns "
           "at omega about a fixed centre B at the distance d from A; a pin C on the drum at "
           "the radius c from B slides in the slot; theta is the angle of BC from the "
           "direction A to B (counterclockwise)",
    params=(Param("d", LENGTH, "pivot A to drum centre B"),
            Param("c", LENGTH, "pin radius BC"),
            Param("theta", ANGLE, "angle of BC from the direction A to B", constraint=None),
            Param("omega", ANGULAR_RATE, "drum's angular velocity (counterclockwise "
                  "positive)", constraint=None)),
    compute=slotted_link,
    equation="v_C = v_r e_AC + rho omega_AD e_perp (the pin's velocity split along and across "
             "the slot)",
    formula="rho = sqrt(d^2 + c^2 + 2 c d cos(theta)), omega_AD = omega c (c + d cos(theta))/"
            "rho^2, v_r = -omega c d sin(theta)/rho, v_C = c abs(omega)",
    latex=(r"$rho = \sqrt{$d^2 + $c^2 + 2 $c $d \cos $theta}",
           r"$omega_AD = \frac{$omega\,$c\,($c + $d \cos $theta)}{$rho^2}",
           r"$v_r = -\frac{$omega\,$c\,$d \sin $theta}{$rho}"),
    reference="E6.9",
    example="dyncalc coriolis --scene slotted-link d=0.4m c=0.3m theta=35deg omega=-10rad/s",
    example_result={"rho": "0.668278752190549621 m", "omega_AD": "-4.21629478210460448 rad/s",
                    "v_r": "1.02994704135827335 m/s", "v_C": "3.0 m/s"},
    accepts_zeta=False, no_zeta_because="it is pure kinematics",
    assumptions=("rigid links; the pin stays in the slot (rho > 0)",),
))
