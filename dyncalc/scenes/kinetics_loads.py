"""Catalog: rigid-body scenes with loads along a body (the ``rigid-body`` command;
../shared/SCENES.md "Rigid-body scenes"): bearing reactions and moments, stress resultants
``N``, ``V``, ``M`` at ``x=`` and ``t=``.

This module is one of :data:`dyncalc.scenes.kinetics.KINETICS_MODULES`: every scene it
registers is run by ``rigid-body --scene`` and by no other command. See
:mod:`dyncalc.scenes.kinetics` for how a scene joins the command (its ``kinds``, ``x``/``t``
as optional parameters, ``accepts_zeta=False``).
"""
from __future__ import annotations

from ..physics.euler_bearing import precessing_shaft
from ..physics.kinetics_loads import angled_bar_on_shaft, beam_spun_up, rotating_angled_arm
from ..result.explain import Formula
from ..units import (ANGLE, ANGULAR_ACCELERATION, ANGULAR_RATE, FORCE, INERTIA, LENGTH, MASS,
                     TIME, TORQUE)
from . import Param, Scene, register
from .kinetics import NO_ZETA, kind

__all__: list[str] = []

_N = "normal force at the section (tension positive)"

register(Scene(
    name="angled-bar-on-shaft",
    summary="a bent bar on a shaft in two bearings, driven by a moment: its angular "
            "acceleration and the bearing forces",
    figure="a massless shaft turns in radial bearings A and B set 4l apart; at O, halfway, a "
           "bent bar (mass m, length 3l) sticks out 2l at right angles (xi) and then runs l "
           "parallel to the shaft toward A (zeta); a moment M0 drives it, omega its angular "
           "velocity at the instant; eta = zeta x xi is the direction of motion",
    params=(Param("m", MASS, "mass of the bent bar"),
            Param("l", LENGTH, "length of the short leg (the bar is 3l long)"),
            Param("M0", TORQUE, "driving moment about the shaft", constraint=None,
                  symbol="M_{0}"),
            Param("omega", ANGULAR_RATE, "angular velocity at the instant (sense of M0)",
                  default="0 rad/s", constraint=None)),
    compute=angled_bar_on_shaft,
    equation="J_zeta alpha = M0 with J_zeta = 20 m l^2/9; Euler about O: M_xi = J_xizeta "
             "alpha, M_eta = J_xizeta omega^2 (J_xizeta = -m l^2/3); Newton: A + B = m a_C "
             "(xi_C = 4l/3)",
    formula="alpha = 9 M0/(20 m l^2), A_xi = -3 m l omega^2/4, A_eta = 27 M0/(80 l), "
            "B_xi = -7 m l omega^2/12, B_eta = 21 M0/(80 l)",
    latex=(r"$alpha = \frac{9\,$M0}{20\,$m\,$l^2}",
           r"$A_xi = -\frac{3}{4}\,$m\,$l\,$omega^2",
           r"$A_eta = \frac{27\,$M0}{80\,$l}",
           r"$B_xi = -\frac{7}{12}\,$m\,$l\,$omega^2",
           r"$B_eta = \frac{21\,$M0}{80\,$l}"),
    reference="E3.41",
    example="dyncalc rigid-body --scene angled-bar-on-shaft m=3kg l=0.5m \"M0=10 N*m\" "
            "omega=2rad/s",
    example_result={"alpha": "6 rad/s^2", "A_xi": "-4.5 N", "A_eta": "6.75 N",
                    "B_xi": "-3.5 N", "B_eta": "5.25 N"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    assumptions=("weight neglected; checks: A_xi + B_xi = -m xi_C omega^2, A_eta + B_eta = "
                 "m xi_C alpha",),
    kinds={"alpha": kind(ANGULAR_ACCELERATION, "α", "angular acceleration of the shaft"),
           "A_xi": kind(FORCE, "A_ξ", "bearing force at A along the long leg xi"),
           "A_eta": kind(FORCE, "A_η", "bearing force at A in the direction of motion eta"),
           "B_xi": kind(FORCE, "B_ξ", "bearing force at B along the long leg xi"),
           "B_eta": kind(FORCE, "B_η", "bearing force at B in the direction of motion eta")},
))


def _uniform(si) -> bool:
    return "alpha0" not in si


register(Scene(
    name="precessing-shaft",
    summary="a spinning shaft whose bearings turn about a perpendicular axis: the bearing "
            "moment (gyroscopic moment)",
    figure="a shaft (J1 about its axis 1, J2 and J3 transverse) spins at omega0 in bearings "
           "carried by a frame that turns about the fixed vertical z by alpha(t); axis 1 stays "
           "horizontal, 3 is along z, 2 = 3 x 1; psi is the spin angle from z to the principal "
           "axis of J3. Uniform turning alpha = Omega t (no alpha0), or harmonic "
           "alpha = alpha0 sin(Omega t) (give alpha0 and t)",
    params=(Param("J1", INERTIA, "moment of inertia about the shaft axis",
                  constraint="nonnegative", symbol="J_{1}"),
            Param("J3", INERTIA, "transverse principal moment (about the axis along z at "
                  "psi = 0)", constraint="nonnegative", symbol="J_{3}"),
            Param("J2", INERTIA, "the other transverse principal moment (default J3)",
                  optional=True, constraint="nonnegative", symbol="J_{2}"),
            Param("omega0", ANGULAR_RATE, "spin relative to the turning frame",
                  constraint=None, symbol=r"\omega_{0}"),
            Param("Omega", ANGULAR_RATE, "turning rate (uniform) or angular frequency "
                  "(harmonic)", constraint=None),
            Param("alpha0", ANGLE, "amplitude of harmonic turning alpha0 sin(Omega t)",
                  optional=True, constraint=None, symbol=r"\alpha_{0}"),
            Param("t", TIME, "the instant (harmonic turning)", optional=True,
                  constraint=None),
            Param("psi", ANGLE, "spin angle at the instant (matters when J2 != J3)",
                  default="0 rad", constraint=None)),
    compute=precessing_shaft,
    equation="M = dH/dt (fixed frame), H = J omega, omega = omega0 e1 + alpha' e3",
    formula="M1 = -(J2 - J3) sin(2 psi) a'^2/2, "
            "M2 = J1 omega0 a' + (J2 - J3) (omega0 a' cos(2 psi) + a'' sin(2 psi)/2), "
            "M3 = (J2 sin(psi)^2 + J3 cos(psi)^2) a'' + (J2 - J3) omega0 a' sin(2 psi); "
            "a' = Omega, a'' = 0 (uniform) or a' = alpha0 Omega cos(Omega t), "
            "a'' = -alpha0 Omega^2 sin(Omega t) (harmonic); book erratum: M2 is not "
            "(J1 - J3) omega0 a'",
    latex=(Formula(r"$alpha_dot = $Omega", _uniform),
           r"$alpha_dot = $alpha0\,$Omega\,\cos($Omega\,$t)",
           r"$alpha_ddot = -$alpha0\,$Omega^2\,\sin($Omega\,$t)",
           Formula(r"$M2 = $J1\,$omega0\,$alpha_dot",
                   lambda si: si.get("J2", si["J3"]) == si["J3"]),
           Formula(r"$M3 = $J3\,$alpha_ddot", lambda si: si.get("J2", si["J3"]) == si["J3"]),
           r"$M1 = -\frac{1}{2}\,($J2 - $J3)\,\sin(2\,$psi)\,$alpha_dot^2",
           r"$M2 = $J1\,$omega0\,$alpha_dot + ($J2 - $J3)\,($omega0\,$alpha_dot\,"
           r"\cos(2\,$psi) + \frac{1}{2}\,$alpha_ddot\,\sin(2\,$psi))",
           r"$M3 = ($J2\,\sin^2 $psi + $J3\,\cos^2 $psi)\,$alpha_ddot + ($J2 - $J3)\,"
           r"$omega0\,$alpha_dot\,\sin(2\,$psi)"),
    reference="E3.42 (book erratum: M2)",
    example="dyncalc rigid-body --scene precessing-shaft \"J1=0.02 kg*m^2\" \"J2=0.6 kg*m^2\" "
            "\"J3=0.5 kg*m^2\" omega0=100rad/s Omega=2rad/s psi=30deg",
    example_result={"M1": "-0.17320508075688772935 N*m", "M2": "14 N*m",
                    "M3": "17.320508075688772935 N*m", "alpha_dot": "2 rad/s",
                    "alpha_ddot": "0 rad/s^2"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    assumptions=("the book's M2 = (J1 - J3) omega0 alpha' is a misprint: dH/dt gives "
                 "J1 omega0 alpha' for a symmetric shaft",),
    kinds={"M1": kind(TORQUE, "M1", "bearing moment about the shaft axis 1"),
           "M2": kind(TORQUE, "M2", "bearing moment about the horizontal axis 2 = 3 x 1 "
                      "(gyroscopic)"),
           "M3": kind(TORQUE, "M3", "bearing moment about the fixed axis 3 (z)"),
           "alpha_dot": kind(ANGULAR_RATE, "α'", "turning rate alpha' at the instant"),
           "alpha_ddot": kind(ANGULAR_ACCELERATION, "α''", "turning acceleration alpha'' at "
                              "the instant")},
))

register(Scene(
    name="beam-spun-up",
    summary="a beam pinned at one end, spun up from rest by a constant moment: N, V, M along "
            "it",
    figure="a uniform beam (mass m, length l) lies in a horizontal plane, pinned at its end A; "
           "from rest at t = 0 a constant moment M0 about the pin turns it; x is the distance "
           "of a section from A. N (tension), V (in the direction of motion) and M (against "
           "the rotation) act from the inner part on the outer part",
    params=(Param("m", MASS, "mass of the beam"), Param("l", LENGTH, "length of the beam"),
            Param("M0", TORQUE, "driving moment about the pin", constraint=None,
                  symbol="M_{0}"),
            Param("x", LENGTH, "distance of the section from the pin, 0 <= x <= l "
                  "(V, M; with t also N)", optional=True, constraint=None),
            Param("t", TIME, "time since the start, t >= 0 (omega; with x also N)",
                  optional=True, constraint=None)),
    compute=beam_spun_up,
    equation="(m l^2/3) alpha = M0; loads on the outer part dm (s alpha) across, dm (s omega^2) "
             "along (d'Alembert), s from the pin",
    formula="alpha = 3 M0/(m l^2), omega = alpha t, V = (3 M0/(2 l)) (1 - (x/l)^2), "
            "M = -M0 (1 - x/l)^2 (1 + x/(2 l)), N = (9 M0^2 t^2/(2 m l^3)) (1 - (x/l)^2); "
            "dM/dx = V",
    latex=(r"$alpha = \frac{3\,$M0}{$m\,$l^2}",
           r"$omega = $alpha\,$t",
           r"$N = \frac{9\,$M0^2\,$t^2}{2\,$m\,$l^3}\,\left(1 - \frac{$x^2}{$l^2}\right)",
           r"$V = \frac{3\,$M0}{2\,$l}\,\left(1 - \frac{$x^2}{$l^2}\right)",
           r"$M = -$M0\,\left(1 - \frac{$x}{$l}\right)^2\,\left(1 + \frac{$x}{2\,$l}\right)"),
    reference="E3.43",
    example="dyncalc rigid-body --scene beam-spun-up m=6kg l=2m \"M0=12 N*m\" x=0.5m t=2s",
    example_result={"alpha": "1.5 rad/s^2", "omega": "3 rad/s", "N": "50.625 N",
                    "V": "8.4375 N", "M": "-7.59375 N*m"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    assumptions=("V and M do not change with time; N grows with t^2",),
    kinds={"alpha": kind(ANGULAR_ACCELERATION, "α", "angular acceleration of the beam"),
           "omega": kind(ANGULAR_RATE, "ω", "angular velocity at t"),
           "N": kind(FORCE, "N", _N),
           "V": kind(FORCE, "V", "shear force at the section (in the direction of motion)"),
           "M": kind(TORQUE, "M", "bending moment at the section (positive against the "
                     "rotation)")},
))

register(Scene(
    name="rotating-angled-arm",
    summary="an L-shaped arm turning steadily about the end of one leg: N, V, M in it",
    figure="an L-shaped arm (mass m, legs a and b at right angles) turns at constant Omega in "
           "a horizontal plane about a fixed axis through 0, the free end of leg a; leg a runs "
           "from 0 to the corner K, leg b from K to the free end E. x1 runs along leg b from E, "
           "x2 along leg a from K; z points to the inside of the L",
    params=(Param("m", MASS, "mass of the whole arm"),
            Param("a", LENGTH, "length of leg a (from the axis to the corner)"),
            Param("b", LENGTH, "length of leg b (from the corner to the free end)"),
            Param("Omega", ANGULAR_RATE, "angular velocity", constraint=None),
            Param("x1", LENGTH, "section on leg b, from its free end E (0 <= x1 <= b)",
                  optional=True, constraint=None, symbol="x_{1}"),
            Param("x2", LENGTH, "section on leg a, from the corner K (0 <= x2 <= a)",
                  optional=True, constraint=None, symbol="x_{2}")),
    compute=rotating_angled_arm,
    one_of=(("x1", "x2"),),
    equation="centrifugal loads dm r Omega^2 on the outer part (toward E), mu = m/(a + b)",
    formula="leg b: N = mu Omega^2 (b x1 - x1^2/2), V = mu Omega^2 a x1, "
            "M = mu Omega^2 a x1^2/2; leg a: N = mu Omega^2 (a b + a x2 - x2^2/2), "
            "V = -mu Omega^2 b^2/2, M = mu Omega^2 b^2 (a - x2)/2; corner: N0 = mu Omega^2 a b, "
            "V0 = -mu Omega^2 b^2/2, M0 = mu Omega^2 a b^2/2",
    latex=(r"$N = \frac{$m}{$a + $b}\,$Omega^2\,\left($b\,$x1 - \frac{$x1^2}{2}\right)",
           r"$V = \frac{$m}{$a + $b}\,$Omega^2\,$a\,$x1",
           r"$M = \frac{$m}{$a + $b}\,$Omega^2\,\frac{$a\,$x1^2}{2}",
           r"$N = \frac{$m}{$a + $b}\,$Omega^2\,\left($a\,$b + $a\,$x2 - "
           r"\frac{$x2^2}{2}\right)",
           r"$V = -\frac{$m}{$a + $b}\,$Omega^2\,\frac{$b^2}{2}",
           r"$M = \frac{$m}{$a + $b}\,$Omega^2\,\frac{$b^2\,($a - $x2)}{2}",
           r"$N0 = \frac{$m}{$a + $b}\,$Omega^2\,$a\,$b",
           r"$V0 = -\frac{$m}{$a + $b}\,$Omega^2\,\frac{$b^2}{2}",
           r"$M0 = \frac{$m}{$a + $b}\,$Omega^2\,\frac{$a\,$b^2}{2}"),
    reference="E4.11",
    example="dyncalc rigid-body --scene rotating-angled-arm m=3kg a=1m b=0.5m Omega=10rad/s "
            "x1=0.25m",
    example_result={"N": "18.75 N", "V": "50 N", "M": "6.25 N*m", "N0": "100 N",
                    "V0": "-25 N", "M0": "25 N*m"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    assumptions=("M vanishes at the axis: a uniformly turning body needs no torque",),
    kinds={"N": kind(FORCE, "N", _N),
           "V": kind(FORCE, "V", "shear force at the section (toward the inside of the L)"),
           "M": kind(TORQUE, "M", "bending moment at the section (stretching the inside "
                     "fibres)"),
           "N0": kind(FORCE, "N0", "normal force in leg a at the corner"),
           "V0": kind(FORCE, "V0", "shear force in leg a at the corner"),
           "M0": kind(TORQUE, "M0", "bending moment at the corner")},
))
