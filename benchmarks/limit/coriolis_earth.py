"""Limit: coriolis on the Earth (latitude [deg], speed [m/s], heading [deg], mass [kg]) ->
a_c, a_c_mag, F_c, F_c_mag, Omega, v_r, coriolis_parameter, a_c_horizontal(_mag),
F_c_horizontal(_mag); JSON lines add the directions of a_c and of the Coriolis force.

Omega = W (0, cos phi, sin phi), v_r = (v sin psi, v cos psi, 0), a_c = 2 Omega x v_r with
each component a*b - c*d rounded once, F_c = -m a_c. The cosines in degrees, the compass and
|x| are dyncalc's numpy-only twins (dyncalc.physics.earth_columns, numerics_arrays): numpy's
cos(radians(phi)), a plain cross product or sqrt(x^2+y^2+z^2) differ in the last bit."""
import numpy as np
import polars as pl

from dyncalc.physics.earth_columns import (compass_sectors, earth_angular_velocity_rows,
                                           enu_velocity_rows)
from dyncalc.physics.numerics_arrays import fsum_rows, hypot_rows, two_product_array
from _limit import arguments, csv_line, json_input, json_lines, json_result, number, read, \
    text, vector

EARTH_RATE = 7.2921159e-5
COMPASS = ["north", "north-north-east", "north-east", "east-north-east", "east",
           "east-south-east", "south-east", "south-south-east", "south", "south-south-west",
           "south-west", "west-south-west", "west", "west-north-west", "north-west",
           "north-north-west"]


def difference(a, b, c, d):
    """a*b - c*d rounded once."""
    h1, l1 = two_product_array(a, b)
    h2, l2 = two_product_array(c, d)
    return fsum_rows(np.stack([h1, l1, -h2, -l2], axis=1))[0]


def magnitude(v):
    return hypot_rows(v[:, 0], v[:, 1], v[:, 2])[0] + 0.0


def directions(v):
    """Compass point and up/down of each row, as JSON strings."""
    flat = (v[:, 0] != 0.0) | (v[:, 1] != 0.0)
    sector = np.where(flat, compass_sectors(v[:, 0], v[:, 1]), 16)
    side = np.where(v[:, 2] > 0.0, 1, np.where(v[:, 2] < 0.0, 2, 0))
    words = []
    for point in [*COMPASS, None]:
        for up in (None, "up", "down"):
            parts = [p for p in (point, up) if p]
            words.append('"' + (" and ".join(parts) or "none") + '"')
    return pl.Series(np.array(words, dtype=object)[sector * 3 + side].tolist())


path, as_json = arguments()
df = read(path)
latitude, speed = number(df, "latitude [deg]"), number(df, "speed [m/s]")
heading, mass = number(df, "heading [deg]"), number(df, "mass [kg]")
omega = earth_angular_velocity_rows(latitude, EARTH_RATE)
vr = enu_velocity_rows(speed, heading, np.zeros(len(df)))
(ox, oy, oz), (vx, vy, vz) = omega.T, vr.T
a_c = 2.0 * np.stack([difference(oy, vz, oz, vy), difference(oz, vx, ox, vz),
                      difference(ox, vy, oy, vx)], axis=1) + 0.0
F_c = a_c * -mass[:, None] + 0.0
flat_a, flat_F = a_c.copy(), F_c.copy()
flat_a[:, 2] = flat_F[:, 2] = 0.0
results = [("a_c", a_c, "m/s^2"), ("a_c_mag", magnitude(a_c), "m/s^2"), ("F_c", F_c, "N"),
           ("F_c_mag", magnitude(F_c), "N"), ("Omega", omega, "rad/s"), ("v_r", vr, "m/s"),
           ("coriolis_parameter", 2.0 * omega[:, 2] + 0.0, "1/s"),
           ("a_c_horizontal", flat_a, "m/s^2"), ("a_c_horizontal_mag", magnitude(flat_a), "m/s^2"),
           ("F_c_horizontal", flat_F, "N"), ("F_c_horizontal_mag", magnitude(flat_F), "N")]
if as_json:
    head = ('"schema": "dyncalc/2", "command": "coriolis", "scene": null, '
            '"model": "Earth, east-north-up", "method": "closed-form"')
    inputs = (json_input(df, "latitude [deg]", "latitude", "deg", True)
              + json_input(df, "speed [m/s]", "speed", "m/s")
              + json_input(df, "heading [deg]", "heading", "deg")
              + json_input(df, "mass [kg]", "mass", "kg"))
    parts = []
    for i, (name, values, unit) in enumerate(results):
        shown = vector(values.T, ", ") if values.ndim == 2 else text(values)
        parts += json_result(name, shown, unit, i == 0)
    extra = ['{"frame": "east-north-up", "directions": {"a_c": ', directions(a_c),
             ', "F_c": ', directions(-a_c + 0.0), "}}"]
    json_lines(len(df), head, inputs, parts, extra)
else:
    csv_line(df, {name: vector(values.T, ",") if values.ndim == 2 else text(values)
                  for name, values, _unit in results},
             {name: f"{name} [{unit}]" for name, _values, unit in results})
