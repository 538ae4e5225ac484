"""The slips students make in the rigid-body load scenes, for ``--check`` (joined to
:data:`dyncalc.commands.rigid_slips.SLIPS`): each function maps the SI inputs and results to
``{result: {slip: value}}``."""
from __future__ import annotations

__all__ = ["LOAD_SLIPS"]


def _angled_bar_on_shaft(v: dict) -> dict:
    """The product of inertia ``J_xizeta = -m l^2/3`` with the wrong sign (the bearings swap
    their shares) or left out (each bearing takes half)."""
    m, l, M0, w = v["m"], v["l"], v["M0"], v["omega"]
    sign = "the sign of the product of inertia J_xizeta wrong (+m l^2/3)"
    left_out = "the product of inertia J_xizeta left out (the bearings share equally)"
    c = m * l * w * w
    return {"A_eta": {sign: 21.0 * M0 / (80.0 * l), left_out: 0.3 * M0 / l},
            "B_eta": {sign: 27.0 * M0 / (80.0 * l), left_out: 0.3 * M0 / l},
            "A_xi": {sign: -7.0 * c / 12.0, left_out: -2.0 * c / 3.0},
            "B_xi": {sign: -0.75 * c, left_out: -2.0 * c / 3.0}}


def _precessing_shaft(v: dict) -> dict:
    """The book's misprinted ``M2 = (J1 - J3) omega0 alpha'`` (at ``psi = 0``, where the derived
    value is ``(J1 + J2 - J3) omega0 alpha'``)."""
    if v.get("psi", 0.0) != 0.0:
        return {}
    J2 = v.get("J2", v["J3"])
    return {"M2": {"the rate of the body-fixed omega_2 taken as zero (the book's misprint "
                   "(J1 - J3) omega0 alpha')": v["M2"] - J2 * v["omega0"] * v["alpha_dot"]}}


def _beam_spun_up(v: dict) -> dict:
    """The moment of inertia about the centre, ``m l^2/12``, used about the pin."""
    why = "the moment of inertia about the centre (m l^2/12) used about the pin"
    alpha = 12.0 * v["M0"] / (v["m"] * v["l"] ** 2)
    found = {"alpha": {why: alpha}}
    if "t" in v:
        found["omega"] = {why: alpha * v["t"]}
    return found


#: Scene name -> its slips.
LOAD_SLIPS = {"angled-bar-on-shaft": _angled_bar_on_shaft,
              "precessing-shaft": _precessing_shaft, "beam-spun-up": _beam_spun_up}
