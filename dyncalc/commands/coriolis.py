"""The ``coriolis`` command's computation: option texts -> checked vectors -> every term of the
relative-motion formula -> a :class:`~dyncalc.result.Result`. :func:`read` parses and checks
every option once (:class:`CoriolisInputs`), :func:`compute` works on what it read;
:func:`coriolis_result` is the two in turn. This module is the record and the dispatch; the
work is in ``coriolis_read`` (reading), ``coriolis_vectors`` (the vector and magnitude forms),
``coriolis_earth`` (``--latitude``), ``coriolis_terms`` (result kinds and the explanation's
lines), ``coriolis_slopes`` (sensitivities), ``coriolis_inverse`` (``NAME=?``),
``coriolis_columns`` (batch columns), ``coriolis_time`` (a motion given in time) and
``coriolis_scenes`` (``--scene``).

Three forms, chosen by the options given:

* **vectors** (``--omega 0,0,2rad/s --vr 3,0,0m/s``): components in the frame's axes; results
  ``a_c`` (and ``|a_c|`` as ``a_c_mag``); with ``--mass`` ``F_c = -m a_c``; when any of
  ``--r --alpha --a0 --ar`` is given, also ``a_euler = alpha x r``,
  ``a_centripetal = Omega x (Omega x r)``, ``a_transport``, the absolute ``a`` and ``a_mag``.
  Missing optional vectors are zero.
* **magnitudes** (``--omega 2rad/s --vr 3m/s``): perpendicular vectors; ``a_c = 2 Omega v_r``,
  ``F_c = m a_c``; ``--r`` is the distance from the rotation axis and ``--alpha`` turns about
  the same axis (``a_euler = alpha r``, ``a_centripetal = Omega^2 r`` and
  ``a_transport = hypot`` of the two, which are perpendicular). ``--a0`` and ``--ar`` need a
  direction and are refused; the absolute ``a`` is not given (the direction of ``v_r`` in the
  plane is not known).
* **Earth** (``--latitude``): a local east-north-up frame turning with
  ``Omega_E (0, cos phi, sin phi)``; ``--vr`` in east, north, up components, or ``--speed`` with
  ``--heading`` (compass: 0 north, 90 deg east) and ``--vertical``; ``--omega`` may only change
  the rate (a magnitude). The explanation names the directions of ``a_c`` and of the Coriolis
  force ``-m a_c``.

Uncertainties: only scalars carry one, so the uncertain inputs are the magnitudes of the scalar
form, ``--mass`` and on the Earth ``--latitude``, ``--omega``, ``--speed``, ``--heading`` and
``--vertical``. ``result.sensitivity`` gives the exact derivatives of every result with respect
to them, worked out on the values as read (``coriolis_slopes``):
nothing is parsed or computed again.
"""
from __future__ import annotations

from ..errors import InputError
from ..result.entries import Result
from .coriolis_inverse import _inverse
from .coriolis_read import OPTIONS, CoriolisInputs, read
from .coriolis_columns import columns
from .coriolis_terms import _KINDS
from .coriolis_time import TIME_KINDS
from .record import Command, Parameter, ResultName
from ..units import LENGTH, TIME

__all__ = ["COMMAND", "coriolis_result", "OPTIONS", "read", "compute", "CoriolisInputs"]


def coriolis_result(texts: dict[str, str | None], words=(), *,
                    strict: bool = False) -> Result:
    """Compute the ``coriolis`` command from the option texts (``{"omega": "0,0,2 rad/s",
    "vr": "3,0,0 m/s"}``; keys are the option names of :data:`OPTIONS`, ``None`` = not given):
    :func:`read`, then :func:`compute`.

    Raises :class:`~dyncalc.errors.InputError` with a message saying what to change.

    >>> res = coriolis_result({"omega": "2 rad/s", "vr": "3 m/s"})
    >>> res.results["a_c"].si, res.results["a_c"].unit
    (12.0, 'm/s^2')
    """
    solved = _inverse(texts, words, strict)
    if solved is not None:
        return solved
    return compute(read(texts, strict, words))


def compute(inputs: CoriolisInputs) -> Result:
    """The Result of the options read by :func:`read`, in their form (vectors, magnitudes or
    Earth), with ``sensitivity``: the exact derivatives of its results with respect to its
    uncertain inputs (:func:`~dyncalc.commands.coriolis_slopes._sensitivity`)."""
    from .coriolis_earth import _earth
    from .coriolis_vectors import _scalars, _vectors

    if inputs.form == "earth":
        return _earth(inputs)
    if inputs.form == "vectors":
        return _vectors(inputs)
    return _scalars(inputs)

# --- the command record ----------------------------------------------------------------------

_VECTOR = "VEC"
#: option -> (metavar, help) of ``dyncalc coriolis --help``, in its order
_HELP = {
    "omega": (_VECTOR, "Angular velocity of the frame: '0,0,2 rad/s' (rad/s, deg/s, rpm), or "
              "a magnitude ('2 rad/s') for perpendicular vectors; with --latitude the rotation "
              "rate only (default 7.2921159e-5 rad/s)."),
    "vr": (_VECTOR, "Velocity relative to the frame: '3,0,0 m/s' (km/h ...), or a magnitude; "
           "with --latitude east, north, up components."),
    "r": (_VECTOR, "Position in the frame (from its origin); a magnitude is the distance from "
          "the rotation axis."),
    "alpha": (_VECTOR, "Angular acceleration of the frame, e.g. '0,0,1 rad/s^2' (a magnitude: "
              "about the axis of --omega)."),
    "v0": (_VECTOR, "Velocity of the frame's origin, e.g. '1,0,0 m/s' (vectors only): adds "
           "to v_transport = v0 + Omega x r."),
    "a0": (_VECTOR, "Acceleration of the frame's origin, e.g. '1,0,0 m/s^2' (vectors only)."),
    "ar": (_VECTOR, "Acceleration relative to the frame (vectors only)."),
    "mass": ("M", "Mass: adds the Coriolis force F_c = -m a_c."),
    "latitude": ("ANGLE", "Earth mode: latitude from -90deg to 90deg (positive north); --vr "
                 "and the other vectors are then east, north, up components."),
    "speed": ("V", "Earth mode: horizontal speed (with --heading), instead of --vr."),
    "heading": ("ANGLE", "Earth mode: compass heading of --speed, 0deg = north, 90deg = "
                "east."),
    "vertical": ("V", "Earth mode: vertical speed, positive up (with or without --speed)."),
}


def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    scene = values.get("scene")
    if scene is not None:
        from .coriolis_scenes import scene_result

        return scene_result(scene, values, words, rtol=rtol, strict=strict)
    from .coriolis_time import is_time_motion

    if is_time_motion(values):
        from .coriolis_time import time_result

        times = values.get("t")
        if times is not None and "," in times:
            raise InputError("--t: a list of times gives a table, one row per time; the "
                             "command line prints it (in Python call once per time)")
        return time_result({name: values.get(name) for name in _TIME_TEXTS}, words,
                           strict=strict)
    if values.get("basis") is not None:
        raise InputError("--basis goes with a motion given in time (--t): constant vectors "
                         "are given and shown in one frame's components")
    if values.get("plot") is not None:
        raise InputError("--plot draws a motion given in time: give --r (and --omega, --R0) "
                         "as expressions in t with --t")
    return coriolis_result({name: values.get(name) for name in OPTIONS}, words,
                           strict=strict)


#: The options the time path reads (the others it refuses by name).
_TIME_TEXTS = (*OPTIONS, "R0", "t", "basis")


def _relative_scenes():
    from ..scenes.relative import relative_scene_names

    return relative_scene_names()


COMMAND = Command(
    "coriolis",
    "Coriolis acceleration and every term of relative motion.",
    """Coriolis acceleration a_c = 2 Omega x v_r and every term of the relative-motion formula
    a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r, in a machine or on Earth.

    Vectors have three components and one unit ("0,0,2 rad/s", "(0, 0, 2) rpm",
    "[1,0,0] km/h"); a component may be an expression with units ("0.5*sin(35deg), 0, 0 m/s":
    a bare component takes the trailing unit, one with its own unit is taken as it is) using
    NAME=QUANTITY parameters (--r "l*cos(30deg), l*sin(30deg), 0" l=2m). Results are in SI.

    Each result is given when its options are: a_c needs --vr; --r (or --v0) adds the
    velocities v_transport = v0 + Omega x r and, with --vr, v = v_transport + v_r; any of
    --r, --alpha, --a0, --ar adds a_euler, a_centripetal, a_transport and, with --vr, the
    absolute a; --mass adds the Coriolis force F_c = -m a_c (the apparent force). Missing
    vectors are zero; every vector has its magnitude (v_mag, a_mag, ...).

    Scalars (--omega 2rad/s --vr 3m/s) are magnitudes of perpendicular vectors: a_c = 2 Omega
    v_r and F_c = m a_c; --r is then the distance from the axis and --alpha turns about the
    same axis; --v0, --a0, --ar and the absolute a need vectors. A result given as
    NAME=QUANTITY with one unknown as NAME=? is solved for it (a_c=12m/s^2 --omega 2rad/s
    vr=?; on the Earth a_c_mag=, a_c_horizontal_mag=, heading north unless --heading).

    --latitude sets up the rotating Earth: x east, y north, z up, Omega = Omega_E (0, cos phi,
    sin phi), Omega_E the sidereal 7.2921159e-5 rad/s (the textbook's 2 pi/day is --omega
    "1 turn/day"); a_c_horizontal and F_c_horizontal are the parts that push sideways on level
    ground. --explain lists each term with its numbers, which vanish and why, and on Earth
    the directions of a_c and of the Coriolis force.

    Motion given in time: --r, --omega (rotating-frame components) and --R0 (the origin's
    position, fixed-frame components) may be expressions in t with NAME=QUANTITY parameters,
    evaluated at --t; v_r, a_r, alpha, v0, a0 are their exact derivatives (the frames
    coincide at t = 0). --basis fixed prints the vectors in the fixed frame's axes; a list of
    times in --t (or --batch over a t column) gives a table; --plot draws the path.
    --scene runs radial-slot-release or slotted-link with their NAME=QUANTITY parameters.

    \b
    Examples:
      dyncalc coriolis --omega "2 rad/s" --vr "3 m/s"
      dyncalc coriolis --omega "0,0,30 rpm" --vr "0.5,0,0 m/s" --r "0.2,0,0 m" --mass 2kg
      dyncalc coriolis --omega "0,0,2 rad/s" --r "l*cos(30deg), l*sin(30deg), 0" l=2m \\
          --vr "0.1*5*sin(35deg), 0, 0 m/s" --v0 "1,0,0 m/s"
      dyncalc coriolis --latitude 45deg --speed "100 km/h" --heading 0deg --mass 1kg --explain
      dyncalc coriolis --latitude 30deg --vr "20,0,0 m/s" --json
      dyncalc coriolis a_c_mag=0.01m/s^2 --latitude 45deg vr=?
      dyncalc coriolis --r "s0 - b*t^2/2, 0, 0 m" s0=4m b=0.5m/s^2 --omega "0,0,2 rad/s" \\
          --t 2s --basis fixed
      dyncalc coriolis --scene slotted-link d=0.4m c=0.3m theta=35deg omega=-10rad/s
    """,
    (Parameter("scene", None, "A relative-motion set-up with its own parameters as "
               "NAME=QUANTITY words (radial-slot-release, slotted-link).", "NAME",
               kind="setting", choices=_relative_scenes),
     *(Parameter(name, dim, _HELP[name][1], _HELP[name][0])
       for name, (dim, _words) in OPTIONS.items()),
     Parameter("R0", LENGTH, "Position of the frame's origin in fixed-frame components, as "
               "expressions in t: motion given in time.", _VECTOR, kind="text"),
     Parameter("t", TIME, "Time at which a motion given in time is evaluated, e.g. 2s; a "
               "list ('0, 0.5, 1 s') gives a table, one row per time.", "TIME", kind="text"),
     Parameter("basis", None, "Components of the vector results of a motion given in time: "
               "rotating (default, the frame's axes at t) or fixed.", "rotating|fixed",
               kind="setting", choices=("rotating", "fixed")),
     Parameter("plot", None, "Draw the path of the point in the fixed frame (a motion given "
               "in time) with its velocity and acceleration at --t into FILE (.png, .svg or "
               ".pdf); needs matplotlib.", "FILE.png", kind="after")),
    (*(ResultName(name, kind[2], kind[0].si, kind[-1]) for name, kind in _KINDS.items()),
     *(ResultName(name, kind[2], kind[0].si, kind[-1]) for name, kind in TIME_KINDS.items()
       if name not in _KINDS)),
    _run,
    words="[NAME=QUANTITY]...",
    columns=columns,
)
