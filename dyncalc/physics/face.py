"""The one face of the physics functions: :func:`check_units` checks each quantity's dimension
on entry (in the manner of MetPy's ``check_units``), and :func:`magnitude` is the one
conversion of a checked quantity to a plain number in a known unit.

A physics function takes pint quantities (a plain number or a numpy array where a parameter
is taken in its SI unit, as the batch kernels pass them) and returns values in known units.
"""
from __future__ import annotations

import functools

from ..units.grammar import _normalise

__all__ = ["check_units", "magnitude"]


def magnitude(quantity, unit: str) -> float:
    """The magnitude of ``quantity`` in ``unit``, a float (a plain number is taken as already
    in ``unit``).

    >>> from dyncalc.units import Q_
    >>> magnitude(Q_(2, "kN/m"), "N/m"), magnitude(3.0, "kg")
    (2000.0, 3.0)
    """
    if hasattr(quantity, "units"):
        return float(quantity.to(unit).magnitude)
    return float(quantity)


def check_units(**dimensions):
    """Decorate a physics function so that each named parameter given as a quantity is
    checked against its :class:`~dyncalc.units.Dim` before the function runs (angles and the
    two kinds of rate by dyncalc's rules, not pint's): a wrong dimension raises
    :class:`~dyncalc.errors.InputError` naming the parameter,
    ``k must be a stiffness [force]/[length]; got 5 kilogram ([mass])``. Parameters given as
    plain numbers or arrays (taken in SI) and ``None`` pass as they are. The decorated
    function carries the mapping as ``dimensions``.

    >>> from dyncalc.units import Q_, STIFFNESS
    >>> @check_units(k=STIFFNESS)
    ... def doubled(k):
    ...     return 2 * k
    >>> doubled(Q_(3, "N/m"))
    <Quantity(6, 'newton / meter')>
    >>> doubled(Q_(3, "kg"))
    Traceback (most recent call last):
    ...
    dyncalc.errors.InputError: k must be a stiffness [force]/[length]; got 3 kilogram ([mass])
    """
    def decorate(function):
        code = function.__code__
        names = code.co_varnames[:code.co_argcount + code.co_kwonlyargcount]
        unknown = set(dimensions) - set(names)
        if unknown:
            raise TypeError(f"{function.__name__} has no parameter {sorted(unknown)[0]!r}")

        @functools.wraps(function)
        def checked(*args, **kwargs):
            for name, value in (*zip(names, args), *kwargs.items()):
                dim = dimensions.get(name)
                if dim is not None and hasattr(value, "units"):
                    _normalise(value, dim, name)
            return function(*args, **kwargs)

        checked.dimensions = dict(dimensions)
        return checked
    return decorate
