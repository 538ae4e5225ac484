"""``dyncalc natural-frequency``."""
from __future__ import annotations

import click

from ..commands.natural_frequency import STANDARD
from .options import complete_scene, output_options

@click.command("natural-frequency")
@click.argument("parameters", nargs=-1, metavar="[NAME=QUANTITY]...")
@click.option("--scene", metavar="NAME", shell_complete=complete_scene,
              help="The set-up (dyncalc scenes lists them); default: chosen by the "
                   "parameters given (k, m: mass-spring; kt, J: torsional; l: pendulum).")
@click.option("--k", metavar="K", help="Stiffness, e.g. '2 kN/m' (k=).")
@click.option("--m", metavar="M", help="Mass, e.g. 4kg (m=).")
@click.option("--kt", metavar="KT", help="Torsional stiffness, e.g. '3 kN*m/rad' (kt=).")
@click.option("--inertia", metavar="J", help="Mass moment of inertia, e.g. '1.2 kg*m^2' (J=).")
@click.option("--length", metavar="L", help="Pendulum length (l=).")
@click.option("--amplitude", metavar="ANGLE",
              help="Swing amplitude for the exact large-amplitude period, e.g. 30deg.")
@click.option("--zeta", metavar="ZETA", help="Damping ratio: adds omega_d, f_d, T_d.")
@click.option("--g", metavar="G", help="Gravitational acceleration (default 9.80665 m/s^2).")
@click.option("--method", metavar="METHOD",
              help="auto (default: the cheapest model meeting --rtol), or one the scene offers "
                   "(dyncalc scenes NAME lists them; pendulums: small-angle, series, elliptic, "
                   "ode; "
                   "half-cylinder-shell: linear, quadrature, ode).")
@output_options
def natural_frequency(parameters, scene, method, out, **options):
    """Natural frequency omega (rad/s), f (Hz) and period T (s) of a scene.

    Scene parameters are given as NAME=QUANTITY words or by the standard options; a
    parameter that cancels out of the answer is never asked for. Bare numbers are SI.

    \b
    Examples:
      dyncalc natural-frequency --k "2 kN/m" --m 4kg
      dyncalc natural-frequency --k 100N/m --m 2kg --zeta 0.05
      dyncalc natural-frequency --length 1m --amplitude 170deg
      dyncalc natural-frequency --scene physical-pendulum m=2kg a=0.5m "J=2/12 kg*m^2"
      dyncalc natural-frequency --k 100N/m --m 2kg --check f=1.13Hz
      dyncalc natural-frequency --batch rows.csv     # header: k [N/m],m [kg]
    """
    if out.batch is not None:
        from ..batch import NaturalFrequencyRows

        return out.run_batch(NaturalFrequencyRows(STANDARD, scene=scene, method=method,
                                                  rtol=out.rtol, strict=out.strict),
                             {**{f"--{o}": v for o, v in options.items()}, "": parameters})
    from ..commands.natural_frequency import natural_frequency as compute

    return out.emit(out.compute(lambda: compute(options, parameters, scene=scene, method=method,
                                                rtol=out.rtol, strict=out.strict)))


COMMANDS = [natural_frequency]
