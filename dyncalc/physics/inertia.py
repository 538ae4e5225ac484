"""Mass and moments of inertia of the standard bodies, each about its own centre of mass in its
own axes (the symmetry axis, a rod's length or a plate's normal along local ``z``).

.. math:: J_{C} = \\operatorname{diag}(J_{xx}, J_{yy}, J_{zz}), \\qquad
          J_{zz}^{\\text{disk}} = \\tfrac12 m r^2,\\ J_{xx}^{\\text{disk}} = \\tfrac14 m r^2

Every body is homogeneous. Thin bodies (``rod``, ``ring``, ``disk``, ``plate``,
``hollow-sphere``, ``half-cylinder-shell``) have no thickness; ``hollow-cylinder`` is a thick
tube (``ri < ro``). A density stands in for the mass: linear (``[mass]/[length]``) for rods and
rings, areal (``[mass]/[length]^2``) for disks, plates and shells, volume
(``[mass]/[length]^3``) for the solid bodies (:data:`DENSITY_KIND`).

The half-cylinder shell (radius ``r``, height ``h``) is the half ``x >= 0`` of a thin
cylindrical shell about local ``z``: its centre of mass lies ``2 r / pi`` off the axis, on
local ``x``; its *reference point*, the one ``at=`` places, is the middle of the axis, not the
centroid (:func:`reference_offset`).

The scalar formulas (:func:`rod_about_end`, :func:`disk_about_axis`,
:func:`disk_about_parallel_axis`) take floats or the double-double numbers of
:mod:`dyncalc.physics.numerics` alike: the rigid-body scenes use them.

Numbers are plain SI floats (kg, m).

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Section 3.2.3 (moments of inertia, Table 3.1).
"""
from __future__ import annotations

import math
from fractions import Fraction

from ..errors import InputError

__all__ = ["BODY_DIMENSIONS", "DENSITY_KIND", "AXIAL_FACTOR", "FORMULAS", "mass_from_density",
           "principal_local", "reference_offset", "rod_about_end", "disk_about_axis",
           "disk_about_parallel_axis", "check_dimensions"]

#: The dimensions (lengths) each body takes, in order.
BODY_DIMENSIONS: dict[str, tuple[str, ...]] = {
    "rod": ("l",), "disk": ("r",), "ring": ("r",), "solid-sphere": ("r",),
    "hollow-sphere": ("r",), "solid-cylinder": ("r", "h"), "hollow-cylinder": ("ri", "ro", "h"),
    "plate": ("a", "b"), "half-cylinder-shell": ("r", "h"), "point": (),
}

#: What ``rho=`` is for each body: ``linear``, ``areal`` or ``volume`` density (a point has
#: none: it takes ``m=``).
DENSITY_KIND: dict[str, str] = {
    "rod": "linear", "ring": "linear", "disk": "areal", "plate": "areal",
    "hollow-sphere": "areal", "half-cylinder-shell": "areal", "solid-sphere": "volume",
    "solid-cylinder": "volume", "hollow-cylinder": "volume",
}

#: ``J / (m r^2)`` about the symmetry axis through the centre, exactly, of the round bodies
#: whose mass sits at one radius or fills it (a thin tube and a hoop: 1).
AXIAL_FACTOR: dict[str, Fraction] = {
    "ring": Fraction(1), "disk": Fraction(1, 2), "solid-cylinder": Fraction(1, 2),
    "solid-sphere": Fraction(2, 5), "hollow-sphere": Fraction(2, 3),
    "half-cylinder-shell": Fraction(1),
}

#: Each body's mass from its density and its moments about its centre in local axes (text).
FORMULAS: dict[str, tuple[str, str]] = {
    "rod": ("m = rho l", "J_xx = J_yy = m l^2/12, J_zz = 0"),
    "disk": ("m = rho pi r^2", "J_xx = J_yy = m r^2/4, J_zz = m r^2/2"),
    "ring": ("m = rho 2 pi r", "J_xx = J_yy = m r^2/2, J_zz = m r^2"),
    "solid-sphere": ("m = rho 4 pi r^3/3", "J_xx = J_yy = J_zz = 2 m r^2/5"),
    "hollow-sphere": ("m = rho 4 pi r^2", "J_xx = J_yy = J_zz = 2 m r^2/3"),
    "solid-cylinder": ("m = rho pi r^2 h", "J_xx = J_yy = m (3 r^2 + h^2)/12, J_zz = m r^2/2"),
    "hollow-cylinder": ("m = rho pi (ro^2 - ri^2) h",
                        "J_xx = J_yy = m (3 (ri^2 + ro^2) + h^2)/12, J_zz = m (ri^2 + ro^2)/2"),
    "plate": ("m = rho a b", "J_xx = m b^2/12, J_yy = m a^2/12, J_zz = m (a^2 + b^2)/12"),
    "half-cylinder-shell": ("m = rho pi r h",
                            "J_xx = m (r^2/2 + h^2/12), J_yy = m (r^2/2 + h^2/12 - 4 r^2/pi^2), "
                            "J_zz = m r^2 (1 - 4/pi^2); centre 2 r/pi off the axis on x"),
    "point": ("", "J = 0"),
}


def rod_about_end(m, l):
    """A uniform rod about a transverse axis through one end: ``m l^2 / 3``.

    >>> rod_about_end(3.0, 2.0)
    4.0
    """
    return m * l * l / 3.0


def disk_about_axis(m, r):
    """A homogeneous disk (or solid cylinder) about its axis: ``m r^2 / 2``.

    >>> disk_about_axis(2.0, 0.5)
    0.25
    """
    return m * r * r / 2.0


def disk_about_parallel_axis(m, r, a):
    """A homogeneous disk about an axis parallel to its own, ``a`` away (parallel-axis
    theorem): ``m (r^2/2 + a^2)``.

    >>> disk_about_parallel_axis(2.0, 0.5, 1.0)
    2.25
    """
    return m * (r * r / 2.0 + a * a)


def check_dimensions(kind: str, dims: dict[str, float], label: str) -> None:
    """Refuse what no body has: a tube whose inner radius is not below the outer one.
    (Each dimension is positive already: the reader refuses zero and negative lengths.)"""
    if kind == "hollow-cylinder" and not dims["ri"] < dims["ro"]:
        raise InputError(f"{label}: the inner radius ri must be less than the outer radius ro; "
                         f"got ri = {dims['ri']:.6g} m, ro = {dims['ro']:.6g} m")


def mass_from_density(kind: str, rho: float, dims: dict[str, float]) -> float:
    """The mass of body ``kind`` of density ``rho`` (SI: kg/m, kg/m^2 or kg/m^3 as
    :data:`DENSITY_KIND` says) and dimensions ``dims`` (m).

    >>> round(mass_from_density("solid-sphere", 1000.0, {"r": 0.1}), 6)  # 4/3 pi 0.001 t
    4.18879
    """
    d = dims
    if kind == "rod":
        return rho * d["l"]
    if kind == "ring":
        return rho * 2.0 * math.pi * d["r"]
    if kind == "disk":
        return rho * math.pi * (d["r"] * d["r"])
    if kind == "plate":
        return rho * d["a"] * d["b"]
    if kind == "hollow-sphere":
        return rho * 4.0 * math.pi * (d["r"] * d["r"])
    if kind == "half-cylinder-shell":
        return rho * math.pi * d["r"] * d["h"]
    if kind == "solid-sphere":
        return rho * 4.0 * math.pi * (d["r"] * d["r"] * d["r"]) / 3.0
    if kind == "solid-cylinder":
        return rho * math.pi * (d["r"] * d["r"]) * d["h"]
    if kind == "hollow-cylinder":
        return rho * math.pi * (d["ro"] * d["ro"] - d["ri"] * d["ri"]) * d["h"]
    raise InputError(f"{kind}() takes m=, not a density")


def principal_local(kind: str, m: float, dims: dict[str, float]) -> tuple[float, float, float]:
    """``(J_xx, J_yy, J_zz)`` of body ``kind`` (mass ``m`` kg, dimensions ``dims`` m) about its
    centre of mass, in its own axes (kg*m^2); the products of inertia there are zero.

    >>> principal_local("solid-cylinder", 12.0, {"r": 1.0, "h": 2.0})
    (7.0, 7.0, 6.0)
    """
    d = dims
    if kind == "point":
        return (0.0, 0.0, 0.0)
    if kind == "rod":
        across = m * (d["l"] * d["l"]) / 12.0
        return (across, across, 0.0)
    if kind in ("disk", "ring", "solid-sphere", "hollow-sphere"):
        axial = float(AXIAL_FACTOR[kind]) * m * (d["r"] * d["r"])
        across = axial if "sphere" in kind else axial / 2.0
        return (across, across, axial)
    if kind == "solid-cylinder":
        r2, h2 = (d["r"] * d["r"]), (d["h"] * d["h"])
        return (m * (3.0 * r2 + h2) / 12.0, m * (3.0 * r2 + h2) / 12.0, m * r2 / 2.0)
    if kind == "hollow-cylinder":
        s2, h2 = d["ri"] * d["ri"] + d["ro"] * d["ro"], (d["h"] * d["h"])
        return (m * (3.0 * s2 + h2) / 12.0, m * (3.0 * s2 + h2) / 12.0, m * s2 / 2.0)
    if kind == "plate":
        a2, b2 = (d["a"] * d["a"]), (d["b"] * d["b"])
        return (m * b2 / 12.0, m * a2 / 12.0, m * (a2 + b2) / 12.0)
    if kind == "half-cylinder-shell":
        r2, h2 = (d["r"] * d["r"]), (d["h"] * d["h"])
        about_axis_x = m * (r2 / 2.0 + h2 / 12.0)
        offset2 = 4.0 * r2 / math.pi ** 2
        return (about_axis_x, about_axis_x - m * offset2, m * (r2 - offset2))
    raise InputError(f"unknown body {kind!r}")


def reference_offset(kind: str, dims: dict[str, float]) -> tuple[float, float, float]:
    """Where the centre of mass lies from the point ``at=`` places, in the body's own axes
    (m): ``(2 r / pi, 0, 0)`` for a half-cylinder shell (``at=`` is the middle of its axis),
    the origin for every other body (``at=`` is its centre).

    >>> reference_offset("half-cylinder-shell", {"r": math.pi, "h": 1.0})
    (2.0, 0.0, 0.0)
    """
    if kind == "half-cylinder-shell":
        return (2.0 * dims["r"] / math.pi, 0.0, 0.0)
    return (0.0, 0.0, 0.0)
