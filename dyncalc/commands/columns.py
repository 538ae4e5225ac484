"""What the commands' column adapters share (``columns(given, settings)`` in each command
module; :mod:`dyncalc.physics.columns` for the kernels under them).

An adapter takes the batch columns of one block of rows as SI arrays. Where a one-off computes
in the unit a value was *typed* in (a spring network adds in its first element's unit; a slope
takes its sine in degrees when typed in degrees), the SI arrays alone cannot reproduce it: the
caller names the typed units in ``settings["units"]`` (parameter key -> unit text, ``""`` or
absent for a bare number read as SI), and :func:`typed_in_si` tells whether they are SI.
"""
from __future__ import annotations

__all__ = ["typed_in_si"]


def typed_in_si(settings: dict, key: str, *si_units: str) -> bool:
    """Whether parameter ``key`` was typed in one of ``si_units`` or as a bare number
    (``settings["units"][key]`` empty). ``False`` when ``settings["units"]`` does not name
    ``key``: the unit typed is not known, so the one-off's arithmetic is not either."""
    units = settings.get("units") or {}
    if key not in units:
        return False
    unit = units[key]
    if unit is None or not str(unit).strip():
        return True
    from ..errors import InputError
    from ..units import parse_unit

    try:
        typed = parse_unit(str(unit))
        return any(typed == parse_unit(si) for si in si_units)
    except InputError:
        return False
