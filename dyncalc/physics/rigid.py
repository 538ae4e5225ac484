"""Natural frequencies of rigid-body set-ups: rolling bodies, drums, pulleys, compound pendulums.

Pure functions on pint quantities (plain floats for pure numbers such as ``kappa`` and ``mu``)
returning an :class:`~dyncalc.physics.outcome.Outcome`. Every formula is a ratio of sums of
products of the inputs; it is evaluated with :class:`~dyncalc.physics.numerics.Wide` numbers
(a float mantissa with a separate binary exponent), so no product or sum overflows or
underflows midway: masses of 1e200 kg on springs of 1e200 N/m give the right frequency, not
``inf/inf``. In the ordinary
range the operations and their roundings are exactly those of the naive float formula.

``kappa`` is the body's shape factor ``J_C / (m r^2)``: solid sphere 2/5, hollow sphere 2/3,
solid cylinder (disk) 1/2, hollow cylinder or hoop 1.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapters 3 to 5.
"""
from __future__ import annotations

import math

from ..errors import PhysicsError
from ..units import ACCELERATION, LENGTH, MASS, STIFFNESS, TORSIONAL_STIFFNESS
from ..lazy import numpy as np
from .columns import Columns, TypedColumn, column_kernel
from .face import check_units, magnitude
from .inertia import disk_about_axis, disk_about_parallel_axis, rod_about_end
from .numerics import Wide, finite_nonzero
from .numerics_arrays import WideArray
from .outcome import Outcome, periodic, periodic_arrays

__all__ = ["rolling_disk_spring", "rolling_in_track", "drum_block_spring", "board_on_drums",
           "clock_pendulum", "pulley_block_spring", "disk_torsion_offset_mass",
           "wheel_on_moving_beam", "angled_member", "ANGLED_MEMBER_FACTOR", "rolling_inertia",
           "drum_block_inertia", "pulley_block_inertia", "wheel_beam_inertia"]

#: ``sqrt(sqrt(65) / 14)``, correctly rounded (mpmath: 0.758864647647982349822...): the
#: angled member's ``omega / sqrt(g / l)``.
ANGLED_MEMBER_FACTOR = 0.7588646476479823


def _si(quantity, unit: str) -> Wide:
    """The magnitude in ``unit`` as a double-double (:func:`~dyncalc.physics.face.magnitude`)."""
    return Wide(magnitude(quantity, unit))


def _check_kappa(kappa: float) -> float:
    kappa = float(kappa)
    if not kappa >= 0.0 or math.isinf(kappa):
        raise PhysicsError(f"kappa = J_C/(m r^2) must be a finite number >= 0; got {kappa!r}")
    return kappa


def _outcome(omega_squared: Wide, **extra) -> Outcome:
    values = periodic(float(omega_squared.sqrt()))
    if extra:
        from ..units import Q_

        for name, (value, unit) in extra.items():
            values[name] = Q_(float(value), unit)
    return Outcome(values)


# The effective masses of the translating scenes: the kinetic energy is ``m_eff x'^2 / 2`` in
# the scene's coordinate. The frequencies below divide the stiffness by them, and
# forced-response drives the same coordinate with them (dyncalc.physics.sdof): one source.
# Each works on Wide numbers and on WideArray columns alike.

def rolling_inertia(mass, kappa):
    """``(1 + kappa) m``, a body rolling without slipping, its centre's displacement the
    coordinate (translation plus rotation at ``x'/r``)."""
    return mass + kappa * mass


def drum_block_inertia(m, M):
    """``m + M/2``: the block's displacement the coordinate, the drum (a disk) turning at
    ``x'/R``."""
    return (M + 2.0 * m) * 0.5


def pulley_block_inertia(m, M):
    """``4 m + 3 M/2``: the pulley centre's displacement ``x`` the coordinate, the block
    moving ``2x``, the pulley (a disk) rolling on its fixed strand."""
    return 4.0 * m + 1.5 * M


def wheel_beam_inertia(m, M, kappa):
    """``m (kappa m + M + kappa M)/(kappa m + M)``: the wheel centre's displacement the
    coordinate, the free beam's motion eliminated by its momentum balance
    ``M X'' = kappa m (x'' - X'')``."""
    coupled = kappa * m + M
    return m * (coupled + kappa * M) / coupled


def _kappa_allowed(kappa):
    """The rows whose ``kappa`` :func:`_check_kappa` accepts (finite, >= 0)."""
    kappa = np.asarray(kappa, dtype=float)
    return (kappa >= 0.0) & ~np.isinf(kappa)


def _columns(omega_squared: WideArray, allowed=True, **extra) -> Columns:
    """:func:`_outcome` on columns: ``omega = sqrt(omega^2)`` as :class:`Wide` takes it, the
    extra values (WideArray) as floats; rows the one-off refuses (``allowed`` False) or with a
    zero or infinite value (the one-off warns) are not exact."""
    values = periodic_arrays(omega_squared.sqrt().to_float())
    for name, value in extra.items():
        values[name] = value.to_float()
    return Columns(values, exact=allowed & finite_nonzero(values))


@check_units(k=STIFFNESS, m=MASS)
def rolling_disk_spring(k, m, kappa: float = 0.5) -> Outcome:
    """A round body rolling without slipping on level ground, held by a spring at its centre.

    .. math:: \\omega^2 = \\frac{k}{(1 + \\kappa)\\, m}

    The kinetic energy of the rolling body is ``(1 + kappa) m x'^2 / 2`` (translation plus
    rotation at ``x'/r``), the spring's energy ``k x^2 / 2``; the radius cancels.

    Parameters
    ----------
    k : Quantity
        Stiffness of the spring attached at the centre ``[force]/[length]``.
    m : Quantity
        Mass of the body ``[mass]``.
    kappa : float
        Shape factor ``J_C / (m r^2)`` (dimensionless, >= 0); 0.5 for a solid cylinder (disk).

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s).

    Notes
    -----
    Rolling needs enough friction; ``kappa = 0`` is a block sliding without friction.

    Examples
    --------
    Example 4.8 of [1]: a disk gives ``omega^2 = 2k/(3m)``:

    >>> from dyncalc.units import Q_
    >>> rolling_disk_spring(Q_(300, "N/m"), Q_(2, "kg")).values["omega"].magnitude  # rad/s
    10.0
    """
    kappa = _check_kappa(kappa)
    mass = _si(m, "kg")
    return _outcome(_si(k, "N/m") / rolling_inertia(mass, kappa))


@column_kernel(rolling_disk_spring)
def _rolling_disk_spring_columns(k, m, kappa=0.5) -> Columns:
    """:func:`rolling_disk_spring` on columns: ``k`` in N/m, ``m`` in kg, ``kappa`` an array;
    the one-off's :class:`Wide` steps on :class:`WideArray` (bit for bit)."""
    mass = WideArray(m)
    return _columns(WideArray(k) / rolling_inertia(mass, kappa), _kappa_allowed(kappa))


@check_units(R=LENGTH, r=LENGTH, g=ACCELERATION)
def rolling_in_track(R, r, g, kappa: float = 0.5) -> Outcome:
    """A round body rolling without slipping inside a circular track, about the bottom.

    .. math:: \\omega^2 = \\frac{g}{(1 + \\kappa)(R - r)}

    The centre of the body moves on a circle of radius ``R - r``; rolling ties the body's
    angular velocity to the centre's speed, so the kinetic energy is
    ``(1 + kappa) m (R - r)^2 phi'^2 / 2`` and the potential ``m g (R - r)(1 - cos phi)``.

    Parameters
    ----------
    R : Quantity
        Radius of the track ``[length]``.
    r : Quantity
        Radius of the body ``[length]``, ``r < R``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.
    kappa : float
        Shape factor ``J_C / (m r^2)`` (dimensionless, >= 0); 0.5 for a solid cylinder.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s), for small oscillations.

    Notes
    -----
    ``R - r`` is taken in the unit ``R`` was given in, so a body nearly as large as its
    track keeps the digits of the gap. ``kappa = 0`` is a bead sliding without friction: a
    simple pendulum of length ``R - r``.

    Examples
    --------
    Examples 4.9 and 5.17 of [1] (``l = R - r``), a solid sphere:

    >>> from dyncalc.units import Q_
    >>> out = rolling_in_track(Q_(1, "m"), Q_(0.2, "m"), Q_(9.80665, "m/s^2"), 0.4)
    >>> round(out.values["omega"].magnitude, 12)  # sqrt(9.80665 / (1.4 * 0.8)) rad/s
    2.959043342028
    """
    kappa = _check_kappa(kappa)
    if hasattr(R, "units") and hasattr(r, "units"):  # the difference in the unit typed
        gap = float((R - r).to("m").magnitude)
    else:  # a plain number is in metres (the face's rule)
        gap = magnitude(R, "m") - magnitude(r, "m")
    if not gap > 0.0:
        from ..units import Q_, format_quantity

        shown = [q if hasattr(q, "units") else Q_(q, "m") for q in (r, R)]
        raise PhysicsError(f"the body (r = {format_quantity(shown[0])}) must be smaller than "
                           f"the track it rolls in (R = {format_quantity(shown[1])})")
    length = Wide(gap)
    return _outcome(_si(g, "m/s**2") / (length + kappa * length))


@column_kernel(rolling_in_track)
def _rolling_in_track_columns(R, r, g, kappa=0.5, *, R_in_metres: bool = False):
    """:func:`rolling_in_track` on columns: ``R``, ``r`` in m, ``g`` in m/s^2, ``kappa`` an
    array.

    The one-off forms the gap ``R - r`` in the unit ``R`` was typed in (then converts it to
    metres), which from the metres a kernel receives gives other bits for ``R`` typed in mm,
    cm, ft, ... (tests/test_columns_rigid.py shows such rows). So the kernel computes when
    ``R`` and ``r`` come as typed (:class:`~dyncalc.physics.columns.TypedColumn`: the gap is
    formed as the one-off forms it, :func:`_gap_as_typed`) or the caller says that every
    row's ``R`` was typed in metres (``R_in_metres=True``; ``r`` may be in any unit: the
    one-off converts it to R's unit, metres, as the caller did), and otherwise returns
    ``None`` (every row to the one-off). Rows with ``R <= r`` are not exact.
    """
    known = True
    if isinstance(R, TypedColumn) and isinstance(r, TypedColumn):
        gap, known = _gap_as_typed(R, r)
    elif R_in_metres:
        gap = np.asarray(R, dtype=float) - np.asarray(r, dtype=float)
    else:
        return None
    length = WideArray(gap)
    return _columns(WideArray(g) / (length + kappa * length),
                    _kappa_allowed(kappa) & (gap > 0.0) & known)


_rolling_in_track_columns.typed_params = ("R", "r")


def _gap_as_typed(R: TypedColumn, r: TypedColumn):
    """``(R - r in metres, rows whose units are known)``: as pint subtracts two quantities, r
    converted to R's unit, the difference in R's unit, then converted to metres; one group of
    rows per pair of units typed."""
    from ..units import Q_

    gap = np.zeros(len(R.typed))
    known = (R.unit != "") & (r.unit != "")
    pairs = np.char.add(np.char.add(R.unit.astype(str), "|"), r.unit.astype(str))
    for pair in sorted(set(pairs[known].tolist())):
        rows = np.flatnonzero(pairs == pair)
        unit_R, unit_r = pair.split("|")
        r_in_R = np.asarray(Q_(r.typed[rows], unit_r).to(unit_R).magnitude, dtype=float)
        gap[rows] = Q_(R.typed[rows] - r_in_R, unit_R).to("m").magnitude
    return gap, known


@check_units(k=STIFFNESS, m=MASS, M=MASS)
def drum_block_spring(k, m, M) -> Outcome:
    """A block on a rope wound on a drum (a homogeneous disk), held by a spring.

    .. math:: \\omega^2 = \\frac{2k}{M + 2m}

    The drum turns at ``x'/R`` when the block moves at ``x'``, so its kinetic energy
    ``(M R^2/2)(x'/R)^2/2 = M x'^2/4`` does not depend on ``R``: the drum radius cancels.

    Parameters
    ----------
    k : Quantity
        Spring stiffness ``[force]/[length]``.
    m : Quantity
        Mass of the block ``[mass]``.
    M : Quantity
        Mass of the drum, a homogeneous disk ``[mass]``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s).

    Examples
    --------
    Example 5.12 of [1]:

    >>> from dyncalc.units import Q_
    >>> out = drum_block_spring(Q_(2, "kN/m"), Q_(4, "kg"), Q_(10, "kg"))
    >>> round(out.values["omega"].magnitude, 12)  # sqrt(4000 / 18) rad/s
    14.907119849999
    """
    return _outcome(_si(k, "N/m") / drum_block_inertia(_si(m, "kg"), _si(M, "kg")))


@column_kernel(drum_block_spring)
def _drum_block_spring_columns(k, m, M) -> Columns:
    """:func:`drum_block_spring` on columns: ``k`` in N/m, ``m``, ``M`` in kg (bit for bit)."""
    return _columns(WideArray(k) / drum_block_inertia(WideArray(m), WideArray(M)))


@check_units(a=LENGTH, g=ACCELERATION)
def board_on_drums(mu: float, a, g, sense: str = "inward") -> Outcome:
    """A board lying on two drums that turn in opposite senses, sliding on them with friction.

    .. math:: \\omega^2 = \\frac{2 \\mu g}{a}

    With the board's centre at ``x`` from midway between the drums, the drum it is nearer
    carries the weight share ``1/2 + x/a`` and the other ``1/2 - x/a``; the sliding friction
    forces differ by ``2 mu m g x / a``. If the drums' tops move toward each other (inward),
    that difference pushes the board back: ``x'' + (2 mu g / a) x = 0``. The mass and the
    drums' speed cancel (as long as the drums slide under the board all the time).

    Parameters
    ----------
    mu : float
        Coefficient of kinetic friction between board and drums (dimensionless, > 0).
    a : Quantity
        Distance between the drum axes ``[length]``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.
    sense : {"inward", "outward"}
        Turning sense of the drums: ``inward`` (tops moving toward each other, the default)
        or ``outward`` (tops moving apart).

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s).

    Raises
    ------
    PhysicsError
        For the outward sense: the board does not oscillate, any offset grows like
        ``exp(lambda t)`` with ``lambda = sqrt(2 mu g / a)``, which the message gives.

    Examples
    --------
    Example 5.13 of [1]:

    >>> from dyncalc.units import Q_
    >>> out = board_on_drums(0.4, Q_(0.8, "m"), Q_(9.80665, "m/s^2"))
    >>> round(out.values["omega"].magnitude, 12)  # sqrt(2 * 0.4 * 9.80665 / 0.8) rad/s
    3.131557120667
    """
    if sense not in ("inward", "outward"):
        raise PhysicsError(f"the drums turn inward or outward; got {sense!r}")
    if not mu > 0.0:
        raise PhysicsError(f"mu must be positive; got {mu!r}")
    rate_squared = 2.0 * Wide(float(mu)) * _si(g, "m/s**2") / _si(a, "m")
    if sense == "outward":
        rate = float(rate_squared.sqrt())
        raise PhysicsError(
            "with the drums turning outward (tops moving apart) the board does not oscillate: "
            "friction pushes it further from the middle and it runs off exponentially, any "
            "offset growing like exp(lambda t) with lambda = sqrt(2 mu g / a) = "
            f"{rate:.6g} 1/s; with sense=inward it oscillates at omega = {rate:.6g} rad/s")
    return _outcome(rate_squared)


@column_kernel(board_on_drums)
def _board_on_drums_columns(mu, a, g, sense: str = "inward"):
    """:func:`board_on_drums` on columns: ``mu`` an array, ``a`` in m, ``g`` in m/s^2, one
    ``sense`` for the call; ``None`` for any sense but ``inward`` (the one-off refuses every
    row). Rows with ``mu <= 0`` (refused) are not exact."""
    if sense != "inward":
        return None
    mu = np.asarray(mu, dtype=float)
    return _columns(2.0 * WideArray(mu) * WideArray(g) / WideArray(a), mu > 0.0)


@check_units(m=MASS, l=LENGTH, M=MASS, r=LENGTH, a=LENGTH, g=ACCELERATION)
def clock_pendulum(m, l, M, r, a, g) -> Outcome:
    """A clock pendulum: a uniform rod pivoted at one end carrying a disk on it.

    .. math:: J_A = \\frac{m l^2}{3} + \\frac{M (r^2 + 2 a^2)}{2}, \\qquad
              \\omega^2 = \\frac{(m l + 2 M a)\\, g}{2 J_A}

    Parameters
    ----------
    m : Quantity
        Mass of the rod ``[mass]``.
    l : Quantity
        Length of the rod ``[length]``.
    M : Quantity
        Mass of the disk (homogeneous) ``[mass]``.
    r : Quantity
        Radius of the disk ``[length]``.
    a : Quantity
        Distance from the pivot to the disk's centre ``[length]``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s) for small swings and ``J_A``
    (kg*m^2), the moment of inertia about the pivot.

    Examples
    --------
    Example 5.15 of [1]:

    >>> from dyncalc.units import Q_
    >>> out = clock_pendulum(Q_(0.5, "kg"), Q_(1, "m"), Q_(2, "kg"), Q_(0.1, "m"),
    ...                      Q_(0.9, "m"), Q_(9.80665, "m/s^2"))
    >>> round(out.values["omega"].magnitude, 12)  # rad/s
    3.345056926893
    >>> round(out.values["J_A"].magnitude, 12)  # kg*m^2
    1.796666666667
    """
    m_, l_, M_ = _si(m, "kg"), _si(l, "m"), _si(M, "kg")
    r_, a_ = _si(r, "m"), _si(a, "m")
    inertia = rod_about_end(m_, l_) + disk_about_parallel_axis(M_, r_, a_)
    moment = (m_ * l_ + 2.0 * M_ * a_) * _si(g, "m/s**2")
    return _outcome(moment / (2.0 * inertia), J_A=(inertia, "kg*m**2"))


@column_kernel(clock_pendulum)
def _clock_pendulum_columns(m, l, M, r, a, g) -> Columns:
    """:func:`clock_pendulum` on columns (SI: kg, m, m/s^2), with ``J_A`` (bit for bit)."""
    m_, l_, M_ = WideArray(m), WideArray(l), WideArray(M)
    r_, a_ = WideArray(r), WideArray(a)
    inertia = rod_about_end(m_, l_) + disk_about_parallel_axis(M_, r_, a_)
    moment = (m_ * l_ + 2.0 * M_ * a_) * WideArray(g)
    return _columns(moment / (2.0 * inertia), J_A=inertia)


@check_units(k=STIFFNESS, m=MASS, M=MASS)
def pulley_block_spring(k, m, M) -> Outcome:
    """A loose pulley (a homogeneous disk) held by a spring, with a block moving twice as far.

    .. math:: \\omega^2 = \\frac{k}{4 m + 3 M / 2}

    The pulley rolls on the fixed strand of its rope: its centre moves ``x``, it turns at
    ``x'/r`` (kinetic energy ``3 M x'^2 / 4``), and the block on the free strand moves ``2x``
    (kinetic energy ``2 m x'^2``); the spring on the pulley's axle stores ``k x^2 / 2``.

    Parameters
    ----------
    k : Quantity
        Spring stiffness ``[force]/[length]``.
    m : Quantity
        Mass of the block ``[mass]``.
    M : Quantity
        Mass of the pulley, a homogeneous disk ``[mass]``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s).

    Examples
    --------
    Example 5.16 of [1]:

    >>> from dyncalc.units import Q_
    >>> out = pulley_block_spring(Q_(1, "kN/m"), Q_(3, "kg"), Q_(4, "kg"))
    >>> round(out.values["omega"].magnitude, 12)  # sqrt(1000 / 18) rad/s
    7.453559924999
    """
    return _outcome(_si(k, "N/m") / pulley_block_inertia(_si(m, "kg"), _si(M, "kg")))


@column_kernel(pulley_block_spring)
def _pulley_block_spring_columns(k, m, M) -> Columns:
    """:func:`pulley_block_spring` on columns: ``k`` in N/m, ``m``, ``M`` in kg."""
    return _columns(WideArray(k) / pulley_block_inertia(WideArray(m), WideArray(M)))


@check_units(M=MASS, R=LENGTH, m=MASS, r=LENGTH, a=LENGTH, kt=TORSIONAL_STIFFNESS, g=ACCELERATION)
def disk_torsion_offset_mass(M, R, m, r, a, kt, g) -> Outcome:
    """A disk on a torsion shaft carrying a small disk whose centre hangs below the axis.

    .. math:: \\omega^2 = \\frac{k_t + m g a}{M R^2/2 + m (r^2/2 + a^2)}

    The shaft and the weight of the offset disk both pull back; the moment of inertia about
    the axis (reported as ``J_A``) is the large disk's plus the small disk's by the
    parallel-axis theorem.

    Parameters
    ----------
    M : Quantity
        Mass of the large disk ``[mass]``.
    R : Quantity
        Radius of the large disk ``[length]``.
    m : Quantity
        Mass of the small disk ``[mass]``.
    r : Quantity
        Radius of the small disk ``[length]``.
    a : Quantity
        Distance of the small disk's centre below the axis ``[length]`` (>= 0).
    kt : Quantity
        Torsional stiffness of the shaft ``[force]*[length]/[angle]`` (>= 0).
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s) for small oscillations and ``J_A``
    (kg*m^2), the moment of inertia about the axis.

    Raises
    ------
    PhysicsError
        When ``kt = 0`` and ``a = 0``: nothing pulls the disk back.

    Examples
    --------
    Example 5.25 of [1]:

    >>> from dyncalc.units import Q_
    >>> out = disk_torsion_offset_mass(Q_(20, "kg"), Q_(0.3, "m"), Q_(2, "kg"),
    ...                                Q_(0.05, "m"), Q_(0.2, "m"), Q_(50, "N*m/rad"),
    ...                                Q_(9.80665, "m/s^2"))
    >>> round(out.values["omega"].magnitude, 12)  # rad/s
    7.408313877247
    """
    M_, R_, m_ = _si(M, "kg"), _si(R, "m"), _si(m, "kg")
    r_, a_, kt_ = _si(r, "m"), _si(a, "m"), _si(kt, "N*m/rad")
    stiffness = kt_ + m_ * _si(g, "m/s**2") * a_
    if not stiffness.m:
        raise PhysicsError("with kt = 0 and a = 0 nothing pulls the disk back (neutral "
                           "equilibrium): it does not oscillate")
    inertia = disk_about_axis(M_, R_) + disk_about_parallel_axis(m_, r_, a_)
    return _outcome(stiffness / inertia, J_A=(inertia, "kg*m**2"))


@column_kernel(disk_torsion_offset_mass)
def _disk_torsion_offset_mass_columns(M, R, m, r, a, kt, g) -> Columns:
    """:func:`disk_torsion_offset_mass` on columns (SI: kg, m, N*m/rad, m/s^2), with ``J_A``;
    rows with ``kt = 0`` and ``a = 0`` (refused) are not exact."""
    M_, R_, m_ = WideArray(M), WideArray(R), WideArray(m)
    r_, a_, kt_ = WideArray(r), WideArray(a), WideArray(kt)
    stiffness = kt_ + m_ * WideArray(g) * a_
    inertia = disk_about_axis(M_, R_) + disk_about_parallel_axis(m_, r_, a_)
    return _columns(stiffness / inertia, stiffness.m != 0.0, J_A=inertia)


@check_units(k=STIFFNESS, m=MASS, M=MASS)
def wheel_on_moving_beam(k, m, M, kappa: float = 0.5) -> Outcome:
    """A wheel held by a spring, rolling on a beam that runs freely on rollers.

    .. math:: \\omega^2 = \\frac{k}{m + \\frac{M}{1 + M/(\\kappa m)}}
              = \\frac{k\\,(\\kappa m + M)}{m\\,(\\kappa m + M + \\kappa M)}

    With ``x`` the wheel's centre and ``X`` the beam, rolling turns the wheel at
    ``(x' - X')/r``; the kinetic energy is
    ``m x'^2/2 + kappa m (x' - X')^2/2 + M X'^2/2`` and the spring (from a fixed support to the
    wheel's centre) stores ``k x^2/2``. The second form, evaluated here, also holds for
    ``kappa = 0`` (a frictionless slider: the beam plays no part and ``omega^2 = k/m``).

    Parameters
    ----------
    k : Quantity
        Spring stiffness ``[force]/[length]``.
    m : Quantity
        Mass of the wheel ``[mass]``.
    M : Quantity
        Mass of the beam ``[mass]``.
    kappa : float
        Shape factor of the wheel ``J_C / (m r^2)`` (dimensionless, >= 0); 0.5 for a disk.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s).

    Notes
    -----
    The system has two degrees of freedom; the other mode has zero frequency: the beam
    drifts at constant speed under a wheel whose centre stays put (it only spins).

    Examples
    --------
    Example 5.27 of [1]:

    >>> from dyncalc.units import Q_
    >>> out = wheel_on_moving_beam(Q_(500, "N/m"), Q_(5, "kg"), Q_(20, "kg"))
    >>> round(out.values["omega"].magnitude, 12)  # rad/s
    8.320502943378
    """
    kappa = _check_kappa(kappa)
    m_, M_ = _si(m, "kg"), _si(M, "kg")
    coupled = kappa * m_ + M_
    out = _outcome(_si(k, "N/m") * coupled / (m_ * (coupled + kappa * M_)))
    out.assumptions.append("the other mode has zero frequency: the beam drifts freely on its "
                           "rollers under the wheel, whose centre stays put while it spins")
    return out


@column_kernel(wheel_on_moving_beam)
def _wheel_on_moving_beam_columns(k, m, M, kappa=0.5) -> Columns:
    """:func:`wheel_on_moving_beam` on columns: ``k`` in N/m, ``m``, ``M`` in kg, ``kappa`` an
    array (bit for bit)."""
    m_, M_ = WideArray(m), WideArray(M)
    coupled = kappa * m_ + M_
    return _columns(WideArray(k) * coupled / (m_ * (coupled + kappa * M_)),
                    _kappa_allowed(kappa))


@check_units(l=LENGTH, g=ACCELERATION)
def angled_member(l, g) -> Outcome:
    """An L-shaped uniform bar swinging in its plane about the free end of its long arm.

    .. math:: \\omega^2 = \\frac{\\sqrt{65}}{14} \\frac{g}{l}

    The long arm (length ``2l``) hangs from the pivot, the short arm (length ``l``) is at right
    angles to it at the far end. With ``m`` the mass per length ``l``: the centre of mass lies
    ``sqrt(65) l / 6`` from the pivot, ``J_A = 7 m l^2``, so
    ``omega^2 = 3 m g (sqrt(65) l / 6) / (7 m l^2)``; the mass cancels.

    Parameters
    ----------
    l : Quantity
        Length of the short arm (the long one is ``2l``) ``[length]``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s) for small swings about the
    equilibrium (in which the long arm leans away from the vertical).

    Examples
    --------
    Example 3.44 of [1]:

    >>> from dyncalc.units import Q_
    >>> out = angled_member(Q_(0.5, "m"), Q_(9.80665, "m/s^2"))
    >>> round(out.values["omega"].magnitude, 12)  # rad/s
    3.360776694825
    """
    ratio = (_si(g, "m/s**2") / _si(l, "m")).sqrt()
    return Outcome(periodic(float(ANGLED_MEMBER_FACTOR * ratio)))


@column_kernel(angled_member)
def _angled_member_columns(l, g) -> Columns:
    """:func:`angled_member` on columns: ``l`` in m, ``g`` in m/s^2 (bit for bit)."""
    ratio = (WideArray(g) / WideArray(l)).sqrt()
    values = periodic_arrays((ANGLED_MEMBER_FACTOR * ratio).to_float())
    return Columns(values, exact=finite_nonzero(values))
