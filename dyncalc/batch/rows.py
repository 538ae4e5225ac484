"""What each command reads from a row: ``RowSpec`` and one subclass per command."""
from __future__ import annotations

import re

from .fast import _natural_frequency_fast


class RowSpec:
    """How one command turns a row's cells into its library call.

    ``key(name)`` maps a column name to the parameter it gives (``None``: not a column this
    command reads); ``compute(texts, labels)`` runs the one-off computation on the cells given
    (texts by parameter key, header units applied) and returns its
    :class:`~dyncalc.result.Result`; ``fast`` is the vectorised path, if the command has one.
    """

    command = ""
    example_header = "k [N/m],m [kg]"
    fast = None

    def key(self, name: str) -> str | None:
        raise NotImplementedError

    def known(self) -> str:
        raise NotImplementedError

    def compute(self, texts: dict[str, str], labels: dict[str, str]):
        raise NotImplementedError


class NaturalFrequencyRows(RowSpec):
    """``natural-frequency``: columns are the standard options (``k``, ``length``, ...) and
    scene parameter names; ``--scene``, ``--method`` and ``--rtol`` apply to every row, and
    without ``--scene`` each row's columns choose its scene, as for a one-off."""

    command = "natural-frequency"

    def __init__(self, standard: dict[str, str], *, scene: str | None = None,
                 method: str | None = None, rtol: float | None = None, strict: bool = False):
        from ..scenes import catalog, get_scene

        self.standard = dict(standard)
        self.scene = get_scene(scene) if scene is not None else None
        self.method, self.rtol, self.strict = method, rtol, strict
        if self.scene is not None:
            self.params = [p.name for p in self.scene.params]
        else:
            self.params = list(dict.fromkeys(p.name for s in catalog().values()
                                             for p in s.params))
        self.fast = _natural_frequency_fast

    def key(self, name):
        param = self.standard.get(name, name)
        return param if param in self.params else None

    def known(self):
        options = [o for o, p in self.standard.items() if p in self.params]
        if self.scene is not None:
            names = list(dict.fromkeys([*self.params, *options]))
            return (f"natural-frequency --scene {self.scene.name} reads "
                    f"{', '.join(names)}")
        return (f"natural-frequency reads {', '.join(options)} and the parameters of the "
                "scenes (dyncalc scenes lists them)")

    def scene_for(self, keys) -> str:
        from ..commands.natural_frequency import infer_scene

        return self.scene.name if self.scene is not None else infer_scene(set(keys))

    def compute(self, texts, labels):
        from ..commands.natural_frequency import compute_scene

        return compute_scene(self.scene_for(texts), texts, labels=labels, method=self.method,
                             rtol=self.rtol, strict=self.strict)


class SpringRows(RowSpec):
    """``spring-series`` / ``spring-parallel``: element columns ``k1``, ``k2``, ... (each cell
    one element as on the command line: ``200 N/m``, ``cantilever(l=2m)``; the non-empty ones
    of a row, in column order) and shared-value columns named for an element parameter
    (``EI``, ``E``, ``l``, ...), as the command line's ``NAME=QUANTITY`` words."""

    example_header = "k1 [N/m],k2 [N/m]"
    _ELEMENT_RE = re.compile(r"^k[0-9]+$")

    def __init__(self, how: str, *, strict: bool = False):
        from ..commands.springs import ELEMENTS

        self.how, self.strict = how, strict
        self.command = f"spring-{how}"
        self.shared = list(dict.fromkeys(p for kind in ELEMENTS.values() for p in kind.params))

    def key(self, name):
        if self._ELEMENT_RE.match(name) or name in self.shared:
            return name
        return None

    def known(self):
        return (f"{self.command} reads elements k1, k2, ... and shared values "
                f"{', '.join(self.shared)}")

    def compute(self, texts, labels):
        from ..commands.springs import network_stiffness

        words = [text for key, text in texts.items() if self._ELEMENT_RE.match(key)]
        words += [f"{key}={text}" for key, text in texts.items()
                  if not self._ELEMENT_RE.match(key)]
        return network_stiffness(self.how, words, strict=self.strict)


class DampingRows(RowSpec):
    """``damping-ratio``: columns ``c``, ``k``, ``m``, ``decrement``, ``ratio``, ``cycles``,
    ``amplitudes``, ``omega``, ``g``; with ``--scene``, also that scene's parameters."""

    command = "damping-ratio"
    example_header = "decrement,omega [rad/s]"
    OPTIONS = ("c", "k", "m", "decrement", "ratio", "cycles", "amplitudes", "omega", "g")

    def __init__(self, *, scene: str | None = None, method: str | None = None,
                 rtol: float | None = None, strict: bool = False):
        self.scene, self.method, self.rtol, self.strict = scene, method, rtol, strict
        self.scene_params: list[str] = []
        if scene is not None:
            from ..scenes import get_scene

            self.scene_params = [p.name for p in get_scene(scene).params
                                 if p.name not in self.OPTIONS]

    def key(self, name):
        return name if name in self.OPTIONS or name in self.scene_params else None

    def known(self):
        names = [*self.OPTIONS, *self.scene_params]
        return f"damping-ratio reads {', '.join(names)}"

    def compute(self, texts, labels):
        from ..commands.damping_ratio import damping_ratio

        options = {name: texts.get(name) for name in self.OPTIONS}
        params = tuple(f"{k}={v}" for k, v in texts.items() if k not in self.OPTIONS)
        return damping_ratio(**options, scene=self.scene, params=params, method=self.method,
                             rtol=self.rtol, strict=self.strict)


class RollingRows(RowSpec):
    """``rolling-onset``: columns ``v0``, ``mu``, ``body``, ``kappa``, ``radius``, ``omega0``,
    ``g``, ``incline``."""

    command = "rolling-onset"
    example_header = "v0 [m/s],mu"
    OPTIONS = ("v0", "mu", "body", "kappa", "radius", "omega0", "g", "incline")

    def __init__(self, *, method: str | None = None, rtol: float | None = None,
                 strict: bool = False):
        self.method, self.rtol, self.strict = method, rtol, strict

    def key(self, name):
        return name if name in self.OPTIONS else None

    def known(self):
        return f"rolling-onset reads {', '.join(self.OPTIONS)}"

    def compute(self, texts, labels):
        from ..commands.rolling_onset import rolling_onset_result

        return rolling_onset_result(dict(texts), method=self.method, rtol=self.rtol,
                                    strict=self.strict)


class CoriolisRows(RowSpec):
    """``coriolis``: columns named for its options (``omega``, ``vr``, ``r``, ``alpha``,
    ``a0``, ``ar``, ``mass``, ``latitude``, ``speed``, ``heading``, ``vertical``)."""

    command = "coriolis"
    example_header = "omega [rad/s],vr [m/s]"

    def __init__(self, *, strict: bool = False):
        from ..commands.coriolis import OPTIONS

        self.options = tuple(OPTIONS)
        self.strict = strict

    def key(self, name):
        return name if name in self.options else None

    def known(self):
        return f"coriolis reads {', '.join(self.options)}"

    def compute(self, texts, labels):
        from ..commands.coriolis import coriolis_result

        return coriolis_result(dict(texts), strict=self.strict)
