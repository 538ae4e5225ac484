"""Catalog: the basic oscillators (mass-spring, torsional, pendulum, physical pendulum)."""
from __future__ import annotations

from ..constants import STANDARD_GRAVITY_TEXT
from ..physics.oscillators import mass_spring, pendulum, physical_pendulum, torsional
from ..result.explain import Formula
from ..units import (ACCELERATION, ANGLE, INERTIA, LENGTH, MASS, STIFFNESS,
                     TORSIONAL_STIFFNESS)
from . import Param, Scene, register

G_DEFAULT = STANDARD_GRAVITY_TEXT


def gravity() -> Param:
    return Param("g", ACCELERATION, "gravitational acceleration", default=G_DEFAULT)


def small_swings(values) -> str:
    """The size of "small oscillations" for a scene that takes no amplitude."""
    return ("no amplitude is given (this scene takes none): omega is the limit of small "
            "swings; sin phi = phi is 1% off at 14 deg, 5% at 32 deg")


def amplitude(limit: str = "below 180 deg", symbol: str = "theta0") -> Param:
    return Param("amplitude", ANGLE, f"swing amplitude {symbol} ({limit}); omit for small "
                 "oscillations", optional=True, constraint="nonnegative",
                 symbol={"theta0": r"\theta_{0}", "phi0": r"\varphi_{0}"}.get(symbol, ""))


register(Scene(
    name="mass-spring",
    summary="a mass on a linear spring",
    figure="a block of mass m hangs on (or slides on a frictionless floor against) a spring "
           "of stiffness k",
    params=(Param("k", STIFFNESS, "spring stiffness"), Param("m", MASS, "mass")),
    compute=mass_spring,
    equation="m x'' + k x = 0",
    formula="omega^2 = k / m",
    latex=(r"$omega = \sqrt{\frac{$k}{$m}}",),
    reference="E5.11, E5.19, E5.26 (after the springs are reduced to one)",
    example="dyncalc natural-frequency --k 100N/m --m 2kg",
    example_result={"omega": "7.0710678118654755 rad/s", "f": "1.1253953951963828 Hz",
                    "T": "0.8885765876316732 s"},
    assumptions=("linear spring, no damping (give --zeta for the damped frequency)",),
))

register(Scene(
    name="torsional",
    summary="a rotor on a torsional spring",
    figure="a disk of moment of inertia J on a shaft of torsional stiffness kt",
    params=(Param("kt", TORSIONAL_STIFFNESS, "torsional stiffness"),
            Param("J", INERTIA, "moment of inertia about the shaft")),
    compute=torsional,
    equation="J phi'' + kt phi = 0",
    formula="omega^2 = kt / J",
    latex=(r"$omega = \sqrt{\frac{$kt}{$J}}",),
    reference="Gross et al., Chapter 5 (free vibrations); no worked example of its own",
    example='dyncalc natural-frequency --kt "3 kN*m/rad" --inertia "1.2 kg*m^2"',
    example_result={"omega": "50 rad/s", "f": "7.957747154594767 Hz",
                    "T": "0.12566370614359174 s"},
    assumptions=("linear torsional spring, massless shaft",),
))

register(Scene(
    name="pendulum",
    summary="a simple pendulum, exact at any amplitude below 180 degrees",
    figure="a point mass on a massless rod of length l swinging in a vertical plane",
    params=(Param("l", LENGTH, "length"), gravity(), amplitude()),
    compute=pendulum,
    equation="theta'' + (g/l) sin(theta) = 0",
    formula="omega_0^2 = g / l; at amplitude theta0: T = 2 pi / (omega_0 AGM(1, cos(theta0/2)))",
    latex=(Formula(r"$omega = \sqrt{\frac{$g}{$l}}", lambda v: "omega_0" not in v),
           r"$omega_0 = \sqrt{\frac{$g}{$l}}",
           r"$T = \frac{2\pi}{$omega_0\,\operatorname{AGM}\left(1, \cos\left(\frac{$amplitude}"
           r"{2}\right)\right)}",
           Formula(r"$omega = \frac{2\pi}{$T}", lambda v: "omega_0" in v)),
    reference="Gross et al., Chapter 5 (the mathematical pendulum); the exact period is the "
              "complete elliptic integral 4 K(sin(theta0/2)) / omega_0",
    example="dyncalc natural-frequency --length 1m --amplitude 90deg",
    example_result={"T": "2.36824634628600988 s", "omega": "2.65309616840881415 rad/s",
                    "omega_0": "3.13155712066696941 rad/s"},
    methods=("small-angle", "series", "elliptic", "ode"),
))

register(Scene(
    name="physical-pendulum",
    summary="a rigid body swinging about a pivot, exact at any amplitude below 180 degrees",
    figure="a body of mass m hangs from a pivot A at distance a above its centre of mass; J is "
           "its moment of inertia about the centre of mass (or give J_A about the pivot)",
    params=(Param("m", MASS, "mass"), Param("a", LENGTH, "pivot to centre of mass"),
            Param("J", INERTIA, "moment of inertia about the centre of mass", optional=True),
            Param("J_A", INERTIA, "moment of inertia about the pivot", optional=True),
            gravity(), amplitude()),
    one_of=(("J", "J_A"),),
    compute=physical_pendulum,
    equation="J_A phi'' + m g a sin(phi) = 0",
    formula="omega_0^2 = m g a / J_A, J_A = J + m a^2; large amplitude as for pendulum",
    latex=(r"$J_A = $J + $m\,$a^2",
           Formula(r"$omega = \sqrt{\frac{$m\,$g\,$a}{$J_A}}", lambda v: "omega_0" not in v),
           r"$omega_0 = \sqrt{\frac{$m\,$g\,$a}{$J_A}}",
           r"$T = \frac{2\pi}{$omega_0\,\operatorname{AGM}\left(1, \cos\left(\frac{$amplitude}"
           r"{2}\right)\right)}",
           Formula(r"$omega = \frac{2\pi}{$T}", lambda v: "omega_0" in v)),
    reference="E3.44, E5.15",
    example='dyncalc natural-frequency --scene physical-pendulum m=2kg a=0.5m "J=(2/12) kg*m^2"',
    example_result={"omega": "3.83535852300668236 rad/s", "T": "1.63822632734056901 s",
                    "J_A": "0.6666666666666667 kg*m^2"},
    methods=("small-angle", "series", "elliptic", "ode"),
))
