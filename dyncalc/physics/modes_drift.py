"""Column kernel of ``modes --scene pendulum-on-sliding-block``: a drift and a swing, in
closed form.

The linearised matrices about phi = 0
(:func:`dyncalc.physics.lagrange.pendulum_on_sliding_block_matrices`)

.. math:: M = \\begin{bmatrix} m_1 + m_2 & m_2 l \\\\ m_2 l & m_2 l^2 \\end{bmatrix}, \\quad
          K = \\begin{bmatrix} 0 & 0 \\\\ 0 & m_2 g l \\end{bmatrix}

have K singular: mode 1 is the rigid-body drift (``omega_1 = 0``, shape ``[1, 0]``, modal
mass ``m1 + m2``, modal stiffness 0, with the one-off's note), and ``det(K - lambda M) = 0``
gives the swing

.. math:: \\omega_2^2 = \\frac{g (m_1 + m_2)}{m_1 l}, \\quad
          \\phi_2 \\propto [-s, 1], \\quad s = \\frac{m_2 l}{m_1 + m_2}\\ \\mathrm{(m/rad)},

with modal mass ``m1 m2 l^2 / (m1 + m2)`` and stiffness ``m2 g l`` for that shape (each
divided by ``s^2`` when ``s > 1``: x is then the largest component, scaled to 1). These are
written without the cancellation of ``m2 l^2 - (m2 l)^2 / (m1 + m2)``.

The one-off solves the same matrices with LAPACK (``sygvd``), where K's zero row and column
stay exactly zero, so its drift is a rigid-body mode on every row; its other values round
otherwise, so they agree within the documented tolerance of ``modes --batch`` (1e-12), not
to the bit. A row is exact where the system is well conditioned (``m1 >= m1_share (m1 + m2)``:
M's condition number at most about 400, so that the one-off's own rounding stays far below
the tolerance), every value is a normal float far from overflow, and a shape's small
component is not within a factor 2 of the floor below which the one-off shows it as 0.

Parameters: ``m1`` (kg, the block), ``m2`` (kg, the bob), ``l`` (m, the rod), ``g`` (m/s^2),
float64 arrays; ``normalize``: ``"max"`` (largest component +1) or ``"mass"`` (unit modal
mass).

Example::

    >>> import numpy as np
    >>> out = drift_modes(np.array([3.0]), np.array([1.0]), np.array([0.5]),
    ...                   np.array([9.80665]))
    >>> out.values["mode_2"].tolist(), round(float(out.values["omega_2"][0]) ** 2, 9)
    ([[-0.125, 1.0]], 26.151066667)

Reference: Gross et al., Engineering Mechanics 3, E4.19 (a pendulum on a sliding block).
"""
from __future__ import annotations

import math

from ..lazy import numpy as np
from .columns import Columns
from .modes import _COMPONENT_FLOOR, rigid_note

__all__ = ["drift_modes", "M1_SHARE"]

#: The least share of the block in the total mass a row needs to be exact (M's condition
#: number is about 4 (m1 + m2) / m1).
M1_SHARE = 1e-2
#: Every value of an exact row lies in [TINY, HUGE] (normal floats, far from overflow).
TINY, HUGE = 1e-280, 1e280


def drift_modes(m1, m2, l, g, normalize: str = "max") -> Columns:
    """The one-off's results of every row, as :func:`~dyncalc.physics.modes_columns.
    stacked_modes` names them (see the module); ``exact`` marks the rows taken."""
    with np.errstate(all="ignore"):
        total = m1 + m2
        s = m2 * l / total                      # x per unit phi in the swing, m/rad
        omega2 = np.sqrt(g * total / (m1 * l))
        swing_mass = m1 * m2 * (l * l) / total  # shape [-s, 1]
        swing_stiffness = m2 * g * l
        x_first = s > 1.0                       # x is the largest component: [1, -1/s]
        small = np.where(x_first, 1.0 / s, s)
        mass2 = np.where(x_first, m1 * total / m2, swing_mass)
        stiffness2 = np.where(x_first, g * total * total / (m2 * l), swing_stiffness)
        floor = _COMPONENT_FLOOR
        exact = (m1 >= M1_SHARE * total) & ~((small > 0.5 * floor) & (small < 2.0 * floor))
        for value in (total, m2 * l, m2 * l * l, swing_stiffness, s, omega2, mass2,
                      stiffness2, g * total):
            exact &= (np.abs(value) >= TINY) & (np.abs(value) <= HUGE)
        shown = np.where(small < floor, 0.0, small)
        zero = np.zeros_like(m1)
        one = np.ones_like(m1)
        swing = np.stack([np.where(x_first, one, -shown), np.where(x_first, -shown, one)], -1)
        drift = np.stack([one, zero], -1)
        values = {"omega_1": zero, "omega_2": omega2, "f_1": zero,
                  "f_2": omega2 / (2.0 * math.pi)}
        if normalize == "mass":
            values.update({"mode_1": drift / np.sqrt(total)[:, None], "modal_mass_1": one,
                           "modal_stiffness_1": zero,
                           "mode_2": swing / np.sqrt(mass2)[:, None], "modal_mass_2": one,
                           "modal_stiffness_2": omega2 ** 2})
        else:
            values.update({"mode_1": drift, "modal_mass_1": total, "modal_stiffness_1": zero,
                           "mode_2": swing, "modal_mass_2": mass2,
                           "modal_stiffness_2": stiffness2})
        for value in values.values():
            exact &= np.isfinite(value).all(axis=-1) if value.ndim > 1 else np.isfinite(value)
    return Columns(values, exact, model="linear", method="eigh", warnings=(rigid_note([0]),),
                   warned=np.ones(len(exact), dtype=bool))
