"""The catalog's single-degree-of-freedom scenes driven on their coordinate: effective mass
(or moment of inertia) and stiffness, then the forced oscillator of :mod:`.forced`.

A scene's small motion in its coordinate ``q`` obeys ``m_eff q'' + c q' + k_eff q = F0
cos(Omega t)``: ``m_eff`` is the coefficient of ``q'^2/2`` in the kinetic energy, ``k_eff``
that of ``q^2/2`` in the linearised potential energy, ``F0`` the generalized force on ``q``
(a force for a displacement, a torque for an angle). The natural frequency is the scene's
own, from the very function natural-frequency calls, so ``omega`` is natural-frequency's to
the bit; ``m_eff`` comes from the same formulas that function divides by (the rigid-body
scenes' inertias of :mod:`.rigid`, the ``J_A`` a scene reports), and ``k_eff = m_eff
omega^2``. Where a scene's frequency does not depend on its mass (a pendulum), the forced
variant takes the mass ``m`` besides its own parameters.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapters 3 to 5 (kinetic energies of the rigid-body set-ups).
.. [2] Rao, *Mechanical Vibrations*, 6th ed., Pearson 2017, Section 3.4 (harmonic force).
"""
from __future__ import annotations

import math

from ..errors import PhysicsError
from .face import magnitude
from .forced import forced_response
from .numerics import Wide
from .outcome import Outcome
from .rigid import drum_block_inertia, pulley_block_inertia, rolling_inertia, wheel_beam_inertia

__all__ = ["INERTIAS", "forced_coordinate"]

#: The SI units of the forcing parameters, for a displacement and for an angle.
_UNITS = {False: {"F0": "N", "c": "N*s/m", "x0": "m", "v0": "m/s"},
          True: {"F0": "N*m", "c": "N*m*s/rad", "x0": "rad", "v0": "rad/s"}}


def _kg(p, name="m"):
    return magnitude(p[name], "kg")


def _m(p, name):
    return magnitude(p[name], "m")


def _kappa(p):
    return float(p.get("kappa", 0.5))


def _wide(function, *values) -> float:
    return float(function(*(Wide(v) if isinstance(v, float) else v for v in values)))


#: Scene name -> ``m_eff(parameters, natural values)`` in kg (a displacement) or kg*m^2 (an
#: angle): ``parameters`` are the keyword arguments of the scene's physics function (with the
#: mass ``m`` where the variant adds it), ``natural`` the SI values it returned.
INERTIAS = {
    "mass-spring": lambda p, n: _kg(p),
    "torsional": lambda p, n: magnitude(p["J"], "kg*m**2"),
    # the bob m at l: J = m l^2
    "pendulum": lambda p, n: _kg(p) * _m(p, "l") ** 2,
    "physical-pendulum": lambda p, n: n["J_A"],
    "rolling-disk-spring": lambda p, n: _wide(rolling_inertia, _kg(p), _kappa(p)),
    # the centre's arc length s = (R - r) psi: T = (1 + kappa) m s'^2 / 2
    "rolling-in-track": lambda p, n: _wide(rolling_inertia, _kg(p), _kappa(p)),
    "drum-block-spring": lambda p, n: _wide(drum_block_inertia, _kg(p), _kg(p, "M")),
    "board-on-drums": lambda p, n: _kg(p),
    "clock-pendulum": lambda p, n: n["J_A"],
    "pulley-block-spring": lambda p, n: _wide(pulley_block_inertia, _kg(p), _kg(p, "M")),
    "disk-torsion-offset-mass": lambda p, n: n["J_A"],
    "wheel-on-moving-beam": lambda p, n: _wide(wheel_beam_inertia, _kg(p), _kg(p, "M"),
                                               _kappa(p)),
    # m the whole bar (3 l long, m/3 per l): J_A = 7 (m/3) l^2
    "angled-member": lambda p, n: 7.0 * _kg(p) * _m(p, "l") ** 2 / 3.0,
    # about the contact point upright: J_P = m r^2 (2 - 4/pi)
    "half-cylinder-shell": lambda p, n: (2.0 - 4.0 / math.pi) * _kg(p) * _m(p, "r") ** 2,
    # massless rod, point mass at the tip
    "rod-torsion-spring": lambda p, n: _kg(p) * _m(p, "l") ** 2,
    "pendulum-accelerating-support": lambda p, n: _kg(p) * _m(p, "l") ** 2,
    "pendulum-on-rotating-disk": lambda p, n: _kg(p) * _m(p, "l") ** 2,
    "bead-on-rotating-ring": lambda p, n: _kg(p) * _m(p, "r") ** 2,
    # the point mass at 2a: J = 4 m a^2
    "pendulum-spring-dashpot": lambda p, n: 4.0 * _kg(p) * _m(p, "a") ** 2,
    # a uniform rod about its end: J = m l^2 / 3
    "rod-in-fluid": lambda p, n: _kg(p) * _m(p, "l") ** 2 / 3.0,
}


def _si_values(values: dict) -> dict:
    """A scene outcome's values as SI floats (a quantity in its SI base, a number as is)."""
    out = {}
    for name, value in values.items():
        if hasattr(value, "units"):
            out[name] = float(value.to_base_units().magnitude)
        elif isinstance(value, (int, float)):
            out[name] = float(value)
    return out


def forced_coordinate(scene: str, natural, own: dict, forcing: dict, *, rotation: bool,
                      mass=None, own_damping: bool = False) -> Outcome:
    """Scene ``scene`` driven on its coordinate: its small motion as
    ``m_eff q'' + c q' + k_eff q = F0 cos(Omega t)``.

    .. math:: \\omega = \\omega_{scene}, \\quad m_{eff} = \\text{the scene's inertia in } q,
              \\quad k_{eff} = m_{eff}\\,\\omega^2, \\quad X = \\frac{F_0}{k_{eff}}\\,V

    Parameters
    ----------
    scene : str
        The catalog name (the key of :data:`INERTIAS`).
    natural : callable
        The scene's physics function (natural-frequency's), called with ``own``.
    own : dict
        The scene's own parameters, as its physics function takes them.
    forcing : dict
        ``zeta``, ``c`` or ``Q`` (damping; ``c`` ``[force]*[time]/[length]``, or
        ``[force]*[length]*[time]/[angle]`` for an angle), ``F0`` (force ``[force]`` or torque
        ``[force]*[length]``), ``Omega`` or ``f_exc``, and ``x0``, ``v0``, ``t``.
    rotation : bool
        Whether the coordinate is an angle (``X`` in rad, ``F_T`` a moment).
    mass : Quantity, optional
        The mass ``[mass]``, for a scene whose frequency does not need it.
    own_damping : bool
        The scene's own ``zeta`` (a dashpot, a drag) damps the motion.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``m_eff`` (kg or kg*m^2), ``k_eff`` (N/m or N*m/rad) and
    the results of :func:`~dyncalc.physics.forced.forced_response` in SI (``X`` in m or rad).

    Examples
    --------
    A drum-and-block (E5.12 of [1]: k = 2 kN/m, m = 4 kg, M = 10 kg) pushed by 10 N at
    10 rad/s: ``m_eff = m + M/2 = 9 kg``, ``X = F0/(k - m_eff Omega^2)``:

    >>> from dyncalc.physics.rigid import drum_block_spring
    >>> out = forced_coordinate("drum-block-spring", drum_block_spring,
    ...                         {"k": 2000.0, "m": 4.0, "M": 10.0}, {"F0": 10.0, "Omega": 10.0},
    ...                         rotation=False)
    >>> out.values["m_eff"], round(out.values["X"], 15), round(10 / (2000 - 900), 15)
    (9.0, 0.009090909090909, 0.009090909090909)
    """
    outcome = natural(**own)
    values = _si_values(outcome.values)
    omega = values["omega"]
    if not (omega > 0.0 and math.isfinite(omega)):
        raise PhysicsError(f"{scene} has no oscillation here (omega = {omega:.6g} rad/s): "
                           "its linear stiffness vanishes, so a harmonic drive has no steady "
                           "amplitude")
    parameters = dict(own)
    if mass is not None:
        parameters["m"] = mass
    m_eff = INERTIAS[scene](parameters, values)
    units = _UNITS[rotation]
    kwargs = {name: (magnitude(value, units[name]) if name in units else value)
              for name, value in forcing.items() if value is not None}
    if own_damping:
        kwargs["zeta"] = values["zeta"]
    out = forced_response(omega=omega, m=m_eff, **kwargs)
    result = {"omega": out.values["omega"], "m_eff": m_eff, "k_eff": m_eff * omega * omega}
    result.update((name, value) for name, value in out.values.items() if name != "omega")
    for name in ("phi_0", "theta_eq"):
        if name in values:
            result[name] = values[name]
    return Outcome(result, warnings=[*outcome.warnings, *out.warnings],
                   assumptions=[*(a for a in outcome.assumptions if "--amplitude" not in a),
                                *out.assumptions],
                   exact_zeros=set(outcome.exact_zeros))
