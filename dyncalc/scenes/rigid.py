"""Catalog: rigid scenes (see docs/scenes.md): rolling bodies, drums, pulleys, compound pendulums.

The physics is in :mod:`dyncalc.physics.rigid`; the references are to Gross et al.,
*Engineering Mechanics 3*, 2nd ed. (E5.12 = Example 5.12).
"""
from __future__ import annotations

from ..physics.bodies import KAPPA
from ..physics.rigid import (angled_member, board_on_drums, clock_pendulum,
                             disk_torsion_offset_mass, drum_block_spring, pulley_block_spring,
                             rolling_disk_spring, rolling_in_track, wheel_on_moving_beam)
from ..units import DIMENSIONLESS, LENGTH, MASS, STIFFNESS, TORSIONAL_STIFFNESS
from . import Constraint, Param, Scene, register
from .basic import gravity, small_swings

#: Shape factors ``kappa = J_C / (m r^2)`` of the bodies a ``body=`` parameter names.
BODIES = KAPPA



def body(default: str = "solid-cylinder") -> Param:
    """The rolling body, by name (passed on as its ``kappa``); the alternative to kappa."""
    return Param("body", None, "the rolling body (sets its shape factor kappa)",
                 default=default, constraint=None, choices=BODIES)


def kappa() -> Param:
    """The shape factor ``J_C / (m r^2)`` given as a number instead of ``body``."""
    return Param("kappa", DIMENSIONLESS, "shape factor J_C/(m r^2) of the body, instead of "
                 "body", optional=True, constraint="nonnegative")


ROLLING = "rolling without slipping (enough friction at the contact)"


register(Scene(
    name="rolling-disk-spring",
    summary="a round body rolling on level ground, held by a spring at its centre",
    figure="a disk (or other round body of mass m, shape factor kappa) rolls without slipping "
           "on a level floor; a horizontal spring of stiffness k joins its centre to a wall",
    params=(Param("k", STIFFNESS, "spring stiffness (attached at the centre)"),
            Param("m", MASS, "mass of the body"), body(), kappa()),
    one_of=(("body", "kappa"),),
    compute=rolling_disk_spring,
    equation="(1 + kappa) m x'' + k x = 0 (x the centre's displacement; rolling: x' = r phi')",
    formula="omega^2 = k / ((1 + kappa) m); a disk (kappa = 1/2) gives 2k/(3m)",
    latex=(r"$omega = \sqrt{\frac{$k}{(1 + $kappa)\,$m}}",),
    reference="E4.8",
    example="dyncalc natural-frequency --scene rolling-disk-spring k=300N/m m=2kg",
    example_result={"omega": "10 rad/s", "f": "1.5915494309189533577 Hz",
                    "T": "0.62831853071795864769 s"},
    assumptions=(ROLLING, "the radius cancels: it is not asked for"),
))

register(Scene(
    name="rolling-in-track",
    summary="a round body rolling to and fro in the bottom of a circular track",
    figure="a round body (radius r, shape factor kappa) rolls without slipping inside a fixed "
           "circular track of radius R, in a vertical plane, about the track's lowest point; "
           "its centre moves on a circle of radius l = R - r",
    params=(Param("R", LENGTH, "radius of the track"), Param("r", LENGTH, "radius of the body"),
            body(), kappa(), gravity()),
    one_of=(("body", "kappa"),),
    constraints=(Constraint("R > r", lambda si: si["R"] > si["r"],
                            ": the body rolls inside the track, so its radius r must be "
                            "smaller than the track's radius R"),),
    compute=rolling_in_track,
    equation="(1 + kappa) (R - r) phi'' + g sin(phi) = 0 (phi the angle of the body's centre "
             "from the lowest point)",
    formula="omega^2 = g / ((1 + kappa) (R - r))",
    latex=(r"$omega = \sqrt{\frac{$g}{(1 + $kappa)\,($R - $r)}}",),
    sizes=(small_swings,),
    reference="E4.9, E5.17 (l = R - r)",
    example="dyncalc natural-frequency --scene rolling-in-track R=1m r=0.2m body=solid-sphere",
    example_result={"omega": "2.9590433420279602251 rad/s", "f": "0.47094637470691179551 Hz",
                    "T": "2.1233840065598526073 s"},
    assumptions=(ROLLING, "small oscillations (sin phi = phi)"),
))

register(Scene(
    name="drum-block-spring",
    summary="a block hanging on a rope wound on a drum, held by a spring",
    figure="a drum (homogeneous disk of mass M) turns on a fixed axle; a rope wound on it "
           "carries a block of mass m, which a spring of stiffness k ties to the floor; the "
           "rope does not slip, so the drum turns at x'/R",
    params=(Param("k", STIFFNESS, "spring stiffness"), Param("m", MASS, "mass of the block"),
            Param("M", MASS, "mass of the drum (homogeneous disk)")),
    compute=drum_block_spring,
    equation="(m + M/2) x'' + k x = 0 (x the block's displacement from equilibrium)",
    formula="omega^2 = 2k / (M + 2m); the drum radius cancels",
    latex=(r"$omega = \sqrt{\frac{2\,$k}{$M + 2\,$m}}",),
    reference="E5.12",
    example="dyncalc natural-frequency --scene drum-block-spring k=2kN/m m=4kg M=10kg",
    example_result={"omega": "14.907119849998597976 rad/s", "f": "2.3725418113905901949 Hz",
                    "T": "0.42148888386244358359 s"},
    assumptions=("massless, inextensible rope that does not slip on the drum",
                 "the drum radius cancels: it is not asked for"),
))

register(Scene(
    name="board-on-drums",
    summary="a board lying on two counter-rotating drums, sliding on them with friction",
    figure="a uniform board lies across two drums whose axes, a apart, are level; the drums "
           "turn in opposite senses, their tops moving toward each other (inward), and the "
           "board slides on both with kinetic friction mu",
    params=(Param("mu", DIMENSIONLESS, "coefficient of kinetic friction"),
            Param("a", LENGTH, "distance between the drum axes"), gravity(),
            Param("sense", None, "turning sense of the drums: inward (tops moving toward "
                  "each other) or outward (tops moving apart)", default="inward",
                  constraint=None, choices={"inward": "inward", "outward": "outward"})),
    compute=board_on_drums,
    equation="x'' + (2 mu g / a) x = 0 (x the board's centre from midway between the drums)",
    formula="omega^2 = 2 mu g / a (independent of the drums' speed and the board's mass); "
            "turning outward, the board runs off exponentially instead",
    latex=(r"$omega = \sqrt{\frac{2\,$mu\,$g}{$a}}",),
    reference="E5.13",
    example="dyncalc natural-frequency --scene board-on-drums mu=0.4 a=0.8m",
    example_result={"omega": "3.1315571206669694084 rad/s", "f": "0.49840279532877113126 Hz",
                    "T": "2.0064092925890404509 s"},
    assumptions=("the drums slide under the board all the time (their surface speed exceeds "
                 "the board's)",),
))

register(Scene(
    name="clock-pendulum",
    summary="a uniform rod pivoted at one end, carrying a disk",
    figure="a uniform rod (mass m, length l) hangs from a pivot A at its upper end; a "
           "homogeneous disk (mass M, radius r) is fixed on it with its centre a below A; the "
           "whole swings in the plane of the disk",
    params=(Param("m", MASS, "mass of the rod"), Param("l", LENGTH, "length of the rod"),
            Param("M", MASS, "mass of the disk"), Param("r", LENGTH, "radius of the disk"),
            Param("a", LENGTH, "pivot to the disk's centre"), gravity()),
    compute=clock_pendulum,
    equation="J_A phi'' + (m l/2 + M a) g sin(phi) = 0",
    formula="J_A = m l^2/3 + M (r^2 + 2a^2)/2, omega^2 = (m l + 2 M a) g / (2 J_A)",
    latex=(r"$J_A = \frac{$m\,$l^2}{3} + \frac{$M\,($r^2 + 2\,$a^2)}{2}",
           r"$omega = \sqrt{\frac{($m\,$l + 2\,$M\,$a)\,$g}{2\,$J_A}}"),
    sizes=(small_swings,),
    reference="E5.15",
    example="dyncalc natural-frequency --scene clock-pendulum m=0.5kg l=1m M=2kg r=0.1m a=0.9m",
    example_result={"omega": "3.3450569268931499241 rad/s", "f": "0.53238234483882957272 Hz",
                    "T": "1.8783492910583546076 s", "J_A": "1.7966666666666666667 kg*m^2"},
    assumptions=("small oscillations (sin phi = phi)",),
))

register(Scene(
    name="pulley-block-spring",
    summary="a loose pulley held by a spring, with a block moving twice as far",
    figure="a loose pulley (homogeneous disk of mass M) rides in a bight of rope: one strand "
           "is fixed, the other carries a block of mass m; a spring of stiffness k holds the "
           "pulley's axle, so the block moves twice as far as the pulley's centre",
    params=(Param("k", STIFFNESS, "spring stiffness (on the pulley's axle)"),
            Param("m", MASS, "mass of the block"),
            Param("M", MASS, "mass of the pulley (homogeneous disk)")),
    compute=pulley_block_spring,
    equation="(4m + 3M/2) x'' + k x = 0 (x the pulley's centre; the block moves 2x)",
    formula="omega^2 = k / (4m + 3M/2)",
    latex=(r"$omega = \sqrt{\frac{$k}{4\,$m + \frac{3}{2}\,$M}}",),
    reference="E5.16",
    example="dyncalc natural-frequency --scene pulley-block-spring k=1kN/m m=3kg M=4kg",
    example_result={"omega": "7.453559924999298988 rad/s", "f": "1.1862709056952950975 Hz",
                    "T": "0.84297776772488716718 s"},
    assumptions=("massless, inextensible rope that does not slip on the pulley",
                 "the pulley radius cancels: it is not asked for"),
))

register(Scene(
    name="disk-torsion-offset-mass",
    summary="a disk on a torsion shaft carrying a small disk below its axis",
    figure="a large homogeneous disk (mass M, radius R) sits on a horizontal shaft of "
           "torsional stiffness kt; a small homogeneous disk (mass m, radius r) is fixed to "
           "it, its centre a below the axis in the equilibrium position",
    params=(Param("M", MASS, "mass of the large disk"),
            Param("R", LENGTH, "radius of the large disk"),
            Param("m", MASS, "mass of the small disk"),
            Param("r", LENGTH, "radius of the small disk"),
            Param("a", LENGTH, "offset of the small disk's centre below the axis",
                  constraint="nonnegative"),
            Param("kt", TORSIONAL_STIFFNESS, "torsional stiffness of the shaft",
                  constraint="nonnegative"),
            gravity()),
    compute=disk_torsion_offset_mass,
    equation="(M R^2/2 + m (r^2/2 + a^2)) phi'' + kt phi + m g a sin(phi) = 0",
    formula="omega^2 = (kt + m g a) / (M R^2/2 + m (r^2/2 + a^2)); J_A the denominator",
    latex=(r"$J_A = \frac{$M\,$R^2}{2} + $m\,\left(\frac{$r^2}{2} + $a^2\right)",
           r"$omega = \sqrt{\frac{$kt + $m\,$g\,$a}{$J_A}}"),
    sizes=(small_swings,),
    reference="E5.25",
    example='dyncalc natural-frequency --scene disk-torsion-offset-mass M=20kg R=0.3m m=2kg '
            'r=0.05m a=0.2m "kt=50 N*m/rad"',
    example_result={"omega": "7.4083138772474262582 rad/s", "f": "1.1790697735402126142 Hz",
                    "T": "0.848126228354962258 s", "J_A": "0.9825 kg*m^2"},
    assumptions=("small oscillations (sin phi = phi)", "the shaft is untwisted at equilibrium"),
))

register(Scene(
    name="wheel-on-moving-beam",
    summary="a wheel held by a spring, rolling on a beam that runs freely on rollers",
    figure="a wheel (mass m, shape factor kappa) rolls without slipping on a beam of mass M "
           "that runs on frictionless rollers; a horizontal spring of stiffness k joins the "
           "wheel's centre to a fixed wall",
    params=(Param("k", STIFFNESS, "spring stiffness (wall to the wheel's centre)"),
            Param("m", MASS, "mass of the wheel"), Param("M", MASS, "mass of the beam"),
            body(), kappa()),
    one_of=(("body", "kappa"),),
    compute=wheel_on_moving_beam,
    equation="m x'' + kappa m (x'' - X'') + k x = 0, M X'' = kappa m (x'' - X'') (x the "
             "wheel's centre, X the beam)",
    formula="omega^2 = k / (m + M / (1 + M/(kappa m))) = k (kappa m + M) / (m (kappa m + M "
            "+ kappa M)); the other mode is the beam's free drift (zero frequency)",
    latex=(r"$omega = \sqrt{\frac{$k\,($kappa\,$m + $M)}{$m\,($kappa\,$m + $M + $kappa\,$M)}}",),
    reference="E5.27",
    example="dyncalc natural-frequency --scene wheel-on-moving-beam k=500N/m m=5kg M=20kg",
    example_result={"omega": "8.3205029433784368303 rad/s", "f": "1.3242491724493427529 Hz",
                    "T": "0.75514489327593184617 s"},
    assumptions=(ROLLING,),
))

register(Scene(
    name="angled-member",
    summary="an L-shaped uniform bar swinging about the free end of its long arm",
    figure="a uniform bar bent at a right angle into a long arm of length 2l and a short arm "
           "of length l hangs from a pivot at the free end of the long arm and swings in its "
           "own vertical plane",
    params=(Param("l", LENGTH, "length of the short arm (the long one is 2l)"), gravity()),
    compute=angled_member,
    equation="7 m l^2 phi'' + (sqrt(65)/2) m g l sin(phi) = 0 (m the mass per length l; phi "
             "from the equilibrium)",
    formula="omega^2 = (sqrt(65)/14) g / l",
    latex=(r"$omega = \sqrt{\frac{\sqrt{65}}{14}\,\frac{$g}{$l}}",),
    sizes=(small_swings,),
    reference="E3.44",
    example="dyncalc natural-frequency --scene angled-member l=0.5m",
    example_result={"omega": "3.3607766948250002907 rad/s", "f": "0.53488422360944101905 Hz",
                    "T": "1.8695634603913365744 s"},
    assumptions=("small oscillations (sin phi = phi)", "the mass cancels: it is not asked for"),
))
