"""The slips students make in the rigid-body scenes, for ``--check`` (issue 21, item 3): each
scene's function maps its SI inputs and results to ``{result: {slip: value}}``; ``--check``
names the slip a wrong answer matches (:mod:`dyncalc.result.checks`)."""
from __future__ import annotations

import math

from .rigid_load_slips import LOAD_SLIPS

__all__ = ["SLIPS", "add_slips"]


def _drum_two_blocks(v: dict) -> dict:
    m1, m2, r1, r2, J, g = (v[n] for n in ("m1", "m2", "r1", "r2", "J_A", "g"))
    if J <= 0.0:
        return {}
    alpha = (m2 * r2 - m1 * r1) * g / J
    why = "the blocks' inertia left out (the rope forces taken as the weights m g)"
    return {"alpha": {why: alpha}, "a1": {why: r1 * alpha}, "a2": {why: r2 * alpha},
            "S1": {"the rope force taken as the weight m1 g": m1 * g},
            "S2": {"the rope force taken as the weight m2 g": m2 * g}}


def _wheel_incline_block(v: dict) -> dict:
    m1, m2, g = v["m1"], v["m2"], v["g"]
    s = math.sin(v["beta"])
    q = v["J_A"] / v["r"] ** 2 if "J_A" in v else v["kappa"] * m1
    drive = g * (m2 - m1 * s)
    return {"a": {"the wheel's rotation left out (J_A/r^2 missing)": drive / (m1 + m2),
                  "J about the contact point used for J_A (a parallel-axis term m1 r^2 too "
                  "many)": drive / (2.0 * m1 + m2 + q)}}


def _two_drums_rope_drive(v: dict) -> dict:
    m1, m2, r1, r2, J1, J2, M0, g = (v[n] for n in ("m1", "m2", "r1", "r2", "J1", "J2", "M0",
                                                     "g"))
    top = g * (m2 * r2 * r2 - m1 * r1 * r2) + M0 * r2
    base = m2 * r2 * r2 + m1 * r1 * r1
    return {"a2": {"the inertia of drum 2 left out": top / (base + J1),
                   "the drums' inertia left out": top / base if base > 0 else math.nan}}


def _direct_central_impact(v: dict) -> dict:
    m1, m2, v1, v2 = v["m1"], v["m2"], v["v1"], v["v2"]
    total = m1 + m2
    v_c = (m1 * v1 + m2 * v2) / total
    elastic = "the impact taken as elastic (e = 1)"
    return {"v1_post": {elastic: v_c - m2 * (v1 - v2) / total,
                        "the bodies taken to move on together (e = 0)": v_c},
            "v2_post": {elastic: v_c + m1 * (v1 - v2) / total,
                        "the bodies taken to move on together (e = 0)": v_c},
            "dE": {"the energy loss of a plastic impact (e = 0)":
                   m1 * m2 * (v1 - v2) ** 2 / (2.0 * total)}}


def _double_pendulum_impulse(v: dict) -> dict:
    """Bar 1's moment of inertia about its centre (m l^2/12) taken about the pin A: the
    impulse-momentum equations solved with it."""
    from ..lazy import numpy as np

    m, l, F = v["m"], v["l"], v["F_hat"]
    d = v.get("d", 5.0 * l / 8.0)
    J_A1, J_C2 = m * l * l / 12.0, m * l * l / 12.0
    system = np.array([[J_A1, 0.0, -l, 0.0],
                       [m * l, m * l / 2.0, 1.0, 0.0],
                       [0.0, J_C2, -l / 2.0, 0.0],
                       [m * l / 2.0, 0.0, -1.0, -1.0]])
    rhs = np.array([0.0, F, F * (l / 2.0 - d), 0.0])
    w1, w2, B, A = (float(x) for x in np.linalg.solve(system, rhs))
    why = "bar 1's moment of inertia about its centre used about the pin A (the parallel-axis " \
          "term m (l/2)^2 left out)"
    return {"omega_1": {why: w1}, "omega_2": {why: w2}, "B_hat": {why: B}, "A_hat": {why: A},
            "v_2": {why: l * w1 + l * w2 / 2.0}}


#: Scene name -> its slips (a scene without an entry has none).
SLIPS = {"drum-two-blocks": _drum_two_blocks, "wheel-incline-block": _wheel_incline_block,
         "two-drums-rope-drive": _two_drums_rope_drive,
         "direct-central-impact": _direct_central_impact,
         "double-pendulum-impulse": _double_pendulum_impulse}
SLIPS.update(LOAD_SLIPS)


def add_slips(scene: str, result) -> None:
    """Add scene ``scene``'s slips at the values of ``result`` (inputs and results, SI) to
    ``result.slips``; none when a value is missing (an inverse problem still has them all)."""
    slips = SLIPS.get(scene)
    if slips is None:
        return
    values = {name: entry.si for name, entry in [*result.inputs.items(),
                                                 *result.results.items()]
              if isinstance(entry.si, float)}
    if "body" in result.inputs and "kappa" not in values:
        from ..scenes import get_scene

        values["kappa"] = float(get_scene(scene).param("body").choices[result.inputs["body"].si])
    try:
        found = slips(values)
    except (KeyError, ArithmeticError, ValueError):
        return
    for name, entries in found.items():
        if name in result.results:
            result.slips.setdefault(name, {}).update(
                {why: value for why, value in entries.items() if math.isfinite(value)})
