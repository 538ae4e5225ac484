"""``dyncalc inertia``: the command line (bodies, holes written ``-disk(...)``, ``--axis``),
the refusals with their exact messages and exit status, ``--value`` and JSON forms, unit
invariance, uncertainty, ``--explain``, ``--check`` and the Python API. Numbers are checked
against hand derivations (textbook table, parallel-axis theorem by hand)."""
import json
import math
import shlex

import numpy as np
import pytest
from click.testing import CliRunner

import dyncalc
from dyncalc.cli import cli
from dyncalc.cli.inertia import bodies_last
from helpers import error_line


def run(*args):
    return CliRunner().invoke(cli, ["inertia", *args])


def values(*args):
    result = run(*args, "--json")
    assert result.exit_code == 0, result.stderr
    data = json.loads(result.stdout)
    assert data["schema"] == "dyncalc/2" and data["command"] == "inertia"
    return {name: np.asarray(item["value"]) if isinstance(item["value"], list)
            else item["value"] for name, item in data["results"].items()}


def test_rod_about_its_end():
    out = values("rod(m=2kg, l=1m, along=x, at=(0.5, 0, 0) m)", "--axis", "z")
    assert out["m"] == 2.0
    assert out["r_c"].tolist() == [0.5, 0.0, 0.0]
    assert out["J_axis"] == pytest.approx(2.0 / 3.0, rel=1e-15)          # m l^2 / 3
    assert out["radius_of_gyration"] == pytest.approx(1 / math.sqrt(3), rel=1e-15)
    assert out["J_C"] == pytest.approx(np.diag([0.0, 1 / 6, 1 / 6]), abs=1e-16)
    assert [out["J_1"], out["J_2"], out["J_3"]] == pytest.approx([0.0, 1 / 6, 1 / 6])
    assert out["axis_1"].tolist() == [1.0, 0.0, 0.0]


def test_hole_written_with_a_minus_and_options_anywhere():
    """A disk R = 0.2 m (4 kg) with a hole r = 5 cm (0.25 kg, the same areal density) 0.1 m
    off the centre: J_z about the origin = M R^2/2 - (m r^2/2 + m d^2)."""
    expected = 4 * 0.04 / 2 - (0.25 * 0.0025 / 2 + 0.25 * 0.01)
    for args in (["-disk(m=0.25kg, r=5cm, at=(0.1, 0, 0) m)", "disk(m=4kg, r=0.2m)"],
                 ["disk(m=4kg, r=0.2m)", "--axis", "z", "-disk(m=0.25kg, r=5cm, at=(0.1, 0, "
                                                        "0) m)"],
                 ["--axis", "z", "--json", "--", "disk(m=4kg, r=0.2m)",
                  "-disk(m=0.25kg, r=5cm, at=(0.1, 0, 0) m)"]):
        result = run(*args) if "--" in args else run(*args, "--json")
        assert result.exit_code == 0, result.stderr
        out = {n: r["value"] for n, r in json.loads(result.stdout)["results"].items()}
        assert out["m"] == 3.75
        assert out["J_O"][2][2] == pytest.approx(expected, rel=1e-14)
        assert out["r_c"][0] == pytest.approx(-0.25 * 0.1 / 3.75, rel=1e-14)


def test_bodies_last_keeps_the_options_in_front():
    assert bodies_last(["-disk(r=1m)", "--axis", "z through (1, 0, 0) m", "rod(l=1m)",
                        "--json"]) == ["--axis", "z through (1, 0, 0) m", "--json", "--",
                                       "-disk(r=1m)", "rod(l=1m)"]
    assert bodies_last(["--value", "m"]) == ["--value", "m"]


def test_the_bent_bar_of_example_3_41():
    """m = 3 kg, l = 0.5 m: J_zeta = 20 m l^2/9, J_xi_zeta = -m l^2/3 (the book's sign)."""
    out = values("rod(m=2kg, l=1m, along=x, at=(0.5, 0, 0) m)",
                 "rod(m=1kg, l=50cm, at=(1, 0, 0.25) m)")
    assert out["J_O"][2][2] == pytest.approx(20 * 3 * 0.25 / 9, rel=1e-14)
    assert out["J_O"][0][2] == out["J_O"][2][0] == pytest.approx(-3 * 0.25 / 3, rel=1e-14)
    assert out["r_c"].tolist() == pytest.approx([4 * 0.5 / 3, 0, 0.5 / 6], rel=1e-14)


def test_density_kinds_and_their_dimensions():
    plate = values("plate(rho=7.8 kg/m^2, a=40cm, b=20cm)", "--axis", "x")
    m = 7.8 * 0.4 * 0.2
    assert plate["m"] == pytest.approx(m, rel=1e-15)
    assert plate["J_axis"] == pytest.approx(m * 0.2 ** 2 / 12, rel=1e-14)  # b along y
    rod = values("rod(rho=0.5 kg/m, l=2m)")
    assert rod["m"] == 1.0
    sphere = values("solid-sphere(rho=1000 kg/m^3, r=10cm)")
    assert sphere["m"] == pytest.approx(4 / 3 * math.pi * 1.0, rel=1e-14)


def test_plate_with_a_hole_about_an_edge():
    """By hand: plate M = rho a b about y through its edge x = a/2, M a^2/12 + M (a/2)^2;
    the hole m = rho pi r^2 at x = 0.1 m, m r^2/4 + m (0.2 - 0.1)^2, subtracted."""
    out = values("plate(rho=7.8 kg/m^2, a=40cm, b=20cm)",
                 "-disk(rho=7.8 kg/m^2, r=5cm, at=(0.1, 0, 0) m)",
                 "--axis", "y through (0.2, 0, 0) m")
    M, m = 7.8 * 0.4 * 0.2, 7.8 * math.pi * 0.05 ** 2
    assert out["m"] == pytest.approx(M - m, rel=1e-15)
    assert out["J_axis"] == pytest.approx(M * 0.16 / 12 + M * 0.04 - (m * 0.0025 / 4
                                                                       + m * 0.01), rel=1e-14)


def test_unit_invariance_kg_m_against_lb_in():
    si = values("solid-cylinder(m=2kg, r=0.1m, h=0.3m, along=(1, 1, 0), at=(0.2, 0, 0.1) m)",
                "-point(m=0.1kg, at=(0.2, 0, 0) m)", "--axis", "z through (0, 0.1, 0) m")
    lb, inch = 0.45359237, 0.0254
    imperial = values(f"solid-cylinder(m={2 / lb!r} lb, r={0.1 / inch!r} in, "
                      f"h={0.3 / inch!r} in, along=(1, 1, 0), at=({0.2 / inch!r}, 0, "
                      f"{0.1 / inch!r}) in)",
                      f"-point(m={0.1 / lb!r} lb, at=({0.2 / inch!r}, 0, 0) in)",
                      "--axis", f"z through (0, {0.1 / inch!r}, 0) in")
    for name in si:
        assert np.asarray(imperial[name], dtype=float) == pytest.approx(
            np.asarray(si[name], dtype=float), rel=1e-12, abs=1e-15), name


def test_value_prints_a_matrix_by_rows_and_unit_converts():
    result = run("disk(m=1kg, r=1m)", "--value", "J_C")
    assert result.exit_code == 0
    assert result.stdout == "0.25,0.0,0.0;0.0,0.25,0.0;0.0,0.0,0.5\n"
    result = run("disk(m=1kg, r=1m)", "--value", "J_3", "--unit", "J_3=g*cm^2")
    assert float(result.stdout) == pytest.approx(0.5e7, rel=1e-15)


def test_explain_names_each_body_and_the_parallel_axis_terms():
    result = run("rod(m=2kg, l=1m, along=x, at=(0.5, 0, 0) m)", "--axis", "z", "--explain")
    assert result.exit_code == 0
    text = result.stdout
    assert "b1 = rod: J_xx = J_yy = m l^2/12, J_zz = 0" in text
    assert "J_O,i = J_C,i + m_i (|c_i|^2 I - c_i c_i^T)" in text
    assert "m (|c|^2 I - c c^T) = [[0, 0, 0], [0, 0.5, 0], [0, 0, 0.5]] kg*m^2" in text
    assert "J_axis = 0.166667 kg*m^2 + 0.5 kg*m^2 = 0.666667 kg*m^2" in text
    assert "J_xy = -int x y dm" in text


def test_check_names_the_missing_parallel_axis_term():
    result = run("rod(m=2kg, l=1m, along=x, at=(0.5, 0, 0) m)", "--axis", "z",
                 "--check", "J_axis=0.1667 kg*m^2")
    assert result.exit_code == 1
    assert "parallel-axis term left out" in result.stdout + result.stderr


def test_uncertain_mass_propagates_linearly():
    out = json.loads(run("rod(m=2kg ± 1%, l=1m, along=x, at=(0.5, 0, 0) m)", "--axis", "z",
                         "--json").stdout)
    J = out["results"]["J_axis"]
    assert J["uncertainty"] == pytest.approx(0.01 * J["value"], rel=1e-6)
    assert out["results"]["radius_of_gyration"]["uncertainty"] == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("args, message", [
    ([], "inertia needs at least one body, e.g. dyncalc inertia \"rod(m=2kg, l=1m)\""),
    (["cube(m=1kg)"], "unknown body 'cube'; the bodies are rod, disk, ring, solid-sphere, "
                      "hollow-sphere, solid-cylinder, hollow-cylinder, plate, "
                      "half-cylinder-shell, point"),
    (["2kg"], "body 1 ('2kg') is not a body: write NAME(KEY=VALUE, ...), e.g. rod(m=2kg, l=1m);"
              " the bodies are rod, disk, ring, solid-sphere, hollow-sphere, solid-cylinder, "
              "hollow-cylinder, plate, half-cylinder-shell, point"),
    (["disk(m=1kg, r=1m"], "body 1 ('disk(m=1kg, r=1m'): a '(' is not closed"),
    (["disk(r=1m)"], "disk() (body 1) needs m= (its mass) or rho= (its areal density "
                     "[mass]/[length]^2)"),
    (["rod(l=1m)"], "rod() (body 1) needs m= (its mass) or rho= (its linear density "
                    "[mass]/[length])"),
    (["point()"], "point() (body 1) needs m=, its mass"),
    (["disk(m=1kg, rho=2kg/m^2, r=1m)"], "disk() (body 1): give m= or rho=, not both"),
    (["disk(m=1kg)"], "disk() (body 1) needs r=; usage: disk(m= | rho=, r=, at=, along=)"),
    (["disk(m=1kg, r=1m, h=1m)"], "disk() has no parameter 'h'; usage: disk(m= | rho=, r=, "
                                  "at=, along=)"),
    (["point(m=1kg, rho=1kg/m)"], "point() has no parameter 'rho'; usage: point(m=, at=, "
                                  "along=)"),
    (["disk(m=1kg, r=1m, r=2m)"], "disk() (body 1): r is given twice"),
    (["disk(m=1kg, r=-1m)"], "r of body 1 (disk) must be positive; got -1 meter"),
    (["rod(m=1kg, l=0m)"], "l of body 1 (rod) must be positive; got 0 meter"),
    (["disk(m=-1kg, r=1m)"], "m of body 1 (disk) must be positive; got -1 kilogram"),
    (["disk(rho=2kg/m^3, r=1m)"], "rho of body 1 (disk) must be an areal density "
                                  "[mass]/[length]^2; got 2 kilogram / meter ** 3 ([mass] / "
                                  "[length] ** 3)"),
    (["hollow-cylinder(m=1kg, ri=2m, ro=1m, h=1m)"],
     "body 1 (hollow-cylinder): the inner radius ri must be less than the outer radius ro; "
     "got ri = 2 m, ro = 1 m"),
    (["rod(m=1kg, l=1m, along=(0, 0, 0))"],
     "along of body 1 (rod) has zero length: a direction needs a non-zero vector"),
    (["disk(m=1kg, r=1m, at=1,0,0 m)"],
     "disk() (body 1): write parameters as KEY=VALUE (a vector in parentheses: at=(0.5, 0, 0) "
     "m); got '0'"),
    (["disk(m=1kg, r=1m)", "-disk(m=2kg, r=1m)"],
     "the negative bodies weigh as much as the others or more: the total mass is -1 kg; a "
     "hole cannot be larger than what it cuts"),
    (["disk(m=1kg, r=1m)", "-disk(m=1kg, r=1m)"],
     "the negative bodies weigh as much as the others or more: the total mass is 0 kg; a "
     "hole cannot be larger than what it cuts"),
    (["disk(m=1kg, r=1m)", "-ring(m=0.9kg, r=1m)"],
     "the negative bodies cut more than there is: the inertia tensor about the centre of "
     "mass is not positive semi-definite (smallest principal moment -0.4 kg*m^2)"),
    (["disk(m=1kg, r=1m)", "--axis", "(0, 0, 0)"],
     "--axis has zero length: a direction needs a non-zero vector"),
    (["disk(m=1kg, r=1m)", "--axis", "z through (1, 0) m"],
     "--axis (the point it passes through) must have 3 components; got 2 in '(1, 0) m'"),
    (["rod(m=1e300kg, l=1e300m)"],
     "a mass, centre or moment of inertia overflows float64 (beyond 1.8e308 in kg, m, "
     "kg*m^2): give the bodies sizes and positions that keep them in range"),
    (["rod(rho=1e-320 kg/m, l=1e-10 m)"],
     "the total mass underflows to zero (below 5e-324 kg): give the bodies larger masses or "
     "densities"),
    (["disk(m=1kg, r=1m)", "--axes", "z"],
     "No such option '--axes' (did you mean '--axis' or '--value'?); see 'dyncalc inertia "
     "--help'"),
])
def test_refusals_exact_messages(args, message):
    assert error_line(run(*args)) == f"Error: {message}"


def test_at_most_200_bodies():
    words = [f"point(m=1kg, at=({i}, 0, 0) m)" for i in range(201)]
    assert error_line(run(*words)) == "Error: inertia takes at most 200 bodies; got 201"
    out = values(*words[:200], "--axis", "z")
    assert out["m"] == 200.0
    assert out["J_axis"] == pytest.approx(sum(i * i for i in range(200)), rel=1e-15)


def test_batch_takes_one_composite_per_row(tmp_path):
    """A row's body cells are the one-off's words (tests/test_batch_inertia.py has more)."""
    rows = tmp_path / "rows.csv"
    rows.write_text('b1,b2,axis\n"rod(m=3kg, l=2m, along=x, at=(1, 0, 0) m)",,z\n'
                    '"disk(m=4kg, r=0.2m)","-disk(m=0.25kg, r=5cm, at=(0.1, 0, 0) m)",x\n')
    result = run("--batch", str(rows), "--json")
    assert (result.exit_code, result.stderr) == (0, "")
    got = [json.loads(line) for line in result.stdout.splitlines()]
    assert got[0]["results"]["J_axis"]["value"] == pytest.approx(4.0, rel=1e-15)  # m l^2/3
    one_off = values("disk(m=4kg, r=0.2m)", "-disk(m=0.25kg, r=5cm, at=(0.1, 0, 0) m)",
                     "--axis", "x")
    assert got[1]["results"]["J_axis"]["value"] == one_off["J_axis"]


def test_python_api_is_the_cli_to_the_bit():
    words = ["solid-cylinder(m=2kg, r=0.1m, h=0.3m, along=(1, 2, 0))", "-point(m=0.1kg)"]
    r = dyncalc.inertia(*words, axis="y through (0, 0, 0.1) m")
    cli = values(*words, "--axis", "y through (0, 0, 0.1) m")
    assert r["J_axis"].to("kg*m^2").magnitude == cli["J_axis"]
    assert r["J_C"].magnitude.tolist() == cli["J_C"].tolist()
    with pytest.raises(dyncalc.InputError, match="^unknown body 'cube'"):
        dyncalc.inertia("cube(m=1kg)")


def test_value_of_J_C_reads_back_as_rows():
    """``--value J_C`` prints rows by ';' (what rigid-body's --inertia-tensor will read)."""
    result = run("plate(m=3kg, a=0.4m, b=0.2m, along=(1, 1, 1))", "--value", "J_C")
    rows = np.array([[float(c) for c in row.split(",")]
                     for row in result.stdout.strip().split(";")])
    J = values("plate(m=3kg, a=0.4m, b=0.2m, along=(1, 1, 1))")["J_C"]
    assert np.array_equal(rows, J) and np.array_equal(rows, rows.T)
    n = np.ones(3) / math.sqrt(3)
    assert n @ rows @ n == pytest.approx(3 * (0.16 + 0.04) / 12, rel=1e-14)  # the normal


def test_help_states_the_sign_convention():
    result = run("--help")
    assert "J_xy = -int x y dm" in result.stdout
    assert shlex.split('"rod(m=2kg, l=1m)"') == ["rod(m=2kg, l=1m)"]
