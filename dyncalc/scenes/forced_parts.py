"""The parts the forced scenes share (dyncalc.scenes.forced and dyncalc.scenes.sdof): the
damping and excitation-frequency parameters and the steady-state formula lines in LaTeX."""
from __future__ import annotations

from ..result.explain import Formula
from ..units import ANGULAR_RATE, CYCLE_RATE, DAMPING, DIMENSIONLESS
from . import Param

__all__ = ["_damping", "_frequency", "_STEADY_LATEX"]


def _damping() -> tuple[Param, ...]:
    return (Param("zeta", DIMENSIONLESS, "damping ratio (default 0: undamped)", default="0",
                  constraint="nonnegative"),
            Param("c", DAMPING, "viscous damping coefficient", optional=True,
                  constraint="nonnegative"),
            Param("Q", DIMENSIONLESS, "quality factor 1/(2 zeta)", optional=True))


def _frequency() -> tuple[Param, ...]:
    return (Param("Omega", ANGULAR_RATE, "excitation angular frequency", optional=True,
                  constraint="nonnegative"),
            Param("f_exc", CYCLE_RATE, "excitation frequency", optional=True,
                  constraint="nonnegative", symbol=r"f_{\mathrm{exc}}"))


def _has(name: str):
    return lambda v: name in v


#: D = sqrt((1 - eta^2)^2 + (2 zeta eta)^2) in the templates.
_D = r"\sqrt{(1 - $eta^2)^2 + (2\,$zeta\,$eta)^2}"
_NUM = r"\sqrt{1 + (2\,$zeta\,$eta)^2}"

_STEADY_LATEX = (
    r"$omega = \sqrt{\frac{$k}{$m}}",
    r"$eta = \frac{$Omega}{$omega}",
    r"$eta = \frac{2\pi\,$f_exc}{$omega}",
    r"$zeta = \frac{$c}{2\,\sqrt{$k\,$m}}",
    Formula(r"$V = \frac{1}{" + _D + "}", lambda v: "F0" in v or "base_accel" in v),
    Formula(r"$V = \frac{$eta^2}{" + _D + "}", _has("unbalance")),
    Formula(r"$V = \frac{" + _NUM + "}{" + _D + "}", _has("base")),
    r"$X = \frac{$F0}{$k}\,$V",
    r"$X = $base\,$V",
    r"$X = \frac{$base_accel}{$omega^2}\,$V",
    r"$X = \frac{$unbalance}{$m}\,$V",
    Formula(r"$phi = \mathrm{atan2}\left(2\,$zeta\,$eta,\ 1 - $eta^2\right)",
            lambda v: "base" not in v),
    Formula(r"$phi = \mathrm{atan2}\left(2\,$zeta\,$eta^3,\ 1 - $eta^2 + (2\,$zeta\,$eta)^2"
            r"\right)", _has("base")),
    r"$TR = \frac{" + _NUM + "}{" + _D + "}",
    r"$F_T = $TR\,$F0",
    r"$F_T = $TR\,$unbalance\,$Omega^2",
    r"$F_T = $m\,$Omega^2\,$X",
    r"$F_T = $TR\,$m\,$base_accel",
    r"$Z = \frac{$base\,$eta^2}{" + _D + "}",
    r"$Z = $X",
    Formula(r"$V_res = \frac{\sqrt{1 + 4\,$zeta^2}}{2\,$zeta}", _has("base")),
    r"$V_res = \frac{1}{2\,$zeta}",
    Formula(r"$Omega_peak = $omega\,\sqrt{\frac{2}{1 + \sqrt{1 + 8\,$zeta^2}}}", _has("base")),
    Formula(r"$Omega_peak = \frac{$omega}{\sqrt{1 - 2\,$zeta^2}}", _has("unbalance")),
    r"$Omega_peak = $omega\,\sqrt{1 - 2\,$zeta^2}",
    Formula(r"$V_peak = \frac{1}{2\,$zeta\,\sqrt{1 - $zeta^2}}", lambda v: "base" not in v),
    r"$Omega_iso = \sqrt{2}\,$omega",
    r"$isolation = 1 - $TR",
    Formula(r"$bandwidth = $omega\,\left(\sqrt{1 - 2\,$zeta^2 + 2\,$zeta\,\sqrt{1 - $zeta^2}}"
            r" - \sqrt{1 - 2\,$zeta^2 - 2\,$zeta\,\sqrt{1 - $zeta^2}}\right)",
            lambda v: "F0" in v or "base_accel" in v),
    r"$Q = \frac{1}{2\,$zeta}",
)
