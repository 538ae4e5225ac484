"""Derivatives of the ``coriolis`` results for the propagation of uncertainties (exact: the
formulas are closed).
"""
from __future__ import annotations

import math
from typing import Any, Callable

from ..lazy import numpy as np
from ..result.entries import Result
from .coriolis_read import CoriolisInputs
from .coriolis_terms import _horizontal, _mag

#
# Only scalars carry an uncertainty (a vector cannot: parse_vector reads none), so the
# uncertain inputs are the magnitudes of the scalar form, --mass and, on the Earth, --latitude,
# --omega (the rate), --speed, --heading and --vertical. Their slopes are worked out by hand on
# the values as read; nothing is parsed or computed again.

#: How an input moves (dOmega, dv_r, dm, side; ``None`` = not at all): the mass only scales
#: F_c; an input that moves neither Omega nor v_r nor m (no slope).
_MASS = (None, None, 1.0, 0)
_STILL = (None, None, 0.0, 0)


def _sensitivity(inputs: CoriolisInputs, result: Result, slopes: Callable[[str], dict]):
    """The :class:`~dyncalc.result.propagate.Sensitivity` of ``result``: its uncertain inputs
    in the order read, named by their options (``omega``, ``vr``, ``latitude`` ...), and
    ``slopes(name)`` (result name -> d result / d input, SI) for each with ``u > 0``."""
    from ..result.propagate import Sensitivity, UncertainInput

    names = [name for name, entry in inputs.entries.items() if entry.uncertainty is not None]
    uncertain = [UncertainInput(name, float(inputs.parsed[name].si),
                                float(inputs.parsed[name].uncertainty)) for name in names]
    table: dict[str, dict[int, Any]] = {name: {} for name in result.results}
    with np.errstate(all="ignore"):  # an overflow is a non-finite slope: refused there
        for index, name in enumerate(names):
            if uncertain[index].sigma == 0:
                continue
            row = slopes(name)
            for key, entry in result.results.items():
                table[key][index] = row.get(key, np.zeros(np.shape(entry.si)))
    return Sensitivity(uncertain, table)


def _scalar_slopes(name: str, Om: float, v: float, r: float, al: float, m: float | None,
                   a_c: float) -> dict[str, float]:
    """Slopes of the scalar form with respect to the magnitude ``name``: ``a_c = 2 Omega v_r``,
    ``F_c = m a_c``, ``a_euler = alpha r``, ``a_centripetal = Omega^2 r`` and
    ``a_transport = r H``, ``H = hypot(alpha, Omega^2)``.

    Parameters: ``Om`` (rad/s), ``v`` (m/s), ``r`` (m), ``al`` (rad/s^2), ``m`` (kg, ``None``
    without --mass), ``a_c`` (m/s^2, as computed). All are >= 0; where ``H = 0``
    (``alpha = Omega = 0``) ``a_transport`` has a corner and the slope is the one-sided one
    (the inputs cannot go below 0): ``r`` for alpha, 0 for Omega.
    """
    H = math.hypot(al, Om * Om)
    if name == "omega":
        row = {"a_c": 2.0 * v, "a_centripetal": 2.0 * Om * r,
               "a_transport": 2.0 * r * Om * (Om * Om / H) if H > 0 else 0.0}
    elif name == "vr":
        row = {"a_c": 2.0 * Om}
    elif name == "r":
        row = {"a_euler": al, "a_centripetal": Om * Om, "a_transport": H}
    elif name == "alpha":
        row = {"a_euler": r, "a_transport": r * (al / H) if H > 0 else r}
    else:  # mass
        return {"F_c": a_c}
    if m is not None and "a_c" in row:
        row["F_c"] = m * row["a_c"]
    return row



def _frame_slopes(fa, m: float | None, move: tuple, v_transport=None,
                  v_abs=None) -> dict[str, Any]:
    """Slopes of every result of the vector formula for an input that moves ``Omega`` by
    ``dOm`` and ``v_r`` by ``dv`` (per SI unit of the input) and the mass ``m`` (kg) by
    ``dm``; ``r``, ``alpha``, ``a0``, ``a_r`` are vectors and carry no uncertainty:

    ``da_c = 2 (dOm x v_r + Omega x dv)``, ``da_centripetal = dOm x (Omega x r) +
    Omega x (dOm x r)`` (= ``da_transport``), ``da = da_transport + da_c``,
    ``dv_transport = dOm x r``, ``dv = dv_transport + dv``,
    ``dF_c = -(m da_c + dm a_c)``, ``d coriolis_parameter = 2 dOm_z``; a magnitude by
    :func:`_norm_slope`.
    """
    dOm, dv, dm, side = (np.zeros(3) if x is None else x for x in move)
    Om, v, r = fa.Omega, fa.v_r, fa.r
    da_c = 2.0 * (np.cross(dOm, v) + np.cross(Om, dv))
    da_cent = np.cross(dOm, np.cross(Om, r)) + np.cross(Om, np.cross(dOm, r))
    dv_t = np.cross(dOm, r)
    row = {"a_c": da_c, "a_c_mag": _norm_slope(fa.a_c, da_c, side),
           "a_euler": np.zeros(3), "a_centripetal": da_cent, "a_transport": da_cent,
           "a_transport_mag": _norm_slope(fa.a_transport, da_cent, side),
           "a": da_cent + da_c, "a_mag": _norm_slope(fa.a, da_cent + da_c, side),
           "Omega": dOm, "v_r": dv, "coriolis_parameter": 2.0 * float(dOm[2]),
           "v_transport": dv_t, "v": dv_t + dv}
    if v_transport is not None:
        row["v_transport_mag"] = _norm_slope(v_transport, dv_t, side)
    flat = _horizontal(da_c)
    row["a_c_horizontal"] = flat
    row["a_c_horizontal_mag"] = _norm_slope(_horizontal(fa.a_c), flat, side)
    if v_abs is not None:
        row["v_mag"] = _norm_slope(v_abs, dv_t + dv, side)
    if m is not None:
        dF_c = -(m * da_c + dm * fa.a_c)
        row["F_c"] = dF_c
        row["F_c_mag"] = _norm_slope(fa.F_c, dF_c, side)
        row["F_c_horizontal"] = _horizontal(dF_c)
        row["F_c_horizontal_mag"] = _norm_slope(_horizontal(fa.F_c), _horizontal(dF_c),
                                                side)
    return row


def _norm_slope(x, dx, side: int) -> float:
    """The slope of ``|x|`` when ``x`` moves by ``dx``: ``x/|x| . dx``. At ``x = 0`` ``|x|``
    has a corner: ``side |dx|`` for an input at a bound (the one-sided slope, ``side`` = +1
    at a lower bound, -1 at an upper one), 0 otherwise (the mean of the two sides)."""
    size = _mag(x)
    if size > 0:
        return float(np.dot(np.asarray(x, dtype=float) / size, dx))
    return side * _mag(dx)


