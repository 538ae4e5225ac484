"""``coriolis`` with the motion given in time (../shared/SPEC.md, "Motion given in time"):
``--r``, ``--omega``, ``--R0`` as component expressions in ``t`` with ``NAME=QUANTITY``
parameters, evaluated at ``--t``.

:func:`read_time` reads and checks every text (dimensions on the expression trees, no sympy);
:func:`compute_time` derives the motion exactly (:mod:`dyncalc.physics.relative_time`, the only
place this command reaches sympy) and gives every term of

    v = v0 + Omega x r + v_r,
    a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r

at that time, in the rotating frame's components or, with ``--basis fixed``, the fixed
frame's (``x_fixed = Q(t) x_rotating``, ``Q(0) = I``).
"""
from __future__ import annotations

import copy
import functools
import math

from ..errors import InputError
from ..lazy import numpy as np
from ..result.entries import Entry, Explanation, Result, entry_from_parsed, format_number
from ..units import (ACCELERATION, ANGLE, ANGULAR_ACCELERATION, ANGULAR_RATE, FORCE, LENGTH,
                     MASS, TIME, VELOCITY, parse_quantity)

__all__ = ["TIME_OPTIONS", "is_time_motion", "read_time", "compute_time", "TimeInputs",
           "split_times", "TIME_KINDS"]

#: The options of the time path: they may be functions of ``t``.
TIME_OPTIONS = {"r": (LENGTH, "a length", "m", "rotating"),
                "omega": (ANGULAR_RATE, "an angular rate", "rad/s", "rotating"),
                "R0": (LENGTH, "a length", "m", "fixed")}
#: Options that the time path derives and so refuses when typed.
_DERIVED = {"vr": "v_r = r'", "ar": "a_r = r''", "alpha": "alpha = Omega'", "v0": "v0 = R0'",
            "a0": "a0 = R0''"}
_BASES = ("rotating", "fixed")

#: Results of the time path: name -> (dim, unit, symbol, description).
TIME_KINDS = {
    "r": (LENGTH, "m", "r", "position in the frame"),
    "v_r": (VELOCITY, "m/s", "v_r", "velocity relative to the frame (r')"),
    "a_r": (ACCELERATION, "m/s^2", "a_r", "acceleration relative to the frame (r'')"),
    "Omega": (ANGULAR_RATE, "rad/s", "Ω", "angular velocity of the frame"),
    "alpha": (ANGULAR_ACCELERATION, "rad/s^2", "α", "angular acceleration of the frame "
                                                      "(Omega')"),
    "v0": (VELOCITY, "m/s", "v0", "velocity of the frame's origin (R0')"),
    "a0": (ACCELERATION, "m/s^2", "a0", "acceleration of the frame's origin (R0'')"),
    "R": (LENGTH, "m", "R", "position of the point from the fixed origin (R0 + r)"),
    "theta": (ANGLE, "deg", "θ", "angle the frame has turned since t = 0"),
    "v_transport": (VELOCITY, "m/s", "v0+Ω×r", "transport velocity (of the frame point)"),
    "v": (VELOCITY, "m/s", "v", "absolute velocity"),
    "v_mag": (VELOCITY, "m/s", "|v|", "magnitude of v"),
    "v_transport_mag": (VELOCITY, "m/s", "|v_transport|", "magnitude of v_transport"),
    "a_transport_mag": (ACCELERATION, "m/s^2", "|a_transport|", "magnitude of a_transport"),
    "a_c": (ACCELERATION, "m/s^2", "2Ω×v_r", "Coriolis acceleration term"),
    "a_c_mag": (ACCELERATION, "m/s^2", "|a_c|", "magnitude of a_c"),
    "a_euler": (ACCELERATION, "m/s^2", "α×r", "Euler term (angular acceleration)"),
    "a_centripetal": (ACCELERATION, "m/s^2", "Ω×(Ω×r)", "centripetal term"),
    "a_transport": (ACCELERATION, "m/s^2", "a0+α×r+Ω×(Ω×r)", "transport acceleration"),
    "a": (ACCELERATION, "m/s^2", "a", "absolute acceleration"),
    "a_mag": (ACCELERATION, "m/s^2", "|a|", "magnitude of a"),
    "F_c": (FORCE, "N", "-m a_c", "Coriolis force (apparent, in the frame)"),
    "F_c_mag": (FORCE, "N", "|F_c|", "magnitude of F_c"),
}


def is_time_motion(texts: dict[str, str | None], words=()) -> bool:
    """Whether the options ask for the motion given in time: ``--t`` or ``--R0`` given, or
    ``t`` named in ``--r`` or ``--omega``."""
    from ..units.timevector import has_time

    if texts.get("t") is not None or texts.get("R0") is not None:
        return True
    return any(texts.get(name) is not None and has_time(texts[name]) for name in ("r", "omega"))


def split_times(text: str) -> list[str]:
    """``"0, 0.5, 1 s"`` -> ``["0 s", "0.5 s", "1 s"]`` (a list of times with one trailing
    unit, or a unit on each); one time gives a list of one."""
    from ..units.split import split_top

    parts = [p.strip() for p in split_top(text, ",")]
    if len(parts) == 1:
        return parts
    last = parts[-1]
    i = 0
    while i < len(last) and (last[i].isdigit() or last[i] in ".eE+-"):
        i += 1
    unit = last[i:].strip()
    out = []
    for p in parts:
        if not p:
            raise InputError(f"--t: an empty time in the list '{text[:80]}'")
        bare = all(ch.isdigit() or ch in ".eE+-" for ch in p)
        out.append(f"{p} {unit}" if unit and bare else p)
    return out


class TimeInputs:
    """What :func:`read_time` read: the vectors (:class:`~dyncalc.units.timevector.TimeVector`
    by option), the parameter values (SI) and entries, the time, the basis, the mass."""

    __slots__ = ("vectors", "params", "entries", "t", "basis", "mass", "warnings")

    def __init__(self, **values):
        for name in self.__slots__:
            setattr(self, name, values[name])


def _parameters(words, strict: bool):
    """``NAME=QUANTITY`` words -> (SI values, Dimensions, entries)."""
    from .eom_units import unit_text
    from ..units.expression import Dimension
    from ..units.grammar import quantity_in_base

    values, dims, entries = {}, {}, {}
    for word in words:
        name, sep, text = word.partition("=")
        name = name.strip()
        if not sep or not name.isidentifier() or name.startswith("_"):
            raise InputError(f"{word[:40]!r} is not NAME=QUANTITY: the parameters of the "
                             "expressions are given as words such as b=0.5m/s^2")
        if name == "t":
            raise InputError("t= is not a parameter: t is the time; give it as --t")
        if "±" in text or "+/-" in text:
            raise InputError(f"{name}=: an uncertainty is not propagated through a motion "
                             "given in time; give the value alone (--mass may carry one)")
        if name in values:
            raise InputError(f"{name}= given twice")
        value, powers, reading = quantity_in_base(text, label=f"{name}=")
        if strict and not any(ch.isalpha() for ch in text) and value != 0:
            raise InputError(f"{name}={text}: a bare number with --strict-units; give its unit")
        values[name], dims[name] = value, Dimension(powers)
        entries[name] = Entry(name, value, None, unit=unit_text(dims[name]), text=text,
                              reading=reading,
                              description="parameter of the expressions")
    return values, dims, entries


@functools.lru_cache(maxsize=32)
def _read_motion(texts: tuple, words: tuple, strict: bool):
    """``(parameter values, vectors, entries)`` of the texts of ``--r``, ``--omega``, ``--R0``
    (in :data:`TIME_OPTIONS`' order, ``None`` when not given) and the ``NAME=QUANTITY``
    words: read once for the same texts (a batch over times reads them once; the callers copy
    what they keep)."""
    from .eom_units import dimension_of_dim
    from ..units.timevector import read_time_vector

    values, dims, entries = _parameters(words, strict)
    vectors = {}
    for (name, (dim, words_, hint, frame)), text in zip(TIME_OPTIONS.items(), texts):
        if text is None:
            continue
        vec = read_time_vector(text, dimension_of_dim(dim), label=f"--{name}",
                               params=dims, dim_words=words_, unit_hint=hint, strict=strict)
        vectors[name] = vec
        what = "position" if name != "omega" else "angular velocity"
        entries[name] = Entry(name, text, None, text=text, assumed_si=bool(vec.assumed_si),
                              description=f"{what} in {frame}-frame components, in t")
    unused = set(values) - set().union(*(v.names for v in vectors.values()))
    if unused:
        raise InputError(f"{sorted(unused)[0]}= is not used by --r, --omega or --R0: leave it "
                         "out or use it in an expression")
    return values, vectors, entries


def read_time(texts: dict[str, str | None], words=(), strict: bool = False) -> TimeInputs:
    """The option texts and ``NAME=QUANTITY`` words of the time path -> :class:`TimeInputs`:
    every expression read by the closed grammar and its dimension checked (no sympy); the
    expressions and parameters once for the same texts (:func:`_read_motion`)."""
    texts = {k: v for k, v in texts.items() if v is not None}
    for name, how in _DERIVED.items():
        if name in texts:
            raise InputError(f"--{name} does not go with a motion given in time: {how} is "
                             "derived from the expressions")
    for name in ("latitude", "speed", "heading", "vertical"):
        if name in texts:
            raise InputError(f"--{name} does not go with a motion given in time (--t): the "
                             "Earth mode takes constant vectors")
    if "t" not in texts:
        from ..units.split import split_top
        from ..units.timevector import has_time

        for name in TIME_OPTIONS:
            for index, part in enumerate(split_top(texts.get(name) or "", ","), 1):
                if has_time(part):
                    raise InputError(f"--{name}: component {index} depends on t: motion given "
                                     "in time needs --t (the time to evaluate at)")
        given = next(n for n in ("r", "omega", "R0") if n in texts)
        raise InputError(f"--t is missing: --{given} is a motion given in time; give the time "
                         "to evaluate it at, e.g. --t 2s")
    if not any(name in texts for name in TIME_OPTIONS):
        raise InputError("--t needs a motion: give --r, --omega or --R0 as expressions in t")
    values, vectors, read = _read_motion(tuple(texts.get(name) for name in TIME_OPTIONS),
                                         tuple(words), strict)
    values, vectors = dict(values), dict(vectors)
    entries = {name: copy.copy(entry) for name, entry in read.items()}
    t = parse_quantity(texts["t"], TIME, label="--t", strict=strict)
    if t.uncertainty is not None:
        raise InputError("--t: an uncertainty is not propagated through a motion given in "
                         "time; give the time alone")
    entries["t"] = entry_from_parsed("t", t, TIME, description="time of evaluation")
    basis = texts.get("basis", "rotating")
    if basis not in _BASES:
        raise InputError(f"--basis must be rotating or fixed; got {basis[:40]!r}")
    mass = None
    if "mass" in texts:
        mass = parse_quantity(texts["mass"], MASS, label="--mass", strict=strict,
                              constraint="positive")
        entries["mass"] = entry_from_parsed("mass", mass, MASS, description="mass")
    return TimeInputs(vectors=vectors, params=values, entries=entries, t=float(t.si),
                      basis=basis, mass=mass, warnings=[])


def _entry(name: str, value) -> Entry:
    dim, unit, symbol, description = TIME_KINDS[name]
    if np.ndim(value):
        value = np.asarray(value, dtype=float) + 0.0
    else:
        value = float(value) + 0.0
    return Entry(name, value, dim, unit=unit, symbol=symbol, description=description)


def _fmt(v, unit: str) -> str:
    return f"{format_number(np.asarray(v, dtype=float) + 0.0, 6)} {unit}"


def _magnitude(v) -> float:
    from ..physics.frames import magnitude

    return magnitude(v)


def compute_time(inputs: TimeInputs) -> Result:
    """Every vector at ``--t`` (:func:`~dyncalc.physics.relative_time.motion_in_time`)."""
    from ..physics.relative_motion import relative_motion
    from ..physics.relative_time import motion_in_time

    vec = inputs.vectors
    motion = motion_in_time(vec.get("r"), vec.get("omega"), vec.get("R0"), inputs.params)
    s = motion.state(inputs.t)
    v0, a0 = s.rotating(s.v0), s.rotating(s.a0)
    m = None if inputs.mass is None else float(inputs.mass.si)
    moving = relative_motion(s.Omega, s.r, v_r=s.v_r, v0=v0, alpha=s.alpha, a0=a0,
                             a_r=s.a_r, m=m)
    fa, v_transport, v = moving.accel, moving.v_transport, moving.v
    absolute = s.rotating(s.R0) + s.r
    vectors = {"r": s.r, "v_r": s.v_r, "a_r": s.a_r, "Omega": s.Omega, "alpha": s.alpha,
               "v0": v0, "a0": a0, "R": absolute, "v_transport": v_transport, "v": v,
               "a_c": fa.a_c, "a_euler": fa.a_euler, "a_centripetal": fa.a_centripetal,
               "a_transport": fa.a_transport, "a": fa.a}
    if fa.F_c is not None:
        vectors["F_c"] = fa.F_c
    fixed = inputs.basis == "fixed"
    results = {}
    own = {"v0": s.v0, "a0": s.a0, "R": s.R0 + s.Q @ s.r}  # given in fixed components
    for name, value in vectors.items():
        if fixed:
            results[name] = _entry(name, own[name] if name in own else s.Q @ value)
        else:
            results[name] = _entry(name, value)
        if name in ("v_transport", "v", "a_transport", "a", "a_c", "F_c"):
            results[f"{name}_mag"] = _entry(f"{name}_mag", _magnitude(value))
    if s.theta is not None:
        results["theta"] = _entry("theta", s.theta)
    warnings = list(moving.warnings) + [w for w in fa.warnings if w not in moving.warnings]
    if motion.rotation == "numerical":
        warnings.append("the frame's axis of rotation turns in time: the rotation Q(t) from "
                        "the rotating to the fixed frame (theta, R, --basis fixed, v0 and a0 in "
                        "rotating components) is integrated numerically (rtol 1e-12)")

    def explain() -> Explanation:  # built only when shown (never in batch)
        rotation = {"none": "the frame does not turn (Omega = 0): Q = I",
                    "closed form": "the frame turns about a fixed axis n = "
                                   f"{_fmt(motion.axis, '')}by theta = int_0^t |Omega| dt "
                                   f"= {motion.derived.get('theta', [''])[0]} rad (exact)",
                    "quadrature": f"the frame turns about a fixed axis n = {_fmt(motion.axis, '')}"
                                  "by theta = int_0^t |Omega| dt (adaptive quadrature: sympy "
                                  "found no closed form)",
                    "numerical": "the frame's axis turns in time: Q' = Q [Omega]x, Q(0) = I "
                                 "integrated numerically (DOP853, rtol 1e-12)"}[motion.rotation]
        lines = []
        for name, how in (("v_r", "r'"), ("a_r", "r''"), ("alpha", "Omega'"), ("v0", "R0'"),
                          ("a0", "R0''")):
            source = {"v_r": "r", "a_r": "r", "alpha": "omega", "v0": "R0", "a0": "R0"}[name]
            if source in vec:
                lines.append(f"{name} = {how} = ({', '.join(motion.derived[name])})")
        lines.append(f"at t = {format_number(inputs.t, 6)} s: r = {_fmt(s.r, 'm')}, v_r = "
                     f"{_fmt(s.v_r, 'm/s')}, a_r = {_fmt(s.a_r, 'm/s^2')}, Omega = "
                     f"{_fmt(s.Omega, 'rad/s')}, alpha = {_fmt(s.alpha, 'rad/s^2')}")
        lines.append(rotation)
        if "R0" in vec:
            lines.append(f"v0 = {_fmt(s.v0, 'm/s')}, a0 = {_fmt(s.a0, 'm/s^2')} (fixed "
                         "components), Q^T times them in the rotating frame")
        lines.append(f"v = v0 + Omega x r + v_r = {_fmt(v, 'm/s')} (rotating components)")
        lines.append(f"a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r = "
                     f"{_fmt(fa.a, 'm/s^2')} (rotating components)")
        basis_words = ("fixed frame's axes (x_fixed = Q(t) x_rotating)" if fixed
                       else "rotating frame's axes at t")
        return Explanation(
            formula=["v_r = r', a_r = r'', alpha = Omega', v0 = R0', a0 = R0'' (exact, sympy)",
                     "v = v0 + Omega x r + v_r",
                     "a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r",
                     "Q' = Q [Omega]x, Q(0) = I (rotating -> fixed components)"],
            substituted=lines,
            assumptions=["--r and --omega are rotating-frame components, --R0 fixed-frame "
                         "components; the two frames coincide at t = 0",
                         f"vector results are components in the {basis_words}; magnitudes do not "
                         "depend on the basis",
                         "t in an expression is always time (never the tonne)"],
            reference="Gross et al., Engineering Mechanics 3, Chapter 6 (relative motion): E6.6, "
                      "E6.7, E6.10, E6.12")

    extra = {"basis": inputs.basis, "rotation": motion.rotation,
             "derivatives": {name: motion.derived[name] for name in
                             ("v_r", "a_r", "alpha", "v0", "a0")}}
    if fixed or motion.rotation != "none":
        extra["rotation_matrix"] = [[float(x) + 0.0 for x in row] for row in s.Q]
    result = Result(command="coriolis", results=results, inputs=dict(inputs.entries),
                    model=f"motion given in time ({inputs.basis} basis)", method="exact "
                    "derivatives" + ("; rotation integrated numerically"
                                     if motion.rotation == "numerical" else ""),
                    warnings=warnings, explanation=explain, extra=extra)
    if inputs.mass is not None and inputs.mass.uncertainty is not None:
        result.sensitivity = lambda: _mass_sensitivity(result, m, float(inputs.mass.uncertainty))
    return result


def _mass_sensitivity(result: Result, m: float, sigma: float):
    """Only ``F_c = -m a_c`` and its magnitude depend on the mass, linearly: their slopes are
    their values over ``m`` (exact); every other result has slope 0."""
    from ..result.propagate import Sensitivity, UncertainInput

    slopes = {}
    for name, entry in result.results.items():
        value = np.asarray(entry.si, dtype=float)
        slope = value / m if name in ("F_c", "F_c_mag") else np.zeros(np.shape(value))
        slopes[name] = {0: slope if np.ndim(slope) else float(slope)}
    return Sensitivity([UncertainInput("mass", m, sigma)], slopes)


def time_result(texts: dict[str, str | None], words=(), *, strict: bool = False) -> Result:
    """:func:`read_time` then :func:`compute_time`."""
    return compute_time(read_time(texts, words, strict))


class PathData:
    """What ``--plot`` draws (:func:`path_data`): ``times`` (s), ``path`` (n, 3: the point's
    position in the fixed frame, NaN where the expressions are not defined), ``point``, ``v``,
    ``a`` (fixed components at ``t``), the window's ``reason``."""

    __slots__ = ("times", "path", "t", "point", "v", "a", "reason")

    def __init__(self, **values):
        for name in self.__slots__:
            setattr(self, name, values[name])


#: Points along the plotted path.
PATH_POINTS = 400


def plot_window(t: float, rate: float, speed: float, accel: float) -> tuple[float, float, str]:
    """The time window ``--plot`` draws around ``t``: one turn of the frame centred on ``t``
    (``t +- pi/|Omega(t)|``) when it turns; else ``t +- |v|/|a|`` (the time over which the
    velocity changes by itself) when both are non-zero; else ``t +- 1 s``; never before
    ``t = 0`` when ``t >= 0`` (the frames coincide at ``t = 0``, where the motion starts)."""
    if rate > 0.0:
        half, reason = math.pi / rate, "one turn of the frame centred on t"
    elif speed > 0.0 and accel > 0.0:
        half, reason = speed / accel, "t +- |v|/|a|"
    else:
        half, reason = 1.0, "t +- 1 s"
    start = t - half
    if t >= 0.0 and start < 0.0:
        start, reason = 0.0, reason + ", from t = 0"
    return start, t + half, reason


def path_data(values: dict[str, str | None], words=(), *, strict: bool = False) -> PathData:
    """The point's path in the fixed frame over :func:`plot_window` and its velocity and
    acceleration at ``--t`` in fixed components, for ``--plot``."""
    from ..physics.relative_time import motion_in_time

    inputs = read_time({name: values.get(name) for name in values
                        if name not in ("plot", "scene")}, words, strict)
    inputs.basis = "fixed"
    result = compute_time(inputs)
    vec = inputs.vectors
    motion = motion_in_time(vec.get("r"), vec.get("omega"), vec.get("R0"), inputs.params)
    res = result.results
    rate = float(np.linalg.norm(result.results["Omega"].si))
    start, end, reason = plot_window(inputs.t, rate, res["v_mag"].si, res["a_mag"].si)
    times = np.linspace(start, end, PATH_POINTS)
    path = motion.positions(times)  # NaN (a gap) where an expression is not defined
    return PathData(times=times, path=path, t=inputs.t, point=np.asarray(res["R"].si),
                    v=np.asarray(res["v"].si), a=np.asarray(res["a"].si), reason=reason)
