"""Spring networks and the stiffness of standard elastic elements.

Pure functions on pint quantities; the arithmetic is done in SI floats by the careful kernels of
:mod:`dyncalc.physics.numerics`, and every result ends in an explicit SI unit.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Examples 5.11, 5.19 and 5.26.
"""
from __future__ import annotations

import math

from ..units import Q_
from ..units import AREA, FORCE, LENGTH, MODULUS, RIGIDITY, SECOND_MOMENT, TORSIONAL_RIGIDITY
from .face import check_units, magnitude
from .columns import Columns, column_kernel
from .numerics import monomial, parallel_sum, series_sum

__all__ = [
    "series_stiffness", "parallel_stiffness", "cantilever_stiffness", "midspan_stiffness",
    "beam_stiffness", "axial_stiffness", "torsion_bar_stiffness", "coil_spring_stiffness",
]




def _common_unit(stiffnesses):
    """The unit to add the elements in: the first element's, so that elements typed in one
    unit give an exact answer in it (200 and 300 lbf/in give 120 lbf/in, not 120.00000000000006
    after a round trip through N/m); SI if converting into it would overflow an element."""
    unit = stiffnesses[0].units
    magnitudes = [float(k.to(unit).magnitude) for k in stiffnesses]
    if all(math.isfinite(m) or not math.isfinite(k.magnitude)
           for m, k in zip(magnitudes, stiffnesses)):
        return unit, magnitudes
    si = "N/m" if stiffnesses[0].check("[force]/[length]") else "N*m/rad"
    return si, [float(k.to(si).magnitude) for k in stiffnesses]


def series_stiffness(stiffnesses):
    """Equivalent stiffness of elements in series.

    .. math:: \\frac{1}{k_{eq}} = \\sum_i \\frac{1}{k_i}

    Parameters
    ----------
    stiffnesses : sequence of Quantity
        Each ``[force]/[length]`` (or each ``[force]*[length]/[angle]``), positive; ``inf`` is a
        rigid link and adds nothing.

    Returns
    -------
    k_eq : Quantity
        In the unit of the first element (SI if that would overflow). At most the smallest
        element.

    Notes
    -----
    Computed as ``k_min / sum(k_min / k_i)`` with exact residuals (:func:`series_sum`): no
    overflow or underflow on the way, within 1 ulp.

    Examples
    --------
    >>> series_stiffness([Q_(200, "N/m"), Q_(300, "N/m")])
    <Quantity(120.0, 'newton / meter')>
    """
    unit, magnitudes = _common_unit(stiffnesses)
    return Q_(series_sum(magnitudes), unit)


def parallel_stiffness(stiffnesses):
    """Equivalent stiffness of elements in parallel.

    .. math:: k_{eq} = \\sum_i k_i

    Parameters and units as :func:`series_stiffness`. The sum is correctly rounded
    (``math.fsum``); it is ``inf`` if an element is rigid or the sum overflows (the caller tells
    the two apart).

    >>> parallel_stiffness([Q_(200, "N/m"), Q_(0.3, "N/mm")])
    <Quantity(500.0, 'newton / meter')>
    >>> parallel_stiffness([Q_(0.5, "lbf/in"), Q_(0.25, "lbf/in")])
    <Quantity(0.75, 'force_pound / inch')>
    """
    unit, magnitudes = _common_unit(stiffnesses)
    return Q_(parallel_sum(magnitudes), unit)


def _stiffness_rows(stiffnesses):
    from ..lazy import numpy as np

    k = np.asarray(stiffnesses, dtype=float)
    if k.ndim != 2 or k.shape[1] == 0:
        raise ValueError(f"the columns of stiffnesses are a 2-D array (rows x elements); got "
                         f"shape {k.shape}")
    return k, np.all(k > 0.0, axis=1)


@column_kernel(series_stiffness)
def _series_columns(stiffnesses) -> Columns:
    """:func:`series_stiffness` on columns: ``stiffnesses`` is a float array (rows x elements)
    in one SI unit (N/m, or N*m/rad for torsional elements); ``k_eq`` in it, bit for bit
    :func:`~dyncalc.physics.numerics.series_sum`
    (:func:`~dyncalc.physics.numerics_arrays.series_sum_rows`). Exact on rows of positive
    elements (``inf``, a rigid link, included), as the one-off computes in SI when the
    elements were given in it."""
    from .numerics_arrays import series_sum_rows

    k, positive = _stiffness_rows(stiffnesses)
    k_eq, ok = series_sum_rows(k)
    return Columns({"k_eq": k_eq}, exact=positive & ok, model="series")


@column_kernel(parallel_stiffness)
def _parallel_columns(stiffnesses) -> Columns:
    """:func:`parallel_stiffness` on columns, as :func:`_series_columns`: ``k_eq`` is the
    row's fsum (:func:`~dyncalc.physics.numerics_arrays.parallel_sum_rows`), ``inf`` where an
    element is rigid or the sum overflows, as the one-off gives it."""
    from .numerics_arrays import parallel_sum_rows

    k, positive = _stiffness_rows(stiffnesses)
    k_eq, ok = parallel_sum_rows(k)
    return Columns({"k_eq": k_eq}, exact=positive & ok, model="parallel")


def _rigidity(name: str, unit: str, product, factors) -> list[tuple[float, int]]:
    """The factors of a rigidity given either as the product (``EI``) or as its two factors
    (``E`` and ``I``), so that ``E * I`` is never formed where it could overflow."""
    if product is not None:
        return [(magnitude(product, unit), 1)]
    if any(f is None for f, _u in factors):
        raise TypeError(f"give {name} or both of its factors")
    return [(magnitude(f, u), 1) for f, u in factors]


@check_units(l=LENGTH, EI=RIGIDITY, E=MODULUS, I=SECOND_MOMENT)
def beam_stiffness(c, l, *, EI=None, E=None, I=None):  # noqa: E741 (the textbook's symbol)
    """Stiffness of a beam at its load point from a beam table.

    .. math:: k = c \\frac{E I}{l^3}

    Parameters
    ----------
    c : float
        The table's coefficient (3 for a cantilever tip, 48 for a simply supported midspan).
    l : Quantity
        Span ``[length]``.
    EI : Quantity, optional
        Bending stiffness ``[force]*[length]^2``; or give
    E, I : Quantity, optional
        Young's modulus ``[force]/[length]^2`` and second moment of area ``[length]^4``.

    Returns
    -------
    k : Quantity in N/m

    Notes
    -----
    Euler-Bernoulli beam, small deflections, massless.

    Examples
    --------
    Example 5.19 of [1] (a beam of stiffness ``EI/a^3``, so ``c = 1``):

    >>> beam_stiffness(1, Q_(1, "m"), EI=Q_(2e4, "N*m^2"))
    <Quantity(20000.0, 'newton / meter')>
    """
    factors = _rigidity("EI", "N*m**2", EI, [(E, "Pa"), (I, "m**4")])
    return Q_(monomial(float(c), factors + [(magnitude(l, "m"), -3)]), "N/m")


@check_units(l=LENGTH, EI=RIGIDITY, E=MODULUS, I=SECOND_MOMENT)
def cantilever_stiffness(l, *, EI=None, E=None, I=None):  # noqa: E741
    """Tip stiffness of a cantilever under a tip load: ``3 EI / l^3`` (see :func:`beam_stiffness`).

    >>> cantilever_stiffness(Q_(2, "m"), E=Q_(200, "GPa"), I=Q_(1e-6, "m^4"))
    <Quantity(75000.0, 'newton / meter')>
    """
    return beam_stiffness(3.0, l, EI=EI, E=E, I=I)


@check_units(l=LENGTH, EI=RIGIDITY, E=MODULUS, I=SECOND_MOMENT)
def midspan_stiffness(l, *, EI=None, E=None, I=None):  # noqa: E741
    """Midspan stiffness of a simply supported beam under a central load: ``48 EI / l^3``.

    Example 5.11 of [1] uses the span ``2l``: ``48 EI / (2l)^3 = 6 EI / l^3``.

    >>> midspan_stiffness(Q_(2, "m"), EI=Q_(8e4, "N*m^2"))
    <Quantity(480000.0, 'newton / meter')>
    """
    return beam_stiffness(48.0, l, EI=EI, E=E, I=I)


@check_units(l=LENGTH, EA=FORCE, E=MODULUS, A=AREA)
def axial_stiffness(l, *, EA=None, E=None, A=None):
    """Axial stiffness of a bar.

    .. math:: k = \\frac{E A}{l}

    Parameters
    ----------
    l : Quantity
        Length ``[length]``.
    EA : Quantity, optional
        Axial rigidity ``[force]``; or give
    E, A : Quantity, optional
        Young's modulus ``[force]/[length]^2`` and cross-section area ``[length]^2``.

    >>> axial_stiffness(Q_(2, "m"), E=Q_(200, "GPa"), A=Q_(1, "cm^2"))
    <Quantity(10000000.0, 'newton / meter')>
    """
    factors = _rigidity("EA", "N", EA, [(E, "Pa"), (A, "m**2")])
    return Q_(monomial(1.0, factors + [(magnitude(l, "m"), -1)]), "N/m")


@check_units(l=LENGTH, GJ_t=TORSIONAL_RIGIDITY, G=MODULUS, J_t=SECOND_MOMENT)
def torsion_bar_stiffness(l, *, GJ_t=None, G=None, J_t=None):
    """Torsional stiffness of a bar.

    .. math:: k_t = \\frac{G J_t}{l}

    Parameters
    ----------
    l : Quantity
        Length ``[length]``.
    GJ_t : Quantity, optional
        Torsional rigidity ``[force]*[length]^2``; or give
    G, J_t : Quantity, optional
        Shear modulus ``[force]/[length]^2`` and torsion constant ``[length]^4`` (for a round
        bar the polar area moment ``pi d^4 / 32``).

    Returns
    -------
    kt : Quantity in N*m/rad

    >>> torsion_bar_stiffness(Q_(0.5, "m"), G=Q_(80, "GPa"), J_t=Q_(1e-8, "m^4"))
    <Quantity(1600.0, 'newton * meter / radian')>
    """
    factors = _rigidity("GJ_t", "N*m**2", GJ_t, [(G, "Pa"), (J_t, "m**4")])
    return Q_(monomial(1.0, factors + [(magnitude(l, "m"), -1)]), "N*m/rad")


@check_units(G=MODULUS, d=LENGTH, D=LENGTH)
def coil_spring_stiffness(G, d, D, n):
    """Stiffness of a helical coil spring.

    .. math:: k = \\frac{G d^4}{8 D^3 n}

    Parameters
    ----------
    G : Quantity
        Shear modulus of the wire ``[force]/[length]^2``.
    d : Quantity
        Wire diameter ``[length]``.
    D : Quantity
        Mean coil diameter ``[length]``.
    n : float
        Number of active turns (need not be whole).

    Notes
    -----
    Close-coiled spring (small helix angle, ``D >> d``); the Wahl correction is not applied.

    >>> coil_spring_stiffness(Q_(80, "GPa"), Q_(2, "mm"), Q_(20, "mm"), 10)
    <Quantity(2000.0, 'newton / meter')>
    """
    factors = [(magnitude(G, "Pa"), 1), (magnitude(d, "m"), 4), (magnitude(D, "m"), -3),
               (float(n), -1)]
    return Q_(monomial(0.125, factors), "N/m")
