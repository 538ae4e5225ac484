"""damping-ratio reads, then computes (issue 14): its uncertainties come from derivatives worked
out on the parsed inputs, exact for the closed forms, and no text is read twice.

Tolerances. The closed forms are differentiated by the chain rule in float64, so each slope
is met to 1e-13 relative against mpmath.diff of the textbook formula at 30 digits (a few
roundings of a handful of operations). Central differences with dyncalc's step
h = 1e-6 |x| would miss that: their truncation error is ~h^2 = 1e-12 and their rounding
~eps/h = 2e-10 relative (:func:`test_differences_would_miss_the_tolerance` shows it). A
scene's own derivatives are central differences (:mod:`dyncalc.scenes.runner`): 1e-8 there.
"""
import math

import mpmath
import pytest

from dyncalc.commands import damping_ratio as dr
from dyncalc.result.propagate import RELATIVE_STEP, propagate
from dyncalc.units import Q_
from helpers import count_readings, json_of

EXACT = 1e-13
DIFF_TOL = 1e-8
G0 = 9.80665


@pytest.fixture(autouse=True)
def mp_precision():
    """30 digits for the mpmath references, restored afterwards."""
    with mpmath.workdps(30):
        yield


def mp_slopes(formula, point: dict[str, float]) -> dict[str, mpmath.mpf]:
    """d formula / d x for every x in ``point`` (mpmath.diff, 30 digits)."""
    names = list(point)
    args = tuple(mpmath.mpf(point[n]) for n in names)
    out = {}
    for i, name in enumerate(names):
        order = tuple(1 if j == i else 0 for j in range(len(names)))
        out[name] = mpmath.diff(lambda *a: formula(**dict(zip(names, a))), args, order)
    return out


def assert_exact(kw, formulas, point, sigma):
    """Every slope of the results in ``formulas`` against mpmath to EXACT, and the
    propagated uncertainty against the hand law sqrt(sum (slope sigma)^2)."""
    result = dr.damping_ratio(**kw)
    sensitivity = result.sensitivity()
    index = {item.name: i for i, item in enumerate(sensitivity.inputs)}
    assert set(index) == set(sigma)
    assert not sensitivity.failed
    propagated = propagate(lambda: dr.damping_ratio(**kw))
    for name, formula in formulas.items():
        assert result.results[name].si == pytest.approx(float(formula(**{
            n: mpmath.mpf(v) for n, v in point.items()})), rel=1e-14), name
        reference = mp_slopes(formula, point)
        for x, slope in reference.items():
            if x not in index:
                continue
            got = sensitivity.slopes[name][index[x]]
            assert got == pytest.approx(float(slope), rel=EXACT, abs=0.0), (name, x)
        hand = math.sqrt(sum(float(reference[x] * sigma[x]) ** 2 for x in sigma))
        assert propagated.results[name].uncertainty == pytest.approx(hand, rel=EXACT), name
    assert propagated.results["regime"].uncertainty is None  # a word: no uncertainty


# --- the closed forms, against mpmath --------------------------------------------------------

def ckm_formulas():
    def zeta(c, k, m):
        return c / (2 * mpmath.sqrt(k * m))

    def omega_d(c, k, m):
        return mpmath.sqrt(4 * k * m - c ** 2) / (2 * m)

    return {
        "zeta": zeta,
        "delta": lambda c, k, m: 2 * mpmath.pi * c / mpmath.sqrt(4 * k * m - c ** 2),
        "Q": lambda c, k, m: 1 / (2 * zeta(c, k, m)),
        "c_c": lambda c, k, m: 2 * mpmath.sqrt(k * m),
        "c": lambda c, k, m: c,
        "omega": lambda c, k, m: mpmath.sqrt(k / m),
        "xi": lambda c, k, m: c / (2 * m),
        "omega_d": omega_d,
        "f_d": lambda c, k, m: omega_d(c, k, m) / (2 * mpmath.pi),
        "T_d": lambda c, k, m: 2 * mpmath.pi / omega_d(c, k, m),
    }


def test_c_k_m_underdamped_is_exact():
    """zeta = c/(2 sqrt(k m)), delta = 2 pi c/sqrt(4km - c^2), Q = 1/(2 zeta), c_c, omega,
    xi = c/(2m), omega_d = sqrt(4km - c^2)/(2m), f_d, T_d, each in c, k and m; the units
    typed (kN*s/m, kN/m, g) are read into SI first."""
    kw = dict(c="(0.01 ± 0.001) kN*s/m", k="(0.1 ± 0.005) kN/m", m="2000 ± 100 g")
    assert_exact(kw, ckm_formulas(), {"c": 10.0, "k": 100.0, "m": 2.0},
                 {"c": 1.0, "k": 5.0, "m": 0.1})


def test_c_k_m_overdamped_is_exact():
    """Overdamped (zeta = 1.41): zeta, Q, c_c, c, omega, xi are closed there too."""
    formulas = {name: f for name, f in ckm_formulas().items()
                if name in ("zeta", "Q", "c_c", "c", "omega", "xi")}
    kw = dict(c="40 ± 1 N*s/m", k="(100 ± 5) N/m", m="2 ± 0.1 kg")
    assert_exact(kw, formulas, {"c": 40.0, "k": 100.0, "m": 2.0},
                 {"c": 1.0, "k": 5.0, "m": 0.1})


def decrement_formulas(delta_of):
    """The results of a decrement ``delta_of(**inputs)`` with a natural frequency omega."""
    def zeta(**x):
        d = delta_of(**x)
        return d / mpmath.sqrt(4 * mpmath.pi ** 2 + d ** 2)

    def omega_d(**x):
        return x["omega"] * mpmath.sqrt(1 - zeta(**x) ** 2)

    return {
        "zeta": zeta,
        "delta": delta_of,
        "Q": lambda **x: 1 / (2 * zeta(**x)),
        "xi": lambda **x: zeta(**x) * x["omega"],
        "omega_d": omega_d,
        "f_d": lambda **x: omega_d(**x) / (2 * mpmath.pi),
        "T_d": lambda **x: 2 * mpmath.pi / omega_d(**x),
    }


def test_decrement_with_omega_is_exact():
    """zeta = delta/sqrt(4 pi^2 + delta^2), Q = 1/(2 zeta), xi = zeta omega,
    omega_d = omega sqrt(1 - zeta^2), f_d, T_d in delta and omega (typed in rpm)."""
    formulas = decrement_formulas(lambda decrement, omega: decrement)
    omega = 115 * 2 * math.pi / 60
    assert_exact(dict(decrement="0.23 ± 0.01", omega="(115 ± 3) rpm"), formulas,
                 {"decrement": 0.23, "omega": omega},
                 {"decrement": 0.01, "omega": 3 * 2 * math.pi / 60})


def test_ratio_and_cycles_with_omega_is_exact():
    """delta = ln(R)/N over N = 3 cycles, then as the decrement."""
    formulas = decrement_formulas(lambda ratio, omega: mpmath.log(ratio) / 3)
    assert_exact(dict(ratio="10 ± 0.5", cycles="3", omega="12 ± 0.5 rad/s"), formulas,
                 {"ratio": 10.0, "omega": 12.0}, {"ratio": 0.5, "omega": 0.5})


def test_ratio_with_k_and_m_is_exact():
    """With k and m: omega = sqrt(k/m), c_c = 2 sqrt(k m), c = zeta c_c."""
    def omega(ratio, k, m):
        return mpmath.sqrt(k / m)

    def of_k_and_m(formula):  # a formula in (ratio, omega) as one in (ratio, k, m)
        return lambda ratio, k, m: formula(ratio=ratio, omega=omega(ratio, k, m))

    base = decrement_formulas(lambda **x: mpmath.log(x["ratio"]))  # one cycle
    formulas = {name: of_k_and_m(formula) for name, formula in base.items()}
    formulas["omega"] = omega
    formulas["c_c"] = lambda ratio, k, m: 2 * mpmath.sqrt(k * m)
    formulas["c"] = lambda ratio, k, m: base["zeta"](ratio=ratio) * 2 * mpmath.sqrt(k * m)
    assert_exact(dict(ratio="2 ± 0.1", k="(100 ± 5) N/m", m="2 ± 0.1 kg"), formulas,
                 {"ratio": 2.0, "k": 100.0, "m": 2.0}, {"ratio": 0.1, "k": 5.0, "m": 0.1})


def test_decrement_alone_is_exact_and_named_as_typed():
    """--decrement alone: zeta, delta and Q, all shares on 'decrement'."""
    data = json_of("damping-ratio", "--decrement", "0.23 ± 0.01", "--explain")
    delta = mpmath.mpf("0.23")
    slope = mpmath.diff(lambda d: d / mpmath.sqrt(4 * mpmath.pi ** 2 + d ** 2), delta)
    assert data["results"]["zeta"]["uncertainty"] == pytest.approx(float(slope) * 0.01,
                                                                   rel=EXACT)
    assert data["results"]["delta"]["uncertainty"] == pytest.approx(0.01, rel=EXACT)
    assert data["extra"]["explanation"]["variance"] == {name: {"decrement": 1.0}
                                               for name in ("zeta", "delta", "Q")}


def test_differences_would_miss_the_tolerance():
    """The tolerance above tells exact derivatives from differences: the central difference
    of damping_from_coefficients with dyncalc's step misses mpmath's d omega_d / d m by more
    than 1e-13 relative, while the slope damping-ratio gives meets it."""
    from dyncalc.physics.damping import damping_from_coefficients

    def omega_d(m):
        return damping_from_coefficients(Q_(10, "N*s/m"), Q_(100, "N/m"),
                                         Q_(m, "kg")).values["omega_d"].magnitude

    h = RELATIVE_STEP * 2.0
    difference = (omega_d(2.0 + h) - omega_d(2.0 - h)) / (2 * h)
    exact = float(mp_slopes(ckm_formulas()["omega_d"], {"c": 10, "k": 100, "m": 2})["m"])
    assert abs(difference - exact) > EXACT * abs(exact)
    sensitivity = dr.damping_ratio(c="10 N*s/m", k="100 N/m", m="2 ± 0.1 kg").sensitivity()
    assert sensitivity.slopes["omega_d"][0] == pytest.approx(exact, rel=EXACT, abs=0.0)


# --- the edges -------------------------------------------------------------------------------

def test_at_a_bound_the_derivative_is_exact():
    """c = 0 ± 1 N*s/m (c >= 0, undamped): d zeta/dc = 1/c_c, d delta/dc = 2 pi/c_c,
    d xi/dc = 1/(2m) and omega_d, which goes with c^2, has slope zero: exact, where a
    one-sided difference had to be taken before."""
    r = propagate(lambda: dr.damping_ratio(c="0 ± 1 N*s/m", k="100 N/m", m="2 kg"))
    c_c = 2 * math.sqrt(200)
    assert r.results["zeta"].uncertainty == pytest.approx(1 / c_c, rel=EXACT)
    assert r.results["delta"].uncertainty == pytest.approx(2 * math.pi / c_c, rel=EXACT)
    assert r.results["xi"].uncertainty == pytest.approx(0.25, rel=EXACT)
    assert r.results["omega_d"].uncertainty == 0.0
    assert "Q" not in r.results


def test_ratio_at_one_is_exact():
    """R = 1 ± 0.1 (R >= 1): d delta/dR = 1/(R N) = 1, d zeta/d delta = 1/(2 pi) at 0."""
    r = propagate(lambda: dr.damping_ratio(ratio="1 ± 0.1"))
    assert r.results["delta"].uncertainty == pytest.approx(0.1, rel=EXACT)
    assert r.results["zeta"].uncertainty == pytest.approx(0.1 / (2 * math.pi), rel=EXACT)


def test_critical_damping_is_exact():
    """c = c_c = 20 N*s/m: zeta is taken as 1, and moves as c/c_c (u = u_c/c_c); Q =
    c_c/(2c) likewise; there is no damped frequency or decrement to propagate."""
    r = propagate(lambda: dr.damping_ratio(c="20 ± 1 N*s/m", k="100 N/m", m="1 kg"))
    assert r.results["regime"].si == "critically damped"
    assert r.results["zeta"].uncertainty == pytest.approx(0.05, rel=EXACT)
    assert r.results["Q"].uncertainty == pytest.approx(0.025, rel=EXACT)
    assert r.results["xi"].uncertainty == pytest.approx(0.5, rel=EXACT)
    assert r.warnings[-1].startswith("zeta = 1: the system is critically damped")


def test_uncertain_cycles_leave_the_decrement_unpropagated():
    """A whole number of cycles has no derivative: zeta, delta, Q (through ln(R)/N) are not
    propagated, with the usual warning; omega and c_c, which do not depend on N, are."""
    r = propagate(lambda: dr.damping_ratio(ratio="10 ± 0.5", cycles="10 ± 1",
                                           k="(100 ± 5) N/m", m="2 kg"))
    for name in ("zeta", "delta", "Q", "c", "xi", "omega_d"):
        assert r.results[name].uncertainty is None, name
        assert f"the uncertainty of {name} could not be propagated" in " ".join(r.warnings)
    assert r.results["omega"].uncertainty == pytest.approx(math.sqrt(50) / 2 * 0.05,
                                                           rel=EXACT)


def test_amplitudes_carry_no_uncertainty_but_omega_does():
    """The peaks of --amplitudes are plain numbers: zeta, delta, Q and the fit's own
    residual and delta_se get uncertainty 0; omega_d = omega 2 pi/h, xi = zeta omega, f_d
    and T_d take omega's, exactly (u(omega_d) = 2 pi u(omega)/h)."""
    r = propagate(lambda: dr.damping_ratio(amplitudes="12.1, 9.0, 6.8, 5.1, 3.8 mV",
                                           omega="25 ± 1 rad/s", method="nonlinear"))
    for name in ("zeta", "delta", "Q", "residual", "delta_se"):
        assert r.results[name].uncertainty == 0.0, name
    delta = r.results["delta"].si
    h = math.hypot(2 * math.pi, delta)
    assert r.results["omega_d"].uncertainty == pytest.approx(2 * math.pi / h, rel=EXACT)
    assert r.results["xi"].uncertainty == pytest.approx(delta / h, rel=EXACT)
    assert r.results["T_d"].uncertainty == pytest.approx(h / 625, rel=EXACT)
    assert r.explanation.variance["omega_d"] == {"omega": 1.0}


# --- a scene: its derivatives carried through zeta -------------------------------------------

def test_scene_derivatives_reach_the_decrement_and_q():
    """rod-in-fluid, zeta = beta l^(3/2) / (m sqrt(6 g)): the scene differentiates zeta (central
    differences on its parameters as read); damping-ratio carries that through
    delta = 2 pi zeta/sqrt(1 - zeta^2) and Q = 1/(2 zeta), which were left unpropagated
    before."""
    r = propagate(lambda: dr.damping_ratio(scene="rod-in-fluid", params=(
        "m=1.5 ± 0.1 kg", "l=0.8m", "beta=2 ± 0.2 N*s/m^2")))
    point = {"m": 1.5, "beta": 2.0}
    sigma = {"m": 0.1, "beta": 0.2}

    def zeta(m, beta):
        return beta * mpmath.mpf("0.8") ** 1.5 / (m * mpmath.sqrt(6 * mpmath.mpf(G0)))

    formulas = {"zeta": zeta,
                "delta": lambda m, beta: 2 * mpmath.pi * zeta(m, beta)
                / mpmath.sqrt(1 - zeta(m, beta) ** 2),
                "Q": lambda m, beta: 1 / (2 * zeta(m, beta))}
    for name, formula in formulas.items():
        slopes = mp_slopes(formula, point)
        terms = {x: float(slopes[x] * sigma[x]) ** 2 for x in sigma}
        assert r.results[name].uncertainty == pytest.approx(math.sqrt(sum(terms.values())),
                                                            rel=DIFF_TOL), name
        shares = r.explanation.variance[name]
        assert set(shares) == {"m", "beta"}
        assert shares["beta"] == pytest.approx(terms["beta"] / sum(terms.values()), rel=1e-6)
    assert not [w for w in r.warnings if "could not be propagated" in w]


# --- nothing is read twice ---------------------------------------------------------------------

@pytest.mark.parametrize("kw, texts", [
    (dict(c="10 ± 1 N*s/m", k="100 ± 5 N/m", m="2 ± 0.1 kg"), 3),
    (dict(decrement="0.23 ± 0.01", omega="12 ± 0.5 rad/s"), 2),
    (dict(ratio="10 ± 0.5", cycles="3", k="100 ± 5 N/m", m="2 ± 0.1 kg"), 4),
    (dict(amplitudes="12.1, 9.0, 6.8, 5.1, 3.8", omega="25 ± 1 rad/s"), 1),
])
def test_propagation_reads_every_text_once(monkeypatch, kw, texts):
    """Propagating every uncertain input of a closed form parses each text once and runs
    the physics (and the fit) once: the derivatives are worked out on the parsed inputs."""
    from dyncalc.physics import damping, decay_fit

    calls = []
    counted = {}
    for module, name in ((dr, "parse_quantity"), (damping, "damping_from_coefficients"),
                         (damping, "damping_from_decrement"), (decay_fit, "fit_decrement")):
        original = getattr(module, name)
        counted[name] = 0

        def counting(*args, _name=name, _original=original, **kwargs):
            counted[_name] += 1
            if _name == "parse_quantity":
                calls.append(args[0])
            return _original(*args, **kwargs)
        monkeypatch.setattr(module, name, counting)
    result = propagate(lambda: dr.damping_ratio(**kw))
    assert len(calls) == texts and len(set(calls)) == texts, calls
    physics = counted["damping_from_coefficients"] + counted["damping_from_decrement"]
    assert physics == 1
    assert counted["fit_decrement"] == (1 if "amplitudes" in kw else 0)
    assert result.results["zeta"].uncertainty is not None


def test_scene_reads_every_text_once(monkeypatch):
    """A damping scene: each parameter text is read once (by the scene runner, the default
    g included), and its physics runs once as typed and twice per uncertain parameter (3)."""
    import dyncalc.scenes
    from dyncalc.scenes import runner

    calls = count_readings(monkeypatch, runner)
    scene = dyncalc.scenes.get_scene("pendulum-spring-dashpot")
    runs = []
    counted = scene.replace(compute=lambda **kw: runs.append(1) or scene.compute(**kw))
    monkeypatch.setattr(dyncalc.scenes, "get_scene", lambda name: counted)
    r = propagate(lambda: dr.damping_ratio(scene="pendulum-spring-dashpot", k="200 ± 10 N/m",
                                           m="2 ± 0.1 kg", params=("a=0.5m", "d=6 ± 0.5 N*s/m")))
    assert len(calls) == 5 and len(set(calls)) == 5, calls
    assert len(runs) == 1 + 2 * 3
    assert r.results["delta"].uncertainty > 0 and r.results["Q"].uncertainty > 0


# --- an inverse scene: a root find, differenced on the values as read ------------------------

def test_inverse_scene_from_q_reads_once_and_solves_once(monkeypatch):
    """pendulum-spring-dashpot solved for k from Q = 10 ± 0.5 (zeta = 1/(2Q), d = 6 N*s/m):
    zeta = d/(8 sqrt(k m + g m^2/(2a))) gives k = ((d Q/4)^2 - g m^2/(2a))/m. Every text is
    read once (Q's as the zeta target it becomes, u(zeta) = u(Q)/(2 Q^2), once too); the
    full root search runs once, as typed, and no root is searched for again (the derivatives
    come from the implicit function theorem at the root found). The shares are named as
    typed: Q, m."""
    from dyncalc.scenes import inverse, runner

    calls = count_readings(monkeypatch, dr, runner, inverse)
    searches = []
    roots = inverse._Problem.roots
    monkeypatch.setattr(inverse._Problem, "roots",
                        lambda self, goal: searches.append(goal) or roots(self, goal))
    r = propagate(lambda: dr.damping_ratio(scene="pendulum-spring-dashpot", params=(
        "m=2 ± 0.1 kg", "a=0.5m", "d=6 N*s/m", "Q=10 ± 0.5")))
    # each typed text once (g by its default), and once the zeta target Q became
    assert sorted(calls) == sorted(["2 ± 0.1 kg", "0.5m", "6 N*s/m", "9.80665 m/s^2",
                                    "10 ± 0.5", "0.05 +/- 0.0025"]), calls
    assert len(searches) == 1

    def k(m, Q):
        return ((6 * Q / 4) ** 2 - G0 * m ** 2 / (2 * 0.5)) / m

    slopes = mp_slopes(k, {"m": 2.0, "Q": 10.0})
    terms = {"m": float(slopes["m"] * 0.1) ** 2, "Q": float(slopes["Q"] * 0.5) ** 2}
    assert r.results["k"].si == pytest.approx(float(k(mpmath.mpf(2), mpmath.mpf(10))),
                                              rel=1e-12)
    assert r.results["k"].uncertainty == pytest.approx(math.sqrt(sum(terms.values())),
                                                       rel=DIFF_TOL)
    shares = r.explanation.variance["k"]
    assert set(shares) == {"m", "Q"}
    assert shares["Q"] == pytest.approx(terms["Q"] / sum(terms.values()), rel=1e-6)
    # zeta and delta follow from Q alone: u(zeta) = u(Q)/(2 Q^2), all of their variance is Q's
    assert r.results["zeta"].uncertainty == pytest.approx(0.5 / 200, rel=DIFF_TOL)
    assert r.explanation.variance["delta"] == {"m": 0.0, "Q": 1.0}
    assert r.inputs["zeta"].uncertainty is None  # zeta (from Q) is shown as before


def test_inverse_scene_from_delta():
    """rod-in-fluid solved for beta from delta = 0.5 ± 0.02: beta = zeta beta_crit,
    zeta = delta/sqrt(4 pi^2 + delta^2), beta_crit = (m/l) sqrt(6 g/l); the shares are
    named delta and m, as the user typed them."""
    r = propagate(lambda: dr.damping_ratio(scene="rod-in-fluid", params=(
        "m=1.5 ± 0.1 kg", "l=0.8m", "delta=0.5 ± 0.02")))

    def beta(m, delta):
        zeta = delta / mpmath.sqrt(4 * mpmath.pi ** 2 + delta ** 2)
        l = mpmath.mpf("0.8")
        return zeta * m / l * mpmath.sqrt(6 * mpmath.mpf(G0) / l)

    slopes = mp_slopes(beta, {"m": 1.5, "delta": 0.5})
    terms = {"m": float(slopes["m"] * 0.1) ** 2, "delta": float(slopes["delta"] * 0.02) ** 2}
    assert r.results["beta"].uncertainty == pytest.approx(math.sqrt(sum(terms.values())),
                                                          rel=DIFF_TOL)
    assert set(r.explanation.variance["beta"]) == {"m", "delta"}
    assert r.results["delta"].uncertainty == pytest.approx(0.02, rel=DIFF_TOL)


def test_a_bracket_is_judged_by_signs_not_by_a_product():
    """Solving again next to a root: omega = sqrt(k/m) with m = 1e300 kg is 1e-165 rad/s at
    k = 1e-30 N/m. Between k = 4e-30 and 9e-30 there is no root (y - goal = 1e-165 and
    2e-165, whose product underflows to 0: taken for a bracket, Brent's method refused it
    and the propagation crashed); between 2.5e-31 and 4e-30 there is one."""
    from dyncalc.scenes import get_scene, inverse, runner

    scene = get_scene("mass-spring")
    prepared = runner.read_inputs(scene, {"m": "1e300 kg"}, {}, False, unknown=("k",))
    problem = inverse._Problem(scene, prepared, scene.param("k"), "omega", None, None)
    assert problem._root_between(4e-30, 9e-30, 1e-165) is None
    assert problem._root_between(2.5e-31, 4e-30, 1e-165) == pytest.approx(1e-30, rel=1e-12)
