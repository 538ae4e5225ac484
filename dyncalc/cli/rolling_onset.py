"""``dyncalc rolling-onset``."""
from __future__ import annotations

import click

from ..physics.bodies import KAPPA
from .options import output_options

BODIES = tuple(KAPPA)


def _complete_body(ctx, param, incomplete):
    from click.shell_completion import CompletionItem

    return [CompletionItem(name) for name in BODIES if name.startswith(incomplete)]


@click.command("rolling-onset",
               short_help="When a sliding ball, cylinder or hoop starts to roll.")
@click.option("--v0", metavar="V0",
              help="Initial sliding speed of the centre, e.g. '5 m/s' or 12mph (>= 0; its "
                   "direction is the positive one).")
@click.option("--mu", metavar="MU", help="Kinetic friction coefficient at the contact (> 0).")
@click.option("--body", metavar="BODY", shell_complete=_complete_body,
              help="solid-sphere (default), hollow-sphere, solid-cylinder, hollow-cylinder "
                   "or hoop.")
@click.option("--kappa", metavar="KAPPA",
              help="Shape factor J_C/(m r^2) of any body, instead of --body (>= 0).")
@click.option("--radius", metavar="R",
              help="Radius: needed with --omega0, and gives omega_roll.")
@click.option("--omega0", metavar="OMEGA0",
              help="Initial spin, e.g. '30 rad/s' or '-600 rpm': positive is the sense of "
                   "rolling forward, negative is backspin (default 0; needs --radius).")
@click.option("--g", metavar="G", help="Gravitational acceleration (default 9.80665 m/s^2).")
@click.option("--incline", metavar="ANGLE",
              help="Slope angle, e.g. 10deg: positive when the body moves uphill, negative "
                   "downhill (between -90 and 90 deg).")
@click.option("--method", type=click.Choice(["auto", "closed-form", "ode"]), default="auto",
              metavar="METHOD",
              help="auto or closed-form (the default: exact to rounding), or ode: integrate "
                   "the equations of motion with scipy's solve_ivp to --rtol, and report the "
                   "difference from the closed form and both timings (JSON error_estimate, "
                   "timing; --explain).")
@output_options
def rolling_onset(method, out, **options):
    """When a ball, cylinder or hoop set down sliding starts to roll without slipping.

    Kinetic friction opposes the slip of the contact point, v0 - r omega0, until it vanishes.
    Results: t_roll (s), x_roll (m, displacement along the surface), v_roll (m/s), with
    --radius omega_roll (rad/s), with backspin that brings the body back path_roll (m), on a
    slope mu_min (the static friction that keeps it rolling). The mass cancels; bare numbers
    are SI.

    \b
    Examples:
      dyncalc rolling-onset --v0 "5 m/s" --mu 0.3 --explain       # E3.45, a bowling ball
      dyncalc rolling-onset --v0 "2 m/s" --mu 0.2 --radius 28.5mm --omega0 "-300 rad/s"
      dyncalc rolling-onset --v0 "3 m/s" --mu 0.25 --body hoop --incline -10deg
      dyncalc rolling-onset --v0 15mph --mu 0.2 --method ode --json
    """
    if out.batch is not None:
        from ..batch import RollingRows

        return out.run_batch(RollingRows(method=method, rtol=out.rtol, strict=out.strict),
                             {f"--{o}": v for o, v in options.items()})
    from ..commands.rolling_onset import rolling_onset_result

    return out.emit(out.compute(lambda: rolling_onset_result(options, method=method,
                                                             rtol=out.rtol, strict=out.strict)))


COMMANDS = [rolling_onset]
