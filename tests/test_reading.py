"""Issue 15, reading what people type (SPEC.md v2, "Quantities on the command line" and
"Uncertainty"): a number and its unit bind tighter than ``/``; ``[angle]`` is a dimension for
checking; a percent is never an angle; nothing may follow an uncertainty but its own unit;
``--check`` refuses an uncertainty; ``1/min`` is not an angular rate; a misspelt unit gets
"did you mean"; the human output shows how each input was read. Every expected number is
worked out here from its definition (1 deg = pi/180 rad), not copied from the program."""
import math

import pytest

from dyncalc.errors import InputError
from dyncalc.units import (ACCELERATION, ANGLE, ANGULAR_RATE, DIMENSIONLESS, LENGTH, MASS,
                           STIFFNESS, TORSIONAL_STIFFNESS, parse_quantity)

from helpers import error_line, invoke, json_of

DEG = math.pi / 180.0


def value(*args):
    result = invoke(*args)
    assert result.exit_code == 0, result.stderr
    return float(result.stdout)


def inputs_line(*args):
    result = invoke(*args)
    assert result.exit_code == 0, result.stderr
    return result.stdout.splitlines()[-1]


# -- a number and its unit bind tighter than '/' ---------------------------------------------

def test_torque_per_degree_is_a_torsional_stiffness():
    """100 N*m / 2 deg = 50 N*m/deg = 50/(pi/180) N*m/rad; omega = sqrt(kt/J), J = 1 kg*m^2.
    Before: (100 N*m / 2) * deg, (180/pi)^2 too small, accepted silently."""
    kt = 50.0 / DEG
    omega = value("natural-frequency", "--kt", "100 N*m / 2 deg", "--inertia", "1 kg*m^2",
                  "--value", "omega")
    assert omega == pytest.approx(math.sqrt(kt), rel=1e-14)
    assert kt == pytest.approx(2864.79, rel=1e-6)


def test_force_over_deflection_is_a_stiffness_and_weight_over_g_a_mass():
    """k = W/delta = 1500 N / 7 mm, m = W/g = 450 N / 9.81 m/s^2 (before: both refused)."""
    k, m = 1500.0 / 0.007, 450.0 / 9.81
    omega = value("natural-frequency", "--k", "1500 N / 7 mm", "--m", "450 N / 9.81 m/s^2",
                  "--value", "omega")
    assert omega == pytest.approx(math.sqrt(k / m), rel=1e-14)
    assert parse_quantity("450 N / 9.81 m/s^2", MASS).si == pytest.approx(45.87155963, 1e-9)


def test_spring_series_of_force_over_two_metres_is_linear():
    """"100 N/2 m" is 50 N/m (before: a torsional spring of 50 N*m/rad)."""
    data = json_of("spring-series", "100 N/2 m", "100 N/m")
    assert data["results"]["k_eq"]["unit"] == "N/m"
    assert data["results"]["k_eq"]["value"] == pytest.approx(1 / (1 / 50 + 1 / 100), 1e-15)


def test_explicit_star_and_slash_keep_left_to_right():
    assert parse_quantity("6 N / 2 / 3 * 1 m^-1", STIFFNESS).si == pytest.approx(1.0, 1e-15)
    assert parse_quantity("1 m/s s", ACCELERATION).si == 1.0  # m/(s s), as GNU units


def test_a_fraction_before_a_unit_is_refused_with_its_reading():
    """2/12 kg*m^2 is 2/(12 kg*m^2) by the precedence rule: refused (wrong dimension) and
    the message shows the reading and the rule."""
    line = error_line(invoke("natural-frequency", "--scene", "physical-pendulum", "m=2kg",
                             "a=0.5m", "J=2/12 kg*m^2"))
    assert line == ("Error: J must be a mass moment of inertia [mass]*[length]^2; got "
                    "0.166666666666667 1 / kilogram / meter ** 2 (1 / [mass] / [length] ** 2) "
                    "(the text was read as '2/(12 kg*m^2)': a number and its unit bind tighter "
                    "than /)")


# -- angles are a dimension ------------------------------------------------------------------

def test_torque_times_degree_is_not_a_stiffness():
    line = error_line(invoke("spring-series", "50 N*m*deg", "100 N/m"))
    assert line == ("Error: element k1 (50 N*m*deg) must be a stiffness [force]/[length] or "
                    "[force]*[length]/[angle]; got 50 degree * meter * newton ([mass] * "
                    "[length] ** 2 * [angle] / [time] ** 2)")
    line = error_line(invoke("natural-frequency", "--kt", "50 N*m*deg", "--inertia",
                             "1 kg*m^2"))
    assert line == ("Error: --kt must be a torsional stiffness [force]*[length]/[angle]; got "
                    "50 degree * meter * newton ([mass] * [length] ** 2 * [angle] / [time] ** "
                    "2)")


def test_bare_torque_is_per_radian_and_per_degree_converts():
    assert parse_quantity("3 N*m", TORSIONAL_STIFFNESS).si == 3.0
    assert parse_quantity("3 N*m/deg", TORSIONAL_STIFFNESS).si == pytest.approx(3 / DEG, 1e-15)


def test_an_angle_squared_or_a_sum_with_a_pure_number_is_not_an_angle():
    args = ("rolling-onset", "--v0", "1m/s", "--mu", "0.2", "--incline")
    assert error_line(invoke(*args, "1 deg*deg")) == (
        "Error: --incline must be an angle [angle]; got 1 degree ** 2 ([angle] ** 2)")
    assert error_line(invoke(*args, "1 rad + 1")) == (
        "Error: --incline: cannot read '1 rad + 1': cannot add a pure number and radian: an "
        "angle and a quantity without one do not add")
    assert parse_quantity("0.5", ANGLE).si == 0.5  # a bare number is radians, as before
    assert parse_quantity("10 deg + 30 arcmin", ANGLE).si == pytest.approx(10.5 * DEG, 1e-15)


def test_unit_option_refuses_an_angle_in_the_wrong_place():
    assert error_line(invoke("spring-series", "3 N*m/rad", "3 N*m/rad", "--unit",
                             "k_eq=N*m*deg")) == (
        "Error: --unit k_eq: N*m*deg is not a unit of [force]*[length]/[angle]; k_eq is a "
        "torsional stiffness")
    assert value("spring-series", "3 N*m/rad", "3 N*m/rad", "--unit", "k_eq=N*m/deg",
                 "--value", "k_eq") == pytest.approx(1.5 * DEG, rel=1e-15)


# -- a percent is never an angle -------------------------------------------------------------

@pytest.mark.parametrize("text, grade", [("100%", 1.0), ("5 %", 0.05)])
def test_percent_incline_is_refused_with_the_angle_of_that_grade(text, grade):
    """SPEC: refused with the advice to give the angle (a grade of 100 % is 45 deg); before,
    100 % was read as 1 rad = 57.3 deg."""
    degrees = math.degrees(math.atan(grade))
    line = error_line(invoke("rolling-onset", "--v0", "1m/s", "--mu", "0.2", "--incline", text))
    shown = f"{grade * 100:g} percent"
    assert line == (f"Error: --incline must be an angle; got {shown}, a ratio, not an angle: a "
                    f"grade of {shown} is {degrees:.6g} deg, so give the angle "
                    f"({degrees:.6g}deg)")
    assert f"{degrees:.6g}" == ("45" if grade == 1 else "2.86241")


def test_percent_stays_a_pure_number():
    assert parse_quantity("5 %", DIMENSIONLESS).si == pytest.approx(0.05, 1e-15)


# -- uncertainties ---------------------------------------------------------------------------

def test_text_after_the_uncertainty_is_refused():
    """Before: 1 m ± 5.01 m."""
    line = error_line(invoke("natural-frequency", "--length", "1 m ± 1 cm + 5 m"))
    assert line == ("Error: --length: cannot read '1 m ± 1 cm + 5 m': only the uncertainty and "
                    "its own unit may follow +/- or ±, not '+ 5 m'; write one value and its "
                    "uncertainty: 2.0 ± 0.1 kg or (100 ± 5) N/m")


@pytest.mark.parametrize("text", ["1±1%m", "1 ± 1 % m", "2 ± 5%kg"])
def test_a_percent_with_a_unit_after_the_uncertainty_is_refused(text):
    """Before: '1±1%m' was 1 ± 1 of a unit '%m', i.e. (0.01 ± 0.01) m, with exit 0."""
    result = invoke("natural-frequency", "--length", text)
    assert result.exit_code == 2
    tail = text.split("±")[1].strip()
    assert error_line(result) == (f"Error: --length: cannot read {text!r}: a percent goes alone "
                                  f"after +/- or ±, not {tail!r}: write 1 m ± 1% (a relative "
                                  "uncertainty) or (1 ± 0.01) m")


def test_the_uncertainty_with_its_own_unit_still_reads():
    parsed = parse_quantity("1 m ± 1 cm", LENGTH)
    assert (parsed.si, parsed.uncertainty) == (1.0, 0.01)
    parsed = parse_quantity("100 N/m ± 5%", STIFFNESS)
    assert parsed.uncertainty == pytest.approx(5.0, 1e-15)


def test_check_refuses_an_uncertainty():
    """SPEC: an uncertainty in --check is refused (use --rtol); before, it was dropped."""
    line = error_line(invoke("natural-frequency", "--k", "100N/m", "--m", "2kg", "--check",
                             "f=1.5 ± 1 Hz"))
    assert line == ("Error: --check f: a check takes no uncertainty (+/- or ±); give the answer "
                    "alone and the tolerance with --rtol")


# -- rates -----------------------------------------------------------------------------------

def test_per_minute_is_not_an_angular_rate():
    """SPEC: 1/min for an angular rate is refused with the advice (before: 1 rad/s)."""
    line = error_line(invoke("natural-frequency", "--scene", "bead-on-rotating-ring", "r=0.2m",
                             "Omega=60 1/min"))
    assert line == ("Error: Omega is an angular rate; got 60 1/min, a plain rate with no angle "
                    "(only 1/s is read as rad/s): for revolutions per minute write rpm or "
                    "rev/min, or give rad/s")
    assert parse_quantity("60 rpm", ANGULAR_RATE).si == pytest.approx(2 * math.pi, 1e-15)
    assert parse_quantity("3 1/s", ANGULAR_RATE).si == 3.0


def test_plain_per_second_is_shown_as_radians_per_second():
    line = inputs_line("natural-frequency", "--scene", "bead-on-rotating-ring", "r=0.2m",
                       "Omega=3 1/s")
    assert "Omega = 3 1/s = 3 rad/s" in line


# -- did you mean ----------------------------------------------------------------------------

@pytest.mark.parametrize("text, shown, hint", [
    ("2kgg", "2kgg", "unknown unit 'kgg' (did you mean 'kg' or 'kg*g'?)"),
    ("2 Kg", "2 Kg", "unknown unit 'Kg' (did you mean 'kg' or 'kG'?)"),
    ("2 kilogramme", "2 kilogramme", "unknown unit 'kilogramme' (did you mean 'kilogram'?)"),
])
def test_misspelt_mass_unit(text, shown, hint):
    line = error_line(invoke("natural-frequency", "--k", "100N/m", "--m", text))
    assert line == f"Error: --m: cannot read '{shown}': {hint}"


@pytest.mark.parametrize("text, hint", [
    ("3 kN/m2", "unknown unit 'm2' (did you mean 'm^2'?)"),
    ("3 N/mmm", "unknown unit 'mmm' (did you mean 'mm' or 'mm*m'?)"),
    ("3 kN/metr", "unknown unit 'metr' (did you mean 'metre' or 'meter'?)"),
])
def test_misspelt_stiffness_unit(text, hint):
    line = error_line(invoke("spring-series", "2kN/m", text))
    assert line == f"Error: element k2 ({text}): cannot read '{text}': {hint}"


# -- how each input was read -----------------------------------------------------------------

def test_inputs_line_shows_the_reading_and_the_si_value():
    """SPEC: k = 1500 N / (7 mm) = 214286 N/m; a unit other than the canonical one is shown
    with the canonical value too; the canonical unit alone as before."""
    line = inputs_line("natural-frequency", "--k", "1500 N / 7 mm", "--m", "450 N / 9.81 m/s^2")
    k, m = f"{1500 / 0.007:.6g}", f"{450 / 9.81:.6g}"
    assert line == (f"inputs: k = 1500 N / (7 mm) = {k} N/m, m = 450 N / (9.81 m/s^2) = {m} kg")
    line = inputs_line("spring-series", "2 kN/m", "12 lbf/in", "300 N/m")
    lbf_in = 12 * 4.4482216152605 / 0.0254
    assert line == f"inputs: k1 = 2 kN/m = 2000 N/m, k2 = 12 lbf/in = {lbf_in:.6g} N/m, k3 = 300 N/m"
    line = inputs_line("natural-frequency", "--k", "2 ± 0.1 kN/m", "--m", "(4 ± 0.1) kg")
    assert line == "inputs: k = 2 ± 0.1 kN/m = 2000 ± 100 N/m, m = 4 ± 0.1 kg"


def test_value_is_in_the_canonical_unit_whatever_was_typed():
    """SPEC v2: --value prints in the canonical unit (already so before issue 15)."""
    kn = value("spring-series", "2kN/m", "3kN/m", "--value", "k_eq")
    n = value("spring-series", "2kN/m", "3000N/m", "--value", "k_eq")
    assert kn == n == pytest.approx(1 / (1 / 2000 + 1 / 3000), rel=1e-15)


# -- found by tests/test_reading_properties.py -----------------------------------------------

def test_a_length_plus_a_length_times_turns_is_refused():
    """pint counts a turn as 2 pi: "1 m + 1 m*turn" was read as (1 + 2 pi) m = 7.28 m (a sum
    whose terms differ in revolutions skipped the angle check)."""
    with pytest.raises(InputError) as err:
        parse_quantity("1 m + 1 m*turn", LENGTH, label="--length")
    assert str(err.value) == ("--length: cannot read '1 m + 1 m*turn': cannot add meter * turn "
                              "and meter: an angle and a quantity without one do not add")


def test_a_parenthesised_number_keeps_its_unit_after_a_slash():
    """"(1 m)/(2) m*m" divides by (2) m*m = 2 m^2 (a parenthesised pure number is a number
    with its unit), as "(1 m)/2 m*m" does."""
    area = parse_quantity("(1 m^3)/(2) m*m", LENGTH).si
    assert area == parse_quantity("(1 m^3)/2 m*m", LENGTH).si == 0.5


def test_did_you_mean_does_not_depend_on_what_was_read_before():
    """pint adds each prefixed unit it meets to its table; the suggestions must not follow
    (before: '3 N/mmm' was offered 'mm' only after some earlier text had used mm)."""
    from dyncalc.units import grammar, parse_unit

    grammar._VOCABULARY.clear()
    before = list(grammar._vocabulary())
    for text in ("Gm", "ks", "nN", "hPa", "Mm/ks"):
        parse_unit(text)
    grammar._VOCABULARY.clear()
    assert grammar._vocabulary() == before
    assert "mm" in before and "Gm" not in before
