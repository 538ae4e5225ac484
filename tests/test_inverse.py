"""Inverse problems (issue 10): a result given as NAME=QUANTITY, one parameter unknown.

Every scene of the catalog is solved back to its own example's inputs (the round trip returns
the input), a dozen inversions are checked against closed forms worked by hand from SCENES.md
(or mpmath), and every refusal is asserted with its exact message.

Tolerances. A closed-form inversion ``x = x1 (y/y1)^(1/a)`` is a handful of roundings (a log,
an exp and the display-unit conversion of the target): 1e-9 leaves six decades of room. A
bracketed root is refined by Brent's method to ~4 eps in x, but the target itself is read back
from a rounded display value and the error in x is that of y divided by the elasticity
d ln y / d ln x (between 0.05 and 2 at the catalog examples): 1e-8 is the tolerance used there.
"""
import json
import math
import re
import shlex

import mpmath
import pytest

from dyncalc.commands.natural_frequency import STANDARD
from dyncalc.errors import InputError
from dyncalc.scenes import computed_scenes, get_scene
from dyncalc.commands.natural_frequency import compute_scene
from helpers import error_line, invoke, json_of

TWO_PI = 2 * math.pi
G0 = 9.80665
CLOSED_TOL = 1e-9   # see the module docstring
ROOT_TOL = 1e-8


@pytest.fixture(autouse=True)
def mp_precision():
    """30 digits for the mpmath references, restored afterwards (other modules set theirs)."""
    with mpmath.workdps(30):
        yield


# -- helpers ---------------------------------------------------------------------------------

#: The commands a scene's example runs (forced scenes: forced-response; rigid-body and
#: relative-motion scenes).
EXAMPLE_COMMANDS = ("natural-frequency", "forced-response", "rigid-body", "coriolis")


def example_texts(scene):
    """The NAME=VALUE texts of a scene's example command (standard options mapped to their
    scene parameters as the CLI does: --length is l=, --inertia is J=)."""
    words = shlex.split(scene.example)
    assert words[0] == "dyncalc" and words[1] in EXAMPLE_COMMANDS, scene.example
    texts, i = {}, 2
    while i < len(words):
        word = words[i]
        if word == "--scene":
            i += 2
        elif word.startswith("--"):
            texts[STANDARD[word[2:]]] = words[i + 1]
            i += 2
        else:
            name, _, text = word.partition("=")
            texts[name] = text
            i += 1
    return texts


def si_text(param, x):
    """``x`` (SI) as a text the parameter reads back exactly."""
    unit = param.dim.si
    return f"{x!r} {unit}" if unit else repr(x)


def numbers(result):
    """Numeric results by name, SI (floats or lists for vectors)."""
    out = {}
    for name, entry in result.results.items():
        if entry.dim is None or isinstance(entry.si, str):
            continue
        out[name] = entry.si
    return out


def solutions(result, name):
    """The solved values of parameter ``name`` (SI), ascending: ``name`` or ``name_1, ...``."""
    pattern = re.compile(rf"^{re.escape(name)}(_\d+)?$")
    found = {n: e.si for n, e in result.results.items()
             if pattern.match(n) and "(solved from " in e.description}
    return [found[n] for n in sorted(found, key=lambda n: found[n])]


def target_text(result, name):
    entry = result.results[name]
    return f"{entry.value_in(entry.unit)!r} {entry.unit}".rstrip()


def rel(a, b):
    return abs(a - b) / abs(b) if b != 0 else abs(a)


#: Parameters a result depends on periodically (cos(t/(2 t0))): thousands of roots, refused
#: as such (MAX_ROOTS); solved for from other parameters instead.
PERIODIC = {("mass-spring-given-response", "t0"), ("mass-spring-given-response", "t")}


def round_trip_cases():
    """(scene, parameter, i) for every numeric parameter the example gives or defaults (g),
    besides zeta; ``i`` rotates the preferred target among omega, f and T."""
    cases = []
    for name in list(computed_scenes()):
        scene = get_scene(name)
        texts = example_texts(scene)
        for param in scene.params:
            if param.dim is None or param.name == "zeta":
                continue
            if (name, param.name) in PERIODIC:
                continue
            if param.name in texts or param.default is not None:
                cases.append(pytest.param(name, param.name, len(cases),
                                          id=f"{name}-{param.name}"))
    return cases


CASES = round_trip_cases()


def test_every_scene_and_every_required_dimensional_parameter_is_covered():
    """The round trip below covers each scene, and in each every required parameter."""
    covered = {(c.values[0], c.values[1]) for c in CASES}
    assert {c[0] for c in covered} == set(list(computed_scenes()))
    for name in list(computed_scenes()):
        scene = get_scene(name)
        for p in scene.params:
            if p.dim is not None and p.default is None and not p.optional \
                    and (name, p.name) not in PERIODIC:
                assert (name, p.name) in covered, (name, p.name)


def pick_target(scene, texts, forward, param, i):
    """A result that moves when ``param`` does (bumped 1 %): omega/f/T first (rotating)."""
    base = numbers(forward)
    assert forward.inputs[param.name].si != 0
    bumped = dict(texts)
    bumped[param.name] = si_text(param, forward.inputs[param.name].si * 1.01)
    moved = numbers(compute_scene(scene, bumped))
    order = ["omega", "f", "T"]
    order = order[i % 3:] + order[:i % 3]
    order += [n for n in base if n not in order]
    for name in order:
        if name in base and name in moved and isinstance(base[name], float) \
                and moved[name] != base[name]:
            return name
    raise AssertionError(f"no result of {scene.name} depends on {param.name}")


def round_trip(scene_name, param_name, target, ask):
    """Forward from the example, then solve back for ``param_name`` from ``target``
    (``ask``: give it as NAME=?, else leave it out) and compare."""
    scene = get_scene(scene_name)
    param = scene.param(param_name)
    texts = example_texts(scene)
    forward = compute_scene(scene, texts)
    original = forward.inputs[param_name].si
    if target is None:
        target = pick_target(scene, texts, forward, param, ask)
        ask = bool(ask % 2)
    posed = {n: t for n, t in texts.items() if n != param_name}
    # a defaulted or optional parameter (g, amplitude, J of a J-or-J_A pair) must be NAME=?
    if ask or param.default is not None or param.optional:
        posed[param_name] = "?"
    posed[target] = target_text(forward, target)
    solved = compute_scene(scene, posed)

    inverse = solved.extra["inverse"]
    assert inverse["unknown"] == param_name
    assert inverse["method"] in ("closed-form", "bracketed-root")
    tol = CLOSED_TOL if inverse["method"] == "closed-form" else ROOT_TOL
    found = solutions(solved, param_name)
    assert found, solved.results.keys()
    assert any(rel(x, original) <= tol for x in found), (found, original)
    assert solved.inputs[target].si == pytest.approx(forward.results[target].si, rel=1e-15)
    goal = forward.results[target].si
    if len(found) == 1:
        # the other results at the solution are those of the forward run
        assert set(solved.results) == {param_name} | set(forward.results)
        expected = numbers(forward)
        for name, value in numbers(solved).items():
            if name == param_name:
                continue
            if isinstance(value, float):
                assert value == pytest.approx(expected[name], rel=ROOT_TOL, abs=1e-300), name
            else:
                assert list(value) == pytest.approx(list(expected[name]), rel=ROOT_TOL,
                                                    abs=1e-12), name
    else:
        # several: all listed, each one really gives the target (recomputed forward)
        assert list(solved.results) == [f"{param_name}_{k}" for k in range(1, len(found) + 1)]
        assert any(w.startswith(f"{len(found)} values of {param_name} give {target} = ")
                   for w in solved.warnings), solved.warnings
        for x in found:
            again = dict(texts)
            again[param_name] = si_text(param, x)
            assert compute_scene(scene, again).results[target].si == pytest.approx(
                goal, rel=ROOT_TOL), (x, target)
    return found


@pytest.mark.parametrize("scene_name, param_name, i", CASES)
def test_round_trip_returns_the_input(scene_name, param_name, i):
    """Every scene, every parameter its example gives: solved back from omega, f or T (or the
    first result that depends on it), left out or given as NAME=? in turn."""
    round_trip(scene_name, param_name, None, i)


@pytest.mark.parametrize("scene_name, param_name, target", [
    ("rod-torsion-spring", "kt", "phi_0"),
    ("rod-torsion-spring", "m", "phi_0"),
    ("pendulum-accelerating-support", "a0", "phi_0"),
    ("bead-on-rotating-ring", "g", "theta_eq"),
    ("bead-on-rotating-ring", "Omega", "theta_eq"),
    ("clock-pendulum", "a", "J_A"),
    ("disk-torsion-offset-mass", "r", "J_A"),
    ("quarter-car", "k", "v_crit"),
    ("quarter-car", "v0", "x_amp"),
    ("quarter-car", "L", "x_amp"),
    ("quarter-car", "m", "x_amp"),
    ("pendulum-spring-dashpot", "k", "omega_d"),
    ("pendulum-spring-dashpot", "m", "T_d"),
    ("pendulum-spring-dashpot", "a", "zeta"),
    ("rod-in-fluid", "beta", "zeta"),
    ("rod-in-fluid", "l", "beta_crit"),
    ("frame-brace-damper", "d", "y_max"),
    ("frame-brace-damper", "m", "f_d"),
    ("coupled-blocks", "m2", "T_2"),
    ("coupled-blocks", "k3", "f_2"),
    ("half-cylinder-shell", "amplitude", "T"),
    ("pendulum", "amplitude", "f"),
    ("pendulum", "l", "omega_0"),
])
def test_round_trip_from_other_results(scene_name, param_name, target):
    """The same round trip from results other than omega/f/T (angles, inertias, speeds,
    amplitudes, damped quantities, the second mode)."""
    round_trip(scene_name, param_name, target, True)


def test_round_trip_with_several_solutions_keeps_the_original():
    """quarter-car: the speed below and the speed above resonance give one amplitude."""
    found = round_trip("quarter-car", "v0", "x_amp", False)
    assert len(found) == 2 and found[0] < 15.9154943 < found[1]   # v_crit between them


# -- against closed forms worked by hand ----------------------------------------------------

def test_readme_example_on_the_command_line():
    """dyncalc natural-frequency f=5Hz m=2kg: k = (2 pi 5)^2 2 = 1973.92 N/m."""
    data = json_of("natural-frequency", "f=5Hz", "m=2kg")
    k = (TWO_PI * 5) ** 2 * 2
    assert data["scene"] == "mass-spring"
    assert list(data["results"]) == ["k", "omega", "f", "T"]
    assert data["results"]["k"]["unit"] == "N/m"
    assert data["results"]["k"]["value"] == pytest.approx(k, rel=1e-12)
    assert data["results"]["omega"]["value"] == pytest.approx(TWO_PI * 5, rel=1e-12)
    assert data["results"]["f"]["value"] == pytest.approx(5.0, rel=1e-12)
    assert data["results"]["T"]["value"] == pytest.approx(0.2, rel=1e-12)
    assert data["inputs"] == {"m": {"value": 2.0, "unit": "kg", "text": "2kg"},
                              "f": {"value": 5.0, "unit": "Hz", "text": "5Hz"}}
    assert data["extra"]["inverse"] == {"unknown": "k", "method": "closed-form",
                                        "detail": "f is proportional to k^(1/2): inverted exactly"}
    human = invoke("natural-frequency", "f=5Hz", "m=2kg")
    assert human.exit_code == 0
    assert human.stdout.splitlines()[0].endswith("solved for k: closed-form")
    assert re.search(r"^k\s+k\s+1973\.92\s+N/m$", human.stdout, re.M), human.stdout


def test_leaving_out_and_question_mark_are_the_same():
    left_out = json_of("natural-frequency", "f=5Hz", "m=2kg")
    asked = json_of("natural-frequency", "f=5Hz", "m=2kg", "k=?")
    assert left_out["results"] == asked["results"]


@pytest.mark.parametrize("target", ["omega=60rpm", "omega=6.283185307179586rad/s",
                                    "omega=360deg/s", "f=1Hz", "f=60 1/min", "f=60rpm",
                                    "T=1s", "T=1000ms"])
@pytest.mark.parametrize("mass", ["m=2kg", "m=2000g"])
def test_unit_invariance(target, mass):
    """One cycle a second in any unit, 2 kg in any unit: k = (2 pi)^2 2 N/m."""
    data = json_of("natural-frequency", target, mass)
    assert data["results"]["k"]["value"] == pytest.approx(TWO_PI ** 2 * 2, rel=1e-12)


def test_pendulum_length_from_period():
    """l = g (T / 2 pi)^2: a 2 s pendulum (the seconds pendulum) is 0.9936 m."""
    result = compute_scene("pendulum", {"T": "2 s"})
    assert solutions(result, "l") == [pytest.approx(G0 / math.pi ** 2, rel=CLOSED_TOL)]
    assert result.extra["inverse"]["method"] == "closed-form"


def test_pendulum_amplitude_from_period_against_mpmath():
    """T = 4 K(sin^2(theta0/2)) / omega_0 (mpmath's K takes m = k^2); solved for theta0."""
    omega0 = mpmath.sqrt(mpmath.mpf(G0) / 1)
    period = mpmath.mpf("2.5")
    theta = mpmath.findroot(
        lambda t: 4 * mpmath.ellipk(mpmath.sin(t / 2) ** 2) / omega0 - period, 1.8)
    result = compute_scene("pendulum", {"l": "1 m", "amplitude": "?", "T": "2.5 s"})
    assert solutions(result, "amplitude") == [pytest.approx(float(theta), rel=ROOT_TOL)]
    assert result.results["amplitude"].unit == "deg"
    assert result.results["amplitude"].value_in("deg") == pytest.approx(
        float(theta * 180 / mpmath.pi), rel=ROOT_TOL)


def test_drum_mass_from_frequency():
    """omega^2 = 2k/(M + 2m): M = 2k/omega^2 - 2m."""
    result = compute_scene("drum-block-spring", {"k": "2 kN/m", "m": "4 kg", "omega": "12 rad/s"})
    assert solutions(result, "M") == [pytest.approx(2 * 2000 / 144 - 8, rel=ROOT_TOL)]


def test_rolling_disk_kappa_from_frequency():
    """omega^2 = k/((1 + kappa) m): kappa = k/(m omega^2) - 1 (a parameter left optional)."""
    result = compute_scene("rolling-disk-spring",
                       {"k": "300 N/m", "m": "2 kg", "kappa": "?", "omega": "9 rad/s"})
    assert solutions(result, "kappa") == [pytest.approx(300 / (2 * 81) - 1, rel=ROOT_TOL)]


def test_rod_torsion_stiffness_from_equilibrium_angle():
    """(g/l) cos phi_0 = kt phi_0/(m l^2): kt = m g l cos(phi_0)/phi_0 (a target in deg)."""
    phi = math.radians(40)
    result = compute_scene("rod-torsion-spring", {"m": "2 kg", "l": "1 m", "phi_0": "40 deg"})
    assert solutions(result, "kt") == [pytest.approx(2 * G0 * math.cos(phi) / phi,
                                                     rel=ROOT_TOL)]
    assert result.results["phi_0"].si == pytest.approx(phi, rel=ROOT_TOL)


def test_mass_spring_zeta_from_damped_frequency():
    """omega_d = omega sqrt(1 - zeta^2): zeta = sqrt(1 - (omega_d/omega)^2) (zeta optional)."""
    data = json_of("natural-frequency", "--k", "100N/m", "--m", "2kg", "--zeta", "?",
                   "omega_d=7rad/s")
    assert data["extra"]["inverse"]["unknown"] == "zeta"
    assert data["results"]["zeta"]["value"] == pytest.approx(math.sqrt(1 - 49 / 50),
                                                             rel=ROOT_TOL)
    assert data["results"]["omega_d"]["value"] == pytest.approx(7.0, rel=ROOT_TOL)


def test_bead_two_spins_give_one_frequency():
    """Below the bifurcation Omega^2 = g/r - omega^2; above it Omega^4 - omega^2 Omega^2 -
    (g/r)^2 = 0. Both are listed, ascending, with a warning that names them."""
    data = json_of("natural-frequency", "--scene", "bead-on-rotating-ring", "omega=2rad/s",
                   "r=0.5m", "Omega=?")
    gr = G0 / 0.5
    low = math.sqrt(gr - 4)
    high = math.sqrt((4 + math.sqrt(16 + 4 * gr ** 2)) / 2)
    # Omega may have either sign (the ring spins either way): four roots, ascending
    assert list(data["results"]) == ["Omega_1", "Omega_2", "Omega_3", "Omega_4"]
    assert data["results"]["Omega_1"]["value"] == pytest.approx(-high, rel=ROOT_TOL)
    assert data["results"]["Omega_2"]["value"] == pytest.approx(-low, rel=ROOT_TOL)
    assert data["results"]["Omega_3"]["value"] == pytest.approx(low, rel=ROOT_TOL)
    assert data["results"]["Omega_4"]["value"] == pytest.approx(high, rel=ROOT_TOL)
    assert data["results"]["Omega_1"]["unit"] == "rad/s"
    assert data["warnings"] == [f"4 values of Omega give omega = 2 rad/s: {-high:.6g} rad/s, "
                                f"{-low:.6g} rad/s, {low:.6g} rad/s, {high:.6g} rad/s; each is "
                                "a result"]
    assert data["extra"]["inverse"] == {"unknown": "Omega", "method": "bracketed-root",
                                        "detail": "a sign change on a grid of Omega, refined "
                                                  "by Brent's method"}


def test_bead_spinning_the_other_way_is_found_too():
    """Omega has no sign constraint (the ring may spin either way) and the frequency depends
    on Omega^2 only: a ring spun at -4.66 rad/s gives omega = 2 rad/s, so solving back from
    omega = 2 rad/s must find -4.66 rad/s among its solutions (the round trip of a negative
    spin), like pendulum-on-rotating-disk and pendulum-accelerating-support do."""
    texts = {"r": "0.5 m", "Omega": "-4.659936470593289 rad/s"}
    forward = compute_scene("bead-on-rotating-ring", texts)
    solved = compute_scene("bead-on-rotating-ring",
                       {"r": "0.5 m", "Omega": "?",
                        "omega": f"{forward.results['omega'].si!r} rad/s"})
    found = solutions(solved, "Omega")
    assert any(rel(x, -4.659936470593289) <= ROOT_TOL for x in found), found


def test_signed_parameter_both_signs_listed():
    """pendulum-accelerating-support: omega^2 = sqrt(g^2 + a0^2)/l is even in a0: +-3 m/s^2."""
    result = compute_scene("pendulum-accelerating-support",
                       {"l": "1 m", "a0": "?", "omega": "3.2023836894876437 rad/s"})
    assert solutions(result, "a0") == [pytest.approx(-3.0, rel=ROOT_TOL),
                                       pytest.approx(3.0, rel=ROOT_TOL)]


def test_physical_pendulum_pivot_distance_two_roots():
    """omega^2 = m g a/(J + m a^2): m omega^2 a^2 - m g a + J omega^2 = 0 has two roots."""
    m, J, w = 2.0, 2 / 12, 3.5
    disc = math.sqrt((m * G0) ** 2 - 4 * m * w ** 2 * J * w ** 2)
    roots = sorted(((m * G0 - disc) / (2 * m * w ** 2), (m * G0 + disc) / (2 * m * w ** 2)))
    result = compute_scene("physical-pendulum",
                       {"m": "2 kg", "J": "(2/12) kg*m^2", "omega": "3.5 rad/s"})
    assert solutions(result, "a") == [pytest.approx(r, rel=ROOT_TOL) for r in roots]


def test_quarter_car_speed_from_amplitude_two_roots():
    """x_amp = U0/|1 - (Omega/omega)^2|, Omega = 2 pi v0/L: v0 = L omega sqrt(1 -+ U0/x)/2pi."""
    omega, L, U0, x = 10.0, 10.0, 0.02, 0.05
    roots = [L * omega * math.sqrt(1 + s * U0 / x) / TWO_PI for s in (-1, 1)]
    result = compute_scene("quarter-car", {"k": "40 kN/m", "m": "400 kg", "L": "10 m",
                                       "U0": "2 cm", "x_amp": "5 cm"})
    assert solutions(result, "v0") == [pytest.approx(r, rel=ROOT_TOL) for r in roots]


def test_damping_ratio_scene_solves_the_damper():
    """damping-ratio --scene rod-in-fluid: zeta = beta/beta_crit, beta_crit = (m/l)
    sqrt(6 g/l): zeta = 0.2 needs beta = 0.2 beta_crit."""
    data = json_of("damping-ratio", "--scene", "rod-in-fluid", "m=1.5kg", "l=0.8m",
                   "zeta=0.2")
    beta_crit = 1.5 / 0.8 * math.sqrt(6 * G0 / 0.8)
    assert data["command"] == "damping-ratio"
    assert data["extra"]["inverse"]["unknown"] == "beta"
    assert data["results"]["beta"]["value"] == pytest.approx(0.2 * beta_crit, rel=CLOSED_TOL)
    assert data["results"]["zeta"]["value"] == pytest.approx(0.2, rel=CLOSED_TOL)


def test_damping_ratio_scene_solves_from_its_decrement():
    """delta is a result of damping-ratio --scene (SPEC: any result name may be given):
    delta = 0.5 per cycle is zeta = 0.5/sqrt(4 pi^2 + 0.25), so beta = zeta beta_crit."""
    result = invoke("damping-ratio", "--scene", "rod-in-fluid", "m=1.5kg", "l=0.8m",
                    "delta=0.5", "--json")
    assert result.exit_code == 0, result.stderr
    data = json.loads(result.stdout)
    zeta = 0.5 / math.sqrt(4 * math.pi ** 2 + 0.25)
    beta_crit = 1.5 / 0.8 * math.sqrt(6 * G0 / 0.8)
    assert data["results"]["beta"]["value"] == pytest.approx(zeta * beta_crit, rel=ROOT_TOL)


# -- refusals ---------------------------------------------------------------------------------

def refusal(*args):
    return error_line(invoke("natural-frequency", *args))


def test_no_solution():
    line = refusal("f=-5Hz", "m=2kg")
    assert line.startswith("Error: no value of k gives f = -5 Hz in mass-spring with the "
                           "other parameters given; over the values of k tried it ranges "
                           "from "), line


def test_no_solution_range_is_the_range_tried():
    """k runs over the whole positive float range, 5e-324 ... 1.8e308 N/m (issue 15: the
    domain's edges are searched too): f from sqrt(5e-324/2)/2pi = 2.50148e-163 Hz to
    sqrt(1.8e308/2)/2pi = 1.50891e+153 Hz. f never reaches 0 for a positive k, so the message
    must not say it does (the range is of the values computed, not of y - goal + goal)."""
    line = refusal("f=-5Hz", "m=2kg")
    low = math.sqrt(5e-324) / math.sqrt(2) / TWO_PI   # 5e-324 / 2 itself underflows
    high = math.sqrt(1.7976931348623157e308 / 2) / TWO_PI
    assert line == ("Error: no value of k gives f = -5 Hz in mass-spring with the other "
                    f"parameters given; over the values of k tried it ranges from {low:.6g} "
                    f"to {high:.6g} Hz")


def test_no_solution_for_an_angle_names_the_range():
    """A pendulum is never faster than its small-angle period 2 pi sqrt(l/g) = 2.00641 s; the
    amplitude search ends at the edge of the domain (issue 15), the last float below pi
    (3.1415926535897927: pi itself is refused), where T = 4 K(sin^2(theta0/2))/omega_0."""
    omega0 = mpmath.sqrt(mpmath.mpf(G0))
    t_min = float(2 * mpmath.pi / omega0)
    with mpmath.workdps(60):  # 1 - sin^2(last/2) is about 8e-32
        last = mpmath.mpf(math.nextafter(math.pi, 0.0))
        t_max = float(4 * mpmath.ellipk(mpmath.sin(last / 2) ** 2) / mpmath.sqrt(G0))
    line = refusal("--scene", "pendulum", "l=1m", "amplitude=?", "T=1s")
    assert line == ("Error: no value of amplitude gives T = 1 s in pendulum with the other "
                    "parameters given; over the values of amplitude tried it ranges from "
                    f"{t_min:.6g} to {t_max:.6g} s")


def test_two_targets():
    assert refusal("f=5Hz", "T=1s", "m=2kg") == ("Error: give one result to solve from, not 2 "
                                                 "(f, T); compare the others with --check")


def test_nothing_missing():
    assert refusal("f=5Hz", "k=1N/m", "m=2kg") == (
        "Error: f= is a result of mass-spring and every parameter is given: leave out the one "
        "to solve for (or give it as NAME=?), or compare with --check f=...")


def test_two_missing():
    assert refusal("f=5Hz") == ("Error: mass-spring: f= leaves 2 parameters unknown (k, m); "
                                "give all but one")


def test_two_asked():
    assert refusal("k=?", "m=?", "f=5Hz") == "Error: give one unknown (NAME=?), not 2 (k, m)"


def test_a_choice_is_not_solved_for():
    assert refusal("--scene", "rolling-disk-spring", "f=5Hz", "k=1N/m", "m=2kg", "body=?") == (
        "Error: body is a choice, not a number to solve for; give kappa=? for the shape factor")


def test_one_of_group_left_open():
    assert refusal("--scene", "physical-pendulum", "m=2kg", "a=0.5m", "omega=3rad/s") == (
        "Error: omega= leaves J or J_A unknown: give one of them, or one as NAME=? to solve "
        "for it")


def test_a_target_the_scene_does_not_have_is_named_as_such():
    """coupled-blocks has omega_1 and omega_2, no omega: 'no value of k1 gives omega = 10
    rad/s' blames the physics for a name the scene never computes. The refusal must point at
    the scene's results (omega_1, ...), as --check and --value do for an unknown result."""
    line = refusal("--scene", "coupled-blocks", "m1=1kg", "m2=2kg", "k1=?", "k2=200N/m",
                   "k3=50N/m", "omega=10rad/s")
    assert "omega_1" in line, line


def test_a_target_that_does_not_depend_on_the_unknown_is_refused():
    """rod-in-fluid: omega^2 = 3g/(2l) whatever the drag beta. Given omega exactly as the scene
    computes it and beta=?, every beta "solves" it: that is not a solution to list (the
    solver lists every grid point, beta_1 = 0 ... beta_6001 = 1e300, and exits 0) but a
    refusal: omega does not depend on beta."""
    result = invoke("natural-frequency", "--scene", "rod-in-fluid", "m=1.5kg", "l=0.8m",
                    "beta=?", "omega=4.2880611877630664rad/s", "--json")
    assert result.exit_code == 2, (result.stdout[:300], result.stderr)
    line = error_line(result)
    assert "beta" in line and "omega" in line, line


def test_solves_terminate():
    """Solves with no answer scan the whole grid (signed parameter, angle, ODE in the loop)
    and still end with an answer or a refusal."""
    assert refusal("--scene", "pendulum-accelerating-support", "l=1m", "a0=?",
                   "omega=1e-3rad/s").startswith("Error: no value of a0 gives omega = ")
    assert refusal("--scene", "bead-on-rotating-ring", "r=0.5m", "Omega=?",
                   "theta_eq=100deg").startswith("Error: no value of Omega gives theta_eq = ")
    data = json_of("natural-frequency", "--scene", "half-cylinder-shell", "r=0.5m",
                   "amplitude=?", "T=2s", "--method", "ode")
    assert data["results"]["T"]["value"] == pytest.approx(2.0, rel=1e-6)


def test_python_api_refusals_are_input_errors():
    with pytest.raises(InputError, match=r"^give one result to solve from, not 2 \(f, T\)"):
        compute_scene("mass-spring", {"f": "5 Hz", "T": "1 s", "m": "2 kg"})


def test_a_chosen_method_is_scouted_cheaply_and_refined_with_itself():
    """--method ode: the scan runs on the cheapest model good to 1e-6 and each root is
    bracketed anew with the ODE; the root then agrees with the elliptic one to the ODE's own
    tolerance (1e-9) and the JSON says the ODE computed the results."""
    ode = json_of("natural-frequency", "--scene", "pendulum", "l=1m", "T=2.5s", "amplitude=?",
                  "--method", "ode")
    exact = json_of("natural-frequency", "--scene", "pendulum", "l=1m", "T=2.5s",
                    "amplitude=?")
    assert ode["method"] == "ode" and exact["method"] == "elliptic"
    assert ode["results"]["amplitude"]["value"] == pytest.approx(
        exact["results"]["amplitude"]["value"], rel=1e-9)
    assert ode["results"]["T"]["value"] == pytest.approx(2.5, rel=1e-9)
