"""The vector and magnitude forms of ``coriolis``: every term of the relative-motion formula
from the inputs read by :func:`dyncalc.commands.coriolis_read.read` (:func:`_compute`, which
the Earth form shares) and the perpendicular magnitudes (:func:`_scalars`).
"""
from __future__ import annotations

from typing import Callable

from ..result.entries import Entry, Explanation, Result
from .coriolis_read import CoriolisInputs
from .coriolis_slopes import _MASS, _STILL, _frame_slopes, _scalar_slopes, _sensitivity
from .coriolis_terms import (REFERENCE, VECTOR_LATEX, _direction, _direction_line, _entry,
                             _fmt, _horizontal, _line, _mag, _scalar_latex, _side,
                             _unavailable, _vector_lines, _why_zero)

def _vectors(inputs: CoriolisInputs) -> Result:
    return _compute(inputs, inputs.si("omega"), inputs.si("vr"), model="vectors")


def _compute(inputs: CoriolisInputs, Omega, v_r, *, model: str, earth: dict | None = None,
             moves: Callable[[], dict] | None = None) -> Result:
    """Every term of the vector formula for ``Omega`` (rad/s) and ``v_r`` (m/s), 3 components
    each; ``r``, ``alpha``, ``a0``, ``ar`` and ``mass`` as read (vectors and Earth mode).
    ``moves()`` gives how each uncertain input other than the mass moves ``Omega`` and ``v_r``
    (:func:`_frame_slopes`)."""
    from ..physics.relative_motion import relative_motion

    si = inputs.si
    mass = inputs.parsed.get("mass")
    motion = relative_motion(Omega, si("r"), v_r=v_r, v0=si("v0"), alpha=si("alpha"),
                             a0=si("a0"), a_r=si("ar"), m=None if mass is None else mass.si)
    fa = motion.accel
    full = any(n in inputs.parsed for n in ("r", "alpha", "a0", "ar"))
    moving = any(n in inputs.parsed for n in ("r", "v0"))
    known = v_r is not None

    results: dict[str, Entry] = {}
    if known:
        results["a_c"] = _entry("a_c", fa.a_c, True)
        results["a_c_mag"] = _entry("a_c_mag", _mag(fa.a_c), False)
    if fa.F_c is not None:
        results["F_c"] = _entry("F_c", fa.F_c, True)
        results["F_c_mag"] = _entry("F_c_mag", _mag(fa.F_c), False)
    if full:
        for name in ("a_euler", "a_centripetal", "a_transport"):
            results[name] = _entry(name, getattr(fa, name), True)
        if known:
            results["a"] = _entry("a", fa.a, True)
            results["a_mag"] = _entry("a_mag", _mag(fa.a), False)
        results["a_transport_mag"] = _entry("a_transport_mag", _mag(fa.a_transport), False)
    if moving:
        results["v_transport"] = _entry("v_transport", motion.v_transport, True)
        results["v_transport_mag"] = _entry("v_transport_mag",
                                            motion.mags["v_transport_mag"], False)
        if known:
            results["v"] = _entry("v", motion.v, True)
            results["v_mag"] = _entry("v_mag", motion.mags["v_mag"], False)

    substituted = []
    assumptions = []
    extra = {}
    if earth is None:
        substituted.append(f"Omega = {_fmt(fa.Omega, 'rad/s')}"
                           + (f", v_r = {_fmt(fa.v_r, 'm/s')}" if known else "")
                           + (f", r = {_fmt(fa.r, 'm')}" if "r" in fa.given else ""))
        assumptions.append("a rigid frame turning with Omega (and alpha) whose origin "
                           "accelerates with a0; r, v_r and a_r are measured in the frame; all "
                           "vectors are components in the frame's axes at this instant (SI)")
    else:
        results["Omega"] = _entry("Omega", fa.Omega, True)
        if earth["derived_v"]:
            results["v_r"] = _entry("v_r", fa.v_r, True)
        results["coriolis_parameter"] = _entry("coriolis_parameter", 2.0 * float(fa.Omega[2]),
                                               False)
        for name, vector in (("a_c", fa.a_c), ("F_c", fa.F_c)):
            if vector is not None:
                flat = _horizontal(vector)
                results[name + "_horizontal"] = _entry(name + "_horizontal", flat, True)
                results[name + "_horizontal_mag"] = _entry(name + "_horizontal_mag",
                                                           _mag(flat), False)
        substituted += earth["lines"]
        assumptions += earth["assumptions"]
    substituted += _vector_lines(fa, full, None if mass is None else mass.si,
                                 motion if moving else None, known)
    assumptions.append("a_c = 2 Omega x v_r is the Coriolis term of the absolute acceleration; "
                       "an observer in the frame sees the Coriolis force F_c = -m a_c, opposite "
                       "to a_c")
    if earth is not None:
        force = -fa.a_c + 0.0
        latitude = inputs.parsed.get("latitude")
        radians = latitude is not None and (latitude.assumed_si or latitude.unit_text.strip()
                                            in ("rad", "radian", "radians"))
        substituted.append(_direction_line("a_c", fa.a_c, "m/s^2", radians))
        if fa.F_c is None:
            line = _direction_line("the Coriolis force F_c = -m a_c", force, "N/kg", radians)
        else:
            line = _direction_line("the Coriolis force F_c = -m a_c", fa.F_c, "N", radians)
        substituted.append(line + _side(fa.v_r, force))
        extra = {"frame": "east-north-up",
                 "directions": {"a_c": _direction(fa.a_c), "F_c": _direction(force)}}
    explanation = Explanation(
        formula=["a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r",
                 "a_transport = a0 + alpha x r + Omega x (Omega x r), a_c = 2 Omega x v_r, "
                 "F_c = -m a_c"] + (["v = v_transport + v_r, v_transport = v0 + Omega x r"]
                                    if moving else []),
        substituted=substituted, assumptions=assumptions, reference=REFERENCE,
        latex=list(VECTOR_LATEX))
    result = Result(command="coriolis", results=results, inputs=dict(inputs.entries),
                    model=model, method="closed-form",
                    warnings=list(earth["warnings"] if earth else []) + fa.warnings,
                    explanation=explanation, extra=extra)
    result.unavailable = _unavailable(results, set(inputs.parsed) | (
        {"vr"} if known else set()))
    m = None if mass is None else float(mass.si)

    def slopes_of():
        found = {} if moves is None else moves()
        return lambda name: _frame_slopes(fa, m, found.get(name, _MASS if name == "mass"
                                                            else _STILL),
                                          motion.v_transport, motion.v)

    result.sensitivity = lambda: _sensitivity(inputs, result, slopes_of())
    return result



def _scalars(inputs: CoriolisInputs) -> Result:
    from ..physics.frames import relative_acceleration

    mass = inputs.parsed.get("mass")
    Om, v = inputs.si("omega"), inputs.si("vr")
    r, al = inputs.si("r"), inputs.si("alpha")
    # perpendicular vectors: Omega and alpha along z, r radial along x, v_r along y
    fa = relative_acceleration([0.0, 0.0, Om], [0.0, v, 0.0],
                               r=None if r is None else [r, 0.0, 0.0],
                               alpha=None if al is None else [0.0, 0.0, al],
                               m=None if mass is None else mass.si)
    full = r is not None or al is not None

    results = {"a_c": _entry("a_c", _mag(fa.a_c), False)}
    if fa.F_c is not None:
        results["F_c"] = _entry("F_c", _mag(fa.F_c), False)
    if full:
        for name in ("a_euler", "a_centripetal", "a_transport"):
            results[name] = _entry(name, _mag(getattr(fa, name)), False)

    def why(term):
        return _why_zero(term, fa, "scalar")

    lines = [_line("a_c", f"2 Omega v_r = 2 x {_fmt(Om, 'rad/s')} x {_fmt(v, 'm/s')}",
                   results["a_c"].si, "m/s^2", why("a_c"))]
    if full:
        rr = 0.0 if r is None else r
        aa = 0.0 if al is None else al
        lines += [
            _line("a_euler", f"alpha r = {_fmt(aa, 'rad/s^2')} x {_fmt(rr, 'm')}",
                  results["a_euler"].si, "m/s^2", why("a_euler")),
            _line("a_centripetal", f"Omega^2 r = ({_fmt(Om, 'rad/s')})^2 x {_fmt(rr, 'm')}",
                  results["a_centripetal"].si, "m/s^2", why("a_centripetal")),
            f"a_transport = sqrt((alpha r)^2 + (Omega^2 r)^2) = "
            f"{_fmt(results['a_transport'].si, 'm/s^2')} (the two are perpendicular; a0 = 0)",
            "a (absolute): not computed in the scalar form: the direction of v_r relative to r "
            "is not known; give vectors",
        ]
    else:
        lines.append("a0, alpha x r, Omega x (Omega x r), a_r: not computed (give --r and "
                     "--alpha for the transport terms, or vectors for the absolute "
                     "acceleration)")
    if fa.F_c is not None:
        lines.append(f"F_c = m a_c = {_fmt(mass.si, 'kg')} x {_fmt(results['a_c'].si, 'm/s^2')}"
                     f" = {_fmt(results['F_c'].si, 'N')} (directed opposite to a_c)")
    latex, latex_substituted, _text = _scalar_latex(results, Om, v, r, al, mass)
    explanation = Explanation(
        latex=latex, latex_substituted=latex_substituted,
        formula=["|a_c| = 2 Omega v_r (Omega perpendicular to v_r)",
                 "|alpha x r| = alpha r, |Omega x (Omega x r)| = Omega^2 r (r perpendicular to "
                 "the axis), |F_c| = m |a_c|"],
        substituted=lines,
        assumptions=["scalars are magnitudes of perpendicular vectors: v_r perpendicular to "
                     "Omega; --r is the distance from the rotation axis and --alpha turns about "
                     "the same axis; for other angles give vectors (3 components)",
                     "a_c = 2 Omega x v_r is the Coriolis term of the absolute acceleration; "
                     "the Coriolis force F_c = -m a_c is opposite to it"],
        reference=REFERENCE)
    result = Result(command="coriolis", results=results, inputs=dict(inputs.entries),
                    model="magnitudes (perpendicular vectors)", method="closed-form",
                    warnings=list(fa.warnings), explanation=explanation)
    m = None if mass is None else float(mass.si)
    result.sensitivity = lambda: _sensitivity(
        inputs, result, lambda name: _scalar_slopes(name, Om, v, r or 0.0, al or 0.0, m,
                                                    results["a_c"].si))
    return result


