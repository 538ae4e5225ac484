"""``dyncalc eom`` from the command line: typed energies, the results and their units,
equilibria (the ones sympy's solve misses too), --about, the state, --explain=latex, the
refusals with their exact messages and exit status, batch mode and the Python API, and that
sympy loads for eom only."""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from helpers import error_line, invoke, json_of

ROOT = Path(__file__).resolve().parents[1]
G = 9.80665


def results(*args):
    return json_of("eom", *args)["results"]


def test_mass_spring_typed():
    r = results("--coords", "x", "--T", "m*x'^2/2", "--V", "k*x^2/2", "m=2kg", "k=200N/m")
    assert r["eom_1"] == {"value": "x'' = -k*x/m", "unit": ""}
    assert r["equilibria"]["value"] == "x=0 (stable)"
    assert r["mass_matrix"] == {"value": [[2.0]], "unit": "kg"}
    assert r["stiffness_matrix"] == {"value": [[200.0]], "unit": "N/m"}
    assert r["omega_1"] == {"value": 10.0, "unit": "rad/s"}
    assert r["f_1"]["value"] == pytest.approx(10 / (2 * math.pi), rel=1e-15)


def test_units_of_the_inputs_do_not_change_the_numbers():
    si = results("--coords", "x", "--T", "m*x'^2/2", "--V", "k*x^2/2", "m=2kg", "k=200N/m")
    imperial = results("--coords", "x", "--T", "m*x'^2/2", "--V", "k*x^2/2",
                       f"m={2 / 0.45359237!r} lb", f"k={200 * 0.0254 / 4.4482216152605!r} lbf/in")
    assert imperial["omega_1"]["value"] == pytest.approx(si["omega_1"]["value"], rel=1e-13)


def test_symbolic_without_values():
    r = results("--coords", "phi", "--T", "m*l^2*phi'^2/2", "--V", "m*g*l*(1 - cos(phi))")
    assert r["eom_1"]["value"] == "phi'' = -g*sin(phi)/l"
    assert r["equilibria"]["value"] == "phi=0 (stable); phi=pi (unstable)"
    assert r["mass_matrix"]["value"] == "[[l^2*m]]"
    assert r["stiffness_matrix"]["value"] == "[[g*l*m]]"
    assert "omega_1" not in r


def test_a_number_with_a_unit_inside_an_expression():
    r = results("--coords", "x", "--T", "M*x'^2/2", "--V", "M*9.81 m/s^2*x + k*x^2/2",
                "M=1kg", "k=100N/m")
    # the weight shifts the equilibrium to -M g / k and leaves omega alone
    eq = json_of("eom", "--coords", "x", "--T", "M*x'^2/2", "--V",
                 "M*9.81 m/s^2*x + k*x^2/2", "M=1kg", "k=100N/m")["extra"]["equilibria"]
    assert eq == [{"x": pytest.approx(-0.0981, rel=1e-13), "stable": True}]
    assert r["omega_1"]["value"] == pytest.approx(10.0, rel=1e-14)
    # with a parameter m, "9.81 m" would be ambiguous: refused, saying so
    line = error_line(invoke("eom", "--coords", "x", "--T", "m*x'^2/2", "--V",
                             "m*9.81 m/s^2*x", "m=1kg"))
    assert line == ("Error: --V: 'm' after the number 9.81 is a name of the expression here, "
                    "not a unit: write 9.81*m for the product at column 8: 'm*9.81 m/s^2*x'")


def test_damping_and_a_generalized_force():
    r = results("--coords", "x", "--T", "m*x'^2/2", "--V", "k*x^2/2", "--D", "c*x'^2/2",
                "--Q", "x: F0*cos(w*t)", "m=2kg", "k=200N/m", "c=4N*s/m", "F0=10N",
                "w=3rad/s", "x=0.1m", "x_dot=1m/s", "t=0.5s")
    assert r["eom_1"]["value"] == "x'' = (F0*cos(t*w) - c*x' - k*x)/m"
    # by hand: (10 cos(1.5) - 4*1 - 200*0.1) / 2
    assert r["x_ddot"]["value"] == pytest.approx((10 * math.cos(1.5) - 4 - 20) / 2, rel=1e-13)
    assert r["x_ddot"]["unit"] == "m/s^2"
    assert r["omega_1"]["value"] == pytest.approx(10.0, rel=1e-14)


def test_the_top_of_the_ring_is_found_by_the_grid():
    """sympy's solve finds 0 and the two riding branches of the bead's static equation at
    values; the grid of starts finds pi (the top) as well, and both branches are stable."""
    data = json_of("eom", "--scene", "bead-on-rotating-ring", "r=0.2m", "Omega=10rad/s")
    eq = data["extra"]["equilibria"]
    theta = math.acos(G / (0.2 * 100))
    assert [(e["theta"], e["stable"]) for e in eq] == [
        (0.0, False), (pytest.approx(theta, rel=1e-12), True),
        (pytest.approx(-theta, rel=1e-12), True), (pytest.approx(math.pi, rel=1e-15), False)]
    assert data["extra"]["about"] == {"theta": pytest.approx(theta, rel=1e-12)}
    omega = math.sqrt(100 - (G / (0.2 * 10)) ** 2)
    assert data["results"]["omega_1"]["value"] == pytest.approx(omega, rel=1e-12)


def test_about_chooses_the_equilibrium():
    r = results("--scene", "bead-on-rotating-ring", "r=0.2m", "Omega=3rad/s", "--about",
                "theta=0")
    assert r["omega_1"]["value"] == pytest.approx(math.sqrt(G / 0.2 - 9), rel=1e-13)
    out = invoke("eom", "--scene", "pendulum", "l=1m", "--about", "phi=pi")
    assert out.exit_code == 0
    assert ("warning: the equilibrium linearised about is unstable: no natural frequency (a "
            "small disturbance grows)") in out.stdout
    assert "omega_1" not in out.stdout
    line = error_line(invoke("eom", "--scene", "pendulum", "l=1m", "--about", "phi=1"))
    assert line == ("Error: --about phi=1: not an equilibrium found; the equilibria are "
                    "phi=0 (stable); phi=3.14159 (unstable)")
    line = error_line(invoke("eom", "--scene", "pendulum", "l=1m", "--about", "x=0"))
    assert line == ("Error: --about takes COORDINATE=VALUE, e.g. \"phi=0\" (the coordinates "
                    "are phi); got 'x=0'")


def test_a_state_gives_the_accelerations():
    """E4.19 at a state against SCENES.md's closed forms."""
    m1, m2, l, phi, w = 2.0, 1.0, 0.5, math.radians(30), 1.5
    r = results("--scene", "pendulum-on-sliding-block", "m1=2kg", "m2=1kg", "l=0.5m",
                "phi=30deg", "phi_dot=1.5rad/s")
    den = m1 + m2 * math.sin(phi) ** 2
    assert r["x_ddot"]["value"] == pytest.approx(
        m2 * math.sin(phi) * (l * w ** 2 + G * math.cos(phi)) / den, rel=1e-13)
    assert r["phi_ddot"]["value"] == pytest.approx(
        -math.sin(phi) * ((m1 + m2) * G + m2 * l * w ** 2 * math.cos(phi)) / (l * den),
        rel=1e-13)
    assert r["phi_ddot"]["unit"] == "rad/s^2"
    line = error_line(invoke("eom", "--scene", "pendulum-on-sliding-block", "m1=2kg",
                             "m2=1kg", "l=0.5m", "phi=30deg"))
    assert line == "Error: x_ddot at the state needs phi_dot= too"


def test_mixed_coordinates_give_units_per_entry():
    data = json_of("eom", "--scene", "block-disk-springs", "M=3kg", "m=1kg", "r=10cm",
                   "k=100N/m")
    rows = data["results"]["mass_matrix"]["value"]  # [[M + m, -m r], [-m r, 3 m r^2 / 2]]
    assert [v for row in rows for v in row] == pytest.approx([4.0, -0.1, -0.1, 0.015],
                                                             rel=1e-15)
    assert data["extra"]["matrix_units"] == {
        "mass_matrix": [["kg", "kg*m"], ["kg*m", "kg*m^2"]],
        "stiffness_matrix": [["N/m", "N/rad"], ["N/rad", "N*m/rad"]]}
    assert data["results"]["mass_matrix"]["unit"] == ""


MIXED = ("eom", "--scene", "block-disk-springs", "M=3kg", "m=1kg", "r=10cm", "k=100N/m")


def test_mixed_matrices_show_each_entrys_unit_in_the_table():
    out = invoke(*MIXED)
    assert out.exit_code == 0
    rows = {line.split()[0]: line for line in out.stdout.splitlines()[1:]}
    assert rows["mass_matrix"].split(None, 2)[2].rstrip() == \
        "[[4 kg, -0.1 kg*m], [-0.1 kg*m, 0.015 kg*m^2]]"
    assert rows["stiffness_matrix"].split(None, 2)[2].rstrip() == \
        "[[100 N/m, 0 N/rad], [0 N/rad, 1 N*m/rad]]"


def test_mixed_matrices_value_reads_back_into_modes():
    """--value writes each entry with its unit; modes --M/--K read it back and give the
    frequencies of the scene's closed form (SCENES.md E4.14)."""
    M = invoke(*MIXED, "--value", "mass_matrix")
    K = invoke(*MIXED, "--value", "stiffness_matrix")
    assert M.stdout == "[[4.0 kg, -0.1 kg*m], [-0.1 kg*m, 0.015000000000000003 kg*m^2]]\n"
    assert K.stdout == "[[100.0 N/m, 0.0 N/rad], [0.0 N/rad, 1.0000000000000002 N*m/rad]]\n"
    again = json_of("modes", "--M", M.stdout.strip(), "--K", K.stdout.strip())
    big, m, k = 3.0, 1.0, 100.0
    root = math.sqrt(4 * big ** 2 - 4 * big * m + 17 * m ** 2)
    expected = [math.sqrt(k * ((2 * big + 5 * m) + sign * root) / (2 * m * (3 * big + m)))
                for sign in (-1, 1)]
    assert [again["results"][f"omega_{i}"]["value"] for i in (1, 2)] == pytest.approx(
        expected, rel=1e-14)
    assert [c["kind"] for c in again["extra"]["coordinates"]] == ["translation", "rotation"]


def test_uniform_matrix_value_stays_plain():
    out = invoke("eom", "--scene", "coupled-blocks", "m1=1kg", "m2=2kg", "k1=100N/m",
                 "k2=200N/m", "k3=50N/m", "--value", "mass_matrix")
    assert out.stdout == "1.0,0.0;0.0,2.0\n"


def test_explain_latex_typesets_the_equations():
    out = invoke("eom", "--scene", "pendulum", "l=1m", "--explain=latex")
    assert out.exit_code == 0
    assert r"\ddot{\phi} &= - \frac{g \sin{\left(\phi \right)}}{l}" in out.stdout
    assert r"T &= \frac{l^{2} \dot{\phi}^{2}}{2}" in out.stdout


@pytest.mark.parametrize("args, message", [
    (["--coords", "x", "--T", "m*x^2/2", "m=2kg"],
     "Error: --T must be an energy ([mass]*[length]^2/[time]^2) or an energy per unit mass "
     "([length]^2/[time]^2); got [mass]*[length]^2 (with x a length)"),
    (["--coords", "x", "--T", "m*x'^2/2", "--V", "k*x", "m=2kg", "k=1N/m"],
     "Error: --V must be an energy, like --T; got [mass]*[length]/[time]^2 (with x a length)"),
    (["--coords", "x", "--T", "m*x'^2/2", "--V", "__import__('os').system('ls')"],
     "Error: --V: names may not begin with '_' ('__import__') at column 1: "
     "'__import__('os').system('ls')'"),
    (["--coords", "x", "--T", "m*x'^2/2", "--V", "k*x^2/2", "m=2kg", "k=1N/m", "q=2"],
     "Error: q= is not a name of --T, --V, --D or --Q (the names there are k, m)"),
    (["--scene", "pendulum", "L=2m"],
     "Error: L= is not a parameter of --scene pendulum (did you mean l?); its parameters are "
     "l, g"),
    (["--scene", "slotted-link"],
     "Error: --scene slotted-link has no free coordinate (it is pure kinematics): eom has no "
     "equation of motion to derive"),
    (["--scene", "pendulum", "--T", "x"],
     "Error: --T does not go with --scene pendulum: the scene carries its coordinates and "
     "energies"),
    (["--scene", "pendulam"],
     "Error: --scene: unknown scene 'pendulam' for eom (did you mean 'pendulum'?); see "
     "dyncalc scenes --command eom"),
    (["--coords", "x, x", "--T", "x'^2"], "Error: --coords names a coordinate twice"),
    (["--coords", "a,b,c,d,e,f,g", "--T", "a'^2"],
     "Error: --coords: eom derives at most 6 coordinates; got 7"),
    (["--T", "x'^2"], "Error: eom needs --coords and --T (and usually --V), or --scene NAME"),
    (["--coords", "x", "--T", "m*x'^2/2", "--Q", "y: 1"],
     "Error: --Q: 'y' is not a coordinate (the coordinates are x)"),
    (["--coords", "x, y", "--T", "m*x'^2/2"],
     "Error: the mass matrix d2T/dq'dq' is singular: some coordinate carries no kinetic "
     "energy (check --T and --coords)"),
    (["--coords", "x", "--T", "m*x'^2/2", "--V", "k*x^2/2", "m=2kg", "k=1N/m", "x=1s"],
     "Error: x= must be a length [length]; got 1 second ([time])"),
    (["--scene", "pendulum", "l=1+/-0.1 m"],
     "Error: l=: an uncertainty is not read here (eom does not propagate one); give the value "
     "alone"),
    (["--scene", "pendulum", "l=-1m"], "Error: l= must be positive; got -1 meter"),
])
def test_refusals(args, message):
    assert error_line(invoke("eom", *args)) == message


def test_batch_over_a_scene(tmp_path):
    path = tmp_path / "rows.csv"
    path.write_text("l [m],phi [deg],phi_dot [rad/s]\n1,10,0\n2,30,1\n")
    out = invoke("eom", "--scene", "pendulum", "--batch", str(path))
    assert out.exit_code == 0, out.stderr
    lines = out.stdout.splitlines()
    assert lines[0] == ("l [m],phi [deg],phi_dot [rad/s],eom_1,equilibria,mass_matrix [m^2],"
                        "stiffness_matrix [m^2/s^2/rad],omega_1 [rad/s],f_1 [Hz],"
                        "phi_ddot [rad/s^2]")
    cells = lines[2].split(",")
    assert float(cells[7]) == pytest.approx(math.sqrt(G / 2), rel=1e-15)
    assert float(cells[9]) == pytest.approx(-G / 2 * math.sin(math.radians(30)), rel=1e-14)
    line = error_line(invoke("eom", "--batch", str(path)))
    assert line == ("Error: eom --batch needs --scene NAME: each row gives that scene's "
                    "parameter values (typed energies are one-offs)")


def test_python_api():
    import dyncalc

    r = dyncalc.eom(scene="coupled-blocks", m1="1 kg", m2="1 kg", k1="100 N/m",
                    k2="100 N/m", k3="50 N/m")
    assert r["omega_1"].to("rad/s").magnitude == pytest.approx(10.0, rel=1e-14)
    assert r["omega_2"].to("rad/s").magnitude == pytest.approx(math.sqrt(200), rel=1e-14)
    assert r.to_dict()["results"]["eom_1"]["value"] == "x1'' = (-k1*x1 - k3*(x1 - x2))/m1"


def _loaded(code: str) -> list[str]:
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120, env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout.strip().splitlines()[-1])


def test_sympy_loads_for_eom_only():
    run = ("import sys, json\nfrom click.testing import CliRunner\nfrom dyncalc.cli import cli\n"
           "r = CliRunner().invoke(cli, {args!r})\nassert r.exit_code == 0, r.output\n"
           "print(json.dumps('sympy' in sys.modules))")
    others = [["natural-frequency", "--scene", "pendulum", "l=1m"],
              ["forced-response", "--k", "1kN/m", "--m", "1kg", "--F0", "1N", "--Omega",
               "10rad/s"],
              ["coriolis", "--omega", "2rad/s", "--vr", "3m/s"],
              ["scenes"], ["eom", "--help"]]
    for args in others:
        assert _loaded(run.format(args=args)) is False, args
    assert _loaded(run.format(args=["eom", "--scene", "pendulum", "l=1m"])) is True


def test_a_runaway_derivation_is_refused():
    """Powers of sums in the coordinates are bounded before sympy sees them; anything else
    that grows too long is stopped by the budget (here shrunk so the test stays short)."""
    line = error_line(invoke("eom", "--coords", "x", "--T", "m*(x'+x)^64/2"))
    assert line == ("Error: --T: eom takes powers up to 8 of an expression in the coordinates "
                    "at column 9: 'm*(x'+x)^64/2'")
    from dyncalc.commands import eom_results

    original = eom_results.BUDGET
    eom_results.BUDGET = 0.05
    try:
        line = error_line(invoke("eom", "--coords", "x", "--T",
                                 "m*x'^2*(1+x)^8*(2+x)^8*(3+x)^8", "--V", "x^2"))
    finally:
        eom_results.BUDGET = original
    assert line == ("Error: the derivation did not finish within 0.05 s; simplify the "
                    "energies (expand fewer powers, fewer nested functions)")


_HOSTILE = ["__import__('os')", "x'", "x''", "m", "k", "*", "/", "^", "(", ")", "+", "-",
            "sin(", "exp(", "2", "9.81 m/s^2", "1e308", ".", "[", "'", ";", ":", "lambda",
            "t", "pi", " ", ",", "atan2(", "\x00", "é", "**", "y'"]


@settings(max_examples=150, deadline=None)
@given(st.lists(st.sampled_from(_HOSTILE), max_size=30), st.booleans())
def test_hostile_energies_are_read_or_refused_before_sympy(pieces, valued):
    """What the user types reaches sympy only as a tree of the grammar that passed the
    dimension check; anything else is an InputError naming the option."""
    from dyncalc.commands.eom import read
    from dyncalc.commands.eom_results import _check_powers, _coordinate_dims
    from dyncalc.errors import InputError

    text = "".join(pieces)
    words = ["m=2kg", "k=3N/m"] if valued else []
    try:
        inputs = read({"coords": "x", "T": "m*x'^2/2", "V": text}, words)
        _coordinate_dims(inputs)
        _check_powers(inputs)
    except InputError as exc:
        assert str(exc).startswith(("--V", "--T", "m=", "k=")) and "\n" not in str(exc), str(exc)


def test_below_the_critical_speed_the_ring_has_two_equilibria():
    """Omega^2 < g/r: only the bottom (stable) and the top (unstable)."""
    data = json_of("eom", "--scene", "bead-on-rotating-ring", "r=0.2m", "Omega=3rad/s")
    assert [(e["theta"], e["stable"]) for e in data["extra"]["equilibria"]] == [
        (0.0, True), (pytest.approx(math.pi, rel=1e-15), False)]


def test_transcendental_equilibria_come_from_the_numeric_search():
    """kt phi = m g l sin(phi) has no closed form; with m g l / kt = 2 its roots are 0
    (unstable: kt < m g l) and +-phi* with phi* = 2 sin(phi*) (stable), found here by
    brentq independently."""
    from scipy.optimize import brentq

    data = json_of("eom", "--coords", "phi", "--T", "J*phi'^2/2", "--V",
                   "kt*phi^2/2 + m*g*l*cos(phi)", "J=1kg*m^2", "kt=1N*m/rad", "m=1kg",
                   "g=2m/s^2", "l=1m")
    star = brentq(lambda p: p - 2 * math.sin(p), 1.0, 3.0, xtol=1e-15)
    assert [(e["phi"], e["stable"]) for e in data["extra"]["equilibria"]] == [
        (0.0, False), (pytest.approx(star, rel=1e-12), True),
        (pytest.approx(-star, rel=1e-12), True)]
    # about the first stable one: omega^2 = (kt - m g l cos(phi*)) / J
    assert data["results"]["omega_1"]["value"] == pytest.approx(
        math.sqrt(1 - 2 * math.cos(star)), rel=1e-11)
