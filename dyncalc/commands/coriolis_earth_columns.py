"""``coriolis --latitude`` batch rows on whole columns, bit for bit the one-off
(:mod:`dyncalc.commands.coriolis_earth`): the Earth's ``Omega`` and the velocity over the
ground through the twins of :mod:`dyncalc.physics.earth_columns`, every term of the formula
through the vector form's columns, and the directions of ``a_c`` and of the Coriolis force
(the JSON ``extra``) named a column at a time.
"""
from __future__ import annotations

import json

from ..lazy import numpy as np

__all__ = ["earth_columns"]

#: The columns an Earth row may give (the others are the generic path's).
_KEYS = {"latitude", "omega", "vr", "speed", "heading", "vertical", "r", "v0", "alpha", "a0",
         "ar", "mass"}
_VECTORS = ("vr", "r", "v0", "alpha", "a0", "ar")
_SCALARS = ("latitude", "omega", "speed", "heading", "vertical", "mass")


def _degrees(key: str, si, settings: dict):
    """``(degrees, ok, bare)`` of the angle column ``key`` as the one-off reads it
    (``quantity.to("degree")`` in the unit typed); ``bare``: the column's numbers have no
    unit and are read in radians (the one-off warns where they are not zero). ``None``
    where the unit typed is not one for the whole column."""
    from ..units import Q_

    units, typed = settings.get("units") or {}, settings.get("typed") or {}
    if key not in units or key not in typed:
        return None
    unit = units[key]
    bare = unit is None or not str(unit).strip()
    if bare:
        unit = "rad"  # (the one-off's quantity of a bare angle: radians)
    from ..errors import InputError
    from ..units import parse_quantity
    from .coriolis_read import OPTIONS

    try:
        sample = parse_quantity(f"1 {unit}", OPTIONS[key][0], label=f"--{key}")
        with np.errstate(all="ignore"):
            degrees = np.asarray(Q_(np.asarray(typed[key], dtype=float), sample.quantity.units)
                                 .to("degree").magnitude, dtype=float)
    except (InputError, ValueError, TypeError, AttributeError, ArithmeticError):
        return None  # a unit the reader refuses here: the generic path says why
    return degrees, np.isfinite(degrees), bare


def earth_columns(given: dict, settings: dict):
    """The results of a block of ``--latitude`` rows (``given``: SI arrays by option name,
    ``(n, 3)`` for vectors; ``settings["units"]`` and ``settings["typed"]``: the unit and
    magnitudes typed, which the one-off's degrees come from), or ``None`` where this form
    cannot take the block (an option refused with these, a unit not known for a column).

    Exact where the one-off gives the same values: a latitude within [-90, 90] deg; a rate
    and a speed not negative, a positive mass, finite values and the vector form's own
    conditions. A latitude or heading column of bare numbers is read in radians, as the
    one-off reads it, each non-zero cell with the one-off's warning (its text from
    ``settings["cells"]``, the cells as typed: ``Columns.row_warnings``).
    """
    from ..constants import EARTH_RATE
    from ..physics.columns import Columns
    from ..physics.earth_columns import earth_angular_velocity_rows, enu_velocity_rows
    from ..physics.numerics_arrays import hypot_rows
    from .coriolis_frame_columns import frame_values

    keys = set(given)
    motion = keys & {"speed", "heading", "vertical"}
    if (keys - _KEYS or ("vr" in keys) == bool(motion)
            or ("speed" in keys) != ("heading" in keys)):
        return None
    arrays = {name: np.asarray(value, dtype=float) for name, value in given.items()}
    if any(arrays[k].ndim != 2 for k in _VECTORS if k in keys) or any(
            arrays[k].ndim != 1 for k in _SCALARS if k in keys):
        return None
    n = len(arrays["latitude"])
    ok = np.ones(n, dtype=bool)
    for value in arrays.values():
        ok &= np.isfinite(value) if value.ndim == 1 else np.all(np.isfinite(value), axis=1)
    latitude = _degrees("latitude", arrays["latitude"], settings)
    if latitude is None:
        return None
    degrees, fine, bare = latitude
    ok &= fine & (degrees >= -90.0) & (degrees <= 90.0)
    cells = settings.get("cells") or {}
    noted = []  # (warning function of a row, rows it applies to): the one-off's reading's
    if bare:
        if "latitude" not in cells:
            ok &= degrees == 0.0
        else:
            noted.append((_latitude_note(cells["latitude"], degrees), degrees != 0.0))
    rate = arrays.get("omega", np.full(n, EARTH_RATE))
    ok &= rate >= 0.0
    for name, low in (("mass", 0.0), ("speed", None)):
        if name in arrays:
            ok &= arrays[name] > 0.0 if low is not None else arrays[name] >= 0.0

    def magnitude(vector):
        value, good = hypot_rows(vector[:, 0], vector[:, 1], vector[:, 2])
        nonlocal ok
        ok &= good & np.isfinite(value)
        return value + 0.0

    with np.errstate(all="ignore"):
        omega = earth_angular_velocity_rows(np.where(ok, degrees, 0.0), rate)
        derived = "vr" not in keys
        if derived:
            heading = np.zeros(n)
            if "heading" in keys:
                read = _degrees("heading", arrays["heading"], settings)
                if read is None:
                    return None
                heading, fine, bare = read
                ok &= fine
                if bare:
                    if "heading" not in cells:
                        ok &= arrays["heading"] == 0.0
                    else:
                        noted.append((_heading_note(cells["heading"]),
                                      arrays["heading"] != 0.0))
            speed = arrays.get("speed", np.zeros(n))
            vr = enu_velocity_rows(speed, np.where(ok, heading, 0.0),
                                   arrays.get("vertical", np.zeros(n)))
        else:
            vr = arrays["vr"]
        values, exact = frame_values(arrays, omega, vr, magnitude)
        values["Omega"] = omega
        if derived:
            values["v_r"] = vr
        values["coriolis_parameter"] = 2.0 * omega[:, 2] + 0.0
        ok &= np.isfinite(values["coriolis_parameter"])
        for name in ("a_c", "F_c"):
            if name in values:
                flat = values[name].copy()
                flat[:, 2] = 0.0
                flat += 0.0
                values[name + "_horizontal"] = flat
                values[name + "_horizontal_mag"] = magnitude(flat)
    a_c = values["a_c"]
    return Columns(values, exact=exact & ok, model="Earth, east-north-up",
                   extras=lambda keep: _directions(a_c[keep]),
                   row_warnings=_notes(noted) if noted else None)


def _latitude_note(cells, degrees):
    """The bare-latitude warning of row ``i`` (its cell as typed, its degrees)."""
    from .coriolis_read import bare_latitude_warning

    return lambda i: bare_latitude_warning(cells[i], float(degrees[i]))


def _heading_note(cells):
    """The bare-heading warning of row ``i``."""
    from .coriolis_read import bare_heading_warning

    return lambda i: bare_heading_warning(cells[i])


def _notes(noted):
    """Each row's warnings (the one-off's order: the latitude's, then the heading's) of the
    rows kept, or ``None`` where none of them warns."""
    from ..physics.columns import warnings_of_rows

    warned = np.logical_or.reduce([where for _note, where in noted])

    def texts_of(i):
        return tuple(note(i) for note, where in noted if where[i])
    return lambda keep: warnings_of_rows(keep, warned, texts_of)


def _direction_texts(v) -> list[str]:
    """The JSON text of ``coriolis_terms._direction`` for each east-north-up row of ``v``:
    ``"west"``, ``"north and down"``, ``"down"`` or ``"none"``."""
    from ..physics.earth_columns import compass_sectors
    from .coriolis_terms import _COMPASS

    east, north, up = v[:, 0], v[:, 1], v[:, 2]
    flat = (east != 0.0) | (north != 0.0)
    sector = np.where(flat, compass_sectors(east, north), 16)
    vertical = np.where(up > 0.0, 1, np.where(up < 0.0, 2, 0))
    words = []
    for point in [*_COMPASS, None]:
        for side in (None, "up", "down"):
            parts = [p for p in (point, side) if p is not None]
            words.append(json.dumps(" and ".join(parts) if parts else "none"))
    table = np.array(words, dtype=object)
    return table[sector * 3 + vertical].tolist()


def _directions(a_c) -> list:
    """The parts of the JSON ``extra`` of each row: the frame and the directions of ``a_c``
    and of the Coriolis force ``-m a_c`` (the one-off names that of ``-a_c``)."""
    force = -a_c + 0.0
    return ['{"frame": "east-north-up", "directions": {"a_c": ', _direction_texts(a_c),
            ', "F_c": ', _direction_texts(force), "}}"]
