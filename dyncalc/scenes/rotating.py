"""Catalog: nonlinear, coupled, rotating and moving-support scenes (see docs/scenes.md).

The ``example_result`` values were computed independently with mpmath at 30 digits from the
formulas of the contract, ../shared/SCENES.md (the half-cylinder's period by mpmath.quad of its
energy integral, the rod's equilibrium by mpmath.findroot, the coupled blocks' frequencies by
mpmath.eig).
"""
from __future__ import annotations

import math

from ..physics.coupled import coupled_blocks
from ..physics.lagrange import coupled_blocks_matrices
from ..physics.nonlinear import half_cylinder_shell, rod_torsion_spring
from ..physics.rotating import (bead_on_rotating_ring, pendulum_accelerating_support,
                                pendulum_on_rotating_disk, quarter_car)
from ..units import (ACCELERATION, ANGULAR_RATE, LENGTH, MASS, STIFFNESS, TORSIONAL_STIFFNESS,
                     VELOCITY)
from ..result.explain import Formula
from . import Constraint, Param, Scene, register
from .basic import amplitude, gravity

def _below_bifurcation(v) -> bool:
    """``Omega^2 r <= g``, compared as ``Omega <= sqrt(g)/sqrt(r)`` (no overflow)."""
    return v["Omega"] <= math.sqrt(v["g"]) / math.sqrt(v["r"])


register(Scene(
    name="half-cylinder-shell",
    summary="a thin half-cylinder shell rocking on flat ground, at any amplitude below 90 "
            "degrees",
    figure="a thin semicircular shell of radius r (a half pipe) lies on its curved side on "
           "a horizontal floor and rocks without slipping; phi is its tilt from the upright "
           "position",
    params=(Param("r", LENGTH, "shell radius"), gravity(), amplitude("below 90 deg", "phi0")),
    compute=half_cylinder_shell,
    equation="phi'' (pi - 2 cos phi) + phi'^2 sin phi + (g/r) sin phi = 0",
    formula="omega_0^2 = g / ((pi - 2) r); at amplitude phi0: T = 4 sqrt(r/g) "
            "int_0^(pi/2) sqrt(pi - 2 + 4 k^2 sin^2 u) / sqrt(1 - k^2 sin^2 u) du, "
            "k = sin(phi0/2) (quadrature), or the equation of motion integrated (ode)",
    latex=(Formula(r"$omega = \sqrt{\frac{$g}{(\pi - 2)\,$r}}", lambda v: "omega_0" not in v),
           r"$omega_0 = \sqrt{\frac{$g}{(\pi - 2)\,$r}}",
           r"q = \sin\left(\frac{$amplitude}{2}\right)",
           r"$T = 4\,\sqrt{\frac{$r}{$g}}\,\int_0^{\pi/2} \frac{\sqrt{\pi - 2 + 4 q^2 \sin^2 u}}"
           r"{\sqrt{1 - q^2 \sin^2 u}} \mathrm{d}u",
           Formula(r"$omega = \frac{2\pi}{$T}", lambda v: "omega_0" in v)),
    reference="E4.18",
    example="dyncalc natural-frequency --scene half-cylinder-shell r=0.5m --amplitude 60deg",
    example_result={"T": "1.94996853096615652 s", "omega": "3.22219831110117381 rad/s",
                    "f": "0.512828788834108581 Hz",
                    "omega_0": "4.14495436047052202 rad/s"},
    methods=("linear", "quadrature", "ode"),
    assumptions=("thin shell (all its mass on the arc), rolling without slipping",),
))

register(Scene(
    name="rod-torsion-spring",
    summary="a rod with a tip mass on a torsion spring, sagging under its weight",
    figure="a massless rod of length l with a point mass m at its tip is pivoted at its other "
           "end on a torsion spring kt that is unstretched with the rod horizontal; the "
           "weight turns it down by phi_0, where it oscillates",
    params=(Param("m", MASS, "tip mass"), Param("l", LENGTH, "rod length"),
            Param("kt", TORSIONAL_STIFFNESS, "torsion spring stiffness (unstretched with the "
                  "rod horizontal)"), gravity()),
    compute=rod_torsion_spring,
    equation="m l^2 phi'' + kt phi - m g l cos(phi) = 0 (phi below the horizontal)",
    formula="(g/l) cos(phi_0) = kt phi_0 / (m l^2) (a bracketed root find on (0, pi/2)); "
            "omega^2 = (g/l) sin(phi_0) + kt / (m l^2)",
    latex=(r"\frac{$g}{$l}\,\cos $phi_0 = \frac{$kt\,$phi_0}{$m\,$l^2}",
           r"$omega = \sqrt{\frac{$g}{$l}\,\sin $phi_0 + \frac{$kt}{$m\,$l^2}}"),
    reference="E5.20",
    example='dyncalc natural-frequency --scene rod-torsion-spring m=2kg l=1m '
            '"kt=30 N*m/rad"',
    example_result={"omega": "4.49127447428653215 rad/s", "f": "0.714808533365155165 Hz",
                    "T": "1.39897602410008818 s", "phi_0": "31.8266447463013929 deg"},
))

register(Scene(
    name="coupled-blocks",
    summary="two blocks coupled by springs between two walls: two modes",
    figure="block m1 is tied to the left wall by k1, block m2 to the right wall by k2, and the "
           "blocks to each other by k3; they slide on a frictionless floor",
    params=(Param("m1", MASS, "mass of block 1"), Param("m2", MASS, "mass of block 2"),
            Param("k1", STIFFNESS, "spring from block 1 to its wall", constraint="nonnegative"),
            Param("k2", STIFFNESS, "spring from block 2 to its wall", constraint="nonnegative"),
            Param("k3", STIFFNESS, "spring between the blocks", constraint="nonnegative")),
    constraints=(Constraint("at least two of k1, k2, k3 positive",
                            lambda si: sum(si[n] > 0 for n in ("k1", "k2", "k3")) >= 2,
                            "; otherwise a block drifts freely (a mode of zero frequency)"),),
    compute=coupled_blocks,
    equation="M x'' + K x = 0, K = [[k1+k3, -k3], [-k3, k2+k3]], M = diag(m1, m2)",
    formula="K v = omega^2 M v: omega_1 < omega_2 and the mode shapes mode_1, mode_2 "
            "(amplitude ratios (x1, x2), unit length, first non-zero component positive)",
    latex=(r"$omega_1 = \sqrt{\frac{1}{2}\,\left(\frac{$k1 + $k3}{$m1} + \frac{$k2 + $k3}{$m2}"
           r"\right) - \sqrt{\frac{1}{4}\,\left(\frac{$k1 + $k3}{$m1} - \frac{$k2 + $k3}{$m2}"
           r"\right)^2 + \frac{$k3^2}{$m1\,$m2}}}",
           r"$omega_2 = \sqrt{\frac{1}{2}\,\left(\frac{$k1 + $k3}{$m1} + \frac{$k2 + $k3}{$m2}"
           r"\right) + \sqrt{\frac{1}{4}\,\left(\frac{$k1 + $k3}{$m1} - \frac{$k2 + $k3}{$m2}"
           r"\right)^2 + \frac{$k3^2}{$m1\,$m2}}}",
           r"$f_1 = \frac{$omega_1}{2\pi}", r"$f_2 = \frac{$omega_2}{2\pi}"),
    reference="E4.15",
    example="dyncalc natural-frequency --scene coupled-blocks m1=1kg m2=2kg k1=100N/m "
            "k2=200N/m k3=50N/m",
    example_result={"omega_1": "10 rad/s", "f_1": "1.59154943091895336 Hz",
                    "T_1": "0.628318530717958648 s", "omega_2": "13.228756555322953 rad/s",
                    "f_2": "2.10542199673896195 Hz", "T_2": "0.47496416468949038 s"},
    accepts_zeta=False,
    no_zeta_because="it has two modes, and one damping ratio for both would be ambiguous",
    matrices=lambda v: coupled_blocks_matrices(v["m1"], v["m2"], v["k1"], v["k2"], v["k3"]),
))

register(Scene(
    name="pendulum-accelerating-support",
    summary="a pendulum whose support accelerates horizontally",
    figure="a simple pendulum of length l hangs from a support (a vehicle) that moves "
           "horizontally with constant acceleration a0; phi from the downward vertical, "
           "positive toward the direction of a0",
    params=(Param("l", LENGTH, "length"),
            Param("a0", ACCELERATION, "support acceleration (any sign; 0 is at rest)",
                  constraint=None), gravity()),
    compute=pendulum_accelerating_support,
    equation="l phi'' + g sin(phi) + a0 cos(phi) = 0",
    formula="phi_0 = -atan(a0/g) (the bob trails behind); omega^2 = sqrt(g^2 + a0^2) / l",
    latex=(r"$phi_0 = -\arctan\left(\frac{$a0}{$g}\right)",
           r"$omega = \sqrt{\frac{\sqrt{$g^2 + $a0^2}}{$l}}"),
    reference="E6.5",
    example="dyncalc natural-frequency --scene pendulum-accelerating-support l=1m "
            "a0=3m/s^2",
    example_result={"omega": "3.20238368948764375 rad/s", "f": "0.509675193858819764 Hz",
                    "T": "1.96203388363648792 s", "phi_0": "-17.009650306455806 deg"},
))

register(Scene(
    name="pendulum-on-rotating-disk",
    summary="a pendulum on a spinning disk, held out by the centrifugal field",
    figure="a pendulum of length l is pivoted at distance r from the centre of a disk that "
           "spins at Omega about its vertical axis; it swings in the horizontal plane "
           "(weight neglected), about the radially outward direction",
    params=(Param("r", LENGTH, "disk centre to pivot"), Param("l", LENGTH, "pendulum length"),
            Param("Omega", ANGULAR_RATE, "spin of the disk (rad/s, rpm, ...)",
                  constraint="nonzero")),
    compute=pendulum_on_rotating_disk,
    equation="phi'' + (r/l) Omega^2 sin(phi) = 0 (phi from the radial direction)",
    formula="omega = sqrt(r/l) Omega",
    latex=(r"$omega = \sqrt{\frac{$r}{$l}}\,$Omega",),
    reference="E6.8",
    example="dyncalc natural-frequency --scene pendulum-on-rotating-disk r=0.5m l=0.2m "
            "Omega=60rpm",
    example_result={"omega": "9.93458826579610123 rad/s", "f": "1.58113883008418967 Hz",
                    "T": "0.632455532033675866 s"},
))

register(Scene(
    name="bead-on-rotating-ring",
    summary="a bead on a ring spinning about its vertical diameter: at the bottom or riding up",
    figure="a bead slides without friction on a circular ring of radius r that spins at Omega "
           "about its vertical diameter; theta is measured from the bottom",
    params=(Param("r", LENGTH, "ring radius"),
            Param("Omega", ANGULAR_RATE, "spin of the ring (rad/s, rpm, ...)",
                  constraint=None), gravity()),
    compute=bead_on_rotating_ring,
    equation="theta'' = sin(theta) (Omega^2 cos(theta) - g/r)",
    formula="Omega^2 < g/r: theta_eq = 0, omega^2 = g/r - Omega^2; Omega^2 > g/r: "
            "theta_eq = acos(g/(r Omega^2)) (and -theta_eq), omega^2 = Omega^2 - "
            "(g/(r Omega))^2; at Omega^2 = g/r omega = 0 (bifurcation)",
    latex=(Formula(r"$omega = \sqrt{\frac{$g}{$r} - $Omega^2}",
                   lambda v: _below_bifurcation(v)),
           Formula(r"$theta_eq = \arccos\left(\frac{$g}{$r\,$Omega^2}\right)",
                   lambda v: not _below_bifurcation(v)),
           Formula(r"$omega = \sqrt{$Omega^2 - \left(\frac{$g}{$r\,$Omega}\right)^2}",
                   lambda v: not _below_bifurcation(v))),
    reference="E6.11",
    example="dyncalc natural-frequency --scene bead-on-rotating-ring r=0.2m Omega=120rpm",
    example_result={"omega": "11.9452299518987473 rad/s", "f": "1.90114239321404878 Hz",
                    "T": "0.525999527215534793 s", "theta_eq": "71.9102317952573478 deg"},
))

register(Scene(
    name="quarter-car",
    summary="a quarter-car on a wavy road: steady amplitude and critical speed",
    figure="a body of mass m rides on a suspension spring k whose lower end follows a road "
           "u = U0 cos(2 pi x / L) at speed v0 (no damping)",
    params=(Param("k", STIFFNESS, "suspension stiffness"), Param("m", MASS, "body mass"),
            Param("L", LENGTH, "road wavelength"), Param("U0", LENGTH, "road amplitude"),
            Param("v0", VELOCITY, "speed", constraint="nonnegative")),
    compute=quarter_car,
    equation="m x'' + k x = k U0 cos(Omega t)",
    formula="omega^2 = k/m, Omega = 2 pi v0 / L, x_amp = U0 / |1 - Omega^2/omega^2|, "
            "v_crit = L sqrt(k/m) / (2 pi)",
    latex=(r"$omega = \sqrt{\frac{$k}{$m}}", r"$Omega = \frac{2\pi\,$v0}{$L}",
           r"$x_amp = \frac{$U0}{\left|1 - $Omega^2/$omega^2\right|}",
           r"$v_crit = \frac{$L\,$omega}{2\pi}"),
    reference="E5.23",
    example="dyncalc natural-frequency --scene quarter-car k=40kN/m m=400kg L=10m U0=2cm "
            "v0=20m/s",
    example_result={"omega": "10 rad/s", "f": "1.59154943091895336 Hz",
                    "T": "0.628318530717958648 s", "Omega": "12.566370614359173 rad/s",
                    "x_amp": "0.0345341606840736282 m",
                    "v_crit": "15.9154943091895336 m/s"},
    accepts_zeta=False,
    no_zeta_because="x_amp is the undamped steady amplitude, which a zeta would not reach",
))
