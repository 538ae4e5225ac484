"""Every term of the ``coriolis`` vector formula on whole columns (:func:`frame_values`), which
the vector form's and the Earth form's batch columns share."""
from __future__ import annotations

from ..lazy import numpy as np


def frame_values(arrays: dict, omega, vr, magnitude):
    """The results of the vector formula (in the one-off's order) for the columns ``omega``
    and ``vr`` (``(n, 3)``, rad/s and m/s; ``vr`` ``None`` when not given) and the other
    vectors and the mass in ``arrays`` (SI), and the rows where they are exact;
    ``magnitude(vector)`` gives a vector's magnitude (and marks the rows it cannot give)."""
    from ..physics.frames import relative_acceleration
    from ..physics.relative_motion import transport_velocity

    keys = set(arrays)
    mass = arrays.get("mass")
    known = vr is not None
    out = relative_acceleration.columns(omega, vr if known else np.zeros_like(omega),
                                        r=arrays.get("r"), alpha=arrays.get("alpha"),
                                        a0=arrays.get("a0"), a_r=arrays.get("ar"),
                                        m=mass if known else None)
    terms = out.values
    exact = out.exact
    values = {}
    if known:
        values.update(a_c=terms["a_c"], a_c_mag=magnitude(terms["a_c"]))
        if mass is not None:
            values.update(F_c=terms["F_c"], F_c_mag=magnitude(terms["F_c"]))
    if keys & {"r", "alpha", "a0", "ar"}:
        for name in ("a_euler", "a_centripetal", "a_transport"):
            values[name] = terms[name]
        if known:
            values.update(a=terms["a"], a_mag=magnitude(terms["a"]))
        values["a_transport_mag"] = magnitude(terms["a_transport"])
    if keys & {"r", "v0"}:
        r = arrays["r"] if "r" in keys else np.zeros_like(omega)
        v_t = transport_velocity.columns(omega, r, v0=arrays.get("v0"))
        values.update(v_transport=v_t.values["v"],
                      v_transport_mag=magnitude(v_t.values["v"]))
        exact = exact & v_t.exact
        if known:
            v = transport_velocity.columns(omega, r, v0=arrays.get("v0"), v_r=vr)
            values.update(v=v.values["v"], v_mag=magnitude(v.values["v"]))
            exact = exact & v.exact
    return values, exact
