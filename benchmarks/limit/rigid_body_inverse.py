"""Limit: rigid-body --scene angled-bar-on-shaft solved for the signed moment (m [kg], l [m],
M0 as ``?``, omega [rad/s], alpha [rad/s^2]) -> M0, alpha, A_xi, A_eta, B_xi, B_eta.

alpha = 9 M0 / (20 m l^2) is linear in M0, but dyncalc reports the one-off's root: Brent's
method (scipy's brentq to the bit: dyncalc.physics.brent_arrays) on the interval of the
one-off's grid where alpha - goal changes sign (every fifth decade, both signs), refined to 50
steps (x (x'/x)^(j/50), C's pow). The interval and its step are read off the linear estimate
of the root and checked by the signs at their ends."""
import numpy as np

from dyncalc.physics.brent_arrays import RTOL_MIN, brent_roots
from dyncalc.physics.numerics_arrays import elementwise
from _limit import arguments, inverse_lines, json_input, number, read, text

DECADES = [5e-324, *(10.0 ** e for e in range(-300, 301, 5)), 1.7976931348623157e308]
GRID = np.array([-d for d in reversed(DECADES)] + [0.0] + DECADES)


def alpha_of(M0, m, l):
    return 9.0 * M0 / (20.0 * m * l * l)


def step_points(a, b, j):
    """The one-off's refinement points j of [a, b] (a b > 0: geometric; the 50th is b)."""
    power = elementwise(lambda r, k: r ** k, b / a, j / 50)
    return np.where(j == 50, b, np.where(a * b > 0, a * power, a + (b - a) * j / 50))


np.seterr(all="ignore")   # b / a on [0, 5e-324]: the linear points are taken there
path, as_json = arguments()
df = read(path)
m, l, w, goal = (number(df, c) for c in ("m [kg]", "l [m]", "omega [rad/s]",
                                           "alpha [rad/s^2]"))
estimate = goal * (20.0 * m * l * l) / 9.0
i = np.clip(np.searchsorted(GRID, estimate) - 1, 0, len(GRID) - 2)
a, b = GRID[i], GRID[i + 1]
ratio = np.where(a * b > 0, np.log(np.abs(estimate / a)) / np.log(np.abs(b / a)),
                 (estimate - a) / (b - a))
j = np.clip(np.floor(ratio * 50).astype(int), 0, 49)
for _ in range(2):   # the step whose ends straddle the goal
    lo, hi = step_points(a, b, j), step_points(a, b, j + 1)
    j = np.clip(j - (alpha_of(lo, m, l) > goal) + (alpha_of(hi, m, l) < goal), 0, 49)
lo, hi = step_points(a, b, j), step_points(a, b, j + 1)
M0 = brent_roots(lambda x, rows: alpha_of(x, m[rows], l[rows]) - goal[rows], lo, hi,
                 xtol=1e-300, rtol=RTOL_MIN, maxiter=200).x
centripetal = m * l * w * w
out = {"M0": text(M0), "alpha": text(alpha_of(M0, m, l)),
       "A_xi": text(0.0 - 0.75 * centripetal), "A_eta": text(27.0 * M0 / (80.0 * l)),
       "B_xi": text(0.0 - 7.0 * centripetal / 12.0), "B_eta": text(21.0 * M0 / (80.0 * l))}
units = {"M0": "N*m", "alpha": "rad/s^2", "A_xi": "N", "A_eta": "N", "B_xi": "N", "B_eta": "N"}
inputs = (json_input(df, "m [kg]", "m", "kg", True) + json_input(df, "l [m]", "l", "m")
          + json_input(df, "omega [rad/s]", "omega", "rad/s")
          + json_input(df, "alpha [rad/s^2]", "alpha", "rad/s^2"))
inverse_lines(df, as_json, "angled-bar-on-shaft", inputs, out, units, "M0", "alpha")
