"""The equilibria of ``spring-coupled-pendulums`` (two pendulums of mass ``m`` and length
``l`` whose bobs a spring of stiffness ``k`` and free length ``b`` joins; ``phi1`` the
bisector, ``phi2`` half the opening, ``0 <= phi2 <= pi/2``) on arrays, for the generated
two-coordinate table (:mod:`dyncalc.scenes.eom_tables2`), written by hand because sympy's
roots are a quartic's (Cardano's formulas, useless in floats).

The static equations (``dV/dphi = 0``, divided by ``2 l``) are

.. math:: g m \\sin\\varphi_1 \\cos\\varphi_2 = 0, \\qquad
          g m \\sin\\varphi_2 \\cos\\varphi_1 + k (2 l \\sin\\varphi_2 - b) \\cos\\varphi_2 = 0

so either ``cos phi2 = 0`` (``phi2 = pi/2``, then ``cos phi1 = 0``: ``phi1 = +-pi/2``) or
``sin phi1 = 0`` (``phi1 = 0`` or ``pi``). With the spring's free length ``b = 0`` the second
then reads ``sin phi2 (g m cos phi1 + 2 k l cos phi2) = 0``: ``phi2 = 0``, or
``cos phi2 = -g m cos phi1 / (2 k l)``, in the domain only for ``phi1 = pi``:
``phi2 = acos(r)``, ``r = g m / (2 k l) <= 1`` (the spring holds the pendulums apart,
upside down). With ``b > 0`` the roots are a quartic's in ``tan(phi2/2)``: not covered here
(those rows take the one-off's numeric search).

Reference: Gross et al., *Engineering Mechanics 3*, 2nd ed., E4.16.
"""
from __future__ import annotations

import math

from ..lazy import numpy as np

__all__ = ["spring_pendulum_roots"]


def spring_pendulum_roots(b, g, k, l, m):
    """``(flat, covered)``: the equilibria in the domain ``0 <= phi2 <= pi/2`` as the two
    coordinates of each in turn (``phi1``, ``phi2``: arrays, NaN where a row has no such
    equilibrium), and ``(n,)`` True where these are all of them (``b = 0`` and ``r`` not
    NaN). Parameters in SI units (``b``, ``l`` in m; ``g`` in m/s^2; ``k`` in N/m; ``m`` in
    kg), arrays of one shape.

    >>> import numpy as np
    >>> flat, covered = spring_pendulum_roots(*(np.array([v]) for v in (0.0, 9.80665, 100.0, 1.0, 1.0)))
    >>> [round(float(v[0]), 6) for v in flat[-2:]], bool(covered[0])
    ([3.141593, 1.521743], True)
    """
    shape = np.shape(np.asarray(b) + np.asarray(g) + np.asarray(k) + np.asarray(l)
                     + np.asarray(m))
    with np.errstate(all="ignore"):
        r = g * m / (2 * k * l)
        apart = np.where(r <= 1, np.arccos(np.where(r <= 1, r, 1.0)), np.nan)
        apart_phi1 = np.where(r <= 1, math.pi, np.nan)
    half, zero, pi = (np.full(shape, v) for v in (math.pi / 2, 0.0, math.pi))
    flat = [half, half, -half, half, zero, zero, pi, zero, np.broadcast_to(apart_phi1, shape),
            np.broadcast_to(apart, shape)]
    covered = (np.asarray(b) == 0) & ~np.isnan(r)
    return flat, np.broadcast_to(covered, shape)
