"""The rigid-body command end to end: scene mode through the CLI (values, --value, --json,
--explain, inverse round trips, --check slips, --batch, the Python API, refusals with exact
messages and exit codes), eom's acceleration against rigid-body's, which commands take the
scenes; and Euler mode (a hand-worked tensor, Euler's equations in principal axes, rotation
invariance, the inertia pipe, refusals)."""
from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import dyncalc
from dyncalc.physics.euler import euler_moment
from helpers import error_line, invoke, json_of

G = 9.80665
DRUM = ["m1=20kg", "m2=15kg", "r1=0.2m", "r2=0.4m"]


def values(*args) -> dict:
    return {name: item["value"] for name, item in json_of(*args)["results"].items()}


# --- scene mode ----------------------------------------------------------------------------------

def test_drum_value_and_textbook_id():
    alpha = (15 * 0.4 - 20 * 0.2) * G / (2 + 20 * 0.04 + 15 * 0.16)
    out = invoke("rigid-body", "--scene", "E4.10", *DRUM, "J_A=2 kg*m^2", "--value", "alpha",
                 "--value", "a2")
    assert out.exit_code == 0
    assert [float(x) for x in out.stdout.split()] == pytest.approx([alpha, 0.4 * alpha],
                                                                   rel=1e-14)
    assert json_of("rigid-body", "--scene", "drum-two-blocks", *DRUM, "J_A=2")["scene"] == \
        "drum-two-blocks"


def test_unit_option_and_explain():
    out = invoke("rigid-body", "--scene", "drum-two-blocks", *DRUM, "J_A=2 kg*m^2", "--unit",
                 "S1=lbf", "--value", "S1")
    S1 = 20 * G * (0.4 * 0.6 * 15 + 2) / (2 + 0.8 + 2.4)
    assert float(out.stdout) == pytest.approx(S1 / 4.4482216152605, rel=1e-12)
    explained = invoke("rigid-body", "--scene", "drum-two-blocks", *DRUM, "J_A=2 kg*m^2",
                       "--explain")
    assert explained.exit_code == 0
    assert ("alpha = (((15 kg) × (0.4 m) - (20 kg) × (0.2 m)) × (9.80665 m/s^2)) / ((2 kg*m^2)"
            " + (20 kg) × (0.2 m)^2 + (15 kg) × (0.4 m)^2) = 3.77179 rad/s^2"
            in explained.stdout)


@pytest.mark.parametrize("scene, given, target, unknown", [
    ("drum-two-blocks", {"m1": 20.0, "m2": 15.0, "r1": 0.2, "r2": 0.4, "J_A": 2.0}, "alpha",
     "J_A"),
    ("wheel-incline-block", {"m1": 20.0, "m2": 15.0, "beta": 0.5, "J_A": 0.4, "r": 0.2}, "a",
     "m2"),
    ("two-drums-rope-drive", {"m1": 10.0, "m2": 20.0, "r1": 0.3, "r2": 0.2, "J1": 1.5,
                              "J2": 0.8, "M0": 50.0}, "a2", "M0"),
    ("direct-central-impact", {"m1": 2.0, "m2": 3.0, "v1": 4.0, "v2": -1.0, "e": 0.6},
     "v2_post", "e"),
    ("double-pendulum-impulse", {"m": 3.0, "l": 1.2, "F_hat": 12.0, "d": 0.3}, "omega_2", "d"),
])
def test_inverse_round_trip(scene, given, target, unknown):
    """Forward, then the result given back with one parameter asked for: the parameter."""
    words = [f"{k}={v}" for k, v in given.items()]
    if scene == "wheel-incline-block":
        words = [w if not w.startswith("beta=") else "beta=0.5rad" for w in words]
    forward = values("rigid-body", "--scene", scene, *words)
    solving = [w for w in words if not w.startswith(f"{unknown}=")]
    back = json_of("rigid-body", "--scene", scene, *solving, f"{target}={forward[target]!r}",
                   f"{unknown}=?")
    assert back["extra"]["inverse"]["unknown"] == unknown
    assert back["results"][unknown]["value"] == pytest.approx(given[unknown], rel=1e-9)


@pytest.mark.parametrize("answer, slip", [
    (f"alpha={2 * G / 2!r}", "the blocks' inertia left out (the rope forces taken as the "
                             "weights m g)"),
    (f"S1={20 * G!r}", "the rope force taken as the weight m1 g"),
])
def test_check_names_the_drum_slips(answer, slip):
    out = invoke("rigid-body", "--scene", "drum-two-blocks", *DRUM, "J_A=2 kg*m^2", "--check",
                 answer)
    assert out.exit_code == 1
    assert out.stdout.rstrip().endswith(f"FAIL; likely slip: {slip}")


def test_check_names_the_missing_parallel_axis_term():
    """Double pendulum: bar 1's J about its centre (m l^2/12) used about the pin A."""
    m, l, F = 3.0, 1.2, 12.0
    A = np.array([[m * l * l / 12, 0, -l, 0], [m * l, m * l / 2, 1, 0],
                  [0, m * l * l / 12, -l / 2, 0], [m * l / 2, 0, -1, -1]])
    wrong = float(np.linalg.solve(A, [0, F, F * (l / 2 - 5 * l / 8), 0])[0])
    out = invoke("rigid-body", "--scene", "double-pendulum-impulse", "m=3kg", "l=1.2m",
                 "F_hat=12 N*s", "--check", f"omega_1={wrong!r} rad/s")
    assert out.exit_code == 1
    assert out.stdout.rstrip().endswith(
        "likely slip: bar 1's moment of inertia about its centre used about the pin A (the "
        "parallel-axis term m (l/2)^2 left out)")
    wheel = invoke("rigid-body", "--scene", "wheel-incline-block", "m1=20kg", "m2=15kg",
                   "beta=30deg", "J_A=0.4 kg*m^2", "r=0.2m", "--check",
                   f"a={G * (15 - 10) / (2 * 20 + 15 + 10)!r}")
    assert wheel.stdout.rstrip().endswith(
        "likely slip: J about the contact point used for J_A (a parallel-axis term m1 r^2 too "
        "many)")


def test_batch_rows_and_inverse_columns(tmp_path):
    rows = tmp_path / "rows.csv"
    rows.write_text("m1 [kg],m2 [kg],r1 [m],r2 [m],J_A [kg*m^2]\n20,15,0.2,0.4,2\n"
                    "10,10,0.1,0.3,0.5\n")
    out = invoke("rigid-body", "--scene", "drum-two-blocks", "--batch", str(rows))
    assert out.exit_code == 0, out.stderr
    lines = out.stdout.splitlines()
    assert lines[0] == ("m1 [kg],m2 [kg],r1 [m],r2 [m],J_A [kg*m^2],alpha [rad/s^2],"
                        "a1 [m/s^2],a2 [m/s^2],S1 [N],S2 [N]")
    second = [float(x) for x in lines[2].split(",")]
    assert second[5] == pytest.approx((3 - 1) * G / (0.5 + 0.1 + 0.9), rel=1e-14)
    solve = tmp_path / "solve.csv"
    solve.write_text("m1 [kg],m2 [kg],r1 [m],r2 [m],alpha [rad/s^2]\n20,15,0.2,0.4,3\n")
    out = invoke("rigid-body", "--scene", "drum-two-blocks", "--batch", str(solve))
    assert out.exit_code == 0, out.stderr
    header, row = out.stdout.splitlines()
    J_A = float(row.split(",")[header.split(",").index("J_A [kg*m^2]")])
    assert J_A == pytest.approx(2 * G / 3 - 0.8 - 2.4, rel=1e-9)
    bad = tmp_path / "bad.csv"
    bad.write_text("m1 [kg],bogus\n1,2\n")
    assert error_line(invoke("rigid-body", "--scene", "drum-two-blocks", "--batch",
                             str(bad))) == (
        "Error: line 1: unknown column 'bogus'; rigid-body --scene drum-two-blocks reads m1, "
        "m2, r1, r2, J_A, g and a result to solve from (alpha, a1, a2, S1, S2)")


def test_batch_euler_rows(tmp_path):
    rows = tmp_path / "euler.csv"
    rows.write_text('inertia_tensor,omega,alpha\n"1,0,0;0,1,0;0,0,2","2,0,3 rad/s","0,0,1"\n')
    out = invoke("rigid-body", "--batch", str(rows))
    assert out.exit_code == 0, out.stderr
    assert out.stdout.splitlines()[1].endswith(',"0.0,-6.0,2.0",6.324555320336759,'
                                               '"2.0,0.0,6.0",11.0')


def test_python_api():
    r = dyncalc.rigid_body(scene="direct-central-impact", m1="2 kg", m2=3, v1="4 m/s", v2=-1,
                           e=0.6)
    assert r["v2_post"].to("m/s").magnitude == pytest.approx(2.2, rel=1e-14)
    euler = dyncalc.rigid_body(inertia_tensor="1,0,0; 0,1,0; 0,0,2 kg*m^2", omega="2,0,3 rad/s")
    assert euler["M"].to("N*m").magnitude.tolist() == [0.0, -6.0, 0.0]
    with pytest.raises(dyncalc.InputError, match="^direct-central-impact needs v1 > v2"):
        dyncalc.rigid_body(scene="direct-central-impact", m1=1, m2=1, v1=0, v2=1, e=0.5)


@pytest.mark.parametrize("scene, words, eom_state, ours, theirs", [
    ("drum-two-blocks", [*DRUM, "J_A=2kg*m^2"], ["phi=0", "phi_dot=0"], "alpha", "phi_ddot"),
    ("wheel-incline-block", ["m1=20kg", "m2=15kg", "beta=30deg", "kappa=0.5"],
     ["x=0", "x_dot=0"], "a", "x_ddot"),
    ("two-drums-rope-drive", ["m1=10kg", "m2=20kg", "r1=0.3m", "r2=0.2m", "J1=1.5kg*m^2",
                              "J2=0.8kg*m^2", "M0=50N*m"], ["x2=0", "x2_dot=0"], "a2",
     "x2_ddot"),
])
def test_eom_derives_the_same_acceleration(scene, words, eom_state, ours, theirs):
    mine = values("rigid-body", "--scene", scene, *words)[ours]
    derived = values("eom", "--scene", scene, *words, *eom_state)[theirs]
    assert derived == pytest.approx(mine, rel=1e-12)


RIGID = ["drum-two-blocks", "wheel-incline-block", "two-drums-rope-drive",
         "direct-central-impact", "double-pendulum-impulse", "angled-bar-on-shaft",
         "precessing-shaft", "beam-spun-up", "rotating-angled-arm"]


def test_only_rigid_body_offers_the_rigid_body_scenes():
    listed = json_of("scenes", "--command", "rigid-body")["scenes"]
    assert [s["name"] for s in listed] == RIGID
    for command in ("natural-frequency", "forced-response", "modes", "damping-ratio"):
        names = [s["name"] for s in json_of("scenes", "--command", command)["scenes"]]
        assert not set(RIGID) & set(names), command
        assert error_line(invoke(command, "--scene", "double-pendulum-impulse", "m=1kg")) == (
            f"Error: {command} does not take double-pendulum-impulse: it is a rigid-body scene "
            "(no oscillation); run 'dyncalc rigid-body --scene double-pendulum-impulse ...'")
    assert error_line(invoke("rigid-body", "--scene", "mass-spring", "k=1N/m", "m=1kg")) == (
        "Error: mass-spring is not a rigid-body scene ('dyncalc scenes mass-spring' names the "
        "commands that take it); the rigid-body scenes are: " + ", ".join(RIGID))


@pytest.mark.parametrize("args, message", [
    (["--scene", "direct-central-impact", "m1=2kg", "m2=3kg", "v1=1m/s", "v2=1m/s", "e=0.5"],
     "direct-central-impact needs v1 > v2 (body 1 must catch body 2: otherwise there is no "
     "impact)"),
    (["--scene", "direct-central-impact", "m1=2kg", "m2=3kg", "v1=4m/s", "v2=1m/s", "e=1.2"],
     "direct-central-impact needs e <= 1 (e is the ratio of separation to approach speed: 0 "
     "plastic, 1 elastic)"),
    (["--scene", "direct-central-impact", "m1=2kg", "m2=3kg", "v1=4m/s", "v2=1m/s",
      "e=-0.1"], "e must not be negative; got -0.1"),
    (["--scene", "double-pendulum-impulse", "m=3kg", "l=1.2m", "F_hat=12N*s", "d=1.5m"],
     "double-pendulum-impulse needs d <= l (the blow strikes bar 2, which is l long)"),
    (["--scene", "wheel-incline-block", "m1=20kg", "m2=15kg", "beta=30deg",
      "J_A=0.4kg*m^2"], "wheel-incline-block needs r with J_A (J_A/r^2 enters the "
                        "acceleration; with body= or kappa= r cancels)"),
    (["--scene", "wheel-incline-block", "m1=20kg", "m2=15kg", "beta=90deg", "kappa=0.5"],
     "wheel-incline-block needs -90 deg < beta < 90 deg (the wheel must rest on the plane)"),
    (["--scene", "drum-two-blocks", *DRUM, "J_A=2kg*m^2", "zeta=0.1"],
     "drum-two-blocks takes no zeta: it is a rigid-body scene (no oscillation to damp); the "
     "parameters of drum-two-blocks are: m1 [mass], m2 [mass], r1 [length], r2 [length], J_A "
     "[mass]*[length]^2, g [length]/[time]^2 = 9.80665 m/s^2"),
    (["--scene", "drum-two-blocks", *DRUM, "J_A=2kg"],
     "J_A must be a mass moment of inertia [mass]*[length]^2; got 2 kilogram ([mass])"),
    ([], "rigid-body needs --scene NAME with its NAME=QUANTITY words ('dyncalc scenes "
         "--command rigid-body' lists the scenes), or --inertia-tensor MATRIX with --omega VEC "
         "and --alpha VEC (Euler's equations)"),
    (["--omega", "1,2,3"], "--omega needs --inertia-tensor MATRIX (in the body's axes, e.g. "
                           "\"2, 0, 0; 0, 2, 0; 0, 0, 1 kg*m^2\")"),
    (["--scene", "drum-two-blocks", "--alpha", "1,2,3"],
     "--alpha does not go with --scene: Euler's equations (--inertia-tensor, --omega, "
     "--alpha) are the other mode of rigid-body"),
    (["--inertia-tensor", "1, 0.2, 0; 0.1, 1, 0; 0, 0, 1 kg*m^2"],
     "--inertia-tensor is not symmetric: row 1, column 2 is 0.2 but row 2, column 1 is 0.1 "
     "kg*m^2"),
    (["--inertia-tensor", "1, 0, 0; 0, -1, 0; 0, 0, 1"],
     "--inertia-tensor is not positive semi-definite: its principal moments are -1, 1, 1 "
     "kg*m^2 (one is negative)"),
    (["--inertia-tensor", "1, 0, 0; 0, 1, 0; 0, 0, 3"],
     "--inertia-tensor violates the triangle inequality of principal moments: J_1 + J_2 = 2 < "
     "J_3 = 3 kg*m^2 (no rigid body has such moments)"),
    (["--inertia-tensor", "1 kg*m^2, 0, 0; 0, 1 kg*m, 0; 0, 0, 1 kg*m^2"],
     "--inertia-tensor row 2, column 2 must be a mass moment of inertia [mass]*[length]^2; got "
     "1 kilogram * meter ([mass] * [length]) (every entry of an inertia tensor)"),
    (["--inertia-tensor", "1, 0; 0, 1 kg*m^2"],
     "--inertia-tensor must be a 3x3 matrix (rows by ';'); got 2x2"),
    (["--inertia-tensor", "1, 0, 0; 0, 1, 0; 0, 0, 1", "--omega", "1, 2, 3 m/s"],
     "--omega must be an angular rate [angle]/[time]; got (1, 2, 3) meter / second ([length] "
     "/ [time])"),
    (["--inertia-tensor", "1, 0, 0; 0, 1, 0; 0, 0, 1", "m=2kg"],
     "--inertia-tensor takes no NAME=QUANTITY words; got 'm=2kg'"),
    (["--inertia-tensor", "1e200, 0, 0; 0, 1e200, 0; 0, 0, 1e200", "--omega", "1e200,1e200,0"],
     "M overflows float64 at these inputs"),
])
def test_refusals(args, message):
    assert error_line(invoke("rigid-body", *args)) == f"Error: {message}"


# --- Euler mode ----------------------------------------------------------------------------------

def test_euler_hand_worked_tensor():
    """J = [[2, -0.5, 0], [-0.5, 3, 0], [0, 0, 4]], omega = (1, 2, 0.5), alpha = (0.3, -0.2,
    1), worked by hand: J omega = (1, 5.5, 2); omega x J omega = (1.25, -1.5, 3.5);
    J alpha = (0.7, -0.75, 4); M = (1.95, -2.25, 7.5); T = (1 + 11 + 1)/2 = 6.5."""
    data = values("rigid-body", "--inertia-tensor", "2, -0.5, 0; -0.5, 3, 0; 0, 0, 4 kg*m^2",
                  "--omega", "1, 2, 0.5 rad/s", "--alpha", "0.3, -0.2, 1 rad/s^2")
    assert data["M"] == pytest.approx([1.95, -2.25, 7.5], rel=1e-15)
    assert data["H"] == pytest.approx([1.0, 5.5, 2.0], rel=1e-15)
    assert data["T"] == pytest.approx(6.5, rel=1e-15)
    assert data["M_mag"] == pytest.approx(math.sqrt(1.95 ** 2 + 2.25 ** 2 + 7.5 ** 2), rel=1e-15)


def test_euler_in_principal_axes_is_the_textbook_form():
    """M1 = J1 a1 - (J2 - J3) w2 w3 and cyclic (Gross et al., Section 3.3)."""
    rng = np.random.default_rng(3)
    for _ in range(5):
        J1, J2 = rng.uniform(0.5, 2.0, 2)
        J3 = rng.uniform(abs(J1 - J2), J1 + J2)
        w, a = rng.normal(size=3), rng.normal(size=3)
        M = euler_moment(np.diag([J1, J2, J3]), w, a)["M"]
        assert M[0] == pytest.approx(J1 * a[0] - (J2 - J3) * w[1] * w[2], rel=1e-12)
        assert M[1] == pytest.approx(J2 * a[1] - (J3 - J1) * w[2] * w[0], rel=1e-12)
        assert M[2] == pytest.approx(J3 * a[2] - (J1 - J2) * w[0] * w[1], rel=1e-12)


def _rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


def test_euler_rotation_invariance():
    """R M(J, w, a) = M(R J R^T, R w, R a), J the tensor of random point masses."""
    rng = np.random.default_rng(7)
    for _ in range(10):
        points, masses = rng.normal(size=(5, 3)), rng.uniform(0.1, 2.0, 5)
        J = sum(m * (p @ p * np.eye(3) - np.outer(p, p)) for m, p in zip(masses, points))
        w, a, R = rng.normal(size=3), rng.normal(size=3), _rotation(rng)
        M = euler_moment(J, w, a)["M"]
        turned = euler_moment(R @ J @ R.T, R @ w, R @ a)
        assert turned["M"] == pytest.approx(R @ M, rel=1e-10, abs=1e-12)
        assert turned["T"] == pytest.approx(euler_moment(J, w, a)["T"], rel=1e-12)


def test_inertia_tensor_from_inertia_value_through_the_cli():
    """The printed J_C of inertia (rows by ';', bare SI) read back in process and through a
    real shell's $(...): a rod along z (J_C = diag(1/6, 1/6, 0) kg*m^2)."""
    text = invoke("inertia", "rod(m=2kg, l=1m)", "--value", "J_C").stdout.strip()
    got = values("rigid-body", "--inertia-tensor", text, "--omega", "0, 1, 0 rad/s",
                 "--alpha", "2, 0, 0 rad/s^2")
    assert got["M"] == pytest.approx([1 / 3, 0, 0], rel=1e-14)
    assert got["T"] == pytest.approx(1 / 12, rel=1e-14)
    exe = Path(sys.executable).parent / "dyncalc"
    line = (f'"{exe}" rigid-body --inertia-tensor "$("{exe}" inertia "rod(m=2kg, l=1m, '
            f'along=x)" --value J_C)" --omega "0, 0, 3 rad/s" --alpha "0, 1, 0" --value M')
    shell = subprocess.run(["bash", "-c", line], capture_output=True, text=True, timeout=60)
    assert shell.returncode == 0, shell.stderr
    assert [float(x) for x in shell.stdout.strip().split(",")] == pytest.approx(
        [0.0, 1 / 6, 0.0], abs=1e-15)


# --- batch: the vectorised path is the one-off's, byte for byte --------------------------------

BATCHES = {
    "drum-two-blocks": "m1 [kg],m2 [lb],r1 [m],r2 [in],J_A [kg*m^2]\n20,33,0.2,15.7,2\n"
                       "10,22.05,0.1,11.811,0.5\n-1,2,0.1,0.2,0.3\n20,44.09245,0.2,7.874015748,"
                       "2\n1e308,1e308,1e308,1e308,1\n",
    "wheel-incline-block": "m1,m2,beta [deg],kappa\n20,15,30,0.5\n5,1,60,1\n3,8,95,0.5\n"
                           "3,8,-10,0.4\n",
    "two-drums-rope-drive": "m1,m2,r1,r2,J1,J2,M0 [N*m]\n10,20,0.3,0.2,1.5,0.8,50\n"
                            "10,20,0.3,0.2,0,0,500\n40,5,0.5,0.1,0.3,0.2,-3\n",
    "direct-central-impact": "m1,m2,v1 [km/h],v2,e\n2,3,14.4,-1,0.6\n1,1,3.6,1,0.5\n"
                             "2,3,10,0,1.5\n5,0.5,-3.6,-7,0\n3.5,1.25,2.75,-0.5,0.35\n",
    "double-pendulum-impulse": "m,l,F_hat [N*s],d\n3,1.2,12,0.3\n3,1.2,12,1.5\n2,0.8,7,\n",
}


@pytest.mark.parametrize("scene", BATCHES)
@pytest.mark.parametrize("as_json", [False, True])
def test_batch_vectorised_equals_generic(scene, as_json, tmp_path, monkeypatch):
    from dyncalc.batch import GENERIC_ENV
    from dyncalc.commands import rigid_columns

    rows = tmp_path / "rows.csv"
    rows.write_text(BATCHES[scene])
    args = ["rigid-body", "--scene", scene, "--batch", str(rows), "--on-error", "skip",
            *(["--json"] if as_json else [])]
    exact = []
    original = rigid_columns.scene_columns

    def counting(given, settings):
        out = original(given, settings)
        exact.append(0 if out is None else int(out.exact.sum()))
        return out

    monkeypatch.setattr(rigid_columns, "scene_columns", counting)
    fast = invoke(*args)
    assert sum(exact) >= 2, exact  # the adapter answered rows
    monkeypatch.setenv(GENERIC_ENV, "1")
    generic = invoke(*args)
    assert (fast.exit_code, fast.stdout, fast.stderr) == (
        generic.exit_code, generic.stdout, generic.stderr)
