"""Limit: rigid-body --scene drum-two-blocks (m1, m2, r1, r2, J_A; g at its default) and
--scene angled-bar-on-shaft (m, l, M0, omega).

    python rigid_body.py drum|angled-bar FILE [--json]

drum-two-blocks: dyncalc's results are the floats nearest the exact rational closed form
(alpha = (m2 r2 - m1 r1) g / (J_A + m1 r1^2 + m2 r2^2), a1 = r1 alpha, a2 = r2 alpha,
S1 = m1 (g + a1), S2 = m2 (g - a2)); no float formula gives those bits, so the formulas run
in double-double (Dekker's exact products) and the few rows whose rounding the error bound
leaves open are done in fractions. angled-bar-on-shaft: plain float formulas."""
import sys
from fractions import Fraction

import numpy as np
from _limit import csv_line, json_input, json_lines, json_result, number, read, text

G = 9.80665


def two_sum(a, b):
    s = a + b
    t = s - a
    return s, (a - (s - t)) + (b - t)


def split(a):
    c = 134217729.0 * a
    h = c - (c - a)
    return h, a - h


def two_prod(a, b):
    p = a * b
    (ah, al), (bh, bl) = split(a), split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def norm(h, lo):
    s = h + lo
    return s, lo - (s - h)


def mul(a, b):
    p, e = two_prod(a[0], b[0])
    return norm(p, e + (a[0] * b[1] + a[1] * b[0]))


def add(a, b):
    s, e = two_sum(a[0], b[0])
    return norm(s, e + (a[1] + b[1]))


def div(a, b):
    q = a[0] / b[0]
    p = mul(b, (q, 0.0))
    s, e = two_sum(a[0], -p[0])
    return norm(q, (s + (e - p[1] + a[1])) / b[0])


def rounded(x, bound):
    """(float, sure): sure where no midpoint lies within ``bound`` (relative) of hi + lo."""
    z = x[0] + x[1]
    rest = (x[0] - z) + x[1]
    half = 0.5 * (np.abs(z) - np.nextafter(np.abs(z), 0.0))
    return z, half - np.abs(rest) > bound * np.abs(z)


def drum_exact(m1, m2, r1, r2, J):
    m1, m2, r1, r2, J, g = (Fraction(v) for v in (m1, m2, r1, r2, J, G))
    alpha = (m2 * r2 - m1 * r1) * g / (J + m1 * r1 * r1 + m2 * r2 * r2)
    return [float(v) for v in (alpha, r1 * alpha, r2 * alpha, m1 * (g + r1 * alpha),
                               m2 * (g - r2 * alpha))]


def drum_values(m1, m2, r1, r2, J):
    """``[alpha, a1, a2, S1, S2]``, each the float nearest the exact value (arrays)."""
    p1, p2 = two_prod(m1, r1), two_prod(m2, r2)
    top = add(p2, (-p1[0], -p1[1]))
    den = add(add((J, 0.0), mul(p1, (r1, 0.0))), mul(p2, (r2, 0.0)))
    alpha = div(mul(top, (G, 0.0)), den)
    # the difference's rounding grows by |m2 r2| + |m1 r1| over |top| (and a sum g +- a by a
    # little more: 2^-80 leaves it 2^23 of room)
    bound = 2.0 ** -80 * (1.0 + (np.abs(p1[0]) + np.abs(p2[0])) / np.abs(top[0]))
    a1, a2 = mul(alpha, (r1, 0.0)), mul(alpha, (r2, 0.0))
    results = [alpha, a1, a2, mul((m1, 0.0), add((G, 0.0), a1)),
               mul((m2, 0.0), add((G, 0.0), (-a2[0], -a2[1])))]
    values, sure = [], np.ones(len(m1), dtype=bool)
    for x in results:
        z, ok = rounded(x, bound)
        values.append(z)
        sure &= ok
    for i in np.flatnonzero(~sure).tolist():
        for column, v in zip(values, drum_exact(m1[i], m2[i], r1[i], r2[i], J[i])):
            column[i] = v
    return values


def drum(df):
    cols = ("m1 [kg]", "m2 [kg]", "r1 [m]", "r2 [m]", "J_A [kg*m^2]")
    values = drum_values(*(number(df, c) for c in cols))
    names = ("alpha", "a1", "a2", "S1", "S2")
    units = ("rad/s^2", "m/s^2", "m/s^2", "N", "N")
    given = [(c, c.split(" ")[0], c.split("[")[1][:-1]) for c in cols]
    return dict(zip(names, values)), dict(zip(names, units)), given, (
        ', "g": {"value": 9.80665, "unit": "m/s^2", "text": "9.80665 m/s^2"}')


def angled_bar(df):
    cols = ("m [kg]", "l [m]", "M0 [N*m]", "omega [rad/s]")
    m, l, M0, w = (number(df, c) for c in cols)
    centripetal = m * l * w * w
    values = {"alpha": 9.0 * M0 / (20.0 * m * l * l), "A_xi": 0.0 - 0.75 * centripetal,
              "A_eta": 27.0 * M0 / (80.0 * l), "B_xi": 0.0 - 7.0 * centripetal / 12.0,
              "B_eta": 21.0 * M0 / (80.0 * l)}
    units = {"alpha": "rad/s^2", "A_xi": "N", "A_eta": "N", "B_xi": "N", "B_eta": "N"}
    given = [(c, c.split(" ")[0], c.split("[")[1][:-1]) for c in cols]
    return values, units, given, ""


def main():
    scene, path, as_json = sys.argv[1], sys.argv[2], "--json" in sys.argv[3:]
    df = read(path)
    values, units, given, tail = (drum if scene == "drum" else angled_bar)(df)
    out = {name: text(v) for name, v in values.items()}
    if as_json:
        name = "drum-two-blocks" if scene == "drum" else "angled-bar-on-shaft"
        head = ('"schema": "dyncalc/2", "command": "rigid-body", "scene": "' + name + '", '
                '"model": "linear", "method": "closed-form"')
        inputs = [p for i, (c, n, u) in enumerate(given) for p in json_input(df, c, n, u, i == 0)]
        if tail:
            inputs.append(tail)
        json_lines(len(df), head, inputs, [p for i, (n, v) in enumerate(out.items())
                                           for p in json_result(n, v, units[n], i == 0)])
    else:
        csv_line(df, out, {n: f"{n} [{u}]" for n, u in units.items()})


if __name__ == "__main__":
    main()
