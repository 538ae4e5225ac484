"""``dyncalc damping-ratio``."""
from __future__ import annotations

import click

from .options import complete_scene, output_options


@click.command("damping-ratio")
@click.argument("parameters", nargs=-1, metavar="[NAME=QUANTITY]...")
@click.option("--c", metavar="C", help="Viscous damping coefficient, e.g. '4 N*s/m' (with "
                                       "--k and --m).")
@click.option("--k", metavar="K", help="Stiffness, e.g. '100 N/m': with --c, or with another "
                                       "form for c_c, c and the damped period.")
@click.option("--m", metavar="M", help="Mass, e.g. 1kg (goes with --k).")
@click.option("--decrement", metavar="DELTA",
              help="Logarithmic decrement per cycle, ln(x_i / x_(i+1)).")
@click.option("--ratio", metavar="R",
              help="Amplitude ratio x_i / x_(i+N) of two peaks N cycles apart (R >= 1).")
@click.option("--cycles", metavar="N",
              help="Whole cycles between the two peaks of --ratio (default 1).")
@click.option("--amplitudes", metavar='"x0,x1,..."',
              help='Successive peaks, one per cycle, one optional unit at the end, e.g. '
                   '"12.1, 8.3, 5.9 mV": the decrement is fitted to all of them.')
@click.option("--scene", metavar="NAME", shell_complete=complete_scene,
              help="A scene with a damper (rod-in-fluid, pendulum-spring-dashpot, "
                   "frame-brace-damper), its parameters as NAME=QUANTITY words.")
@click.option("--omega", metavar="OMEGA",
              help="Undamped natural angular frequency, e.g. '12 rad/s' or 115rpm: adds "
                   "omega_d, f_d, T_d.")
@click.option("--g", metavar="G", help="Gravitational acceleration of a scene (default "
                                       "9.80665 m/s^2).")
@click.option("--method", metavar="METHOD",
              help="Fit of --amplitudes: log-linear (default; least squares of ln x) or "
                   "nonlinear (least squares of x, scipy); a scene's own methods with --scene.")
@click.option("--plot", metavar="FILE.png",
              help="Draw the free decay (the peaks and the fitted envelope for --amplitudes) "
                   "into FILE (.png, .svg or .pdf); needs matplotlib (the plot extra).")
@output_options
def damping_ratio(parameters, c, k, m, decrement, ratio, cycles, amplitudes, scene, omega, g,
                  method, plot, out):
    """Damping ratio zeta, log decrement delta, Q, regime and damped period from a
    measurement: a damper rating, a decrement, two peaks, a list of peaks or a scene.

    Give exactly one of --c/--k/--m, --decrement, --ratio (with --cycles), --amplitudes or
    --scene. --omega (or --k and --m) adds the damped frequency and period; k and m add the
    critical damping coefficient c_c and c. Regime: undamped, underdamped, critically damped
    (also when c equals c_c to within the rounding of the inputs), overdamped. Peaks that are
    not exponential (Coulomb friction, noise larger than the decay) come with a warning.

    \b
    Examples:
      dyncalc damping-ratio --ratio 10 --cycles 10          # E5.18: zeta = 0.0366
      dyncalc damping-ratio --c "4 N*s/m" --k 100N/m --m 1kg
      dyncalc damping-ratio --decrement 0.23 --omega "12 rad/s"
      dyncalc damping-ratio --amplitudes "12.1, 9.0, 6.8, 5.1, 3.8 mV" --omega 25rad/s \\
          --plot decay.png
      dyncalc damping-ratio --scene rod-in-fluid m=1.5kg l=0.8m "beta=2 N*s/m^2"  # E5.14
    """
    if out.batch is not None:
        from ..batch import DampingRows

        options = {"--c": c, "--k": k, "--m": m, "--decrement": decrement, "--ratio": ratio,
                   "--cycles": cycles, "--amplitudes": amplitudes, "--omega": omega, "--g": g,
                   "--plot": plot, "": parameters}
        return out.run_batch(DampingRows(scene=scene, method=method, rtol=out.rtol,
                                         strict=out.strict), options)
    from ..commands.damping_ratio import damping_ratio as compute
    from .plot import plot_decay

    result = out.compute(lambda: compute(
        c=c, k=k, m=m, omega=omega, decrement=decrement, ratio=ratio, cycles=cycles,
        amplitudes=amplitudes, scene=scene, params=parameters, g=g, method=method,
        rtol=out.rtol, strict=out.strict))
    if plot is not None:
        plot_decay(result, plot)
    return out.emit(result)


COMMANDS = [damping_ratio]
