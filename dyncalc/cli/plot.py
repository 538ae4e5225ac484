"""``--plot``: pictures of a result, drawn with matplotlib (imported only when a plot is asked
for). Today the free decay of a ``damping-ratio`` result; nothing here computes a result."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..result import Result, format_number

__all__ = ["plot_decay", "plot_forced", "plot_loads", "plot_coriolis", "PLOT_FORMATS"]

PLOT_FORMATS = (".png", ".svg", ".pdf")


def plot_decay(result: Result, path: str) -> str:
    """Draw the free decay of a damping-ratio result into ``path`` (PNG, SVG or PDF).

    For fitted peaks: the measured peaks with the fitted envelope ``x0 exp(-delta i)``, on a
    linear and on a logarithmic axis (where an exponential decay is a straight line). Otherwise:
    the response ``x(t)`` from a unit initial displacement released from rest, over a few
    periods, with its envelope; in seconds when the natural frequency is known, else against
    damped cycles (or ``omega t``) with a warning saying so. matplotlib is imported here only,
    with its Agg canvas (no display needed). Returns the path written.
    """
    target = Path(path)
    if target.suffix.lower() not in PLOT_FORMATS:
        raise InputError(f"--plot: {path[:80]!r} must end in "
                         f"{', '.join(PLOT_FORMATS[:-1])} or {PLOT_FORMATS[-1]}")
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError("--plot needs matplotlib: pip install 'dyncalc[plot]'") from None

    zeta = result.results.get("zeta")
    if "amplitudes" not in result.inputs and (zeta is None or zeta.overflowed):
        raise InputError(f"--plot: zeta overflows float64 at these inputs, so there is no "
                         f"decay to draw; {path[:80]!r} was not written")
    fig = Figure(figsize=(9.0, 4.8), dpi=100, layout="constrained")
    FigureCanvasAgg(fig)
    if "amplitudes" in result.inputs:
        _draw_peaks(fig, result)
    else:
        _draw_response(fig, result)
    _save(fig, target, path)
    result.extra["plot"] = str(target)
    return str(target)


def _value(result: Result, name: str):
    entry = result.results.get(name)
    if entry is None or entry.overflowed or not isinstance(entry.si, float):
        return None
    return entry.si


def _natural_frequency(result: Result):
    if "omega" in result.results:
        return _value(result, "omega")
    if "omega" in result.inputs:
        return result.inputs["omega"].si
    return None


def _draw_peaks(fig, result: Result) -> None:
    peaks = np.asarray(result.inputs["amplitudes"].si, dtype=float)
    unit = result.inputs["amplitudes"].unit
    fit = result.extra["fit"]
    delta, x0 = _value(result, "delta") or 0.0, fit["x0"]
    zeta = _value(result, "zeta")
    n = peaks.size
    period = _value(result, "T_d")
    cycles = np.arange(n)
    fine = np.linspace(0.0, n - 1, 400)
    with np.errstate(over="ignore"):  # a period near 1e308 s: its multiples leave float64
        timed = None if period is None else (cycles * period, fine * period)
    if timed is not None and np.isfinite(timed[0]).all() and np.isfinite(timed[1]).all():
        xs, xf, xlabel = timed[0], timed[1], "time since the first peak (s)"
    else:
        xs, xf, xlabel = cycles, fine, "cycle i"
    envelope = x0 * np.exp(-delta * fine)
    label_fit = f"fitted envelope x0 exp(-δ i), δ = {delta:.4g} ({result.method})"
    ylabel = f"peak amplitude ({unit})" if unit else "peak amplitude"
    for ax, log in ((fig.add_subplot(1, 2, 1), False), (fig.add_subplot(1, 2, 2), True)):
        ax.plot(xf, envelope, "-", color="tab:blue", label=label_fit)
        ax.plot(xs, peaks, "o", color="tab:red", label=f"measured peaks ({n})")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", alpha=0.3)
        if log:
            from matplotlib.ticker import FuncFormatter

            ax.set_yscale("log")
            plain = FuncFormatter(lambda v, _pos: f"{v:g}")
            ax.yaxis.set_major_formatter(plain)
            ax.yaxis.set_minor_formatter(plain)
            ax.set_title("logarithmic axis: exponential = straight line", fontsize=10)
        else:
            ax.set_ylim(bottom=0.0)
            ax.set_title("measured peaks and fitted envelope", fontsize=10)
            ax.legend(fontsize=8)
    fig.suptitle(f"damping-ratio: ζ = {format_number(zeta, 4)}, δ = {delta:.4g}, "
                 f"fit residual {fit['residual']:.2g}"
                 + ("  (NOT exponential: see warnings)" if fit["systematic"]
                    or fit["scattered"] else ""), fontsize=11)


def _draw_response(fig, result: Result) -> None:
    from ..physics.damping import free_response

    zeta = _value(result, "zeta") or 0.0
    regime = result.results["regime"].si
    omega = _natural_frequency(result)
    ax = fig.add_subplot(1, 1, 1)
    oscillates = regime in ("undamped", "underdamped")
    if oscillates:
        s = math.sqrt((1.0 - zeta) * (1.0 + zeta))
        if regime == "underdamped" and zeta >= 1.0:  # a huge decrement: zeta rounded to 1
            delta = _value(result, "delta")
            s = 2.0 * math.pi / math.hypot(2.0 * math.pi, delta)
        cycle = 2.0 * math.pi / s                       # one damped period in omega t
        span = 5.0 * cycle
        if zeta > 0.0:
            span = min(span, max(1.5 * cycle, math.log(1e3) / zeta))
    else:
        slow = 1.0 if zeta == 1.0 else 1.0 / (zeta + math.sqrt(zeta - 1.0)
                                              * math.sqrt(zeta + 1.0))
        span = (8.0 if zeta == 1.0 else math.log(100.0) / slow)
    tau = np.linspace(0.0, span, 2000)
    x = free_response(min(zeta, 1.0) if oscillates else zeta, tau)
    why = "no natural frequency given"
    if omega is not None:
        with np.errstate(over="ignore", under="ignore"):
            t, xlabel = tau / omega, "time t (s)"
        if not 1e-300 < t[-1] < 1e300:  # seconds beyond float64 (omega = 3e-162 rad/s)
            result.warnings.append(f"--plot: the decay lasts {span:.3g} / omega with omega "
                                   f"= {omega:.3g} rad/s, a time beyond float64, so the "
                                   "plot's time axis is dimensionless")
            omega, why = None, "seconds beyond float64"
    else:
        result.warnings.append("--plot: no natural frequency given (--omega, or --k and --m), "
                               "so the plot's time axis is dimensionless")
    if omega is None and oscillates:
        t, xlabel = tau / cycle, f"t / T_d (damped cycles; {why})"
    elif omega is None:
        t, xlabel = tau, f"ω t (dimensionless time; {why})"
    ax.plot(t, x, color="tab:blue", label="x(t) / x(0), released from rest")
    if oscillates:
        env = np.exp(-zeta * tau) / s
        ax.plot(t, env, "--", color="tab:red", label="envelope ± exp(-ζ ω t) / sqrt(1 - ζ²)")
        ax.plot(t, -env, "--", color="tab:red")
    ax.axhline(0.0, color="black", linewidth=0.6)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("x / x(0)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    ax.set_title(f"free decay: ζ = {format_number(zeta, 4)} ({regime})", fontsize=11)


def plot_forced(result: Result, path: str) -> str:
    """Draw a forced-response result into ``path`` (PNG, SVG or PDF): the magnification ``V``
    and the phase lag ``phi`` against ``Omega/omega`` on log axes with the operating point
    marked (the curves of :func:`dyncalc.commands.forced_curves.frequency_curves`); with
    ``--t``, a third panel with the time history of ``x`` from ``x0``, ``v0``
    (:func:`dyncalc.commands.forced_curves.time_history`). Returns the path written."""
    from ..commands.forced_curves import frequency_curves, time_history

    target = _target(path)
    curves = frequency_curves(result)
    history = time_history(result) if "t" in result.inputs else None
    Figure, FigureCanvasAgg = _matplotlib()
    fig = Figure(figsize=(9.0, 7.5 if history else 5.5), dpi=100, layout="constrained")
    FigureCanvasAgg(fig)
    rows = 3 if history else 2
    amp = fig.add_subplot(rows, 1, 1)
    eta0, V0, phi0 = curves.point
    what = {"force": "X k / F0", "base": "X / u0", "base-accel": "X k / (m B0)",
            "unbalance": "m X / (m_u e)"}[curves.kind]
    amp.plot(curves.eta, curves.V, color="tab:blue", label=f"V = {what}")
    if math.isfinite(V0):
        amp.plot([eta0], [V0], "o", color="tab:red", label=f"operating point η = {eta0:.4g}, "
                                                           f"V = {format_number(V0, 4)}")
    amp.set_xscale("log")
    amp.set_yscale("log")
    amp.set_ylabel("magnification V")
    amp.grid(True, which="both", alpha=0.3)
    amp.legend(fontsize=8)
    ph = fig.add_subplot(rows, 1, 2, sharex=amp)
    ph.plot(curves.eta, np.degrees(curves.phi), color="tab:blue")
    ph.plot([eta0], [math.degrees(phi0)], "o", color="tab:red")
    ph.set_xscale("log")
    ph.set_ylim(0.0, 180.0)
    ph.set_yticks([0, 45, 90, 135, 180])
    ph.set_xlabel("frequency ratio η = Ω / ω")
    ph.set_ylabel("phase lag φ (deg)")
    ph.grid(True, which="both", alpha=0.3)
    if history:
        ax = fig.add_subplot(rows, 1, 3)
        coordinate = result.extra.get("coordinate", {})   # a scene driven on its own
        sym = coordinate.get("name", "x")
        unit = "rad" if coordinate.get("kind") == "angle" else "m"
        ax.plot(history[0], history[1], color="tab:blue",
                label=f"{sym}(t): transient + steady")
        ax.axhline(0.0, color="black", linewidth=0.6)
        ax.set_xlabel("time t (s)")
        ax.set_ylabel(f"{sym} ({unit})")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="upper right")
    fig.suptitle(f"forced-response ({curves.kind}): ζ = {format_number(curves.zeta, 4)}",
                 fontsize=11)
    _save(fig, target, path)
    result.extra["plot"] = str(target)
    return str(target)


def plot_coriolis(data, path: str) -> str:
    """Draw a motion given in time (``coriolis --t ... --plot``) into ``path``: the point's
    path in the fixed frame's x-y plane over the window of
    :func:`dyncalc.commands.coriolis_time.plot_window`, the point at ``--t`` with its velocity
    and acceleration arrows (each scaled to a fifth of the drawing, its magnitude in the
    legend). ``data`` is a :class:`~dyncalc.commands.coriolis_time.PathData`. Returns the path
    written."""
    target = _target(path)
    Figure, FigureCanvasAgg = _matplotlib()
    fig = Figure(figsize=(7.0, 7.0), dpi=100, layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    xy = data.path[:, :2]
    ax.plot(xy[:, 0], xy[:, 1], color="tab:blue",
            label=f"path, t = {data.times[0]:.4g} to {data.times[-1]:.4g} s ({data.reason})")
    ax.plot([data.point[0]], [data.point[1]], "o", color="black",
            label=f"point at t = {data.t:.4g} s")
    finite = xy[np.all(np.isfinite(xy), axis=1)]
    span = float(np.ptp(finite, axis=0).max()) if len(finite) else 0.0
    span = span or max(float(np.hypot(*data.point[:2])), 1.0)
    for vector, colour, name, unit in ((data.v, "tab:green", "v", "m/s"),
                                       (data.a, "tab:red", "a", "m/s^2")):
        size = float(np.linalg.norm(vector))
        planar = float(np.hypot(vector[0], vector[1]))
        if planar == 0.0:
            continue
        scale = 0.2 * span / planar
        tip = (data.point[0] + scale * vector[0], data.point[1] + scale * vector[1])
        ax.plot([tip[0]], [tip[1]], alpha=0.0)  # the arrow's tip inside the drawing
        ax.annotate("", xy=tip, xytext=(data.point[0], data.point[1]), annotation_clip=False,
                    arrowprops={"arrowstyle": "->", "color": colour, "linewidth": 2})
        ax.plot([], [], color=colour, linewidth=2,
                label=f"{name} = {format_number(size, 4)} {unit} (arrow not to scale)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (m, fixed frame)")
    ax.set_ylabel("y (m, fixed frame)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    fig.suptitle("coriolis: path in the fixed frame (x-y plane)", fontsize=11)
    _save(fig, target, path)
    return str(target)


def _target(path: str) -> Path:
    target = Path(path)
    if target.suffix.lower() not in PLOT_FORMATS:
        raise InputError(f"--plot: {path[:80]!r} must end in "
                         f"{', '.join(PLOT_FORMATS[:-1])} or {PLOT_FORMATS[-1]}")
    return target


def _matplotlib():
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:
        raise InputError("--plot needs matplotlib: pip install 'dyncalc[plot]'") from None
    return Figure, FigureCanvasAgg


def _save(fig, target: Path, path: str) -> None:
    try:
        fig.savefig(target)
    except OSError as exc:
        raise InputError(f"--plot: cannot write {path[:80]!r}: {exc.strerror or exc}") from None
    except ValueError as exc:  # a NUL in the path ("embedded null byte")
        raise InputError(f"--plot: cannot write {path[:80]!r}: {exc}") from None


def plot_loads(result: Result, path: str) -> str:
    """Draw the N, V, M diagrams of a ``rigid-body`` result (``beam-spun-up``,
    ``rotating-angled-arm``) into ``path`` (PNG, SVG or PDF): three stacked axes against the
    position along the bar, one column per leg, the section asked for marked (the curves of
    :func:`dyncalc.commands.rigid_diagrams.load_diagram`). Returns the path written."""
    from ..commands.rigid_diagrams import load_diagram

    target = _target(path)
    diagram = load_diagram(result)
    Figure, FigureCanvasAgg = _matplotlib()
    columns = len(diagram.legs)
    fig = Figure(figsize=(4.8 * columns + 1.0, 7.5), dpi=100, layout="constrained")
    FigureCanvasAgg(fig)
    rows = (("N", "normal force N (N)", "N"), ("V", "shear force V (N)", "N"),
            ("M", "bending moment M (N m)", "N m"))
    for j, leg in enumerate(diagram.legs):
        top = None
        for i, (name, label, unit) in enumerate(rows):
            ax = fig.add_subplot(3, columns, i * columns + j + 1, sharex=top)
            top = top or ax
            values = getattr(leg, name)
            ax.plot(leg.x, values, color="tab:blue")
            ax.fill_between(leg.x, values, 0.0, color="tab:blue", alpha=0.15)
            ax.axhline(0.0, color="black", linewidth=0.6)
            if leg.section is not None:
                at = leg.x.index(leg.section)
                ax.axvline(leg.section, color="tab:red", linewidth=0.8, linestyle="--")
                ax.plot([leg.section], [values[at]], "o", color="tab:red",
                        label=f"{name} = {format_number(values[at], 4)} {unit} at the "
                              "section")
                ax.legend(fontsize=8)
            if j == 0:
                ax.set_ylabel(label)
            if i == 0 and columns > 1:
                ax.set_title(leg.name, fontsize=10)
            ax.grid(True, alpha=0.3)
        ax.set_xlabel(leg.label)
    fig.suptitle(f"stress resultants: {diagram.title}", fontsize=11)
    _save(fig, target, path)
    result.extra["plot"] = str(target)
    return str(target)
