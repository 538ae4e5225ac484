"""``dyncalc coriolis``."""
from __future__ import annotations

import click

from .options import output_options

VECTOR = "VEC"


@click.command("coriolis")
@click.option("--omega", metavar=VECTOR,
              help="Angular velocity of the frame: '0,0,2 rad/s' (rad/s, deg/s, rpm), or a "
                   "magnitude ('2 rad/s') for perpendicular vectors; with --latitude the "
                   "rotation rate only (default 7.2921159e-5 rad/s).")
@click.option("--vr", metavar=VECTOR,
              help="Velocity relative to the frame: '3,0,0 m/s' (km/h ...), or a magnitude; "
                   "with --latitude east, north, up components.")
@click.option("--r", metavar=VECTOR,
              help="Position in the frame (from its origin); a magnitude is the distance "
                   "from the rotation axis.")
@click.option("--alpha", metavar=VECTOR,
              help="Angular acceleration of the frame, e.g. '0,0,1 rad/s^2' (a magnitude: "
                   "about the axis of --omega).")
@click.option("--a0", metavar=VECTOR,
              help="Acceleration of the frame's origin, e.g. '1,0,0 m/s^2' (vectors only).")
@click.option("--ar", metavar=VECTOR,
              help="Acceleration relative to the frame (vectors only).")
@click.option("--mass", metavar="M", help="Mass: adds the Coriolis force F_c = -m a_c.")
@click.option("--latitude", metavar="ANGLE",
              help="Earth mode: latitude from -90deg to 90deg (positive north); --vr and the "
                   "other vectors are then east, north, up components.")
@click.option("--speed", metavar="V",
              help="Earth mode: horizontal speed (with --heading), instead of --vr.")
@click.option("--heading", metavar="ANGLE",
              help="Earth mode: compass heading of --speed, 0deg = north, 90deg = east.")
@click.option("--vertical", metavar="V",
              help="Earth mode: vertical speed, positive up (with or without --speed).")
@output_options
def coriolis(out, **options):
    """Coriolis acceleration a_c = 2 Omega x v_r and every term of the relative-motion formula
    a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r, in a machine or on Earth.

    Vectors have three components and one unit ("0,0,2 rad/s", "(0, 0, 2) rpm",
    "[1,0,0] km/h"); results are in SI. With --mass also the Coriolis force F_c = -m a_c (the
    apparent force, opposite to a_c). Any of --r, --alpha, --a0, --ar adds a_euler
    (alpha x r), a_centripetal (Omega x (Omega x r)), a_transport and the absolute a; missing
    ones are zero. a_c_mag, F_c_mag and a_mag are the magnitudes (--check compares those).

    Scalars (--omega 2rad/s --vr 3m/s) are magnitudes of perpendicular vectors: a_c = 2 Omega
    v_r and F_c = m a_c; --r is then the distance from the axis and --alpha turns about the
    same axis; --a0, --ar and the absolute a need vectors.

    --latitude sets up the rotating Earth: x east, y north, z up, Omega = Omega_E (0, cos phi,
    sin phi). --explain lists each term with its numbers, which vanish and why, and on Earth
    the directions of a_c and of the Coriolis force.

    \b
    Examples:
      dyncalc coriolis --omega "2 rad/s" --vr "3 m/s"
      dyncalc coriolis --omega "0,0,30 rpm" --vr "0.5,0,0 m/s" --r "0.2,0,0 m" --mass 2kg
      dyncalc coriolis --latitude 45deg --speed "100 km/h" --heading 0deg --mass 1kg --explain
      dyncalc coriolis --latitude 30deg --vr "20,0,0 m/s" --json
    """
    if out.batch is not None:
        from ..batch import CoriolisRows

        return out.run_batch(CoriolisRows(strict=out.strict),
                             {f"--{o}": v for o, v in options.items()})
    from ..commands.coriolis import coriolis_result

    return out.emit(out.compute(lambda: coriolis_result(options, strict=out.strict)))


COMMANDS = [coriolis]
