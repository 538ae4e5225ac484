"""The logarithmic decrement fitted to a list of decaying peaks, and a test of their shape.

A free viscously damped oscillation has peaks one cycle apart that fall geometrically,
``x_i = x_0 exp(-delta i)``. Given the measured peaks, :func:`fit_decrement` estimates
``delta`` by least squares, either on ``ln x_i`` (a straight line in ``i``: closed form, every
peak weighted by its relative error) or on ``x_i`` itself (scipy's ``least_squares``, weighting
the large early peaks), reports how far the peaks scatter about the fitted envelope, and warns
when they are not exponential.

The criterion for "not exponential" (both parts are computed on ``ln x_i``, whichever method
fitted ``delta``):

* **systematic** — with four or more peaks, a quadratic term is added to the straight line
  (``ln x_i = a + b u_i + b2 (u_i^2 - mean u^2)``, ``u_i`` the centred index; the three terms
  are orthogonal, so the line is unchanged). The peaks bend systematically when the quadratic
  term is significant at the 0.1 % level (``|t| = |b2| / se(b2)`` above Student's two-sided
  0.999 quantile with ``n - 3`` degrees of freedom) *and* large enough to matter: it changes
  the local decrement across the record by more than 10 % of the fitted one. Coulomb (dry)
  friction, whose peaks fall by the same amount every cycle, bends ``ln x`` downward;
  amplitude-dependent (for instance quadratic, aerodynamic) damping bends it upward; beating
  of two close modes bends it either way.
* **large** — with three or more peaks, the scatter of ``ln x_i`` about the line holds more
  than 1 % of their variation (``R^2 < 0.99``): the decay the fit explains is not much larger
  than the noise, and ``delta`` is poorly determined (its standard error is reported).

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Section 5.2.3 (the logarithmic decrement).
"""
from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field

from ..lazy import numpy as np

from ..errors import PhysicsError

__all__ = ["DecayFit", "fit_decrement", "t_critical", "FIT_METHODS", "R2_LIMIT",
           "CURVATURE_LIMIT"]

#: The fitting methods: the first is the default.
FIT_METHODS = ("log-linear", "nonlinear")

#: Below this coefficient of determination of ``ln x`` the scatter counts as large.
R2_LIMIT = 0.99

#: A significant bend counts when it changes the decrement across the record by more than
#: this fraction of the fitted decrement.
CURVATURE_LIMIT = 0.10

#: Student's t, two-sided 0.1 % (the 0.9995 quantile), for 1 to 30 degrees of freedom.
_T_999 = (636.6192, 31.5991, 12.9240, 8.6103, 6.8688, 5.9588, 5.4079, 5.0413, 4.7809, 4.5869,
          4.4370, 4.3178, 4.2208, 4.1405, 4.0728, 4.0150, 3.9651, 3.9216, 3.8834, 3.8495,
          3.8193, 3.7921, 3.7676, 3.7454, 3.7251, 3.7066, 3.6896, 3.6739, 3.6594, 3.6460)

_TINY, _HUGE = sys.float_info.min, sys.float_info.max

#: The normal 0.9995 quantile.
_Z_999 = 3.2905267314919255


def t_critical(dof: int) -> float:
    """Student's t at which a two-sided test with ``dof`` degrees of freedom is significant
    at the 0.1 % level (the 0.9995 quantile).

    A table to 30 degrees of freedom, the Cornish-Fisher expansion in ``1/dof`` beyond (within
    1e-3 there); no scipy.stats at run time (importing it costs half a second).

    >>> t_critical(1), t_critical(30)
    (636.6192, 3.646)
    >>> round(t_critical(1000), 3)
    3.3
    """
    if dof < 1:
        raise ValueError("at least one degree of freedom is needed")
    if dof <= len(_T_999):
        return _T_999[dof - 1]
    z, v = _Z_999, float(dof)
    return (z + (z ** 3 + z) / (4 * v) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * v ** 2)
            + (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / (384 * v ** 3))


@dataclass
class DecayFit:
    """The fitted envelope ``x0 exp(-delta i)`` of ``n`` peaks and how well it fits.

    ``residual`` is the rms scatter of ``ln x_i`` about the fitted envelope with ``n - 2``
    degrees of freedom (about the relative scatter of the peaks; 0 for two peaks), ``delta_se``
    the standard error of ``delta`` (``None`` for two peaks), ``r_squared`` the coefficient of
    determination of the straight line through ``ln x_i`` (``None`` when the peaks are all
    equal or there are two), ``curvature_t`` the t statistic of the quadratic term and
    ``delta_start``, ``delta_end`` the local decrements it implies at both ends of the record
    (``None`` below four peaks). ``systematic`` and ``scattered`` say which part of the
    criterion fired; ``warnings`` says so in words.
    """

    delta: float
    x0: float
    n: int
    method: str
    residual: float
    delta_se: float | None
    r_squared: float | None
    curvature_t: float | None = None
    delta_start: float | None = None
    delta_end: float | None = None
    systematic: bool = False
    scattered: bool = False
    converged: bool = True
    warnings: list[str] = field(default_factory=list)

    def as_dict(self) -> dict:
        """The fit's numbers for JSON (non-finite values as ``None``)."""
        def clean(v):
            if v is None or isinstance(v, (bool, int, str)):
                return v
            return float(v) if math.isfinite(v) else None

        return {"peaks": self.n, "x0": clean(self.x0), "residual": clean(self.residual),
                "delta_se": clean(self.delta_se), "r_squared": clean(self.r_squared),
                "curvature_t": clean(self.curvature_t), "delta_start": clean(self.delta_start),
                "delta_end": clean(self.delta_end), "systematic": self.systematic,
                "scattered": self.scattered, "converged": self.converged}


def _log_line(y: np.ndarray):
    """Least-squares line through ``y_i`` against the centred index ``u_i = i - (n-1)/2``:
    ``(mean, slope, residuals, Sxx)``. ``sum u = 0``, so the two coefficients are separate
    projections and nothing cancels."""
    n = y.size
    u = np.arange(n) - (n - 1) / 2.0
    mean = math.fsum(y.tolist()) / n
    dev = y - mean
    sxx = n * (n * n - 1) / 12.0               # sum u^2, exactly
    slope = math.fsum((u * dev).tolist()) / sxx
    return mean, slope, dev - slope * u, sxx, u, dev


def fit_decrement(peaks, method: str = "log-linear", rtol: float = 1e-9) -> DecayFit:
    """Fit ``x_i = x0 exp(-delta i)`` to successive peaks ``x_0, x_1, ...`` one cycle apart.

    Parameters
    ----------
    peaks : sequence of float
        At least two positive, finite peak amplitudes in time order (any one unit).
    method : {"log-linear", "nonlinear"}
        ``log-linear``: least squares of ``ln x_i = ln x0 - delta i`` (closed form; equal
        weight to every peak's relative error). ``nonlinear``: least squares of
        ``x_i - x0 exp(-delta i)`` with :func:`scipy.optimize.least_squares` started from the
        log-linear fit (equal weight to every peak's absolute error, as for a fixed
        instrument noise); scipy is imported only for it.
    rtol : float
        Convergence tolerance of the nonlinear fit (relative change of the parameters).

    Returns
    -------
    DecayFit
        ``delta`` may come out negative (growing peaks); the caller decides what to do.

    Examples
    --------
    Peaks that halve every cycle:

    >>> fit = fit_decrement([8.0, 4.0, 2.0, 1.0])
    >>> round(fit.delta, 15) == round(math.log(2), 15), round(fit.x0, 12), fit.warnings
    (True, 8.0, [])

    Peaks of a Coulomb (dry friction) decay fall linearly, not geometrically:

    >>> fit = fit_decrement([10.0, 9.0, 8.0, 7.0, 6.0, 5.0, 4.0, 3.0])
    >>> fit.systematic, round(fit.delta_start, 3), round(fit.delta_end, 3)
    (True, 0.069, 0.266)
    """
    x = np.asarray(peaks, dtype=float)
    n = x.size
    if n < 2:
        raise ValueError("at least two peaks are needed")
    if method not in FIT_METHODS:
        raise ValueError(f"unknown method {method!r}")
    # ln of the peaks scaled exactly by the power of two of the first: |y| stays small, so
    # its rounding is a few 1e-17 absolute, not half an ulp of ln(1e-300) = -690
    shift = math.frexp(float(x[0]))[1]
    scaled = np.ldexp(x, -shift)
    if not np.all((scaled >= _TINY) & (scaled <= _HUGE)):
        # peaks beyond float range of the first (1e-300 after 1e300): the scaled value would
        # underflow or overflow, so take ln from mantissa and exponent apart
        mantissa, exponent = np.frexp(x)
        y = np.log(mantissa) + (exponent - shift) * math.log(2.0)
    else:
        y = np.log(scaled)
    mean, slope, resid, sxx, u, dev = _log_line(y)
    sst = math.fsum((dev * dev).tolist())
    ssr = math.fsum((resid * resid).tolist())
    delta = 0.0 - slope  # 0.0 - 0.0 is +0.0
    # ln x0 = mean - slope * (n - 1)/2, the line at i = 0
    x0 = math.ldexp(math.exp(mean + delta * (n - 1) / 2.0), shift)
    converged = True
    notes: list[str] = []
    if method == "nonlinear":
        delta, x0, model_log, se_nl, converged, why = _nonlinear(
            np.ldexp(x, -shift), delta, math.ldexp(x0, -shift), rtol)
        x0 = math.ldexp(x0, shift)
        if not converged:
            notes.append(f"the nonlinear fit stopped before meeting the tolerance {rtol:g} "
                         f"({why}); delta is the last iterate")
        fit_resid = y - model_log
    else:
        fit_resid = resid
        se_nl = None
    dof = n - 2
    residual = math.sqrt(math.fsum((fit_resid * fit_resid).tolist()) / dof) if dof else 0.0
    if not dof:
        delta_se = None
    elif method == "nonlinear":
        delta_se = se_nl
    else:
        delta_se = math.sqrt(ssr / dof / sxx)

    # the noise floor of ln x from rounding alone: a few ulps of the largest |ln x|
    floor = 4.0 * np.finfo(float).eps * max(1.0, float(np.max(np.abs(y))))
    exact = sst <= n * floor * floor
    r_squared = None if (dof == 0 or exact) else max(0.0, 1.0 - ssr / sst)
    fit = DecayFit(delta=delta, x0=x0, n=n, method=method, residual=residual,
                   delta_se=delta_se, r_squared=r_squared, converged=converged,
                   warnings=notes)
    if r_squared is not None and r_squared < R2_LIMIT and ssr > n * floor * floor:
        fit.scattered = True
    if n >= 4:
        _curvature(fit, u, resid, -slope, floor)
    fit.warnings += _shape_warnings(fit)
    return fit


def _curvature(fit: DecayFit, u: np.ndarray, resid: np.ndarray, line_delta: float,
               floor: float) -> None:
    """Add the quadratic term to the log line and test it (see the module's criterion)."""
    n = u.size
    p2 = u * u - (n * n - 1) / 12.0            # orthogonal to 1 and u on the centred grid
    s22 = math.fsum((p2 * p2).tolist())
    b2 = math.fsum((p2 * resid).tolist()) / s22
    left = resid - b2 * p2
    ssr2 = math.fsum((left * left).tolist())
    se2 = max(math.sqrt(ssr2 / (n - 3) / s22), floor / math.sqrt(s22))
    t = float(b2 / se2)
    # local decrement -(d ln x / di) of the quadratic at i = 0 and i = n - 1
    half = (n - 1) / 2.0
    fit.delta_start = line_delta + 2.0 * b2 * half
    fit.delta_end = line_delta - 2.0 * b2 * half
    fit.curvature_t = t
    change = abs(fit.delta_end - fit.delta_start)
    if abs(t) > t_critical(n - 3) and change > CURVATURE_LIMIT * abs(line_delta):
        fit.systematic = True


def _shape_warnings(fit: DecayFit) -> list[str]:
    out = []
    if fit.systematic:
        how = ("the decrement grows as the peaks shrink, as with Coulomb (dry) friction"
               if fit.delta_end > fit.delta_start else
               "the decrement shrinks as the peaks shrink, as with amplitude-dependent "
               "(e.g. quadratic) damping")
        out.append(f"the peaks are not exponential: ln(x) bends systematically (t = "
                   f"{fit.curvature_t:.3g} for a quadratic term, significant at 0.1%); the "
                   f"decrement per cycle goes from {fit.delta_start:.4g} at the first peak to "
                   f"{fit.delta_end:.4g} at the last: {how}; delta is an average over the "
                   "record")
    if fit.scattered:
        se = f" +/- {fit.delta_se:.2g}" if fit.delta_se is not None else ""
        out.append(f"the peaks are not clearly exponential: their scatter about the fitted "
                   f"envelope (rms {fit.residual:.3g} in ln x) is large next to the decay it "
                   f"explains (R^2 = {fit.r_squared:.4f} < {R2_LIMIT}); delta = "
                   f"{fit.delta:.4g}{se} (standard error)")
    return out


def _nonlinear(x: np.ndarray, delta0: float, x00: float, rtol: float):
    """Least squares of the peaks themselves (scaled near 1 by the caller); returns
    ``(delta, x0, ln of the fitted peaks, se of delta, converged, solver message)``."""
    from scipy.optimize import least_squares

    n = x.size
    scale = float(np.max(x))
    z = x / scale
    if float(np.min(z)) < _TINY:
        raise PhysicsError("--method nonlinear: the peaks span more than float64's range (the "
                           "smallest is below 2.2e-308 of the largest), so their absolute "
                           "errors cannot be fitted; use --method log-linear")
    i = np.arange(n, dtype=float)

    def residuals(p):
        return p[0] * np.exp(-p[1] * i) - z

    def jacobian(p):
        e = np.exp(-p[1] * i)
        return np.column_stack((e, -p[0] * i * e))

    tol = max(float(rtol), 2.3e-16)
    start = np.array([x00 / scale, delta0])
    sol = least_squares(residuals, start, jac=jacobian, method="lm", xtol=tol, ftol=tol,
                        gtol=tol)
    # scipy's LM stops on its cost-change test near sqrt(eps) in delta whatever the tolerance;
    # two Gauss-Newton steps from its answer reach the least-squares point to rounding
    params = np.array(sol.x, dtype=float)
    for _ in range(2):
        step = np.linalg.lstsq(jacobian(params), -residuals(params), rcond=None)[0]
        if not np.all(np.isfinite(step)):
            break
        params = params + step
    amp, delta = float(params[0]), float(params[1])
    ok = bool(sol.success) and sol.status > 0
    se = None
    if n > 2:
        s2 = float(np.sum(sol.fun ** 2)) / (n - 2)
        try:
            cov = np.linalg.inv(sol.jac.T @ sol.jac) * s2
            se = math.sqrt(max(float(cov[1, 1]), 0.0))
        except np.linalg.LinAlgError:
            se = math.inf
    model_log = math.log(amp) - delta * i if amp > 0 else np.full(n, -math.inf)
    return delta, amp * scale, model_log + math.log(scale), se, ok, sol.message
