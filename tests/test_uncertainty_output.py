"""How uncertainties are shown: batch columns u(NAME), JSON lines, --value 'u(NAME)', the table."""
import csv
import io
import json
import math

from click.testing import CliRunner

from dyncalc.cli import cli


def _run(args, text):
    return CliRunner().invoke(cli, args, input=text)


def _rows(output):
    return list(csv.reader(io.StringIO(output)))


def test_csv_gets_uncertainty_columns_that_match_the_hand_propagation():
    text = "k [N/m],m [kg]\n100+/-5,2\n(200 ± 10) N/m,4+/-0.2\n300,6\n"
    result = _run(["natural-frequency", "--batch", "-"], text)
    assert result.exit_code == 0, result.output
    rows = _rows(result.output)
    assert rows[0] == ["k [N/m]", "m [kg]", "omega [rad/s]", "u(omega) [rad/s]", "f [Hz]",
                       "u(f) [Hz]", "T [s]", "u(T) [s]"]
    omega = math.sqrt(100 / 2)
    # u(omega)/omega = 1/2 sqrt((u_k/k)^2 + (u_m/m)^2)
    assert math.isclose(float(rows[1][3]), omega / 2 * 0.05, rel_tol=1e-8)
    assert math.isclose(float(rows[2][3]), omega / 2 * math.hypot(0.05, 0.05), rel_tol=1e-8)
    assert math.isclose(float(rows[2][5]), float(rows[2][3]) / (2 * math.pi), rel_tol=1e-8)
    # T = 2 pi / omega: u(T)/T = u(omega)/omega
    assert math.isclose(float(rows[2][7]) / float(rows[2][6]),
                        float(rows[2][3]) / float(rows[2][2]), rel_tol=1e-8)
    # a row without uncertainty (the vectorised path) leaves its u() cells empty
    assert rows[3][3] == rows[3][5] == rows[3][7] == ""
    assert float(rows[3][2]) == omega


def test_batch_uncertainty_equals_the_one_off():
    text = "k1,k2\n200+/-10 N/m,300 N/m\n"
    batch = _rows(_run(["spring-series", "--batch", "-"], text).output)
    one = json.loads(_run(["spring-series", "200+/-10 N/m", "300 N/m", "--json"], "").output)
    assert batch[0][-2:] == ["k_eq [N/m]", "u(k_eq) [N/m]"]
    assert float(batch[1][-2]) == one["results"]["k_eq"]["value"]
    assert float(batch[1][-1]) == one["results"]["k_eq"]["uncertainty"]
    # d k_eq / d k1 = (k_eq / k1)^2 = 0.36: u = 3.6 N/m
    assert math.isclose(one["results"]["k_eq"]["uncertainty"], 3.6, rel_tol=1e-8)


def test_json_lines_carry_the_uncertainty():
    text = "k [N/m],m [kg]\n100+/-5,2\n"
    result = _run(["natural-frequency", "--batch", "-", "--json"], text)
    line = json.loads(result.output.splitlines()[0])
    assert line["line"] == 2
    assert line["inputs"]["k"] == {"value": 100.0, "uncertainty": 5.0, "unit": "N/m",
                                   "text": "(100+/-5) N/m"}
    assert math.isclose(line["results"]["omega"]["uncertainty"],
                        math.sqrt(50) / 2 * 0.05, rel_tol=1e-8)


def test_a_bad_uncertainty_in_a_cell_names_its_line():
    text = "k [N/m],m [kg]\n100+/-5,2\n100+/--5,2\n"
    result = _run(["natural-frequency", "--batch", "-"], text)
    assert result.exit_code == 2
    assert result.output.splitlines()[-1] == (
        "Error: line 3: k (its uncertainty) must not be negative; got -5 newton / meter")


def test_value_of_the_uncertainty_alone():
    args = ["natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2kg"]
    result = _run([*args, "--value", "u(omega)"], "")
    assert result.exit_code == 0
    assert math.isclose(float(result.output), math.sqrt(50) / 2 * 0.05, rel_tol=1e-8)
    in_rpm = _run([*args, "--value", "u(f)", "--unit", "f=rpm"], "")
    assert math.isclose(float(in_rpm.output), float(result.output) / (2 * math.pi) * 60,
                        rel_tol=1e-8)  # f is differenced on its own


def test_value_of_an_uncertainty_that_is_not_there():
    result = _run(["natural-frequency", "--k", "100 N/m", "--m", "2kg", "--value", "u(f)"], "")
    assert result.exit_code == 2
    assert result.output == ("Error: --value u(f): f has no uncertainty (give one on an input: "
                             "2.0+/-0.1 kg)\n")


def test_table_shows_value_plus_minus_two_figures():
    result = _run(["natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2.0+/-0.1 kg"], "")
    lines = result.output.splitlines()
    assert lines[2].split() == ["omega", "ω", "7.07107", "±", "0.25", "rad/s"]
    assert lines[-1] == "inputs: k = 100 ± 5 N/m, m = 2 ± 0.1 kg"


def test_a_value_that_underflows_in_si_still_takes_its_nudges():
    """4.9e-324 km/h is 0 in m/s: the nudge is scaled by the unit (0.2778 m/s per km/h), not by
    si / magnitude (0 / 4.9e-324), which divided by zero (found by the long fuzz run)."""
    result = _run(["rolling-onset", "--v0", "4.9e-324+/-1e300 km/h", "--mu", "5%", "--body",
                   "hollow-sphere"], "")
    assert result.exit_code == 0, result.output
    assert "warning: the uncertainty of t_roll overflows float64" in result.output
    assert "internal error" not in result.output


def test_an_uncertainty_in_percent_of_a_dimensional_value_is_relative():
    """100 N/m ± 5% is 100 ± 5 N/m; 2 kg +/- 5 % is 2 ± 0.1 kg (and 100 ± 5% bare is SI)."""
    relative = json.loads(_run(["natural-frequency", "--k", "100 N/m ± 5%", "--m",
                                "2 kg +/- 5 %", "--json"], "").output)
    absolute = json.loads(_run(["natural-frequency", "--k", "(100 ± 5) N/m", "--m",
                                "2 ± 0.1 kg", "--json"], "").output)
    assert relative["inputs"]["k"]["uncertainty"] == 5.0
    assert relative["inputs"]["m"]["uncertainty"] == 0.1
    assert relative["results"] == absolute["results"]


def test_a_percent_on_one_side_of_a_pure_number_is_refused_as_ambiguous():
    result = _run(["natural-frequency", "--k", "100N/m", "--m", "2kg", "--zeta",
                   "0.05 ± 10%"], "")
    assert result.exit_code == 2
    assert result.output == ("Error: --zeta: cannot read '0.05 ± 10%': a pure number with a "
                             "unit (%) on one side only is ambiguous; write both sides alike: "
                             "5% ± 1% or 0.05 ± 0.01\n")
    both = json.loads(_run(["natural-frequency", "--k", "100N/m", "--m", "2kg", "--zeta",
                            "5% ± 1%", "--json"], "").output)
    assert both["inputs"]["zeta"] == {"value": 5.0, "uncertainty": 1.0, "unit": "%",
                                      "text": "5% ± 1%"}
