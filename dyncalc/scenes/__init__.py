"""The scene catalog: one declarative entry per physical set-up (docs/scenes.md lists them).

A scene is data: its parameters (name, dimension, default, constraint), the physics function it
calls (a dotted path, imported only when the scene is computed), its equation of motion and
formula, the textbook example it reproduces and one runnable example command. ``dyncalc
scenes`` prints from the same data, ``tools/gen_docs.py`` writes docs/scenes.md from it, and
one parametrised test runs every scene's example, so help and catalog never drift from the
code.

Scenes are added with :func:`register`; the catalog modules that do so are listed in
:data:`CATALOG_MODULES` and imported on first use of :func:`catalog`.
"""
from __future__ import annotations

import importlib
import re
import sys
from typing import Any

from ..errors import InputError
from ..records import Frozen

__all__ = ["Param", "Constraint", "Scene", "register", "catalog", "get_scene", "scene_names",
           "computed_scenes", "is_example_id", "scenes_of_example", "KINETICS_MODULES",
           "RELATIVE_MODULE", "registered_by", "is_kinetics_scene", "refuse_kinetics"]

#: Modules whose import registers scenes.
CATALOG_MODULES: tuple[str, ...] = (
    "dyncalc.scenes.basic", "dyncalc.scenes.rigid", "dyncalc.scenes.rotating",
    "dyncalc.scenes.damped", "dyncalc.scenes.forced", "dyncalc.scenes.lagrange",
    "dyncalc.scenes.kinetics", "dyncalc.scenes.kinetics_loads", "dyncalc.scenes.relative",
)

#: The catalog modules whose scenes the rigid-body command runs (and no other command).
KINETICS_MODULES = ("dyncalc.scenes.kinetics", "dyncalc.scenes.kinetics_loads")
#: The catalog module whose scenes coriolis runs (relative motion: no frequency).
RELATIVE_MODULE = "dyncalc.scenes.relative"


# Param, Constraint and Scene behave as frozen dataclasses (the same constructor, repr,
# equality, hash and immutability); they are written out by hand because @dataclass generates
# and compiles their methods at import, which every one-off run would pay for (issue 8).


class Param(Frozen):
    """One parameter of a scene.

    ``dim`` is a :class:`dyncalc.units.Dim` (``None`` for a choice such as ``body``);
    ``default`` the text used when the user gives none; ``optional`` a parameter that may be
    left out with no default (an amplitude); otherwise a parameter with neither is required.
    ``constraint`` is one of the units module's (``positive``, ``nonnegative``, ``None``),
    ``choices`` maps the words of a choice parameter to the value passed on.
    """

    __slots__ = ("name", "dim", "description", "default", "optional", "constraint", "choices",
                 "symbol")

    def __init__(self, name: str, dim: Any, description: str, default: str | None = None,
                 optional: bool = False, constraint: str | None = "positive",
                 choices: dict | None = None, symbol: str = ""):
        _set_all(self, name, dim, description, default, optional, constraint, choices, symbol)

    def signature(self) -> str:
        """``l [length]``, ``g [length]/[time]^2 = 9.80665 m/s^2``, ``amplitude [angle]?``"""
        kind = self.dim.display if self.dim is not None else "{" + ", ".join(self.choices) + "}"
        if self.default is not None:
            return f"{self.name} {kind} = {self.default}"
        return f"{self.name} {kind}" + ("?" if self.optional else "")


class Constraint(Frozen):
    """A relation between parameters (``R > r``): ``holds`` takes the SI values by name."""

    __slots__ = ("text", "holds", "why")

    def __init__(self, text: str, holds: Any, why: str = ""):
        _set_all(self, text, holds, why)


class Scene(Frozen):
    """One set-up: what it is, what it needs, what it computes and where it comes from.

    ``compute`` is the physics function itself (its module loads numpy, pint and scipy only when
    it computes, through :mod:`dyncalc.lazy` and imports inside functions); ``equation`` the
    equation of motion, ``formula`` the closed form (or how it is solved), ``reference`` the
    textbook example (``"E5.12"``), ``example`` a runnable command line and ``example_result``
    the value text it gives per result; ``one_of`` holds groups of which exactly one must be
    given, ``methods`` the methods besides ``auto`` (empty: closed form only); ``accepts_zeta``:
    whether ``--zeta`` adds damped results (``no_zeta_because`` says why not). ``latex`` holds
    the formula lines in LaTeX, ``$name`` for a parameter or result (strings or
    :class:`dyncalc.result.explain.Formula`, used only when its condition holds); ``sizes``
    functions of the SI values by name (and ``method``) that say how large an assumption's error
    is at these inputs (a sentence, or None). ``matrices``, on a scene with several degrees
    of freedom, is a function of the SI values by name giving its
    :class:`~dyncalc.physics.lagrange.Linearised` mass and stiffness matrices (what ``modes
    --scene`` solves); a scene with no equilibrium gives a function that raises. ``kinds``
    maps result names to their own :class:`~dyncalc.result.kinds.ResultKind` where the
    shared table (:func:`dyncalc.result.kinds.result_kind`) has none or means something else
    (a rigid-body scene's ``V`` is a shear force, not a magnification).
    ``no_frequency``, when not empty, says why ``natural-frequency`` refuses the scene on
    purpose (it has no equilibrium): its ``example`` is then the runnable ``eom`` command and
    ``example_result`` that command's accelerations.
    """

    __slots__ = ("name", "summary", "figure", "params", "compute", "equation", "formula",
                 "reference", "example", "example_result", "constraints", "one_of", "methods",
                 "accepts_zeta", "no_zeta_because", "assumptions", "latex", "sizes", "matrices",
                 "kinds", "no_frequency")

    def __init__(self, name: str, summary: str, figure: str, params: tuple[Param, ...],
                 compute: Any, equation: str, formula: str, reference: str, example: str,
                 example_result: dict | None = None, constraints: tuple[Constraint, ...] = (),
                 one_of: tuple[tuple[str, ...], ...] = (), methods: tuple[str, ...] = (),
                 accepts_zeta: bool = True,
                 no_zeta_because: str = "its damping comes from its own parameters",
                 assumptions: tuple[str, ...] = (), latex: tuple = (), sizes: tuple = (),
                 matrices: Any = None, kinds: dict | None = None, no_frequency: str = ""):
        _set_all(self, name, summary, figure, params, compute, equation, formula, reference,
                 example, {} if example_result is None else example_result, constraints,
                 one_of, methods, accepts_zeta, no_zeta_because, assumptions, latex, sizes,
                 matrices, {} if kinds is None else kinds, no_frequency)

    def replace(self, **changes) -> Scene:
        """A copy with ``changes`` (what ``dataclasses.replace`` does)."""
        values = {name: getattr(self, name) for name in self.__slots__}
        values.update(changes)
        return Scene(**values)

    def param(self, name: str) -> Param | None:
        return next((p for p in self.params if p.name == name), None)

    def signature(self) -> str:
        return ", ".join(p.signature() for p in self.params)

    @property
    def examples(self) -> tuple[str, ...]:
        """The textbook example ids its ``reference`` cites (``("E4.9", "E5.17")``)."""
        return tuple(_EXAMPLE_ID.findall(self.reference))



def _set_all(record, *values) -> None:
    """Set a frozen record's fields, in the order of its ``__slots__``."""
    for name, value in zip(record.__slots__, values):
        object.__setattr__(record, name, value)


#: A textbook example id as scenes cite it in their ``reference``: ``E5.12``.
_EXAMPLE_ID = re.compile(r"\bE\d+\.\d+\b")

_SCENES: dict[str, Scene] = {}
_imported = 0  # how many of CATALOG_MODULES have been imported, in order
_ORIGIN: dict[str, str] = {}  # scene name -> the module that registered it
_ordered = False  # whether _SCENES is in catalog order (module order, then registration)


def register(scene: Scene) -> Scene:
    """Add ``scene`` to the catalog (a name may be registered once).

    A scene that accepts ``zeta`` gets the optional parameter ``zeta`` (damping ratio, adds the
    damped results) appended to its parameters.
    """
    from ..units import DIMENSIONLESS

    if scene.name in _SCENES:
        raise ValueError(f"scene {scene.name!r} is registered twice")
    if scene.accepts_zeta and scene.param("zeta") is None:
        zeta = Param("zeta", DIMENSIONLESS, "damping ratio: adds omega_d, f_d, T_d",
                     optional=True, constraint="nonnegative")
        scene = scene.replace(params=(*scene.params, zeta))
    _SCENES[scene.name] = scene
    _ORIGIN[scene.name] = sys._getframe(1).f_globals.get("__name__", "")
    return scene


def _load(until: str | None = None) -> None:
    """Import the catalog modules in order: all of them, or only until scene ``until`` is
    registered (a one-off of mass-spring loads the basic scenes and their physics alone, not
    every physics module of the catalog: start-up)."""
    global _imported
    while _imported < len(CATALOG_MODULES) and (until is None or until not in _SCENES):
        importlib.import_module(CATALOG_MODULES[_imported])
        _imported += 1


def catalog() -> dict[str, Scene]:
    """Every scene, by name, in catalog order: the order of CATALOG_MODULES, then the order
    each module registers its scenes — whichever module was imported first (a test or a
    command may import one of them directly)."""
    global _ordered
    _load()
    if not _ordered:
        rank = {module: i for i, module in enumerate(CATALOG_MODULES)}
        ordered = sorted(_SCENES.items(),
                         key=lambda item: rank.get(_ORIGIN[item[0]], len(rank)))  # stable
        _SCENES.clear()
        _SCENES.update(ordered)
        _ordered = True
    return _SCENES


def registered_by(name: str) -> str:
    """The catalog module that registered scene ``name`` ("" for no scene): which commands
    take it (:data:`KINETICS_MODULES`, :data:`RELATIVE_MODULE`). A name already registered (as
    :func:`get_scene` leaves it) costs no further import; another loads the catalog first."""
    if name not in _ORIGIN:
        _load()
    return _ORIGIN.get(name, "")


def is_kinetics_scene(name: str) -> bool:
    """Whether scene ``name`` is a rigid-body scene (registered by :data:`KINETICS_MODULES`)."""
    return registered_by(name) in KINETICS_MODULES


def refuse_kinetics(name: str, command: str) -> None:
    """Refuse rigid-body scene ``name`` to ``command`` (natural-frequency, forced-response,
    modes, damping-ratio), pointing to rigid-body."""
    if is_kinetics_scene(name):
        raise InputError(f"{command} does not take {name}: it is a rigid-body scene (no "
                         f"oscillation); run 'dyncalc rigid-body --scene {name} ...'")


def scene_names() -> list[str]:
    return list(catalog())


def computed_scenes() -> dict[str, Scene]:
    """The scenes ``natural-frequency`` computes, by name in catalog order: the catalog less
    those it refuses on purpose (:attr:`Scene.no_frequency`, no equilibrium)."""
    return {name: scene for name, scene in catalog().items() if not scene.no_frequency}


def is_example_id(text: str) -> bool:
    """Whether ``text`` is a textbook example id (``E5.12``, ``e5.12``)."""
    return _EXAMPLE_ID.fullmatch(text.upper()) is not None


def scenes_of_example(example: str) -> list[Scene]:
    """The scenes that cite example ``example`` (``E5.15``), in catalog order; refuses an id
    no scene cites."""
    example = example.upper()
    found = [s for s in catalog().values() if example in s.examples]
    if not found:
        raise InputError(f"no scene reproduces example {example}; 'dyncalc scenes' lists the "
                         "examples of each scene")
    return found


def get_scene(name: str) -> Scene:
    """The scene called ``name``, or the one scene that reproduces textbook example ``name``
    (``E5.12``); refuses an unknown name with the list of known ones, and an example several
    scenes cite with their names."""
    if is_example_id(name) and name not in _SCENES:
        found = scenes_of_example(name)
        if len(found) > 1:
            raise InputError(f"example {name.upper()} is reproduced by several scenes: "
                             f"{', '.join(s.name for s in found)}; name one of them")
        return found[0]
    _load(until=name)
    scenes = _SCENES if name in _SCENES else catalog()
    if name not in scenes:
        from difflib import get_close_matches

        close = get_close_matches(name, list(scenes))
        if close:
            raise InputError(f"there is no scene {name!r} (did you mean "
                             f"{' or '.join(repr(c) for c in close)}?); 'dyncalc scenes' "
                             "lists them all")
        known = ", ".join(scenes) if scenes else "none yet: the catalog is empty"
        raise InputError(f"there is no scene {name!r}; the scenes are: {known}")
    return scenes[name]
