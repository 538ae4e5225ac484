"""Whole columns of ``coriolis`` batch rows at once (:func:`columns`), bit for bit the
one-off's values.
"""
from __future__ import annotations

from ..lazy import numpy as np


def columns(given: dict, settings: dict):
    """The results of a block of batch rows at once, or ``None`` when not vectorised here.

    ``given`` maps the columns the block gives (the record's input names: ``omega``, ``vr``,
    ``r``, ``v0``, ``alpha``, ``a0``, ``ar``, ``mass``) to SI arrays, ``(n, 3)`` for
    vectors and ``(n,)`` for magnitudes and the mass; ``settings`` is not used. The vector
    form and the magnitudes form are vectorised through the kernel of
    :func:`~dyncalc.physics.frames.relative_acceleration` (the velocities through that of
    :func:`~dyncalc.physics.relative_motion.transport_velocity`), magnitudes by the twin of
    ``math.hypot`` (:func:`~dyncalc.physics.numerics_arrays.hypot_rows`); the Earth form
    (``latitude``, ``speed``, ...) by :func:`~dyncalc.commands.coriolis_earth_columns.
    earth_columns`; mixed or missing inputs give ``None``. Exact where the
    one-off gives these values with no warning and no refusal (a term or magnitude beyond
    float64, an underflow to zero, a negative magnitude).
    """
    from ..physics.columns import Columns
    from ..physics.frames import relative_acceleration
    from ..physics.numerics_arrays import hypot_rows

    keys = set(given)
    if "latitude" in keys:
        from .coriolis_earth_columns import earth_columns

        return earth_columns(given, settings)
    if ("omega" not in keys or not keys & {"vr", "r", "v0"}
            or keys - {"omega", "vr", "r", "v0", "alpha", "a0", "ar", "mass"}):
        return None
    arrays = {name: np.asarray(value, dtype=float) for name, value in given.items()}
    vectors = arrays["omega"].ndim == 2
    if not vectors and ("vr" not in keys or "v0" in keys):
        return None
    shapes = {name: value.ndim for name, value in arrays.items() if name != "mass"}
    if set(shapes.values()) != {2 if vectors else 1} or arrays.get("mass", np.ones(1)).ndim != 1:
        return None
    mass = arrays.get("mass")
    ok = np.ones(len(arrays["omega"]), dtype=bool)
    for value in arrays.values():
        ok &= np.isfinite(value) if value.ndim == 1 else np.all(np.isfinite(value), axis=1)
    if mass is not None:
        ok &= mass > 0.0

    def magnitude(vector):
        value, fine = hypot_rows(vector[:, 0], vector[:, 1], vector[:, 2])
        nonlocal ok
        ok &= fine & np.isfinite(value)
        return value + 0.0

    if vectors:
        from .coriolis_frame_columns import frame_values

        values, exact = frame_values(arrays, arrays["omega"], arrays.get("vr"), magnitude)
        return Columns(values, exact=exact & ok, model="vectors")
    if keys & {"a0", "ar"}:
        return None
    for value in arrays.values():
        ok &= value >= 0.0
    zero = np.zeros(len(ok))

    def along(axis: int, value):
        vector = np.zeros((len(ok), 3))
        vector[:, axis] = value
        return vector

    r, alpha = arrays.get("r"), arrays.get("alpha")
    out = relative_acceleration.columns(
        np.stack([zero, zero, arrays["omega"]], axis=1), along(1, arrays["vr"]),
        r=None if r is None else along(0, r), alpha=None if alpha is None else along(2, alpha),
        m=mass)
    terms = out.values
    values = {"a_c": magnitude(terms["a_c"])}
    if mass is not None:
        values["F_c"] = magnitude(terms["F_c"])
    if r is not None or alpha is not None:
        for name in ("a_euler", "a_centripetal", "a_transport"):
            values[name] = magnitude(terms[name])
    return Columns(values, exact=out.exact & ok, model="magnitudes (perpendicular vectors)")

