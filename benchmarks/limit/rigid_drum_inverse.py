"""Limit: rigid-body --scene drum-two-blocks solved for the drum's inertia (m1, m2, r1, r2 [kg,
m], J_A as ``?``, alpha [rad/s^2]; g at its default) -> J_A, alpha, a1, a2, S1, S2.

alpha = (m2 r2 - m1 r1) g / (J_A + m1 r1^2 + m2 r2^2) falls as J_A grows (m2 r2 > m1 r1 in the
benchmark's rows), each value the float nearest the exact rational (rigid_body.drum_values:
double-double, fractions where its rounding is not certain). dyncalc reports the one-off's
root: Brent's method (dyncalc.physics.brent_arrays, scipy's brentq to the bit) on the step of
the one-off's grid (zero, then every fifth decade) and its 50-point refinement
(x (x'/x)^(j/50), C's pow) where alpha - goal changes sign; the interval and the step are
read off the closed-form root J_A = top g / alpha - m1 r1^2 - m2 r2^2 and checked by the signs
at their ends."""
import numpy as np

from dyncalc.physics.brent_arrays import RTOL_MIN, brent_roots
from dyncalc.physics.numerics_arrays import elementwise
from _limit import arguments, inverse_lines, json_input, number, read, text
from rigid_body import G, drum_values

DECADES = [5e-324, *(10.0 ** e for e in range(-300, 301, 5)), 1.7976931348623157e308]
GRID = np.array([0.0] + DECADES)


def step_points(a, b, j):
    """The one-off's refinement points j of [a, b] (a b > 0: geometric; the 50th is b)."""
    power = elementwise(lambda r, k: r ** k, b / a, j / 50)
    return np.where(j == 50, b, np.where(a * b > 0, a * power, a + (b - a) * j / 50))


np.seterr(all="ignore")
path, as_json = arguments()
df = read(path)
m1, m2, r1, r2, goal = (number(df, c) for c in ("m1 [kg]", "m2 [kg]", "r1 [m]", "r2 [m]",
                                                   "alpha [rad/s^2]"))


def alpha_of(J, rows=slice(None)):
    return drum_values(m1[rows], m2[rows], r1[rows], r2[rows], J)[0]


estimate = (m2 * r2 - m1 * r1) * G / goal - m1 * r1 * r1 - m2 * r2 * r2
i = np.clip(np.searchsorted(GRID, estimate) - 1, 0, len(GRID) - 2)
a, b = GRID[i], GRID[i + 1]
ratio = np.where(a * b > 0, np.log(np.abs(estimate / np.where(a > 0, a, 1.0)))
                 / np.log(np.abs(b / np.where(a > 0, a, 1.0))), (estimate - a) / (b - a))
j = np.clip(np.floor(ratio * 50).astype(int), 0, 49)
for _ in range(2):   # the step whose ends straddle the goal (alpha falls as J_A grows)
    lo, hi = step_points(a, b, j), step_points(a, b, j + 1)
    j = np.clip(j - (alpha_of(lo) < goal) + (alpha_of(hi) > goal), 0, 49)
lo, hi = step_points(a, b, j), step_points(a, b, j + 1)
J = brent_roots(lambda x, rows: alpha_of(x, rows) - goal[rows], lo, hi, xtol=1e-300,
                rtol=RTOL_MIN, maxiter=200).x
alpha, a1, a2, S1, S2 = drum_values(m1, m2, r1, r2, J)
out = {"J_A": text(J), "alpha": text(alpha), "a1": text(a1), "a2": text(a2), "S1": text(S1),
       "S2": text(S2)}
units = {"J_A": "kg*m^2", "alpha": "rad/s^2", "a1": "m/s^2", "a2": "m/s^2", "S1": "N",
         "S2": "N"}
inputs = (json_input(df, "m1 [kg]", "m1", "kg", True) + json_input(df, "m2 [kg]", "m2", "kg")
          + json_input(df, "r1 [m]", "r1", "m") + json_input(df, "r2 [m]", "r2", "m")
          + [', "g": {"value": 9.80665, "unit": "m/s^2", "text": "9.80665 m/s^2"}']
          + json_input(df, "alpha [rad/s^2]", "alpha", "rad/s^2"))
inverse_lines(df, as_json, "drum-two-blocks", inputs, out, units, "J_A", "alpha")
