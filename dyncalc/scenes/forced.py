"""Catalog: forced set-ups (the ``forced-response`` command; ../shared/SCENES.md, "Forced scenes").

:data:`OSCILLATOR` is the command's own model, the mass-spring-damper driven by one harmonic
excitation (not listed in the catalog: it is what ``forced-response`` computes without
``--scene``). :data:`DRIVEN` holds the catalog scenes that ``forced-response --scene`` runs
with their own forcing and, unlike natural-frequency, damping (``quarter-car``,
``frame-brace-damper``). ``mass-spring-given-response`` and ``rolling-wheel-moving-ground``
are registered in the catalog. Every ``example_result`` was computed independently with
mpmath at 30 digits from the formulas of ../shared/SCENES.md.
"""
from __future__ import annotations

from ..physics.forced import SQRT_HALF, forced_response
from ..physics.forced_scenes import (frame_brace_forced, mass_spring_given_response,
                                     quarter_car_forced, rolling_wheel_moving_ground)
from ..result.explain import Formula
from ..units import (ACCELERATION, ANGULAR_RATE, DIMENSIONLESS, FORCE, LENGTH, MASS,
                     STIFFNESS, TIME, UNBALANCE, VELOCITY)
from . import Param, Scene, register
from .basic import gravity
from .damped import FRAME_FIGURE, FRAME_PARAMS
from .forced_parts import _STEADY_LATEX, _damping, _frequency
from .rigid import body, kappa

__all__ = ["OSCILLATOR", "DRIVEN", "EXCITATION_PARAMS", "forced_scene"]

#: The excitation parameters, one of which the oscillator takes.
EXCITATION_PARAMS = ("F0", "base", "base_accel", "unbalance")


_ASSUMPTIONS = ("linear viscous damping (a force c x' against the velocity)",)

OSCILLATOR = Scene(
    name="mass-spring-damper",
    summary="a mass on a spring and a viscous damper, driven harmonically",
    figure="a block of mass m on a spring k and a damper c; the block is pushed by a force "
           "F0 cos(Omega t), or the support moves u0 cos(Omega t), or the ground accelerates "
           "B0 cos(Omega t), or a rotor of unbalance m_u e spins at Omega inside it",
    params=(Param("k", STIFFNESS, "stiffness", optional=True),
            Param("m", MASS, "mass (the whole machine's, unbalance included)", optional=True),
            Param("omega", ANGULAR_RATE, "natural angular frequency, instead of k and m",
                  optional=True),
            *_damping(),
            Param("F0", FORCE, "force amplitude", optional=True, constraint="nonnegative",
                  symbol="F_{0}"),
            Param("base", LENGTH, "support displacement amplitude u0", optional=True,
                  constraint="nonnegative", symbol="u_{0}"),
            Param("base_accel", ACCELERATION, "ground acceleration amplitude B0",
                  optional=True, constraint="nonnegative", symbol="B_{0}"),
            Param("unbalance", UNBALANCE, "rotating unbalance m_u e", optional=True,
                  constraint="nonnegative", symbol=r"m_{u}e"),
            *_frequency(),
            Param("x0", LENGTH, "initial displacement (with t)", optional=True,
                  constraint=None, symbol="x_{0}"),
            Param("v0", VELOCITY, "initial velocity (with t)", optional=True,
                  constraint=None, symbol="v_{0}"),
            Param("t", TIME, "time of the total response x", optional=True,
                  constraint="nonnegative")),
    compute=forced_response,
    equation="m x'' + c x' + k x = F0 cos(Omega t) | k u + c u' (u = u0 cos(Omega t)) | "
             "-m B0 cos(Omega t) (x relative to the ground) | m_u e Omega^2 cos(Omega t)",
    formula="eta = Omega/omega, D = sqrt((1 - eta^2)^2 + (2 zeta eta)^2), "
            "X = X_st V (V = 1/D; unbalance eta^2/D; base TR), "
            "TR = sqrt(1 + (2 zeta eta)^2)/D, phi = atan2(2 zeta eta, 1 - eta^2); "
            "half-power frequencies from the quartic X(Omega) = X_peak/sqrt(2)",
    latex=_STEADY_LATEX,
    reference="",
    example="dyncalc forced-response --k 40kN/m --m 40kg --zeta 0.05 --F0 100N --Omega 1500rpm",
    one_of=(("k", "omega"), ("zeta", "c", "Q"), ("Omega", "f_exc")),
    accepts_zeta=False,
    no_zeta_because="",
    assumptions=_ASSUMPTIONS,
)

_QUARTER_CAR = Scene(
    name="quarter-car",
    summary="a quarter-car on a wavy road, with damping",
    figure="a body of mass m rides on a suspension spring k and damper c whose lower ends "
           "follow a road u = U0 cos(2 pi x / L) at speed v0",
    params=(Param("k", STIFFNESS, "suspension stiffness"), Param("m", MASS, "body mass"),
            Param("L", LENGTH, "road wavelength"), Param("U0", LENGTH, "road amplitude"),
            Param("v0", VELOCITY, "speed", constraint="nonnegative"), *_damping()),
    compute=quarter_car_forced,
    equation="m x'' + c x' + k x = k u + c u', u = U0 cos(Omega t), Omega = 2 pi v0 / L",
    formula="Omega = 2 pi v0 / L; base motion: x_amp = X = U0 TR, "
            "TR = sqrt(1 + (2 zeta eta)^2)/sqrt((1 - eta^2)^2 + (2 zeta eta)^2); "
            "v_crit = L sqrt(k/m) / (2 pi)",
    latex=(r"$Omega = \frac{2\pi\,$v0}{$L}", r"$v_crit = \frac{$L\,$omega}{2\pi}",
           *(t for t in _STEADY_LATEX if not (isinstance(t, str) and "$base" in t))),
    reference="E5.23",
    example="dyncalc forced-response --scene quarter-car k=40kN/m m=400kg L=10m U0=2cm "
            "v0=20m/s --zeta 0.2",
    one_of=(("zeta", "c", "Q"),),
    accepts_zeta=False,
    assumptions=("linear suspension; the wheel follows the road",),
)

_FRAME = Scene(
    name="frame-brace-damper",
    summary="a frame braced by a diagonal spring and dashpot, its ground shaken at Omega",
    figure=FRAME_FIGURE,
    params=(*FRAME_PARAMS, *_frequency()),
    compute=frame_brace_forced,
    equation="m y'' + (d/2) y' + (k/2) y = -m b0 cos(Omega t) (y relative to the ground)",
    formula="base acceleration on k/2 and d/2: omega^2 = k/(2m), zeta = (d/2) sqrt(1/(2 k m)), "
            "y0 = 2 m b0/k, y_max = y0/(2 zeta sqrt(1 - zeta^2)) for zeta < 1/sqrt(2), else y0",
    latex=(r"$y0 = \frac{2\,$m\,$b0}{$k}",
           Formula(r"$y_max = \frac{$y0}{2\,$zeta\,\sqrt{1 - $zeta^2}}",
                   lambda v: v["zeta"] < SQRT_HALF),
           r"$omega = \sqrt{\frac{$k}{2\,$m}}",
           r"$zeta = \frac{$d}{2}\,\sqrt{\frac{1}{2\,$k\,$m}}",
           *(t for t in _STEADY_LATEX if not (isinstance(t, str) and (
               "$base" in t or "$k" in t or "$m" in t)))),
    reference="E5.21",
    example='dyncalc forced-response --scene frame-brace-damper m=500kg "k=200 kN/m" '
            '"d=2 kN*s/m" "b0=1 m/s^2" --Omega 14rad/s',
    one_of=(("Omega", "f_exc"),),
    accepts_zeta=False,
    assumptions=("small deflections, massless columns, linear spring and dashpot",),
)

#: Catalog scenes that forced-response runs with their own forcing, by name.
DRIVEN = {"quarter-car": _QUARTER_CAR, "frame-brace-damper": _FRAME}

register(Scene(
    name="mass-spring-given-response",
    summary="the force that makes a mass-spring follow a prescribed motion",
    figure="a block (mass m) on a spring (stiffness k), undamped, pushed along the spring axis "
           "by F(t) so that x(t) = x0 [cos(t/(2 t0)) + c (1 - cos((t - T)/(2 t0))) H(t - T)]",
    params=(Param("m", MASS, "mass"), Param("k", STIFFNESS, "spring stiffness"),
            Param("x0", LENGTH, "amplitude of the prescribed motion"),
            Param("t0", TIME, "time scale of the prescribed motion"),
            Param("T", TIME, "time of the step"),
            Param("c", DIMENSIONLESS, "step factor", default="20"),
            Param("t", TIME, "time asked for", constraint="nonnegative")),
    compute=mass_spring_given_response,
    equation="m x'' + k x = F(t)",
    formula="q = k - m/(4 t0^2); F = q x0 cos(t/(2 t0)) for t < T, "
            "F = q x0 cos(t/(2 t0)) + c x0 (k - q cos((t - T)/(2 t0))) for t >= T",
    latex=(r"$omega = \sqrt{\frac{$k}{$m}}",
           Formula(r"$F = \left($k - \frac{$m}{4\,$t0^2}\right)\,$x0\,\cos\frac{$t}{2\,$t0}",
                   lambda v: v["t"] < v["T"]),
           Formula(r"$F = \left($k - \frac{$m}{4\,$t0^2}\right)\,$x0\,\cos\frac{$t}{2\,$t0} + "
                   r"$c\,$x0\,\left($k - \left($k - \frac{$m}{4\,$t0^2}\right)\,"
                   r"\cos\frac{$t - $T}{2\,$t0}\right)", lambda v: v["t"] >= v["T"]),
           Formula(r"$x = $x0\,\cos\frac{$t}{2\,$t0}", lambda v: v["t"] < v["T"]),
           Formula(r"$x = $x0\,\left(\cos\frac{$t}{2\,$t0} + $c\,\left(1 - "
                   r"\cos\frac{$t - $T}{2\,$t0}\right)\right)", lambda v: v["t"] >= v["T"])),
    reference="E5.22",
    example="dyncalc forced-response --scene mass-spring-given-response m=4kg k=1N/m x0=1m "
            "t0=1s T=2s t=5s",
    example_result={"omega": "0.5 rad/s", "F": "20 N", "x": "17.784112351099008083 m"},
    accepts_zeta=False,
    no_zeta_because="the motion is prescribed: the force follows from it",
))

register(Scene(
    name="rolling-wheel-moving-ground",
    summary="a wheel on a spring rolling on ground that shakes sideways",
    figure="a wheel (mass m, shape factor kappa) rolls without slipping on a floor that moves "
           "as u0 cos(Omega t); a horizontal spring k joins its centre to a fixed wall",
    params=(Param("m", MASS, "mass of the wheel"), Param("k", STIFFNESS, "spring stiffness"),
            Param("u0", LENGTH, "ground amplitude"),
            Param("Omega", ANGULAR_RATE, "ground angular frequency"),
            body(), kappa(), gravity()),
    compute=rolling_wheel_moving_ground,
    equation="(1 + kappa) m x'' + k x = -kappa m u0 Omega^2 cos(Omega t)",
    formula="omega^2 = k/((1 + kappa) m); x0 = kappa m u0 Omega^2 / ((1 + kappa) m Omega^2 - k), "
            "x_amp = |x0|; H_max = |k - m Omega^2| |x0|; mu0 = H_max/(m g)",
    latex=(r"$omega = \sqrt{\frac{$k}{(1 + $kappa)\,$m}}",
           r"$x_amp = \left|\frac{$kappa\,$m\,$u0\,$Omega^2}{(1 + $kappa)\,$m\,$Omega^2 - $k}"
           r"\right|",
           r"$H_max = \left|$k - $m\,$Omega^2\right|\,$x_amp",
           r"$mu0 = \frac{$H_max}{$m\,$g}"),
    reference="E5.24",
    example="dyncalc forced-response --scene rolling-wheel-moving-ground m=2kg k=300N/m "
            "u0=1cm Omega=20rad/s",
    example_result={"omega": "10 rad/s", "x_amp": "0.0044444444444444444444 m",
                    "phi": "0 rad", "H_max": "2.2222222222222222222 N",
                    "mu0": "0.11330180144199202695"},
    one_of=(("body", "kappa"),),
    accepts_zeta=False,
    no_zeta_because="the rolling wheel is undamped",
    assumptions=("rolling without slipping (the friction needed is mu0 m g)",),
))


def forced_scene(name: str) -> Scene:
    """The scene ``forced-response --scene NAME`` runs: a driven variant (:data:`DRIVEN`), a
    forced scene of the catalog, or a single-degree-of-freedom scene driven by ``F0`` on its
    coordinate (:func:`dyncalc.scenes.sdof.driven_variant`); refuses any other (several
    degrees of freedom) with the reason."""
    from . import get_scene
    from .sdof import COORDINATES, driven_variant

    if name in DRIVEN:
        return DRIVEN[name]
    scene = get_scene(name)
    if scene.name in DRIVEN:
        return DRIVEN[scene.name]
    if scene.compute.__module__ == "dyncalc.physics.forced_scenes":
        return scene
    from . import refuse_kinetics

    refuse_kinetics(scene.name, "forced-response")
    if scene.name in COORDINATES:
        return driven_variant(scene.name)
    from ..errors import InputError

    raise InputError(f"forced-response --scene takes a scene with one degree of freedom; "
                     f"{scene.name} has more than one (modes gives its frequencies and mode shapes), so "
                     "it has no single effective mass and stiffness to drive")


def forced_scene_names() -> list[str]:
    """The scenes forced-response --scene takes (for completion and help), in catalog
    order after the driven variants."""
    from . import catalog
    from .sdof import COORDINATES

    return [*DRIVEN, *(n for n, s in catalog().items() if n not in DRIVEN and (
        s.compute.__module__ == "dyncalc.physics.forced_scenes" or n in COORDINATES))]
