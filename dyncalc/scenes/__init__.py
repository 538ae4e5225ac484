"""The scene catalog: one declarative entry per physical set-up of SCENES.md.

A scene is data: its parameters (name, dimension, default, constraint), the physics function it
calls (a dotted path, imported only when the scene is computed), its equation of motion and
formula, the textbook example it reproduces and one runnable example command. ``dyncalc
scenes`` prints from the same data, and one parametrised test runs every scene's example, so
help and catalog never drift from the code.

Scenes are added with :func:`register`; the catalog modules that do so are listed in
:data:`CATALOG_MODULES` and imported on first use of :func:`catalog`.
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass, field
from typing import Any

from ..errors import InputError

__all__ = ["Param", "Constraint", "Scene", "register", "catalog", "get_scene", "scene_names"]

#: Modules whose import registers scenes.
CATALOG_MODULES: tuple[str, ...] = (
    "dyncalc.scenes.basic", "dyncalc.scenes.rigid", "dyncalc.scenes.rotating",
    "dyncalc.scenes.damped",
)


@dataclass(frozen=True)
class Param:
    """One parameter of a scene.

    ``dim`` is a :class:`dyncalc.units.Dim` (``None`` for a choice such as ``body``);
    ``default`` the text used when the user gives none; ``optional`` a parameter that may be
    left out with no default (an amplitude); otherwise a parameter with neither is required.
    ``constraint`` is one of the units module's (``positive``, ``nonnegative``, ``None``),
    ``choices`` maps the words of a choice parameter to the value passed on.
    """

    name: str
    dim: Any
    description: str
    default: str | None = None
    optional: bool = False
    constraint: str | None = "positive"
    choices: dict | None = None
    symbol: str = ""                 # LaTeX symbol in formulas, if not derived from the name

    def signature(self) -> str:
        """``l [length]``, ``g [length]/[time]^2 = 9.80665 m/s^2``, ``amplitude [angle]?``"""
        kind = self.dim.display if self.dim is not None else "{" + ", ".join(self.choices) + "}"
        if self.default is not None:
            return f"{self.name} {kind} = {self.default}"
        return f"{self.name} {kind}" + ("?" if self.optional else "")


@dataclass(frozen=True)
class Constraint:
    """A relation between parameters (``R > r``): ``holds`` takes the SI values by name."""

    text: str
    holds: Any
    why: str = ""


@dataclass(frozen=True)
class Scene:
    """One set-up: what it is, what it needs, what it computes and where it comes from."""

    name: str
    summary: str
    figure: str
    params: tuple[Param, ...]
    compute: str                     # "dyncalc.physics.oscillators:mass_spring"
    equation: str                    # equation of motion
    formula: str                     # the closed form (or how it is solved)
    reference: str                   # "E5.12"
    example: str                     # a runnable command line
    example_result: dict = field(default_factory=dict)  # result -> value text the example gives
    constraints: tuple[Constraint, ...] = ()
    one_of: tuple[tuple[str, ...], ...] = ()   # groups of which exactly one must be given
    methods: tuple[str, ...] = ()              # besides "auto"; empty: closed form only
    accepts_zeta: bool = True                  # --zeta adds damped results
    no_zeta_because: str = "its damping comes from its own parameters"  # when it does not
    assumptions: tuple[str, ...] = ()
    #: formula lines in LaTeX, ``$name`` for a parameter or result (see :mod:`dyncalc.explain`);
    #: strings or :class:`dyncalc.explain.Formula` (used only when its condition holds)
    latex: tuple = ()
    #: functions of the SI values by name (and ``method``) that say how large an assumption's
    #: error is at these inputs (a sentence, or None when there is nothing to say)
    sizes: tuple = ()

    def param(self, name: str) -> Param | None:
        return next((p for p in self.params if p.name == name), None)

    def signature(self) -> str:
        return ", ".join(p.signature() for p in self.params)

    def function(self):
        module, _, name = self.compute.partition(":")
        return getattr(importlib.import_module(module), name)


_SCENES: dict[str, Scene] = {}
_loaded = False


def register(scene: Scene) -> Scene:
    """Add ``scene`` to the catalog (a name may be registered once).

    A scene that accepts ``zeta`` gets the optional parameter ``zeta`` (damping ratio, adds the
    damped results) appended to its parameters.
    """
    import dataclasses

    from ..units import DIMENSIONLESS

    if scene.name in _SCENES:
        raise ValueError(f"scene {scene.name!r} is registered twice")
    if scene.accepts_zeta and scene.param("zeta") is None:
        zeta = Param("zeta", DIMENSIONLESS, "damping ratio: adds omega_d, f_d, T_d",
                     optional=True, constraint="nonnegative")
        scene = dataclasses.replace(scene, params=(*scene.params, zeta))
    _SCENES[scene.name] = scene
    return scene


def catalog() -> dict[str, Scene]:
    """Every scene, by name, in the order registered."""
    global _loaded
    if not _loaded:
        for module in CATALOG_MODULES:
            importlib.import_module(module)
        _loaded = True
    return _SCENES


def scene_names() -> list[str]:
    return list(catalog())


def get_scene(name: str) -> Scene:
    """The scene called ``name``; refuses an unknown name with the list of known ones."""
    scenes = catalog()
    if name not in scenes:
        known = ", ".join(scenes) if scenes else "none yet: the catalog is empty"
        raise InputError(f"there is no scene {name!r}; the scenes are: {known}")
    return scenes[name]
