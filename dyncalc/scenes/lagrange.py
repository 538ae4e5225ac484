"""Catalog: the Lagrange scenes of chapter 4 (E4.14, E4.16, E4.17, E4.19;
../shared/SCENES.md "Lagrange scenes"), for ``natural-frequency`` (closed forms) and ``modes``
(the linearised matrices of :mod:`dyncalc.physics.lagrange`). ``disk-on-swinging-bar`` has no
equilibrium: both refuse it on purpose (:attr:`dyncalc.scenes.Scene.no_frequency`), and its
example is the ``eom`` command that gives its accelerations.

The ``example_result`` values were computed independently with mpmath at 30 digits from the
formulas of ../shared/SCENES.md (the pendulums' equilibrium by mpmath.findroot; the disk's
accelerations from the closed forms of ../shared/SCENES.md).
"""
from __future__ import annotations

from ..physics.lagrange import (NO_EQUILIBRIUM, block_disk_springs, block_disk_springs_matrices,
                                disk_on_swinging_bar, disk_on_swinging_bar_matrices,
                                pendulum_on_sliding_block, pendulum_on_sliding_block_matrices,
                                spring_coupled_pendulums, spring_coupled_pendulums_matrices)
from ..errors import InputError
from ..units import INERTIA, LENGTH, MASS, STIFFNESS
from . import Param, register
from . import Scene
from .basic import gravity


def _radius(values) -> float:
    if "r" not in values:
        raise InputError("modes --scene block-disk-springs needs r= (the disk's radius): it "
                         "cancels from the frequencies but not from the mode shapes")
    return values["r"]


_TWO_MODES = "it has two modes, and one damping ratio for both would be ambiguous"

register(Scene(
    name="block-disk-springs",
    summary="a block on a wall spring carrying a rolling disk tied to it by a second spring",
    figure="a block M slides on a frictionless floor, tied to a wall by a spring k; on its top "
           "face a homogeneous disk (m, r) rolls without slipping, its centre tied by a second "
           "spring k to a post on the block; x is the block's displacement, phi the disk's "
           "rotation (positive moving its centre backward on the block)",
    params=(Param("M", MASS, "mass of the block"), Param("m", MASS, "mass of the disk"),
            Param("r", LENGTH, "radius of the disk: it cancels from the frequencies; modes "
                  "needs it for the mode shapes", optional=True),
            Param("k", STIFFNESS, "stiffness of each spring")),
    compute=block_disk_springs,
    equation="(M + m) x'' - m r phi'' + k x = F(t); -m x'' + (3/2) m r phi'' + k r phi = 0",
    formula="omega_1^2, omega_2^2 = k ((2M + 5m) -+ sqrt(4M^2 - 4M m + 17 m^2)) / "
            "(2 m (3M + m)); modes: M = [[M + m, -m r], [-m r, 3 m r^2/2]], "
            "K = diag(k, k r^2)",
    latex=(r"$omega_1 = \sqrt{$k\,\frac{2$M + 5$m - \sqrt{4$M^2 - 4$M\,$m + 17$m^2}}"
           r"{2$m\,(3$M + $m)}}",
           r"$omega_2 = \sqrt{$k\,\frac{2$M + 5$m + \sqrt{4$M^2 - 4$M\,$m + 17$m^2}}"
           r"{2$m\,(3$M + $m)}}"),
    reference="E4.14",
    example="dyncalc natural-frequency --scene block-disk-springs M=2kg m=1kg k=100N/m",
    example_result={"omega_1": "5.34522483824848769369106961759 rad/s",
                    "f_1": "0.850718954944823509996625824157 Hz",
                    "T_1": "1.175476335853899785616561943 s",
                    "omega_2": "10 rad/s", "f_2": "1.59154943091895335768883763373 Hz",
                    "T_2": "0.628318530717958647692528676656 s"},
    accepts_zeta=False, no_zeta_because=_TWO_MODES,
    matrices=lambda v: block_disk_springs_matrices(v["M"], v["m"], _radius(v), v["k"]),
))

register(Scene(
    name="spring-coupled-pendulums",
    summary="two equal pendulums on one pivot, their bobs joined by a spring",
    figure="two simple pendulums (bob m, massless rod l) hang from the same pivot; a spring "
           "(k, free length b) joins the bobs; phi1 is the angle of the rods' bisector from "
           "the downward vertical, phi2 half the angle between the rods",
    params=(Param("m", MASS, "mass of each bob"), Param("l", LENGTH, "length of each rod"),
            Param("k", STIFFNESS, "spring stiffness"),
            Param("b", LENGTH, "free length of the spring", constraint="nonnegative"),
            gravity()),
    compute=spring_coupled_pendulums,
    equation="l phi1'' + g sin(phi1) cos(phi2) = 0; m l phi2'' + m g cos(phi1) sin(phi2) + "
             "k (2 l sin(phi2) - b) cos(phi2) = 0",
    formula="phi2_0 in [0, pi/2) solves m g sin(phi2) + k (2 l sin(phi2) - b) cos(phi2) = 0 "
            "(bisection); omega_1^2 = g cos(phi2_0)/l, omega_2^2 = g/(l cos(phi2_0)) + "
            "2 k cos(phi2_0)^2/m",
    latex=(r"\tan $phi2_0 = \frac{$k\,($b - 2 $l \sin $phi2_0)}{$m\,$g}",
           r"$omega_1 = \sqrt{\frac{$g \cos $phi2_0}{$l}}",
           r"$omega_2 = \sqrt{\frac{$g}{$l \cos $phi2_0} + \frac{2 $k \cos^2 $phi2_0}{$m}}"),
    reference="E4.16",
    example="dyncalc natural-frequency --scene spring-coupled-pendulums m=1kg l=1m k=100N/m "
            "b=0.5m",
    example_result={"omega_1": "3.08624237885840239088659628431 rad/s",
                    "f_1": "0.491190730175004717261971411305 Hz",
                    "T_1": "2.03586903939272900035933928141 s",
                    "omega_2": "14.0985571347152985735614542244 rad/s",
                    "f_2": "2.24385505845344830745460871399 Hz",
                    "T_2": "0.445661584170788053173894674429 s",
                    "phi2_0": "0.240291336943812874049898019789 rad"},
    accepts_zeta=False, no_zeta_because=_TWO_MODES,
    matrices=lambda v: spring_coupled_pendulums_matrices(v["m"], v["l"], v["k"], v["b"],
                                                         v["g"]),
))

register(Scene(
    name="disk-on-swinging-bar",
    summary="a disk sliding freely along a bar that swings about its upper end",
    figure="a uniform bar (m1, l) swings in a vertical plane about a fixed pin at its upper "
           "end; a disk (m2, J2 about its centre) threaded on the bar slides along it without "
           "friction and turns with it; phi is the bar's angle from the downward vertical, x "
           "the distance of the disk's centre from the pin (valid while 0 <= x <= l)",
    params=(Param("m1", MASS, "mass of the bar"), Param("l", LENGTH, "length of the bar"),
            Param("m2", MASS, "mass of the disk"),
            Param("J2", INERTIA, "moment of inertia of the disk about its centre"), gravity()),
    compute=disk_on_swinging_bar,
    equation="(m1 l^2/3 + m2 x^2 + J2) phi'' + 2 m2 x x' phi' + (m1 l/2 + m2 x) g sin(phi) "
             "= 0; x'' - x phi'^2 - g cos(phi) = 0",
    formula="none: no equilibrium (at rest the disk accelerates outward at g cos(phi)); at a "
            "state phi_ddot = -(2 m2 x x_dot phi_dot + (m1 l/2 + m2 x) g sin(phi)) / "
            "(m1 l^2/3 + m2 x^2 + J2), x_ddot = x phi_dot^2 + g cos(phi)",
    reference="E4.17",
    example="dyncalc eom --scene disk-on-swinging-bar m1=2kg l=1m m2=1kg J2=0.01kg*m^2 "
            "phi=0.3rad x=0.5m phi_dot=1rad/s x_dot=0.2m/s",
    example_result={"phi_ddot": "-4.90693689062928627659340705325 rad/s^2",
                    "x_ddot": "9.86865058108362427252526159318 m/s^2"},
    accepts_zeta=False, no_zeta_because="it has no equilibrium to oscillate about",
    matrices=disk_on_swinging_bar_matrices,
    no_frequency=NO_EQUILIBRIUM,
))

register(Scene(
    name="pendulum-on-sliding-block",
    summary="a pendulum hanging from a block that slides freely",
    figure="a block m1 slides without friction on a horizontal surface; a simple pendulum "
           "(bob m2, massless rod l) hangs from a pin on it; x is the block's position, phi "
           "the rod's angle from the downward vertical",
    params=(Param("m1", MASS, "mass of the block"), Param("m2", MASS, "mass of the bob"),
            Param("l", LENGTH, "length of the rod"), gravity()),
    compute=pendulum_on_sliding_block,
    equation="(m1 + m2) x'' + m2 l phi'' cos(phi) - m2 l phi'^2 sin(phi) = 0; "
             "x'' cos(phi) + l phi'' + g sin(phi) = 0",
    formula="omega^2 = (m1 + m2) g / (m1 l); the other mode is the free drift (omega = 0)",
    latex=(r"$omega = \sqrt{\frac{($m1 + $m2)\,$g}{$m1\,$l}}",),
    reference="E4.19",
    example="dyncalc natural-frequency --scene pendulum-on-sliding-block m1=3kg m2=1kg l=0.5m",
    example_result={"omega": "5.11381136400890980955106142257 rad/s",
                    "f": "0.813888356621525704585572272968 Hz",
                    "T": "1.2286697455054267550201490592 s"},
    accepts_zeta=False, no_zeta_because=_TWO_MODES,
    matrices=lambda v: pendulum_on_sliding_block_matrices(v["m1"], v["m2"], v["l"], v["g"]),
))
