"""The column kernel of :func:`~dyncalc.physics.relative_motion.coriolis_earth` (the scalar
Earth set-up that ``coriolis``'s inverse problems solve, ``a_c_mag=... --latitude 45deg
vr=?``), bit for bit the one-off on every row it marks exact.

.. math:: |\\mathbf a_c| = 2\\Omega_E v\\sqrt{\\sin^2\\varphi + \\cos^2\\varphi\\sin^2\\psi},
          \\quad |\\mathbf a_{c,h}| = 2\\Omega_E v|\\sin\\varphi|

computed as the one-off does: ``Omega = Omega_E (0, cos phi, sin phi)`` and
``v = v (sin psi, cos psi, 0)`` through the twins of :mod:`dyncalc.physics.earth_columns`,
``a_c = 2 Omega x v`` through the vector form's column kernel
(:func:`~dyncalc.physics.frames.relative_acceleration`), magnitudes through
:func:`~dyncalc.physics.numerics_arrays.hypot_rows` (``math.hypot``'s twin).

Reference: Gross et al., Engineering Mechanics 3, Chapter 6 (relative motion on the Earth).
"""
from __future__ import annotations

import math

from ..lazy import numpy as np
from .columns import Columns, TypedColumn

__all__ = ["coriolis_earth_columns", "degrees_of"]


def degrees_of(angle):
    """``(degrees, ok)`` of an angle column as the one-off's ``_degrees`` reads a quantity
    (``quantity.to("degree")`` in its unit): a :class:`TypedColumn` (magnitudes as typed, one
    unit a row) converted by pint one unit at a time; ``ok`` False where the degrees leave
    float64 (the one-off then reduces by turns) or a unit is not an angle's."""
    from ..units import Q_

    if not isinstance(angle, TypedColumn):
        return None
    typed = np.asarray(angle.typed, dtype=float)
    units = np.asarray(angle.unit)
    degrees = np.full(len(typed), np.nan)
    for unit in set(units.tolist()):
        rows = units == unit
        with np.errstate(all="ignore"):
            degrees[rows] = np.asarray(Q_(typed[rows], unit).to("degree").magnitude,
                                       dtype=float)
    return degrees, np.isfinite(degrees)


def coriolis_earth_columns(latitude, vr, heading=None, omega=None, mass=None, phi=None,
                           psi=None) -> Columns:
    """:func:`~dyncalc.physics.relative_motion.coriolis_earth` on columns.

    Parameters
    ----------
    latitude, heading : TypedColumn
        Angles as typed (``heading`` ``None``: north); or ``latitude`` SI (radians) with its
        degrees as the one-off reads them in ``phi``, and the heading's degrees in ``psi``
        (plain arrays: what a batch has read).
    vr : array
        Horizontal speed [length]/[time] (m/s).
    omega : array, optional
        The Earth's rate [angle]/[time] (rad/s; ``None``: the sidereal rate).
    mass : array, optional
        Mass [mass] (kg): adds ``F_c_mag`` and ``F_c_horizontal_mag``.

    Exact where ``|latitude| <= pi/2`` (the scene's constraint, on SI radians), every value is
    finite and non-zero (a zero may be an underflow the one-off warns about), and no magnitude
    needs CPython's rescaling.

    >>> out = coriolis_earth_columns(TypedColumn(np.array([math.pi / 2]),
    ...                              np.array([90.0]), np.array(["degree"])), np.array([10.0]))
    >>> out.values["a_c_mag"].tolist(), out.exact.tolist()
    ([0.00145842318], [True])
    """
    from ..constants import EARTH_RATE
    from .earth_columns import earth_angular_velocity_rows, enu_velocity_rows
    from .frames import relative_acceleration
    from .numerics_arrays import hypot_rows

    n = len(np.asarray(vr))
    if phi is not None:
        phi_deg, ok, si = np.asarray(phi, dtype=float), np.isfinite(phi), latitude
    else:
        read = degrees_of(latitude)
        if read is None:
            return None
        (phi_deg, ok), si = read, latitude.si
    if psi is not None:
        psi_deg, fine = np.asarray(psi, dtype=float), np.isfinite(psi)
    elif heading is not None:
        read = degrees_of(heading)
        if read is None:
            return None
        psi_deg, fine = read
    else:
        psi_deg, fine = np.zeros(n), np.ones(n, dtype=bool)
    v = np.asarray(vr, dtype=float)
    rate = np.full(n, EARTH_RATE) if omega is None else np.asarray(omega, dtype=float)
    ok = ok & fine & np.isfinite(v) & np.isfinite(rate)
    ok &= np.abs(np.asarray(si, dtype=float)) <= math.pi / 2
    with np.errstate(all="ignore"):
        Omega = earth_angular_velocity_rows(np.where(ok, phi_deg, 0.0), rate)
        velocity = enu_velocity_rows(v, np.where(ok, psi_deg, 0.0), np.zeros(n))
        terms = relative_acceleration.columns(Omega, velocity)
        ok &= np.asarray(terms.exact, dtype=bool)
        a_c = terms.values["a_c"]
        flat = np.stack([a_c[:, 0], a_c[:, 1], np.zeros(n)], axis=1) + 0.0

        def norm(vector):
            value, good = hypot_rows(vector[:, 0], vector[:, 1], vector[:, 2])
            nonlocal ok
            ok &= good & np.isfinite(value)
            return value + 0.0

        values = {"a_c_mag": norm(a_c), "a_c_horizontal_mag": norm(flat)}
        if mass is not None:
            m = np.asarray(mass, dtype=float)
            for name, base in (("F_c_mag", "a_c_mag"), ("F_c_horizontal_mag",
                                                       "a_c_horizontal_mag")):
                values[name] = m * values[base]
                ok &= np.isfinite(values[name])
        for value in values.values():  # a zero the one-off may call an underflow: its own
            ok &= value != 0.0
    return Columns(values, exact=ok, model="Earth, horizontal motion")


coriolis_earth_columns.typed_params = ("latitude", "heading")
