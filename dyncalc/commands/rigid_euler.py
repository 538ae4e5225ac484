"""``rigid-body``'s Euler mode: reading ``--inertia-tensor``, ``--omega``, ``--alpha`` and the
Result of :func:`dyncalc.physics.euler.euler_moment`."""
from __future__ import annotations

from ..lazy import numpy as np
from ..result import Result
from ..result.entries import Entry, Explanation, format_number
from ..units import (ANGULAR_ACCELERATION, ANGULAR_MOMENTUM, ANGULAR_RATE, ENERGY, INERTIA,
                     TORQUE, parse_vector)

__all__ = ["read_euler", "euler_result"]

_VECTORS = {"omega": (ANGULAR_RATE, "angular velocity (body axes)"),
            "alpha": (ANGULAR_ACCELERATION, "angular acceleration (body axes)")}

#: Euler mode's results: dimension, symbol, words.
KINDS = {
    "M": (TORQUE, "M", "moment on the body, J alpha + omega x (J omega) (body axes)"),
    "M_mag": (TORQUE, "|M|", "magnitude of M"),
    "H": (ANGULAR_MOMENTUM, "H", "angular momentum J omega (body axes)"),
    "T": (ENERGY, "T", "kinetic energy of rotation omega.J omega/2"),
}


def read_euler(options: dict, strict: bool):
    """``({"J": (3, 3), "omega": (3,), "alpha": (3,)} SI arrays, input entries)``; the tensor
    checked (:func:`dyncalc.physics.euler.check_tensor`), each refusal naming the option or the
    entry."""
    from ..physics.euler import check_tensor
    from ..units.matrix import parse_matrix

    text = options["inertia_tensor"]
    matrix = parse_matrix(text, label="--inertia-tensor", max_order=3)
    if matrix.order != 3:
        from ..errors import InputError

        raise InputError(f"--inertia-tensor must be a 3x3 matrix (rows by ';'); got "
                         f"{matrix.order}x{matrix.order}")
    J, bare = matrix.si(lambda i, j: (INERTIA, "every entry of an inertia tensor"),
                        strict=strict)
    check_tensor(J)
    euler = {"J": J}
    entries = {"inertia_tensor": Entry("inertia_tensor", J + 0.0, INERTIA, unit=INERTIA.si,
                                       text=text, assumed_si=bare,
                                       description="inertia tensor (body axes)")}
    for name, (dim, words) in _VECTORS.items():
        typed = options.get(name)
        if typed is None:
            euler[name] = np.zeros(3)
            entries[name] = Entry(name, np.zeros(3), dim, unit=dim.si, text="0, 0, 0",
                                  description=words + " (default zero)")
            continue
        parsed = parse_vector(typed, dim, label=f"--{name}", strict=strict)
        euler[name] = np.asarray(parsed.si, dtype=float) + 0.0
        entries[name] = Entry(name, euler[name], dim, unit=parsed.unit_text or dim.si,
                              assumed_si=parsed.assumed_si, text=parsed.text,
                              description=words)
    return euler, entries


def euler_result(euler: dict, entries: dict) -> Result:
    """The Result of Euler's equations at the tensor and vectors read."""
    from ..physics.euler import euler_moment

    values = euler_moment(euler["J"], euler["omega"], euler["alpha"])
    results = {name: Entry(name, values[name], dim, unit=dim.si, symbol=symbol,
                           description=words) for name, (dim, symbol, words) in KINDS.items()}
    result = Result(command="rigid-body", results=results, inputs=entries, model="euler",
                    method="closed-form", explanation=lambda: _explain(euler, values))
    result.sensitivity = lambda: _sensitivity(euler, values)
    return result


def _show(value, unit: str) -> str:
    return f"{format_number(np.asarray(value, dtype=float) + 0.0, 6)} {unit}"


def _explain(euler: dict, values: dict) -> Explanation:
    J, w, a = euler["J"], euler["omega"], euler["alpha"]
    with np.errstate(all="ignore"):
        Ja, Jw = J @ a, J @ w
    return Explanation(
        formula=["M = J alpha + omega x (J omega)  (Euler's equations, body axes)",
                 "H = J omega,  T = omega . (J omega) / 2"],
        substituted=[f"J = {_show(J, INERTIA.si)}", f"omega = {_show(w, 'rad/s')}",
                     f"alpha = {_show(a, 'rad/s^2')}",
                     f"J alpha = {_show(Ja, 'N*m')}", f"J omega = {_show(Jw, 'kg*m^2/s')}",
                     f"omega x (J omega) = {_show(values['M'] - Ja, 'N*m')}",
                     f"M = {_show(values['M'], 'N*m')}, |M| = {_show(values['M_mag'], 'N*m')}",
                     f"T = {_show(values['T'], 'J')}"],
        assumptions=["J, omega and alpha in the same body-fixed axes, J about the centre of "
                     "mass or a fixed point of the body",
                     "products of inertia with the minus sign, J_xy = -int x y dm (as "
                     "'dyncalc inertia' gives them)"],
        reference="Euler's equations (Gross et al., Engineering Mechanics 3, Section 3.3)",
        latex=[r"\mathbf{M} = J\,\boldsymbol{\alpha} + \boldsymbol{\omega}\times"
               r"(J\,\boldsymbol{\omega})"],
        example='dyncalc rigid-body --inertia-tensor "1, 0, 0; 0, 1, 0; 0, 0, 2 kg*m^2" '
                '--omega "2, 0, 3 rad/s" gives M = (0, -6, 0) N*m')


def _sensitivity(euler: dict, values: dict):
    """No input of Euler mode carries an uncertainty (a matrix or vector cannot): nothing to
    propagate."""
    from ..result.propagate import central_differences

    return central_differences([], {}, lambda i, h: None)
