"""Spring networks: textbook examples, independent checks, properties, accuracy, refusals."""
import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncalc.errors import InputError
from dyncalc.commands.springs import network_stiffness
from dyncalc.physics import springs
from dyncalc.physics.numerics import monomial, parallel_sum, series_sum
from dyncalc.units import Q_

LBF = 4.4482216152605   # N, exact by definition
INCH = 0.0254           # m, exact by definition

# The textbook works symbolically; these numbers are ours: EI = 2e4 N m^2, a = 1 m, k = 5 kN/m.
EI, A, K = 2e4, 1.0, 5e3


def k_eq(how, *words):
    return network_stiffness(how, list(words)).results["k_eq"].si


# --- textbook examples (Gross et al., Engineering Mechanics 3) -------------------------------

def test_e5_11_beam_parallel_to_truss():
    """E5.11: midspan of a beam of span 2l parallel to a three-bar truss EA/((1+sqrt 2) l)."""
    ei, ea, l = 1e5, 2e7, 1.5
    expected = 48 * ei / (2 * l) ** 3 + ea / ((1 + math.sqrt(2)) * l)
    got = k_eq("parallel", "simply-supported(l=2*1.5m)", "axial(l=(1+2**0.5)*1.5m)",
               "EI=1e5 N*m^2", "EA=2e7 N")
    assert got == pytest.approx(expected, rel=1e-15)
    assert expected == pytest.approx(6 * ei / l**3 + ea / (2.414213562373095 * l), rel=1e-14)


def test_e5_19_beam_in_series_with_spring():
    """E5.19: k* = k EI / (k a^3 + EI)."""
    expected = K * EI / (K * A**3 + EI)
    assert expected == 4000.0
    assert k_eq("series", "beam(c=1, l=1m, EI=2e4N*m^2)", "5kN/m") == pytest.approx(
        expected, rel=1e-15)


def test_e5_26_system_1_all_parallel():
    """E5.26 system 1: cantilevers of lengths 2a and a and the spring in parallel."""
    expected = 27 * EI / (8 * A**3) + K
    got = k_eq("parallel", "cantilever(l=2m)", "cantilever(l=1m)", "5kN/m", "EI=2e4 N*m^2")
    assert got == pytest.approx(expected, rel=1e-15)
    assert got == 72500.0


def test_e5_26_system_2_pair_in_series_with_spring():
    """E5.26 system 2: the cantilever pair in parallel, in series with the spring."""
    expected = 27 * EI * K / (27 * EI + 8 * K * A**3)
    got = k_eq("series", "parallel(cantilever(l=2m), cantilever(l=1m))", "5kN/m",
               "EI=2e4 N*m^2")
    assert got == pytest.approx(expected, rel=1e-15)
    assert got == pytest.approx(4655.172413793103, rel=1e-15)


def test_e5_26_with_modulus_and_second_moment_in_other_units():
    """The same system with E and I given separately, in GPa and cm^4 (E I = 2e4 N m^2)."""
    got = k_eq("series", "parallel(cantilever(l=2000mm), cantilever(l=100cm))", "5 N/mm",
               "E=200GPa", "I=10cm^4")
    assert got == pytest.approx(27 * EI * K / (27 * EI + 8 * K * A**3), rel=1e-14)


# --- element formulas against a second derivation --------------------------------------------

def test_cantilever_matches_deflection_formula():
    """Tip deflection of a cantilever under F is F l^3 / (3 E I): k = F / deflection."""
    E, I, l, F = 210e9, 8.33e-6, 2.5, 1000.0
    deflection = F * l**3 / (3 * E * I)
    got = springs.cantilever_stiffness(Q_(l, "m"), E=Q_(E, "Pa"), I=Q_(I, "m^4"))
    assert got.to("N/m").magnitude == pytest.approx(F / deflection, rel=1e-15)


def test_midspan_matches_deflection_formula():
    E, I, l, F = 70e9, 1.2e-6, 3.0, 500.0
    deflection = F * l**3 / (48 * E * I)
    got = springs.midspan_stiffness(Q_(l, "m"), E=Q_(E, "Pa"), I=Q_(I, "m^4"))
    assert got.to("N/m").magnitude == pytest.approx(F / deflection, rel=1e-15)


def test_torsion_bar_round_bar():
    """G J_t / l with the polar moment pi d^4/32 of a 20 mm steel bar, 1 m long."""
    G, d, l = 80e9, 0.02, 1.0
    expected = G * math.pi * d**4 / 32 / l
    got = k_eq("series", f"torsion-bar(l=1m, G=80GPa, J_t={math.pi * d**4 / 32!r} m^4)")
    assert got == pytest.approx(expected, rel=1e-15)
    result = network_stiffness("series", ["torsion-bar(l=1m, GJ_t=1e4 N*m^2)"])
    assert result.results["k_eq"].unit == "N*m/rad"


def test_coil_spring_by_energy():
    """A coil spring is a torsion bar of length pi D n twisted by F D/2: k = G d^4/(8 D^3 n)."""
    G, d, D, n = 79.3e9, 3e-3, 24e-3, 8.5
    J = math.pi * d**4 / 32
    torsion_k = G * J / (math.pi * D * n)          # torque per radian of the wire
    expected = torsion_k / (D / 2) ** 2           # force per unit deflection at radius D/2
    got = k_eq("parallel", "coil(G=79.3GPa, d=3mm, D=24mm, n=8.5)")
    assert got == pytest.approx(expected, rel=1e-14)


def test_axial_with_area():
    got = k_eq("parallel", "axial(l=2m, E=200GPa, A=1cm^2)")
    assert got == pytest.approx(200e9 * 1e-4 / 2, rel=1e-15)


def test_element_stiffness_reported_as_results():
    result = network_stiffness("series", ["cantilever(l=2m)", "5kN/m", "cantilever(l=1m)",
                                          "EI=2e4 N*m^2"])
    assert list(result.results) == ["k_eq", "k1", "k3"]
    assert result.results["k1"].si == pytest.approx(3 * EI / 8, rel=1e-15)
    assert result.results["k3"].si == pytest.approx(3 * EI, rel=1e-15)
    assert set(result.inputs) == {"k1.l", "k1.EI", "k2", "k3.l", "k3.EI"}


# --- units -----------------------------------------------------------------------------------

def test_unit_invariance_lbf_in_and_n_mm():
    """The same three springs typed in lbf/in and in N/mm give the same SI answer."""
    lbf_in = [12.0, 30.0, 7.5]
    n_mm = [x * LBF / INCH / 1000 for x in lbf_in]
    a = k_eq("series", *(f"{x!r} lbf/in" for x in lbf_in))
    b = k_eq("series", *(f"{x!r} N/mm" for x in n_mm))
    c = 1 / sum(1 / (x * LBF / INCH) for x in lbf_in)
    assert a == pytest.approx(c, rel=2e-16 * 4)
    assert b == pytest.approx(c, rel=2e-16 * 4)
    p = k_eq("parallel", *(f"{x!r} lbf/in" for x in lbf_in))
    q = k_eq("parallel", *(f"{x!r} N/mm" for x in n_mm))
    assert p == pytest.approx(q, rel=1e-15)


def test_result_in_the_unit_typed_and_exact():
    result = network_stiffness("series", ["200 lbf/in", "300 lbf/in"])
    entry = result.results["k_eq"]
    assert entry.unit == "lbf/in"
    assert entry.value_in() == 120.0
    assert entry.si == pytest.approx(120 * LBF / INCH, rel=1e-15)


def test_mixed_units_give_si():
    entry = network_stiffness("parallel", ["200 N/m", "0.3 N/mm"]).results["k_eq"]
    assert (entry.unit, entry.value_in()) == ("N/m", 500.0)


# --- rigid links and extremes ----------------------------------------------------------------

def test_rigid_link_in_series_adds_nothing():
    assert k_eq("series", "300 N/m", "inf", "inf N/m") == 300.0


def test_rigid_link_in_parallel_is_rigid():
    result = network_stiffness("parallel", ["300 N/m", "inf"])
    assert math.isinf(result.results["k_eq"].si)
    assert result.warnings == ["k_eq is infinite: the network is rigid (a rigid element "
                               "carries the load alone); JSON gives its value as null"]


def test_all_rigid_series_is_rigid():
    assert math.isinf(k_eq("series", "inf", "inf"))


def test_subnormal_beside_one():
    """1e-320 N/m in series with 1 N/m: the naive 1/(1/k1 + 1/k2) gives 0 (1/1e-320 = inf)."""
    assert k_eq("series", "1e-320 N/m", "1 N/m") == 1e-320
    assert k_eq("parallel", "1e-320 N/m", "1 N/m") == 1.0


def test_huge_in_series_no_overflow():
    """1e300 and 1e300 in series: the naive form is fine, but 1e308 x 2 is not."""
    assert k_eq("series", "1e308 N/m", "1e308 N/m") == 5e307
    assert k_eq("series", "1e300 N/m", "1e-300 N/m") == 1e-300


def test_parallel_overflow_refused():
    with pytest.raises(InputError) as err:
        network_stiffness("parallel", ["1e308N/m", "1e308N/m"])
    assert str(err.value) == "k_eq overflows float64 (the largest is 1.8e308 N/m)"


def test_element_function_extreme_inputs_do_not_overflow_midway():
    """3 E I / l^3 with E I = 1e400 (E I overflows) and l^3 = 1e300: the answer is 3e100."""
    got = k_eq("parallel", "cantilever(l=1e100 m, E=1e200 Pa, I=1e200 m^4)")
    assert got == pytest.approx(3e100, rel=1e-15)


def test_underflow_to_zero_warns():
    result = network_stiffness("parallel", ["cantilever(l=1e200 m, EI=1e-200 N*m^2)"])
    assert result.results["k_eq"].si == 0.0
    assert result.warnings == [
        "k_eq underflows to zero (below 4.9e-324 N/m) although no input is zero",
        "k1 underflows to zero (below 4.9e-324 N/m) although no input is zero"]


# --- properties ------------------------------------------------------------------------------

positive = st.floats(min_value=1e-300, max_value=1e300, allow_nan=False, allow_infinity=False)
elements = st.lists(positive, min_size=1, max_size=8)


@settings(max_examples=300, deadline=None)
@given(elements)
def test_series_at_most_smallest_and_parallel_at_least_largest(ks):
    s = series_sum(ks)
    assert 0 < s <= min(ks)
    p = parallel_sum(ks)
    assert p >= max(ks)


@settings(max_examples=300, deadline=None)
@given(elements, st.randoms(use_true_random=False))
def test_order_does_not_matter(ks, rnd):
    shuffled = list(ks)
    rnd.shuffle(shuffled)
    assert series_sum(shuffled) == series_sum(ks)
    assert parallel_sum(shuffled) == parallel_sum(ks)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.floats(min_value=1e-100, max_value=1e100), min_size=1, max_size=8),
       st.floats(min_value=1e-100, max_value=1e100))
def test_scaling_every_element_scales_the_result(ks, c):
    assert series_sum([c * k for k in ks]) == pytest.approx(c * series_sum(ks), rel=1e-15)
    assert parallel_sum([c * k for k in ks]) == pytest.approx(c * parallel_sum(ks), rel=1e-15)


@settings(max_examples=100, deadline=None)
@given(st.lists(st.floats(min_value=1e-3, max_value=1e6), min_size=2, max_size=5))
def test_cli_words_equal_library(ks):
    words = [f"{k!r} N/m" for k in ks]
    assert k_eq("series", *words) == series_sum(ks)
    nested = k_eq("series", f"parallel({words[0]}, {words[1]})", *words[2:])
    assert nested == series_sum([parallel_sum(ks[:2])] + ks[2:])


# --- accuracy against mpmath (40 digits from the float64 inputs) -----------------------------

def _ulps(got, ref):
    return float(abs(mpmath.mpf(got) - ref) / mpmath.mpf(math.ulp(float(ref))))


def test_series_within_one_ulp_of_mpmath():
    import random

    rnd = random.Random(20261122)
    mpmath.mp.dps = 40
    worst = 0.0
    cases = [[1e-320, 1.0], [5e-324, 5e-324], [1e308, 1e308, 1e308], [1e-300, 1e300],
             [2.2250738585072014e-308, 3.0], [200.0, 300.0], [1.0, 3.0, 7.0]]
    for _ in range(3000):
        n = rnd.randint(1, 7)
        cases.append([10 ** rnd.uniform(-300, 300) for _ in range(n)])
    for ks in cases:
        ref = 1 / mpmath.fsum(1 / mpmath.mpf(k) for k in ks)
        worst = max(worst, _ulps(series_sum(ks), ref))
    assert worst <= 1.0, f"worst series error {worst:.3f} ulp"


def test_parallel_is_correctly_rounded():
    import random

    rnd = random.Random(7)
    mpmath.mp.dps = 40
    for _ in range(2000):
        ks = [10 ** rnd.uniform(-300, 300) for _ in range(rnd.randint(1, 7))]
        ref = mpmath.fsum(mpmath.mpf(k) for k in ks)
        assert _ulps(parallel_sum(ks), ref) <= 0.5


def test_monomial_within_four_ulp_of_mpmath():
    import random

    rnd = random.Random(3)
    mpmath.mp.dps = 40
    worst = 0.0
    for _ in range(2000):
        factors = [(10 ** rnd.uniform(-60, 60), rnd.choice([-4, -3, -1, 1, 3, 4]))
                   for _ in range(rnd.randint(1, 4))]
        c = rnd.choice([3.0, 48.0, 0.125, 1.0])
        ref = mpmath.mpf(c)
        for x, p in factors:
            ref *= mpmath.mpf(x) ** p
        if not (mpmath.mpf("2.3e-308") < ref < mpmath.mpf("1.7e308")):
            continue
        worst = max(worst, _ulps(monomial(c, factors), ref))
    assert worst <= 4.0, f"worst monomial error {worst:.3f} ulp"


# --- refusals --------------------------------------------------------------------------------

@pytest.mark.parametrize("how, words, message", [
    ("series", [], "spring-series needs at least one stiffness, e.g. dyncalc spring-series "
                   "200N/m 300N/m"),
    ("series", ["0 N/m", "1 N/m"], "element k1 (0 N/m) must be positive; got 0 newton / meter"),
    ("parallel", ["-5 N/m"], "element k1 (-5 N/m) must be positive; got -5 newton / meter"),
    ("series", ["nan N/m"], "element k1 (nan N/m): cannot read 'nan N/m': NaN is not a number "
                            "dyncalc accepts"),
    ("series", ["5 kg", "1 N/m"], "element k1 (5 kg) must be a stiffness [force]/[length] or "
                                  "[force]*[length]/[angle]; got 5 kilogram ([mass])"),
    ("series", ["3 N*m/rad", "1 N/m"], "linear [force]/[length] and torsional "
                                       "[force]*[length]/[angle] stiffnesses cannot be "
                                       "combined in one network"),
    ("series", ["spring(k=1N/m)"], "unknown element 'spring'; the elements are series, "
                                   "parallel, cantilever, simply-supported, beam, axial, "
                                   "torsion-bar, coil"),
    ("series", ["cantilever(EI=1N*m^2)"], "cantilever() (k1) needs l: give it inside the "
                                          "parentheses or as l=... after the elements; usage: "
                                          "cantilever(l=..., EI=... | E=..., I=...)"),
    ("series", ["cantilever(l=1m)"], "cantilever() (k1) needs EI or E and I; usage: "
                                     "cantilever(l=..., EI=... | E=..., I=...)"),
    ("series", ["cantilever(l=1m, EI=1N*m^2, E=1Pa)"], "cantilever() (k1): give EI or E+I, "
                                                       "not both"),
    ("series", ["cantilever(l=1m, E=1Pa)"], "cantilever() (k1) needs I with E"),
    ("series", ["cantilever(l=1m, x=2)"], "cantilever() has no parameter 'x'; usage: "
                                          "cantilever(l=..., EI=... | E=..., I=...)"),
    ("series", ["cantilever(l=1m, l=2m, EI=1N*m^2)"], "cantilever(): l is given twice"),
    ("series", ["cantilever(l=1m, 5)"], "cantilever(...): write parameters as NAME=QUANTITY; "
                                        "got '5'; usage: cantilever(l=..., EI=... | E=..., "
                                        "I=...)"),
    ("series", ["1 N/m", "E=200GPa"], "E=200GPa is not used by any element; shared values "
                                      "are for the parameters of cantilever(), "
                                      "simply-supported(), beam(), axial(), torsion-bar() "
                                      "and coil()"),
    ("series", ["cantilever(l=1m)", "EI=1N*m^2", "EI=2N*m^2"], "EI is given twice"),
    ("series", ["series()"], "series() needs at least one element"),
    ("series", ["parallel(1N/m,,2N/m)"], "parallel(...): an element is empty (two commas in "
                                         "a row?)"),
    ("series", ["parallel(1N/m, 2N/m"], "parallel(...): a '(' is not closed"),
    ("series", ["parallel(1N/m), 2N/m)"], "parallel(...): a ')' has no matching '('"),
    ("series", ["cantilever(l=-1m, EI=1N*m^2)"], "l of k1 must be positive; got -1 meter"),
    ("series", ["coil(G=80GPa, d=2mm, D=20mm, n=0)"], "n of k1 must be positive; got 0"),
    ("series", ["cantilever(l=1m, EI=5 kg)"], "EI of k1 must be a bending stiffness "
                                              "[force]*[length]^2; got 5 kilogram ([mass])"),
])
def test_refusals(how, words, message):
    with pytest.raises(InputError) as err:
        network_stiffness(how, words)
    assert str(err.value) == message


def test_deep_nesting_refused():
    text = "series(" * 20 + "1N/m" + ")" * 20
    with pytest.raises(InputError) as err:
        network_stiffness("series", [text])
    assert str(err.value) == "the network is nested more than 16 levels deep"


def test_strict_units_refuses_bare_number():
    with pytest.raises(InputError) as err:
        network_stiffness("series", ["200", "300 N/m"], strict=True)
    assert str(err.value) == ("element k1 (200): '200' has no unit and --strict-units is on; "
                              "write it with a unit, e.g. 200 N/m")


@pytest.mark.parametrize("how, words", [
    ("series", ["parallel(cantilever(l=2m), cantilever(l=1m))", "5kN/m", "EI=2e4 N*m^2"]),
    ("parallel", ["cantilever(l=2m)", "5 kN/m", "EI=2e4 N*m^2"]),
    ("series", ["2 kN/m", "3 kN/m"]),
    ("series", ["2 kN/m", "3000 N/m"]),
    ("parallel", ["12 lbf/in", "parallel(3 lbf/in, 4 lbf/in)"]),
    ("series", ["3 kN*m/rad", "torsion-bar(l=0.5m, G=80GPa, J_t=1e-8m^4)"]),
])
def test_shown_value_agrees_with_si_value(how, words):
    """Whatever unit k_eq is shown in, the number shown is the SI value converted to it."""
    from dyncalc.units import convert

    for entry in network_stiffness(how, words).results.values():
        assert entry.value_in() == pytest.approx(convert(entry.si, entry.dim, entry.unit),
                                                 rel=1e-15), entry.name


def test_element_functions_show_k_eq_in_si():
    entry = network_stiffness("series", ["parallel(cantilever(l=2m), cantilever(l=1m))",
                                         "5kN/m", "EI=2e4 N*m^2"]).results["k_eq"]
    assert (entry.unit, entry.value_in()) == ("N/m", pytest.approx(4655.172413793103,
                                                                   rel=1e-15))


def test_series_with_an_element_that_underflowed_to_zero_warns():
    """3 EI/l^3 with l = 1e300 m underflows to 0: the series is 0, with the underflow warning
    (it used to divide by zero; found by the fuzz suite, issue 9)."""
    result = network_stiffness("series", ["cantilever(l=1e300 m, EI=1 N*m^2)", "1 N/m"])
    assert result.results["k_eq"].si == 0.0
    assert ("k_eq underflows to zero (below 4.9e-324 N/m) although no input is zero"
            in result.warnings)
