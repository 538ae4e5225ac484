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

from ..physics.kinetics import drum_two_blocks
from ..result.kinds import ResultKind
from ..units import (ACCELERATION, ANGULAR_ACCELERATION, FORCE, INERTIA, LENGTH, MASS)
from . import Param, Scene, register
from .basic import gravity

__all__ = ["KINETICS_MODULES", "NO_ZETA", "kind", "is_kinetics_scene", "kinetics_scene_names"]

#: The catalog modules whose scenes the rigid-body command runs (and no other command).
KINETICS_MODULES = ("dyncalc.scenes.kinetics", "dyncalc.scenes.kinetics_loads")

#: Why a rigid-body scene takes no ``zeta``.
NO_ZETA = "it is a rigid-body scene (no oscillation to damp)"


def kind(dim, symbol: str, description: str) -> ResultKind:
    """A result kind shown in the SI unit of ``dim`` (the canonical unit)."""
    return ResultKind(dim, dim.si, symbol, description)


def is_kinetics_scene(name: str) -> bool:
    """Whether scene ``name`` (a registered name) is a rigid-body scene."""
    from . import _ORIGIN, catalog

    catalog()
    return _ORIGIN.get(name) in KINETICS_MODULES


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
