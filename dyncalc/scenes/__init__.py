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

__all__ = ["Param", "Scene", "register", "catalog", "get_scene", "scene_names"]

#: Modules whose import registers scenes (filled as the catalog grows).
CATALOG_MODULES: tuple[str, ...] = ()


@dataclass(frozen=True)
class Param:
    """One parameter of a scene.

    ``dim`` is a :class:`dyncalc.units.Dim`; ``default`` the text used when the user gives none
    (``None``: required); ``constraint`` one of the units module's constraints (``positive``,
    ``nonnegative``, ...), ``description`` one line for the catalog.
    """

    name: str
    dim: Any
    description: str
    default: str | None = None
    constraint: str | None = "positive"


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
    constraints: tuple[str, ...] = field(default_factory=tuple)   # "R > r"

    def function(self):
        module, _, name = self.compute.partition(":")
        return getattr(importlib.import_module(module), name)


_SCENES: dict[str, Scene] = {}
_loaded = False


def register(scene: Scene) -> Scene:
    """Add ``scene`` to the catalog (a name may be registered once)."""
    if scene.name in _SCENES:
        raise ValueError(f"scene {scene.name!r} is registered twice")
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
