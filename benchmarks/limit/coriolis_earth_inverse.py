"""Limit: coriolis on the Earth solved for the speed (a_c_mag [m/s^2], latitude [deg], vr as
``?``) -> vr, a_c_mag, a_c_horizontal_mag, heading north at the sidereal rate.

|a_c| is proportional to v, so v = exp(ln a_c - ln y1) with y1 = |a_c| at v = 1 m/s (the
one-off's exact inversion of the monomial, libm's log and exp), and both magnitudes again at v.
Omega = W (0, cos phi, sin phi), v_r = (0, v, 0), a_c = 2 Omega x v_r with each component
a*b - c*d rounded once; the cosines in degrees and |x| are dyncalc's numpy-only twins
(dyncalc.physics.earth_columns, numerics_arrays), as in coriolis_earth.py."""
import math

import numpy as np

from dyncalc.physics.earth_columns import earth_angular_velocity_rows
from dyncalc.physics.numerics_arrays import elementwise, fsum_rows, hypot_rows, \
    two_product_array
from _limit import arguments, csv_line, json_input, json_lines, json_result, number, read, \
    text

EARTH_RATE = 7.2921159e-5


def difference(a, b, c, d):
    """a*b - c*d rounded once."""
    h1, l1 = two_product_array(a, b)
    h2, l2 = two_product_array(c, d)
    return fsum_rows(np.stack([h1, l1, -h2, -l2], axis=1))[0]


def magnitudes(omega, v):
    """(|a_c|, |a_c,h|) of a velocity v north."""
    (ox, oy, oz), zero = omega.T, np.zeros(len(v))
    a_c = 2.0 * np.stack([difference(oy, zero, oz, v), difference(oz, zero, ox, zero),
                          difference(ox, v, oy, zero)], axis=1) + 0.0
    flat = a_c.copy()
    flat[:, 2] = 0.0
    return (hypot_rows(*a_c.T)[0] + 0.0, hypot_rows(*(flat + 0.0).T)[0] + 0.0)


path, as_json = arguments()
df = read(path)
goal, latitude = number(df, "a_c_mag [m/s^2]"), number(df, "latitude [deg]")
omega = earth_angular_velocity_rows(latitude, EARTH_RATE)
y1 = magnitudes(omega, np.ones(len(df)))[0]
v = elementwise(math.exp, elementwise(math.log, goal) - elementwise(math.log, y1))
a_c_mag, a_c_horizontal_mag = magnitudes(omega, v)
if as_json:
    head = ('"schema": "dyncalc/2", "command": "coriolis", "scene": "coriolis-earth", '
            '"model": "Earth, horizontal motion", "method": "closed-form"')
    inputs = (json_input(df, "latitude [deg]", "latitude", "deg", True)
              + [', "heading": {"value": 0.0, "unit": "deg", "text": "0 deg"}, "omega": '
                 '{"value": 7.2921159e-05, "unit": "rad/s", "text": "7.2921159e-5 rad/s"}']
              + json_input(df, "a_c_mag [m/s^2]", "a_c_mag", "m/s^2"))
    results = (json_result("vr", text(v), "m/s", True)
               + json_result("a_c_mag", text(a_c_mag), "m/s^2")
               + json_result("a_c_horizontal_mag", text(a_c_horizontal_mag), "m/s^2"))
    json_lines(len(df), head, inputs, results,
               '{"inverse": {"unknown": "vr", "method": "closed-form", "detail": "a_c_mag is '
               'proportional to vr^(1): inverted exactly"}}')
else:
    csv_line(df, {"vr": text(v), "a_c_mag": text(a_c_mag),
                  "a_c_horizontal_mag": text(a_c_horizontal_mag)},
             {"vr": "vr_result [m/s]", "a_c_mag": "a_c_mag_result [m/s^2]",
              "a_c_horizontal_mag": "a_c_horizontal_mag [m/s^2]"})
