"""The Lagrange scenes of chapter 4 (E4.14, E4.16, E4.17, E4.19): closed-form frequencies for
``natural-frequency`` and the linearised mass and stiffness matrices for ``modes``.

Each scene's matrices are derived by hand from its energies (../shared/SCENES.md, "Lagrange scenes"):
``M_ij = d^2 T / dq_i' dq_j'`` and ``K_ij = d^2 V / dq_i dq_j`` at the equilibrium, the
derivation written in the docstring of each ``*_matrices`` function. The closed forms and the
eigenvalues of the matrices are two derivations of the same frequencies, and the tests hold
them against each other.

Arithmetic in 40-digit decimals with an exponent range far beyond float64 (as
:mod:`dyncalc.physics.coupled` does), so that nothing overflows midway; only the results are
rounded to floats.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 4.
"""
from __future__ import annotations

import math
from decimal import Decimal, localcontext

from ..errors import PhysicsError
from ..units import ACCELERATION, INERTIA, LENGTH, MASS, STIFFNESS
from .face import check_units, magnitude
from .outcome import Outcome, periodic

__all__ = ["block_disk_springs", "spring_coupled_pendulums", "disk_on_swinging_bar",
           "pendulum_on_sliding_block", "coupled_blocks_matrices", "block_disk_springs_matrices",
           "spring_coupled_pendulums_matrices", "pendulum_on_sliding_block_matrices",
           "disk_on_swinging_bar_matrices", "NO_EQUILIBRIUM",
           "Linearised", "pendulums_equilibrium"]

_DIGITS = 40


def _context(ctx) -> None:
    ctx.prec, ctx.Emax, ctx.Emin = _DIGITS, 10 ** 6, -10 ** 6


def _float(value: Decimal) -> float:
    try:
        return float(value)
    except OverflowError:  # pragma: no cover - Decimal -> float gives inf, not an error
        return math.inf


class Linearised:
    """A scene linearised about its equilibrium: the coordinates (names and kinds,
    ``length`` or ``angle``), ``M`` and ``K`` in SI (lists of rows), the equilibrium in
    words, and the scene's own results of the linearisation (``phi2_0``) in SI."""

    __slots__ = ("coordinates", "kinds", "M", "K", "equilibrium", "extra")

    def __init__(self, coordinates, kinds, M, K, equilibrium: str, extra=None):
        self.coordinates, self.kinds, self.M, self.K = coordinates, kinds, M, K
        self.equilibrium, self.extra = equilibrium, dict(extra or {})


def _two_modes(lam1: Decimal, lam2: Decimal, note: str) -> Outcome:
    values = {**periodic(_float(lam1.sqrt()), "_1"), **periodic(_float(lam2.sqrt()), "_2")}
    return Outcome(values, assumptions=[note])


# --- coupled-blocks (E4.15) -----------------------------------------------------------------

def coupled_blocks_matrices(m1: float, m2: float, k1: float, k2: float, k3: float
                            ) -> Linearised:
    """``coupled-blocks`` (SI floats): coordinates x1, x2 from the unstretched positions.

    ``T = m1 x1'^2/2 + m2 x2'^2/2`` gives ``M = diag(m1, m2)``;
    ``V = k1 x1^2/2 + k3 (x2 - x1)^2/2 + k2 x2^2/2`` gives
    ``K = [[k1 + k3, -k3], [-k3, k2 + k3]]`` (exact: V is quadratic).
    """
    return Linearised(("x1", "x2"), ("length", "length"), [[m1, 0.0], [0.0, m2]],
                      [[k1 + k3, -k3], [-k3, k2 + k3]], "x1 = x2 = 0 (springs unstretched)")


# --- block-disk-springs (E4.14) -------------------------------------------------------------

@check_units(M=MASS, m=MASS, r=LENGTH, k=STIFFNESS)
def block_disk_springs(M, m, k, r=None) -> Outcome:
    """A block on a wall spring with a disk rolling on its top face, tied by a second spring
    to a post on the block (E4.14 of [1]).

    .. math:: \\omega_{1,2}^2 = k\\,\\frac{(2M + 5m) \\mp \\sqrt{4M^2 - 4Mm + 17m^2}}
              {2m(3M + m)}

    (r cancels). The smaller root is computed as ``omega_1^2 = 2 k^2 / (m (3M + m)
    omega_2^2)`` (the product of the roots, ``det K / det M``): no cancellation.

    Parameters
    ----------
    M : Quantity
        Mass of the block ``[mass]``.
    m : Quantity
        Mass of the disk (homogeneous) ``[mass]``.
    k : Quantity
        Stiffness of each of the two springs ``[force]/[length]``.
    r : Quantity, optional
        Radius of the disk ``[length]``: it cancels from the frequencies (the mode shapes of
        ``modes`` need it).

    Returns
    -------
    Outcome with ``omega_1 < omega_2`` (rad/s), ``f_1``, ``T_1``, ``f_2``, ``T_2``.

    Examples
    --------
    >>> from dyncalc.units import Q_
    >>> out = block_disk_springs(Q_(2, "kg"), Q_(1, "kg"), Q_(100, "N/m"))
    >>> round(out.values["omega_1"].magnitude, 9), round(out.values["omega_2"].magnitude, 9)
    (5.345224838, 10.0)
    """
    with localcontext() as ctx:
        _context(ctx)
        M_, m_, k_ = (Decimal(magnitude(x, u)) for x, u in ((M, "kg"), (m, "kg"), (k, "N/m")))
        root = (4 * M_ * M_ - 4 * M_ * m_ + 17 * m_ * m_).sqrt()
        lam2 = k_ * (2 * M_ + 5 * m_ + root) / (2 * m_ * (3 * M_ + m_))
        lam1 = 2 * k_ * k_ / (m_ * (3 * M_ + m_)) / lam2
        return _two_modes(lam1, lam2, "small oscillations about x = 0, phi = 0; the disk "
                                      "rolls without slipping on the block")


def block_disk_springs_matrices(M: float, m: float, r: float, k: float) -> Linearised:
    """``block-disk-springs`` (SI floats): coordinates x (block), phi (disk, positive when its
    centre C moves backward on the block, so C is at ``x - r phi``).

    ``T = M x'^2/2 + m (x' - r phi')^2/2 + (m r^2/2) phi'^2/2`` gives
    ``M_xx = M + m``, ``M_xphi = -m r``, ``M_phiphi = m r^2 + m r^2/2 = 3 m r^2/2``;
    ``V = k x^2/2 + k (r phi)^2/2`` gives ``K = diag(k, k r^2)`` (exact: both are quadratic).
    """
    return Linearised(("x", "phi"), ("length", "angle"),
                      [[M + m, -m * r], [-m * r, 1.5 * m * r * r]], [[k, 0.0], [0.0, k * r * r]],
                      "x = 0, phi = 0 (both springs unstressed)")


# --- spring-coupled-pendulums (E4.16) --------------------------------------------------------

def pendulums_equilibrium(m: float, l: float, k: float, b: float, g: float) -> float:
    """``phi2_0`` in [0, pi/2): the root of ``m g sin(phi) + k (2 l sin(phi) - b) cos(phi)``,
    by bisection on the scaled form ``a sin(phi) + (2 sin(phi) - beta) cos(phi)``,
    ``a = m g/(k l)``, ``beta = b/l`` (increasing in phi: one root, at 0 when ``b = 0``).

    >>> round(pendulums_equilibrium(1.0, 1.0, 100.0, 0.5, 9.81), 12)
    0.240287326075
    """
    if b == 0.0:
        return 0.0
    with localcontext() as ctx:
        _context(ctx)
        a = _float(Decimal(m) * Decimal(g) / (Decimal(k) * Decimal(l)))
        beta = _float(Decimal(b) / Decimal(l))

    def f(phi: float) -> float:
        s, c = math.sin(phi), math.cos(phi)
        return a * s + (2.0 * s - beta) * c if math.isfinite(a) else s

    lo, hi = 0.0, math.pi / 2
    while True:
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            return hi if abs(f(hi)) < abs(f(lo)) else lo
        if f(mid) > 0.0:
            hi = mid
        else:
            lo = mid


@check_units(m=MASS, l=LENGTH, k=STIFFNESS, b=LENGTH, g=ACCELERATION)
def spring_coupled_pendulums(m, l, k, b, g) -> Outcome:
    """Two equal pendulums on one pivot joined by a spring of free length b (E4.16 of [1]).

    .. math:: \\tan\\varphi_{2,0} = \\frac{k (b - 2 l \\sin\\varphi_{2,0})}{m g}, \\quad
              \\omega_1^2 = \\frac{g \\cos\\varphi_{2,0}}{l}, \\quad
              \\omega_2^2 = \\frac{g}{l \\cos\\varphi_{2,0}} + \\frac{2 k \\cos^2\\varphi_{2,0}}{m}

    Parameters
    ----------
    m : Quantity
        Mass of each bob ``[mass]``.
    l : Quantity
        Length of each (massless) rod ``[length]``.
    k : Quantity
        Spring stiffness ``[force]/[length]``.
    b : Quantity
        Free length of the spring ``[length]`` (>= 0).
    g : Quantity
        Gravity ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega_1`` (the pair swinging together), ``omega_2`` (opening and closing),
    their ``f`` and ``T``, and ``phi2_0`` (half the opening angle at rest).

    Examples
    --------
    With ``b = 0`` the rods hang together: ``omega_1^2 = g/l``, ``omega_2^2 = g/l + 2k/m``.

    >>> from dyncalc.units import Q_
    >>> out = spring_coupled_pendulums(Q_(1, "kg"), Q_(1, "m"), Q_(50, "N/m"), Q_(0, "m"),
    ...                                Q_(9.81, "m/s^2"))
    >>> round(out.values["omega_1"].magnitude ** 2, 9), round(out.values["omega_2"].magnitude ** 2, 9)
    (9.81, 109.81)
    """
    from ..units import Q_

    m_, l_, k_, b_, g_ = (magnitude(x, u) for x, u in ((m, "kg"), (l, "m"), (k, "N/m"),
                                                        (b, "m"), (g, "m/s^2")))
    phi = pendulums_equilibrium(m_, l_, k_, b_, g_)
    with localcontext() as ctx:
        _context(ctx)
        c = Decimal(math.cos(phi))
        m_, l_, k_, g_ = (Decimal(x) for x in (m_, l_, k_, g_))
        lam1 = g_ * c / l_
        lam2 = g_ / (l_ * c) + 2 * k_ * c * c / m_
        out = _two_modes(lam1, lam2, "small oscillations about phi1 = 0, phi2 = phi2_0; "
                                     "massless rods, point bobs, the bobs never cross")
    out.values["phi2_0"] = Q_(phi, "rad")
    out.exact_zeros.add("phi2_0")
    return out


def spring_coupled_pendulums_matrices(m: float, l: float, k: float, b: float, g: float
                                      ) -> Linearised:
    """``spring-coupled-pendulums`` (SI floats): coordinates phi1 (the bisector's angle) and
    phi2 (half the opening), about ``phi1 = 0``, ``phi2 = phi2_0``
    (:func:`pendulums_equilibrium`).

    ``T = m l^2 (phi1'^2 + phi2'^2)`` gives ``M = diag(2 m l^2, 2 m l^2)``;
    ``V = -2 m g l cos(phi1) cos(phi2) + k (2 l sin(phi2) - b)^2/2`` gives, at phi1 = 0,
    ``V_11 = 2 m g l cos(phi2_0)``, ``V_12 = 2 m g l sin(phi1) sin(phi2) = 0``,
    ``V_22 = 2 m g l cos(phi2_0) + k ((2 l cos(phi2_0))^2 - 2 l sin(phi2_0) (2 l sin(phi2_0) - b))``
    (the general form, not yet simplified with the equilibrium condition: the closed form of
    :func:`spring_coupled_pendulums` uses it, so the two agree only if both are right).
    """
    phi = pendulums_equilibrium(m, l, k, b, g)
    s, c = math.sin(phi), math.cos(phi)
    inertia = 2.0 * m * l * l
    k11 = 2.0 * m * g * l * c
    k22 = k11 + k * (4.0 * l * l * c * c - 2.0 * l * s * (2.0 * l * s - b))
    return Linearised(("phi1", "phi2"), ("angle", "angle"), [[inertia, 0.0], [0.0, inertia]],
                      [[k11, 0.0], [0.0, k22]],
                      f"phi1 = 0, phi2 = phi2_0 = {phi:.6g} rad", {"phi2_0": phi})


# --- disk-on-swinging-bar (E4.17) -------------------------------------------------------------

#: Why disk-on-swinging-bar has no frequency (natural-frequency and modes say it).
NO_EQUILIBRIUM = ("disk-on-swinging-bar has no equilibrium with the disk free to slide: at "
                  "rest the disk accelerates outward along the bar at g cos(phi), so there is "
                  "no oscillation about a rest position and no natural frequency; dyncalc "
                  "eom --scene disk-on-swinging-bar derives its equations of motion")


@check_units(m1=MASS, l=LENGTH, m2=MASS, J2=INERTIA, g=ACCELERATION)
def disk_on_swinging_bar(m1, l, m2, J2, g) -> Outcome:
    """A disk sliding freely along a swinging bar (E4.17 of [1]): no equilibrium, so no
    natural frequency; always raises :class:`~dyncalc.errors.PhysicsError` saying why.

    Parameters
    ----------
    m1 : Quantity
        Mass of the bar ``[mass]``.
    l : Quantity
        Length of the bar ``[length]``.
    m2 : Quantity
        Mass of the disk ``[mass]``.
    J2 : Quantity
        The disk's moment of inertia about its centre ``[mass]*[length]^2``.
    g : Quantity
        Gravity ``[length]/[time]^2``.

    >>> from dyncalc.units import Q_
    >>> disk_on_swinging_bar(Q_(1, "kg"), Q_(1, "m"), Q_(1, "kg"), Q_(0.01, "kg*m^2"),
    ...                      Q_(9.81, "m/s^2"))
    Traceback (most recent call last):
    ...
    dyncalc.errors.PhysicsError: disk-on-swinging-bar has no equilibrium ...
    """
    raise PhysicsError(NO_EQUILIBRIUM)


def disk_on_swinging_bar_matrices(values) -> Linearised:
    """What ``modes --scene disk-on-swinging-bar`` solves: nothing, it has no equilibrium;
    always raises :class:`~dyncalc.errors.PhysicsError` (:data:`NO_EQUILIBRIUM`)."""
    raise PhysicsError(NO_EQUILIBRIUM)


# --- pendulum-on-sliding-block (E4.19) ---------------------------------------------------------

@check_units(m1=MASS, m2=MASS, l=LENGTH, g=ACCELERATION)
def pendulum_on_sliding_block(m1, m2, l, g) -> Outcome:
    """A pendulum hanging from a block that slides freely (E4.19 of [1]).

    .. math:: \\omega^2 = \\frac{(m_1 + m_2)\\,g}{m_1 l}

    Parameters
    ----------
    m1 : Quantity
        Mass of the block ``[mass]``.
    m2 : Quantity
        Mass of the bob ``[mass]``.
    l : Quantity
        Length of the (massless) rod ``[length]``.
    g : Quantity
        Gravity ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f``, ``T``; the other mode is the free drift (zero
    frequency), as ``modes --scene pendulum-on-sliding-block`` shows.

    Examples
    --------
    A heavy block: the fixed pendulum's ``g/l``.

    >>> from dyncalc.units import Q_
    >>> out = pendulum_on_sliding_block(Q_(3, "kg"), Q_(1, "kg"), Q_(0.5, "m"),
    ...                                 Q_(9.81, "m/s^2"))
    >>> round(out.values["omega"].magnitude ** 2, 12)
    26.16
    """
    with localcontext() as ctx:
        _context(ctx)
        m1_, m2_, l_, g_ = (Decimal(magnitude(x, u)) for x, u in
                            ((m1, "kg"), (m2, "kg"), (l, "m"), (g, "m/s^2")))
        lam = (m1_ + m2_) * g_ / (m1_ * l_)
        values = periodic(_float(lam.sqrt()))
    return Outcome(values, assumptions=[
        "small swings about phi = 0; the other mode has zero frequency: the block and bob "
        "drift together (the horizontal momentum is conserved)"])


def pendulum_on_sliding_block_matrices(m1: float, m2: float, l: float, g: float
                                       ) -> Linearised:
    """``pendulum-on-sliding-block`` (SI floats): coordinates x (block), phi (rod from the
    downward vertical), about phi = 0.

    ``T = (m1 + m2) x'^2/2 + m2 l x' phi' cos(phi) + m2 l^2 phi'^2/2`` gives, at phi = 0,
    ``M = [[m1 + m2, m2 l], [m2 l, m2 l^2]]``; ``V = -m2 g l cos(phi)`` gives
    ``K = [[0, 0], [0, m2 g l]]``: K is singular, one rigid-body mode (the drift).
    """
    return Linearised(("x", "phi"), ("length", "angle"),
                      [[m1 + m2, m2 * l], [m2 * l, m2 * l * l]], [[0.0, 0.0], [0.0, m2 * g * l]],
                      "phi = 0 (bob below the pin), any x")
