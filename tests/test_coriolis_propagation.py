"""Uncertainty propagation through ``coriolis`` by its own exact derivatives (read, then
compute: ``result.sensitivity``), against derivatives taken by ``mpmath.diff`` of the hand
formulas at 30 digits.

Tolerance. The slopes are closed formulas (cross products, ``2 Omega v sin(phi)`` ...)
evaluated in float64: a few roundings, so they meet the 30-digit references to 1e-13
relative (a component that is zero in the reference: 1e-13 of the largest component). The
central differences used before (h = 1e-6 |x|) carry a rounding error of about eps/h = 2e-10
relative and a truncation error of h^2 = 1e-12, so they would miss this tolerance: these tests
tell exact derivatives from differences. The propagated uncertainties are the GUM sum
u(y)^2 = sum (dy/dx_i)^2 u(x_i)^2 of those slopes, held to the same 1e-13.
"""
from collections import Counter

import mpmath
import numpy as np
import pytest

from dyncalc.commands import coriolis_read as coriolis_module
from dyncalc.commands.coriolis import coriolis_result, read
from dyncalc.physics import frames
from dyncalc.result.propagate import propagate

EXACT = 1e-13


@pytest.fixture(autouse=True)
def mp_precision():
    """30 digits for the mpmath references, restored afterwards."""
    with mpmath.workdps(30):
        yield


def assert_exact(actual, expected, what="", floor=0.0):
    """``actual`` (float or array) meets the mpmath ``expected`` to :data:`EXACT` relative,
    component by component; a zero component to EXACT of the largest one, or of ``floor``
    where all are zero (a slope that vanishes exactly: |a_c_horizontal| = 2 W v sin phi does
    not depend on the heading, and a rounding or two of its size is left)."""
    actual = np.atleast_1d(np.asarray(actual, dtype=float))
    expected = [mpmath.mpf(e) for e in np.atleast_1d(np.asarray(expected, dtype=object))]
    assert actual.shape == (len(expected),), what
    top = max(abs(e) for e in expected)
    for a, e in zip(actual, expected):
        bound = EXACT * (abs(e) if e != 0 else top if top != 0 else floor)
        assert abs(mpmath.mpf(float(a)) - e) <= bound, (what, float(a), float(e))


def partials(function, point):
    """``{input index: {result: [d component / d input]}}`` by mpmath.diff at ``point``;
    ``function(*point)`` returns result name -> list of mpf components."""
    names = function(*point)
    out = {}
    for i in range(len(point)):
        def along(t, name, k, i=i):
            moved = list(point)
            moved[i] = t
            return function(*moved)[name][k]
        out[i] = {name: [mpmath.diff(lambda t: along(t, name, k), point[i])
                         for k in range(len(values))] for name, values in names.items()}
    return out


def gum(slopes_by_input, sigmas, name):
    """sqrt(sum (slope u)^2) per component, in mpmath."""
    size = len(slopes_by_input[0][name])
    return [mpmath.sqrt(sum((slopes_by_input[i][name][k] * sigmas[i]) ** 2
                            for i in slopes_by_input)) for k in range(size)]


def check(texts, order, function, point):
    """Propagate ``texts``; every slope of ``result.sensitivity()`` and every propagated
    uncertainty meet the mpmath references of ``function`` at ``point`` (inputs in
    ``order``, which is also the order and the names of the variance shares)."""
    result = propagate(lambda: coriolis_result(texts))
    sensitivity = result.sensitivity()
    assert [item.name for item in sensitivity.inputs] == order
    assert not sensitivity.failed
    reference = partials(function, point)
    sigmas = [mpmath.mpf(item.sigma) for item in sensitivity.inputs]
    for name, entry in result.results.items():
        for i, item in enumerate(sensitivity.inputs):
            assert_exact(sensitivity.slopes[name][i], reference[i][name], (name, item.name),
                         floor=float(np.max(np.abs(entry.si))))
        assert_exact(entry.uncertainty, gum(reference, sigmas, name), (name, "u"))
        if np.any(np.asarray(entry.uncertainty) > 0):
            assert list(result.explanation.variance[name]) == order, name
    return result


def mp_cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def mp_norm(a):
    return mpmath.sqrt(sum(x * x for x in a))


def flat(results):
    """Earth mode: the horizontal parts (east, north, 0) of a_c and F_c and their norms."""
    for name in ("a_c", "F_c"):
        if name in results:
            east, north, _ = results[name]
            results[name + "_horizontal"] = [east, north, mpmath.mpf(0)]
            results[name + "_horizontal_mag"] = [mpmath.sqrt(east ** 2 + north ** 2)]
    return results


def si_of(texts, name):
    return mpmath.mpf(float(read(texts).parsed[name].si))


# --------------------------------------------------------------------------------------------
# The scalar form


def test_scalar_form_exact_slopes():
    """a_c = 2 Omega v_r, F_c = m a_c, a_euler = alpha r, a_centripetal = Omega^2 r,
    a_transport = r hypot(alpha, Omega^2): all five magnitudes uncertain."""
    texts = {"omega": "2.5 ± 0.1 rad/s", "vr": "3.7 ± 0.2 m/s", "r": "0.45 ± 0.01 m",
             "alpha": "4.2 ± 0.3 rad/s^2", "mass": "2.3 ± 0.05 kg"}

    def scalar(Om, v, r, al, m):
        a_c = 2 * Om * v
        return {"a_c": [a_c], "F_c": [m * a_c], "a_euler": [al * r],
                "a_centripetal": [Om ** 2 * r],
                "a_transport": [mpmath.sqrt((al * r) ** 2 + (Om ** 2 * r) ** 2)]}

    point = [mpmath.mpf(x) for x in (2.5, 3.7, 0.45, 4.2, 2.3)]
    result = check(texts, ["omega", "vr", "r", "alpha", "mass"], scalar, point)
    # by hand, as a cross-check of the references: u(a_c) = 2 sqrt((v u_Om)^2 + (Om u_v)^2)
    assert result.results["a_c"].uncertainty == pytest.approx(
        2 * float(mpmath.sqrt((3.7 * 0.1) ** 2 + (2.5 * 0.2) ** 2)), rel=EXACT)


def test_scalar_form_in_other_units():
    """rpm, km/h and cm: the slopes are per SI unit, the uncertainties in SI."""
    texts = {"omega": "30 ± 1 rpm", "vr": "10 ± 1 km/h", "r": "20 ± 1 cm"}
    point = [si_of(texts, n) for n in ("omega", "vr", "r")]

    def scalar(Om, v, r):
        return {"a_c": [2 * Om * v], "a_euler": [mpmath.mpf(0)],
                "a_centripetal": [Om ** 2 * r], "a_transport": [Om ** 2 * r]}

    result = check(texts, ["omega", "vr", "r"], scalar, point)
    assert result.results["a_euler"].uncertainty == 0.0


def test_scalar_form_at_its_bounds_takes_the_one_sided_slope():
    """Omega = alpha = 0 (they cannot go negative): a_transport = r hypot(alpha, Omega^2) has
    a corner; its slope in alpha is the one-sided r, in Omega 0, in r hypot(0, 0) = 0.
    a_c = 2 Omega v grows as 2 v from Omega = 0."""
    texts = {"omega": "0 ± 0.1 rad/s", "vr": "3 m/s", "r": "0.5 ± 0.1 m",
             "alpha": "0 ± 1 rad/s^2"}
    result = propagate(lambda: coriolis_result(texts))
    slopes = result.sensitivity().slopes
    assert [slopes["a_transport"][i] for i in range(3)] == [0.0, 0.0, 0.5]
    assert [slopes["a_c"][i] for i in range(3)] == [6.0, 0.0, 0.0]
    assert result.results["a_transport"].uncertainty == 0.5 * 1.0
    assert result.results["a_c"].uncertainty == pytest.approx(6.0 * 0.1, rel=1e-15)
    assert result.results["a_centripetal"].uncertainty == 0.0  # d(Omega^2 r) = 0 at Omega = 0


# --------------------------------------------------------------------------------------------
# The mass (vectors)


def test_mass_with_vectors():
    """Only --mass is uncertain: dF_c/dm = -a_c = -2 Omega x v_r, d|F_c|/dm = |a_c|; the
    other results do not depend on it (zero, shaped like the result)."""
    texts = {"omega": "0.3,-1.2,2 rad/s", "vr": "3,0.5,-1 m/s", "r": "1,2,3 m",
             "alpha": "0,0,1 rad/s^2", "a0": "1,0,0 m/s^2", "mass": "2.5 ± 0.1 kg"}
    Om = [mpmath.mpf(x) for x in (0.3, -1.2, 2)]
    v = [mpmath.mpf(x) for x in (3, 0.5, -1)]

    def vectors(m):
        a_c = [2 * x for x in mp_cross(Om, v)]
        F_c = [-m * x for x in a_c]
        return {"F_c": F_c, "F_c_mag": [mp_norm(F_c)]}

    result = propagate(lambda: coriolis_result(texts))
    sensitivity = result.sensitivity()
    assert [item.name for item in sensitivity.inputs] == ["mass"]
    reference = partials(vectors, [mpmath.mpf(2.5)])[0]
    for name in ("F_c", "F_c_mag"):
        assert_exact(sensitivity.slopes[name][0], reference[name], name)
        assert_exact(result.results[name].uncertainty,
                     [abs(s) * mpmath.mpf(0.1) for s in reference[name]], name)
        assert result.explanation.variance[name] == {"mass": 1.0}
    for name in ("a_c", "a_c_mag", "a_euler", "a_centripetal", "a_transport", "a", "a_mag"):
        u = result.results[name].uncertainty
        assert np.shape(u) == np.shape(result.results[name].si) and not np.any(u), name


# --------------------------------------------------------------------------------------------
# The Earth


def test_earth_latitude_speed_heading_vertical_rate_and_mass():
    """Omega = W (0, cos phi, sin phi), v_r = (v sin psi, v cos psi, w), a_c = 2 Omega x v_r,
    F_c = -m a_c, f = 2 W sin phi; six uncertain inputs."""
    texts = {"latitude": "37.5 ± 0.4 deg", "speed": "85 ± 3 km/h", "heading": "62 ± 2 deg",
             "vertical": "1.5 ± 0.3 m/s", "omega": "7.2921159e-5 ± 1e-7 rad/s",
             "mass": "1200 ± 15 kg"}

    def earth(phi, W, v, psi, w, m):
        Om = [0, W * mpmath.cos(phi), W * mpmath.sin(phi)]
        vr = [v * mpmath.sin(psi), v * mpmath.cos(psi), w]
        a_c = [2 * x for x in mp_cross(Om, vr)]
        F_c = [-m * x for x in a_c]
        return flat({"a_c": a_c, "a_c_mag": [mp_norm(a_c)], "F_c": F_c,
                     "F_c_mag": [mp_norm(F_c)], "Omega": Om, "v_r": vr,
                     "coriolis_parameter": [2 * Om[2]]})

    point = [mpmath.radians(37.5), si_of(texts, "omega"), si_of(texts, "speed"),
             mpmath.radians(62), mpmath.mpf(1.5), mpmath.mpf(1200)]
    # the order of the variance shares: the options as read (latitude, omega, then motion)
    check(texts, ["latitude", "omega", "speed", "heading", "vertical", "mass"], earth, point)


def test_earth_latitude_and_rate_through_the_centripetal_term():
    """With --r the transport terms depend on the latitude and the rate:
    a_centripetal = Omega x (Omega x r), a = a0 + alpha x r + a_centripetal + a_c + a_r,
    v_transport = Omega x r, v = v_transport + v_r."""
    texts = {"latitude": "-30.25 ± 0.5 deg", "vr": "20,5,1 m/s",
             "r": "1200,-400,6.371e6 m", "alpha": "0,0,1e-9 rad/s^2", "a0": "0,0,0.01 m/s^2",
             "ar": "1,0,0 m/s^2", "omega": "7e-5 ± 1e-6 rad/s"}
    vr = [mpmath.mpf(x) for x in (20, 5, 1)]
    r = [mpmath.mpf(x) for x in (1200, -400, 6.371e6)]
    alpha = [0, 0, mpmath.mpf(1e-9)]
    a0 = [0, 0, mpmath.mpf(0.01)]
    ar = [1, 0, 0]

    def earth(phi, W):
        Om = [0, W * mpmath.cos(phi), W * mpmath.sin(phi)]
        a_c = [2 * x for x in mp_cross(Om, vr)]
        cent = mp_cross(Om, mp_cross(Om, r))
        euler = mp_cross(alpha, r)
        transport = [x + y + z for x, y, z in zip(a0, euler, cent)]
        a = [x + y + z for x, y, z in zip(transport, a_c, ar)]
        v_t = mp_cross(Om, r)
        v = [x + y for x, y in zip(v_t, vr)]
        return flat({"a_c": a_c, "a_c_mag": [mp_norm(a_c)], "a_euler": [mpmath.mpf(0)] * 3,
                "a_centripetal": cent, "a_transport": transport, "a": a,
                "a_mag": [mp_norm(a)], "Omega": Om, "coriolis_parameter": [2 * Om[2]],
                "a_transport_mag": [mp_norm(transport)], "v_transport": v_t,
                "v_transport_mag": [mp_norm(v_t)], "v": v, "v_mag": [mp_norm(v)]})

    check(texts, ["latitude", "omega"], earth,
          [mpmath.radians(-30.25), mpmath.mpf(7e-5)])


def test_earth_bare_radians():
    """A bare latitude and heading are radians: the slopes are per radian all the same."""
    texts = {"latitude": "0.7 ± 0.01", "speed": "10 ± 1 m/s", "heading": "1.2 ± 0.1"}

    def earth(phi, v, psi):
        W = mpmath.mpf(frames.EARTH_RATE)
        Om = [0, W * mpmath.cos(phi), W * mpmath.sin(phi)]
        vr = [v * mpmath.sin(psi), v * mpmath.cos(psi), 0]
        a_c = [2 * x for x in mp_cross(Om, vr)]
        return flat({"a_c": a_c, "a_c_mag": [mp_norm(a_c)], "Omega": Om, "v_r": vr,
                     "coriolis_parameter": [2 * Om[2]]})

    check(texts, ["latitude", "speed", "heading"], earth,
          [mpmath.mpf(0.7), mpmath.mpf(10), mpmath.mpf(1.2)])


def test_earth_corners_of_the_magnitudes():
    """|a_c| = 0 has a corner. At the North Pole (latitude 90 deg, it can only fall) moving
    up, the slope is the one-sided -|d a_c/d phi| = -2 W w; from a speed of 0 (it can only
    grow) +|2 Omega x (sin psi, cos psi, 0)|; at an interior zero (vertical 0 ± 1, no
    horizontal motion) the mean of the two sides, 0 - as the central differences gave."""
    W = frames.EARTH_RATE
    pole = propagate(lambda: coriolis_result({"latitude": "90 ± 1 deg", "vertical": "3 m/s"}))
    assert pole.results["a_c_mag"].si == 0.0
    assert pole.sensitivity().slopes["a_c_mag"][0] == pytest.approx(-2 * W * 3, rel=1e-15)
    assert pole.results["a_c_mag"].uncertainty == pytest.approx(
        2 * W * 3 * np.radians(1.0), rel=1e-15)
    # d sin(phi)/d phi = cos 90 deg = 0 exactly (a difference would give about h)
    assert pole.results["coriolis_parameter"].uncertainty == 0.0

    still = propagate(lambda: coriolis_result({"latitude": "60 deg", "speed": "0 ± 1 m/s",
                                               "heading": "90 deg"}))
    # v_r along east: |2 Omega x e_east| = 2 W (|Omega| perpendicular to east)
    assert still.results["a_c_mag"].uncertainty == pytest.approx(2 * W, rel=1e-15)

    interior = propagate(lambda: coriolis_result({"latitude": "60 deg",
                                                  "vertical": "0 ± 1 m/s"}))
    assert interior.results["a_c_mag"].uncertainty == 0.0
    # while the vector itself moves: d a_c / dw = 2 Omega x (0, 0, 1) = (2 W cos 60, 0, 0)
    assert interior.results["a_c"].uncertainty[0] == pytest.approx(W, rel=1e-15)


# --------------------------------------------------------------------------------------------
# Cost: nothing is read or computed again


@pytest.mark.parametrize("texts", [
    {"omega": "2 ± 0.1 rad/s", "vr": "3 ± 0.2 m/s", "r": "0.5 ± 0.01 m",
     "alpha": "4 ± 0.3 rad/s^2", "mass": "2 ± 0.05 kg"},
    {"omega": "0,0,2 rad/s", "vr": "3,0,0 m/s", "r": "1,2,3 m", "mass": "2 ± 0.1 kg"},
    {"latitude": "45 ± 1 deg", "speed": "100 ± 5 km/h", "heading": "30 ± 2 deg",
     "vertical": "2 ± 0.5 m/s", "omega": "7.29e-5 ± 1e-7 rad/s", "mass": "3 ± 0.1 kg",
     "r": "0,0,6.4e6 m"},
], ids=["scalars", "vectors", "earth"])
def test_propagation_reads_every_text_once(monkeypatch, texts):
    """Each option text is parsed exactly once (through the parse_quantity and parse_vector
    names coriolis_read.py uses) and the formula is computed once: no re-runs per input."""
    reads = Counter()
    computed = []
    originals = {name: getattr(coriolis_module, name)
                 for name in ("parse_quantity", "parse_vector")}

    def counting(name):
        def parse(text, *args, **kwargs):
            reads[(kwargs.get("label"), text)] += 1
            return originals[name](text, *args, **kwargs)
        return parse

    for name in originals:
        monkeypatch.setattr(coriolis_module, name, counting(name))
    relative_acceleration = frames.relative_acceleration
    monkeypatch.setattr(frames, "relative_acceleration",
                        lambda *a, **k: computed.append(1) or relative_acceleration(*a, **k))

    result = propagate(lambda: coriolis_result(texts))
    assert reads == Counter({(f"--{name}", text): 1 for name, text in texts.items()})
    assert len(computed) == 1
    uncertain = sorted(name for name, text in texts.items() if "±" in text)
    assert sorted(item.name for item in result.sensitivity().inputs) == uncertain
    assert sum(reads.values()) == len(texts)  # and the sensitivity read nothing more
    assert any(np.any(entry.uncertainty) for entry in result.results.values())
