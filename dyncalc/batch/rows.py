"""What each command reads from a row: ``RowSpec`` and one subclass per command."""
from __future__ import annotations

import re

from ..errors import InputError

from .fast import _natural_frequency_fast
from .fast_inverse import inverse_blocks


class RowSpec:
    """How one command turns a row's cells into its library call.

    ``key(name)`` maps a column name to the parameter it gives (``None``: not a column this
    command reads); ``compute(texts, labels)`` runs the one-off computation on the cells given
    (texts by parameter key, header units applied) and returns its
    :class:`~dyncalc.result.Result`; ``fast`` is the vectorised path, if the command has one.
    """

    command = ""
    example_header = "k [N/m],m [kg]"
    #: rows in a CSV chunk (:func:`dyncalc.batch.chunk_rows`; the first chunk fixes the
    #: columns): 16384, fewer where a chunk's work holds more memory per row
    csv_rows = 16384
    fast = None
    #: the command's column adapter (:attr:`dyncalc.commands.record.Command.columns`), the
    #: settings it is given and the ``strict`` flag (for the vectorised path)
    adapter = None
    settings: dict = {}
    strict = False

    def parameter(self, key: str):
        """The record parameter a column key gives (vectorised path); ``None``: not one."""
        return None

    def input_names(self, keys: list[str]) -> dict[str, str]:
        """The name the one-off gives the input of each column key of a row."""
        return {key: key for key in keys}

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
        self.inverse = inverse_blocks  # the rows that solve for a parameter

    def key(self, name):
        """A parameter (by option or scene name), or a result to solve from (``f``, ``T``,
        ... as ``f=5Hz`` in the one-off: the row is an inverse problem)."""
        from ..scenes.runner import is_result_name

        param = self.standard.get(name, name)
        if param in self.params:
            return param
        return name if is_result_name(name) else None

    def known(self):
        options = [o for o, p in self.standard.items() if p in self.params]
        if self.scene is not None:
            names = list(dict.fromkeys([*self.params, *options]))
            return (f"natural-frequency --scene {self.scene.name} reads "
                    f"{', '.join(names)} and a result to solve from (f, omega, T, ...)")
        return (f"natural-frequency reads {', '.join(options)}, the parameters of the "
                "scenes (dyncalc scenes lists them) and a result to solve from (f, omega, T, "
                "...)")

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

        from ..commands.springs import SPRING_PARALLEL, SPRING_SERIES

        self.how, self.strict = how, strict
        self.command = f"spring-{how}"
        self.shared = list(dict.fromkeys(p for kind in ELEMENTS.values() for p in kind.params))
        record = SPRING_SERIES if how == "series" else SPRING_PARALLEL
        if record.columns is not None:
            from .fast_springs import spring_fast

            # plain stiffnesses (fast_commands) and element words (fast_springs)
            self.adapter, self.fast = record.columns, spring_fast
            self.probed = {}  # one probe per kind of block a run, not one per chunk

    def parameter(self, key):
        """An element column holds plain stiffnesses on the vectorised path (a torsional
        spring, a beam word or a shared value leaves the row to the generic path)."""
        if not self._ELEMENT_RE.match(key):
            return None
        from ..commands.record import Parameter
        from ..units import STIFFNESS

        return Parameter(key, STIFFNESS)

    def input_names(self, keys):
        """The one-off numbers a row's elements in order: ``k1``, ``k3`` given are its k1, k2."""
        elements = [key for key in keys if self._ELEMENT_RE.match(key)]
        names = {key: f"k{i}" for i, key in enumerate(elements, 1)}
        names.update((key, key) for key in keys if key not in names)
        return names

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


class RecordRows(RowSpec):
    """A command's rows, generated from its Command record
    (:class:`dyncalc.commands.record.Command`): a column may be named for any of the record's
    physics inputs (``v0``, ``mu``, ...; settings such as ``--method`` apply to every row and
    are no columns) or, with a scene, for one of that scene's parameters (passed on as the
    ``NAME=QUANTITY`` words of the one-off); each row runs ``record.compute``."""

    def __init__(self, record, settings: dict | None = None, *, scene_words: tuple = (),
                 rtol: float | None = None, strict: bool = False, example: str = "",
                 targets: tuple = ()):
        self.record, self.settings = record, dict(settings or {})
        self.targets = targets  # besides result names, what a scene row may solve from
        self.command = record.name
        self.columns = [p.name for p in record.inputs]
        self.scene_words = [name for name in scene_words if name not in self.columns]
        self.rtol, self.strict = rtol, strict
        self.example_header = example or self.example_header
        if record.columns is not None and not self.scene_words:
            from .fast_commands import _command_fast

            self.adapter, self.fast = record.columns, _command_fast

    def parameter(self, key):
        return self.record.parameter(key) if key in self.columns else None

    def key(self, name):
        if name in self.columns or name in self.scene_words:
            return name
        if self.scene_words:  # with a scene, a result to solve from (``zeta``, ``delta``)
            from ..scenes.runner import is_result_name

            return name if is_result_name(name) or name in self.targets else None
        return None

    def known(self):
        solve = " and a result to solve from (zeta, delta, ...)" if self.scene_words else ""
        return f"{self.command} reads {', '.join([*self.columns, *self.scene_words])}{solve}"

    def compute(self, texts, labels):
        values = {name: texts.get(name) for name in self.columns}
        values.update(self.settings)
        words = tuple(f"{k}={v}" for k, v in texts.items() if k not in self.columns)
        return self.record.compute(values, words, rtol=self.rtol, strict=self.strict)


def DampingRows(*, scene: str | None = None, method: str | None = None,
                rtol: float | None = None, strict: bool = False) -> RecordRows:
    """``damping-ratio``: its record's columns (``c``, ``k``, ``m``, ``decrement``, ...);
    with ``--scene``, also that scene's parameters and a result to solve one of them from
    (``zeta``, ``delta``, ``Q``, as the one-off's ``NAME=QUANTITY`` words)."""
    from ..commands.damping_ratio import COMMAND
    from ..scenes import get_scene

    words = tuple(p.name for p in get_scene(scene).params) if scene is not None else ()
    return RecordRows(COMMAND, {"scene": scene, "method": method}, scene_words=words,
                      rtol=rtol, strict=strict, example="decrement,omega [rad/s]",
                      targets=("delta", "Q"))


def RollingRows(*, method: str | None = None, rtol: float | None = None,
                strict: bool = False) -> RecordRows:
    """``rolling-onset``: its record's columns (``v0``, ``mu``, ``body``, ...)."""
    from ..commands.rolling_onset import COMMAND

    return RecordRows(COMMAND, {"method": method}, rtol=rtol, strict=strict,
                      example="v0 [m/s],mu")


def CoriolisRows(*, strict: bool = False) -> RecordRows:
    """``coriolis``: its record's columns (``omega``, ``vr``, ``r``, ...) and the results an
    inverse problem starts from (``a_c``, ``a_c_mag``, ...), with ``?`` in the option column
    to solve for (``vr=?`` in the one-off)."""
    from ..commands.coriolis import COMMAND

    return _CoriolisRows(COMMAND, strict=strict, example="omega [rad/s],vr [m/s]")


class _CoriolisRows(RecordRows):
    """:class:`RecordRows` of ``coriolis`` that also read its inverse problems: a result column
    (:data:`dyncalc.scenes.coriolis_scalar.TARGETS`) and a ``?`` cell go to the one-off as
    ``NAME=QUANTITY`` and ``NAME=?`` words (the perpendicular ones solved on columns:
    :mod:`dyncalc.batch.fast_coriolis`; the Earth's: :mod:`dyncalc.batch.fast_coriolis_earth`)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        from .fast_coriolis_earth import coriolis_rows_fast

        self.fast = coriolis_rows_fast

    def key(self, name):
        from ..scenes.coriolis_scalar import TARGETS

        if any(name in names for names in TARGETS.values()):
            return name
        return super().key(name)

    def compute(self, texts, labels):
        asked = {name: "?" for name, text in texts.items()
                 if name in self.columns and text is not None and text.strip() == "?"}
        values = {name: texts.get(name) for name in self.columns if name not in asked}
        values.update(self.settings)
        words = tuple(f"{k}={v}" for k, v in {**texts, **asked}.items()
                      if k not in self.columns or k in asked)
        return self.record.compute(values, words, rtol=self.rtol, strict=self.strict)



class CoriolisTimeRows(RowSpec):
    """``coriolis`` with a motion given in time, one row per time: the expressions and their
    parameters come from the command line (``--r``, ``--omega``, ``--R0``, ``NAME=`` words),
    the rows give ``t`` and may override a parameter."""

    command = "coriolis"
    example_header = "t [s]"
    #: 60-odd result columns a row on top of sympy's 78 MB: 16384 rows a chunk peaked at
    #: 117 MB (CSV), 8192 at 94 MB, 4096 at 90 MB, as fast (issue 17: <= 100 MB)
    csv_rows = 4096

    def __init__(self, values: dict, words=(), *, strict: bool = False):
        self.values, self.strict = dict(values), strict
        self.words = {w.partition("=")[0].strip(): w for w in words}
        from .fast_coriolis_time import coriolis_time_fast  # a t column on arrays

        self.fast = coriolis_time_fast

    def key(self, name):
        return name if name == "t" or name in self.words else None

    def known(self):
        names = ", ".join(["t", *self.words])
        return f"coriolis with a motion given in time reads {names}"

    def compute(self, texts, labels):
        from ..commands.coriolis import COMMAND

        values = dict(self.values)
        values["t"] = texts.get("t", values.get("t"))
        if values["t"] is None:
            raise InputError("no t in this row: the file's t column gives the time")
        words = [f"{k}={texts[k]}" if k in texts else w for k, w in self.words.items()]
        return COMMAND.compute(values, tuple(words), strict=self.strict)


def ForcedRows(*, scene: str | None = None, rtol: float | None = None,
               strict: bool = False) -> RecordRows:
    """``forced-response``: its record's columns (``k``, ``m``, ``zeta``, ``F0``, ``Omega``,
    ...); with ``--scene``, also that scene's parameters."""
    from ..commands.forced_response import COMMAND
    from ..scenes.forced import forced_scene

    words = tuple(p.name for p in forced_scene(scene).params) if scene is not None else ()
    spec = RecordRows(COMMAND, {"scene": scene}, scene_words=words, rtol=rtol, strict=strict,
                      example="k [N/m],m [kg],zeta,F0 [N],Omega [rad/s]")
    # up to 19 result columns, each through a double-double kernel: 16384 rows a chunk
    # peaked at 113 MB on 10^6 rows, 8192 at 87 MB (issue 17: <= 100 MB), no slower
    spec.csv_rows = 8192
    # one probe (a one-off) per kind of block a run, not one per chunk: undamped rows split
    # in two blocks a chunk (isolation or not), and their probes were a ninth of a run
    spec.probed = {}
    return spec


def RigidRows(*, scene: str | None = None, rtol: float | None = None,
              strict: bool = False) -> RecordRows:
    """``rigid-body``: with ``--scene``, the scene's parameters (and a result to solve one of
    them from), row by row; without, the Euler mode's ``inertia_tensor``, ``omega`` and
    ``alpha`` as quoted cells."""
    from ..commands.rigid_body import COMMAND, rigid_scene

    if scene is None:  # Euler rows on columns (dyncalc.physics.euler_columns)
        from ..commands.rigid_columns import euler_columns_of
        from .fast_commands import _command_fast

        spec = RecordRows(COMMAND, {"scene": None}, rtol=rtol, strict=strict,
                          example="inertia_tensor,omega,alpha")
        spec.adapter, spec.fast = euler_columns_of, _command_fast
        spec.csv_rows = 4096  # nine numbers a tensor cell: fewer rows a chunk, flat memory
        return spec
    chosen = rigid_scene(scene)
    spec = RecordRows(COMMAND, {"scene": scene}, rtol=rtol, strict=strict,
                      targets=tuple(chosen.kinds), example="m1 [kg],m2 [kg]")
    # every column is a scene word: the scene's alpha is a result to solve from, not --alpha
    spec.columns = []
    spec.scene_words = [p.name for p in chosen.params]
    spec.known = lambda: (f"rigid-body --scene {chosen.name} reads "
                          f"{', '.join(spec.scene_words)} and a result to solve from "
                          f"({', '.join(chosen.kinds)})")
    # the vectorised path: the scene's physics on each row's SI floats (commands/rigid_columns)
    from ..commands.record import Parameter
    from ..commands.rigid_columns import scene_columns
    from .fast_rigid import rigid_fast

    params = {p.name: Parameter(p.name, p.dim, p.description, kind="choice",
                                choices=tuple(p.choices)) if p.choices is not None
              else Parameter(p.name, p.dim, p.description) for p in chosen.params}
    spec.parameter = params.get
    # forward rows through the scene's adapter; inverse rows in closed form (fast_rigid)
    spec.adapter, spec.fast = scene_columns, rigid_fast
    return spec


def ModesRows(*, scene: str | None = None, normalize: str | None = None,
              strict: bool = False) -> RecordRows:
    """``modes``: one system per row, its matrices as quoted cells (``M``, ``K``, ``C``);
    with ``--scene``, that scene's parameters instead."""
    from ..commands.modes import COMMAND
    from ..scenes import get_scene

    words = tuple(p.name for p in get_scene(scene).params) if scene is not None else ()
    spec = RecordRows(COMMAND, {"scene": scene, "normalize": normalize}, scene_words=words,
                      strict=strict, example='M,K')
    if scene is None:  # matrices of bare numbers solved on a stack (dyncalc.batch.fast_modes)
        from .fast_modes import modes_fast

        spec.fast = modes_fast
        spec.probed = {}  # one probe (a one-off) per kind of rows a run, not one per chunk
        # up to 27 numbers a row read, 16 written: 8192 rows a chunk peaked at 95 MB on 10^6
        # rows with a non-proportional C, 4096 at 81 MB, as fast (issue 17: <= 100 MB)
        spec.csv_rows = 4096
        return spec
    # every column is a scene word (block-disk-springs' M is the block's mass, not --M); no
    # result to solve from (modes has no inverse problems)
    spec.columns, spec.scene_words = [], list(words)
    spec.key = lambda name: name if name in spec.scene_words else None
    spec.known = lambda: f"modes --scene {scene} reads {', '.join(spec.scene_words)}"
    from ..commands.modes_scene_columns import SCENES, scene_columns

    if get_scene(scene).name in SCENES:  # the scene's matrices on columns, then the stack
        from ..commands.record import Parameter
        from .fast_commands import _command_fast
        from .fast_modes import PROBE_RTOL

        params = {p.name: Parameter(p.name, p.dim, p.description)
                  for p in get_scene(scene).params}
        spec.parameter = params.get
        spec.adapter, spec.fast = scene_columns, _command_fast
        spec.probe_rtol = PROBE_RTOL  # the stack rounds otherwise than sygvd (1e-12)
        spec.probed = {}  # one probe (a one-off) per kind of block a run
    return spec


def EomRows(*, scene: str | None = None, about: str | None = None,
            rtol: float | None = None, strict: bool = False) -> RecordRows:
    """``eom --scene NAME``: columns are the scene's parameters and the state (``x``,
    ``x_dot``, ``t``); the scenes :mod:`dyncalc.commands.eom_columns` takes are derived once
    and computed on whole columns, the other rows derive once more each (sympy)."""
    from ..commands.eom import COMMAND
    from ..scenes.energies import energies

    if scene is None:
        raise InputError("eom --batch needs --scene NAME: each row gives that scene's "
                         "parameter values (typed energies are one-offs)")
    record = energies(scene)
    state = [*record.coords, *(c + "_dot" for c in record.coords), "t"]
    words = (*(p.name for p in record.params), *state,
             *(("body",) if record.param("kappa") is not None else ()))
    spec = RecordRows(COMMAND, {"scene": scene, "about": about}, scene_words=words,
                      rtol=rtol, strict=strict,
                      example=",".join(p.name for p in record.params[:2]))
    # the vectorised path: derived once, the numbers on columns (commands/eom_columns)
    from ..commands.eom_columns import light_probe, scene_columns, scene_parameters
    from .fast_commands import _command_fast

    spec.parameter = scene_parameters(scene).get
    spec.adapter, spec.fast = scene_columns, _command_fast
    spec.light_probe = light_probe  # a scene of the generated table: no one-off, no sympy
    spec.probed = {}  # one probe (a whole one-off) per kind of block, not one per chunk
    return spec
