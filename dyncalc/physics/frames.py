"""Relative motion in a moving, rotating frame (the ``coriolis`` command).

A point moves relative to a frame whose origin accelerates with ``a0`` and which turns with the
angular velocity ``Omega`` and the angular acceleration ``alpha``. Its absolute acceleration is

.. math:: \\mathbf a = \\underbrace{\\mathbf a_0 + \\boldsymbol\\alpha\\times\\mathbf r
          + \\boldsymbol\\Omega\\times(\\boldsymbol\\Omega\\times\\mathbf r)}_{\\mathbf a_t}
          + \\underbrace{2\\,\\boldsymbol\\Omega\\times\\mathbf v_r}_{\\mathbf a_c}
          + \\mathbf a_r

with ``r``, ``v_r``, ``a_r`` the position, velocity and acceleration measured in the frame.
Every vector is given by its components in the frame's axes. The Coriolis force (the apparent
force an observer in the frame sees) is ``F_c = -m a_c``.

The functions take pint quantities (any units of the right dimension) or plain SI values and
return SI magnitudes as numpy arrays (m/s^2, N, rad/s, m/s). Cross products are formed on
vectors scaled by powers of two (exact), each component correctly rounded
(:func:`~dyncalc.physics.numerics.cross_product`: near-parallel vectors keep their small cross
product), so that no intermediate product overflows or underflows
when the result itself is representable: ``Omega x (Omega x r)`` with ``Omega = 1e200 rad/s``
and ``r = 1e-300 m`` is ``1e100 m/s^2``, not ``inf``. A result beyond float64 is refused
(:class:`~dyncalc.errors.PhysicsError`); one that underflows to zero from non-zero factors
comes with a warning.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 6 (relative motion).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..lazy import numpy as np

from ..constants import EARTH_RATE
from ..errors import InputError, PhysicsError
from .columns import Columns, column_kernel
from .numerics import cross_product, two_product

__all__ = ["EARTH_RATE", "coriolis_acceleration", "euler_acceleration",
           "centripetal_acceleration", "coriolis_force", "relative_acceleration",
           "FrameAcceleration", "earth_angular_velocity", "enu_velocity", "cos_sin_degrees",
           "magnitude"]


_UNITS = {"a_c": "m/s^2", "a_euler": "m/s^2", "a_centripetal": "m/s^2",
          "a_transport": "m/s^2", "a": "m/s^2", "F_c": "N"}


# --------------------------------------------------------------------------------------------
# Vectors scaled by powers of two


def _si_vector(value, unit: str, name: str) -> np.ndarray:
    if hasattr(value, "to"):
        value = value.to(unit.replace("^", "**")).magnitude
    arr = np.array(value, dtype=float)
    if arr.shape != (3,):
        raise InputError(f"{name} must have 3 components; got shape {arr.shape}")
    return arr + 0.0  # no negative zeros


def _si_scalar(value, unit: str) -> float:
    if hasattr(value, "to"):
        value = value.to(unit.replace("^", "**")).magnitude
    return float(value)


@dataclass(frozen=True)
class _Scaled:
    """A vector ``ldexp(m, e)`` whose mantissa ``m`` has its largest component in [0.5, 1)
    (or is zero)."""

    m: np.ndarray
    e: int

    @classmethod
    def of(cls, v, e: int = 0) -> "_Scaled":
        v = np.asarray(v, dtype=float)
        top = float(np.max(np.abs(v)))
        if top == 0.0:
            return cls(np.zeros(3), 0)
        _, shift = math.frexp(top)
        return cls(np.ldexp(v, -shift), e + shift)

    def cross(self, other: "_Scaled") -> "_Scaled":
        """The cross product, each component of the mantissas' product correctly rounded
        (:func:`~dyncalc.physics.numerics.cross_product`: exact products, one rounding), so
        near-parallel vectors keep their small cross product."""
        if not (np.all(np.isfinite(self.m)) and np.all(np.isfinite(other.m))):
            with np.errstate(all="ignore"):  # inf or nan: non-finite, refused by the caller
                return _Scaled(np.cross(self.m, other.m), self.e + other.e)
        return _Scaled.of(cross_product(self.m, other.m), self.e + other.e)

    def times(self, factor: float) -> "_Scaled":
        if factor == 0.0 or not self.nonzero:
            return _Scaled(np.zeros(3), 0)
        mant, shift = math.frexp(factor)
        return _Scaled.of(self.m * mant, self.e + shift)

    @property
    def nonzero(self) -> bool:
        return bool(np.any(self.m != 0.0))

    def value(self) -> np.ndarray:
        with np.errstate(over="ignore", under="ignore"):
            return np.ldexp(self.m, self.e) + 0.0


# --------------------------------------------------------------------------------------------
# The terms one by one


def _checked(name: str, scaled: _Scaled, warnings: list[str] | None = None) -> np.ndarray:
    value = scaled.value()
    unit = _UNITS.get(name, "SI")
    if not np.all(np.isfinite(value)):
        raise PhysicsError(f"{name} overflows float64 at these inputs (a component beyond "
                           f"1.8e308 {unit})")
    if scaled.nonzero and not np.any(value != 0.0) and warnings is not None:
        warnings.append(f"{name} underflows to zero (below 4.9e-324 {unit}) although its "
                        "factors are not zero")
    return value


def coriolis_acceleration(Omega, v_r) -> np.ndarray:
    """The Coriolis term of the relative-motion formula.

    .. math:: \\mathbf a_c = 2\\,\\boldsymbol\\Omega \\times \\mathbf v_r

    Parameters
    ----------
    Omega : Quantity or array
        Angular velocity of the frame ``[angle]/[time]`` (3 components; SI: rad/s).
    v_r : Quantity or array
        Velocity relative to the frame ``[length]/[time]`` (3 components; SI: m/s).

    Returns
    -------
    numpy.ndarray
        ``a_c`` in m/s^2. The Coriolis force is ``-m a_c``.

    Examples
    --------
    A slider moving outward at 3 m/s along a link turning at 2 rad/s:

    >>> from dyncalc.units import Q_
    >>> coriolis_acceleration(Q_([0, 0, 2], "rad/s"), Q_([3, 0, 0], "m/s")).tolist()
    [0.0, 12.0, 0.0]
    """
    Om = _Scaled.of(_si_vector(Omega, "rad/s", "Omega"))
    v = _Scaled.of(_si_vector(v_r, "m/s", "v_r"))
    return _checked("a_c", Om.cross(v).times(2.0))


def euler_acceleration(alpha, r) -> np.ndarray:
    """The Euler (angular-acceleration) term ``alpha x r`` in m/s^2.

    >>> euler_acceleration([0, 0, 3.0], [2.0, 0, 0]).tolist()
    [0.0, 6.0, 0.0]
    """
    al = _Scaled.of(_si_vector(alpha, "rad/s^2", "alpha"))
    rr = _Scaled.of(_si_vector(r, "m", "r"))
    return _checked("a_euler", al.cross(rr))


def centripetal_acceleration(Omega, r) -> np.ndarray:
    """The centripetal term ``Omega x (Omega x r)`` in m/s^2 (it points at the axis).

    >>> centripetal_acceleration([0, 0, 2.0], [0.5, 0, 1.0]).tolist()
    [-2.0, 0.0, 0.0]
    """
    Om = _Scaled.of(_si_vector(Omega, "rad/s", "Omega"))
    rr = _Scaled.of(_si_vector(r, "m", "r"))
    return _checked("a_centripetal", Om.cross(Om.cross(rr)))


def coriolis_force(m, a_c) -> np.ndarray:
    """The Coriolis force ``F_c = -m a_c`` in N (the apparent force in the rotating frame).

    >>> coriolis_force(2.0, [0.0, 12.0, 0.0]).tolist()
    [0.0, -24.0, 0.0]
    """
    return _checked("F_c", _Scaled.of(_si_vector(a_c, "m/s^2", "a_c"))
                    .times(-_si_scalar(m, "kg")))


def magnitude(v) -> float:
    """``|v|`` without overflow or underflow of the squares (``inf`` beyond float64).

    >>> magnitude([3e200, 4e200, 12e200])
    1.3e+201
    """
    try:
        return float(math.hypot(*(float(x) for x in v)))
    except OverflowError:
        return math.inf


# --------------------------------------------------------------------------------------------
# All terms at once


@dataclass
class FrameAcceleration:
    """Every term of the relative-motion formula, SI numpy arrays (m/s^2; ``F_c`` in N).

    ``given`` names the optional inputs that were given (``r``, ``alpha``, ``a0``, ``a_r``,
    ``m``); ``parallel`` names the cross products that vanish because their factors are
    parallel (both non-zero); ``warnings`` holds underflows.
    """

    Omega: np.ndarray
    v_r: np.ndarray
    r: np.ndarray
    alpha: np.ndarray
    a0: np.ndarray
    a_r: np.ndarray
    a_c: np.ndarray
    a_euler: np.ndarray
    a_centripetal: np.ndarray
    a_transport: np.ndarray
    a: np.ndarray
    F_c: np.ndarray | None = None
    given: set[str] = field(default_factory=set)
    parallel: set[str] = field(default_factory=set)
    warnings: list[str] = field(default_factory=list)


def _sum(name: str, *terms: np.ndarray) -> np.ndarray:
    with np.errstate(over="ignore", invalid="ignore"):
        total = np.sum(terms, axis=0) + 0.0
    if not np.all(np.isfinite(total)):
        raise PhysicsError(f"{name} overflows float64 at these inputs (a component beyond "
                           f"1.8e308 {_UNITS[name]})")
    return total


def relative_acceleration(Omega, v_r, r=None, alpha=None, a0=None, a_r=None,
                          m=None) -> FrameAcceleration:
    """Every term of the absolute acceleration of a point moving in a rotating frame.

    .. math:: \\mathbf a = \\mathbf a_0 + \\boldsymbol\\alpha\\times\\mathbf r
              + \\boldsymbol\\Omega\\times(\\boldsymbol\\Omega\\times\\mathbf r)
              + 2\\,\\boldsymbol\\Omega\\times\\mathbf v_r + \\mathbf a_r,
              \\qquad \\mathbf F_c = -m\\,\\mathbf a_c

    Parameters
    ----------
    Omega : Quantity or array
        Angular velocity of the frame ``[angle]/[time]``.
    v_r : Quantity or array
        Velocity relative to the frame ``[length]/[time]``.
    r : Quantity or array, optional
        Position relative to the frame's origin ``[length]`` (default 0: at the origin).
    alpha : Quantity or array, optional
        Angular acceleration of the frame ``[angle]/[time]^2`` (default 0).
    a0 : Quantity or array, optional
        Acceleration of the frame's origin ``[length]/[time]^2`` (default 0).
    a_r : Quantity or array, optional
        Acceleration relative to the frame ``[length]/[time]^2`` (default 0).
    m : Quantity or float, optional
        Mass ``[mass]``: gives the Coriolis force ``F_c``.

    Returns
    -------
    FrameAcceleration
        The terms as SI arrays; ``a_transport = a0 + a_euler + a_centripetal``,
        ``a = a_transport + a_c + a_r``.

    Raises
    ------
    PhysicsError
        A term overflows float64.

    Notes
    -----
    All vectors are components in the same axes (those of the moving frame at this instant).
    The inputs are not checked for being finite: the command line refuses infinities first.

    Examples
    --------
    The set-up of E6.12 of [1] with numbers of our own: a frame translating with
    ``a0 = 4 m/s^2`` (no rotation), a point on a circle of radius 2 m moving at 2 m/s, at
    ``phi = 90 deg`` from the direction of ``a0``; ``|a| = sqrt(a0^2 + v^4/r^2) = sqrt(20)``:

    >>> out = relative_acceleration([0, 0, 0], [-2.0, 0, 0], r=[0, 2.0, 0], a0=[4.0, 0, 0],
    ...                             a_r=[0, -2.0, 0])
    >>> out.a.tolist(), round(magnitude(out.a), 12)
    ([4.0, -2.0, 0.0], 4.472135955)
    """
    given = {name for name, value in (("r", r), ("alpha", alpha), ("a0", a0), ("a_r", a_r),
                                      ("m", m)) if value is not None}
    zero = np.zeros(3)
    Om_v = _si_vector(Omega, "rad/s", "Omega")
    v_v = _si_vector(v_r, "m/s", "v_r")
    r_v = zero if r is None else _si_vector(r, "m", "r")
    al_v = zero if alpha is None else _si_vector(alpha, "rad/s^2", "alpha")
    a0_v = zero if a0 is None else _si_vector(a0, "m/s^2", "a0")
    ar_v = zero if a_r is None else _si_vector(a_r, "m/s^2", "a_r")

    warnings: list[str] = []
    parallel: set[str] = set()
    Om, v, rr, al = (_Scaled.of(x) for x in (Om_v, v_v, r_v, al_v))

    coriolis = Om.cross(v).times(2.0)
    euler = al.cross(rr)
    inner = Om.cross(rr)
    centripetal = Om.cross(inner)
    for name, scaled, factors in (("a_c", coriolis, (Om, v)), ("a_euler", euler, (al, rr)),
                                  ("a_centripetal", inner, (Om, rr))):
        if all(f.nonzero for f in factors) and not scaled.nonzero:
            parallel.add(name)
    a_c = _checked("a_c", coriolis, warnings)
    a_euler = _checked("a_euler", euler, warnings)
    a_centripetal = _checked("a_centripetal", centripetal, warnings)
    a_transport = _sum("a_transport", a0_v, a_euler, a_centripetal)
    a = _sum("a", a_transport, a_c, ar_v)
    F_c = None
    if m is not None:
        F_c = _checked("F_c", coriolis.times(-_si_scalar(m, "kg")), warnings)
    return FrameAcceleration(Omega=Om_v, v_r=v_v, r=r_v, alpha=al_v, a0=a0_v, a_r=ar_v,
                             a_c=a_c, a_euler=a_euler, a_centripetal=a_centripetal,
                             a_transport=a_transport, a=a, F_c=F_c, given=given,
                             parallel=parallel, warnings=warnings)


class _ScaledRows:
    """The twin of :class:`_Scaled` for ``n`` vectors at once, a component at a time:
    mantissas ``c`` (three arrays of ``n``: x, y, z) and exponents ``e`` (n), each row scaled
    as :class:`_Scaled` scales its vector."""

    __slots__ = ("c", "e")

    def __init__(self, columns, e=0):
        x, y, z = (np.asarray(c, dtype=float) for c in columns)
        top = np.maximum(np.maximum(np.abs(x), np.abs(y)), np.abs(z))
        _, shift = np.frexp(top)
        shift = shift.astype(np.int64)
        zero = top == 0.0
        down = _exponents(-shift)
        with np.errstate(over="ignore", under="ignore"):
            self.c = tuple(np.ldexp(c, down) for c in (x, y, z))
        self.e = e + shift
        if zero.any():
            self.c = tuple(np.where(zero, 0.0, c) for c in self.c)
            self.e = np.where(zero, 0, self.e)

    @classmethod
    def of(cls, rows) -> "_ScaledRows":
        """The scaled vectors of an ``(n, 3)`` array."""
        rows = np.asarray(rows, dtype=float)
        return cls((rows[:, 0], rows[:, 1], rows[:, 2]))

    def cross(self, other: "_ScaledRows") -> "_ScaledRows":
        """The twin of :meth:`_Scaled.cross`: each component of the mantissas' cross product
        from exact products (:func:`~dyncalc.physics.numerics_arrays.two_product_array`)
        summed by the twin of ``math.fsum``, bit for bit; rows with a non-finite mantissa
        give NaN (the one-off refuses them)."""
        from .numerics_arrays import fsum_rows, two_product_array

        (a0, a1, a2), (b0, b1, b2) = self.c, other.c

        def difference(p, q, r, t):
            h1, l1 = two_product_array(p, q)
            h2, l2 = two_product_array(r, t)
            total, ok = fsum_rows(np.stack([h1, l1, -h2, -l2], axis=1))
            return np.where(ok, total, np.nan)

        with np.errstate(over="ignore", under="ignore", invalid="ignore"):
            return _ScaledRows((difference(a1, b2, a2, b1), difference(a2, b0, a0, b2),
                                difference(a0, b1, a1, b0)), self.e + other.e)

    def times(self, factor) -> "_ScaledRows":
        factor = np.broadcast_to(np.asarray(factor, dtype=float), self.e.shape)
        mant, shift = np.frexp(factor)
        with np.errstate(under="ignore", invalid="ignore"):
            out = _ScaledRows(tuple(c * mant for c in self.c),
                              self.e + shift.astype(np.int64))
        still = (factor == 0.0) | ~self.nonzero
        if still.any():
            out.c = tuple(np.where(still, 0.0, c) for c in out.c)
            out.e = np.where(still, 0, out.e)
        return out

    @property
    def nonzero(self):
        x, y, z = self.c
        return (x != 0.0) | (y != 0.0) | (z != 0.0)

    def value(self):
        """The vectors, ``(n, 3)``: each mantissa times two to its exponent, plus 0.0."""
        up = _exponents(self.e)
        out = np.empty((len(self.e), 3))
        with np.errstate(over="ignore", under="ignore"):
            for j, c in enumerate(self.c):
                out[:, j] = np.ldexp(c, up)
        out += 0.0
        return out


def _exponents(e):
    """Exponents for ``numpy.ldexp`` as :func:`~dyncalc.physics.numerics_arrays.ldexp_array`
    takes them (clipped far beyond any overflow or underflow, as int32)."""
    from .numerics_arrays import _EXP_LIMIT

    return np.clip(np.asarray(e, dtype=np.int64), -_EXP_LIMIT, _EXP_LIMIT).astype(np.int32)


def _zero_rows(scaled: _ScaledRows, value) -> np.ndarray:
    """Rows a non-zero scaled product gives as zero (an underflow the one-off warns of)."""
    return scaled.nonzero & (value[:, 0] == 0.0) & (value[:, 1] == 0.0) & (value[:, 2] == 0.0)


@column_kernel(relative_acceleration)
def _relative_acceleration_columns(Omega, v_r, r=None, alpha=None, a0=None, a_r=None,
                                   m=None) -> Columns:
    """:func:`relative_acceleration` on columns: every vector an ``(n, 3)`` SI array, ``m``
    an ``(n,)`` array. The same power-of-two scaling (:class:`_ScaledRows`), the same exact
    cross products and sums in the same order, bit for bit; ``values`` are the FrameAcceleration's
    terms ``a_c``, ``a_euler``, ``a_centripetal``, ``a_transport``, ``a`` (and ``F_c`` with
    ``m``). Exact where no term overflows (the one-off refuses) or underflows to zero from
    non-zero factors (it warns). A term of vectors not given is zero (not computed: the
    cross product of zeros; a non-finite Omega makes ``a_c`` non-finite, so not exact,
    whatever the other terms)."""
    Om_v = np.asarray(Omega, dtype=float) + 0.0
    v_v = np.asarray(v_r, dtype=float) + 0.0
    zero = np.zeros_like(Om_v)
    r_v, al_v, a0_v, ar_v = (zero if x is None else np.asarray(x, dtype=float) + 0.0
                             for x in (r, alpha, a0, a_r))
    Om = _ScaledRows.of(Om_v)
    coriolis = Om.cross(_ScaledRows.of(v_v)).times(2.0)
    scaled = {"a_c": coriolis}
    if r is not None or alpha is not None:
        rr = _ScaledRows.of(r_v)
        scaled["a_euler"] = _ScaledRows.of(al_v).cross(rr)
        if r is not None:
            scaled["a_centripetal"] = Om.cross(Om.cross(rr))
    exact = np.ones(len(Om_v), dtype=bool)
    terms = {}
    for name in ("a_c", "a_euler", "a_centripetal"):
        if name not in scaled:
            terms[name] = np.zeros_like(Om_v)
            continue
        terms[name] = scaled[name].value()
        exact &= ~_zero_rows(scaled[name], terms[name])
    alone = len(scaled) == 1 and a0 is None and a_r is None
    with np.errstate(over="ignore", invalid="ignore"):
        if alone:  # (0 + 0) + 0 + 0.0 is 0.0, and (0.0 + a_c) + 0 + 0.0 is a_c + 0.0
            terms["a_transport"] = np.zeros_like(Om_v)
            terms["a"] = terms["a_c"] + 0.0
        else:
            terms["a_transport"] = (a0_v + terms["a_euler"]) + terms["a_centripetal"] + 0.0
            terms["a"] = (terms["a_transport"] + terms["a_c"]) + ar_v + 0.0
    if m is not None:
        force = coriolis.times(-np.asarray(m, dtype=float))
        terms["F_c"] = force.value()
        exact &= ~_zero_rows(force, terms["F_c"])
    with np.errstate(invalid="ignore"):
        for name, value in terms.items():
            if (not alone or name in ("a_c", "F_c")) and not np.isfinite(value).all():
                exact &= np.isfinite(value).all(axis=1)  # (alone: the others are 0 or a_c)
    return Columns(terms, exact=exact, model="vectors")


# --------------------------------------------------------------------------------------------
# The rotating Earth: a local east-north-up frame


#: pi/180 as a double-double (``DEG_HI + DEG_LO`` is pi/180 to about 35 digits).
DEG_HI = math.pi / 180.0
DEG_LO = 2.9486522708701687e-19


def cos_sin_degrees(degrees: float) -> tuple[float, float]:
    """``(cos, sin)`` of an angle in degrees, exact at multiples of 90 degrees.

    The angle is reduced to within 45 degrees of a multiple of 90 (exactly, in floating
    point), so ``cos 90 deg`` is 0, not 6.1e-17; the rest is turned into radians with a
    double-double pi/180 and the rounding of that product is put back to first order, so
    ``sin 30 deg`` is 0.5, not 0.49999999999999994.

    >>> cos_sin_degrees(90.0), cos_sin_degrees(-180.0), cos_sin_degrees(30.0)[1]
    ((0.0, 1.0), (-1.0, 0.0), 0.5)
    """
    d = math.fmod(float(degrees), 360.0)
    quarter = round(d / 90.0)
    rest = d - 90.0 * quarter  # exact: within 45 degrees of a multiple of 90
    x, err = two_product(rest, DEG_HI)
    x_lo = err + rest * DEG_LO
    c0, s0 = math.cos(x), math.sin(x)
    c, s = c0 - s0 * x_lo, s0 + c0 * x_lo
    if abs(rest) == 45.0:  # sqrt(1/2) correctly rounded, the same for both
        c, s = math.sqrt(0.5), math.copysign(math.sqrt(0.5), rest)
    quarter %= 4
    if quarter == 1:
        c, s = -s, c
    elif quarter == 2:
        c, s = -c, -s
    elif quarter == 3:
        c, s = s, -c
    return c + 0.0, s + 0.0


def _degrees(angle) -> float:
    """An angle (pint quantity, or a float in radians) in degrees; one whose degrees leave
    float64 (1e307 rad) is first reduced to within a turn (``fmod`` of its turns is exact)."""
    if hasattr(angle, "to"):
        degrees = float(angle.to("degree").magnitude)
        if math.isinf(degrees):
            degrees = 360.0 * math.fmod(float(angle.to("turn").magnitude), 1.0)
        return degrees
    degrees = math.degrees(float(angle))
    return math.degrees(math.fmod(float(angle), math.tau)) if math.isinf(degrees) else degrees


def earth_angular_velocity(latitude, rate=EARTH_RATE) -> np.ndarray:
    """The Earth's angular velocity in the local east-north-up frame, in rad/s.

    .. math:: \\boldsymbol\\Omega = \\Omega_E\\,(0,\\ \\cos\\varphi,\\ \\sin\\varphi)

    Parameters
    ----------
    latitude : Quantity or float
        Geographic latitude ``[angle]`` (a float is in radians), positive north.
    rate : Quantity or float, optional
        Rotation rate ``[angle]/[time]``; default the sidereal rate 7.2921159e-5 rad/s.

    Examples
    --------
    At the North Pole the whole rotation is about the local vertical:

    >>> from dyncalc.units import Q_
    >>> earth_angular_velocity(Q_(90, "deg")).tolist()
    [0.0, 0.0, 7.2921159e-05]
    """
    c, s = cos_sin_degrees(_degrees(latitude))
    w = _si_scalar(rate, "rad/s")
    return np.array([0.0, w * c, w * s]) + 0.0


def enu_velocity(speed, heading, vertical=0.0) -> np.ndarray:
    """A velocity in east-north-up components from a horizontal speed, a compass heading
    (0 = north, 90 deg = east) and a vertical speed (positive up), in m/s.

    .. math:: \\mathbf v = (v \\sin\\psi,\\ v\\cos\\psi,\\ w)

    >>> from dyncalc.units import Q_
    >>> enu_velocity(Q_(20, "m/s"), Q_(90, "deg")).tolist()
    [20.0, 0.0, 0.0]
    """
    c, s = cos_sin_degrees(_degrees(heading))
    v = _si_scalar(speed, "m/s")
    w = _si_scalar(vertical, "m/s")
    return np.array([v * s, v * c, w]) + 0.0
