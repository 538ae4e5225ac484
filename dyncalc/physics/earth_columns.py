"""The rotating Earth's vectors on whole columns (``coriolis --latitude --batch``), bit for bit
the one-off functions of :mod:`dyncalc.physics.frames`.

* :func:`cos_sin_degrees_rows` is the twin of :func:`~dyncalc.physics.frames.cos_sin_degrees`:
  the same exact reduction to within 45 degrees of a multiple of 90, the same double-double
  pi/180, libm's ``cos`` and ``sin`` row by row (numpy's own may round differently).
* :func:`earth_angular_velocity_rows`, ``Omega = Omega_E (0, cos phi, sin phi)``, and
  :func:`enu_velocity_rows`, ``v = (v sin psi, v cos psi, w)``, as ``(n, 3)`` arrays.
* :func:`compass_sectors` the compass point (0 north ... 15 north-north-west) of an east and a
  north component, as ``coriolis`` names the directions of a_c and of the Coriolis force.

Reference: Gross et al., Engineering Mechanics 3, Chapter 6 (relative motion on the Earth).
"""
from __future__ import annotations

import math

from ..lazy import numpy as np

__all__ = ["cos_sin_degrees_rows", "earth_angular_velocity_rows", "enu_velocity_rows",
           "compass_sectors"]


def cos_sin_degrees_rows(degrees):
    """``(cos, sin)`` of angles in degrees, each a float64 array: the twin of
    :func:`~dyncalc.physics.frames.cos_sin_degrees` (exact at multiples of 90 degrees).

    Parameters: ``degrees`` (array, [angle] in degrees; finite).

    >>> c, s = cos_sin_degrees_rows(np.array([90.0, -180.0, 30.0]))
    >>> c.tolist(), s.tolist()
    ([0.0, -1.0, 0.8660254037844387], [1.0, 0.0, 0.5])
    """
    from .frames import DEG_HI, DEG_LO
    from .numerics_arrays import elementwise, two_product_array

    d = np.fmod(np.asarray(degrees, dtype=float), 360.0)
    quarter = np.round(d / 90.0)
    rest = d - 90.0 * quarter  # exact: within 45 degrees of a multiple of 90
    x, err = two_product_array(rest, DEG_HI)
    x_lo = err + rest * DEG_LO
    c0, s0 = elementwise(math.cos, x), elementwise(math.sin, x)
    c, s = c0 - s0 * x_lo, s0 + c0 * x_lo
    half = np.abs(rest) == 45.0  # sqrt(1/2) correctly rounded, the same for both
    root = math.sqrt(0.5)
    c = np.where(half, root, c)
    s = np.where(half, np.copysign(root, rest), s)
    q = np.mod(quarter, 4.0)
    cos = np.select([q == 1.0, q == 2.0, q == 3.0], [-s, -c, s], c)
    sin = np.select([q == 1.0, q == 2.0, q == 3.0], [c, -s, -c], s)
    return cos + 0.0, sin + 0.0


def earth_angular_velocity_rows(degrees, rate):
    """``Omega_E (0, cos phi, sin phi)`` (rad/s) for latitudes in degrees and rates in rad/s
    (arrays, or a float rate): the twin of
    :func:`~dyncalc.physics.frames.earth_angular_velocity`, an ``(n, 3)`` array.

    >>> earth_angular_velocity_rows(np.array([90.0]), 7.2921159e-5).tolist()
    [[0.0, 0.0, 7.2921159e-05]]
    """
    c, s = cos_sin_degrees_rows(degrees)
    w = np.broadcast_to(np.asarray(rate, dtype=float), c.shape)
    return np.stack([np.zeros_like(c), w * c, w * s], axis=1) + 0.0


def enu_velocity_rows(speed, heading_degrees, vertical):
    """``(v sin psi, v cos psi, w)`` (m/s) for speeds (m/s), compass headings in degrees and
    vertical speeds (m/s): the twin of :func:`~dyncalc.physics.frames.enu_velocity`, an
    ``(n, 3)`` array.

    >>> enu_velocity_rows(np.array([20.0]), np.array([90.0]), np.array([0.0])).tolist()
    [[20.0, 0.0, 0.0]]
    """
    c, s = cos_sin_degrees_rows(heading_degrees)
    v = np.asarray(speed, dtype=float)
    w = np.broadcast_to(np.asarray(vertical, dtype=float), v.shape)
    return np.stack([v * s, v * c, w], axis=1) + 0.0


#: Bearings within this many sixteenths of a turn of a boundary between compass points are
#: taken again through libm's ``atan2`` (numpy's may differ from it by an ulp or two).
_NEAR = 1e-6


def compass_sectors(east, north):
    """The compass point ``round(bearing / 22.5) % 16`` (0 north, 4 east, ...) of each row,
    ``bearing = degrees(atan2(east, north)) % 360`` as ``coriolis`` computes it one row at a
    time, an integer array (rows with both components zero give 0; the caller names them).

    >>> compass_sectors(np.array([1.0, 0.0, -1.0]), np.array([0.0, -1.0, 1.0])).tolist()
    [4, 8, 14]
    """
    from .numerics_arrays import elementwise

    east = np.asarray(east, dtype=float)
    north = np.asarray(north, dtype=float)
    to_degrees = 180.0 / math.pi  # math.degrees multiplies by this constant
    with np.errstate(all="ignore"):
        bearing = np.remainder(np.arctan2(east, north) * to_degrees, 360.0)
        steps = bearing / 22.5
        near = np.abs(steps - np.floor(steps) - 0.5) < _NEAR
        if near.any():
            index = np.flatnonzero(near)
            exact = elementwise(math.atan2, east[index], north[index]) * to_degrees
            bearing[index] = np.remainder(exact, 360.0)
            steps = bearing / 22.5
    return np.mod(np.round(steps), 16.0).astype(np.int64)
