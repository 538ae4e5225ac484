"""``forced-response``: steady and total response of a single-degree-of-freedom oscillator
to one harmonic excitation (../shared/SPEC.md v2, "forced-response").

:func:`read` checks which options were given (one natural frequency, at most one damping,
exactly one excitation, one excitation frequency) and gathers the texts of the scene it runs:
the driven mass-spring-damper (:data:`dyncalc.scenes.forced.OSCILLATOR`) or, with ``--scene``,
a forced scene with its own parameters. :func:`compute` runs it forward, or solves for the one
unknown when a result is given (``TR=0.1 k=?``: :mod:`dyncalc.scenes.inverse`).
"""
from __future__ import annotations

import math

from ..errors import InputError
from ..result import Result
from ..units import (ANGULAR_RATE, CYCLE_RATE, DAMPING, DIMENSIONLESS, FORCE, LENGTH, MASS,
                     STIFFNESS, TIME, UNBALANCE, VELOCITY, ACCELERATION)
from .record import Command, Parameter, ResultName
from .words import gather_texts

__all__ = ["COMMAND", "ForcedInputs", "read", "compute", "forced_response"]

#: The excitation options, by scene parameter.
_EXCITATIONS = {"F0": "--F0", "base": "--base", "base_accel": "--base-accel",
                "unbalance": "--unbalance"}
#: The excitation kinds of :mod:`dyncalc.physics.forced`, by scene parameter.
_KINDS = {"F0": "force", "base": "base", "base_accel": "base-accel", "unbalance": "unbalance"}
_DAMPINGS = {"zeta": "--zeta", "c": "--c", "Q": "--Q"}
_EXCITATION_USAGE = "--F0 FORCE, --base U0, --base-accel B0 or --unbalance ME"
#: The oscillator's parameters (a name among them is never a result to solve from).
_PARAMETERS = ("k", "m", "omega", "zeta", "c", "Q", *_EXCITATIONS, "Omega", "f_exc", "x0",
               "v0", "t")


class ForcedInputs:
    """What :func:`read` checked: the scene to run (the oscillator or a forced scene), its
    parameter texts and their labels (``--k`` or ``k=``), and the run's settings."""

    __slots__ = ("scene", "texts", "labels", "rtol", "strict")

    def __init__(self, scene, texts: dict[str, str], labels: dict[str, str], rtol, strict):
        self.scene, self.texts, self.labels = scene, texts, labels
        self.rtol, self.strict = rtol, strict


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


def read(options: dict[str, str | None], words=(), *, scene: str | None = None,
         rtol: float | None = None, strict: bool = False) -> ForcedInputs:
    """The options as typed (by parameter name) and the ``NAME=QUANTITY`` words ->
    :class:`ForcedInputs`, refusing the combinations that ask for no or several natural
    frequencies, dampings, excitations or excitation frequencies."""
    from ..scenes.forced import OSCILLATOR, forced_scene

    texts, labels = gather_texts({name: (text, _flag(name)) for name, text in options.items()},
                                 words, "a parameter")
    if scene is not None:
        chosen = forced_scene(scene)
        _check_driven(chosen, options, texts)
        for name in options:
            if options[name] is not None and chosen.param(name) is None:
                why = ("it is driven by --F0 on its coordinate" if _is_driven(chosen)
                       else "the scene has its own forcing")
                raise InputError(f"{_flag(name)} does not go with --scene {chosen.name}: "
                                 f"{why}; its parameters are {chosen.signature()}")
        return ForcedInputs(chosen, texts, labels, rtol, strict)
    _check_forms(texts, labels)
    return ForcedInputs(OSCILLATOR, texts, labels, rtol, strict)


def _is_driven(chosen) -> bool:
    """Whether ``chosen`` is a catalog scene driven on its coordinate (dyncalc.scenes.sdof)."""
    from ..scenes.sdof import COORDINATES

    return chosen.name in COORDINATES and chosen.param("F0") is not None


def _check_driven(chosen, options: dict, texts: dict) -> None:
    """Refuse what a scene driven on its coordinate does not take: another excitation than
    ``--F0``, a damping where the scene has its own, ``--Omega`` where ``Omega=`` is the
    scene's own spin, an inverse problem."""
    from ..scenes.runner import is_inverse
    from ..scenes.sdof import COORDINATES, has_spin, refuse_excitation

    coordinate = COORDINATES.get(chosen.name)
    if coordinate is None or chosen.param("F0") is None:
        return
    for name in ("base", "base_accel", "unbalance"):
        if options.get(name) is not None or name in texts:
            raise refuse_excitation(chosen.name, _flag(name))
    if coordinate.damped:
        for name in _DAMPINGS:
            if options.get(name) is not None or name in texts:
                raise InputError(f"{_flag(name)} does not go with --scene {chosen.name}: its "
                                 "damping is its own (its parameters give zeta)")
    if options.get("Omega") is not None and has_spin(chosen.name):
        raise InputError(f"--Omega does not go with --scene {chosen.name}: its Omega= is the "
                         "spin of the set-up; give the excitation frequency as --f-exc")
    if "amplitude" in texts:
        raise InputError(f"amplitude= does not go with forced-response --scene "
                         f"{chosen.name}: the driven response is linear (small motion about "
                         "the equilibrium); natural-frequency takes an amplitude")
    if is_inverse(chosen, texts):
        raise InputError(f"forced-response --scene {chosen.name} runs forward only: give "
                         "every parameter (an inverse problem works on the mass-spring-damper "
                         "itself, --k --m without --scene)")


def _shown(names, labels) -> str:
    return " and ".join(labels[n].rstrip("=") if labels[n].startswith("--")
                        else labels[n] for n in names)


def _check_forms(texts: dict[str, str], labels: dict[str, str]) -> None:
    from ..scenes.runner import is_result_name

    excitations = [n for n in _EXCITATIONS if n in texts]
    solving = any(is_result_name(n) and n not in _PARAMETERS for n in texts)
    if not excitations and not solving:
        raise InputError(f"forced-response needs one excitation: {_EXCITATION_USAGE}")
    if len(excitations) > 1:
        raise InputError(f"forced-response takes one excitation, not {len(excitations)}: got "
                         f"{_shown(excitations, labels)}; give one of {_EXCITATION_USAGE}")
    if "Omega" in texts and "f_exc" in texts:
        raise InputError("give the excitation frequency as --Omega or as --f-exc, not both")
    if "Omega" not in texts and "f_exc" not in texts:
        raise InputError("forced-response needs the excitation frequency: --Omega W (rad/s, "
                         "rpm) or --f-exc F (Hz)")
    dampings = [n for n in _DAMPINGS if n in texts]
    if len(dampings) > 1:
        raise InputError(f"give the damping as one of --zeta, --c and --Q, not "
                         f"{len(dampings)}: got {_shown(dampings, labels)}")
    if "k" in texts and "omega" in texts:
        raise InputError("give the natural frequency as --k and --m or as --omega, not both")
    if "k" not in texts and "omega" not in texts:
        raise InputError("forced-response needs the natural frequency: --k K --m M, or "
                         "--omega OMEGA_N (with --m M for the amplitude of a force or an "
                         "unbalance)")
    if "k" in texts and "m" not in texts:
        raise InputError("--k needs --m: together they give the natural frequency sqrt(k/m)")
    if "c" in texts and "m" not in texts:
        raise InputError("--c needs --m: zeta = c / (2 m omega)")
    if "unbalance" in texts and "m" not in texts:
        raise InputError("--unbalance needs --m (the whole machine's mass): X = (m_u e / m) V")
    if ("x0" in texts or "v0" in texts) and "t" not in texts:
        raise InputError("--x0 and --v0 give the total response at a time: give --t TIME too")


def compute(inputs: ForcedInputs) -> Result:
    """Run the scene forward, or solve it for its unknown when a result is given."""
    from .natural_frequency import compute_scene

    from ..scenes.forced import OSCILLATOR

    result = compute_scene(inputs.scene, inputs.texts, labels=inputs.labels,
                           rtol=inputs.rtol, strict=inputs.strict, command="forced-response")
    _coordinate_entries(result)
    kind = next((_KINDS[n] for n in _EXCITATIONS if n in inputs.texts), None)
    if inputs.scene is OSCILLATOR and kind is not None:
        from .forced_slips import forced_slips

        values = {name: entry.si for name, entry in result.results.items()
                  if isinstance(entry.si, float)}
        for name, slips in forced_slips(values, kind).items():
            result.slips.setdefault(name, {}).update(slips)
    return result


#: For a scene driven on an angle: the results that are angles, moments, inertias.
_ROTATION = {"X": "ANGLE", "X_res": "ANGLE", "X_peak": "ANGLE", "x": "ANGLE",
             "F_T": "TORQUE", "m_eff": "INERTIA", "k_eff": "TORSIONAL_STIFFNESS"}
_ROTATION_WORDS = {"X": "steady amplitude of {s}", "X_res": "steady amplitude of {s} at "
                   "Omega = omega", "X_peak": "largest steady amplitude of {s} over Omega",
                   "x": "total {s} at time t", "F_T": "amplitude of the moment on the support",
                   "m_eff": "effective moment of inertia in {s}",
                   "k_eff": "effective torsional stiffness in {s}"}


def _coordinate_entries(result: Result) -> None:
    """A scene driven on its coordinate (:mod:`dyncalc.scenes.sdof`): the coordinate named
    in ``extra`` and in the amplitudes' descriptions; for an angle, the amplitudes in rad, the
    force on the support a moment, ``m_eff`` and ``k_eff`` rotational."""
    from ..scenes.sdof import COORDINATES

    coordinate = COORDINATES.get(result.scene)
    if coordinate is None or "m_eff" not in result.results:
        return
    from .. import units
    from ..result.entries import Entry

    result.extra["coordinate"] = {"name": coordinate.symbol, "is": coordinate.what,
                                  "F0": coordinate.drive,
                                  "kind": "angle" if coordinate.rotation else "displacement"}
    sym = coordinate.symbol
    for name, entry in list(result.results.items()):
        if name not in _ROTATION:
            continue
        if coordinate.rotation:
            dim = getattr(units, _ROTATION[name])
            unit = dim.si.replace("**", "^")
            words = _ROTATION_WORDS[name].format(s=sym)
            result.results[name] = Entry(name, entry.si, dim, unit=unit, symbol=entry.symbol,
                                         description=words)
        elif name in ("X", "X_res", "X_peak", "x", "m_eff", "k_eff"):
            entry.description = f"{entry.description} ({sym}: {coordinate.what})"


def forced_response(options: dict[str, str | None], words=(), *, scene: str | None = None,
                    rtol: float | None = None, strict: bool = False) -> Result:
    """The command: the options as typed (``{"k": "40 kN/m", "F0": "100 N", ...}``) and
    ``NAME=QUANTITY`` words -> the Result (:func:`read`, then :func:`compute`).

    >>> r = forced_response({"k": "40 kN/m", "m": "40kg", "zeta": "0.05", "F0": "100N",
    ...                      "Omega": "1500rpm"})
    >>> round(r.results["TR"].si, 6), round(r.results["X"].si * 1e6, 3)  # X in micrometres
    (0.047154, 105.578)
    """
    return compute(read(options, words, scene=scene, rtol=rtol, strict=strict))


#: The columns a batch block may give the adapter (the oscillator's parameters).
_COLUMN_NAMES = frozenset(_PARAMETERS)
#: Parameters that may be negative (an initial condition); every other must be positive.
_SIGNED = ("x0", "v0")


def columns(given: dict, settings: dict):
    """The results of a block of batch rows, or ``None`` when not handled here (a scene, a
    result given to solve from, a form the one-off refuses). Undamped blocks carry the
    one-off's warning that the resonance results are unbounded on every row.

    ``given`` maps the columns of the block (the record's input names: ``k``, ``m``,
    ``zeta``, ``F0``, ``Omega``, ...) to float64 SI arrays; ``settings`` holds ``scene``.
    Without a scene, for the forms :func:`read` accepts (no result given to solve from), the
    columns go through :func:`dyncalc.physics.forced_columns.forced_columns`, the one-off's
    float operations on whole arrays with its exact roundings reproduced (bit for bit); the
    rows it leaves go through :func:`dyncalc.physics.forced.forced_response` on plain SI
    floats (no parsing, no pint, no Result), the very function the one-off calls. A row is
    exact when every input is finite and positive (``x0``, ``v0`` finite), it raises
    nothing and every result is finite and non-zero.
    A result that exists on some rows only (``isolation``, ``bandwidth``, the peak) is NaN
    on the others: the batch splits a block by the results its rows have
    (``Columns.optional``). Damped rows beyond the peak's or the bandwidth's limits are the
    kernel's too, each with the one-off's warning (``Columns.row_warnings``, its values in
    the text); the rows the kernel leaves are taken here only where the one-off warns
    nothing.
    """
    from ..lazy import numpy as np
    from ..physics.columns import Columns
    from ..physics.forced_columns import forced_columns

    keys = set(given)
    if settings.get("scene") is not None or not keys or keys - _COLUMN_NAMES:
        return None
    try:
        _check_forms(dict.fromkeys(keys, ""), {k: _flag(k) for k in keys})
    except InputError:
        return None
    arrays = {name: np.asarray(value, dtype=float) for name, value in given.items()}
    n = len(next(iter(arrays.values())))
    kernel = forced_columns(arrays, with_warnings=True)
    values, exact, notes = kernel if kernel is not None else (
        {}, np.zeros(n, dtype=bool), None)
    names = dict.fromkeys(name for name in values if name != "isolation"
                          or not np.all(np.isnan(values[name])))
    rows = {}
    for i in np.flatnonzero(~exact).tolist():
        row = _one_row({name: float(array[i]) for name, array in arrays.items()})
        if row is not None:
            rows[i] = row
            names.update(dict.fromkeys(row))
    order = [name for name in _RESULT_ORDER if name in names]
    out = {name: np.array(values[name]) if name in values else np.full(n, math.nan)
           for name in order}
    for i, row in rows.items():
        for name in order:
            out[name][i] = row.get(name, math.nan)
    exact = exact.copy()
    exact[list(rows)] = True
    if keys & set(_DAMPINGS):  # each row's warnings: the kernel's (none on the rows above)
        return Columns(out, exact=exact, model="linear", method="closed-form", optional=True,
                       row_warnings=notes)
    from ..physics.forced import UNDAMPED_WARNING  # undamped: every row the kernel answers warns

    return Columns(out, exact=exact, model="linear", method="closed-form", optional=True,
                   warnings=(UNDAMPED_WARNING,), warned=np.ones(n, dtype=bool))


def _one_row(row: dict) -> dict | None:
    """One row through :func:`dyncalc.physics.forced.forced_response` on SI floats (the rows
    the column kernel leaves: outside its domain, a rounding it could not certify, a form it
    does not take); ``None`` where the one-off would refuse, warn or give a value that is not
    finite and non-zero."""
    from ..errors import PhysicsError
    from ..physics.forced import forced_response as physics

    if not all(math.isfinite(v) and (v > 0.0 or name in _SIGNED) for name, v in row.items()):
        return None
    try:
        out = physics(**row)
    except (InputError, PhysicsError, ArithmeticError, ValueError):
        return None
    values = out.values
    if out.warnings or not all(isinstance(v, float) and math.isfinite(v) and v != 0.0
                               for v in values.values()):
        return None
    return values


def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    return forced_response({p.name: values.get(p.name) for p in COMMAND.inputs}, words,
                           scene=values.get("scene"), rtol=rtol, strict=strict)


def _scene_choices():
    from ..scenes.forced import forced_scene_names

    return forced_scene_names()


COMMAND = Command(
    "forced-response",
    "Steady and total response to harmonic excitation: X, phase, TR, resonance, isolation.",
    """Steady amplitude X, phase lag phi, magnification V, transmissibility TR, the force on
    the support F_T, resonance (X_res, peak, exact half-power bandwidth), isolation, and with
    --x0/--v0/--t the total response x, of a mass-spring-damper driven harmonically.

    Give the natural frequency (--k and --m, or --omega with --m where the amplitude needs
    it), the damping (--zeta, --c or --Q; default undamped), exactly one excitation (--F0,
    --base, --base-accel, --unbalance) and its frequency (--Omega or --f-exc). A result given
    as NAME=QUANTITY with one parameter left out (or NAME=?) is solved for it. Assumes linear
    viscous damping and the steady state reached after about 4/(zeta omega).

    \b
    Examples:
      dyncalc forced-response --k 40kN/m --m 40kg --zeta 0.05 --F0 100N --Omega 1500rpm
      dyncalc forced-response --omega 10rad/s --zeta 0.1 --base 5mm --f-exc 3Hz
      dyncalc forced-response --k 2MN/m --m 200kg --zeta 0.1 --unbalance "0.05 kg*m" \\
          --Omega 3000rpm
      dyncalc forced-response TR=0.1 --zeta 0.05 --Omega 1500rpm --m 40kg k=?
      dyncalc forced-response --k 100N/m --m 1kg --F0 1N --Omega 10rad/s --x0 0 --v0 0 \\
          --t 3s                                   # undamped resonance: grows linearly
      dyncalc forced-response --omega 10rad/s --zeta 0.1 --base 5mm --f-exc 3Hz \\
          --plot response.png
      dyncalc forced-response --scene quarter-car k=40kN/m m=400kg L=10m U0=2cm \\
          v0=20m/s --zeta 0.2                      # E5.23 with damping
    """,
    (
        Parameter("scene", None, "A forced set-up with its own parameters as NAME=QUANTITY "
                  "words (quarter-car, frame-brace-damper, mass-spring-given-response, "
                  "rolling-wheel-moving-ground).", "NAME", kind="setting",
                  choices=_scene_choices),
        Parameter("k", STIFFNESS, "Stiffness, e.g. '40 kN/m' (with --m).", "K"),
        Parameter("m", MASS, "Mass, e.g. 40kg (for unbalance: the whole machine's).", "M"),
        Parameter("omega", ANGULAR_RATE, "Natural angular frequency instead of --k and --m, "
                  "e.g. '10 rad/s'.", "OMEGA_N"),
        Parameter("zeta", DIMENSIONLESS, "Damping ratio (default 0: undamped).", "Z"),
        Parameter("c", DAMPING, "Viscous damping coefficient, e.g. '200 N*s/m'.", "C"),
        Parameter("Q", DIMENSIONLESS, "Quality factor Q = 1/(2 zeta).", "Q"),
        Parameter("F0", FORCE, "Force amplitude: F0 cos(Omega t) on the mass.", "FORCE"),
        Parameter("base", LENGTH, "Support displacement amplitude u0 (through spring and "
                  "damper).", "U0"),
        Parameter("base_accel", ACCELERATION, "Ground acceleration amplitude B0 (X is then "
                  "relative to the ground).", "B0"),
        Parameter("unbalance", UNBALANCE, "Rotating unbalance m_u e, e.g. '0.01 kg*m' (force "
                  "m_u e Omega^2).", "ME"),
        Parameter("Omega", ANGULAR_RATE, "Excitation angular frequency, e.g. 1500rpm or "
                  "'157 rad/s'.", "W"),
        Parameter("f_exc", CYCLE_RATE, "Excitation frequency in Hz (instead of --Omega).",
                  "F"),
        Parameter("x0", LENGTH, "Initial displacement for the total response (with --t).",
                  "X0"),
        Parameter("v0", VELOCITY, "Initial velocity for the total response (with --t).",
                  "V0"),
        Parameter("t", TIME, "Time of the total response x (transient plus steady state).",
                  "TIME"),
        Parameter("plot", None, "Draw the magnification and phase against Omega/omega (log "
                  "axes, the operating point marked; with --t also the time history of x) "
                  "into FILE (.png, .svg or .pdf); needs matplotlib (the plot extra).",
                  "FILE.png", kind="after"),
    ),
    (
        ResultName("omega", "ω", ANGULAR_RATE.si, "natural angular frequency"),
        ResultName("zeta", "ζ", "", "damping ratio"),
        ResultName("eta", "η", "", "frequency ratio Omega/omega"),
        ResultName("X", "X", LENGTH.si, "steady amplitude (relative to the ground for "
                                        "--base-accel)"),
        ResultName("phi", "φ", "rad", "phase lag behind the excitation, 0 to pi"),
        ResultName("V", "V", "", "magnification"),
        ResultName("TR", "TR", "", "transmissibility"),
        ResultName("F_T", "F_T", FORCE.si, "amplitude of the force on the support"),
        ResultName("Z", "Z", LENGTH.si, "amplitude of the spring's deflection (base "
                                        "excitation)"),
        ResultName("X_res", "X_res", LENGTH.si, "steady amplitude at Omega = omega"),
        ResultName("V_res", "V_res", "", "magnification at Omega = omega"),
        ResultName("Omega_peak", "Ω_peak", ANGULAR_RATE.si, "excitation frequency of the "
                                                             "largest amplitude"),
        ResultName("X_peak", "X_peak", LENGTH.si, "largest steady amplitude over Omega"),
        ResultName("V_peak", "V_peak", "", "largest magnification over Omega"),
        ResultName("Omega_iso", "Ω_iso", ANGULAR_RATE.si, "above it TR < 1"),
        ResultName("isolation", "I", "", "1 - TR, when TR < 1"),
        ResultName("bandwidth", "Δω", ANGULAR_RATE.si, "exact half-power bandwidth"),
        ResultName("Q", "Q", "", "quality factor 1/(2 zeta)"),
        ResultName("x", "x", LENGTH.si, "total displacement at --t"),
    ),
    _run,
    words="[NAME=QUANTITY]...",
    columns=columns,
)

#: The results in the order the one-off gives them (the record's order).
_RESULT_ORDER = tuple(r.name for r in COMMAND.results)
