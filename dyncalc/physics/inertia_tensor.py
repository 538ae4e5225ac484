"""Inertia tensors placed, turned and summed: the rotation of a body's own axes, the
parallel-axis theorem, composites with holes, principal moments and axes, the moment about
any axis.

Sign convention (the book's, Gross et al. E3.41: ``J_xi_zeta = -m l^2/3`` for the bent bar):
the tensor carries the products of inertia with a minus sign,

.. math:: J = \\begin{pmatrix} \\int (y^2 + z^2)\\,dm & -\\int x y\\,dm & -\\int x z\\,dm \\\\
          \\cdot & \\int (x^2 + z^2)\\,dm & -\\int y z\\,dm \\\\
          \\cdot & \\cdot & \\int (x^2 + y^2)\\,dm \\end{pmatrix},

so that the angular momentum is ``L = J omega`` and the moment about the unit axis ``n`` is
``n^T J n``. Parallel-axis theorem (Steiner): ``J_O = J_C + m (|c|^2 I - c c^T)``.

Numbers are SI floats and numpy arrays (kg, m, kg*m^2).

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Sections 3.2.3 and 3.3.2, Example 3.41.
"""
from __future__ import annotations

import math

from ..errors import InputError, PhysicsError
from ..lazy import numpy as np
from .inertia import principal_local, reference_offset

__all__ = ["PlacedBody", "Composite", "body_frame", "steiner", "placed", "composite",
           "principal", "moment_about", "DEGENERATE", "unit_vector", "squared_norm",
           "quadratic_form"]

_OVERFLOW = ("a mass, centre or moment of inertia overflows float64 (beyond 1.8e308 in kg, m, "
             "kg*m^2): give the bodies sizes and positions that keep them in range")

#: Two principal moments closer than this fraction of the trace are taken as equal (their
#: axes are then chosen by the rule of :func:`principal`).
DEGENERATE = 1e-12


def unit_vector(v, message: str):
    """``v / |v|``, scaled by its largest component first (no overflow for 1e300, no
    underflow for 1e-320); InputError ``message`` for a zero vector."""
    v = np.asarray(v, dtype=float)
    largest = float(np.max(np.abs(v)))
    if not largest > 0.0 or not np.all(np.isfinite(v)):
        raise InputError(message)
    v = v / largest
    return v / float(np.linalg.norm(v))


def body_frame(along):
    """The rotation whose columns are the body's own axes ``x, y, z`` in the world's: ``z``
    along the unit vector of ``along``; ``x`` the projection, onto the plane normal to it, of
    the world axis that follows ``along``'s largest component in the cycle x -> y -> z -> x
    (the first largest, when two are equal); ``y = z x x``. ``along = z`` gives the identity,
    ``along = x`` the cycle (y, z, x), ``along = y`` (z, x, y).

    >>> body_frame([1.0, 0.0, 0.0]).tolist()
    [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    """
    u = unit_vector(along, "along= has zero length")
    largest = int(np.argmax(np.abs(u)))
    w = np.zeros(3)
    w[(largest + 1) % 3] = 1.0
    x = w - float(w @ u) * u
    x = x / float(np.linalg.norm(x))
    y = np.cross(u, x)
    return np.column_stack([x, y, u])


def steiner(m: float, d):
    """The parallel-axis term ``m (|d|^2 I - d d^T)``: what a tensor about the centre of mass
    gains about a point ``-d`` from it (``d`` the centre's position from that point).

    >>> steiner(2.0, [0.0, 0.0, 1.0]).tolist()
    [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 0.0]]
    """
    d = np.asarray(d, dtype=float)
    return m * (float(squared_norm(d)) * np.eye(3) - np.outer(d, d))


def squared_norm(d):
    """``|d|^2 = (d_x^2 + d_y^2) + d_z^2`` over the last axis, in this order (not BLAS's
    ``d @ d``, whose order and fused multiply-adds depend on the processor): the one-off and
    the column kernel (:mod:`.inertia_placed_columns`) share it, so they agree bit for bit.

    >>> float(squared_norm(np.array([1.0, 2.0, 2.0])))
    9.0
    """
    return (d[..., 0] * d[..., 0] + d[..., 1] * d[..., 1]) + d[..., 2] * d[..., 2]


class PlacedBody:
    """One body in the world: its signed mass ``m`` (negative for a hole), centre of mass
    ``c``, its tensor ``J_C`` about its centre and ``J_O`` about the origin (world axes, signed
    as the mass), the rotation ``frame`` of its own axes and its ``steiner`` term."""

    __slots__ = ("kind", "m", "c", "J_C", "J_O", "frame", "steiner")

    def __init__(self, kind, m, c, J_C, J_O, frame, steiner_term):
        self.kind, self.m, self.c, self.J_C, self.J_O = kind, m, c, J_C, J_O
        self.frame, self.steiner = frame, steiner_term


def placed(kind: str, m: float, dims: dict[str, float], at=(0.0, 0.0, 0.0),
           along=(0.0, 0.0, 1.0), sign: int = 1) -> PlacedBody:
    """Body ``kind`` of mass ``m`` (kg) and dimensions ``dims`` (m), its reference point at
    ``at`` (m), its own ``z`` along ``along``; ``sign = -1`` cuts it out (a hole).

    .. math:: J_C = R\\, \\operatorname{diag}(J_{xx}, J_{yy}, J_{zz})\\, R^T, \\qquad
              J_O = J_C + m (|c|^2 I - c c^T)

    >>> body = placed("rod", 3.0, {"l": 2.0}, at=(1.0, 0.0, 0.0), along=(1.0, 0.0, 0.0))
    >>> body.J_O.round(12).tolist()   # the rod about its end: m l^2/3 = 4 about y and z
    [[0.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0]]
    """
    frame = body_frame(along)
    local = np.diag(principal_local(kind, m, dims))
    c = np.asarray(at, dtype=float) + frame @ np.asarray(reference_offset(kind, dims))
    J_C = frame @ local @ frame.T
    J_C = (J_C + J_C.T) / 2.0
    term = steiner(m, c)
    signed = float(sign)
    return PlacedBody(kind, signed * m, c, signed * J_C, signed * (J_C + term), frame,
                      signed * term)


class Composite:
    """A composite's mass ``m``, centre of mass ``r_c``, tensors ``J_O`` (about the origin)
    and ``J_C`` (about ``r_c``)."""

    __slots__ = ("m", "r_c", "J_O", "J_C")

    def __init__(self, m, r_c, J_O, J_C):
        self.m, self.r_c, self.J_O, self.J_C = m, r_c, J_O, J_C


def composite(bodies: list[PlacedBody]) -> Composite:
    """The sum of placed bodies (holes signed negative):
    ``m = sum m_i``, ``r_c = sum m_i c_i / m``, ``J_O = sum J_O,i``,
    ``J_C = J_O - m (|r_c|^2 I - r_c r_c^T)``.

    Refuses (InputError) a total mass that is not positive and a ``J_C`` that no body has:
    a negative principal moment, or ``J_1 + J_2 < J_3`` (for any body
    ``J_1 + J_2 - J_3 = 2 int x_3^2 dm >= 0``): the holes cut more than there is.

    >>> disk = placed("disk", 4.0, {"r": 1.0})
    >>> hole = placed("disk", 1.0, {"r": 0.5}, sign=-1)
    >>> float(composite([disk, hole]).J_C[2, 2])   # 4/2 - 1 (1/4)/2
    1.875
    """
    m = sum(b.m for b in bodies)
    if not all(math.isfinite(b.m) and np.all(np.isfinite(b.J_O)) for b in bodies) \
            or not math.isfinite(m):
        raise PhysicsError(_OVERFLOW)
    if m == 0.0 and all(b.m >= 0.0 for b in bodies):
        raise PhysicsError("the total mass underflows to zero (below 5e-324 kg): give the "
                           "bodies larger masses or densities")
    if not m > 0.0:
        raise InputError(f"the negative bodies weigh as much as the others or more: the total "
                         f"mass is {m:.6g} kg; a hole cannot be larger than what it cuts")
    moment = sum(b.m * b.c for b in bodies)
    r_c = moment / m
    J_O = sum(b.J_O for b in bodies)
    J_O = (J_O + J_O.T) / 2.0
    J_C = J_O - steiner(m, r_c)
    J_C = (J_C + J_C.T) / 2.0
    if not (np.all(np.isfinite(r_c)) and np.all(np.isfinite(J_O)) and np.all(np.isfinite(J_C))):
        raise PhysicsError(_OVERFLOW)
    moments = np.linalg.eigvalsh(J_C)
    # rounding of the sums: a fraction of the largest terms added or taken away
    scale = 1e-9 * sum(abs(float(np.trace(b.J_O))) for b in bodies)
    if moments[0] < -scale:
        raise InputError(f"the negative bodies cut more than there is: the inertia tensor "
                         f"about the centre of mass is not positive semi-definite (smallest "
                         f"principal moment {moments[0]:.6g} kg*m^2)")
    if moments[0] + moments[1] < moments[2] - scale:
        raise InputError(f"the negative bodies cut more than there is: the principal moments "
                         f"{moments[0]:.6g}, {moments[1]:.6g}, {moments[2]:.6g} kg*m^2 break "
                         "J_1 + J_2 >= J_3, which every body keeps")
    return Composite(m, r_c, J_O, J_C)


def principal(J):
    """Principal moments (ascending) and axes of a symmetric tensor (numpy.linalg.eigh).

    Axes convention: each axis is a unit vector whose component of largest magnitude is
    positive (the first such, when two are equal to 1e-12). Where two or three moments are
    equal (to 1e-12 of the trace) the axes of that plane are the projections of the world
    axes x, y, z, in that order, orthonormalised (so a disk along z gives x, y, z).

    >>> moments, axes = principal([[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]])
    >>> moments.tolist(), axes.tolist()
    ([1.0, 2.0, 3.0], [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    """
    J = np.asarray(J, dtype=float)
    moments, vectors = np.linalg.eigh(J)
    axes = vectors.T.copy()
    tol = DEGENERATE * max(float(np.sum(np.abs(moments))), np.finfo(float).tiny)
    i = 0
    while i < 3:
        j = i + 1
        while j < 3 and moments[j] - moments[i] <= tol:
            j += 1
        if j - i > 1:
            axes[i:j] = _plane_basis(axes[i:j], j - i)
        i = j
    for k in range(3):
        axes[k] = _signed(axes[k])
    return moments, axes


def _plane_basis(vectors, count: int):
    """``count`` orthonormal vectors spanning the same space as ``vectors``: the world axes
    x, y, z projected onto it, in order, Gram-Schmidt (those that project to nearly nothing
    skipped)."""
    projector = vectors.T @ vectors
    basis: list = []
    for e in np.eye(3):
        v = projector @ e
        for b in basis:
            v = v - float(b @ v) * b
        norm = float(np.linalg.norm(v))
        if norm > 1e-6:
            basis.append(v / norm)
        if len(basis) == count:
            break
    return np.array(basis)


def _signed(axis):
    """``axis`` with its largest component (the first, on a tie) positive; -0.0 made 0.0."""
    size = np.abs(axis)
    first = int(np.argmax(size >= size.max() * (1.0 - 1e-12)))
    out = axis if axis[first] > 0 else -axis
    return out + 0.0


def moment_about(J_C, m: float, r_c, direction, point=(0.0, 0.0, 0.0)) -> float:
    """The moment of inertia about the axis through ``point`` along ``direction``:
    ``n^T (J_C + m (|d|^2 I - d d^T)) n`` with ``n`` the unit direction and
    ``d = r_c - point``.

    >>> moment_about([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 2.0]], 2.0, [0, 0, 0], [0, 0, 5.0],
    ...              [1.0, 0, 0])
    4.0
    """
    n = unit_vector(direction, "--axis: the axis direction has zero length")
    d = np.asarray(r_c, dtype=float) - np.asarray(point, dtype=float)
    J = np.asarray(J_C, dtype=float) + steiner(m, d)
    return float(quadratic_form(n, J))


def quadratic_form(n, J):
    """``n^T J n`` as ``v = n^T J`` (``v_j = (n_x J_xj + n_y J_yj) + n_z J_zj``), then
    ``(v_x n_x + v_y n_y) + v_z n_z``, in this order (not BLAS's, which depends on the
    processor); ``J`` one matrix or a stack ``(..., 3, 3)``, shared with the column kernel.

    >>> float(quadratic_form(np.array([0.6, 0.8, 0.0]), np.diag([1.0, 2.0, 3.0])))
    1.6400000000000001
    """
    v = [(n[0] * J[..., 0, j] + n[1] * J[..., 1, j]) + n[2] * J[..., 2, j] for j in range(3)]
    return (v[0] * n[0] + v[1] * n[1]) + v[2] * n[2]
