"""Column kernel of ``inertia`` for placed and turned bodies: each body at ``at=`` (a column of
positions), its own axes turned by a word (``along=x``, ``-y``, ...: a signed permutation),
composites with holes, and the moment about any axis (``--axis``: a direction, perhaps through
a point); bit for bit
:func:`dyncalc.commands.inertia.compute` on each row.

.. math:: J_{C,i} = R_i \\operatorname{diag}(J_{xx}, J_{yy}, J_{zz})_i R_i^T, \\qquad
          J_{O,i} = J_{C,i} + m_i (|c_i|^2 I - c_i c_i^T),

    m = \\sum s_i m_i, \\quad r_c = \\sum s_i m_i c_i / m, \\quad
    J_C = J_O - m (|r_c|^2 I - r_c r_c^T), \\quad J_{axis} = n^T (J_C + m (|d|^2 I
    - d d^T)) n, \\ d = r_c - p.

Bit for bit because every step is the one-off's in the same order: a rotation by a signed
permutation has one non-zero term in each sum (exact whatever the order, signed zeros too),
``|c|^2`` and ``n^T J n`` are :func:`~dyncalc.physics.inertia_tensor.squared_norm` and
:func:`~dyncalc.physics.inertia_tensor.quadratic_form` in both, the sums over
bodies run left to right from 0, and ``eigh``/``eigvalsh`` on the stack are one LAPACK call
per matrix, as the one-off's. The principal axes follow the rule of
:func:`~dyncalc.physics.inertia_tensor.principal`: a unit vector with its largest component
positive; where moments are equal the rows are exact only when ``eigh`` gives signed world
axes (else the rule's Gram-Schmidt could round otherwise: the generic path answers).

Parameters: ``bodies``, each ``(kind, sign, m, dims, at, frame)``: ``m`` (kg) and ``dims``
(m) arrays, ``at`` an ``(n, 3)`` array (m) or ``None`` (the origin), ``frame`` the body's
own axes (a 3x3 signed permutation, :func:`~dyncalc.physics.inertia_tensor.body_frame`);
``axis`` the ``(unit direction, point)`` of ``--axis`` (as
:func:`~dyncalc.commands.inertia_read.read_axis` reads them: the same on every row) for
``J_axis`` or ``None``.

Example::

    >>> rod = ("rod", 1.0, np.array([3.0]), {"l": np.array([2.0])},
    ...        np.array([[1.0, 0.0, 0.0]]), np.array([[0.0, 0, 1], [1, 0, 0], [0, 1, 0]]))
    >>> z = (np.array([0.0, 0.0, 1.0]), np.zeros(3))
    >>> placed_composite([rod], axis=z).values["J_axis"].tolist()   # m l^2 / 3 about its end
    [4.0]

Reference: Gross et al., Engineering Mechanics 3, Section 3.2.3 and Example 3.41.
"""
from __future__ import annotations

from ..lazy import numpy as np
from .columns import Columns
from .inertia import principal_local, reference_offset
from .inertia_tensor import DEGENERATE, quadratic_form, squared_norm

__all__ = ["placed_composite", "is_signed_permutation"]


def is_signed_permutation(frame) -> bool:
    """Whether ``frame`` has one +-1 and two zeros in each row and column."""
    a = np.abs(np.asarray(frame, dtype=float))
    unit = (a == 1.0) | (a == 0.0)
    return bool(unit.all() and ((a == 1.0).sum(axis=0) == 1).all()
                and ((a == 1.0).sum(axis=1) == 1).all())


def _turned(frame, local, n):
    """``frame diag(local) frame^T`` for every row: ``(n, 3, 3)``."""
    J = np.zeros((n, 3, 3))
    for i in range(3):
        for j in range(3):
            total = 0.0
            for k in range(3):
                total = total + (frame[i, k] * local[k]) * frame[j, k]
            J[:, i, j] = total
    return J


def _steiner(m, d):
    """``m (|d|^2 I - d d^T)`` for every row (the one-off's
    :func:`~dyncalc.physics.inertia_tensor.steiner`, elementwise)."""
    s = squared_norm(d)
    n = len(m)
    term = np.empty((n, 3, 3))
    for i in range(3):
        for j in range(3):
            term[:, i, j] = m * ((s * (1.0 if i == j else 0.0)) - d[:, i] * d[:, j])
    return term


def _symmetric(J):
    return (J + J.transpose(0, 2, 1)) / 2.0


#: Rows computed at a time: each row is on its own, and the kernel's two dozen ``(n, 3, 3)``
#: temporaries for a 16384-row chunk were 30 MB of the 100 MB budget (10^7 rows: 105 MB).
SLICE = 4096


def placed_composite(bodies: list, axis=None) -> Columns:
    """The results of ``inertia`` for placed, turned bodies (see the module); overflow
    marks rows not exact, never warned by numpy. Computed :data:`SLICE` rows at a time."""
    n = len(bodies[0][2])
    with np.errstate(all="ignore"):
        if n <= SLICE:
            return _placed_composite(bodies, axis)
        pieces = [_placed_composite([_rows(body, n, start, start + SLICE) for body in bodies],
                                    axis) for start in range(0, n, SLICE)]
    values = {name: np.concatenate([piece.values[name] for piece in pieces])
              for name in pieces[0].values}
    return Columns(values, np.concatenate([piece.exact for piece in pieces]),
                   model=pieces[0].model)


def _rows(body: tuple, n: int, start: int, stop: int) -> tuple:
    """A body's rows ``start:stop`` (its arrays of ``n`` rows; a frame is the same on all)."""
    kind, sign, mass, dims, at, frame = body

    def cut(value):
        value = np.asarray(value)
        return value[start:stop] if value.ndim and value.shape[0] == n else value

    return (kind, sign, cut(mass), {key: cut(value) for key, value in dims.items()},
            None if at is None else cut(at), frame)


def _placed_composite(bodies: list, axis) -> Columns:
    n = len(bodies[0][2])
    m = 0.0
    moment = 0.0
    J_O = 0.0
    finite = np.ones(n, dtype=bool)
    scale = 0.0
    for kind, sign, mass, dims, at, frame in bodies:
        frame = np.asarray(frame, dtype=float)
        local = [np.broadcast_to(np.asarray(v, dtype=float), (n,))
                 for v in principal_local(kind, mass, dims)]
        J_C = _symmetric(_turned(frame, local, n))
        offset = [np.broadcast_to(np.asarray(v, dtype=float), (n,))
                  for v in reference_offset(kind, dims)]
        c = np.zeros((n, 3)) if at is None else np.asarray(at, dtype=float)
        turned = np.empty((n, 3))
        for i in range(3):
            total = 0.0
            for k in range(3):
                total = total + frame[i, k] * offset[k]
            turned[:, i] = total
        c = c + turned
        signed = float(sign)
        body_m = signed * mass
        body_J_O = signed * (J_C + _steiner(mass, c))
        finite &= np.isfinite(body_m) & np.isfinite(body_J_O).all(axis=(1, 2))
        m = m + body_m
        moment = moment + body_m[:, None] * c
        J_O = J_O + body_J_O
        trace = (body_J_O[:, 0, 0] + body_J_O[:, 1, 1]) + body_J_O[:, 2, 2]
        scale = scale + np.abs(trace)
    exact = finite & np.isfinite(m) & (m > 0.0)
    safe_m = np.where(exact, m, 1.0)
    r_c = moment / safe_m[:, None]
    J_O = _symmetric(J_O)
    J_C = _symmetric(J_O - _steiner(safe_m, r_c))
    exact &= (np.isfinite(r_c).all(axis=1) & np.isfinite(J_O).all(axis=(1, 2))
              & np.isfinite(J_C).all(axis=(1, 2)))
    work = J_C.copy()
    work[~exact] = np.eye(3)  # rows left to the generic path: any matrix eigh takes
    scale = 1e-9 * scale
    checked = np.linalg.eigvalsh(work)
    exact &= ~(checked[:, 0] < -scale) & ~(checked[:, 0] + checked[:, 1]
                                           < checked[:, 2] - scale)
    moments, vectors = np.linalg.eigh(work)
    axes = _principal_axes(moments, vectors, exact)
    values = {"m": m + 0.0, "r_c": r_c + 0.0, "J_O": J_O + 0.0, "J_C": J_C + 0.0}
    clipped = np.maximum(moments, 0.0)
    for k in range(3):
        values[f"J_{k + 1}"] = np.ascontiguousarray(clipped[:, k])
    for k in range(3):
        values[f"axis_{k + 1}"] = np.ascontiguousarray(axes[:, k, :])
    if axis is not None:
        # n^T (J_C + m (|d|^2 I - d d^T)) n with d = r_c - p: the one-off's moment_about
        direction, point = axis
        J = quadratic_form(direction, J_C + _steiner(safe_m, r_c - point))
        exact &= np.isfinite(J) & (J > 0.0)   # a zero moment: the one-off's signed zero
        values["J_axis"] = J
        values["radius_of_gyration"] = np.sqrt(np.where(exact, J, 1.0) / safe_m)
    exact &= np.all([np.isfinite(v).reshape(n, -1).all(axis=1) for v in values.values()],
                    axis=0)
    return Columns(values, exact, model=bodies[0][0] if len(bodies) == 1 else "composite")


def _principal_axes(moments, vectors, exact):
    """The axes of :func:`~dyncalc.physics.inertia_tensor.principal` (``(n, 3, 3)``, axis
    ``k`` in ``[:, k, :]``); rows with equal moments whose eigenvectors are not signed world
    axes are marked not exact (in place)."""
    tol = DEGENERATE * np.maximum((np.abs(moments[:, 0]) + np.abs(moments[:, 1]))
                                  + np.abs(moments[:, 2]), np.finfo(float).tiny)
    g01 = moments[:, 1] - moments[:, 0] <= tol
    g02 = g01 & (moments[:, 2] - moments[:, 0] <= tol)
    g12 = ~g01 & (moments[:, 2] - moments[:, 1] <= tol)
    degenerate = g01 | g12
    unit = (np.abs(vectors) == 1.0) | (vectors == 0.0)
    world_axes = unit.all(axis=(1, 2)) & ((np.abs(vectors) == 1.0).sum(axis=1) == 1).all(axis=1)
    exact &= ~degenerate | world_axes
    axes = vectors.transpose(0, 2, 1).copy()
    if degenerate.any():
        world = np.argmax(np.abs(vectors), axis=1)  # (n, 3): the world axis of moment k
        order = world.copy()
        sort01 = g01 & ~g02
        order[sort01, :2] = np.sort(world[sort01, :2], axis=1)
        order[g12, 1:] = np.sort(world[g12, 1:], axis=1)
        order[g02] = np.sort(world[g02], axis=1)
        rows = np.flatnonzero(degenerate)
        axes[rows] = 0.0
        for k in range(3):
            axes[rows, k, order[rows, k]] = 1.0
    # _signed: the largest component (the first, on a tie to 1e-12) positive; -0.0 made 0.0
    size = np.abs(axes)
    first = np.argmax(size >= size.max(axis=2, keepdims=True) * (1.0 - 1e-12), axis=2)
    lead = np.take_along_axis(axes, first[:, :, None], axis=2)[:, :, 0]
    axes = np.where((lead > 0.0)[:, :, None], axes, -axes) + 0.0
    return axes
