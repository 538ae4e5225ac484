"""Catalog: rigid-body scenes (the ``rigid-body`` command; ../shared/SCENES.md "Rigid-body
scenes"): connected bodies on ropes, a wheel and a block, impacts and impulses.

How a scene joins the ``rigid-body`` command
--------------------------------------------
``rigid-body --scene NAME`` accepts exactly the scenes registered by the modules of
:data:`KINETICS_MODULES` — this one and :mod:`dyncalc.scenes.kinetics_loads` (bearing
reactions, stress resultants along a bar) — and no other command offers them
(:func:`is_kinetics_scene`: natural-frequency, forced-response and modes refuse them with a
pointer to ``rigid-body``). Both modules are in ``CATALOG_MODULES``, so ``dyncalc scenes``,
``dyncalc scenes E4.10`` and docs/scenes.md list them. To add a scene:

1. write its physics as a function of pint quantities or SI floats returning an
   :class:`~dyncalc.physics.outcome.Outcome` of SI floats (decorated with ``check_units``);
2. ``register(Scene(...))`` it in one of the two modules with the parameter names of
   ../shared/SCENES.md, ``accepts_zeta=False``, ``no_zeta_because=NO_ZETA``, its ``latex``
   lines, ``reference``, ``example`` (a ``dyncalc rigid-body --scene ...`` line), ``example_result``
   (computed independently) and ``kinds``: the kinds of its results
   (:func:`kind` builds one; the scene's own kinds take precedence over the shared table of
   :mod:`dyncalc.result.kinds`, so ``V`` may be a shear force here);
3. a result that depends on the position or the time takes ``x=`` / ``t=`` as ordinary
   optional parameters (``Param("x", LENGTH, ..., optional=True)``).

Inverse problems (``alpha=2rad/s^2 J_A=?``), ``--batch``, ``--explain``, ``--json`` and the
Python API then work with no further code; ``--check`` slips are listed in
:data:`dyncalc.commands.rigid_body.SLIPS` by scene name.
"""
from __future__ import annotations

import math

from ..physics.kinetics import (direct_central_impact, double_pendulum_impulse, drum_two_blocks,
                                two_drums_rope_drive, wheel_incline_block)
from ..result.explain import Formula
from ..result.kinds import ResultKind
from ..units import (ACCELERATION, ANGLE, ANGULAR_ACCELERATION, ANGULAR_RATE, DIMENSIONLESS,
                     ENERGY, FORCE, IMPULSE, INERTIA, LENGTH, MASS, TORQUE, VELOCITY)
from . import KINETICS_MODULES, Constraint, Param, Scene, is_kinetics_scene, register
from .basic import gravity
from .rigid import body, kappa

__all__ = ["KINETICS_MODULES", "NO_ZETA", "kind", "is_kinetics_scene", "kinetics_scene_names"]


#: Why a rigid-body scene takes no ``zeta``.
NO_ZETA = "it is a rigid-body scene (no oscillation to damp)"


def kind(dim, symbol: str, description: str) -> ResultKind:
    """A result kind shown in the SI unit of ``dim`` (the canonical unit)."""
    return ResultKind(dim, dim.si, symbol, description)


def kinetics_scene_names() -> list[str]:
    """The scenes ``rigid-body --scene`` takes, in catalog order."""
    from . import catalog

    return [name for name in catalog() if is_kinetics_scene(name)]


def _masses(*names: str, what: str = "mass of block") -> tuple[Param, ...]:
    return tuple(Param(n, MASS, f"{what} {n[-1]}") for n in names)


register(Scene(
    name="drum-two-blocks",
    summary="two blocks hanging from a stepped drum, on opposite sides of its axle",
    figure="a drum turns on a fixed frictionless axle A (moment of inertia J_A); block 1 (mass "
           "m1) hangs from a rope wound on radius r1, block 2 (mass m2) from a rope on radius "
           "r2 on the other side, so their weights turn the drum in opposite senses",
    params=(*_masses("m1", "m2"),
            Param("r1", LENGTH, "radius of the groove of block 1"),
            Param("r2", LENGTH, "radius of the groove of block 2"),
            Param("J_A", INERTIA, "moment of inertia of the drum about its axle",
                  constraint="nonnegative"),
            gravity()),
    compute=drum_two_blocks,
    equation="(J_A + m1 r1^2 + m2 r2^2) phi'' = (m2 r2 - m1 r1) g (phi positive when block 2 "
             "descends)",
    formula="alpha = (m2 r2 - m1 r1) g / (J_A + m1 r1^2 + m2 r2^2), a1 = r1 alpha, "
            "a2 = r2 alpha, S1 = m1 (g + a1), S2 = m2 (g - a2)",
    latex=(r"$alpha = \frac{($m2\,$r2 - $m1\,$r1)\,$g}{$J_A + $m1\,$r1^2 + $m2\,$r2^2}",
           r"$a1 = $r1\,$alpha", r"$a2 = $r2\,$alpha",
           r"$S1 = $m1\,($g + $a1)", r"$S2 = $m2\,($g - $a2)"),
    reference="E4.10",
    example="dyncalc rigid-body --scene drum-two-blocks m1=20kg m2=15kg r1=0.2m r2=0.4m "
            '"J_A=2 kg*m^2"',
    example_result={"alpha": "3.7717884615384615385 rad/s^2",
                    "a1": "0.75435769230769230769 m/s^2", "a2": "1.5087153846153846154 m/s^2",
                    "S1": "211.22015384615384615 N", "S2": "124.46901923076923077 N"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    assumptions=("the system is in static balance when m1 r1 = m2 r2",),
    kinds={"alpha": kind(ANGULAR_ACCELERATION, "α", "angular acceleration of the drum "
                         "(positive: block 2 goes down)"),
           "a1": kind(ACCELERATION, "a1", "acceleration of block 1 (up positive)"),
           "a2": kind(ACCELERATION, "a2", "acceleration of block 2 (down positive)"),
           "S1": kind(FORCE, "S1", "force in the rope of block 1"),
           "S2": kind(FORCE, "S2", "force in the rope of block 2")},
))


register(Scene(
    name="wheel-incline-block",
    summary="a wheel rolling on an incline, pulled up the slope by a rope to a hanging block",
    figure="a wheel (mass m1, moment of inertia J_A about its centre A, rolling radius r) "
           "rolls without slipping on a plane inclined at beta; a rope tied to its axle runs "
           "parallel to the slope to an ideal pulley at the top and hangs down to a block "
           "(mass m2)",
    params=(Param("m1", MASS, "mass of the wheel"), Param("m2", MASS, "mass of the block"),
            Param("beta", ANGLE, "incline of the plane (|beta| < 90 deg)", constraint=None),
            Param("J_A", INERTIA, "moment of inertia of the wheel about its centre (with r)",
                  optional=True, constraint="nonnegative"),
            Param("r", LENGTH, "rolling radius of the wheel (with J_A)", optional=True),
            body(default=None), kappa(), gravity()),
    compute=wheel_incline_block,
    constraints=(Constraint("r with J_A", lambda v: "J_A" not in v or "r" in v,
                            " (J_A/r^2 enters the acceleration; with body= or kappa= r "
                            "cancels)"),
                 Constraint("-90 deg < beta < 90 deg", lambda v: abs(v["beta"]) < math.pi / 2,
                            " (the wheel must rest on the plane)")),
    one_of=(("J_A", "body", "kappa"),),
    equation="((1 + kappa) m1 + m2) x'' = (m2 - m1 sin(beta)) g, kappa m1 = J_A/r^2 (x: wheel "
             "centre up the slope = block down)",
    formula="a = g (m2 - m1 sin(beta)) / (m1 + m2 + J_A/r^2), S = m2 (g - a), "
            "H = (J_A/r^2) a, N = m1 g cos(beta), mu_min = |H|/N; with kappa, J_A/r^2 = kappa m1",
    latex=(r"$a = \frac{$g\,($m2 - $m1\,\sin $beta)}{$m1 + $m2 + $J_A/$r^2}",
           r"$a = \frac{$g\,($m2 - $m1\,\sin $beta)}{(1 + $kappa)\,$m1 + $m2}",
           r"$S = $m2\,($g - $a)", r"$H = \frac{$J_A}{$r^2}\,$a", r"$H = $kappa\,$m1\,$a",
           r"$N = $m1\,$g\,\cos $beta", r"$mu_min = \frac{|$H|}{$N}"),
    reference="E4.12",
    example='dyncalc rigid-body --scene wheel-incline-block m1=20kg m2=15kg beta=30deg '
            '"J_A=0.4 kg*m^2" r=0.2m',
    example_result={"a": "1.0896277777777777778 m/s^2", "S": "130.75533333333333333 N",
                    "H": "10.896277777777777778 N", "N": "169.85616052045330511 N",
                    "mu_min": "0.064150029909958418279"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    assumptions=("the rope stays taut (S > 0 for every input)",),
    kinds={"a": kind(ACCELERATION, "a", "acceleration of the block (down positive; the "
                     "wheel's centre up the slope)"),
           "S": kind(FORCE, "S", "rope force"),
           "H": kind(FORCE, "H", "static friction force on the wheel (down the slope "
                     "positive)"),
           "N": kind(FORCE, "N", "normal force on the wheel"),
           "mu_min": kind(DIMENSIONLESS, "μ_min", "least static friction coefficient for "
                          "rolling")},
))

register(Scene(
    name="two-drums-rope-drive",
    summary="two drums coupled by a rope, one driven by a moment, a block hanging from each",
    figure="drum 1 (moment of inertia J1) is driven by the moment M0; block 1 (mass m1) hangs "
           "from a rope on its radius r1; a coupling rope runs on radius r2 of drum 1 and of "
           "drum 2 (J2), from whose radius r2 block 2 (mass m2) hangs; turning in the sense "
           "of M0 raises block 1 and lowers block 2",
    params=(*_masses("m1", "m2"),
            Param("r1", LENGTH, "radius of drum 1 carrying block 1"),
            Param("r2", LENGTH, "radius of the coupling rope on both drums and of block 2's "
                  "rope"),
            Param("J1", INERTIA, "moment of inertia of the driven drum 1",
                  constraint="nonnegative"),
            Param("J2", INERTIA, "moment of inertia of drum 2", constraint="nonnegative"),
            Param("M0", TORQUE, "driving moment on drum 1", constraint=None), gravity()),
    compute=two_drums_rope_drive,
    equation="(m2 + m1 (r1/r2)^2 + (J1 + J2)/r2^2) x2'' = M0/r2 + (m2 - m1 r1/r2) g (x2: "
             "block 2 down)",
    formula="a2 = (g (m2 r2^2 - m1 r1 r2) + M0 r2) / (m2 r2^2 + m1 r1^2 + J1 + J2), "
            "a1 = (r1/r2) a2, alpha = a2/r2, S1 = m1 (g + a1), S2 = m2 (g - a2)",
    latex=(r"$a2 = \frac{$g\,($m2\,$r2^2 - $m1\,$r1\,$r2) + $M0\,$r2}{$m2\,$r2^2 + "
           r"$m1\,$r1^2 + $J1 + $J2}",
           r"$a1 = \frac{$r1}{$r2}\,$a2", r"$alpha = \frac{$a2}{$r2}",
           r"$S1 = $m1\,($g + $a1)", r"$S2 = $m2\,($g - $a2)"),
    reference="E4.13",
    example='dyncalc rigid-body --scene two-drums-rope-drive m1=10kg m2=20kg r1=0.3m r2=0.2m '
            '"J1=1.5 kg*m^2" "J2=0.8 kg*m^2" "M0=50 N*m"',
    example_result={"a2": "2.9903325 m/s^2", "a1": "4.48549875 m/s^2",
                    "alpha": "14.9516625 rad/s^2", "S1": "142.9214875 N", "S2": "136.32635 N"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    assumptions=("the hanging ropes stay taut (a2 < g and a1 > -g; warned otherwise)",),
    kinds={"a2": kind(ACCELERATION, "a2", "acceleration of block 2 (down positive)"),
           "a1": kind(ACCELERATION, "a1", "acceleration of block 1 (up positive)"),
           "alpha": kind(ANGULAR_ACCELERATION, "α", "angular acceleration of both drums (in "
                         "the sense of M0)"),
           "S1": kind(FORCE, "S1", "force in the rope of block 1"),
           "S2": kind(FORCE, "S2", "force in the rope of block 2")},
))

register(Scene(
    name="direct-central-impact",
    summary="two bodies colliding head-on along the line of their centres",
    figure="two bodies (masses m1, m2) move along one straight line through both centres of "
           "mass at v1 and v2 (signed); body 1 is behind and catches body 2 (v1 > v2); the "
           "impact is central, straight and smooth, with coefficient of restitution e",
    params=(Param("m1", MASS, "mass of body 1 (behind)"),
            Param("m2", MASS, "mass of body 2 (ahead)"),
            Param("v1", VELOCITY, "velocity of body 1 before the impact (signed)",
                  constraint=None),
            Param("v2", VELOCITY, "velocity of body 2 before the impact (signed, < v1)",
                  constraint=None),
            Param("e", DIMENSIONLESS, "coefficient of restitution (0 plastic, 1 elastic)",
                  constraint="nonnegative")),
    compute=direct_central_impact,
    constraints=(Constraint("v1 > v2", lambda v: v["v1"] > v["v2"],
                            " (body 1 must catch body 2: otherwise there is no impact)"),
                 Constraint("e <= 1", lambda v: v["e"] <= 1.0,
                            " (e is the ratio of separation to approach speed: 0 plastic, "
                            "1 elastic)")),
    equation="m1 v1 + m2 v2 = m1 v1_post + m2 v2_post, v2_post - v1_post = e (v1 - v2)",
    formula="v_c = (m1 v1 + m2 v2)/(m1 + m2), v1_post = v_c - e m2 (v1 - v2)/(m1 + m2), "
            "v2_post = v_c + e m1 (v1 - v2)/(m1 + m2), F_hat = (1 + e) m1 m2 (v1 - v2)/"
            "(m1 + m2), dE = (1 - e^2) m1 m2 (v1 - v2)^2 / (2 (m1 + m2))",
    latex=(r"$v_c = \frac{$m1\,$v1 + $m2\,$v2}{$m1 + $m2}",
           r"$v1_post = $v_c - \frac{$e\,$m2\,($v1 - $v2)}{$m1 + $m2}",
           r"$v2_post = $v_c + \frac{$e\,$m1\,($v1 - $v2)}{$m1 + $m2}",
           r"$F_hat = \frac{(1 + $e)\,$m1\,$m2\,($v1 - $v2)}{$m1 + $m2}",
           r"$dE = \frac{(1 - $e^2)\,$m1\,$m2\,($v1 - $v2)^2}{2\,($m1 + $m2)}"),
    reference="classic (not a book example)",
    example="dyncalc rigid-body --scene direct-central-impact m1=2kg m2=3kg v1=4m/s "
            "v2=-1m/s e=0.6",
    example_result={"v_c": "1 m/s", "v1_post": "-0.8 m/s", "v2_post": "2.2 m/s",
                    "F_hat": "9.6 N*s", "dE": "9.6 J"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    kinds={"v_c": kind(VELOCITY, "v_c", "common velocity at the end of compression"),
           "v1_post": kind(VELOCITY, "v1'", "velocity of body 1 after the impact"),
           "v2_post": kind(VELOCITY, "v2'", "velocity of body 2 after the impact"),
           "F_hat": kind(IMPULSE, "F_hat", "impulse each body receives (body 2 forward, body 1 "
                         "backward)"),
           "dE": kind(ENERGY, "ΔE", "kinetic energy lost")},
))

def _impulse_latex(d: str) -> tuple:
    """The double pendulum's lines with the blow at ``d`` (``$d`` given, or ``$d_0``)."""
    given = (lambda v: "d" in v) if d == "$d" else (lambda v: "d" not in v)
    return tuple(Formula(text.replace("D", d), given) for text in (
        r"$omega_1 = \frac{6\,$F_hat\,(3\,D - $l)}{7\,$m\,$l^2}",
        r"$omega_2 = \frac{6\,$F_hat\,(5\,$l - 8\,D)}{7\,$m\,$l^2}",
        r"$v_2 = \frac{3\,$F_hat\,(3\,$l - 2\,D)}{7\,$m\,$l}",
        r"$B_hat = \frac{2\,$F_hat\,(3\,D - $l)}{7\,$l}"))


register(Scene(
    name="double-pendulum-impulse",
    summary="two hanging bars, pinned in line, the lower one struck by a horizontal impulse",
    figure="two identical uniform bars (mass m, length l each) hang at rest in one vertical "
           "line: bar 1 from a fixed pin A, bar 2 from a pin B at the lower end of bar 1; a "
           "horizontal impulse F_hat strikes bar 2 at the height d above its lower end",
    params=(Param("m", MASS, "mass of each bar"), Param("l", LENGTH, "length of each bar"),
            Param("F_hat", IMPULSE, "the horizontal impulse", symbol=r"\hat{F}"),
            Param("d", LENGTH, "height of the blow above the lower end of bar 2 (default "
                  "d_0 = 5l/8: bar 2 only translates)", optional=True,
                  constraint="nonnegative")),
    compute=double_pendulum_impulse,
    constraints=(Constraint("d <= l", lambda v: "d" not in v or v["d"] <= v["l"],
                            " (the blow strikes bar 2, which is l long)"),),
    equation="impulse-momentum: J_A1 omega_1 = l B_hat, m v_2 = F_hat - B_hat, "
             "J_C2 omega_2 = F_hat (l/2 - d) + B_hat l/2, v_2 = l omega_1 + (l/2) omega_2 "
             "(J_A1 = m l^2/3, J_C2 = m l^2/12)",
    formula="omega_1 = 6 F_hat (3d - l)/(7 m l^2), omega_2 = 6 F_hat (5l - 8d)/(7 m l^2), "
            "v_2 = 3 F_hat (3l - 2d)/(7 m l), B_hat = 2 F_hat (3d - l)/(7 l), A_hat = B_hat/2, "
            "d_0 = 5l/8, d_A0 = l/3",
    latex=(r"$d_0 = \frac{5\,$l}{8}", r"$d_A0 = \frac{$l}{3}",
           *_impulse_latex("$d"), *_impulse_latex("$d_0"), r"$A_hat = \frac{$B_hat}{2}"),
    reference="E3.46",
    example='dyncalc rigid-body --scene double-pendulum-impulse m=3kg l=1.2m "F_hat=12 N*s"',
    example_result={"omega_1": "2.5 rad/s", "omega_2": "0 rad/s", "v_2": "3 m/s",
                    "A_hat": "1.5 N*s", "B_hat": "3 N*s", "d_0": "0.75 m", "d_A0": "0.4 m"},
    accepts_zeta=False,
    no_zeta_because=NO_ZETA,
    assumptions=("for d < l/3 the pin impulses change sign",),
    kinds={"omega_1": kind(ANGULAR_RATE, "ω1", "angular velocity of bar 1 just after the blow"),
           "omega_2": kind(ANGULAR_RATE, "ω2", "angular velocity of bar 2 just after the blow"),
           "v_2": kind(VELOCITY, "v2", "velocity of the centre of bar 2 just after the blow"),
           "A_hat": kind(IMPULSE, "A_hat", "impulse of the pin A on bar 1 (in the direction of "
                         "F_hat)"),
           "B_hat": kind(IMPULSE, "B_hat", "impulse bar 1 passes to bar 2 at B (against F_hat)"),
           "d_0": kind(LENGTH, "d0", "height of the blow for which bar 2 only translates"),
           "d_A0": kind(LENGTH, "d_A0", "height of the blow for which the pins take no "
                        "impulse")},
))
